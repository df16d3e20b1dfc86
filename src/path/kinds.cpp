// grape — evaluation, exact lengths and bounds of the path kinds in kinds.hpp.
#include "kinds.hpp"

#include "geometry.hpp"

#include <algorithm>
#include <cmath>

namespace grape::detail {

namespace {

// Pieces of at most a quarter turn: quadrature and bound sampling then see smooth,
// non-oscillating pieces however many turns the path makes.
void quarter_turn_breaks(double span, std::vector<double>& out) {
    const double quarters = std::ceil(std::abs(span) / (0.5 * pi));
    const int n = static_cast<int>(std::clamp(quarters, 1.0, 4096.0));
    for (int k = 1; k < n; ++k) out.push_back(static_cast<double>(k) / n);
}

void even_breaks(std::size_t segments, std::vector<double>& out) {
    for (std::size_t k = 1; k < segments; ++k) out.push_back(static_cast<double>(k) / static_cast<double>(segments));
}

// Segment and local t of u on `segments` equal spans; a u within rounding of a join belongs
// to the segment that starts there.
std::size_t spline_segment(double u, std::size_t segments, double& t) noexcept {
    double x = u * static_cast<double>(segments);
    const double r = std::round(x);
    if (std::abs(x - r) <= 8.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, r)) x = r;
    return segment_of(x, segments, t);
}

}  // namespace

// --- ArcNode ------------------------------------------------------------------------------

ArcNode::ArcNode(PathKind kind, Vec2 center, double rx, double ry, double rotation, double a0, double a1) noexcept
    : PathNode(kind),
      center(center),
      rx(rx),
      ry(ry),
      rotation(rotation),
      a0(a0),
      a1(a1),
      ex_(Vec2{std::cos(rotation), std::sin(rotation)} * rx),
      ey_(Vec2{-std::sin(rotation), std::cos(rotation)} * ry),
      span_(a1 - a0) {
    if (rotation == 0.0) {  // keep circles exact: cos 0 = 1, sin 0 = 0
        ex_ = {rx, 0.0};
        ey_ = {0.0, ry};
    }
}

Vec2 ArcNode::at_angle(double theta) const noexcept {
    return center + ex_ * std::cos(theta) + ey_ * std::sin(theta);
}

Vec2 ArcNode::point(double u) const noexcept { return at_angle(a0 + span_ * u); }

Vec2 ArcNode::d1(double u) const noexcept {
    const double theta = a0 + span_ * u;
    return (ey_ * std::cos(theta) - ex_ * std::sin(theta)) * span_;
}

Vec2 ArcNode::d2(double u) const noexcept {
    const double theta = a0 + span_ * u;
    return (ex_ * std::cos(theta) + ey_ * std::sin(theta)) * (-span_ * span_);
}

double ArcNode::length_at(double u) const noexcept {
    if (rx != ry) return PathNode::length_at(u);
    return rx * std::abs(span_) * std::clamp(u, 0.0, 1.0);
}

void ArcNode::interior_breaks(std::vector<double>& out) const { quarter_turn_breaks(span_, out); }

Bounds ArcNode::compute_bounds() const {
    Bounds box;
    box.add(point(0.0));
    box.add(point(1.0));
    const double lo = std::min(a0, a1);
    const double hi = std::max(a0, a1);
    // x(θ) = cx + ex.x·cos θ + ey.x·sin θ is extreme where tan θ = ey.x / ex.x (and y alike).
    for (const double base : {std::atan2(ey_.x, ex_.x), std::atan2(ey_.y, ex_.y)}) {
        const double k0 = std::ceil((lo - base) / pi);
        const double k1 = std::min(std::floor((hi - base) / pi), k0 + 1.0);
        for (double k = k0; k <= k1; k += 1.0) box.add(at_angle(base + k * pi));
    }
    return box;
}

void ArcNode::append_flattened(double tolerance, std::vector<Vec2>& out) const {
    if (rx != ry) {
        PathNode::append_flattened(tolerance, out);
        return;
    }
    // A chord over Δθ sags r·(1 − cos(Δθ/2)): the largest Δθ within tolerance, evenly.
    const double step = 2.0 * std::acos(std::max(-1.0, 1.0 - tolerance / rx));
    const double n = std::clamp(std::ceil(std::abs(span_) / step), 1.0, 1e7);
    const int count = static_cast<int>(n);
    for (int k = 1; k <= count; ++k) out.push_back(k == count ? point(1.0) : point(static_cast<double>(k) / n));
}

// --- SpiralNode ---------------------------------------------------------------------------

SpiralNode::SpiralNode(Vec2 center, double r0, double r1, double a0, double a1) noexcept
    : PathNode(PathKind::spiral), center(center), r0(r0), r1(r1), a0(a0), a1(a1) {
    // (F(r1) − F(r0))/ρ loses about log10(r/ρ) digits: near-constant radii use quadrature.
    const double rho = r1 - r0;
    closed_ = a1 == a0 || rho == 0.0 || std::abs(rho) >= 0.01 * std::max(r0, r1);
}

Vec2 SpiralNode::point(double u) const noexcept {
    const double r = r0 + (r1 - r0) * u;
    const double theta = a0 + (a1 - a0) * u;
    return center + Vec2{std::cos(theta), std::sin(theta)} * r;
}

Vec2 SpiralNode::d1(double u) const noexcept {
    const double rho = r1 - r0, span = a1 - a0;
    const double r = r0 + rho * u;
    const double theta = a0 + span * u;
    const Vec2 radial{std::cos(theta), std::sin(theta)};
    return radial * rho + perpendicular(radial) * (r * span);
}

Vec2 SpiralNode::d2(double u) const noexcept {
    const double rho = r1 - r0, span = a1 - a0;
    const double r = r0 + rho * u;
    const double theta = a0 + span * u;
    const Vec2 radial{std::cos(theta), std::sin(theta)};
    return perpendicular(radial) * (2.0 * rho * span) - radial * (r * span * span);
}

double SpiralNode::length_at(double u) const noexcept {
    if (!closed_) return PathNode::length_at(u);
    u = std::clamp(u, 0.0, 1.0);
    const double rho = r1 - r0;
    const double k = std::abs(a1 - a0);
    if (k == 0.0) return std::abs(rho) * u;
    if (rho == 0.0) return r0 * k * u;
    // speed = √(ρ² + k²r²) with dr = ρ du: L = [H(k·r(u)) − H(k·r0)] / (k·ρ), H = ∫√(τ² + ρ²) dτ.
    const double r = r0 + rho * u;
    return (hyperbolic_length(k * r, std::abs(rho)) - hyperbolic_length(k * r0, std::abs(rho))) / (k * rho);
}

void SpiralNode::interior_breaks(std::vector<double>& out) const { quarter_turn_breaks(a1 - a0, out); }

// --- SineWaveNode -------------------------------------------------------------------------

SineWaveNode::SineWaveNode(Vec2 a, Vec2 b, double frequency, double amplitude) noexcept
    : PathNode(PathKind::sine_wave),
      a(a),
      b(b),
      frequency(frequency),
      amplitude(amplitude),
      delta_(b - a),
      normal_(perpendicular(normalized(b - a))),
      omega_(2.0 * pi * frequency) {}

Vec2 SineWaveNode::point(double u) const noexcept {
    return a + delta_ * u + normal_ * (amplitude * std::sin(omega_ * u));
}

Vec2 SineWaveNode::d1(double u) const noexcept {
    return delta_ + normal_ * (amplitude * omega_ * std::cos(omega_ * u));
}

Vec2 SineWaveNode::d2(double u) const noexcept {
    return normal_ * (-amplitude * omega_ * omega_ * std::sin(omega_ * u));
}

void SineWaveNode::interior_breaks(std::vector<double>& out) const {
    // One piece per half wave.
    const double halves = std::clamp(std::ceil(2.0 * std::abs(frequency)), 1.0, 65536.0);
    even_breaks(static_cast<std::size_t>(halves), out);
}

// --- QuadraticNode ------------------------------------------------------------------------

QuadraticNode::QuadraticNode(PathKind kind, Vec2 c0, Vec2 c1, Vec2 c2, std::array<Vec2, 3> inputs,
                             double seconds) noexcept
    : PathNode(kind), c{c0, c1, c2}, inputs(inputs), seconds(seconds) {
    // speed = |c1 + b·u| with b = 2·c2 = |b|·√((u − t0)² + k²).
    const Vec2 b = 2.0 * c2;
    const double b2 = length_squared(b);
    scale_ = std::sqrt(b2);
    t0_ = b2 > 0.0 ? -dot(c1, b) / b2 : 0.0;
    k_ = b2 > 0.0 ? std::abs(cross(c1, b)) / b2 : 0.0;
    // H(1 − t0) − H(−t0) loses about log10|t0| digits: nearly straight arcs use quadrature.
    closed_ = b2 == 0.0 || std::abs(t0_) <= 64.0;
}

double QuadraticNode::length_at(double u) const noexcept {
    if (!closed_) return PathNode::length_at(u);
    u = std::clamp(u, 0.0, 1.0);
    if (scale_ == 0.0) return grape::length(c[1]) * u;
    return scale_ * (hyperbolic_length(u - t0_, k_) - hyperbolic_length(-t0_, k_));
}

Bounds QuadraticNode::compute_bounds() const {
    Bounds box;
    box.add(point(0.0));
    box.add(point(1.0));
    if (c[2].x != 0.0) {
        const double u = -c[1].x / (2.0 * c[2].x);
        if (u > 0.0 && u < 1.0) box.add(point(u));
    }
    if (c[2].y != 0.0) {
        const double u = -c[1].y / (2.0 * c[2].y);
        if (u > 0.0 && u < 1.0) box.add(point(u));
    }
    return box;
}

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

// --- ComplexNode --------------------------------------------------------------------------

ComplexNode::ComplexNode(std::vector<Path> parts_in, std::vector<double> cues_in)
    : PathNode(PathKind::complex), parts(std::move(parts_in)), cues(std::move(cues_in)) {
    double s = 0.0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const double start = cues[i];
        const double end = i + 1 < parts.size() ? cues[i + 1] : 1.0;
        // An empty span is skipped; so is one too thin for 1/width (adjacent doubles).
        if (!(end > start) || !std::isfinite(1.0 / (end - start))) continue;
        const PathNode* node = &NodeAccess::node(parts[i]);
        pieces_.push_back(Piece{node, start, end - start, 1.0 / (end - start), s});
        starts_.push_back(start);
        s += node->length();
    }
}

const ComplexNode::Piece& ComplexNode::piece_at(double u) const noexcept {
    const auto it = std::upper_bound(starts_.begin(), starts_.end(), u);
    const std::size_t i = it == starts_.begin() ? 0 : static_cast<std::size_t>(it - starts_.begin()) - 1;
    return pieces_[i];
}

namespace {

// The part's own parameter; exactly 1 at the whole's end, whatever (1 − start)/width rounds to.
double local(double u, double start, double inv_width) noexcept {
    return u >= 1.0 ? 1.0 : std::clamp((u - start) * inv_width, 0.0, 1.0);
}

}  // namespace

Vec2 ComplexNode::point(double u) const noexcept {
    const Piece& p = piece_at(u);
    return p.node->point(local(u, p.start, p.inv_width));
}

Vec2 ComplexNode::d1(double u) const noexcept {
    const Piece& p = piece_at(u);  // chain rule: d/du = d/dv · dv/du, dv/du = 1/width
    return p.node->d1(local(u, p.start, p.inv_width)) * p.inv_width;
}

Vec2 ComplexNode::d2(double u) const noexcept {
    const Piece& p = piece_at(u);
    // Scaled in two steps: inv_width² alone overflows for spans under ~1e-154.
    return (p.node->d2(local(u, p.start, p.inv_width)) * p.inv_width) * p.inv_width;
}

double ComplexNode::length_at(double u) const noexcept {
    if (!(u > 0.0)) return 0.0;
    if (u >= 1.0) return pieces_.back().s0 + pieces_.back().node->length();
    const Piece& p = piece_at(u);
    return p.s0 + p.node->length_at(local(u, p.start, p.inv_width));
}

Bounds ComplexNode::compute_bounds() const {
    Bounds box;
    for (const Piece& p : pieces_) box.add(p.node->bounds());
    return box;
}

void ComplexNode::interior_breaks(std::vector<double>& out) const {
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
        const Piece& p = pieces_[i];
        if (i > 0 && p.start > out.back()) out.push_back(p.start);
        const auto& inner = p.node->breaks();
        for (std::size_t k = 1; k + 1 < inner.size(); ++k) {
            const double u = p.start + inner[k] * p.width;
            if (u > out.back() && u < p.start + p.width && u < 1.0) out.push_back(u);
        }
    }
}

void ComplexNode::append_flattened(double tolerance, std::vector<Vec2>& out) const {
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
        const Vec2 start = pieces_[i].node->point(0.0);
        if (i > 0 && (out.empty() || out.back() != start)) out.push_back(start);
        pieces_[i].node->append_flattened(tolerance, out);
    }
}

// --- derivative bounds (for the path queries) ----------------------------------------------
// Each is a supremum over [a, b] of the analytic |x″| and |x‴|, by the triangle inequality on
// the closed forms above (the rotated axes ex, ey are orthogonal, so |ex·cos θ + ey·sin θ| ≤
// max(rx, ry)).

PathNode::DerivativeBounds ArcNode::derivative_bounds(double, double) const noexcept {
    const double r = std::max(rx, ry);
    const double s = std::abs(span_);
    return {r * s * s, r * s * s * s};
}

PathNode::DerivativeBounds SpiralNode::derivative_bounds(double a, double b) const noexcept {
    // x″ = 2ρs·e⊥ − r·s²·e and x‴ = −3ρs²·e − r·s³·e⊥ with r linear (largest at an end).
    const double rho = std::abs(r1 - r0), s = std::abs(a1 - a0);
    const double r = std::max(std::abs(r0 + (r1 - r0) * a), std::abs(r0 + (r1 - r0) * b));
    return {2.0 * rho * s + r * s * s, 3.0 * rho * s * s + r * s * s * s};
}

PathNode::DerivativeBounds SineWaveNode::derivative_bounds(double, double) const noexcept {
    const double w = std::abs(omega_), amp = std::abs(amplitude);
    return {amp * w * w, amp * w * w * w};
}

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
