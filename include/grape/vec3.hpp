// grape — Vec3: a 3-D vector or point, with the same operators and helpers as Vec2.
#pragma once

#include <algorithm>
#include <cmath>

namespace grape {

/// A 3-D vector or point in world units (right-handed axes).
struct Vec3 {
    double x = 0.0;  ///< first component
    double y = 0.0;  ///< second component
    double z = 0.0;  ///< third component

    /// Adds o componentwise.
    constexpr Vec3& operator+=(Vec3 o) noexcept { x += o.x; y += o.y; z += o.z; return *this; }
    /// Subtracts o componentwise.
    constexpr Vec3& operator-=(Vec3 o) noexcept { x -= o.x; y -= o.y; z -= o.z; return *this; }
    /// Scales by s.
    constexpr Vec3& operator*=(double s) noexcept { x *= s; y *= s; z *= s; return *this; }
    /// Divides by s.
    constexpr Vec3& operator/=(double s) noexcept { x /= s; y /= s; z /= s; return *this; }
    /// Componentwise equality (exact).
    friend constexpr bool operator==(Vec3, Vec3) noexcept = default;
};

/// Componentwise sum.
constexpr Vec3 operator+(Vec3 a, Vec3 b) noexcept { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
/// Componentwise difference.
constexpr Vec3 operator-(Vec3 a, Vec3 b) noexcept { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
/// Negation.
constexpr Vec3 operator-(Vec3 a) noexcept { return {-a.x, -a.y, -a.z}; }
/// a scaled by s.
constexpr Vec3 operator*(Vec3 a, double s) noexcept { return {a.x * s, a.y * s, a.z * s}; }
/// a scaled by s.
constexpr Vec3 operator*(double s, Vec3 a) noexcept { return {a.x * s, a.y * s, a.z * s}; }
/// a divided by s.
constexpr Vec3 operator/(Vec3 a, double s) noexcept { return {a.x / s, a.y / s, a.z / s}; }

/// Dot product.
constexpr double dot(Vec3 a, Vec3 b) noexcept { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// Cross product a × b (right-handed: x × y = z).
constexpr Vec3 cross(Vec3 a, Vec3 b) noexcept {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// |a|², exact for exact inputs (no square root).
constexpr double length_squared(Vec3 a) noexcept { return dot(a, a); }
/// |a|, without overflow or underflow for huge or tiny components. (Not the three-argument
/// std::hypot: some standard libraries compute it without scaling, and it overflows.)
inline double length(Vec3 a) noexcept {
    const double s = dot(a, a);
    if (s >= 0x1p-960 && s <= 0x1p960) return std::sqrt(s);  // no square lost or overflowed
    if (std::isnan(s)) return s;
    const double m = std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z)});
    if (m == 0.0 || std::isinf(m)) return m;
    const Vec3 b{a.x / m, a.y / m, a.z / m};
    return m * std::sqrt(dot(b, b));
}
/// |a − b|.
inline double distance(Vec3 a, Vec3 b) noexcept { return length(a - b); }
/// a / |a|; the zero vector stays zero (no NaN).
inline Vec3 normalized(Vec3 a) noexcept {
    const double l = length(a);
    return l > 0.0 ? a / l : Vec3{};
}
/// (1 − t)·a + t·b: exactly a at t = 0 and exactly b at t = 1; t outside [0, 1] extrapolates.
constexpr Vec3 lerp(Vec3 a, Vec3 b, double t) noexcept { return a * (1.0 - t) + b * t; }
/// |a − b| ≤ tolerance in every component.
constexpr bool approx_equal(Vec3 a, Vec3 b, double tolerance = 1e-12) noexcept {
    const Vec3 d = a - b;
    return (d.x <= tolerance && -d.x <= tolerance) && (d.y <= tolerance && -d.y <= tolerance) &&
           (d.z <= tolerance && -d.z <= tolerance);
}
/// Every component finite (not NaN, not ±inf).
inline bool is_finite(Vec3 a) noexcept { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }
/// A unit vector perpendicular to the unit vector a, chosen deterministically (from the axis
/// along which a is smallest); (1, 0, 0) turned away from a if a is zero.
inline Vec3 any_perpendicular(Vec3 a) noexcept {
    const double ax = std::abs(a.x), ay = std::abs(a.y), az = std::abs(a.z);
    const Vec3 e = ax <= ay && ax <= az ? Vec3{1, 0, 0} : ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
    return normalized(e - a * dot(e, a));
}

}  // namespace grape
