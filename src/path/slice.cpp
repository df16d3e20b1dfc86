// grape — exact slices of paths (blossoms for the polynomial kinds, angle ranges for arcs,
// parts for complex paths), points beside a path, and SVG path data from a path.
#include <grape/error.hpp>
#include <grape/path_query.hpp>

#include "kinds.hpp"
#include "math/number_text.hpp"
#include "path_node.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace grape {

namespace {

using detail::ArcNode;
using detail::ComplexNode;
using detail::CubicBezierNode;
using detail::CubicSplineNode;
using detail::PolylineNode;
using detail::QuadraticNode;
using detail::ReparametrizedNode;
using detail::SpiralNode;

[[noreturn]] void slice_fail(const char* who, const std::string& what) { throw Error(std::string(who) + ": " + what); }

// The blossom of a cubic Bézier: de Casteljau with a different t per level. Its values at
// (a,a,a), (a,a,b), (a,b,b), (b,b,b) are the control points of the piece over [a, b].
Vec2 blossom(const Vec2 (&p)[4], double t1, double t2, double t3) noexcept {
    const Vec2 a = lerp(p[0], p[1], t1), b = lerp(p[1], p[2], t1), c = lerp(p[2], p[3], t1);
    const Vec2 d = lerp(a, b, t2), e = lerp(b, c, t2);
    return lerp(d, e, t3);
}

// The blossom of a power-basis cubic c0 + c1·t + c2·t² + c3·t³.
Vec2 blossom(const CubicSplineNode::Segment& s, double x, double y, double z) noexcept {
    return s.c0 + s.c1 * ((x + y + z) / 3.0) + s.c2 * ((x * y + y * z + z * x) / 3.0) + s.c3 * (x * y * z);
}

// Per-segment pieces of an n-segment spline over [u0, u1]: segment, local t range, cue.
template <class Emit>
void spline_pieces(std::size_t n, double u0, double u1, Emit emit) {
    const double nn = static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double lo = static_cast<double>(i) / nn, hi = static_cast<double>(i + 1) / nn;
        const double a = std::max(u0, lo), b = std::min(u1, hi);
        if (!(b > a)) continue;
        const double base = static_cast<double>(i);
        emit(i, std::clamp(a * nn - base, 0.0, 1.0), std::clamp(b * nn - base, 0.0, 1.0),
             std::clamp((a - u0) / (u1 - u0), 0.0, 1.0));
    }
}

// The parts a complex path travels, with their spans: ComplexNode's rule skips an empty span
// and one too thin for 1/width.
template <class F>
void for_each_part(const ComplexNode& c, F f) {
    for (std::size_t i = 0; i < c.parts.size(); ++i) {
        const double start = c.cues[i];
        const double end = i + 1 < c.parts.size() ? c.cues[i + 1] : 1.0;
        if (!(end > start) || !std::isfinite(1.0 / (end - start))) continue;
        f(c.parts[i], start, end);
    }
}

Path cut(const Path& path, double u0, double u1);

Path cut_complex(const ComplexNode& c, double u0, double u1) {
    std::vector<Path> parts;
    std::vector<double> cues;
    for_each_part(c, [&](const Path& part, double start, double end) {
        const double a = std::max(u0, start), b = std::min(u1, end);
        if (!(b > a)) return;
        const double width = end - start;
        const double lo = std::clamp((a - start) / width, 0.0, 1.0);
        const double hi = b >= end ? 1.0 : std::clamp((b - start) / width, 0.0, 1.0);
        if (!(hi > lo)) return;
        parts.push_back(cut(part, lo, hi));
        cues.push_back(parts.size() == 1 ? 0.0 : std::clamp((a - u0) / (u1 - u0), cues.back(), 1.0));
    });
    if (parts.empty()) return LinearPath(c.point(u0), c.point(u0));
    return ComplexPath(std::move(parts), std::move(cues));
}

Path cut(const Path& path, double u0, double u1) {
    if (u0 == 0.0 && u1 == 1.0) return path;
    const detail::PathNode& node = detail::NodeAccess::node(path);
    switch (node.kind()) {
        case PathKind::linear: return LinearPath(path.point(u0), path.point(u1));
        case PathKind::circle:
        case PathKind::elliptical_arc: {
            const auto& a = static_cast<const ArcNode&>(node);
            const double t0 = a.a0 + (a.a1 - a.a0) * u0, t1 = u1 == 1.0 ? a.a1 : a.a0 + (a.a1 - a.a0) * u1;
            if (node.kind() == PathKind::circle) return CirclePath(a.center, a.rx, t0, t1);
            return EllipticalArcPath(a.center, a.rx, a.ry, a.rotation, t0, t1);
        }
        case PathKind::spiral: {
            const auto& s = static_cast<const SpiralNode&>(node);
            auto at = [](double from, double to, double u) { return u == 1.0 ? to : from + (to - from) * u; };
            return SpiralPath(s.center, std::max(0.0, at(s.r0, s.r1, u0)), std::max(0.0, at(s.r0, s.r1, u1)),
                              at(s.a0, s.a1, u0), at(s.a0, s.a1, u1));
        }
        case PathKind::quadratic_bezier: {
            const auto& q = static_cast<const QuadraticNode&>(node);
            const auto& p = q.inputs;
            auto bl = [&p](double s, double t) { return lerp(lerp(p[0], p[1], s), lerp(p[1], p[2], s), t); };
            return QuadraticBezierPath(bl(u0, u0), bl(u0, u1), bl(u1, u1));
        }
        case PathKind::physics: {
            const auto& q = static_cast<const QuadraticNode&>(node);
            const double t0 = u0 * q.seconds;
            return PhysicsPath(path.point(u0), q.inputs[1] + q.inputs[2] * t0, q.inputs[2], (u1 - u0) * q.seconds);
        }
        case PathKind::cubic_bezier: {
            const auto& b = static_cast<const CubicBezierNode&>(node);
            return CubicBezierPath(blossom(b.p, u0, u0, u0), blossom(b.p, u0, u0, u1), blossom(b.p, u0, u1, u1),
                                   blossom(b.p, u1, u1, u1));
        }
        case PathKind::linear_spline: {
            const auto& s = static_cast<const PolylineNode&>(node);
            std::vector<Path> parts;
            std::vector<double> cues;
            spline_pieces(s.points.size() - 1, u0, u1, [&](std::size_t i, double a, double b, double cue) {
                parts.push_back(LinearPath(lerp(s.points[i], s.points[i + 1], a), lerp(s.points[i], s.points[i + 1], b)));
                cues.push_back(cues.empty() ? 0.0 : std::max(cue, cues.back()));
            });
            if (parts.size() == 1) return parts.front();
            return ComplexPath(std::move(parts), std::move(cues));
        }
        case PathKind::hermite_spline:
        case PathKind::catmull_rom_spline: {
            const auto& s = static_cast<const CubicSplineNode&>(node);
            std::vector<Path> parts;
            std::vector<double> cues;
            spline_pieces(s.segments.size(), u0, u1, [&](std::size_t i, double a, double b, double cue) {
                const auto& g = s.segments[i];
                parts.push_back(CubicBezierPath(blossom(g, a, a, a), blossom(g, a, a, b), blossom(g, a, b, b),
                                                blossom(g, b, b, b)));
                cues.push_back(cues.empty() ? 0.0 : std::max(cue, cues.back()));
            });
            if (parts.size() == 1) return parts.front();
            return ComplexPath(std::move(parts), std::move(cues));
        }
        case PathKind::complex: return cut_complex(static_cast<const ComplexNode&>(node), u0, u1);
        case PathKind::reparametrized: {
            const auto& r = static_cast<const ReparametrizedNode&>(node);
            return cut(r.source(), r.source_u(u0), r.source_u(u1)).reparametrized();
        }
        case PathKind::sine_wave:
            slice_fail("slice", "a sine wave has no exact slice among the path kinds (its phase); slice a complex path "
                          "or spline that approximates it instead");
        case PathKind::cosine_spline:
            slice_fail("slice", "a cosine spline has no exact slice among the path kinds (the easing inside a segment)");
    }
    slice_fail("slice", "unknown path kind");
}

// --- SVG path data ----------------------------------------------------------------------------

struct SvgWriter {
    std::string out;
    Vec2 pen{std::nan(""), std::nan("")};

    void number(double v) { out += detail::general_text(v == 0.0 ? 0.0 : v, 17); }  // no "-0"
    void command(char c, std::initializer_list<Vec2> points) {
        if (!out.empty()) out += ' ';
        out += c;
        bool first = true;
        for (const Vec2 p : points) {
            if (!first) out += ' ';
            first = false;
            number(p.x);
            out += ' ';
            number(p.y);
        }
        pen = points.size() ? *(points.end() - 1) : pen;
    }
    // A part that starts where the pen is (to rounding: the parser's arc centers and ends agree
    // to a few ulps) continues the subpath.
    void move_to(Vec2 p) {
        const double scale = std::max({std::abs(p.x), std::abs(p.y), 1.0});
        if (!(distance(p, pen) <= 1e-12 * scale)) command('M', {p});
    }

    void arc(const ArcNode& a) {
        const double span = a.a1 - a.a0;
        // Pieces of at most a quarter turn: the large-arc flag is 0, and a reader's center from the
        // end points stays well conditioned (it is not near a half turn).
        const int n = std::max(1, static_cast<int>(std::ceil(std::abs(span) / (0.5 * pi))));
        for (int k = 1; k <= n; ++k) {
            const double theta = k == n ? a.a1 : a.a0 + span * k / n;
            const Vec2 end = a.at_angle(theta);
            out += " A";
            number(a.rx);
            out += ' ';
            number(a.ry);
            out += ' ';
            number(a.rotation * 180.0 / pi);
            out += span > 0.0 ? " 0 1 " : " 0 0 ";  // y down: increasing angles sweep positively
            number(end.x);
            out += ' ';
            number(end.y);
            pen = end;
        }
    }

    void path(const Path& p) {
        const detail::PathNode& node = detail::NodeAccess::node(p);
        move_to(node.point(0.0));
        switch (node.kind()) {
            case PathKind::linear: command('L', {node.point(1.0)}); return;
            case PathKind::circle:
            case PathKind::elliptical_arc: arc(static_cast<const ArcNode&>(node)); return;
            case PathKind::quadratic_bezier:
            case PathKind::physics: {
                const auto& q = static_cast<const QuadraticNode&>(node);
                command('Q', {q.c[0] + 0.5 * q.c[1], node.point(1.0)});
                return;
            }
            case PathKind::cubic_bezier: {
                const auto& b = static_cast<const CubicBezierNode&>(node);
                command('C', {b.p[1], b.p[2], b.p[3]});
                return;
            }
            case PathKind::linear_spline:
            case PathKind::cosine_spline: {
                const auto& s = static_cast<const PolylineNode&>(node);
                for (std::size_t i = 1; i < s.points.size(); ++i) command('L', {s.points[i]});
                return;
            }
            case PathKind::hermite_spline:
            case PathKind::catmull_rom_spline: {
                for (const auto& g : static_cast<const CubicSplineNode&>(node).segments) {
                    command('C', {blossom(g, 0, 0, 1), blossom(g, 0, 1, 1), g.c0 + g.c1 + g.c2 + g.c3});
                }
                return;
            }
            case PathKind::complex:
                for_each_part(static_cast<const ComplexNode&>(node), [this](const Path& part, double, double) { path(part); });
                return;
            case PathKind::reparametrized: path(static_cast<const ReparametrizedNode&>(node).source()); return;
            case PathKind::spiral: slice_fail("svg_path_data", "a spiral has no SVG form (SVG draws lines, Béziers and arcs)");
            case PathKind::sine_wave: slice_fail("svg_path_data", "a sine wave has no SVG form (SVG draws lines, Béziers and arcs)");
        }
    }
};

}  // namespace

Path slice(const Path& path, double u0, double u1) {
    if (!(u0 >= 0.0 && u0 < u1 && u1 <= 1.0)) {
        slice_fail("slice", "the range must satisfy 0 ≤ u0 < u1 ≤ 1 (got u0 = " + detail::number_text(u0) +
                          ", u1 = " + detail::number_text(u1) + ")");
    }
    return cut(path, u0, u1);
}

Path slice_by_length(const Path& path, double s0, double s1) {
    const double total = path.length();
    if (!(s0 >= 0.0 && s0 < s1 && s1 <= total)) {
        slice_fail("slice_by_length", "the lengths must satisfy 0 ≤ s0 < s1 ≤ length() = " + detail::number_text(total) +
                                    " (got s0 = " + detail::number_text(s0) + ", s1 = " + detail::number_text(s1) + ")");
    }
    const double u0 = path.u_at_length(s0);
    const double u1 = s1 >= total ? 1.0 : path.u_at_length(s1);
    if (!(u1 > u0)) slice_fail("slice_by_length", "the lengths fall where the path stands still (u " + detail::number_text(u0) + ")");
    return cut(path, u0, u1);
}

Vec2 offset_point(const Path& path, double u, double distance) noexcept {
    const PathFrame f = frame(path, u);
    return f.point + f.normal * distance;
}

std::string svg_path_data(const Path& path) {
    SvgWriter w;
    w.path(path);
    return w.out;
}

}  // namespace grape
