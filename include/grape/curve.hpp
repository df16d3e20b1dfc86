// grape — curves: when an animation gets there. A curve maps normalized time t in [0, 1] to
// progress along the path. Progress may leave [0, 1] (back, elastic): paths extend along
// their end tangents, so the overshoot shows in space too.
//
// `Curve` is a small value (a kind plus a few numbers; only a custom curve shares its points
// on the heap). Evaluation is noexcept, allocation-free and a switch on the kind.
//
//   grape::Curve c = grape::Curve::quad_in_out();
//   double p = c(0.25);                                   // 0.125
//   grape::Curve css = grape::parse_curve("cubic-bezier(0.25,0.1,0.25,1)");
//
// Threads: a Curve is immutable after construction; one Curve (a custom curve's shared points
// included) may be evaluated, copied and printed from any number of threads at once. Assigning
// to one Curve object while another thread reads it is a data race, as for any value.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grape {

/// The tiny pure easing functions of normalized time x (Robert Penner's, canonical constants).
/// Each maps 0 → 0 and 1 → 1 exactly; out(x) = 1 − in(1 − x); in-out joins in and out
/// at x = ½. Usable on their own, without a Curve.
namespace ease {

inline constexpr double back_overshoot = 1.70158;      ///< Penner's back s: a 10 % undershoot
inline constexpr double elastic_amplitude = 1.0;       ///< Penner's elastic a (values < 1 mean 1)
inline constexpr double elastic_period = 0.3;          ///< elastic p for in and out, in units of t
inline constexpr double elastic_in_out_period = 0.45;  ///< elastic p for in-out (0.3 · 1.5)

inline double linear(double x) noexcept { return x; }

inline double quad_in(double x) noexcept { return x * x; }
inline double quad_out(double x) noexcept { const double y = 1.0 - x; return 1.0 - y * y; }
inline double quad_in_out(double x) noexcept {
    if (x < 0.5) return 2.0 * x * x;
    const double y = 2.0 - 2.0 * x;
    return 1.0 - 0.5 * y * y;
}

inline double cubic_in(double x) noexcept { return x * x * x; }
inline double cubic_out(double x) noexcept { const double y = 1.0 - x; return 1.0 - y * y * y; }
inline double cubic_in_out(double x) noexcept {
    if (x < 0.5) return 4.0 * x * x * x;
    const double y = 2.0 - 2.0 * x;
    return 1.0 - 0.5 * y * y * y;
}

inline double quart_in(double x) noexcept { const double x2 = x * x; return x2 * x2; }
inline double quart_out(double x) noexcept { const double y = (1.0 - x) * (1.0 - x); return 1.0 - y * y; }
inline double quart_in_out(double x) noexcept {
    if (x < 0.5) { const double x2 = x * x; return 8.0 * x2 * x2; }
    const double y = (2.0 - 2.0 * x) * (2.0 - 2.0 * x);
    return 1.0 - 0.5 * y * y;
}

inline double quint_in(double x) noexcept { const double x2 = x * x; return x2 * x2 * x; }
inline double quint_out(double x) noexcept {
    const double y = 1.0 - x;
    const double y2 = y * y;
    return 1.0 - y2 * y2 * y;
}
inline double quint_in_out(double x) noexcept {
    if (x < 0.5) { const double x2 = x * x; return 16.0 * x2 * x2 * x; }
    const double y = 2.0 - 2.0 * x;
    const double y2 = y * y;
    return 1.0 - 0.5 * y2 * y2 * y;
}

// cos(π/2) is 6e-17, not 0: the ends are pinned so that 1 → 1 holds exactly.
inline double sine_in(double x) noexcept { return x == 1.0 ? 1.0 : 1.0 - std::cos(x * 1.5707963267948966); }
inline double sine_out(double x) noexcept { return x == 1.0 ? 1.0 : std::sin(x * 1.5707963267948966); }
/// Written as the join of in and out (equal to −(cos πx − 1)/2) so that ½ → ½ exactly.
inline double sine_in_out(double x) noexcept { return x < 0.5 ? 0.5 * sine_in(2.0 * x) : 0.5 + 0.5 * sine_out(2.0 * x - 1.0); }

// Penner's guards make the ends exact; they leave a 2⁻¹⁰ step right next to the guarded end.
inline double expo_in(double x) noexcept { return x == 0.0 ? 0.0 : std::exp2(10.0 * x - 10.0); }
inline double expo_out(double x) noexcept { return x == 1.0 ? 1.0 : 1.0 - std::exp2(-10.0 * x); }
inline double expo_in_out(double x) noexcept {
    if (x == 0.0 || x == 1.0) return x;
    return x < 0.5 ? 0.5 * std::exp2(20.0 * x - 10.0) : 1.0 - 0.5 * std::exp2(10.0 - 20.0 * x);
}

// Outside [−1, 1] of the square root argument the curve holds its end value instead of NaN.
inline double circ_in(double x) noexcept { const double r = 1.0 - x * x; return 1.0 - (r > 0.0 ? std::sqrt(r) : 0.0); }
inline double circ_out(double x) noexcept { const double y = 1.0 - x; const double r = 1.0 - y * y; return r > 0.0 ? std::sqrt(r) : 0.0; }
inline double circ_in_out(double x) noexcept { return x < 0.5 ? 0.5 * circ_in(2.0 * x) : 0.5 + 0.5 * circ_out(2.0 * x - 1.0); }

/// Back in with overshoot s: (s + 1)x³ − s·x², written x²(x + s(x − 1)) so that 1 → 1 exactly.
inline double back_in(double x, double s = back_overshoot) noexcept { return x * x * (x + s * (x - 1.0)); }
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
inline double bounce_in(double x) noexcept { return 1.0 - bounce_out(1.0 - x); }
inline double bounce_in_out(double x) noexcept {
    return x < 0.5 ? 0.5 - 0.5 * bounce_out(1.0 - 2.0 * x) : 0.5 + 0.5 * bounce_out(2.0 * x - 1.0);
}

}  // namespace ease

/// Every kind of curve. The Penner kinds come in families of three: in, out, in-out.
enum class CurveKind : std::uint8_t {
    linear,
    quad_in, quad_out, quad_in_out,
    cubic_in, cubic_out, cubic_in_out,
    quart_in, quart_out, quart_in_out,
    quint_in, quint_out, quint_in_out,
    sine_in, sine_out, sine_in_out,
    expo_in, expo_out, expo_in_out,
    circ_in, circ_out, circ_in_out,
    back_in, back_out, back_in_out,
    elastic_in, elastic_out, elastic_in_out,
    bounce_in, bounce_out, bounce_in_out,
    cubic_bezier,  ///< CSS cubic-bezier(x1, y1, x2, y2)
    steps,         ///< CSS steps(n, position)
    monotone,      ///< through user points, monotone cubic (Fritsch–Carlson)
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
/// Which end eases.
enum class EaseDirection : std::uint8_t { in, out, in_out };

namespace detail {
struct MonotoneData;  // knots and Fritsch–Carlson slopes (src/curve/curve.cpp)
double cubic_bezier_eval(double x1, double y1, double x2, double y2, double t) noexcept;
double steps_eval(double n, double position, double t) noexcept;
double monotone_eval(const MonotoneData& data, double t) noexcept;
}  // namespace detail

/// An easing curve: progress = curve(t). Default: linear.
class Curve {
public:
    /// Linear (progress = t).
    Curve() noexcept = default;

    /// The canonical Penner curve of the kind (kind must not be cubic_bezier, steps or
    /// monotone: use their factories). Throws grape::Error otherwise.
    explicit Curve(CurveKind kind);
    /// The Penner curve of a family and direction, canonical constants.
    Curve(EaseFamily family, EaseDirection direction) noexcept;

    static Curve linear() noexcept { return Curve(); }
    static Curve quad_in() noexcept { return {EaseFamily::quad, EaseDirection::in}; }
    static Curve quad_out() noexcept { return {EaseFamily::quad, EaseDirection::out}; }
    static Curve quad_in_out() noexcept { return {EaseFamily::quad, EaseDirection::in_out}; }
    static Curve cubic_in() noexcept { return {EaseFamily::cubic, EaseDirection::in}; }
    static Curve cubic_out() noexcept { return {EaseFamily::cubic, EaseDirection::out}; }
    static Curve cubic_in_out() noexcept { return {EaseFamily::cubic, EaseDirection::in_out}; }
    static Curve sine_in_out() noexcept { return {EaseFamily::sine, EaseDirection::in_out}; }
    static Curve bounce_out() noexcept { return {EaseFamily::bounce, EaseDirection::out}; }

    /// Back with overshoot s (finite, ≥ 0; 1.70158 undershoots 10 %). In-out uses 1.525·s per half.
    static Curve back(EaseDirection direction, double overshoot = ease::back_overshoot);
    /// Elastic with amplitude a (finite, ≥ 1) and period p in units of t (finite, > 0);
    /// a non-positive period picks Penner's default (0.3, or 0.45 for in-out).
    static Curve elastic(EaseDirection direction, double amplitude = ease::elastic_amplitude, double period = 0.0);
    /// CSS cubic-bezier(x1, y1, x2, y2): x1, x2 in [0, 1], y1, y2 finite. Solved for t to
    /// |x(t) − t_in| ≤ 1e-12; outside [0, 1] continues along the end tangents as CSS does.
    static Curve cubic_bezier(double x1, double y1, double x2, double y2);
    /// CSS steps(n, position): n ≥ 1 (≥ 2 for jump_none). Evaluated without the CSS
    /// "before flag" (an animation playing forward).
    static Curve steps(int n, StepPosition position = StepPosition::jump_end);
    /// A smooth curve through points (x strictly increasing from exactly 0 to exactly 1,
    /// y finite), monotone cubic (Fritsch–Carlson): never overshoots between monotone data.
    /// Outside [0, 1] it continues along its end tangents.
    static Curve monotone(std::span<const double> x, std::span<const double> y);

    /// Progress at normalized time t (any t; the formula kinds are meant for [0, 1]).
    double operator()(double t) const noexcept;

    /// Which kind of curve this is.
    CurveKind kind() const noexcept { return kind_; }
    /// The kind's numbers: back (overshoot), elastic (amplitude, period), cubic_bezier
    /// (x1, y1, x2, y2), steps (n, position as a number); zero otherwise.
    double parameter(int i) const noexcept { return i >= 0 && i < 4 ? p_[i] : 0.0; }
    /// The knots of a monotone curve (empty otherwise).
    std::span<const double> knots_x() const noexcept;
    std::span<const double> knots_y() const noexcept;

    /// Same kind and numbers (monotone curves: the same points).
    friend bool operator==(const Curve& a, const Curve& b) noexcept;

private:
    CurveKind kind_ = CurveKind::linear;
    double p_[4] = {0.0, 0.0, 0.0, 0.0};
    std::shared_ptr<const detail::MonotoneData> points_;
};

/// The curve's name, which parse_curve reads back to an equal curve: "quad-in-out",
/// "back-out(2.5)", "elastic-in(1.2,0.4)", "cubic-bezier(0.25,0.1,0.25,1)",
/// "steps(4,jump-end)", "monotone(0,0,0.5,0.8,1,1)" (x, y pairs). Numbers print shortest
/// round-trip.
std::string to_string(const Curve& curve);

/// Reads a curve name: every to_string form, plus the CSS keywords ease, ease-in, ease-out,
/// ease-in-out, step-start, step-end, steps(n) and the positions start/end. Spaces around
/// numbers are allowed. Throws grape::Error naming the text and listing the valid names.
Curve parse_curve(std::string_view name);

/// The names of every parameter-free curve (linear and the 30 Penner curves), in order.
std::span<const std::string_view> curve_names() noexcept;

/// The name of a CurveKind ("quad-in-out", "cubic-bezier", "steps", "monotone").
std::string_view to_string(CurveKind kind) noexcept;

// --- inline evaluation: one switch, the formula kinds inlined -----------------------------

/// True for the kinds that carry numbers (back, elastic, cubic_bezier, steps, monotone):
/// their evaluation needs the Curve, the others' only the kind.
constexpr bool has_parameters(CurveKind kind) noexcept {
    switch (kind) {
        case CurveKind::back_in:
        case CurveKind::back_out:
        case CurveKind::back_in_out:
        case CurveKind::elastic_in:
        case CurveKind::elastic_out:
        case CurveKind::elastic_in_out:
        case CurveKind::cubic_bezier:
        case CurveKind::steps:
        case CurveKind::monotone: return true;
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
        case CurveKind::cubic_in: return ease::cubic_in(t);
        case CurveKind::cubic_out: return ease::cubic_out(t);
        case CurveKind::cubic_in_out: return ease::cubic_in_out(t);
        case CurveKind::quart_in: return ease::quart_in(t);
        case CurveKind::quart_out: return ease::quart_out(t);
        case CurveKind::quart_in_out: return ease::quart_in_out(t);
        case CurveKind::quint_in: return ease::quint_in(t);
        case CurveKind::quint_out: return ease::quint_out(t);
        case CurveKind::quint_in_out: return ease::quint_in_out(t);
        case CurveKind::sine_in: return ease::sine_in(t);
        case CurveKind::sine_out: return ease::sine_out(t);
        case CurveKind::sine_in_out: return ease::sine_in_out(t);
        case CurveKind::expo_in: return ease::expo_in(t);
        case CurveKind::expo_out: return ease::expo_out(t);
        case CurveKind::expo_in_out: return ease::expo_in_out(t);
        case CurveKind::circ_in: return ease::circ_in(t);
        case CurveKind::circ_out: return ease::circ_out(t);
        case CurveKind::circ_in_out: return ease::circ_in_out(t);
        case CurveKind::bounce_in: return ease::bounce_in(t);
        case CurveKind::bounce_out: return ease::bounce_out(t);
        case CurveKind::bounce_in_out: return ease::bounce_in_out(t);
        default: return t;
    }
}
}  // namespace detail

inline double Curve::operator()(double t) const noexcept {
    switch (kind_) {
        case CurveKind::back_in: return ease::back_in(t, p_[0]);
        case CurveKind::back_out: return ease::back_out(t, p_[0]);
        case CurveKind::back_in_out: return ease::back_in_out(t, p_[0]);
        case CurveKind::elastic_in: return ease::elastic_in(t, p_[0], p_[1]);
        case CurveKind::elastic_out: return ease::elastic_out(t, p_[0], p_[1]);
        case CurveKind::elastic_in_out: return ease::elastic_in_out(t, p_[0], p_[1]);
        case CurveKind::cubic_bezier: return detail::cubic_bezier_eval(p_[0], p_[1], p_[2], p_[3], t);
        case CurveKind::steps: return detail::steps_eval(p_[0], p_[1], t);
        case CurveKind::monotone: return detail::monotone_eval(*points_, t);
        default: return detail::ease_formula(kind_, t);
    }
}

}  // namespace grape
