// grape — roll tracks in arc length, frames rolled by them, and automatic banking.
#include <grape/error.hpp>
#include <grape/roll3.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

namespace grape {
namespace {

std::string roll_where(const char* field) { return std::string("RollTrack: ") + field + ": "; }

// The frame f turned by phi about its tangent (normal toward binormal), orthonormal again.
Frame3 turned_roll3(Frame3 f, double phi) noexcept {
    if (phi == 0.0) return f;
    const double c = std::cos(phi), s = std::sin(phi);
    const Vec3 n = f.normal * c + f.binormal * s;
    const Vec3 q = normalized(n - f.tangent * dot(n, f.tangent));
    f.normal = q == Vec3{} ? f.normal : q;
    f.binormal = cross(f.tangent, f.normal);
    return f;
}

// d²roll/ds² at the keys of a C² cubic spline (natural: 0 at the ends; clamped: the end slopes
// given), by the tridiagonal system of the spline's continuity, solved by Thomas's algorithm
// (diagonally dominant: no pivoting needed).
std::vector<double> spline_second_roll3(std::span<const RollKey> k, bool clamped, double a, double b) {
    const std::size_t n = k.size();
    std::vector<double> lower(n, 0.0), diag(n, 1.0), upper(n, 0.0), rhs(n, 0.0);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double h0 = k[i].s - k[i - 1].s, h1 = k[i + 1].s - k[i].s;
        lower[i] = h0;
        diag[i] = 2.0 * (h0 + h1);
        upper[i] = h1;
        rhs[i] = 6.0 * ((k[i + 1].roll - k[i].roll) / h1 - (k[i].roll - k[i - 1].roll) / h0);
    }
    if (clamped) {
        const double h0 = k[1].s - k[0].s, hn = k[n - 1].s - k[n - 2].s;
        diag[0] = 2.0 * h0;
        upper[0] = h0;
        rhs[0] = 6.0 * ((k[1].roll - k[0].roll) / h0 - a);
        lower[n - 1] = hn;
        diag[n - 1] = 2.0 * hn;
        rhs[n - 1] = 6.0 * (b - (k[n - 1].roll - k[n - 2].roll) / hn);
    }
    for (std::size_t i = 1; i < n; ++i) {
        const double m = lower[i] / diag[i - 1];
        diag[i] -= m * upper[i - 1];
        rhs[i] -= m * rhs[i - 1];
    }
    std::vector<double> second(n, 0.0);
    second[n - 1] = rhs[n - 1] / diag[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) second[i] = (rhs[i] - upper[i] * second[i + 1]) / diag[i];
    return second;
}

// a + b with its rounding error (Knuth's two-sum), for the smoothing window's prefix sums.
std::pair<double, double> two_sum_roll3(double a, double b) noexcept {
    const double s = a + b;
    const double bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}

}  // namespace

RollTrack::RollTrack() : keys_{RollKey{}} {}

RollTrack::RollTrack(std::span<const RollKey> keys, const RollTrackDef& def)
    : keys_(keys.begin(), keys.end()), interpolation_(def.interpolation), curves_(def.curves) {
    if (keys_.empty()) throw Error(roll_where("keys") + "needs at least 1 key");
    for (std::size_t i = 0; i < keys_.size(); ++i) {
        const std::string at = "keys[" + std::to_string(i) + "]";
        if (!std::isfinite(keys_[i].s) || !(keys_[i].s >= 0.0)) {
            throw Error(roll_where(at.c_str()) + "s must be finite and >= 0 (got " + detail::number_text(keys_[i].s) + ")");
        }
        if (!std::isfinite(keys_[i].roll)) {
            throw Error(roll_where(at.c_str()) + "roll must be finite (got " + detail::number_text(keys_[i].roll) + ")");
        }
        if (i > 0 && !(keys_[i].s > keys_[i - 1].s)) {
            throw Error(roll_where(at.c_str()) + "s must be greater than the previous key's (got " +
                        detail::number_text(keys_[i].s) + " after " + detail::number_text(keys_[i - 1].s) + ")");
        }
    }
    if (interpolation_ == RollInterpolation::curves) {
        if (!curves_.empty() && curves_.size() + 1 != keys_.size()) {
            throw Error(roll_where("curves") + "needs one curve per interval, " + std::to_string(keys_.size() - 1) +
                        " (got " + std::to_string(curves_.size()) + ")");
        }
    } else {
        if (!curves_.empty()) throw Error(roll_where("curves") + "only mode curves takes curves");
        if (!std::isfinite(def.start_slope)) throw Error(roll_where("start_slope") + "must be finite");
        if (!std::isfinite(def.end_slope)) throw Error(roll_where("end_slope") + "must be finite");
        if (keys_.size() >= 2) {
            second_ = spline_second_roll3(keys_, interpolation_ == RollInterpolation::clamped_spline, def.start_slope,
                                          def.end_slope);
        }
    }
}

double RollTrack::roll_at(double s) const noexcept {
    if (!(s > keys_.front().s)) return keys_.front().roll;  // NaN too
    if (s >= keys_.back().s) return keys_.back().roll;
    const auto it = std::upper_bound(keys_.begin(), keys_.end(), s, [](double v, const RollKey& k) { return v < k.s; });
    const std::size_t i = static_cast<std::size_t>(it - keys_.begin()) - 1;
    const RollKey& a = keys_[i];
    const RollKey& b = keys_[i + 1];
    const double h = b.s - a.s;
    const double t = (s - a.s) / h;
    if (interpolation_ == RollInterpolation::curves) {
        const double p = curves_.empty() ? t : curves_[i](t);
        // At p = 0 and p = 1 the keys come back exactly; equal keys give that value exactly.
        return p == 1.0 ? b.roll : a.roll + (b.roll - a.roll) * p;
    }
    const double ta = 1.0 - t;
    // A³ − A and B³ − B vanish exactly at t = 0 and t = 1, so the keys come back exactly.
    return ta * a.roll + t * b.roll + ((ta * ta * ta - ta) * second_[i] + (t * t * t - t) * second_[i + 1]) * (h * h / 6.0);
}

RolledFrames3::RolledFrames3(Frames3 frames, RollTrack roll) : frames_(std::move(frames)), roll_(std::move(roll)) {
    const double length = frames_.path().length();
    const double last = roll_.keys().back().s;
    // The keys' s are arc lengths of this path; rounding of a length computed elsewhere is let pass.
    if (last > length * (1.0 + 1e-12) + 1e-300) {
        throw Error("RolledFrames3: roll: the last key's s (" + detail::number_text(last) +
                    ") is beyond the path's length (" + detail::number_text(length) + ")");
    }
}

RolledFrames3::RolledFrames3(Path3 path, RollTrack roll, Vec3 up)
    : RolledFrames3(Frames3(std::move(path), FramesDef{.up = up}), std::move(roll)) {}

double RolledFrames3::roll(double u) const noexcept { return roll_.roll_at(frames_.length_at(u)); }

Frame3 RolledFrames3::frame(double u) const noexcept { return turned_roll3(frames_.frame(u), roll(u)); }

Frame3 RolledFrames3::frame_at_length(double s) const noexcept {
    return turned_roll3(frames_.frame(frames_.path().u_at_length(s)), roll_.roll_at(s));
}

namespace {

// The fields bank_angle and bank_track share; throws grape::Error naming the first bad one.
void check_bank3(const std::string& where, const BankDef& def) {
    if (!std::isfinite(def.speed) || !(def.speed >= 0.0)) {
        throw Error(where + "speed: must be finite and >= 0 (got " + detail::number_text(def.speed) + ")");
    }
    if (!std::isfinite(def.gravity) || !(def.gravity > 0.0)) {
        throw Error(where + "gravity: must be finite and > 0 (got " + detail::number_text(def.gravity) + ")");
    }
    if (!(def.max_angle >= 0.0 && def.max_angle <= 0.5 * std::numbers::pi)) {
        throw Error(where + "max_angle: must be in [0, pi/2] (got " + detail::number_text(def.max_angle) + ")");
    }
    if (!is_finite(def.up) || length(def.up) == 0.0) throw Error(where + "up: not finite or zero");
}

// The bank at u for a def already checked.
double bank3(const Path3& path, double u, const BankDef& def) noexcept {
    const Frenet3 f = path.frenet(u);
    if (!f.normal_defined) return 0.0;
    const Vec3 w = normalized(def.up);
    const Vec3 upright = normalized(w - f.tangent * dot(w, f.tangent));
    if (upright == Vec3{}) return 0.0;  // vertical: no upright frame to bank
    // The sideways unit of the upright frame (its binormal): a positive roll tilts the normal
    // toward it. The lateral curvature κ·(n·side) leans the vehicle toward the centre's side.
    const Vec3 side = cross(f.tangent, upright);
    const double lateral = f.curvature * dot(f.normal, side);
    const double bank = std::atan(def.speed * def.speed * std::abs(lateral) / def.gravity);
    return std::copysign(std::min(bank, def.max_angle), lateral);
}

}  // namespace

double bank_angle(const Path3& path, double u, const BankDef& def) {
    check_bank3("bank_angle: ", def);
    return bank3(path, u, def);
}

RollTrack bank_track(const Path3& path, const BankDef& def) {
    const std::string where = "bank_track: ";
    check_bank3(where, def);
    if (!std::isfinite(def.smoothing) || !(def.smoothing >= 0.0)) {
        throw Error(where + "smoothing: must be finite and >= 0 (got " + detail::number_text(def.smoothing) + ")");
    }
    if (def.samples < 2 || def.samples > (std::size_t{1} << 20)) {
        throw Error(where + "samples: must be in [2, 2^20] (got " + std::to_string(def.samples) + ")");
    }
    const double total = path.length();
    if (!(total > 0.0)) {
        const RollKey only{0.0, bank3(path, 0.0, def)};
        return RollTrack(std::span<const RollKey>(&only, 1));
    }
    const std::size_t n = def.samples;
    std::vector<RollKey> keys(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double s = k + 1 == n ? total : total * static_cast<double>(k) / static_cast<double>(n - 1);
        keys[k] = {s, bank3(path, path.u_at_length(s), def)};
    }
    const double step = total / static_cast<double>(n - 1);
    const auto half = static_cast<std::size_t>(std::floor(0.5 * def.smoothing / step));
    if (half > 0) {
        // Prefix sums carried as double-double (two-sum), so a window's mean is within a few
        // ulp of the mean of its samples however many samples precede it.
        std::vector<double> hi(n + 1, 0.0), lo(n + 1, 0.0);
        for (std::size_t k = 0; k < n; ++k) {
            const auto [s, e] = two_sum_roll3(hi[k], keys[k].roll);
            hi[k + 1] = s;
            lo[k + 1] = lo[k] + e;
        }
        std::vector<double> mean(n);
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t a = k >= half ? k - half : 0, b = std::min(n, k + half + 1);
            mean[k] = ((hi[b] - hi[a]) + (lo[b] - lo[a])) / static_cast<double>(b - a);
        }
        for (std::size_t k = 0; k < n; ++k) keys[k].roll = mean[k];
    }
    return RollTrack(keys);
}

}  // namespace grape
