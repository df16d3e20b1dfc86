// grape — math: Vec2, Gauss–Legendre quadrature and a safeguarded scalar root finder.
// Header-only templates so the integrand and the function inline; no allocation.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace grape {

/// \addtogroup math
/// @{

/// π to double precision.
inline constexpr double pi = 3.141592653589793238462643383279502884;

/// A 2-D vector or point in world units (screen convention: y points down).
struct Vec2 {
    double x = 0.0;  ///< world units, to the right
    double y = 0.0;  ///< world units, down

    constexpr Vec2& operator+=(Vec2 o) noexcept { x += o.x; y += o.y; return *this; }  ///< adds o componentwise
    constexpr Vec2& operator-=(Vec2 o) noexcept { x -= o.x; y -= o.y; return *this; }  ///< subtracts o componentwise
    constexpr Vec2& operator*=(double s) noexcept { x *= s; y *= s; return *this; }  ///< scales both components by s
    constexpr Vec2& operator/=(double s) noexcept { x /= s; y /= s; return *this; }  ///< divides both components by s
    friend constexpr bool operator==(Vec2, Vec2) noexcept = default;  ///< both components equal (exact)
};

constexpr Vec2 operator+(Vec2 a, Vec2 b) noexcept { return {a.x + b.x, a.y + b.y}; }  ///< componentwise sum
constexpr Vec2 operator-(Vec2 a, Vec2 b) noexcept { return {a.x - b.x, a.y - b.y}; }  ///< componentwise difference
constexpr Vec2 operator-(Vec2 a) noexcept { return {-a.x, -a.y}; }  ///< both components negated
constexpr Vec2 operator*(Vec2 a, double s) noexcept { return {a.x * s, a.y * s}; }  ///< a scaled by s
constexpr Vec2 operator*(double s, Vec2 a) noexcept { return {a.x * s, a.y * s}; }  ///< a scaled by s
constexpr Vec2 operator/(Vec2 a, double s) noexcept { return {a.x / s, a.y / s}; }  ///< a divided by s

/// Dot product.
constexpr double dot(Vec2 a, Vec2 b) noexcept { return a.x * b.x + a.y * b.y; }
/// z of the 3-D cross product: positive when b turns counter-clockwise from a (in y-up axes).
constexpr double cross(Vec2 a, Vec2 b) noexcept { return a.x * b.y - a.y * b.x; }
/// |a|², exact for exact inputs (no square root).
constexpr double length_squared(Vec2 a) noexcept { return dot(a, a); }
/// |a|, without overflow or underflow for huge or tiny components.
inline double length(Vec2 a) noexcept { return std::hypot(a.x, a.y); }
/// |a − b|.
inline double distance(Vec2 a, Vec2 b) noexcept { return length(a - b); }
/// a / |a|; the zero vector stays zero (no NaN).
inline Vec2 normalized(Vec2 a) noexcept {
    const double l = length(a);
    return l > 0.0 ? a / l : Vec2{};
}
/// a turned a quarter turn: (−y, x).
constexpr Vec2 perpendicular(Vec2 a) noexcept { return {-a.y, a.x}; }
/// (1 − t)·a + t·b: exactly a at t = 0 and exactly b at t = 1; t outside [0, 1] extrapolates.
constexpr Vec2 lerp(Vec2 a, Vec2 b, double t) noexcept { return a * (1.0 - t) + b * t; }
/// (1 − t)·a + t·b for scalars, exact at both ends.
constexpr double lerp(double a, double b, double t) noexcept { return a * (1.0 - t) + b * t; }
/// |a − b| ≤ tolerance in both components.
constexpr bool approx_equal(Vec2 a, Vec2 b, double tolerance = 1e-12) noexcept {
    const Vec2 d = a - b;
    return (d.x <= tolerance && -d.x <= tolerance) && (d.y <= tolerance && -d.y <= tolerance);
}
/// Both components finite (not NaN, not ±inf).
inline bool is_finite(Vec2 a) noexcept { return std::isfinite(a.x) && std::isfinite(a.y); }

/// An axis-aligned box; `min` ≤ `max` componentwise once anything has been added.
struct Bounds {
    Vec2 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};  ///< the smallest x and y (+∞ while empty)
    Vec2 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};  ///< the largest x and y (−∞ while empty)

    /// Grows the box to hold p.
    constexpr void add(Vec2 p) noexcept {
        min = {p.x < min.x ? p.x : min.x, p.y < min.y ? p.y : min.y};
        max = {p.x > max.x ? p.x : max.x, p.y > max.y ? p.y : max.y};
    }
    /// Grows the box to hold b.
    constexpr void add(const Bounds& b) noexcept { add(b.min); add(b.max); }
    /// p inside or on the box, within tolerance.
    constexpr bool contains(Vec2 p, double tolerance = 0.0) const noexcept {
        return p.x >= min.x - tolerance && p.x <= max.x + tolerance && p.y >= min.y - tolerance &&
               p.y <= max.y + tolerance;
    }
    constexpr Vec2 size() const noexcept { return max - min; }  ///< max − min: width and height
};

namespace detail {
// 10-point Gauss–Legendre rule on [−1, 1] (symmetric: the nodes ±x_i share weight w_i),
// computed to 20 digits from the roots of P_10.
inline constexpr std::array<double, 5> gl10_x{0.97390652851717172008, 0.86506336668898451073,
                                              0.67940956829902440623, 0.43339539412924719080,
                                              0.14887433898163121088};
inline constexpr std::array<double, 5> gl10_w{0.066671344308688137594, 0.14945134915058059315,
                                              0.21908636251598204400, 0.26926671930999635509,
                                              0.29552422471475287017};
}  // namespace detail

/// ∫ f over [a, b] with one 10-point Gauss–Legendre rule: exact for polynomials of degree ≤ 19.
template <class F>
constexpr double gauss_legendre(F&& f, double a, double b) noexcept(noexcept(f(a))) {
    const double half = 0.5 * (b - a);
    const double mid = 0.5 * (a + b);
    double sum = 0.0;
    for (std::size_t i = 0; i < detail::gl10_x.size(); ++i) {
        const double dx = half * detail::gl10_x[i];
        sum += detail::gl10_w[i] * (f(mid - dx) + f(mid + dx));
    }
    return sum * half;
}

namespace detail {
// One 10-point rule on [a, b]: the integral of f and of |f| (the scale of its rounding noise).
template <class F>
constexpr std::pair<double, double> gauss_legendre_with_scale(F& f, double a, double b) noexcept(noexcept(f(a))) {
    const double half = 0.5 * (b - a);
    const double mid = 0.5 * (a + b);
    double sum = 0.0;
    double scale = 0.0;
    for (std::size_t i = 0; i < gl10_x.size(); ++i) {
        const double dx = half * gl10_x[i];
        const double lo = f(mid - dx);
        const double hi = f(mid + dx);
        sum += gl10_w[i] * (lo + hi);
        scale += gl10_w[i] * (std::abs(lo) + std::abs(hi));
    }
    return {sum * half, scale * std::abs(half)};
}
}  // namespace detail

/// ∫ f over [a, b], adaptive: an interval is accepted when one rule and the sum over its two
/// halves agree within its share of `tolerance` (absolute) or within the rounding noise of
/// the rules themselves (64 ulp of ∫|f| there: a tighter target could never be met), at
/// `max_depth` bisections, or once 2¹⁶ intervals have been split (a bound on the work for
/// integrands that are not smooth). Allocation-free (recursion depth ≤ max_depth).
/// Meant for smooth integrands: split at any kink or jump first (a kink within ~0.6% of an
/// interval's end lies outside every node of both rules and can go unnoticed).
template <class F>
double integrate(F&& f, double a, double b, double tolerance = 1e-13, int max_depth = 30) noexcept(
    noexcept(f(a))) {
    constexpr double noise = 64.0 * std::numeric_limits<double>::epsilon();
    struct Step {
        F& f;
        long budget = 1L << 16;
        double operator()(double lo, double hi, double whole, double tol, int depth) {
            const double mid = 0.5 * (lo + hi);
            const auto [left, left_scale] = detail::gauss_legendre_with_scale(f, lo, mid);
            const auto [right, right_scale] = detail::gauss_legendre_with_scale(f, mid, hi);
            const double both = left + right;
            const double error = std::abs(both - whole);
            if (depth <= 0 || --budget <= 0 || error <= tol || error <= noise * (left_scale + right_scale))
                return both;
            const double l = (*this)(lo, mid, left, 0.5 * tol, depth - 1);
            return l + (*this)(mid, hi, right, 0.5 * tol, depth - 1);
        }
    };
    if (a == b) return 0.0;
    Step step{f};
    return step(a, b, gauss_legendre(f, a, b), tolerance, max_depth);
}

/// Result of find_root.
struct Root {
    double x = 0.0;        ///< the root (best estimate)
    int iterations = 0;    ///< Newton or bisection steps taken
    bool converged = false;  ///< |bracket| ≤ tolerance or f(x) == 0 reached
};

/// Root of f in [lo, hi] where f(lo) and f(hi) have opposite signs (or one is zero).
/// `fd(x)` returns {f(x), f'(x)}. Newton steps from `guess`, replaced by bisection whenever
/// Newton would leave the bracket or shrink it too slowly, so it always converges.
/// Stops when the bracket is narrower than `tolerance` (absolute) or cannot be split any
/// more in double precision. If the signs do not bracket a root (or f is NaN at an end),
/// returns the end with the smaller |f| and converged = false.
template <class FD>
Root find_root(FD&& fd, double lo, double hi, double guess, double tolerance = 1e-15,
               int max_iterations = 200) noexcept(noexcept(fd(lo))) {
    const double flo = fd(lo).first;
    const double fhi = fd(hi).first;
    if (flo == 0.0) return {lo, 0, true};
    if (fhi == 0.0) return {hi, 0, true};
    if (!((flo < 0.0 && fhi > 0.0) || (flo > 0.0 && fhi < 0.0))) {
        return {std::abs(flo) < std::abs(fhi) ? lo : hi, 0, false};
    }
    if (flo > 0.0) std::swap(lo, hi);  // orient so that f(lo) < 0 < f(hi); lo may exceed hi
    double x = (guess > (std::min)(lo, hi) && guess < (std::max)(lo, hi)) ? guess : 0.5 * (lo + hi);
    double step_before = std::abs(hi - lo);
    double step = step_before;
    for (int i = 1; i <= max_iterations; ++i) {
        const auto [fx, dfx] = fd(x);
        if (fx == 0.0) return {x, i, true};
        if (fx < 0.0) lo = x; else hi = x;  // a NaN f(x) counts as positive: the bracket still shrinks
        if (std::abs(hi - lo) <= tolerance) return {x, i, true};
        const double newton = x - fx / dfx;
        const bool newton_inside = std::isfinite(newton) && (newton - lo) * (newton - hi) < 0.0;
        // Newton only while it at least halves the step of two iterations ago (as rtsafe does).
        if (newton_inside && std::abs(2.0 * fx) < std::abs(step_before * dfx)) {
            step_before = step;
            step = newton - x;
            x = newton;
            if (std::abs(step) <= 0.5 * tolerance) return {x, i, true};
        } else {
            step_before = step;
            step = 0.5 * (hi - lo);
            const double mid = lo + step;
            if (mid == lo || mid == hi) return {x, i, true};  // the bracket is two adjacent doubles
            x = mid;
        }
    }
    return {x, max_iterations, false};
}

/// @}

}  // namespace grape
