// grape — Quat: unit quaternions for 3-D orientation. Products, rotating vectors, bases and
// frames (Shepperd's method), axis-angle, rotation vectors, Euler angles in a named order,
// shortest-arc slerp and Shoemake's squad. Typed animations of a Quat member slerp.
//
//   grape::Quat q = grape::from_axis_angle({0, 0, 1}, grape::pi / 2);  // a quarter turn about z
//   grape::Vec3 v = grape::rotate(q, {1, 0, 0});                       // (0, 1, 0) within an ulp
//   engine.animate(ship, &Ship::orientation, grape::from_to(q0, q1), 2.0);
#pragma once

#include <grape/export_math.hpp>
#include <grape/math.hpp>
#include <grape/vec3.hpp>

#include <cmath>

namespace grape {

/// \addtogroup quat
/// @{

/// A quaternion w + x·i + y·j + z·k; as an orientation, a unit one (|q| = 1) rotating by angle
/// θ about the unit axis n is (cos θ/2, sin θ/2·n), and q and −q are the same rotation. The
/// default is the identity (no rotation). Products compose right to left: rotate(a * b, v) is
/// rotate(a, rotate(b, v)).
struct Quat {
    double w = 1.0;  ///< scalar part: cos θ/2 for a unit quaternion
    double x = 0.0;  ///< i component
    double y = 0.0;  ///< j component
    double z = 0.0;  ///< k component
    /// Componentwise equality (exact): q and −q are the same rotation but not equal here.
    friend constexpr bool operator==(const Quat&, const Quat&) noexcept = default;
};

/// The Hamilton product a·b: the rotation b, then a.
constexpr Quat operator*(const Quat& a, const Quat& b) noexcept {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
/// Every component negated: the same rotation.
constexpr Quat operator-(const Quat& q) noexcept { return {-q.w, -q.x, -q.y, -q.z}; }
/// q scaled by s (componentwise).
constexpr Quat operator*(const Quat& q, double s) noexcept { return {q.w * s, q.x * s, q.y * s, q.z * s}; }
/// q scaled by s (componentwise).
constexpr Quat operator*(double s, const Quat& q) noexcept { return q * s; }
/// The conjugate (w, −x, −y, −z): for a unit quaternion its inverse, the opposite rotation.
constexpr Quat conjugate(const Quat& q) noexcept { return {q.w, -q.x, -q.y, -q.z}; }
/// The 4-D dot product: cos of half the angle between two unit rotations (up to sign).
constexpr double dot(const Quat& a, const Quat& b) noexcept { return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z; }
/// The vector part (x, y, z).
constexpr Vec3 vector_part(const Quat& q) noexcept { return {q.x, q.y, q.z}; }
/// |q|, without overflow or underflow for huge or tiny components.
GRAPE_MATH_API double length(const Quat& q) noexcept;
/// q / |q|; the identity where |q| is zero or not finite (no NaN).
GRAPE_MATH_API Quat normalized(const Quat& q) noexcept;
/// Every component finite.
inline bool is_finite(const Quat& q) noexcept {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}
/// v rotated by the unit quaternion q (q·v·q*, computed as v + 2w(u × v) + 2u × (u × v) with u
/// the vector part: 15 multiplications, no matrix).
constexpr Vec3 rotate(const Quat& q, Vec3 v) noexcept {
    const Vec3 u{q.x, q.y, q.z};
    const Vec3 t = 2.0 * cross(u, v);
    return v + q.w * t + cross(u, t);
}

/// The unit quaternion (w, x, y, z) / |(w, x, y, z)|. Throws grape::Error naming the argument
/// when a component is not finite or all four are zero.
GRAPE_MATH_API Quat unit_quat(double w, double x, double y, double z);

/// The rotation by `angle` radians about `axis` (right-handed: counter-clockwise looking down
/// the axis toward the origin). Throws grape::Error when axis is zero or not finite, or angle
/// is not finite.
GRAPE_MATH_API Quat from_axis_angle(Vec3 axis, double angle);
/// An axis and an angle of a rotation.
struct AxisAngle {
    Vec3 axis{1.0, 0.0, 0.0};  ///< unit axis
    double angle = 0.0;        ///< radians, in [0, π]
};
/// The axis and angle of the unit quaternion q, the angle in [0, π] (q or −q, whichever has
/// w ≥ 0); the axis is (1, 0, 0) for the identity. Accurate at small angles (atan2, not acos).
GRAPE_MATH_API AxisAngle axis_angle(const Quat& q) noexcept;

/// The rotation by |r| radians about r / |r| (a rotation vector, "exponential map"); the
/// identity for r = 0. r finite; accurate for small |r| (no division by |r|).
GRAPE_MATH_API Quat from_rotation_vector(Vec3 r) noexcept;
/// The rotation vector of the unit quaternion q: axis times angle, the angle in [0, π] (q or
/// −q, whichever has w ≥ 0). Inverse of from_rotation_vector for |r| < π.
GRAPE_MATH_API Vec3 rotation_vector(const Quat& q) noexcept;
/// One step of integrating an angular velocity `omega` (world axes, rad per unit of time) held
/// constant for `dt`: normalized(from_rotation_vector(omega·dt) · q). Exact for a constant
/// omega up to rounding, which the renormalization keeps from growing: |q| stays 1 within a
/// few ulp over any number of steps.
GRAPE_MATH_API Quat integrate_rotation(const Quat& q, Vec3 omega, double dt) noexcept;

/// The three axes of a rotation: where it takes (1, 0, 0), (0, 1, 0) and (0, 0, 1); the columns
/// of its matrix.
struct Basis {
    Vec3 x{1.0, 0.0, 0.0};  ///< image of the first axis
    Vec3 y{0.0, 1.0, 0.0};  ///< image of the second axis
    Vec3 z{0.0, 0.0, 1.0};  ///< image of the third axis
};
/// The rotation taking the world axes to the right-handed orthonormal basis (x, y, z), by
/// Shepperd's method (from whichever of 4w², 4x², 4y², 4z² is largest, so no division by a
/// small number), normalized, with w ≥ 0. Throws grape::Error naming the axis when one is not
/// finite, when the basis is not orthonormal within 1e-5 (each |aᵢ·aⱼ − δᵢⱼ|: float data
/// passes), or when it is left-handed (x × y = −z, a reflection).
GRAPE_MATH_API Quat from_basis(Vec3 x, Vec3 y, Vec3 z);
/// from_basis without its checks, noexcept, for bases orthonormal by construction (frames of
/// a Frames3, to_basis): any other input gives a unit quaternion of no particular meaning.
GRAPE_MATH_API Quat from_basis_unchecked(Vec3 x, Vec3 y, Vec3 z) noexcept;
/// from_basis(b.x, b.y, b.z).
inline Quat from_basis(const Basis& b) { return from_basis(b.x, b.y, b.z); }
/// The basis of the unit quaternion q (the columns of its rotation matrix), orthonormal within
/// a few ulp for |q| = 1; from_basis(to_basis(q)) is ±q within a few ulp.
GRAPE_MATH_API Basis to_basis(const Quat& q) noexcept;

/// The order of three Tait–Bryan angles, named by the axes in the order they apply,
/// intrinsically: the first rotation about the named world axis, the second about the once
/// rotated second axis, the third about the twice rotated third axis. Intrinsic x-y-z is the
/// same rotation as extrinsic (fixed axes) z-y-x with the same angles: R = R_x(first)·
/// R_y(second)·R_z(third).
enum class EulerOrder {
    xyz,  ///< R_x(first)·R_y(second)·R_z(third)
    xzy,  ///< R_x(first)·R_z(second)·R_y(third)
    yxz,  ///< R_y(first)·R_x(second)·R_z(third)
    yzx,  ///< R_y(first)·R_z(second)·R_x(third)
    zxy,  ///< R_z(first)·R_x(second)·R_y(third)
    zyx,  ///< R_z(first)·R_y(second)·R_x(third): yaw, pitch, roll (aerospace, z up)
};
/// Three angles in radians, in the order of an EulerOrder.
struct EulerAngles {
    double first = 0.0;   ///< about the order's first axis (yaw for zyx)
    double second = 0.0;  ///< about its second axis (pitch for zyx), in [−π/2, π/2] from to_euler
    double third = 0.0;   ///< about its third axis (roll for zyx)
};
/// The rotation of the angles in `order` (the product of three axis rotations). Throws
/// grape::Error naming the angle when one is not finite.
GRAPE_MATH_API Quat from_euler(const EulerAngles& angles, EulerOrder order);
/// The angles in `order` of the unit quaternion q: first and third in [−π, π], second in
/// [−π/2, π/2], read from half-angle sums and differences (Bernardes and Viollet, PLoS ONE
/// 2022), so accurate up to the lock. Gimbal lock (second = ±π/2, where only first ± third is
/// defined), taken as within 1e-12 of it in the half-angle sines (a rotation error below
/// 5e-12 rad): third is 0 and first carries the whole turn, the same for q and −q.
GRAPE_MATH_API EulerAngles to_euler(const Quat& q, EulerOrder order) noexcept;

/// Shortest-arc spherical linear interpolation between two unit quaternions, prepared once:
/// b is replaced by −b when a·b < 0 (the same rotation, so the turn is at most half a turn),
/// the angle Ω between them is 2·atan2(|a − b|, |a + b|) (accurate at 0 and at π/2), and
///   slerp(t) = (1 − t)·sinc((1 − t)Ω)/sinc(Ω)·a + t·sinc(tΩ)/sinc(Ω)·b,
/// the usual sin((1 − t)Ω)/sin Ω form without its division by sin Ω ≈ 0. The angle from a
/// grows linearly in t; t = 0 gives a exactly, t = 1 gives b or −b exactly (b's sign when
/// a·b ≥ 0); t outside [0, 1] extrapolates along the same great circle.
class GRAPE_MATH_API Slerp {
public:
    Slerp() noexcept = default;  ///< identity to identity
    Slerp(const Quat& a, const Quat& b) noexcept;  ///< from a to b (or −b) on the shortest arc
    Quat operator()(double t) const noexcept;      ///< the rotation at t
    /// Half the rotation angle from a to the end: Ω in [0, π/2], radians.
    double half_angle() const noexcept { return omega_; }

private:
    Quat a_, b_;
    double omega_ = 0.0;
    double sinc_omega_ = 1.0;
};
/// Slerp(a, b)(t), bit for bit.
GRAPE_MATH_API Quat slerp(const Quat& a, const Quat& b, double t) noexcept;

/// Shoemake's inner control point for key q between prev and next (SIGGRAPH 1985):
/// q·exp(−(log(q⁻¹·next) + log(q⁻¹·prev))/4), each log on the shortest arc. At the first or
/// last key pass the key itself as its missing neighbour.
GRAPE_MATH_API Quat squad_control(const Quat& prev, const Quat& q, const Quat& next) noexcept;
/// Shoemake's spherical quadrangle interpolation from q0 to q1 with inner control points s0,
/// s1 (squad_control): slerp(slerp(q0, q1, t), slerp(s0, s1, t), 2t(1 − t)). Exactly q0 at
/// t = 0 and ±q1 at t = 1; C¹ across keys when each segment uses its keys' control points.
GRAPE_MATH_API Quat squad(const Quat& q0, const Quat& q1, const Quat& s0, const Quat& s1, double t) noexcept;

/// @}

/// \cond
template <class V>
struct Interpolate;
/// \endcond

/// Typed animations of a Quat member slerp on the shortest arc (grape/value.hpp): from_to(a,
/// b) ends on b or −b (the same rotation), to(b) from the member's current value, and by(d)
/// composes, from · d: d is a rotation in the object's own axes, applied before `from`
/// (rotate(from · d, v) = rotate(from, rotate(d, v))).
template <>
struct Interpolate<Quat> {
    /// slerp(a, b, t).
    static Quat lerp(const Quat& a, const Quat& b, double t) noexcept { return slerp(a, b, t); }
    /// The ends prepared once: Slerp(a, b)(t) is slerp(a, b, t) bit for bit.
    static Slerp prepare(const Quat& a, const Quat& b) noexcept { return Slerp(a, b); }
    /// The end of by(amount): from · amount, normalized.
    static Quat compose(const Quat& from, const Quat& amount) noexcept { return normalized(from * amount); }
};

}  // namespace grape
