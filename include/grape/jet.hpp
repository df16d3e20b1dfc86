// grape — math: Jet2, forward-mode automatic differentiation in two variables (value,
// gradient and Hessian), so a function C(x, y) written once as a template gives its
// derivatives exactly. Standard library only. Used by the dynamics' implicit curves.
#pragma once

#include <cmath>

namespace grape {

/// \addtogroup math
/// @{

// ---------------------------------------------------------------------------------------
// Forward-mode automatic differentiation in two variables (value, gradient, Hessian)
// ---------------------------------------------------------------------------------------

/// A number carrying its gradient and Hessian with respect to (x, y): write an implicit curve
/// once as a template `C(x, y)` and get ∇C and the Hessian exactly (no finite differences).
struct Jet2 {
    double v = 0.0;    ///< value
    double gx = 0.0;   ///< ∂/∂x
    double gy = 0.0;   ///< ∂/∂y
    double hxx = 0.0;  ///< ∂²/∂x²
    double hxy = 0.0;  ///< ∂²/∂x∂y
    double hyy = 0.0;  ///< ∂²/∂y²

    constexpr Jet2() noexcept = default;
    /// A constant (zero derivatives).
    constexpr Jet2(double value) noexcept : v(value) {}  // NOLINT: implicit on purpose
    /// A value with its gradient (dx, dy) and Hessian (dxx, dxy, dyy).
    constexpr Jet2(double value, double dx, double dy, double dxx = 0.0, double dxy = 0.0,
                   double dyy = 0.0) noexcept
        : v(value), gx(dx), gy(dy), hxx(dxx), hxy(dxy), hyy(dyy) {}
    /// The independent variable x at `value`.
    static constexpr Jet2 x(double value) noexcept { return {value, 1.0, 0.0}; }
    /// The independent variable y at `value`.
    static constexpr Jet2 y(double value) noexcept { return {value, 0.0, 1.0}; }
};

namespace detail {
// f(a) by the chain rule, given f, f′ and f″ at a.v: ∇f = f′∇a, H f = f″ ∇a∇aᵀ + f′ H a.
constexpr Jet2 chain(const Jet2& a, double f, double f1, double f2) noexcept {
    return {f,
            f1 * a.gx,
            f1 * a.gy,
            f2 * a.gx * a.gx + f1 * a.hxx,
            f2 * a.gx * a.gy + f1 * a.hxy,
            f2 * a.gy * a.gy + f1 * a.hyy};
}
}  // namespace detail

/// Sum.
constexpr Jet2 operator+(const Jet2& a, const Jet2& b) noexcept {
    return {a.v + b.v, a.gx + b.gx, a.gy + b.gy, a.hxx + b.hxx, a.hxy + b.hxy, a.hyy + b.hyy};
}
/// Difference.
constexpr Jet2 operator-(const Jet2& a, const Jet2& b) noexcept {
    return {a.v - b.v, a.gx - b.gx, a.gy - b.gy, a.hxx - b.hxx, a.hxy - b.hxy, a.hyy - b.hyy};
}
/// Negation.
constexpr Jet2 operator-(const Jet2& a) noexcept { return {-a.v, -a.gx, -a.gy, -a.hxx, -a.hxy, -a.hyy}; }
/// Product (product rule to second order).
constexpr Jet2 operator*(const Jet2& a, const Jet2& b) noexcept {
    return {a.v * b.v,
            a.gx * b.v + a.v * b.gx,
            a.gy * b.v + a.v * b.gy,
            a.hxx * b.v + 2.0 * a.gx * b.gx + a.v * b.hxx,
            a.hxy * b.v + a.gx * b.gy + a.gy * b.gx + a.v * b.hxy,
            a.hyy * b.v + 2.0 * a.gy * b.gy + a.v * b.hyy};
}
/// Quotient (b.v ≠ 0).
constexpr Jet2 operator/(const Jet2& a, const Jet2& b) noexcept {
    const double r = 1.0 / b.v;
    return a * detail::chain(b, r, -r * r, 2.0 * r * r * r);
}
constexpr Jet2& operator+=(Jet2& a, const Jet2& b) noexcept { return a = a + b; }  ///< a = a + b
constexpr Jet2& operator-=(Jet2& a, const Jet2& b) noexcept { return a = a - b; }  ///< a = a − b
constexpr Jet2& operator*=(Jet2& a, const Jet2& b) noexcept { return a = a * b; }  ///< a = a · b
constexpr Jet2& operator/=(Jet2& a, const Jet2& b) noexcept { return a = a / b; }  ///< a = a / b
/// √a (a > 0 where differentiated).
inline Jet2 sqrt(const Jet2& a) noexcept {
    const double s = std::sqrt(a.v);
    return detail::chain(a, s, 0.5 / s, -0.25 / (s * a.v));
}
/// sin a.
inline Jet2 sin(const Jet2& a) noexcept {
    const double s = std::sin(a.v), c = std::cos(a.v);
    return detail::chain(a, s, c, -s);
}
/// cos a.
inline Jet2 cos(const Jet2& a) noexcept {
    const double s = std::sin(a.v), c = std::cos(a.v);
    return detail::chain(a, c, -s, -c);
}
/// eᵃ.
inline Jet2 exp(const Jet2& a) noexcept {
    const double e = std::exp(a.v);
    return detail::chain(a, e, e, e);
}
/// Natural logarithm (a > 0).
inline Jet2 log(const Jet2& a) noexcept { return detail::chain(a, std::log(a.v), 1.0 / a.v, -1.0 / (a.v * a.v)); }
/// aⁿ for a real exponent (a > 0 unless n is a whole number).
inline Jet2 pow(const Jet2& a, double n) noexcept {
    const double p2 = std::pow(a.v, n - 2.0);
    return detail::chain(a, p2 * a.v * a.v, n * p2 * a.v, n * (n - 1.0) * p2);
}

/// @}

}  // namespace grape
