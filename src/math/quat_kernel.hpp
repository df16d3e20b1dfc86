// Internal pieces shared by the quaternion files: sin(x)/x, and exp and log on half-angle
// vectors (the quaternion exponential of a pure quaternion and its inverse).
#pragma once

#include <grape/quat.hpp>

#include <cmath>

namespace grape::detail {

/// sin(x)/x, 1 at 0. Below 2⁻¹³ the series 1 − x²/6 + x⁴/120 is exact to rounding (the next
/// term, x⁶/5040, is under 2⁻⁹⁰); above it the quotient is within two ulp.
inline double sinc(double x) noexcept {
    const double x2 = x * x;
    if (x2 < 0x1p-26) return 1.0 - x2 * (1.0 / 6.0 - x2 * (1.0 / 120.0));
    return std::sin(x) / x;
}

/// exp of the pure quaternion (0, v): (cos |v|, sinc(|v|)·v), the rotation by 2|v| about v.
/// Exactly the identity for v = 0.
inline Quat exp_half(Vec3 v) noexcept {
    const double a = length(v);
    const double s = sinc(a);
    return {std::cos(a), s * v.x, s * v.y, s * v.z};
}

/// log of a unit quaternion as its half-angle vector, from q as given (its sign kept: a q with
/// w < 0 gives a half angle above π/2). atan2(|u|, w)/|u| by its series where |u| is tiny.
inline Vec3 log_half(const Quat& q) noexcept {
    const Vec3 u{q.x, q.y, q.z};
    const double s = length(u);
    // atan(s/w) = s/w·(1 − (s/w)²/3 + ...): below 2⁻²⁷ the dropped term is under an ulp.
    const double k = s < 0x1p-27 * std::abs(q.w) ? 1.0 / q.w : std::atan2(s, q.w) / s;
    return u * k;
}

}  // namespace grape::detail
