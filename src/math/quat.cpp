// Unit quaternions: lengths, factories, axis-angle, rotation vectors, bases, slerp and squad.
#include <grape/error.hpp>
#include <grape/quat.hpp>

#include "math/quat_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace grape {

namespace {

// The rotation matrix's entry (row r, column c) of a basis whose columns are the axes.
struct QuatColumns {
    const Vec3& x;
    const Vec3& y;
    const Vec3& z;
    double m(int r, int c) const noexcept {
        const Vec3& v = c == 0 ? x : c == 1 ? y : z;
        return r == 0 ? v.x : r == 1 ? v.y : v.z;
    }
};

void check_axis_finite(Vec3 v, const char* name) {
    if (!is_finite(v)) throw Error(std::string("from_basis: ") + name + " is not finite");
}

}  // namespace

double length(const Quat& q) noexcept {
    const double s = dot(q, q);
    if (s >= 0x1p-960 && s <= 0x1p960) return std::sqrt(s);  // no square lost or overflowed
    if (std::isnan(s)) return s;
    const double m = std::max({std::abs(q.w), std::abs(q.x), std::abs(q.y), std::abs(q.z)});
    if (m == 0.0 || std::isinf(m)) return m;
    const Quat b{q.w / m, q.x / m, q.y / m, q.z / m};  // not q·(1/m): 1/m overflows for subnormal m
    return m * std::sqrt(dot(b, b));
}

Quat normalized(const Quat& q) noexcept {
    const double l = length(q);
    if (!(l > 0.0) || !std::isfinite(l)) return Quat{};
    return {q.w / l, q.x / l, q.y / l, q.z / l};
}

Quat unit_quat(double w, double x, double y, double z) {
    const double c[4] = {w, x, y, z};
    const char* names[4] = {"w", "x", "y", "z"};
    for (int i = 0; i < 4; ++i)
        if (!std::isfinite(c[i])) throw Error(std::string("unit_quat: ") + names[i] + " is not finite");
    if (w == 0.0 && x == 0.0 && y == 0.0 && z == 0.0) throw Error("unit_quat: all four components are zero");
    return normalized(Quat{w, x, y, z});
}

Quat from_axis_angle(Vec3 axis, double angle) {
    if (!is_finite(axis)) throw Error("from_axis_angle: axis is not finite");
    if (axis == Vec3{}) throw Error("from_axis_angle: axis is zero");
    if (!std::isfinite(angle)) throw Error("from_axis_angle: angle is not finite");
    const Vec3 n = normalized(axis);
    const double s = std::sin(0.5 * angle);
    return {std::cos(0.5 * angle), s * n.x, s * n.y, s * n.z};
}

AxisAngle axis_angle(const Quat& q) noexcept {
    const Quat p = q.w < 0.0 ? -q : q;
    const Vec3 u = vector_part(p);
    const double s = length(u);
    if (s == 0.0) return {};
    return {u / s, 2.0 * std::atan2(s, p.w)};
}

Quat from_rotation_vector(Vec3 r) noexcept { return detail::exp_half(0.5 * r); }

Vec3 rotation_vector(const Quat& q) noexcept { return 2.0 * detail::log_half(q.w < 0.0 ? -q : q); }

Quat integrate_rotation(const Quat& q, Vec3 omega, double dt) noexcept {
    return normalized(from_rotation_vector(omega * dt) * q);
}

Quat from_basis(Vec3 x, Vec3 y, Vec3 z) {
    check_axis_finite(x, "x");
    check_axis_finite(y, "y");
    check_axis_finite(z, "z");
    // float data is orthonormal to ~1e-7 per entry; 1e-5 leaves room for a few float steps.
    constexpr double tolerance = 1e-5;
    const Vec3* axes[3] = {&x, &y, &z};
    const char* names[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) {
            const double g = dot(*axes[i], *axes[j]) - (i == j ? 1.0 : 0.0);
            if (!(std::abs(g) <= tolerance))
                throw Error(std::string("from_basis: ") + names[i] + (i == j ? " is not of unit length" : " is not perpendicular to ") +
                            (i == j ? "" : names[j]) + " (within 1e-5)");
        }
    if (dot(cross(x, y), z) < 0.0) throw Error("from_basis: x, y, z is left-handed (a reflection, not a rotation)");
    return from_basis_unchecked(x, y, z);
}

Quat from_basis_unchecked(Vec3 x, Vec3 y, Vec3 z) noexcept {
    const QuatColumns c{x, y, z};
    const double m00 = c.m(0, 0), m11 = c.m(1, 1), m22 = c.m(2, 2);
    // 4w², 4x², 4y², 4z², each from the diagonal; the largest is at least 1 (they sum to 4).
    const double f[4] = {1.0 + m00 + m11 + m22, 1.0 + m00 - m11 - m22, 1.0 - m00 + m11 - m22, 1.0 - m00 - m11 + m22};
    int k = 0;
    for (int i = 1; i < 4; ++i)
        if (f[i] > f[k]) k = i;
    const double r = 0.5 * std::sqrt(f[k]);  // the largest component, at least 1/2
    const double s = 0.25 / r;
    Quat q;
    switch (k) {
    case 0:
        q = {r, (c.m(2, 1) - c.m(1, 2)) * s, (c.m(0, 2) - c.m(2, 0)) * s, (c.m(1, 0) - c.m(0, 1)) * s};
        break;
    case 1:
        q = {(c.m(2, 1) - c.m(1, 2)) * s, r, (c.m(0, 1) + c.m(1, 0)) * s, (c.m(0, 2) + c.m(2, 0)) * s};
        break;
    case 2:
        q = {(c.m(0, 2) - c.m(2, 0)) * s, (c.m(0, 1) + c.m(1, 0)) * s, r, (c.m(1, 2) + c.m(2, 1)) * s};
        break;
    default:
        q = {(c.m(1, 0) - c.m(0, 1)) * s, (c.m(0, 2) + c.m(2, 0)) * s, (c.m(1, 2) + c.m(2, 1)) * s, r};
        break;
    }
    q = normalized(q);
    return q.w < 0.0 ? -q : q;
}

Basis to_basis(const Quat& q) noexcept {
    const double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    const double xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    const double wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    return {{1.0 - 2.0 * (yy + zz), 2.0 * (xy + wz), 2.0 * (xz - wy)},
            {2.0 * (xy - wz), 1.0 - 2.0 * (xx + zz), 2.0 * (yz + wx)},
            {2.0 * (xz + wy), 2.0 * (yz - wx), 1.0 - 2.0 * (xx + yy)}};
}

Slerp::Slerp(const Quat& a, const Quat& b) noexcept : a_(a), b_(dot(a, b) < 0.0 ? -b : b) {
    const Quat d{a_.w - b_.w, a_.x - b_.x, a_.y - b_.y, a_.z - b_.z};
    const Quat s{a_.w + b_.w, a_.x + b_.x, a_.y + b_.y, a_.z + b_.z};
    omega_ = 2.0 * std::atan2(length(d), length(s));
    sinc_omega_ = detail::sinc(omega_);
}

Quat Slerp::operator()(double t) const noexcept {
    const double ca = (1.0 - t) * detail::sinc((1.0 - t) * omega_) / sinc_omega_;
    const double cb = t * detail::sinc(t * omega_) / sinc_omega_;
    return {ca * a_.w + cb * b_.w, ca * a_.x + cb * b_.x, ca * a_.y + cb * b_.y, ca * a_.z + cb * b_.z};
}

Quat slerp(const Quat& a, const Quat& b, double t) noexcept { return Slerp(a, b)(t); }

Quat squad_control(const Quat& prev, const Quat& q, const Quat& next) noexcept {
    const Quat qi = conjugate(q);
    Quat to_next = qi * next, to_prev = qi * prev;
    if (to_next.w < 0.0) to_next = -to_next;  // the shortest arcs
    if (to_prev.w < 0.0) to_prev = -to_prev;
    const Vec3 l = detail::log_half(to_next) + detail::log_half(to_prev);
    return q * detail::exp_half(-0.25 * l);
}

Quat squad(const Quat& q0, const Quat& q1, const Quat& s0, const Quat& s1, double t) noexcept {
    return slerp(slerp(q0, q1, t), slerp(s0, s1, t), 2.0 * t * (1.0 - t));
}

}  // namespace grape
