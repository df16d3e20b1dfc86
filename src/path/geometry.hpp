// grape — small numeric helpers shared by the path kinds.
#pragma once

#include <grape/math.hpp>

#include <cmath>

namespace grape::detail {

/// A parameter just inside [a, b) from the right: d1 at a break b belongs to the piece that
/// starts there, so step back by a relative hair that floor() still sees.
inline double inside_right(double a, double b) noexcept {
    const double v = b - (b - a) * 1e-12;
    return v < b ? v : std::nextafter(b, a);
}

/// Real roots of a·t² + b·t + c = 0 into roots[0..1] (a may be 0); returns how many.
/// Uses the cancellation-free form q = −(b + sign(b)·√disc)/2.
inline int quadratic_roots(double a, double b, double c, double roots[2]) noexcept {
    if (a == 0.0) {
        if (b == 0.0) return 0;
        roots[0] = -c / b;
        return 1;
    }
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return 0;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    if (q == 0.0) {  // b == 0 and c == 0
        roots[0] = 0.0;
        return 1;
    }
    roots[0] = q / a;
    roots[1] = c / q;
    return 2;
}

/// ∫ √(τ² + k²) dτ from 0 to x (k ≥ 0): ½[x√(x² + k²) + k²·asinh(x/k)].
inline double hyperbolic_length(double x, double k) noexcept {
    const double r = std::hypot(x, k);
    return k > 0.0 ? 0.5 * (x * r + k * k * std::asinh(x / k)) : 0.5 * x * std::abs(x);
}

}  // namespace grape::detail
