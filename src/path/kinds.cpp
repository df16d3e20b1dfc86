// grape — evaluation, exact lengths and bounds of the curve kinds in kinds.hpp: arcs, spirals,
// sine waves, quadratics. Splines are in kinds_splines.cpp, complex paths in kinds_complex.cpp.
#include "kinds.hpp"

#include "geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grape::detail {

namespace {

// Pieces of at most a quarter turn: quadrature and bound sampling then see smooth,
// non-oscillating pieces however many turns the path makes.
void quarter_turn_breaks(double span, std::vector<double>& out) {
    const double quarters = std::ceil(std::abs(span) / (0.5 * pi));
    const int n = static_cast<int>(std::clamp(quarters, 1.0, 4096.0));
    for (int k = 1; k < n; ++k) out.push_back(static_cast<double>(k) / n);
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
      omega_(2.0 * pi * frequency),
      half_(frequency != 0.0 ? 0.5 / std::abs(frequency) : HUGE_VAL),
      half_length_(half_ < 1.0 ? from_crest(half_) : 0.0) {}

// The speed √(|Δ|² + (A·ω·cos ωu)²) repeats every half wave, so the length of k half waves
// is k times one's: the length costs the same at any frequency (integrating every wave took
// minutes at 10⁶ waves). ∫ of the speed over [0, r], r within one half wave from a crest,
// split at the quarter where cos ωu = 0 (a kink of the speed when Δ = 0). The target is
// relative to the piece, so k pieces stay within it of the whole.
double SineWaveNode::from_crest(double r) const noexcept {
    auto speed = [this](double u) noexcept { return grape::length(d1(u)); };
    const double quarter = 0.5 * half_;
    const double first = std::min(r, quarter);
    const double tolerance = 1e-15 * std::max(gauss_legendre(speed, 0.0, first), std::numeric_limits<double>::min());
    double sum = integrate(speed, 0.0, first, tolerance, 40);
    if (r > quarter) sum += integrate(speed, quarter, r, tolerance, 40);
    return sum;
}

double SineWaveNode::length_at(double u) const noexcept {
    if (!(u > 0.0)) return 0.0;
    u = std::min(u, 1.0);
    if (!(half_ < 1.0)) return from_crest(u);  // less than a half wave in all
    const double k = std::floor(u / half_);
    const double r = std::clamp(u - k * half_, 0.0, half_);
    return k * half_length_ + from_crest(r);
}

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

}  // namespace grape::detail
