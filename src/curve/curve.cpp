// Curves: validation, the solver for CSS cubic-bezier, steps, the monotone cubic, and names.
#include <grape/curve.hpp>
#include <grape/error.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace grape {

namespace detail {

struct MonotoneData {
    std::vector<double> x;
    std::vector<double> y;
    std::vector<double> m;  // dy/dx at each knot
};

double cubic_bezier_eval(double x1, double y1, double x2, double y2, double t) noexcept {
    if (!(t > 0.0)) {
        if (!(t < 0.0)) return t;  // 0 (exact) or NaN (passed through, never invented)
        // CSS: a straight line through the start with the start tangent.
        const double slope = x1 > 0.0 ? y1 / x1 : (x2 > 0.0 ? y2 / x2 : 0.0);
        return slope * t;
    }
    if (t >= 1.0) {
        if (t == 1.0) return 1.0;
        const double slope = x2 < 1.0 ? (y2 - 1.0) / (x2 - 1.0) : (x1 < 1.0 ? (y1 - 1.0) / (x1 - 1.0) : 0.0);
        return 1.0 + slope * (t - 1.0);
    }
    // Power form: x(u) = ((ax·u + bx)·u + cx)·u, monotone on [0, 1] because x1, x2 ∈ [0, 1].
    const double cx = 3.0 * x1;
    const double bx = 3.0 * (x2 - x1) - cx;
    const double ax = 1.0 - cx - bx;
    const double cy = 3.0 * y1;
    const double by = 3.0 * (y2 - y1) - cy;
    const double ay = 1.0 - cy - by;
    constexpr double tolerance = 1e-12;
    auto x_of = [&](double u) { return ((ax * u + bx) * u + cx) * u; };

    double u = t;
    bool solved = false;
    for (int i = 0; i < 8; ++i) {
        const double f = x_of(u) - t;
        if (std::abs(f) <= tolerance) { solved = true; break; }
        const double slope = (3.0 * ax * u + 2.0 * bx) * u + cx;
        if (std::abs(slope) < 1e-9) break;  // flat spot: Newton would fly off
        u -= f / slope;
        if (!(u >= 0.0 && u <= 1.0)) break;
    }
    if (!solved) {
        // Bisection always converges: x is non-decreasing and x(0) = 0 < t < 1 = x(1).
        double lo = 0.0;
        double hi = 1.0;
        u = t;
        for (int i = 0; i < 200; ++i) {
            const double f = x_of(u) - t;
            if (std::abs(f) <= tolerance) break;
            if (f > 0.0) hi = u; else lo = u;
            u = 0.5 * (lo + hi);
        }
    }
    return ((ay * u + by) * u + cy) * u;
}

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

double monotone_eval(const MonotoneData& d, double t) noexcept {
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

constexpr std::array<std::string_view, 31> kind_names{
    "linear",
    "quad-in", "quad-out", "quad-in-out",
    "cubic-in", "cubic-out", "cubic-in-out",
    "quart-in", "quart-out", "quart-in-out",
    "quint-in", "quint-out", "quint-in-out",
    "sine-in", "sine-out", "sine-in-out",
    "expo-in", "expo-out", "expo-in-out",
    "circ-in", "circ-out", "circ-in-out",
    "back-in", "back-out", "back-in-out",
    "elastic-in", "elastic-out", "elastic-in-out",
    "bounce-in", "bounce-out", "bounce-in-out",
};

constexpr std::array<std::string_view, 4> position_names{"jump-start", "jump-end", "jump-none", "jump-both"};

bool is_back(CurveKind k) noexcept { return k >= CurveKind::back_in && k <= CurveKind::back_in_out; }
bool is_elastic(CurveKind k) noexcept { return k >= CurveKind::elastic_in && k <= CurveKind::elastic_in_out; }

using detail::number_text;

void check_finite(std::string_view where, std::string_view what, double v) {
    if (!std::isfinite(v))
        throw Error(std::string(where) + ": " + std::string(what) + " must be finite (got " + number_text(v) + ")");
}

double default_period(EaseDirection direction) noexcept {
    return direction == EaseDirection::in_out ? ease::elastic_in_out_period : ease::elastic_period;
}

}  // namespace

Curve::Curve(EaseFamily family, EaseDirection direction) noexcept
    : kind_(static_cast<CurveKind>(1 + 3 * static_cast<int>(family) + static_cast<int>(direction))) {
    if (is_back(kind_)) p_[0] = ease::back_overshoot;
    if (is_elastic(kind_)) {
        p_[0] = ease::elastic_amplitude;
        p_[1] = default_period(direction);
    }
}

Curve::Curve(CurveKind kind) {
    if (kind > CurveKind::bounce_in_out)
        throw Error("Curve: kind " + std::string(to_string(kind)) +
                    " needs its parameters: use Curve::cubic_bezier, Curve::steps or Curve::monotone");
    if (kind == CurveKind::linear) return;
    const int index = static_cast<int>(kind) - 1;
    *this = Curve(static_cast<EaseFamily>(index / 3), static_cast<EaseDirection>(index % 3));
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
    c.points_ = std::move(data);
    return c;
}

std::span<const double> Curve::knots_x() const noexcept {
    return points_ ? std::span<const double>(points_->x) : std::span<const double>();
}

std::span<const double> Curve::knots_y() const noexcept {
    return points_ ? std::span<const double>(points_->y) : std::span<const double>();
}

bool operator==(const Curve& a, const Curve& b) noexcept {
    if (a.kind_ != b.kind_) return false;
    for (int i = 0; i < 4; ++i)
        if (!(a.p_[i] == b.p_[i])) return false;
    if (a.kind_ != CurveKind::monotone) return true;
    return a.points_ == b.points_ || (a.points_->x == b.points_->x && a.points_->y == b.points_->y);
}

std::string_view to_string(CurveKind kind) noexcept {
    const auto i = static_cast<std::size_t>(kind);
    if (i < kind_names.size()) return kind_names[i];
    switch (kind) {
        case CurveKind::cubic_bezier: return "cubic-bezier";
        case CurveKind::steps: return "steps";
        case CurveKind::monotone: return "monotone";
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
        const double period = k == CurveKind::elastic_in_out ? ease::elastic_in_out_period : ease::elastic_period;
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
        "step-start, step-end, monotone(x0,y0,x1,y1,...)";
    throw Error(message);
}

double parse_number(std::string_view whole, std::string_view text) {
    text = trim(text);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double value = 0.0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size() || !std::isfinite(value))
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
    for (std::size_t i = 0; i < kind_names.size(); ++i) {
        if (name != kind_names[i]) continue;
        const auto kind = static_cast<CurveKind>(i);
        if (open == std::string_view::npos) return Curve(kind);
        const int index = static_cast<int>(i) - 1;
        const auto direction = static_cast<EaseDirection>(index % 3);
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
