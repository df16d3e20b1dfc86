// grape — evaluation and bounds of the spline kinds in kinds.hpp: polylines (linear and
// cosine) and piecewise cubics (Hermite, Catmull–Rom).
#include "kinds.hpp"

#include "geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grape::detail {

namespace {

// Segment and local t of u on `segments` equal spans; a u within rounding of a join belongs
// to the segment that starts there.
std::size_t spline_segment(double u, std::size_t segments, double& t) noexcept {
    double x = u * static_cast<double>(segments);
    const double r = std::round(x);
    if (std::abs(x - r) <= 8.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, r)) x = r;
    return segment_of(x, segments, t);
}

}  // namespace

// --- PolylineNode -------------------------------------------------------------------------

PolylineNode::PolylineNode(PathKind kind, std::vector<Vec2> pts)
    : PathNode(kind), points(std::move(pts)), cosine_(kind == PathKind::cosine_spline) {
    cumulative_.assign(points.size(), 0.0);
    for (std::size_t i = 1; i < points.size(); ++i) {
        cumulative_[i] = cumulative_[i - 1] + distance(points[i - 1], points[i]);
    }
}

Vec2 PolylineNode::point(double u) const noexcept {
    double t;
    const std::size_t i = spline_segment(u, points.size() - 1, t);
    const double mu = cosine_ ? 0.5 * (1.0 - std::cos(pi * t)) : t;
    return lerp(points[i], points[i + 1], mu);
}

Vec2 PolylineNode::d1(double u) const noexcept {
    double t;
    const std::size_t n = points.size() - 1;
    const std::size_t i = spline_segment(u, n, t);
    const double rate = static_cast<double>(n) * (cosine_ ? 0.5 * pi * std::sin(pi * t) : 1.0);
    return (points[i + 1] - points[i]) * rate;
}

Vec2 PolylineNode::d2(double u) const noexcept {
    if (!cosine_) return {};
    double t;
    const std::size_t n = points.size() - 1;
    const std::size_t i = spline_segment(u, n, t);
    const double nn = static_cast<double>(n);
    return (points[i + 1] - points[i]) * (nn * nn * 0.5 * pi * pi * std::cos(pi * t));
}

double PolylineNode::length_at(double u) const noexcept {
    double t;
    const std::size_t i = spline_segment(std::clamp(u, 0.0, 1.0), points.size() - 1, t);
    const double mu = cosine_ ? 0.5 * (1.0 - std::cos(pi * t)) : t;
    return cumulative_[i] + (cumulative_[i + 1] - cumulative_[i]) * mu;
}

Bounds PolylineNode::compute_bounds() const {
    Bounds box;
    for (const Vec2 p : points) box.add(p);
    return box;
}

void PolylineNode::interior_breaks(std::vector<double>& out) const { even_breaks(points.size() - 1, out); }

void PolylineNode::append_flattened(double, std::vector<Vec2>& out) const {
    for (std::size_t i = 1; i < points.size(); ++i) {
        if (out.empty() || out.back() != points[i]) out.push_back(points[i]);
    }
}

// --- CubicSplineNode ----------------------------------------------------------------------

namespace {

CubicSplineNode::Segment hermite(Vec2 p0, Vec2 p1, Vec2 m0, Vec2 m1) noexcept {
    return {p0, m0, 3.0 * (p1 - p0) - 2.0 * m0 - m1, 2.0 * (p0 - p1) + m0 + m1};
}

}  // namespace

CubicSplineNode::CubicSplineNode(PathKind kind, std::vector<Vec2> pts, std::vector<Vec2> tans, CatmullRom type)
    : PathNode(kind), points(std::move(pts)), tangents(std::move(tans)), type(type) {
    const std::size_t n = points.size();
    segments.reserve(n - 1);
    if (kind == PathKind::hermite_spline) {
        for (std::size_t i = 0; i + 1 < n; ++i) segments.push_back(hermite(points[i], points[i + 1], tangents[i], tangents[i + 1]));
        return;
    }
    const double alpha = type == CatmullRom::uniform ? 0.0 : type == CatmullRom::centripetal ? 0.5 : 1.0;
    // Knot spacing |Δp|^α; coincident points would give 0, so they fall back to 1 (uniform).
    auto spacing = [alpha](Vec2 a, Vec2 b) {
        const double d = alpha == 0.0 ? 1.0 : std::pow(distance(a, b), alpha);
        return d > 0.0 ? d : 1.0;
    };
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const Vec2 p1 = points[i], p2 = points[i + 1];
        // Phantom points mirror the neighbour at the ends.
        const Vec2 p0 = i > 0 ? points[i - 1] : 2.0 * p1 - p2;
        const Vec2 p3 = i + 2 < n ? points[i + 2] : 2.0 * p2 - p1;
        const double d01 = spacing(p0, p1), d12 = spacing(p1, p2), d23 = spacing(p2, p3);
        // Barry–Goldman tangents in knot units, scaled to the segment's local t by d12.
        const Vec2 m1 = (p1 - p0) / d01 - (p2 - p0) / (d01 + d12) + (p2 - p1) / d12;
        const Vec2 m2 = (p2 - p1) / d12 - (p3 - p1) / (d12 + d23) + (p3 - p2) / d23;
        segments.push_back(hermite(p1, p2, m1 * d12, m2 * d12));
    }
}

Vec2 CubicSplineNode::point(double u) const noexcept {
    double t;
    const Segment& s = segments[spline_segment(u, segments.size(), t)];
    return ((s.c3 * t + s.c2) * t + s.c1) * t + s.c0;
}

Vec2 CubicSplineNode::d1(double u) const noexcept {
    double t;
    const Segment& s = segments[spline_segment(u, segments.size(), t)];
    return ((3.0 * s.c3 * t + 2.0 * s.c2) * t + s.c1) * static_cast<double>(segments.size());
}

Vec2 CubicSplineNode::d2(double u) const noexcept {
    double t;
    const Segment& s = segments[spline_segment(u, segments.size(), t)];
    const double n = static_cast<double>(segments.size());
    return (6.0 * s.c3 * t + 2.0 * s.c2) * (n * n);
}

Bounds CubicSplineNode::compute_bounds() const {
    Bounds box;
    for (const Vec2 p : points) box.add(p);
    double roots[2];
    for (const Segment& s : segments) {
        for (int axis = 0; axis < 2; ++axis) {
            const auto get = [axis](Vec2 v) { return axis == 0 ? v.x : v.y; };
            const int count = quadratic_roots(3.0 * get(s.c3), 2.0 * get(s.c2), get(s.c1), roots);
            for (int i = 0; i < count; ++i) {
                const double t = roots[i];
                if (t > 0.0 && t < 1.0) box.add(((s.c3 * t + s.c2) * t + s.c1) * t + s.c0);
            }
        }
    }
    return box;
}

void CubicSplineNode::interior_breaks(std::vector<double>& out) const {
    // Segment joins, and cusps inside segments (x′ = y′ = 0, a kink in the speed) so that
    // quadrature and the arc-length table meet them at a break.
    const double n = static_cast<double>(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Segment& s = segments[i];
        if (i > 0) out.push_back(static_cast<double>(i) / n);
        const double scale = grape::length(s.c1) + grape::length(s.c2) + grape::length(s.c3);
        double cusps[4];
        int count = 0;
        for (int axis = 0; axis < 2; ++axis) {
            const auto get = [axis](Vec2 v) { return axis == 0 ? v.x : v.y; };
            double roots[2];
            const int m = quadratic_roots(3.0 * get(s.c3), 2.0 * get(s.c2), get(s.c1), roots);
            for (int k = 0; k < m; ++k) {
                const double t = roots[k];
                const Vec2 d = (3.0 * s.c3 * t + 2.0 * s.c2) * t + s.c1;
                if (t > 1e-9 && t < 1.0 - 1e-9 && grape::length(d) <= 1e-9 * scale) cusps[count++] = t;
            }
        }
        for (int a = 1; a < count; ++a) {
            for (int b = a; b > 0 && cusps[b] < cusps[b - 1]; --b) std::swap(cusps[b], cusps[b - 1]);
        }
        for (int k = 0; k < count; ++k) {
            const double u = (static_cast<double>(i) + cusps[k]) / n;
            if (u > out.back() + 1e-12) out.push_back(u);
        }
    }
}

// Derivative bounds: suprema over [a, b] of |x″| and |x‴| by the triangle inequality on the
// closed forms above.

PathNode::DerivativeBounds PolylineNode::derivative_bounds(double a, double b) const noexcept {
    if (!cosine_) return {0.0, 0.0};
    double t;
    const std::size_t n = points.size() - 1;
    const std::size_t i = spline_segment(0.5 * (a + b), n, t);
    const double nn = static_cast<double>(n);
    const double chord = distance(points[i], points[i + 1]);
    return {chord * nn * nn * 0.5 * pi * pi, chord * nn * nn * nn * 0.5 * pi * pi * pi};
}

PathNode::DerivativeBounds CubicSplineNode::derivative_bounds(double a, double b) const noexcept {
    // Per segment x″ = (6·c3·t + 2·c2)·n² is affine in t (largest at an end), x‴ = 6·c3·n³.
    double t;
    const std::size_t i = spline_segment(0.5 * (a + b), segments.size(), t);
    const Segment& s = segments[i];
    const double n = static_cast<double>(segments.size());
    const double base = static_cast<double>(i);
    const double ta = std::clamp(a * n - base, 0.0, 1.0), tb = std::clamp(b * n - base, 0.0, 1.0);
    const double d2 = std::max(grape::length(6.0 * s.c3 * ta + 2.0 * s.c2), grape::length(6.0 * s.c3 * tb + 2.0 * s.c2));
    return {d2 * n * n, 6.0 * grape::length(s.c3) * n * n * n};
}

}  // namespace grape::detail
