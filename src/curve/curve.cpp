// Curves: validation, steps, the monotone cubic, and names (cubic_bezier.cpp, svg_curve.cpp,
// spring.cpp and function_curve.cpp hold the other kinds).
#include "curve_data.hpp"
#include "math/number_text.hpp"

#include <grape/curve.hpp>
#include <grape/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace grape {

namespace detail {

double steps_eval(double n, double position, double t) noexcept {
    if (std::isnan(t)) return t;
    const auto pos = static_cast<StepPosition>(static_cast<int>(position));
    double current = std::floor(t * n);
    if (pos == StepPosition::jump_start || pos == StepPosition::jump_both) current += 1.0;
    if (t >= 0.0 && current < 0.0) current = 0.0;
    double jumps = n;
    if (pos == StepPosition::jump_none) jumps = n - 1.0;
    if (pos == StepPosition::jump_both) jumps = n + 1.0;
    if (t <= 1.0 && current > jumps) current = jumps;
    return current / jumps;
}

double monotone_eval(const CurveData& base, double t) noexcept {
    const auto& d = static_cast<const MonotoneData&>(base);
    const std::size_t last = d.x.size() - 1;
    if (!(t > 0.0)) {
        if (t == 0.0) return d.y[0];
        if (std::isnan(t)) return t;
        return d.y[0] + d.m[0] * t;
    }
    if (t >= 1.0) return d.y[last] + d.m[last] * (t - 1.0);
    // Segment k holds t in [x_k, x_{k+1}).
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(d.x.begin(), d.x.end(), t) - d.x.begin()) - 1;
    const double h = d.x[k + 1] - d.x[k];
    const double s = (t - d.x[k]) / h;
    const double s2 = s * s;
    const double s3 = s2 * s;
    const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
    const double h10 = s3 - 2.0 * s2 + s;
    const double h01 = -2.0 * s3 + 3.0 * s2;
    const double h11 = s3 - s2;
    return h00 * d.y[k] + h10 * h * d.m[k] + h01 * d.y[k + 1] + h11 * h * d.m[k + 1];
}

}  // namespace detail

namespace {

constexpr std::array<std::string_view, 41> kind_names{
    "linear",
    "quad-in", "quad-out", "quad-in-out", "quad-out-in",
    "cubic-in", "cubic-out", "cubic-in-out", "cubic-out-in",
    "quart-in", "quart-out", "quart-in-out", "quart-out-in",
    "quint-in", "quint-out", "quint-in-out", "quint-out-in",
    "sine-in", "sine-out", "sine-in-out", "sine-out-in",
    "expo-in", "expo-out", "expo-in-out", "expo-out-in",
    "circ-in", "circ-out", "circ-in-out", "circ-out-in",
    "back-in", "back-out", "back-in-out", "back-out-in",
    "elastic-in", "elastic-out", "elastic-in-out", "elastic-out-in",
    "bounce-in", "bounce-out", "bounce-in-out", "bounce-out-in",
};
static_assert(kind_names.size() == static_cast<std::size_t>(CurveKind::bounce_out_in) + 1);

constexpr std::array<std::string_view, 4> position_names{"jump-start", "jump-end", "jump-none", "jump-both"};

bool is_back(CurveKind k) noexcept { return k >= CurveKind::back_in && k <= CurveKind::back_out_in; }
bool is_elastic(CurveKind k) noexcept { return k >= CurveKind::elastic_in && k <= CurveKind::elastic_out_in; }

using detail::number_text;

void check_finite(std::string_view where, std::string_view what, double v) {
    if (!std::isfinite(v))
        throw Error(std::string(where) + ": " + std::string(what) + " must be finite (got " + number_text(v) + ")");
}

// The shortest elastic period accepted (in units of t).
constexpr double min_elastic_period = 1e-15;

double default_period(EaseDirection direction) noexcept {
    return direction == EaseDirection::in_out ? ease::elastic_in_out_period : ease::elastic_period;
}

}  // namespace

Curve::Curve(EaseFamily family, EaseDirection direction) noexcept
    : kind_(static_cast<CurveKind>(1 + 4 * static_cast<int>(family) + static_cast<int>(direction))) {
    if (is_back(kind_)) p_[0] = ease::back_overshoot;
    if (is_elastic(kind_)) {
        p_[0] = ease::elastic_amplitude;
        p_[1] = default_period(direction);
    }
}

Curve::Curve(CurveKind kind) {
    if (kind > CurveKind::bounce_out_in)
        throw Error("Curve: kind " + std::string(to_string(kind)) +
                    " needs its parameters: use Curve::cubic_bezier, steps, monotone, svg, spring or from_function");
    if (kind == CurveKind::linear) return;
    const int index = static_cast<int>(kind) - 1;
    *this = Curve(static_cast<EaseFamily>(index / 4), static_cast<EaseDirection>(index % 4));
}

Curve Curve::back(EaseDirection direction, double overshoot) {
    check_finite("Curve::back", "overshoot", overshoot);
    if (overshoot < 0.0)
        throw Error("Curve::back: overshoot must be >= 0 (got " + number_text(overshoot) + ")");
    Curve c(EaseFamily::back, direction);
    c.p_[0] = overshoot;
    return c;
}

Curve Curve::elastic(EaseDirection direction, double amplitude, double period) {
    check_finite("Curve::elastic", "amplitude", amplitude);
    check_finite("Curve::elastic", "period", period);
    if (amplitude < 1.0)
        throw Error("Curve::elastic: amplitude must be >= 1, the distance from start to end (got " +
                    number_text(amplitude) + ")");
    // The formula divides by the period: below this 2π/p overflows to infinity and every
    // value is NaN (and a period this short swings 10¹⁵ times in t ∈ [0, 1], which no frame
    // rate shows). Periods ≤ 0 keep meaning "the default".
    if (period > 0.0 && period < min_elastic_period)
        throw Error("Curve::elastic: period must be >= " + number_text(min_elastic_period) + " or <= 0 for the default (got " +
                    number_text(period) + ")");
    Curve c(EaseFamily::elastic, direction);
    c.p_[0] = amplitude;
    c.p_[1] = period > 0.0 ? period : default_period(direction);
    return c;
}

Curve Curve::cubic_bezier(double x1, double y1, double x2, double y2) {
    const std::string where = "cubic-bezier";
    check_finite(where, "y1", y1);
    check_finite(where, "y2", y2);
    if (!(x1 >= 0.0 && x1 <= 1.0))
        throw Error(where + ": x1 must be in [0, 1] (got " + number_text(x1) + ")");
    if (!(x2 >= 0.0 && x2 <= 1.0))
        throw Error(where + ": x2 must be in [0, 1] (got " + number_text(x2) + ")");
    Curve c;
    c.kind_ = CurveKind::cubic_bezier;
    c.p_[0] = x1;
    c.p_[1] = y1;
    c.p_[2] = x2;
    c.p_[3] = y2;
    c.data_ = detail::cubic_bezier_table(x1, x2);
    return c;
}

Curve Curve::steps(int n, StepPosition position) {
    if (static_cast<int>(position) > 3)
        throw Error("steps: position must be jump-start, jump-end, jump-none or jump-both");
    const int minimum = position == StepPosition::jump_none ? 2 : 1;
    if (n < minimum)
        throw Error("steps: n must be >= " + std::to_string(minimum) + " for " +
                    std::string(position_names[static_cast<std::size_t>(position)]) + " (got " +
                    std::to_string(n) + ")");
    Curve c;
    c.kind_ = CurveKind::steps;
    c.p_[0] = n;
    c.p_[1] = static_cast<double>(static_cast<int>(position));
    return c;
}

Curve Curve::monotone(std::span<const double> x, std::span<const double> y) {
    const std::string where = "Curve::monotone";
    if (x.size() != y.size())
        throw Error(where + ": x and y must have the same size (got " + std::to_string(x.size()) + " and " +
                    std::to_string(y.size()) + ")");
    if (x.size() < 2) throw Error(where + ": needs at least 2 points (got " + std::to_string(x.size()) + ")");
    for (std::size_t i = 0; i < x.size(); ++i) {
        check_finite(where, "x[" + std::to_string(i) + "]", x[i]);
        check_finite(where, "y[" + std::to_string(i) + "]", y[i]);
        if (i > 0 && !(x[i] > x[i - 1]))
            throw Error(where + ": x must increase strictly (x[" + std::to_string(i) + "] = " + number_text(x[i]) +
                        " after " + number_text(x[i - 1]) + ")");
    }
    if (x.front() != 0.0) throw Error(where + ": x must start at 0 (got " + number_text(x.front()) + ")");
    if (x.back() != 1.0) throw Error(where + ": x must end at 1 (got " + number_text(x.back()) + ")");

    auto data = std::make_shared<detail::MonotoneData>();
    data->x.assign(x.begin(), x.end());
    data->y.assign(y.begin(), y.end());
    const std::size_t n = x.size();
    std::vector<double> delta(n - 1);
    for (std::size_t k = 0; k + 1 < n; ++k) delta[k] = (y[k + 1] - y[k]) / (x[k + 1] - x[k]);
    // Fritsch–Carlson: average secants, zero at local extrema, then shrink each segment's
    // pair of slopes into the circle α² + β² ≤ 9 that guarantees a monotone piece.
    std::vector<double>& m = data->m;
    m.assign(n, 0.0);
    m[0] = delta[0];
    m[n - 1] = delta[n - 2];
    for (std::size_t k = 1; k + 1 < n; ++k)
        m[k] = (delta[k - 1] * delta[k] > 0.0) ? 0.5 * (delta[k - 1] + delta[k]) : 0.0;
    for (std::size_t k = 0; k + 1 < n; ++k) {
        if (delta[k] == 0.0) {
            m[k] = 0.0;
            m[k + 1] = 0.0;
            continue;
        }
        const double alpha = m[k] / delta[k];
        const double beta = m[k + 1] / delta[k];
        const double r2 = alpha * alpha + beta * beta;
        if (r2 > 9.0) {
            const double tau = 3.0 / std::sqrt(r2);
            m[k] = tau * alpha * delta[k];
            m[k + 1] = tau * beta * delta[k];
        }
    }
    Curve c;
    c.kind_ = CurveKind::monotone;
    c.data_ = std::move(data);
    return c;
}

std::span<const double> Curve::knots_x() const noexcept {
    if (kind_ != CurveKind::monotone) return {};
    return static_cast<const detail::MonotoneData&>(*data_).x;
}

std::span<const double> Curve::knots_y() const noexcept {
    if (kind_ != CurveKind::monotone) return {};
    return static_cast<const detail::MonotoneData&>(*data_).y;
}

double Curve::settling_time() const noexcept {
    return kind_ == CurveKind::spring ? static_cast<const detail::SpringData&>(*data_).span : 0.0;
}

bool operator==(const Curve& a, const Curve& b) noexcept {
    if (a.kind_ != b.kind_) return false;
    for (int i = 0; i < 4; ++i)
        if (!(a.p_[i] == b.p_[i])) return false;
    if (a.data_ == b.data_) return true;
    switch (a.kind_) {
        case CurveKind::monotone: {
            const auto& x = static_cast<const detail::MonotoneData&>(*a.data_);
            const auto& y = static_cast<const detail::MonotoneData&>(*b.data_);
            return x.x == y.x && x.y == y.y;
        }
        case CurveKind::svg:
            return detail::svg_same(static_cast<const detail::SvgData&>(*a.data_),
                                    static_cast<const detail::SvgData&>(*b.data_));
        case CurveKind::spring:
            return static_cast<const detail::SpringData&>(*a.data_).by_duration ==
                   static_cast<const detail::SpringData&>(*b.data_).by_duration;
        case CurveKind::function: return false;  // different callables (copies share data_)
        default: return true;
    }
}

std::string_view to_string(CurveKind kind) noexcept {
    const auto i = static_cast<std::size_t>(kind);
    if (i < kind_names.size()) return kind_names[i];
    switch (kind) {
        case CurveKind::cubic_bezier: return "cubic-bezier";
        case CurveKind::steps: return "steps";
        case CurveKind::monotone: return "monotone";
        case CurveKind::svg: return "svg";
        case CurveKind::spring: return "spring";
        case CurveKind::function: return "function";
        default: return "unknown";
    }
}

std::span<const std::string_view> curve_names() noexcept { return kind_names; }

std::string to_string(const Curve& c) {
    const CurveKind k = c.kind();
    std::string name(to_string(k));
    // "(a,b,...)" appended to the name in place (no temporaries to concatenate).
    const auto arguments = [&name](std::initializer_list<std::string_view> args) {
        name += '(';
        for (const std::string_view& a : args) {
            if (&a != args.begin()) name += ',';
            name += a;
        }
        name += ')';
    };
    const auto p = [&c](int i) { return number_text(c.parameter(i)); };
    if (is_back(k)) {
        if (c.parameter(0) != ease::back_overshoot) arguments({p(0)});
    } else if (is_elastic(k)) {
        const double period = k == CurveKind::elastic_in_out ? ease::elastic_in_out_period : ease::elastic_period;  // out-in: 0.3
        if (c.parameter(0) != ease::elastic_amplitude || c.parameter(1) != period) arguments({p(0), p(1)});
    } else if (k == CurveKind::cubic_bezier) {
        arguments({p(0), p(1), p(2), p(3)});
    } else if (k == CurveKind::steps) {
        arguments({p(0), position_names[static_cast<std::size_t>(c.parameter(1))]});
    } else if (k == CurveKind::monotone) {
        name += "(";
        const auto x = c.knots_x();
        const auto y = c.knots_y();
        for (std::size_t i = 0; i < x.size(); ++i) {
            if (i > 0) name += ",";
            name += number_text(x[i]) + "," + number_text(y[i]);
        }
        name += ")";
    } else if (k == CurveKind::svg) {
        name += '(';
        name += detail::svg_text(detail::data_of<detail::SvgData>(c));
        name += ')';
    } else if (k == CurveKind::spring) {
        if (detail::data_of<detail::SpringData>(c).by_duration) {
            name = "spring-duration";
            arguments({p(0), p(1), p(2)});
        } else {
            arguments({p(0), p(1), p(2), p(3)});
        }
    }
    return name;
}

namespace {

std::string_view trim(std::string_view s) noexcept {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

[[noreturn]] void unknown_curve(std::string_view text, std::string_view reason) {
    std::string message = "parse_curve: " + std::string(reason) + " '" + std::string(text) + "'; valid names: ";
    for (std::string_view n : kind_names) message += std::string(n) + ", ";
    message +=
        "back-in|out|in-out(overshoot), elastic-in|out|in-out(amplitude,period), cubic-bezier(x1,y1,x2,y2), "
        "ease, ease-in, ease-out, ease-in-out, steps(n[,jump-start|jump-end|jump-none|jump-both|start|end]), "
        "step-start, step-end, monotone(x0,y0,x1,y1,...), svg(SVG path data from x = 0 to x = 1), "
        "spring(stiffness,damping[,mass[,velocity]]), spring-duration(duration[,bounce[,velocity]])";
    throw Error(message);
}

double parse_number(std::string_view whole, std::string_view text) {
    text = trim(text);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double value = 0.0;
    if (!detail::parse_finite(text, value))
        throw Error("parse_curve: '" + std::string(text) + "' is not a finite number in '" + std::string(whole) + "'");
    return value;
}

std::string normalized_name(std::string_view s) {
    std::string out(s);
    for (char& ch : out) {
        if (ch == '_') ch = '-';
        if (ch >= 'A' && ch <= 'Z') ch = static_cast<char>(ch - 'A' + 'a');
    }
    return out;
}

}  // namespace

Curve parse_curve(std::string_view text) {
    const std::string_view whole = trim(text);
    const std::size_t open = whole.find('(');
    const std::string name = normalized_name(trim(whole.substr(0, open)));
    if (name == "svg") {
        // The path data keeps its commas and spaces: everything between the parentheses.
        if (open == std::string_view::npos || whole.back() != ')')
            unknown_curve(text, "svg takes its path data in parentheses:");
        return Curve::svg(whole.substr(open + 1, whole.size() - open - 2));
    }
    std::vector<std::string_view> args;
    if (open != std::string_view::npos) {
        if (whole.back() != ')') unknown_curve(text, "missing ')' in");
        std::string_view inside = whole.substr(open + 1, whole.size() - open - 2);
        while (true) {
            const std::size_t comma = inside.find(',');
            args.push_back(trim(inside.substr(0, comma)));
            if (comma == std::string_view::npos) break;
            inside.remove_prefix(comma + 1);
        }
    }
    auto expect_args = [&](std::size_t lo, std::size_t hi) {
        if (args.size() < lo || args.size() > hi)
            throw Error("parse_curve: '" + std::string(whole) + "' takes " + std::to_string(lo) +
                        (hi != lo ? " to " + std::to_string(hi) : std::string()) + " arguments (got " +
                        std::to_string(args.size()) + ")");
    };
    auto number = [&](std::size_t i) { return parse_number(whole, args[i]); };

    if (name == "cubic-bezier") {
        expect_args(4, 4);
        return Curve::cubic_bezier(number(0), number(1), number(2), number(3));
    }
    if (name == "ease" || name == "ease-in" || name == "ease-out" || name == "ease-in-out") {
        if (open != std::string_view::npos) unknown_curve(text, "CSS keywords take no arguments:");
        if (name == "ease") return Curve::cubic_bezier(0.25, 0.1, 0.25, 1.0);
        if (name == "ease-in") return Curve::cubic_bezier(0.42, 0.0, 1.0, 1.0);
        if (name == "ease-out") return Curve::cubic_bezier(0.0, 0.0, 0.58, 1.0);
        return Curve::cubic_bezier(0.42, 0.0, 0.58, 1.0);
    }
    if (name == "step-start" && open == std::string_view::npos) return Curve::steps(1, StepPosition::jump_start);
    if (name == "step-end" && open == std::string_view::npos) return Curve::steps(1, StepPosition::jump_end);
    if (name == "steps") {
        expect_args(1, 2);
        const double n = number(0);
        if (n != std::floor(n) || n < 1.0 || n > 1e9)
            throw Error("parse_curve: steps count must be a whole number >= 1 (got '" + std::string(args[0]) + "')");
        StepPosition position = StepPosition::jump_end;
        if (args.size() == 2) {
            const std::string p = normalized_name(args[1]);
            if (p == "jump-start" || p == "start") position = StepPosition::jump_start;
            else if (p == "jump-end" || p == "end") position = StepPosition::jump_end;
            else if (p == "jump-none") position = StepPosition::jump_none;
            else if (p == "jump-both") position = StepPosition::jump_both;
            else
                throw Error("parse_curve: unknown steps position '" + std::string(args[1]) +
                            "'; valid: jump-start, jump-end, jump-none, jump-both, start, end");
        }
        return Curve::steps(static_cast<int>(n), position);
    }
    if (name == "monotone") {
        if (args.size() < 4 || args.size() % 2 != 0)
            throw Error("parse_curve: monotone takes x, y pairs, at least 2 (got " + std::to_string(args.size()) +
                        " numbers in '" + std::string(whole) + "')");
        std::vector<double> x;
        std::vector<double> y;
        for (std::size_t i = 0; i < args.size(); i += 2) {
            x.push_back(number(i));
            y.push_back(number(i + 1));
        }
        return Curve::monotone(x, y);
    }
    if (name == "spring") {
        expect_args(2, 4);
        return Curve::spring({.stiffness = number(0),
                              .damping = number(1),
                              .mass = args.size() > 2 ? number(2) : 1.0,
                              .velocity = args.size() > 3 ? number(3) : 0.0});
    }
    if (name == "spring-duration") {
        expect_args(1, 3);
        return Curve::spring_duration(number(0), args.size() > 1 ? number(1) : 0.0, args.size() > 2 ? number(2) : 0.0);
    }
    if (name == "function")
        throw Error("parse_curve: a function curve (Curve::from_function) has no text form; give it in code");
    for (std::size_t i = 0; i < kind_names.size(); ++i) {
        if (name != kind_names[i]) continue;
        const auto kind = static_cast<CurveKind>(i);
        if (open == std::string_view::npos) return Curve(kind);
        const int index = static_cast<int>(i) - 1;
        const auto direction = static_cast<EaseDirection>(index % 4);
        if (is_back(kind)) {
            expect_args(1, 1);
            return Curve::back(direction, number(0));
        }
        if (is_elastic(kind)) {
            expect_args(1, 2);
            return Curve::elastic(direction, number(0), args.size() == 2 ? number(1) : 0.0);
        }
        unknown_curve(text, "this curve takes no arguments:");
    }
    unknown_curve(text, "unknown curve name");
}

}  // namespace grape
