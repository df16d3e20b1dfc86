// grape — frames with ends given, closed loops and world up, on top of the RMF table.
#include <grape/error.hpp>
#include <grape/frames3.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace grape {
namespace {

constexpr double pi_f3 = std::numbers::pi;

// An angle in (−π, π].
double wrap_f3(double a) noexcept {
    a = std::remainder(a, 2.0 * pi_f3);
    return a <= -pi_f3 ? a + 2.0 * pi_f3 : a;
}

// The roll about the unit t that takes the unit n (⟂ t) to the unit m (⟂ t), in (−π, π].
double roll_f3(Vec3 t, Vec3 n, Vec3 m) noexcept { return std::atan2(dot(cross(n, m), t), dot(n, m)); }

// r without its part along t, unit (any_perpendicular(t) if nothing is left).
Vec3 across_f3(Vec3 r, Vec3 t) noexcept {
    const Vec3 q = normalized(r - t * dot(r, t));
    return q == Vec3{} ? any_perpendicular(t) : q;
}

// The frame f rolled by phi about its tangent, made orthonormal again.
Frame3 rolled_f3(Frame3 f, double phi) noexcept {
    if (phi == 0.0) return f;
    const double c = std::cos(phi), s = std::sin(phi);
    f.normal = across_f3(f.normal * c + f.binormal * s, f.tangent);
    f.binormal = cross(f.tangent, f.normal);
    return f;
}

// Angle between the unit t and the line of the unit w, in [0, π/2].
double cone_angle_f3(Vec3 t, Vec3 w) noexcept {
    return std::atan2(length(cross(t, w)), std::abs(dot(t, w)));
}

// 5-point Gauss–Legendre rule for the length of path on [a, b]: exact for a speed that is a
// polynomial of degree 9, and on a panel where the halves agree with the whole to rounding.
double gauss_length_f3(const Path3& path, double a, double b) noexcept {
    static constexpr double x[5] = {0.0, 0.5384693101056831, -0.5384693101056831, 0.9061798459386640, -0.9061798459386640};
    static constexpr double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                                    0.2369268850561891};
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    double sum = 0.0;
    for (int k = 0; k < 5; ++k) sum += w[k] * length(path.d1(mid + half * x[k]));
    return sum * half;
}

// Panels of [a, b] (inside one piece) on which the rule agrees with its two halves within
// `allowed` per unit of u or within the rounding of the speed (64 ulp of `speed`, the piece's
// mean speed, per unit of u: near a stop the speed is |d1| of nearly cancelling terms, and its
// rounding does not shrink with the panel). Work is bounded: at most 40 halvings (a cusp, where
// the speed has a kink the rule cannot resolve) and 4096 panels a piece.
void arc_panels_f3(const Path3& path, double a, double b, double whole, double allowed, double speed, int depth,
                   std::size_t& budget, std::vector<double>& u, std::vector<double>& len) {
    const double m = 0.5 * (a + b);
    const double left = gauss_length_f3(path, a, m), right = gauss_length_f3(path, m, b);
    const double resolved =
        (b - a) * std::max(allowed, 64 * std::numeric_limits<double>::epsilon() * speed) +
        64 * std::numeric_limits<double>::epsilon() * whole;
    if (depth >= 40 || budget <= 2 || std::abs(left + right - whole) <= resolved || !(a < m && m < b)) {
        u.push_back(a);
        len.push_back(left + right);
        if (budget > 0) --budget;
        return;
    }
    --budget;
    arc_panels_f3(path, a, m, left, allowed, speed, depth + 1, budget, u, len);
    arc_panels_f3(path, m, b, right, allowed, speed, depth + 1, budget, u, len);
}

}  // namespace

RotationMinimizingFrames Frames3::make_rmf(const Path3& path, const FramesDef& def) {
    const std::string where = "Frames3: ";
    if (!is_finite(def.up) || length(def.up) == 0.0) throw Error(where + "up: not finite or zero");
    if (def.mode == FrameMode::ends && (!is_finite(def.end_up) || length(def.end_up) == 0.0)) {
        throw Error(where + "end_up: not finite or zero");
    }
    if (def.mode == FrameMode::reference_up && !(def.cone >= 0.05 && def.cone <= 1.5)) {
        throw Error(where + "cone: must be in [0.05, 1.5] radians, got " + detail::number_text(def.cone));
    }
    if (def.mode == FrameMode::reference_up || def.mode == FrameMode::frenet) {
        // The RMF is only the fallback here: start it from whatever normal is defined.
        const Vec3 t0 = path.tangent(0.0);
        const Vec3 w = normalized(def.up);
        const Vec3 start = cone_angle_f3(t0, w) > 1e-3 ? w : any_perpendicular(t0);
        return RotationMinimizingFrames(path, start, def.tolerance);
    }
    try {
        return RotationMinimizingFrames(path, def.up, def.tolerance);
    } catch (const Error& e) {
        throw Error(where + e.what());
    }
}

Frames3::Frames3(Path3 path, const FramesDef& def)
    : path_(std::move(path)), mode_(def.mode), up_(normalized(def.up)), rmf_(make_rmf(path_, def)),
      length_(path_.length()) {
    const std::string where = "Frames3: ";
    {
        // Each piece from its exact start length (length_at at a break), so the panels' sums
        // carry no rounding from one piece into the next; within 1e-15 of the length per u.
        const auto breaks = path_.breaks();
        std::vector<double> len;
        for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
            const std::size_t first = arc_u_.size();
            const double whole = gauss_length_f3(path_, breaks[i], breaks[i + 1]);
            const double width = breaks[i + 1] - breaks[i];
            std::size_t budget = 4096;
            arc_panels_f3(path_, breaks[i], breaks[i + 1], whole, 1e-15 * length_, width > 0.0 ? whole / width : 0.0, 0,
                          budget, arc_u_, len);
            double s = path_.length_at(breaks[i]);
            for (std::size_t k = first; k < arc_u_.size(); ++k) {
                arc_s_.push_back(s);
                s += len[k];
            }
        }
        if (arc_u_.empty()) {
            arc_u_.push_back(0.0);
            arc_s_.push_back(0.0);
        }
    }
    if (mode_ == FrameMode::ends || mode_ == FrameMode::closed) {
        const Frame3 end = rmf_.frame(1.0);
        Vec3 target;
        if (mode_ == FrameMode::ends) {
            if (!(cone_angle_f3(end.tangent, normalized(def.end_up)) > 1e-6)) {
                throw Error(where + "end_up: parallel to the tangent at u = 1");
            }
            target = across_f3(def.end_up, end.tangent);
        } else {
            const double gap = distance(path_.point(0.0), path_.point(1.0));
            if (!(gap <= 1e-9 * length_)) {
                throw Error(where + "path: mode closed needs point(1) = point(0), they are " + detail::number_text(gap) +
                            " apart");
            }
            target = across_f3(rmf_.frame(0.0).normal, end.tangent);
        }
        twist_ = roll_f3(end.tangent, end.normal, target) + 2.0 * pi_f3 * def.extra_turns;
        return;
    }
    if (mode_ != FrameMode::reference_up) return;

    // Sample α on the RMF's knots and their midpoints, at least 64 per piece.
    const double cone = def.cone;
    auto inside = [&](double u) noexcept { return cone_angle_f3(path_.tangent(u), up_) < cone; };
    std::vector<double> grid;
    const auto breaks = path_.breaks();
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        for (int k = 0; k < 64; ++k) grid.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * k / 64.0);
    }
    for (std::size_t i = 0; i < rmf_.knot_count(); ++i) {
        grid.push_back(rmf_.knot_u(i));
        if (i + 1 < rmf_.knot_count()) grid.push_back(0.5 * (rmf_.knot_u(i) + rmf_.knot_u(i + 1)));
    }
    grid.push_back(1.0);
    std::sort(grid.begin(), grid.end());
    grid.erase(std::unique(grid.begin(), grid.end()), grid.end());

    // The edge between an outside u and an inside u, by bisection to adjacent doubles.
    auto edge = [&](double out, double in) noexcept {
        for (int i = 0; i < 200; ++i) {
            const double m = 0.5 * (out + in);
            if (m == out || m == in) break;
            (inside(m) ? in : out) = m;
        }
        return out;  // the last u outside: the world-up roll is defined there
    };
    // The world-up roll's rate per unit length at u, by a one-sided difference toward `away`.
    auto rate = [&](double u, double away) noexcept {
        const double h = (away - u) * 1e-6;
        const double v = u + h;
        const double ds = path_.length_at(v) - path_.length_at(u);
        if (!(std::abs(ds) > 0.0)) return 0.0;
        return wrap_f3(reference_roll(v) - reference_roll(u)) / ds;
    };
    std::size_t i = 0;
    while (i < grid.size()) {
        if (!inside(grid[i])) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j + 1 < grid.size() && inside(grid[j + 1])) ++j;
        Blend b{};
        const bool from_start = i == 0, to_end = j + 1 == grid.size();
        b.u0 = from_start ? 0.0 : edge(grid[i - 1], grid[i]);
        b.u1 = to_end ? 1.0 : edge(grid[j + 1], grid[j]);
        b.s0 = path_.length_at(b.u0);
        b.s1 = path_.length_at(b.u1);
        if (from_start && to_end) {
            b.psi0 = b.psi1 = 0.0;
        } else if (from_start) {
            b.psi0 = b.psi1 = reference_roll(b.u1);
        } else if (to_end) {
            b.psi0 = b.psi1 = reference_roll(b.u0);
        } else {
            b.psi0 = reference_roll(b.u0);
            b.psi1 = b.psi0 + wrap_f3(reference_roll(b.u1) - b.psi0);
            b.rate0 = rate(b.u0, std::max(0.0, b.u0 - 1e-3 * (b.u1 - b.u0)));
            b.rate1 = rate(b.u1, std::min(1.0, b.u1 + 1e-3 * (b.u1 - b.u0)));
        }
        blends_.push_back(b);
        i = j + 1;
    }
}

// The roll from the RMF's normal to the world-up normal at u, where that is defined.
double Frames3::reference_roll(double u) const noexcept {
    const Frame3 f = rmf_.frame(u);
    return roll_f3(f.tangent, f.normal, across_f3(up_, f.tangent));
}

Frame3 Frames3::frame(double u) const noexcept {
    u = std::clamp(u, 0.0, 1.0);
    switch (mode_) {
    case FrameMode::rotation_minimizing:
        return rmf_.frame(u);
    case FrameMode::ends:
    case FrameMode::closed: {
        const double share = length_ > 0.0 ? arc_length_at(u) / length_ : u;
        return rolled_f3(rmf_.frame(u), twist_ * share);
    }
    case FrameMode::frenet: {
        const Frenet3 f = path_.frenet(u);
        return {f.point, f.tangent, f.normal, f.binormal};
    }
    case FrameMode::reference_up:
        break;
    }
    const auto it = std::upper_bound(blends_.begin(), blends_.end(), u, [](double v, const Blend& b) { return v < b.u0; });
    if (it != blends_.begin() && u <= (it - 1)->u1) {
        const Blend& b = *(it - 1);
        const double span = b.s1 - b.s0;
        double psi = b.psi0;
        if (span > 0.0) {
            // Cubic Hermite in arc length: values and rates at both ends.
            const double t = std::clamp((arc_length_at(u) - b.s0) / span, 0.0, 1.0);
            const double t2 = t * t, t3 = t2 * t;
            psi = (2 * t3 - 3 * t2 + 1) * b.psi0 + (t3 - 2 * t2 + t) * span * b.rate0 + (3 * t2 - 2 * t3) * b.psi1 +
                  (t3 - t2) * span * b.rate1;
        }
        return rolled_f3(rmf_.frame(u), psi);
    }
    Frame3 f;
    f.point = path_.point(u);
    f.tangent = path_.tangent(u);
    f.normal = across_f3(up_, f.tangent);
    f.binormal = cross(f.tangent, f.normal);
    return f;
}

double Frames3::arc_length_at(double u) const noexcept {
    const auto it = std::upper_bound(arc_u_.begin(), arc_u_.end(), u);
    const std::size_t j = it == arc_u_.begin() ? 0 : static_cast<std::size_t>(it - arc_u_.begin()) - 1;
    return arc_s_[j] + gauss_length_f3(path_, arc_u_[j], u);
}

double Frames3::length_at(double u) const noexcept {
    if (!(u > 0.0)) return 0.0;  // NaN too
    if (u >= 1.0) return length_;
    return arc_length_at(u);
}

const Path3& Frames3::path() const noexcept { return path_; }
FrameMode Frames3::mode() const noexcept { return mode_; }
double Frames3::twist() const noexcept { return twist_; }
std::size_t Frames3::cone_count() const noexcept { return blends_.size(); }

}  // namespace grape
