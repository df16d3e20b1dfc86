// A curve from SVG path data, as GSAP's CustomEase reads one: progress = y at x.
#include "curve_data.hpp"

#include <grape/curve.hpp>
#include <grape/error.hpp>
#include <grape/path.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <variant>

namespace grape {

namespace detail {

namespace {

using Kind = SvgPiece::Kind;

// y at x on one piece whose x runs from cx[0] to cx[3] (> cx[0]), for x in [cx[0], cx[3]):
// solved from the nearer end, so that x − x0 or x3 − x is exact (Sterbenz) and the Bernstein
// sums keep their digits next to that end.
double piece_y(const SvgPiece& p, double x) noexcept {
    const double x0 = p.cx[0];
    const double x3 = p.cx[3];
    if (p.kind == Kind::line) {
        const double y0 = p.cy[0];
        const double y3 = p.cy[3];
        if (x - x0 <= x3 - x) return y0 + (y3 - y0) * ((x - x0) / (x3 - x0));
        return y3 - (y3 - y0) * ((x3 - x) / (x3 - x0));
    }
    if (x - x0 <= x3 - x) {
        const double v = x - x0;
        if (!(v > 0.0)) return p.cy[0];
        const double s = bernstein_solve(p.cx[1] - x0, p.cx[2] - x0, x3 - x0, v);
        return p.cy[0] + bernstein(p.cy[1] - p.cy[0], p.cy[2] - p.cy[0], p.cy[3] - p.cy[0], s);
    }
    const double w = bernstein_solve(x3 - p.cx[2], x3 - p.cx[1], x3 - x0, x3 - x);
    return p.cy[3] - bernstein(p.cy[3] - p.cy[2], p.cy[3] - p.cy[1], p.cy[3] - p.cy[0], w);
}

std::string point_text(double x, double y) {
    std::string out = number_text(x);
    out += ',';
    out += number_text(y);
    return out;
}

}  // namespace

double svg_eval(const CurveData& base, double t) noexcept {
    const auto& d = static_cast<const SvgData&>(base);
    if (!(t > 0.0)) return std::isnan(t) ? t : d.y_start;
    if (t >= 1.0) return d.y_end;
    // The last piece starting at or before t (a vertical piece at t is passed over: y jumps).
    const auto k = static_cast<std::size_t>(std::upper_bound(d.start_x.begin(), d.start_x.end(), t) - d.start_x.begin()) - 1;
    return piece_y(d.pieces[k], t);
}

std::string svg_text(const SvgData& d) {
    std::string out = "M";  // appended, not "M" + text: g++ 12 -O3 misreads that as an overlapping copy
    out += point_text(d.pieces.front().px[0], d.pieces.front().py[0]);
    for (const SvgPiece& p : d.pieces) {
        const int n = p.kind == Kind::line ? 2 : p.kind == Kind::quadratic ? 3 : 4;
        out += p.kind == Kind::line ? " L" : p.kind == Kind::quadratic ? " Q" : " C";
        for (int i = 1; i < n; ++i) {
            if (i > 1) out += ' ';
            out += point_text(p.px[i], p.py[i]);
        }
    }
    return out;
}

bool svg_same(const SvgData& a, const SvgData& b) noexcept {
    if (a.pieces.size() != b.pieces.size()) return false;
    for (std::size_t i = 0; i < a.pieces.size(); ++i) {
        const SvgPiece& p = a.pieces[i];
        const SvgPiece& q = b.pieces[i];
        if (p.kind != q.kind) return false;
        for (int j = 0; j < 4; ++j)
            if (p.px[j] != q.px[j] || p.py[j] != q.py[j]) return false;
    }
    return true;
}

}  // namespace detail

namespace {

using detail::number_text;
using detail::point_text;
using detail::SvgPiece;
using Kind = SvgPiece::Kind;

// Ends and joins are matched within this: relative commands add their offsets, so a path
// meant to end at x = 1 may end a few ulp away; 1e-12 is ~4500 ulp of 1, far above that
// rounding and far below any visible step.
constexpr double join_tolerance = 1e-12;

std::string segment_name(std::size_t i, const SvgPiece& p) {
    const char* command = p.kind == Kind::line ? "L" : p.kind == Kind::quadratic ? "Q" : "C";
    std::string out = "segment ";
    out += std::to_string(i + 1);
    out += " (";
    out += command;
    out += " from ";
    out += point_text(p.px[0], p.py[0]);
    out += ')';
    return out;
}

// x never decreasing along the piece, checked exactly on its points: a line or quadratic's x′
// is linear in s (non-negative at both ends suffices); a cubic's x′/3 is the quadratic
// Bernstein polynomial a(1−s)² + 2b(1−s)s + cs², non-negative on [0, 1] exactly when a ≥ 0,
// c ≥ 0 and (b ≥ 0 or b² ≤ ac). b² ≤ ac is allowed 4 ulp of slack: a tangent-touching
// control polygon (b² = ac) computed from rounded differences must not be refused.
bool x_never_decreases(const SvgPiece& p) noexcept {
    if (p.kind == Kind::line) return p.px[1] >= p.px[0];
    if (p.kind == Kind::quadratic) return p.px[1] >= p.px[0] && p.px[2] >= p.px[1];
    const double a = p.px[1] - p.px[0];
    const double b = p.px[2] - p.px[1];
    const double c = p.px[3] - p.px[2];
    if (a < 0.0 || c < 0.0) return false;
    return b >= 0.0 || b * b <= a * c * (1.0 + 4.0 * std::numeric_limits<double>::epsilon());
}

// The piece's cubic form (lines keep their two points, evaluated as lines).
void set_cubic(SvgPiece& p) noexcept {
    if (p.kind == Kind::cubic) {
        std::copy(p.px, p.px + 4, p.cx);
        std::copy(p.py, p.py + 4, p.cy);
    } else if (p.kind == Kind::line) {
        p.cx[0] = p.px[0], p.cx[3] = p.px[1];
        p.cy[0] = p.py[0], p.cy[3] = p.py[1];
    } else {
        // Degree elevation: C1 = Q0 + ⅔(Q1 − Q0), C2 = Q2 + ⅔(Q1 − Q2) (exact but for rounding).
        p.cx[0] = p.px[0], p.cx[3] = p.px[2];
        p.cy[0] = p.py[0], p.cy[3] = p.py[2];
        p.cx[1] = p.px[0] + 2.0 / 3.0 * (p.px[1] - p.px[0]);
        p.cy[1] = p.py[0] + 2.0 / 3.0 * (p.py[1] - p.py[0]);
        p.cx[2] = p.px[2] + 2.0 / 3.0 * (p.px[1] - p.px[2]);
        p.cy[2] = p.py[2] + 2.0 / 3.0 * (p.py[1] - p.py[2]);
    }
}

}  // namespace

Curve Curve::svg(std::string_view data) {
    const std::string where = "Curve::svg";
    const ComplexPath path = [&] {
        try {
            return parse_svg_path(data);
        } catch (const Error& e) {
            throw Error(where + ": " + e.what());
        }
    }();
    if (!(path.length() > 0.0)) throw Error(where + ": the path data draws nothing");
    auto d = std::make_shared<detail::SvgData>();
    for (const Path& part : path.parts()) {
        const PathSpec spec = describe(part);
        SvgPiece p;
        if (const auto* line = std::get_if<LinearSpec>(&spec)) {
            p.kind = Kind::line;
            p.px[0] = line->start.x, p.py[0] = line->start.y;
            p.px[1] = line->end.x, p.py[1] = line->end.y;
        } else if (const auto* q = std::get_if<QuadraticBezierSpec>(&spec)) {
            p.kind = Kind::quadratic;
            for (int i = 0; i < 3; ++i) p.px[i] = q->control[i].x, p.py[i] = q->control[i].y;
        } else if (const auto* c = std::get_if<CubicBezierSpec>(&spec)) {
            p.kind = Kind::cubic;
            for (int i = 0; i < 4; ++i) p.px[i] = c->control[i].x, p.py[i] = c->control[i].y;
        } else {
            throw Error(where + ": segment " + std::to_string(d->pieces.size() + 1) +
                        " is an arc; an easing path takes lines and Béziers (M L H V C S Q T), write the arc as C");
        }
        if (!d->pieces.empty()) {
            // One continuous path: this piece starts where the last one ended (a tiny gap left
            // by rounding or a dropped zero-length segment is closed).
            const SvgPiece& prev = d->pieces.back();
            const int prev_last = prev.kind == Kind::line ? 1 : prev.kind == Kind::quadratic ? 2 : 3;
            if (std::abs(p.px[0] - prev.px[prev_last]) > join_tolerance ||
                std::abs(p.py[0] - prev.py[prev_last]) > join_tolerance)
                throw Error(where + ": " + segment_name(d->pieces.size(), p) + " does not start where segment " +
                            std::to_string(d->pieces.size()) + " ends (" + number_text(prev.px[prev_last]) + "," +
                            number_text(prev.py[prev_last]) + "): the data must be one continuous path");
            p.px[0] = prev.px[prev_last];
            p.py[0] = prev.py[prev_last];
        } else {
            if (std::abs(p.px[0]) > join_tolerance)
                throw Error(where + ": the path must start at x = 0 (got " + number_text(p.px[0]) + ")");
            p.px[0] = 0.0;
        }
        if (!x_never_decreases(p))
            throw Error(where + ": " + segment_name(d->pieces.size(), p) +
                        " goes back in x; progress is y at x, so x must never decrease along the path");
        d->pieces.push_back(p);
    }
    SvgPiece& end = d->pieces.back();
    const int end_last = end.kind == Kind::line ? 1 : end.kind == Kind::quadratic ? 2 : 3;
    if (std::abs(end.px[end_last] - 1.0) > join_tolerance)
        throw Error(where + ": the path must end at x = 1 (got " + number_text(end.px[end_last]) + ")");
    end.px[end_last] = 1.0;
    for (std::size_t i = 0; i < d->pieces.size(); ++i) {
        SvgPiece& p = d->pieces[i];
        if (!x_never_decreases(p))  // again, after the end was set to 1
            throw Error(where + ": " + segment_name(i, p) +
                        " goes back in x; progress is y at x, so x must never decrease along the path");
        set_cubic(p);
        d->start_x.push_back(p.cx[0]);
    }
    d->y_start = d->pieces.front().py[0];
    d->y_end = end.py[end_last];
    Curve c;
    c.kind_ = CurveKind::svg;
    c.data_ = std::move(d);
    return c;
}

}  // namespace grape
