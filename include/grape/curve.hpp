// grape — curves: when an animation gets there. A curve maps normalized time t in [0, 1] to
// progress along the path. Progress may leave [0, 1] (back, elastic): paths extend along
// their end tangents, so the overshoot shows in space too.
//
// `Curve` is a small value (a kind plus a few numbers; cubic-bezier, monotone, SVG, spring and
// function curves share their data on the heap: copies share it). Evaluation is noexcept,
// allocation-free and a switch on the kind.
//
//   grape::Curve c = grape::Curve::quad_in_out();
//   double p = c(0.25);                                   // 0.125
//   grape::Curve css = grape::parse_curve("cubic-bezier(0.25,0.1,0.25,1)");
//   grape::Curve mine = grape::Curve::svg("M0,0 C0.2,0 0.3,1 1,1");  // GSAP CustomEase data
//   grape::Curve wobble = grape::Curve::from_function([](double t) { return t * t * (3 - 2 * t); });
//
// Threads: a Curve is immutable after construction; one Curve (a custom curve's shared points
// included) may be evaluated, copied and printed from any number of threads at once. Assigning
// to one Curve object while another thread reads it is a data race, as for any value. A
// function curve calls your callable from whichever thread evaluates it (the thread that
// ticks an Engine playing it): the callable must be safe to call there, and from several
// threads at once if the curve is shared between threads.
#pragma once

#include <grape/export_curve.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace grape {

/// \addtogroup curve
/// @{

namespace detail {
/// x < edge ? a : b by integer masks (pick_below on targets without SSE2, such as wasm);
/// memcpy, not std::bit_cast: some C++20 libraries (emscripten 3.1.6's) lack it.
inline double pick_below_bits(double x, double edge, double a, double b) noexcept {
    const std::uint64_t mask = std::uint64_t{0} - static_cast<std::uint64_t>(x < edge);
    std::uint64_t ia, ib;
    std::memcpy(&ia, &a, sizeof a);
    std::memcpy(&ib, &b, sizeof b);
    const std::uint64_t bits = (ia & mask) | (ib & ~mask);
    double out;
    std::memcpy(&out, &bits, sizeof out);
    return out;
}
/// x < edge ? a : b without a branch (a and b already computed): the polynomial in-out and
/// out-in kinds join two cheap halves at x = ½, and a branch there mispredicts half the
/// time when many animations run at unrelated phases.
inline double pick_below(double x, double edge, double a, double b) noexcept {
#if defined(__SSE2__)
    const __m128d below = _mm_cmplt_sd(_mm_set_sd(x), _mm_set_sd(edge));
    return _mm_cvtsd_f64(_mm_or_pd(_mm_and_pd(below, _mm_set_sd(a)), _mm_andnot_pd(below, _mm_set_sd(b))));
#else
    return pick_below_bits(x, edge, a, b);
#endif
}
}  // namespace detail

/// The tiny pure easing functions of normalized time x (Robert Penner's, canonical constants).
/// Each maps 0 → 0 and 1 → 1 exactly; out(x) = 1 − in(1 − x); in-out joins in and out
/// at x = ½. Usable on their own, without a Curve.
namespace ease {

inline constexpr double back_overshoot = 1.70158;      ///< Penner's back s: a 10 % undershoot
inline constexpr double elastic_amplitude = 1.0;       ///< Penner's elastic a (values < 1 mean 1)
inline constexpr double elastic_period = 0.3;          ///< elastic p for in and out, in units of t
inline constexpr double elastic_in_out_period = 0.45;  ///< elastic p for in-out (0.3 · 1.5)

/// x itself: no easing.
inline double linear(double x) noexcept { return x; }

/// Quadratic in: x².
inline double quad_in(double x) noexcept { return x * x; }
/// Quadratic out: 1 − (1 − x)².
inline double quad_out(double x) noexcept { const double y = 1.0 - x; return 1.0 - y * y; }
/// Quadratic in-out: quad in to ½, then quad out.
inline double quad_in_out(double x) noexcept {
    const double y = 2.0 - 2.0 * x;
    return detail::pick_below(x, 0.5, 2.0 * x * x, 1.0 - 0.5 * y * y);
}

/// Cubic in: x³.
inline double cubic_in(double x) noexcept { return x * x * x; }
/// Cubic out: 1 − (1 − x)³.
inline double cubic_out(double x) noexcept { const double y = 1.0 - x; return 1.0 - y * y * y; }
/// Cubic in-out: cubic in to ½, then cubic out.
inline double cubic_in_out(double x) noexcept {
    const double y = 2.0 - 2.0 * x;
    return detail::pick_below(x, 0.5, 4.0 * x * x * x, 1.0 - 0.5 * y * y * y);
}

/// Quartic in: x⁴.
inline double quart_in(double x) noexcept { const double x2 = x * x; return x2 * x2; }
/// Quartic out: 1 − (1 − x)⁴.
inline double quart_out(double x) noexcept { const double y = (1.0 - x) * (1.0 - x); return 1.0 - y * y; }
/// Quartic in-out: quartic in to ½, then quartic out.
inline double quart_in_out(double x) noexcept {
    const double x2 = x * x;
    const double y = (2.0 - 2.0 * x) * (2.0 - 2.0 * x);
    return detail::pick_below(x, 0.5, 8.0 * x2 * x2, 1.0 - 0.5 * y * y);
}

/// Quintic in: x⁵.
inline double quint_in(double x) noexcept { const double x2 = x * x; return x2 * x2 * x; }
/// Quintic out: 1 − (1 − x)⁵.
inline double quint_out(double x) noexcept {
    const double y = 1.0 - x;
    const double y2 = y * y;
    return 1.0 - y2 * y2 * y;
}
/// Quintic in-out: quintic in to ½, then quintic out.
inline double quint_in_out(double x) noexcept {
    const double x2 = x * x;
    const double y = 2.0 - 2.0 * x;
    const double y2 = y * y;
    return detail::pick_below(x, 0.5, 16.0 * x2 * x2 * x, 1.0 - 0.5 * y2 * y2 * y);
}

// cos(π/2) is 6e-17, not 0: the ends are pinned so that 1 → 1 holds exactly.
/// Sine in: 1 − cos(πx/2), exactly 1 at x = 1.
inline double sine_in(double x) noexcept { return x == 1.0 ? 1.0 : 1.0 - std::cos(x * 1.5707963267948966); }
/// Sine out: sin(πx/2), exactly 1 at x = 1.
inline double sine_out(double x) noexcept { return x == 1.0 ? 1.0 : std::sin(x * 1.5707963267948966); }
/// Written as the join of in and out (equal to −(cos πx − 1)/2) so that ½ → ½ exactly.
inline double sine_in_out(double x) noexcept { return x < 0.5 ? 0.5 * sine_in(2.0 * x) : 0.5 + 0.5 * sine_out(2.0 * x - 1.0); }

// Penner's guards make the ends exact; they leave a 2⁻¹⁰ step right next to the guarded end.
/// Exponential in: 2^(10x − 10), exactly 0 at x = 0.
inline double expo_in(double x) noexcept { return x == 0.0 ? 0.0 : std::exp2(10.0 * x - 10.0); }
/// Exponential out: 1 − 2^(−10x), exactly 1 at x = 1.
inline double expo_out(double x) noexcept { return x == 1.0 ? 1.0 : 1.0 - std::exp2(-10.0 * x); }
/// Exponential in-out: expo in to ½, then expo out.
inline double expo_in_out(double x) noexcept {
    if (x == 0.0 || x == 1.0) return x;
    return x < 0.5 ? 0.5 * std::exp2(20.0 * x - 10.0) : 1.0 - 0.5 * std::exp2(10.0 - 20.0 * x);
}

// Outside [−1, 1] of the square root argument the curve holds its end value instead of NaN.
/// Circular in: 1 − √(1 − x²) (holds 1 where the root's argument is negative).
inline double circ_in(double x) noexcept { const double r = 1.0 - x * x; return 1.0 - (r > 0.0 ? std::sqrt(r) : 0.0); }
/// Circular out: √(1 − (1 − x)²) (holds 0 where the root's argument is negative).
inline double circ_out(double x) noexcept { const double y = 1.0 - x; const double r = 1.0 - y * y; return r > 0.0 ? std::sqrt(r) : 0.0; }
/// Circular in-out: circ in to ½, then circ out.
inline double circ_in_out(double x) noexcept { return x < 0.5 ? 0.5 * circ_in(2.0 * x) : 0.5 + 0.5 * circ_out(2.0 * x - 1.0); }

/// Back in with overshoot s: (s + 1)x³ − s·x², written x²(x + s(x − 1)) so that 1 → 1 exactly.
inline double back_in(double x, double s = back_overshoot) noexcept { return x * x * (x + s * (x - 1.0)); }
/// Back out with overshoot s: the mirror of back_in, 1 − back_in(1 − x, s).
inline double back_out(double x, double s = back_overshoot) noexcept { return 1.0 - back_in(1.0 - x, s); }
/// Penner's in-out scales the overshoot by 1.525 so each half also dips about 10 %.
inline double back_in_out(double x, double s = back_overshoot) noexcept {
    const double s2 = s * 1.525;
    return x < 0.5 ? 0.5 * back_in(2.0 * x, s2) : 0.5 + 0.5 * back_out(2.0 * x - 1.0, s2);
}

/// Elastic in with amplitude a (≥ 1) and period p: −a·2^(10(x−1))·sin((x − 1 − s)·2π/p),
/// s = p/(2π)·asin(1/a), exact at both ends.
inline double elastic_in(double x, double a = elastic_amplitude, double p = elastic_period) noexcept {
    if (x == 0.0 || x == 1.0) return x;
    if (!(a > 1.0)) a = 1.0;
    const double s = p / (2.0 * 3.141592653589793) * std::asin(1.0 / a);
    return -a * std::exp2(10.0 * (x - 1.0)) * std::sin((x - 1.0 - s) * (2.0 * 3.141592653589793) / p);
}
/// The mirror of elastic in; equal to Penner's out for a = 1 (for a > 1 Penner's own out
/// turns its phase the other way and is not a mirror image).
inline double elastic_out(double x, double a = elastic_amplitude, double p = elastic_period) noexcept {
    return 1.0 - elastic_in(1.0 - x, a, p);
}
/// Elastic in-out: elastic in to ½, then elastic out (Penner's period 0.45 by default).
inline double elastic_in_out(double x, double a = elastic_amplitude, double p = elastic_in_out_period) noexcept {
    return x < 0.5 ? 0.5 * elastic_in(2.0 * x, a, p) : 0.5 + 0.5 * elastic_out(2.0 * x - 1.0, a, p);
}

/// Four parabolas 7.5625·(x − k)² + h meeting 1 at 4/11, 8/11, 10/11 and 1.
inline double bounce_out(double x) noexcept {
    constexpr double n = 7.5625;
    constexpr double d = 2.75;
    if (x == 1.0) return 1.0;  // the last parabola reaches 1 only up to rounding
    if (x < 1.0 / d) return n * x * x;
    if (x < 2.0 / d) { x -= 1.5 / d; return n * x * x + 0.75; }
    if (x < 2.5 / d) { x -= 2.25 / d; return n * x * x + 0.9375; }
    x -= 2.625 / d;
    return n * x * x + 0.984375;
}
/// Bounce in: the mirror of bounce_out, 1 − bounce_out(1 − x).
inline double bounce_in(double x) noexcept { return 1.0 - bounce_out(1.0 - x); }
/// Bounce in-out: bounce in to ½, then bounce out.
inline double bounce_in_out(double x) noexcept {
    return x < 0.5 ? 0.5 - 0.5 * bounce_out(1.0 - 2.0 * x) : 0.5 + 0.5 * bounce_out(2.0 * x - 1.0);
}

// Out-in: the out curve to ½, then the in curve (Robert Penner's family as Tweener and
// Flash's transitions wrote it): fast at both ends, slow through the middle. 0 → 0, ½ → ½
// and 1 → 1 exactly. Back and elastic keep their in/out constants (no 1.525 or 0.45).
/// Quadratic out-in: quad out to ½, then quad in.
inline double quad_out_in(double x) noexcept { return detail::pick_below(x, 0.5, 0.5 * quad_out(2.0 * x), 0.5 + 0.5 * quad_in(2.0 * x - 1.0)); }
/// Cubic out-in: cubic out to ½, then cubic in.
inline double cubic_out_in(double x) noexcept { return detail::pick_below(x, 0.5, 0.5 * cubic_out(2.0 * x), 0.5 + 0.5 * cubic_in(2.0 * x - 1.0)); }
/// Quartic out-in: quartic out to ½, then quartic in.
inline double quart_out_in(double x) noexcept { return detail::pick_below(x, 0.5, 0.5 * quart_out(2.0 * x), 0.5 + 0.5 * quart_in(2.0 * x - 1.0)); }
/// Quintic out-in: quintic out to ½, then quintic in.
inline double quint_out_in(double x) noexcept { return detail::pick_below(x, 0.5, 0.5 * quint_out(2.0 * x), 0.5 + 0.5 * quint_in(2.0 * x - 1.0)); }
/// Sine out-in: sine out to ½, then sine in.
inline double sine_out_in(double x) noexcept { return x < 0.5 ? 0.5 * sine_out(2.0 * x) : 0.5 + 0.5 * sine_in(2.0 * x - 1.0); }
/// Exponential out-in: expo out to ½, then expo in.
inline double expo_out_in(double x) noexcept { return x < 0.5 ? 0.5 * expo_out(2.0 * x) : 0.5 + 0.5 * expo_in(2.0 * x - 1.0); }
/// Circular out-in: circ out to ½, then circ in.
inline double circ_out_in(double x) noexcept { return x < 0.5 ? 0.5 * circ_out(2.0 * x) : 0.5 + 0.5 * circ_in(2.0 * x - 1.0); }
/// Back out-in with overshoot s (not scaled by 1.525): back out to ½, then back in.
inline double back_out_in(double x, double s = back_overshoot) noexcept {
    return x < 0.5 ? 0.5 * back_out(2.0 * x, s) : 0.5 + 0.5 * back_in(2.0 * x - 1.0, s);
}
/// Elastic out-in: elastic out to ½, then elastic in (period 0.3 by default).
inline double elastic_out_in(double x, double a = elastic_amplitude, double p = elastic_period) noexcept {
    return x < 0.5 ? 0.5 * elastic_out(2.0 * x, a, p) : 0.5 + 0.5 * elastic_in(2.0 * x - 1.0, a, p);
}
/// Bounce out-in: bounce out to ½, then bounce in.
inline double bounce_out_in(double x) noexcept { return x < 0.5 ? 0.5 * bounce_out(2.0 * x) : 0.5 + 0.5 * bounce_in(2.0 * x - 1.0); }

}  // namespace ease

/// Every kind of curve. The Penner kinds come in families of four: in, out, in-out, out-in
/// (kind = 1 + 4·family + direction).
enum class CurveKind : std::uint8_t {
    linear,
    quad_in, quad_out, quad_in_out, quad_out_in,
    cubic_in, cubic_out, cubic_in_out, cubic_out_in,
    quart_in, quart_out, quart_in_out, quart_out_in,
    quint_in, quint_out, quint_in_out, quint_out_in,
    sine_in, sine_out, sine_in_out, sine_out_in,
    expo_in, expo_out, expo_in_out, expo_out_in,
    circ_in, circ_out, circ_in_out, circ_out_in,
    back_in, back_out, back_in_out, back_out_in,
    elastic_in, elastic_out, elastic_in_out, elastic_out_in,
    bounce_in, bounce_out, bounce_in_out, bounce_out_in,
    cubic_bezier,  ///< CSS cubic-bezier(x1, y1, x2, y2)
    steps,         ///< CSS steps(n, position)
    monotone,      ///< through user points, monotone cubic (Fritsch–Carlson)
    svg,           ///< y at x along SVG path data from (0, y0) to (1, y1) (GSAP's CustomEase)
    spring,        ///< a damped spring released from rest offset 1 (closed form)
    function,      ///< your own callable double(double)
};

/// CSS steps() jump positions: where the n jumps fall.
enum class StepPosition : std::uint8_t {
    jump_start,  ///< jump at t = 0 (CSS `start`): n jumps, first value 1/n
    jump_end,    ///< jump at t = 1 (CSS `end`, the default): n jumps, last value reached at 1
    jump_none,   ///< no jump at either end: n − 1 jumps, n ≥ 2
    jump_both,   ///< jumps at both ends: n + 1 jumps
};

/// The Penner families, for building curves from (family, direction).
enum class EaseFamily : std::uint8_t { quad, cubic, quart, quint, sine, expo, circ, back, elastic, bounce };
/// Which end eases (out-in: out to ½, then in).
enum class EaseDirection : std::uint8_t { in, out, in_out, out_in };

/// A damped spring m·x″ + c·x′ + k·x = 0 pulling progress 1 − x from 0 to 1 (x(0) = 1).
/// Time is the spring's own, in seconds.
struct SpringCurveDef {
    double stiffness = 100.0;  ///< k, N/m (> 0, finite)
    double damping = 10.0;     ///< c, N·s/m (> 0, finite): ζ = c / (2√(k·m)); < 1 bounces
    double mass = 1.0;         ///< m, kg (> 0, finite)
    double velocity = 0.0;     ///< initial progress per second of spring time (finite; > 0 towards 1)
};

/// A spring is settled once |x| (its distance from 1, in units of the whole move) stays
/// below this: the curve spans the spring's time from release to then.
inline constexpr double spring_settle_tolerance = 1e-3;

namespace detail {
struct CurveData {};  // what a curve shares on the heap; one derived type per kind (src/curve/)
GRAPE_CURVE_API double cubic_bezier_eval(const CurveData& table, double x1, double y1, double x2, double y2,
                                         double t) noexcept;
GRAPE_CURVE_API double steps_eval(double n, double position, double t) noexcept;
GRAPE_CURVE_API double monotone_eval(const CurveData& data, double t) noexcept;
GRAPE_CURVE_API double svg_eval(const CurveData& data, double t) noexcept;
GRAPE_CURVE_API double spring_eval(const CurveData& data, double t) noexcept;
GRAPE_CURVE_API double function_eval(const CurveData& data, double t) noexcept;
}  // namespace detail

/// An easing curve: progress = curve(t). Default: linear.
class GRAPE_CURVE_API Curve {
public:
    /// Linear (progress = t).
    Curve() noexcept = default;

    /// The canonical Penner curve of the kind (linear or a Penner kind; the others have
    /// factories). Throws grape::Error otherwise.
    explicit Curve(CurveKind kind);
    /// The Penner curve of a family and direction, canonical constants.
    Curve(EaseFamily family, EaseDirection direction) noexcept;

    /// A factory for every named Penner curve (curve_names(): "quad-in" is quad_in()), canonical
    /// constants.
    static Curve linear() noexcept { return Curve(); }
    /// ease::quad_in as a Curve.
    static Curve quad_in() noexcept { return {EaseFamily::quad, EaseDirection::in}; }
    /// ease::quad_out as a Curve.
    static Curve quad_out() noexcept { return {EaseFamily::quad, EaseDirection::out}; }
    /// ease::quad_in_out as a Curve.
    static Curve quad_in_out() noexcept { return {EaseFamily::quad, EaseDirection::in_out}; }
    /// ease::cubic_in as a Curve.
    static Curve cubic_in() noexcept { return {EaseFamily::cubic, EaseDirection::in}; }
    /// ease::cubic_out as a Curve.
    static Curve cubic_out() noexcept { return {EaseFamily::cubic, EaseDirection::out}; }
    /// ease::cubic_in_out as a Curve.
    static Curve cubic_in_out() noexcept { return {EaseFamily::cubic, EaseDirection::in_out}; }
    /// ease::quart_in as a Curve.
    static Curve quart_in() noexcept { return {EaseFamily::quart, EaseDirection::in}; }
    /// ease::quart_out as a Curve.
    static Curve quart_out() noexcept { return {EaseFamily::quart, EaseDirection::out}; }
    /// ease::quart_in_out as a Curve.
    static Curve quart_in_out() noexcept { return {EaseFamily::quart, EaseDirection::in_out}; }
    /// ease::quint_in as a Curve.
    static Curve quint_in() noexcept { return {EaseFamily::quint, EaseDirection::in}; }
    /// ease::quint_out as a Curve.
    static Curve quint_out() noexcept { return {EaseFamily::quint, EaseDirection::out}; }
    /// ease::quint_in_out as a Curve.
    static Curve quint_in_out() noexcept { return {EaseFamily::quint, EaseDirection::in_out}; }
    /// ease::sine_in as a Curve.
    static Curve sine_in() noexcept { return {EaseFamily::sine, EaseDirection::in}; }
    /// ease::sine_out as a Curve.
    static Curve sine_out() noexcept { return {EaseFamily::sine, EaseDirection::out}; }
    /// ease::sine_in_out as a Curve.
    static Curve sine_in_out() noexcept { return {EaseFamily::sine, EaseDirection::in_out}; }
    /// ease::expo_in as a Curve.
    static Curve expo_in() noexcept { return {EaseFamily::expo, EaseDirection::in}; }
    /// ease::expo_out as a Curve.
    static Curve expo_out() noexcept { return {EaseFamily::expo, EaseDirection::out}; }
    /// ease::expo_in_out as a Curve.
    static Curve expo_in_out() noexcept { return {EaseFamily::expo, EaseDirection::in_out}; }
    /// ease::circ_in as a Curve.
    static Curve circ_in() noexcept { return {EaseFamily::circ, EaseDirection::in}; }
    /// ease::circ_out as a Curve.
    static Curve circ_out() noexcept { return {EaseFamily::circ, EaseDirection::out}; }
    /// ease::circ_in_out as a Curve.
    static Curve circ_in_out() noexcept { return {EaseFamily::circ, EaseDirection::in_out}; }
    /// ease::back_in as a Curve.
    static Curve back_in() noexcept { return {EaseFamily::back, EaseDirection::in}; }
    /// ease::back_out as a Curve.
    static Curve back_out() noexcept { return {EaseFamily::back, EaseDirection::out}; }
    /// ease::back_in_out as a Curve.
    static Curve back_in_out() noexcept { return {EaseFamily::back, EaseDirection::in_out}; }
    /// ease::elastic_in as a Curve.
    static Curve elastic_in() noexcept { return {EaseFamily::elastic, EaseDirection::in}; }
    /// ease::elastic_out as a Curve.
    static Curve elastic_out() noexcept { return {EaseFamily::elastic, EaseDirection::out}; }
    /// ease::elastic_in_out as a Curve.
    static Curve elastic_in_out() noexcept { return {EaseFamily::elastic, EaseDirection::in_out}; }
    /// ease::bounce_in as a Curve.
    static Curve bounce_in() noexcept { return {EaseFamily::bounce, EaseDirection::in}; }
    /// ease::bounce_out as a Curve.
    static Curve bounce_out() noexcept { return {EaseFamily::bounce, EaseDirection::out}; }
    /// ease::bounce_in_out as a Curve.
    static Curve bounce_in_out() noexcept { return {EaseFamily::bounce, EaseDirection::in_out}; }
    /// Out-in of a family: out to ½, then in (canonical constants).
    static Curve out_in(EaseFamily family) noexcept { return {family, EaseDirection::out_in}; }
    /// ease::quad_out_in as a Curve.
    static Curve quad_out_in() noexcept { return out_in(EaseFamily::quad); }
    /// ease::cubic_out_in as a Curve.
    static Curve cubic_out_in() noexcept { return out_in(EaseFamily::cubic); }
    /// ease::quart_out_in as a Curve.
    static Curve quart_out_in() noexcept { return out_in(EaseFamily::quart); }
    /// ease::quint_out_in as a Curve.
    static Curve quint_out_in() noexcept { return out_in(EaseFamily::quint); }
    /// ease::sine_out_in as a Curve.
    static Curve sine_out_in() noexcept { return out_in(EaseFamily::sine); }
    /// ease::expo_out_in as a Curve.
    static Curve expo_out_in() noexcept { return out_in(EaseFamily::expo); }
    /// ease::circ_out_in as a Curve.
    static Curve circ_out_in() noexcept { return out_in(EaseFamily::circ); }
    /// ease::back_out_in as a Curve.
    static Curve back_out_in() noexcept { return out_in(EaseFamily::back); }
    /// ease::elastic_out_in as a Curve.
    static Curve elastic_out_in() noexcept { return out_in(EaseFamily::elastic); }
    /// ease::bounce_out_in as a Curve.
    static Curve bounce_out_in() noexcept { return out_in(EaseFamily::bounce); }

    /// Back with overshoot s (finite, ≥ 0; 1.70158 undershoots 10 %). In-out uses 1.525·s
    /// per half, out-in s.
    static Curve back(EaseDirection direction, double overshoot = ease::back_overshoot);
    /// Elastic with amplitude a (finite, ≥ 1) and period p in units of t (finite, ≥ 1e-15:
    /// shorter overflows 2π/p); a non-positive period picks Penner's default (0.3, or 0.45 for in-out; out-in's
    /// halves take 0.3).
    static Curve elastic(EaseDirection direction, double amplitude = ease::elastic_amplitude, double period = 0.0);
    /// CSS cubic-bezier(x1, y1, x2, y2): x1, x2 in [0, 1], y1, y2 finite; outside [0, 1]
    /// continues along the end tangents as CSS does. Solved to round-off: on the half of the
    /// curve nearer t (mirrored through (½, ½) above ½, where 1 − t is exact) x(s) is a sum of
    /// non-negative Bernstein terms, evaluated to 8 ulp of itself, and Halley's iteration in a
    /// bracket, with bisection, stops at the double s where x(s) − t changes sign. So s is
    /// exact for a t within 8 ulp of the given one: y is within a few ulp of the exact y(t)
    /// wherever t·|y′(t)| is O(|y|), flat ends (ease, ease-in, ease-out) included. Only next to an interior point
    /// where x′ = 0 (when x2 < x1 and (x1 − x2)² = x1·(1 − x2), e.g. cubic-bezier(1,0,0,1) at
    /// ½), where y(t) has a vertical tangent, that freedom in t shows: there y is within
    /// ∛(8 ulp(t) / |x‴/6|)·|y′(s)| (6e-6·|y′| for (1,·,0,·)).
    static Curve cubic_bezier(double x1, double y1, double x2, double y2);
    /// CSS steps(n, position): n ≥ 1 (≥ 2 for jump_none). Evaluated without the CSS
    /// "before flag" (an animation playing forward).
    static Curve steps(int n, StepPosition position = StepPosition::jump_end);
    /// A smooth curve through points (x strictly increasing from exactly 0 to exactly 1,
    /// y finite), monotone cubic (Fritsch–Carlson): never overshoots between monotone data.
    /// Outside [0, 1] it continues along its end tangents.
    static Curve monotone(std::span<const double> x, std::span<const double> y);
    /// Progress = y at x along SVG path data, as GSAP's CustomEase takes it: one continuous
    /// path (`M L H V C S Q T`, absolute or relative, parsed by grape::parse_svg_path) from
    /// x = 0 to x = 1 (each within 1e-12, then set exactly), x never decreasing along any
    /// segment (checked exactly on the control points; a vertical segment is a jump: y takes
    /// its end value from there on). y is free (overshoot allowed). Each segment's x(s) = t is
    /// solved from its nearer end as cubic_bezier is (to the double where the computed
    /// x(s) − t changes sign), so y has cubic_bezier's accuracy.
    /// Outside [0, 1] holds the end values.
    /// Throws grape::Error naming the segment (its number from 1 and its start) that breaks a rule.
    static Curve svg(std::string_view data);
    /// A damped spring, closed form for under-, critically and over-damped springs. The curve
    /// spans the spring's time from release until it settles (settling_time(): after it |x|
    /// stays below spring_settle_tolerance), normalized so that curve(1) = 1 exactly:
    /// curve(t) = 1 − x(t·T) + t·x(T), within 1e-3 of the physical value everywhere. Outside
    /// [0, 1] holds 0 and 1. Play it over settling_time() seconds to move in physical time.
    /// Throws grape::Error for a parameter out of range and for a spring that swings more
    /// than a million times before it settles (ζ below ~2.2e-6: ln(1000)/(π·ζ) half-swings).
    static Curve spring(const SpringCurveDef& def);
    /// A spring by perceptual duration and bounce, as SwiftUI's Spring(duration:bounce:) and
    /// CSS spring generators give it: mass 1, stiffness (2π/duration)², damping
    /// 4π(1 − bounce)/duration for bounce ≥ 0 (ζ = 1 − bounce), 4π/(duration·(1 + bounce)) for
    /// bounce < 0 (overdamped). duration > 0, bounce in (−1, 1), velocity as in SpringCurveDef.
    static Curve spring_duration(double duration, double bounce = 0.0, double velocity = 0.0);
    /// Any callable double(double) as a curve (shared: copies call the same object; an
    /// Engine's curve table keeps it alive while an animation plays it). f(0) and f(1) must be
    /// finite (checked here). A non-finite result at t is replaced by the nearer end's value
    /// (f(0) for t < ½, f(1) otherwise); NaN t passes through. The callable must not throw:
    /// evaluation is noexcept, so an exception ends the program (std::terminate). See the
    /// thread rule at the top of this header. Has no text form: to_string gives "function".
    static Curve from_function(std::function<double(double)> f);

    /// Progress at normalized time t (any t; the formula kinds are meant for [0, 1]).
    double operator()(double t) const noexcept;

    /// Which kind of curve this is.
    CurveKind kind() const noexcept { return kind_; }
    /// The kind's numbers: back (overshoot), elastic (amplitude, period), cubic_bezier
    /// (x1, y1, x2, y2), steps (n, position as a number), spring (stiffness, damping, mass,
    /// velocity; for spring_duration: duration, bounce, velocity, 0); zero otherwise.
    double parameter(int i) const noexcept { return i >= 0 && i < 4 ? p_[i] : 0.0; }
    /// A spring's span in seconds of spring time (t = 1); 0 for other kinds.
    double settling_time() const noexcept;
    /// The address of the data copies share (cubic_bezier, monotone, svg, spring, function), else
    /// nullptr: equal for copies, distinct for curves made separately.
    const void* identity() const noexcept { return data_.get(); }
    /// The knots of a monotone curve (empty otherwise).
    std::span<const double> knots_x() const noexcept;
    /// The knots' y, one per knots_x() (empty unless monotone).
    std::span<const double> knots_y() const noexcept;

    /// Same kind and numbers (monotone curves: the same points; svg: the same segments;
    /// function curves: copies of one from_function curve).
    friend GRAPE_CURVE_API bool operator==(const Curve& a, const Curve& b) noexcept;

private:
    CurveKind kind_ = CurveKind::linear;
    double p_[4] = {0.0, 0.0, 0.0, 0.0};
    std::shared_ptr<const detail::CurveData> data_;
};

/// The curve's name, which parse_curve reads back to an equal curve: "quad-in-out",
/// "back-out(2.5)", "elastic-in(1.2,0.4)", "cubic-bezier(0.25,0.1,0.25,1)",
/// "steps(4,jump-end)", "monotone(0,0,0.5,0.8,1,1)" (x, y pairs), "svg(M0,0 C0.2,0 0.3,1 1,1)"
/// (absolute M, L, Q, C), "spring(100,10,1,0)" (stiffness, damping, mass, velocity),
/// "spring-duration(0.5,0.3,0)" (duration, bounce, velocity). Numbers print shortest
/// round-trip. A function curve prints "function", which does not parse.
GRAPE_CURVE_API std::string to_string(const Curve& curve);

/// Reads a curve name: every to_string form, plus the CSS keywords ease, ease-in, ease-out,
/// ease-in-out, step-start, step-end, steps(n) and the positions start/end; spring(k,c) and
/// spring(k,c,m) (mass 1, velocity 0 by default), spring-duration(d) and spring-duration(d,b);
/// svg(any SVG path data). Spaces around numbers are allowed. Throws grape::Error naming the
/// text and listing the valid names.
GRAPE_CURVE_API Curve parse_curve(std::string_view name);

/// The names of every parameter-free curve (linear and the 40 Penner curves), in CurveKind
/// order: the one list scenes, the tool and the web bindings offer.
GRAPE_CURVE_API std::span<const std::string_view> curve_names() noexcept;

/// The name of a CurveKind ("quad-in-out", "cubic-bezier", "steps", "monotone", "svg",
/// "spring", "function").
GRAPE_CURVE_API std::string_view to_string(CurveKind kind) noexcept;

// --- inline evaluation: one switch, the formula kinds inlined -----------------------------

/// True for the kinds that carry numbers or data (back, elastic, cubic_bezier, steps,
/// monotone, svg, spring, function): their evaluation needs the Curve, the others' only the kind.
constexpr bool has_parameters(CurveKind kind) noexcept {
    switch (kind) {
        case CurveKind::back_in:
        case CurveKind::back_out:
        case CurveKind::back_in_out:
        case CurveKind::back_out_in:
        case CurveKind::elastic_in:
        case CurveKind::elastic_out:
        case CurveKind::elastic_in_out:
        case CurveKind::elastic_out_in:
        case CurveKind::cubic_bezier:
        case CurveKind::steps:
        case CurveKind::monotone:
        case CurveKind::svg:
        case CurveKind::spring:
        case CurveKind::function: return true;
        default: return false;
    }
}

namespace detail {
/// The formula of a kind without parameters (has_parameters(kind) false) at t; t itself for
/// the kinds with parameters. Inline, so a loop over many kinds (the anim engine's tick)
/// evaluates it without a call.
inline double ease_formula(CurveKind kind, double t) noexcept {
    switch (kind) {
        case CurveKind::linear: return t;
        case CurveKind::quad_in: return ease::quad_in(t);
        case CurveKind::quad_out: return ease::quad_out(t);
        case CurveKind::quad_in_out: return ease::quad_in_out(t);
        case CurveKind::quad_out_in: return ease::quad_out_in(t);
        case CurveKind::cubic_in: return ease::cubic_in(t);
        case CurveKind::cubic_out: return ease::cubic_out(t);
        case CurveKind::cubic_in_out: return ease::cubic_in_out(t);
        case CurveKind::cubic_out_in: return ease::cubic_out_in(t);
        case CurveKind::quart_in: return ease::quart_in(t);
        case CurveKind::quart_out: return ease::quart_out(t);
        case CurveKind::quart_in_out: return ease::quart_in_out(t);
        case CurveKind::quart_out_in: return ease::quart_out_in(t);
        case CurveKind::quint_in: return ease::quint_in(t);
        case CurveKind::quint_out: return ease::quint_out(t);
        case CurveKind::quint_in_out: return ease::quint_in_out(t);
        case CurveKind::quint_out_in: return ease::quint_out_in(t);
        case CurveKind::sine_in: return ease::sine_in(t);
        case CurveKind::sine_out: return ease::sine_out(t);
        case CurveKind::sine_in_out: return ease::sine_in_out(t);
        case CurveKind::sine_out_in: return ease::sine_out_in(t);
        case CurveKind::expo_in: return ease::expo_in(t);
        case CurveKind::expo_out: return ease::expo_out(t);
        case CurveKind::expo_in_out: return ease::expo_in_out(t);
        case CurveKind::expo_out_in: return ease::expo_out_in(t);
        case CurveKind::circ_in: return ease::circ_in(t);
        case CurveKind::circ_out: return ease::circ_out(t);
        case CurveKind::circ_in_out: return ease::circ_in_out(t);
        case CurveKind::circ_out_in: return ease::circ_out_in(t);
        case CurveKind::bounce_in: return ease::bounce_in(t);
        case CurveKind::bounce_out: return ease::bounce_out(t);
        case CurveKind::bounce_in_out: return ease::bounce_in_out(t);
        case CurveKind::bounce_out_in: return ease::bounce_out_in(t);
        default: return t;
    }
}
}  // namespace detail

inline double Curve::operator()(double t) const noexcept {
    switch (kind_) {
        case CurveKind::back_in: return ease::back_in(t, p_[0]);
        case CurveKind::back_out: return ease::back_out(t, p_[0]);
        case CurveKind::back_in_out: return ease::back_in_out(t, p_[0]);
        case CurveKind::back_out_in: return ease::back_out_in(t, p_[0]);
        case CurveKind::elastic_in: return ease::elastic_in(t, p_[0], p_[1]);
        case CurveKind::elastic_out: return ease::elastic_out(t, p_[0], p_[1]);
        case CurveKind::elastic_in_out: return ease::elastic_in_out(t, p_[0], p_[1]);
        case CurveKind::elastic_out_in: return ease::elastic_out_in(t, p_[0], p_[1]);
        case CurveKind::cubic_bezier: return detail::cubic_bezier_eval(*data_, p_[0], p_[1], p_[2], p_[3], t);
        case CurveKind::steps: return detail::steps_eval(p_[0], p_[1], t);
        case CurveKind::monotone: return detail::monotone_eval(*data_, t);
        case CurveKind::svg: return detail::svg_eval(*data_, t);
        case CurveKind::spring: return detail::spring_eval(*data_, t);
        case CurveKind::function: return detail::function_eval(*data_, t);
        default: return detail::ease_formula(kind_, t);
    }
}

/// @}

}  // namespace grape
