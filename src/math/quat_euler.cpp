// Euler (Tait–Bryan) angles to and from unit quaternions, from half-angle sums and
// differences of the quaternion's components (Bernardes and Viollet, PLoS ONE 17(11), 2022).
#include <grape/error.hpp>
#include <grape/math.hpp>
#include <grape/quat.hpp>

#include <cmath>
#include <string>

namespace grape {

namespace {

struct EulerAxes {
    int i, j, k;  // the axes in the order they apply (0 x, 1 y, 2 z)
    double parity;  // +1 when (i, j, k) is a cyclic order of (x, y, z), −1 otherwise
};

EulerAxes euler_axes(EulerOrder order) noexcept {
    switch (order) {
    case EulerOrder::xyz: return {0, 1, 2, 1.0};
    case EulerOrder::xzy: return {0, 2, 1, -1.0};
    case EulerOrder::yxz: return {1, 0, 2, -1.0};
    case EulerOrder::yzx: return {1, 2, 0, 1.0};
    case EulerOrder::zxy: return {2, 0, 1, 1.0};
    case EulerOrder::zyx: break;
    }
    return {2, 1, 0, -1.0};
}

Quat euler_axis_turn(int axis, double angle) noexcept {
    const double c = std::cos(0.5 * angle), s = std::sin(0.5 * angle);
    return axis == 0 ? Quat{c, s, 0, 0} : axis == 1 ? Quat{c, 0, s, 0} : Quat{c, 0, 0, s};
}

double euler_component(const Quat& q, int axis) noexcept { return axis == 0 ? q.x : axis == 1 ? q.y : q.z; }

}  // namespace

Quat from_euler(const EulerAngles& angles, EulerOrder order) {
    if (!std::isfinite(angles.first)) throw Error("from_euler: first angle is not finite");
    if (!std::isfinite(angles.second)) throw Error("from_euler: second angle is not finite");
    if (!std::isfinite(angles.third)) throw Error("from_euler: third angle is not finite");
    const EulerAxes e = euler_axes(order);
    return euler_axis_turn(e.i, angles.first) * euler_axis_turn(e.j, angles.second) * euler_axis_turn(e.k, angles.third);
}

EulerAngles to_euler(const Quat& q, EulerOrder order) noexcept {
    // With c, s the cosines and sines of the half angles, q = q_i(α)·q_j(β)·q_k(γ) expands to
    //   w + ε·q_j = (c_β + ε·s_β)·cos((α + γ)/2),   q_i + q_k = (c_β + ε·s_β)·sin((α + γ)/2),
    //   w − ε·q_j = (c_β − ε·s_β)·cos((α − γ)/2),   q_i − q_k = (c_β − ε·s_β)·sin((α − γ)/2),
    // and (c_β + ε·s_β)/(c_β − ε·s_β) = tan(ε·β/2 + π/4).
    const EulerAxes e = euler_axes(order);
    const double qi = euler_component(q, e.i), qj = euler_component(q, e.j), qk = euler_component(q, e.k);
    const double sum_c = q.w + e.parity * qj, sum_s = qi + qk;
    const double diff_c = q.w - e.parity * qj, diff_s = qi - qk;
    const double sum_m = std::hypot(sum_c, sum_s), diff_m = std::hypot(diff_c, diff_s);
    const double half_pi = 0.5 * pi;
    EulerAngles a;
    a.second = e.parity * (2.0 * std::atan2(sum_m, diff_m) - half_pi);
    // Lock: one pair vanishes (its magnitude is √2·sin of the distance to the lock over two).
    constexpr double lock = 1e-12;
    const double scale = std::hypot(sum_m, diff_m);  // √2·|q|
    if (diff_m <= lock * scale) {
        a.first = 2.0 * std::atan2(sum_s, sum_c);
    } else if (sum_m <= lock * scale) {
        a.first = 2.0 * std::atan2(diff_s, diff_c);
    } else {
        const double half_sum = std::atan2(sum_s, sum_c), half_diff = std::atan2(diff_s, diff_c);
        a.first = half_sum + half_diff;
        a.third = half_sum - half_diff;
    }
    a.first = std::remainder(a.first, 2.0 * pi);
    a.third = std::remainder(a.third, 2.0 * pi);
    return a;
}

}  // namespace grape
