// What the curves with data share on the heap (private to the curve module): one type per
// kind, each derived from detail::CurveData so that a Curve holds any of them.
#pragma once

#include <grape/curve.hpp>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace grape::detail {

/// Monotone curve: knots and their Fritsch–Carlson slopes.
struct MonotoneData : CurveData {
    std::vector<double> x;
    std::vector<double> y;
    std::vector<double> m;  // dy/dx at each knot
};

/// One piece of an SVG curve: a line, quadratic or cubic Bézier (absolute points, as given),
/// and its cubic form for evaluation.
struct SvgPiece {
    enum class Kind : unsigned char { line, quadratic, cubic };
    Kind kind = Kind::cubic;
    double px[4] = {};  // the points as written (line: 2, quadratic: 3, cubic: 4)
    double py[4] = {};
    double cx[4] = {};  // cubic control points (a line or quadratic raised exactly to degree 3 where it can be)
    double cy[4] = {};
};

/// SVG curve: its pieces in order of x, with their start x.
struct SvgData : CurveData {
    std::vector<SvgPiece> pieces;
    std::vector<double> start_x;  // pieces[i] covers [start_x[i], start_x[i + 1])
    double y_start = 0.0;
    double y_end = 0.0;
};

/// Spring: the closed form's constants (see spring.cpp).
struct SpringData : CurveData {
    enum class Regime : unsigned char { under, critical, over };
    Regime regime = Regime::under;
    double zeta_omega = 0.0;  // ζ·ω0, the decay rate
    double omega = 0.0;       // ωd (under) or γ = ω0·√(ζ² − 1) (over); 0 when critical
    double b = 0.0;           // B = ζ·ω0 − v0, the coefficient of the second mode (see spring.cpp)
    double slow = 0.0;        // over: the slow decay rate ζ·ω0 − γ = ω0² / (ζ·ω0 + γ)
    double span = 0.0;        // T: spring seconds the curve covers
    double end_offset = 0.0;  // x(T), removed linearly so that curve(1) = 1
    bool by_duration = false; // made by spring_duration (its to_string form)
};

/// Function curve: the callable and its finite end values.
struct FunctionData : CurveData {
    std::function<double(double)> f;
    double at0 = 0.0;
    double at1 = 1.0;
};

/// A curve's shared data as its kind's type (the kind must match).
template <class Data>
const Data& data_of(const Curve& c) noexcept {
    return static_cast<const Data&>(*static_cast<const CurveData*>(c.identity()));
}

/// x of a spring at spring time tau (x(0) = 1; the curve is 1 − x).
double spring_offset(const SpringData& d, double tau) noexcept;

/// cubic-bezier's table of starts for x1, x2 (computed once per curve).
std::shared_ptr<const CurveData> cubic_bezier_table(double x1, double x2);

/// The SVG curve's path data as to_string writes it (absolute M, L, Q, C; shortest numbers).
std::string svg_text(const SvgData& d);
/// Same pieces, point for point.
bool svg_same(const SvgData& a, const SvgData& b) noexcept;

/// B(s) = 3(1−s)²s·c1 + 3(1−s)s²·c2 + s³·c3 (a Bézier from 0 through c1, c2 to c3) in its
/// Bernstein form: a sum of non-negative terms when 0 ≤ c1, c2, c3, so that it keeps its
/// relative accuracy (≈ 8 ulp of B) however small s is.
inline double bernstein(double c1, double c2, double c3, double s) noexcept {
    const double m = 1.0 - s;
    return s * (3.0 * m * (m * c1 + s * c2) + s * s * c3);
}

/// The s in [0, 1] with B(s) = v, for B non-decreasing on [0, 1] and 0 < v < c3: Halley
/// inside a bracket [lo, hi] with B(lo) < v < B(hi), bisecting (geometrically while the
/// bracket spans more than a factor 4, so a flat start is found in a few steps) whenever
/// Halley would leave it. Stops when B(s) = v, when the step is within an ulp of s (or
/// Halley's error estimate after it is), or when lo and hi are adjacent doubles: s is then
/// within an ulp or two of the point
/// where the computed B(s) − v changes sign. At most 200 steps (work bounded; a few Halley
/// steps on ordinary curves).
/// Started from s0 inside a bracket [lo, hi] known to hold the solution (to rounding).
inline double bernstein_solve(double c1, double c2, double c3, double v, double lo, double hi, double s0) noexcept {
    const double d0 = c1;  // B′ = 3·(Bernstein form with d0, d1, d2)
    const double d1 = c2 - c1;
    const double d2 = c3 - c2;
    const double e0 = d1 - d0;  // B″ = 6·((1 − s)·e0 + s·e1)
    const double e1 = d2 - d1;
    double s = s0;
    double last_step = hi - lo;
    for (int i = 0; i < 200; ++i) {
        const double g = bernstein(c1, c2, c3, s) - v;
        if (g == 0.0) break;
        (g < 0.0 ? lo : hi) = s;
        const double m = 1.0 - s;
        const double slope = 3.0 * (m * (m * d0 + 2.0 * s * d1) + s * s * d2);
        const double bend = 6.0 * (m * e0 + s * e1);
        // Halley's step (Newton's with the curvature: cubic convergence, one or two
        // evaluations fewer than Newton on ordinary curves), with one division; for tiny
        // numbers (a flat start, t below 1e-200) from the Newton step r instead, so that no
        // product of small numbers underflows.
        double next;
        if (slope > 1e-100 && std::abs(g) > 1e-200) {
            next = s - 2.0 * g * slope / (2.0 * slope * slope - g * bend);
        } else {
            const double r = g / slope;
            next = s - r / (1.0 - 0.5 * r * bend / slope);
        }
        // Converged: the step is within an ulp of s, where the sign of g is rounding; or the
        // step is so small that Halley's next error, ≈ K·step³ with K = (B″/2B′)² + |B‴/6B′|,
        // is below a quarter ulp of s even 16 times over (saves the last evaluation).
        const double step = std::abs(next - s);
        if (step <= 0x1p-52 * s) return next;
        const double q = bend / slope;
        const double k = 0.25 * q * q + std::abs(e1 - e0) / std::abs(slope);
        if (16.0 * k * step * step * step <= 0x1p-54 * s && next > lo && next < hi) return next;
        // Bisect when the step leaves the bracket, or, after a few steps, crawls (a step over
        // 0.4 of the last one: a flat end or flat point, where the distance only halves).
        if (!(next > lo && next < hi) || (i >= 4 && std::abs(next - s) > 0.4 * last_step)) {
            next = lo > 0.0 && hi > 4.0 * lo ? std::sqrt(lo) * std::sqrt(hi) : 0.5 * (lo + hi);  // no underflow of lo·hi
            if (!(next > lo && next < hi)) break;  // lo and hi are adjacent doubles
        }
        last_step = std::abs(next - s);
        s = next;
    }
    return s;
}

/// From the bracket [0, 1] and the straight line's guess v/c3.
inline double bernstein_solve(double c1, double c2, double c3, double v) noexcept {
    return bernstein_solve(c1, c2, c3, v, 0.0, 1.0, v / c3);
}

/// cubic-bezier's start: the solved s at x = k/32 on each half (s for x ≤ ½, w = 1 − s for
/// x ≥ ½ as the mirrored curve's parameter), so that a t finds a bracket 1/32 wide in x by
/// one multiplication and starts from the straight line between its ends: two or three
/// Halley steps instead of four or five from s = t.
struct BezierTable : CurveData {
    static constexpr int n = 32;
    double s[n / 2 + 1];  // s[k]: x(s) = k/n, k = 0..n/2
    double w[n / 2 + 1];  // w[j]: the mirrored curve's x(w) = j/n
};

}  // namespace grape::detail
