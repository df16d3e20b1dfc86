// A bead in its generalized coordinate: ü = (x′·F/m − (x′·x″) u̇²)/|x′|² on one smooth part
// at a time; joins, ends and wrap-around are handled between parts.
#include <grape/dynamics.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <string>

namespace grape {

namespace {
using detail::number_text;
}  // namespace

class Bead::Ode final : public SecondOrderSystem {
public:
    explicit Ode(const Bead& bead) noexcept : bead_(bead) {}
    std::size_t size() const noexcept override { return 1; }
    void acceleration(double t, std::span<const double> q, std::span<const double> v,
                      std::span<double> a) noexcept override {
        const ParametricSample f = bead_.frame(q[0]);
        const Vec2 force = bead_.applied_force(t, f.point, f.d1 * v[0]);
        a[0] = bead_acceleration(f, force, bead_.def_.mass, v[0]);
    }

private:
    const Bead& bead_;
};

Bead::Bead(ParametricFunction curve, const BeadDef& def) {
    if (!curve) throw Error("Bead: curve must be a callable (got an empty function)");
    std::vector<Part> parts;
    parts.push_back({std::move(curve), 0.0, 1.0});
    bounded_ = false;
    init_parts(std::move(parts), def);
}

void Bead::init_parts(std::vector<Part> parts, const BeadDef& def) {
    if (!std::isfinite(def.u)) throw Error("BeadDef: u must be finite (got " + number_text(def.u) + ")");
    if (bounded_ && !(def.u >= 0.0 && def.u <= 1.0))
        throw Error("BeadDef: u must be in [0, 1] on a path (got " + number_text(def.u) + ")");
    if (!std::isfinite(def.speed)) throw Error("BeadDef: speed must be finite (got " + number_text(def.speed) + ")");
    if (!(def.mass > 0.0) || !std::isfinite(def.mass))
        throw Error("BeadDef: mass must be positive and finite (got " + number_text(def.mass) + ")");
    if (!std::isfinite(def.gravity.x) || !std::isfinite(def.gravity.y))
        throw Error("BeadDef: gravity must be finite (got " + number_text(def.gravity.x) + ", " + number_text(def.gravity.y) + ")");
    if (!(def.drag >= 0.0) || !std::isfinite(def.drag))
        throw Error("BeadDef: drag must be finite and ≥ 0 (got " + number_text(def.drag) + ")");
    if (!(def.restitution >= 0.0 && def.restitution <= 1.0))
        throw Error("BeadDef: restitution must be in [0, 1] (got " + number_text(def.restitution) + ")");
    def_ = def;
    stepper_ = Stepper(def.integrator, def.rk45);
    parts_ = std::move(parts);
    part_ = 0;
    if (bounded_) {
        while (part_ + 1 < parts_.size() && def.u >= parts_[part_ + 1].u0) ++part_;
        const Part& p = parts_[part_];
        local_u_ = std::clamp((def.u - p.u0) / (p.u1 - p.u0), 0.0, 1.0);
        const Vec2 first = parts_.front().curve(0.0).point;
        const Vec2 last = parts_.back().curve(1.0).point;
        const double scale = 1.0 + std::max(length(first), length(last));
        closed_ = distance(first, last) <= 1e-12 * scale;
    } else {
        local_u_ = def.u;
    }
    const double s = length(frame(local_u_).d1);
    local_rate_ = s > 0.0 ? def.speed / s : 0.0;
}

ParametricSample Bead::frame(double local_u) const noexcept { return parts_[part_].curve(local_u); }

Vec2 Bead::applied_force(double t, Vec2 x, Vec2 v) const noexcept {
    Vec2 f = def_.mass * def_.gravity - def_.drag * v;
    if (force_) f += force_(t, x, v);
    return f;
}

double Bead::u() const noexcept {
    const Part& p = parts_[part_];
    return bounded_ ? p.u0 + local_u_ * (p.u1 - p.u0) : local_u_;
}

double Bead::u_rate() const noexcept {
    const Part& p = parts_[part_];
    return bounded_ ? local_rate_ * (p.u1 - p.u0) : local_rate_;
}

Vec2 Bead::position() const noexcept { return frame(local_u_).point; }
Vec2 Bead::velocity() const noexcept { return frame(local_u_).d1 * local_rate_; }
double Bead::speed() const noexcept { return length(frame(local_u_).d1) * local_rate_; }

double Bead::energy() const noexcept {
    const ParametricSample f = frame(local_u_);
    const Vec2 v = f.d1 * local_rate_;
    return 0.5 * def_.mass * length_squared(v) - def_.mass * dot(def_.gravity, f.point);
}

double Bead::acceleration() const noexcept {
    const ParametricSample f = frame(local_u_);
    return bead_acceleration(f, applied_force(time_, f.point, f.d1 * local_rate_), def_.mass, local_rate_);
}

// Moves the bead across the end of its current part, keeping its speed along the path; at
// an open end it stops or bounces.
void Bead::transfer(double speed, int direction) {
    std::size_t next = part_;
    bool moved = true;
    if (direction > 0) {
        if (part_ + 1 < parts_.size()) next = part_ + 1;
        else if (closed_) next = 0;
        else moved = false;
    } else {
        if (part_ > 0) next = part_ - 1;
        else if (closed_) next = parts_.size() - 1;
        else moved = false;
    }
    if (moved) {
        part_ = next;
        local_u_ = direction > 0 ? 0.0 : 1.0;
        const double s = length(frame(local_u_).d1);
        local_rate_ = s > 0.0 ? speed / s : 0.0;
    } else {
        local_u_ = direction > 0 ? 1.0 : 0.0;
        local_rate_ = def_.ends == BeadEnd::bounce ? -def_.restitution * local_rate_ : 0.0;
    }
}

StepStats Bead::step(double dt) {
    if (!(dt > 0.0) || !std::isfinite(dt)) throw Error("Bead::step: dt must be positive and finite (got " + number_text(dt) + ")");
    StepStats total;
    auto add = [&total](const StepStats& s) {
        total.evaluations += s.evaluations;
        total.substeps += s.substeps;
        total.rejected += s.rejected;
        total.forced += s.forced;
        total.status = worse(total.status, s.status);
    };
    Ode ode(*this);
    double remaining = dt;
    // Each pass integrates to the end of the step or to the next crossing of a part's end.
    for (int pass = 0; remaining > 0.0; ++pass) {
        const double u0 = local_u_, r0 = local_rate_;
        add(stepper_.step(ode, time_, {&local_u_, 1}, {&local_rate_, 1}, remaining));
        if (!bounded_ || (local_u_ >= 0.0 && local_u_ <= 1.0)) {
            time_ += remaining;
            break;
        }
        const double end = local_u_ > 1.0 ? 1.0 : 0.0;
        const int direction = end == 1.0 ? 1 : -1;
        const bool at_open_end = (direction > 0 ? part_ + 1 == parts_.size() : part_ == 0) && !closed_;
        if (pass >= 64 || (at_open_end && def_.ends == BeadEnd::stop)) {
            // Stopped at an end (or a pathological number of crossings): rest there.
            local_u_ = end;
            local_rate_ = 0.0;
            time_ += remaining;
            break;
        }
        // When in the step the part's end was crossed: the root of the cubic Hermite
        // interpolant of u over the step (third-order accurate).
        const double u1 = local_u_, r1 = local_rate_, h = remaining;
        auto hermite = [&](double s) {
            const double s2 = s * s, s3 = s2 * s;
            const double value = (2 * s3 - 3 * s2 + 1) * u0 + (s3 - 2 * s2 + s) * h * r0 + (-2 * s3 + 3 * s2) * u1 +
                                 (s3 - s2) * h * r1 - end;
            const double slope = (6 * s2 - 6 * s) * u0 + (3 * s2 - 4 * s + 1) * h * r0 + (-6 * s2 + 6 * s) * u1 +
                                 (3 * s2 - 2 * s) * h * r1;
            return std::pair{value, slope};
        };
        const double tau = u0 == end ? 0.0 : find_root(hermite, 0.0, 1.0, (end - u0) / (u1 - u0), 1e-14).x;
        local_u_ = u0;
        local_rate_ = r0;
        const double sub = tau * remaining;
        if (sub > 0.0) add(stepper_.step(ode, time_, {&local_u_, 1}, {&local_rate_, 1}, sub));
        time_ += sub;
        remaining -= sub;
        const double speed = length(frame(end).d1) * local_rate_;
        local_u_ = end;
        transfer(speed, direction);
        ++crossings_;
    }
    return total;
}

}  // namespace grape
