// grape — what every node shares: caches, quadrature, bounds, flattening; and the nodes
// declared in path_node.hpp (linear, cubic Bézier, arc-length reparametrization).
#include "path_node.hpp"

#include "geometry.hpp"

#include <grape/error.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace grape::detail {


void PathNode::interior_breaks(std::vector<double>&) const {}

PathNode::DerivativeBounds PathNode::derivative_bounds(double, double) const noexcept {
    const double unknown = std::numeric_limits<double>::infinity();
    return {unknown, unknown};
}

void PathNode::finish() {
    breaks_.clear();
    breaks_.push_back(0.0);
    interior_breaks(breaks_);
    breaks_.push_back(1.0);

    // The quadrature target is relative to the whole length, estimated by one rule per piece.
    double estimate = 0.0;
    auto speed = [this](double u) noexcept { return grape::length(d1(u)); };
    for (std::size_t i = 0; i + 1 < breaks_.size(); ++i) {
        estimate += gauss_legendre(speed, breaks_[i], breaks_[i + 1]);
    }
    quad_tolerance_ = std::max(1e-14 * estimate, std::numeric_limits<double>::min());

    if (closed_form_length()) {
        length_ = length_at(1.0);
    } else {
        cumulative_.assign(breaks_.size(), 0.0);
        for (std::size_t i = 0; i + 1 < breaks_.size(); ++i) {
            cumulative_[i + 1] = cumulative_[i] + integrate_speed(breaks_[i], breaks_[i + 1]);
        }
        length_ = cumulative_.back();
    }
    if (!std::isfinite(length_)) {
        // Finite inputs whose differences or products overflow (coordinates near 1e308).
        throw Error("Path (" + std::string(to_string(kind_)) +
                    "): the length overflows a double; coordinates or parameters are too large");
    }
    bounds_ = compute_bounds();
}

double PathNode::integrate_speed(double a, double b) const noexcept {
    auto speed = [this](double u) noexcept { return grape::length(d1(u)); };
    // Rounding noise of each rule is about 1e-16 of its value, far below the target, so the
    // adaptive scheme stops by agreement, not by depth, on smooth pieces.
    return integrate(speed, a, b, quad_tolerance_, 40);
}

double PathNode::length_at(double u) const noexcept {
    if (!(u > 0.0)) return 0.0;
    if (u >= 1.0) return length_;
    const auto it = std::upper_bound(breaks_.begin(), breaks_.end(), u);
    const auto i = static_cast<std::size_t>(it - breaks_.begin()) - 1;
    return cumulative_[i] + integrate_speed(breaks_[i], u);
}

Bounds PathNode::compute_bounds() const {
    Bounds box;
    const int n = std::max(2, samples_per_piece());
    for (std::size_t piece = 0; piece + 1 < breaks_.size(); ++piece) {
        const double a = breaks_[piece];
        const double b = breaks_[piece + 1];
        box.add(point(a));
        box.add(point(b));
        Vec2 prev = d1(a);
        double prev_u = a;
        for (int k = 1; k <= n; ++k) {
            const double u = k == n ? inside_right(a, b) : a + (b - a) * k / n;
            const Vec2 d = d1(u);
            box.add(point(u));
            // A sign change of a coordinate's derivative brackets an extreme of it.
            for (int axis = 0; axis < 2; ++axis) {
                const double f0 = axis == 0 ? prev.x : prev.y;
                const double f1 = axis == 0 ? d.x : d.y;
                if ((f0 < 0.0 && f1 > 0.0) || (f0 > 0.0 && f1 < 0.0)) {
                    auto fd = [this, axis](double v) noexcept {
                        const Vec2 g = d1(v);
                        const Vec2 h = d2(v);
                        return std::pair<double, double>{axis == 0 ? g.x : g.y, axis == 0 ? h.x : h.y};
                    };
                    const Root r = find_root(fd, prev_u, u, 0.5 * (prev_u + u), 1e-15);
                    box.add(point(r.x));
                }
            }
            prev = d;
            prev_u = u;
        }
    }
    return box;
}

namespace {

// Distance from p to the chord a–b (flattening tolerances are far inside the range where |ab|²
// overflows, so the plain form serves here; closest.cpp has the overflow-safe one).
double chord_distance(Vec2 p, Vec2 a, Vec2 b) noexcept {
    const Vec2 ab = b - a;
    const double l2 = length_squared(ab);
    const double t = l2 > 0.0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return distance(p, a + ab * t);
}

struct Flattener {
    const PathNode& node;
    double tolerance;
    std::vector<Vec2>& out;

    // Accepts the chord pa–pb over [a, b] when both the measured distance of seven interior
    // samples and the second-derivative bound h²/8·max|x″ × chord| are within tolerance;
    // the bound covers the deviation between samples, the samples cover backtracking.
    void range(double a, double b, Vec2 pa, Vec2 pb, int depth) {
        const double h = b - a;
        const Vec2 chord = pb - pa;
        const double chord_length = grape::length(chord);
        double deviation = 0.0;
        double bend = 0.0;
        for (int k = 0; k <= 8; ++k) {
            const double u = k == 8 ? inside_right(a, b) : a + h * k / 8.0;
            if (k > 0 && k < 8) deviation = std::max(deviation, chord_distance(node.point(u), pa, pb));
            const Vec2 dd = node.d2(u);
            bend = std::max(bend, chord_length > 0.0 ? std::abs(cross(dd, chord)) / chord_length
                                                     : grape::length(dd));
        }
        const bool flat = deviation <= tolerance && bend * h * h / 8.0 <= tolerance;
        if (flat || depth >= 40 || !(deviation < std::numeric_limits<double>::infinity())) {
            out.push_back(pb);
            return;
        }
        const double m = 0.5 * (a + b);
        const Vec2 pm = node.point(m);
        range(a, m, pa, pm, depth + 1);
        range(m, b, pm, pb, depth + 1);
    }
};

}  // namespace

void PathNode::append_flattened(double tolerance, std::vector<Vec2>& out) const {
    Flattener f{*this, tolerance, out};
    const int initial = std::max(1, samples_per_piece() / 4);
    for (std::size_t piece = 0; piece + 1 < breaks_.size(); ++piece) {
        const double a = breaks_[piece];
        const double b = breaks_[piece + 1];
        double prev_u = a;
        Vec2 prev = point(a);
        for (int k = 1; k <= initial; ++k) {
            const double u = k == initial ? b : a + (b - a) * k / initial;
            // At a break the right end belongs to this piece: evaluate from inside.
            const Vec2 p = k == initial ? point(inside_right(a, b)) : point(u);
            f.range(prev_u, u, prev, p, 0);
            prev_u = u;
            prev = p;
        }
    }
}

// --- LinearNode ---------------------------------------------------------------------------

void LinearNode::append_flattened(double, std::vector<Vec2>& out) const { out.push_back(b); }

Bounds LinearNode::compute_bounds() const {
    Bounds box;
    box.add(a);
    box.add(b);
    return box;
}

// --- CubicBezierNode ----------------------------------------------------------------------

Bounds CubicBezierNode::compute_bounds() const {
    Bounds box;
    box.add(p[0]);
    box.add(p[3]);
    // d/dt = c1 + 2·c2·t + 3·c3·t²: its roots in (0, 1) are the extremes.
    double roots[2];
    for (int axis = 0; axis < 2; ++axis) {
        const auto get = [axis](Vec2 v) { return axis == 0 ? v.x : v.y; };
        const int n = quadratic_roots(3.0 * get(c[3]), 2.0 * get(c[2]), get(c[1]), roots);
        for (int i = 0; i < n; ++i) {
            if (roots[i] > 0.0 && roots[i] < 1.0) box.add(point(roots[i]));
        }
    }
    return box;
}

void CubicBezierNode::interior_breaks(std::vector<double>& out) const {
    // Pieces between the extremes of x and y: a cusp (x′ = y′ = 0, a kink in the speed)
    // then sits on a break, where quadrature and the arc-length table handle it exactly.
    double roots[4];
    int count = 0;
    for (int axis = 0; axis < 2; ++axis) {
        const auto get = [axis](Vec2 v) { return axis == 0 ? v.x : v.y; };
        double r[2];
        const int n = quadratic_roots(3.0 * get(c[3]), 2.0 * get(c[2]), get(c[1]), r);
        for (int i = 0; i < n; ++i) {
            if (r[i] > 1e-9 && r[i] < 1.0 - 1e-9) roots[count++] = r[i];
        }
    }
    for (int i = 1; i < count; ++i) {  // at most four: insertion sort
        for (int j = i; j > 0 && roots[j] < roots[j - 1]; --j) std::swap(roots[j], roots[j - 1]);
    }
    for (int i = 0; i < count; ++i) {
        if (roots[i] > out.back() + 1e-9) out.push_back(roots[i]);
    }
}

// --- ReparametrizedNode -------------------------------------------------------------------

ReparametrizedNode::ReparametrizedNode(Path source)
    : PathNode(PathKind::reparametrized), source_(std::move(source)), source_node_(&NodeAccess::node(source_)) {
    build();
}

void ReparametrizedNode::build() {
    // The table is built in arc-length units scaled by a power of two (exact) that puts the
    // length in [1, 2), so a path of length 1e-320 has a table as fine as one of length 1.
    const double unscaled = source_node_->length();
    exponent_ = unscaled > 0.0 ? -std::ilogb(unscaled) : 0;
    scaled_length_ = std::ldexp(unscaled, exponent_);
    // A denormal path's derivatives carry absolute rounding of a few denormal ulps, which the
    // scaling makes relative: no table can be more accurate than that, and asking for more
    // would split spans up to the budget (minutes for a cubic of length 3e-320).
    noise_ = 16.0 * std::ldexp(std::numeric_limits<double>::denorm_min(), exponent_);
    const double total = scaled_length_;
    const auto& br = source_node_->breaks();
    // The span budget grows with the smooth pieces, so that a long path gets the spans its
    // error needs (about six per piece) whatever its length, while a path whose arc length
    // the model cannot follow (rounding noise above 1e-10·L) still builds in bounded time and
    // memory, linear in its pieces: 2^16 spans plus 256 per piece.
    max_spans_ = (std::size_t{1} << 16) + 256 * (br.size() > 1 ? br.size() - 1 : 0);
    if (total > 0.0) {
        double s = 0.0;
        for (std::size_t piece = 0; piece + 1 < br.size(); ++piece) {
            // Four spans per piece to start, so the quarter-point checks see the piece's shape.
            constexpr int initial = 4;
            for (int k = 0; k < initial; ++k) {
                const double va = br[piece] + (br[piece + 1] - br[piece]) * k / initial;
                const double vb = k + 1 == initial ? br[piece + 1]
                                                   : br[piece] + (br[piece + 1] - br[piece]) * (k + 1) / initial;
                if (vb > va) s = build_span_checked(va, vb, s, 0, total);
            }
        }
    }
    if (spans_.empty()) {
        Span still{};
        still.dv = 1.0;
        still.newton = true;
        spans_.push_back(still);
    }

    // Buckets over s give the first span to look at without a binary search.
    const std::size_t count = 4 * spans_.size();
    buckets_.resize(count);
    bucket_scale_ = total > 0.0 ? static_cast<double>(count) / scaled_length_ : 0.0;
    std::size_t i = 0;
    for (std::size_t b = 0; b < count; ++b) {
        const double s = total > 0.0 ? static_cast<double>(b) / bucket_scale_ : 0.0;
        while (i + 1 < spans_.size() && spans_[i + 1].s0 <= s) ++i;
        buckets_[b] = static_cast<std::uint32_t>(i);
    }
}

double ReparametrizedNode::build_span_checked(double va, double vb, double sa, int depth, double total) {
    const PathNode& src = *source_node_;
    const int e = exponent_;
    // Derivatives scaled before any product, so that denormal ones keep their digits.
    auto scaled = [e](Vec2 d) noexcept { return Vec2{std::ldexp(d.x, e), std::ldexp(d.y, e)}; };
    auto speed = [&src, &scaled](double v) noexcept { return grape::length(scaled(src.d1(v))); };
    const double h = vb - va;
    // s at the quarter points, by adaptive quadrature (the truth the model is checked against).
    const double quad_tol = std::max(1e-15 * total, noise_);
    // One rule per quarter; when their sum agrees with one rule over the span the quarters
    // are far more accurate still (spans hold no kinks: those are breaks). Otherwise each
    // quarter gets adaptive quadrature.
    double q[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
    double quarter[4];
    double lo_hi[5];
    for (int k = 0; k <= 4; ++k) lo_hi[k] = k == 4 ? vb : va + h * k / 4.0;
    double sum = 0.0;
    for (int k = 0; k < 4; ++k) sum += quarter[k] = gauss_legendre(speed, lo_hi[k], lo_hi[k + 1]);
    if (!(std::abs(sum - gauss_legendre(speed, va, vb)) <= quad_tol)) {
        for (int k = 0; k < 4; ++k) quarter[k] = integrate(speed, lo_hi[k], lo_hi[k + 1], quad_tol, 40);
    }
    for (int k = 1; k <= 4; ++k) q[k] = q[k - 1] + quarter[k - 1];
    // Hermite data of s(t), t in [0, 1]: s′ = h·|x′|, s″ = h²·(x′·x″)/|x′|; where the path
    // stops (|x′| = 0) s″ takes its one-sided limit ±|x″|.
    const double vr = inside_right(va, vb);
    const Vec2 g0 = scaled(src.d1(va)), h0 = scaled(src.d2(va));
    const Vec2 g1 = scaled(src.d1(vr)), h1 = scaled(src.d2(vr));
    const double sp0 = grape::length(g0), sp1 = grape::length(g1);
    const double m0 = h * sp0;
    const double m1 = h * sp1;
    const double a0 = h * h * (sp0 > 0.0 ? dot(g0, h0) / sp0 : grape::length(h0));
    const double a1 = h * h * (sp1 > 0.0 ? dot(g1, h1) / sp1 : -grape::length(h1));
    const double S = q[4];
    Span sp{};
    sp.v0 = va;
    sp.dv = h;
    sp.s0 = sa;
    sp.ds = S;
    sp.inv_ds = S > 0.0 ? 1.0 / S : 0.0;
    sp.k1 = m0;
    sp.k2 = 0.5 * a0;
    sp.k3 = 10.0 * S - 6.0 * m0 - 4.0 * m1 - 1.5 * a0 + 0.5 * a1;
    sp.k4 = -15.0 * S + 8.0 * m0 + 7.0 * m1 + 1.5 * a0 - a1;
    sp.k5 = 6.0 * S - 3.0 * m0 - 3.0 * m1 - 0.5 * a0 + 0.5 * a1;
    auto model = [&sp](double t) { return t * (sp.k1 + t * (sp.k2 + t * (sp.k3 + t * (sp.k4 + t * sp.k5)))); };
    double error = 0.0;
    for (int k = 1; k <= 3; ++k) error = std::max(error, std::abs(model(k / 4.0) - q[k]));
    // 1e-10·L leaves a factor 10 to the promised 1e-9·L for the error between check points.
    const bool good = error <= std::max(1e-10 * total, noise_);
    // The span budget (build()) bounds time and memory for paths whose arc length the model
    // cannot follow to 1e-10·L (coordinates so large that rounding noise exceeds it): past it
    // the remaining spans are kept as they are, with Newton lookups.
    const bool last =
        depth >= 48 || spans_.size() >= max_spans_ || !(0.5 * (va + vb) > va && 0.5 * (va + vb) < vb);
    // A span whose inverse model misses although the path moves at both ends is split too:
    // lookups then cost one polynomial instead of Newton steps.
    if (last || (good && (fit_inverse(sp, total, noise_) || depth >= 24))) {
        if (last) fit_inverse(sp, total, noise_);
        spans_.push_back(sp);
        return sa + S;
    }
    const double vm = 0.5 * (va + vb);
    const double sm = build_span_checked(va, vm, sa, depth + 1, total);
    return build_span_checked(vm, vb, sm, depth + 1, total);
}

bool ReparametrizedNode::fit_inverse(Span& sp, double total, double noise) noexcept {
    // The inverse t(σ) of P(t) = σ·ds: t′ = ds/P′, t″ = −ds²·P″/P′³ at both ends, quintic
    // Hermite between. Where P′ nearly vanishes t(σ) has a square-root shape no polynomial
    // follows: such spans keep Newton on the forward model.
    sp.newton = true;
    const double S = sp.ds;
    const double p1_0 = sp.k1;
    const double p1_1 = sp.k1 + 2.0 * sp.k2 + 3.0 * sp.k3 + 4.0 * sp.k4 + 5.0 * sp.k5;
    const double p2_0 = 2.0 * sp.k2;
    const double p2_1 = 2.0 * sp.k2 + 6.0 * sp.k3 + 12.0 * sp.k4 + 20.0 * sp.k5;
    if (!(S > 0.0) || !(p1_0 > 0.05 * S) || !(p1_1 > 0.05 * S)) return true;  // Newton it is
    const double m0 = S / p1_0, m1 = S / p1_1;
    const double a0 = -S * S * p2_0 / (p1_0 * p1_0 * p1_0);
    const double a1 = -S * S * p2_1 / (p1_1 * p1_1 * p1_1);
    sp.j1 = m0;
    sp.j2 = 0.5 * a0;
    sp.j3 = 10.0 - 6.0 * m0 - 4.0 * m1 - 1.5 * a0 + 0.5 * a1;
    sp.j4 = -15.0 + 8.0 * m0 + 7.0 * m1 + 1.5 * a0 - a1;
    sp.j5 = 6.0 - 3.0 * m0 - 3.0 * m1 - 0.5 * a0 + 0.5 * a1;
    // Checked against the forward model at 15 interior points to 2e-11·L: with the forward
    // model's 1e-10·L well inside 1e-9·L, and tight enough that the inverse's own wiggles
    // (the larger part of the lookup error at 2e-10) leave room for the bulk evaluators'
    // smooth table (kernel.hpp) to land within 2e-10·L of Path::point.
    for (int k = 1; k < 16; ++k) {
        const double g = k / 16.0;
        const double t = g * (sp.j1 + g * (sp.j2 + g * (sp.j3 + g * (sp.j4 + g * sp.j5))));
        if (!(t >= 0.0 && t <= 1.0)) return false;
        const double p = t * (sp.k1 + t * (sp.k2 + t * (sp.k3 + t * (sp.k4 + t * sp.k5))));
        if (!(std::abs(p - g * S) <= std::max(2e-11 * total, noise))) return false;
    }
    sp.newton = false;
    return true;
}

namespace {

// Unit tangent where the source stops (|x′| = 0): the chord across a small neighbourhood.
Vec2 stopped_direction(const PathNode& src, double v) noexcept {
    const double e = 1e-7;
    return normalized(src.point(std::min(v + e, 1.0)) - src.point(std::max(v - e, 0.0)));
}

}  // namespace

Vec2 ReparametrizedNode::d1(double u) const noexcept {
    const double v = source_u(u);
    const Vec2 g = source_node_->d1(v);
    const double speed = grape::length(g);
    const double total = length();
    if (speed > 0.0) return g * (total / speed);
    return stopped_direction(*source_node_, v) * total;
}

Vec2 ReparametrizedNode::d2(double u) const noexcept {
    // x(u) = X(v(u)) with dv/du = L/|X′|, d²v/du² = −L²·(X′·X″)/|X′|⁴.
    const double v = source_u(u);
    const Vec2 g = source_node_->d1(v);
    const double speed2 = length_squared(g);
    if (!(speed2 > 0.0)) return {};
    const Vec2 h = source_node_->d2(v);
    const double total = length();
    const double dv = total / std::sqrt(speed2);
    return h * (dv * dv) - g * (total * total * dot(g, h) / (speed2 * speed2));
}

void ReparametrizedNode::append_flattened(double tolerance, std::vector<Vec2>& out) const {
    source_node_->append_flattened(tolerance, out);  // same shape
}

}  // namespace grape::detail
