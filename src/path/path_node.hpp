// grape — the shape behind a Path (private to the path module; other modules read paths
// through describe() in path.hpp, or through kernel.hpp for bulk evaluation).
//
// A PathNode is immutable once `finish()` has run (make_node does it): it evaluates a
// point and its first two derivatives for u in [0, 1] and caches its length, bounds and the
// u where it may be non-smooth. The Path handle adds the end-tangent extension outside
// [0, 1]. LinearNode, CubicBezierNode and ReparametrizedNode are declared here with their
// fields and inline evaluation; kernel.cpp copies what bulk evaluators need from them.
#pragma once

#include <grape/path.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace grape::detail {

/// The abstract shape: point, d1, d2 on u in [0, 1] (callers clamp), cached length/bounds.
class PathNode {
public:
    virtual ~PathNode() = default;
    PathNode(const PathNode&) = delete;
    PathNode& operator=(const PathNode&) = delete;

    /// Which kind of path this node is (anim switches on it to skip virtual calls).
    PathKind kind() const noexcept { return kind_; }
    /// Position at u in [0, 1].
    virtual Vec2 point(double u) const noexcept = 0;
    /// dx/du at u in [0, 1] (one-sided at breaks: the piece that starts at u).
    virtual Vec2 d1(double u) const noexcept = 0;
    /// d²x/du² at u in [0, 1].
    virtual Vec2 d2(double u) const noexcept = 0;

    /// sup |x″| and sup |x‴| over [a, b] inside one smooth piece (between two breaks).
    struct DerivativeBounds {
        double d2, d3;
    };
    /// Proven bounds over [a, b] for the path queries (closest point); default unknown (∞),
    /// which makes a search subdivide instead of discarding.
    virtual DerivativeBounds derivative_bounds(double a, double b) const noexcept;

    /// Arc length over [0, 1], computed once by finish().
    double length() const noexcept { return length_; }
    /// Tight axis-aligned box over [0, 1], computed once by finish().
    const Bounds& bounds() const noexcept { return bounds_; }
    /// Arc length from 0 to u in [0, 1]. Default: cached piece lengths + quadrature.
    virtual double length_at(double u) const noexcept;
    /// Parameters 0 = b_0 < b_1 < ... < b_k = 1 between which the node is smooth.
    const std::vector<double>& breaks() const noexcept { return breaks_; }

    /// Appends a polyline from just after point(0) to point(1) (point(0) is the caller's)
    /// staying within `tolerance` of the shape. Default: adaptive subdivision by flatness.
    virtual void append_flattened(double tolerance, std::vector<Vec2>& out) const;

    /// Fills the caches (length, bounds, breaks); make_node calls it once after construction,
    /// because the base constructor cannot call the derived evaluation. Throws grape::Error
    /// when the length overflows a double.
    void finish();

protected:
    explicit PathNode(PathKind kind) noexcept : kind_(kind) {}

    /// Appends the interior parameters in (0, 1), increasing and after out.back() (out
    /// starts as {0}), where the node may be non-smooth: spline joins, complex-path cues,
    /// cusps (zero speed, a kink in |x′| that quadrature must not straddle). Default: none.
    virtual void interior_breaks(std::vector<double>& out) const;
    /// True when length_at is a closed form (then finish() takes length_at(1) as the
    /// length); otherwise the length comes from adaptive Gauss–Legendre per piece.
    virtual bool closed_form_length() const noexcept { return false; }
    /// Default: sampled extremes of each coordinate refined by root finding on d1.
    virtual Bounds compute_bounds() const;
    /// How many samples per piece compute_bounds and flattening start from (oscillating
    /// kinds need more so no extreme falls between samples).
    virtual int samples_per_piece() const noexcept { return 16; }

    /// Adaptive quadrature of the speed |d1| over [a, b] inside one smooth piece.
    double integrate_speed(double a, double b) const noexcept;

private:
    PathKind kind_;
    double length_ = 0.0;
    double quad_tolerance_ = 0.0;  // absolute error target of integrate_speed
    Bounds bounds_;
    std::vector<double> breaks_;   // 0, interior breaks..., 1
    std::vector<double> cumulative_;  // arc length at each break
};

/// The Path handle's node, for the path module's own sources. Path keeps its node
/// protected; a class derived from it may name the member, so the public header needs no
/// friend for this.
struct NodeAccess : Path {
    /// The node behind any Path.
    static const PathNode& node(const Path& path) noexcept { return *(path.*(&NodeAccess::node_)); }
    /// A Path sharing `node`.
    static Path wrap(std::shared_ptr<const PathNode> node) noexcept { return NodeAccess(std::move(node)); }

private:
    explicit NodeAccess(std::shared_ptr<const PathNode> node) noexcept : Path(std::move(node)) {}
};

/// Constructs a node and fills its caches.
template <class T, class... Args>
std::shared_ptr<const T> make_node(Args&&... args) {
    auto node = std::make_shared<T>(std::forward<Args>(args)...);
    node->finish();
    return node;
}

/// A straight segment a → b.
class LinearNode final : public PathNode {
public:
    LinearNode(Vec2 a, Vec2 b) noexcept : PathNode(PathKind::linear), a(a), b(b), delta(b - a) {}
    Vec2 point(double u) const noexcept override { return lerp(a, b, u); }  // exact at both ends
    Vec2 d1(double) const noexcept override { return delta; }
    Vec2 d2(double) const noexcept override { return {}; }
    double length_at(double u) const noexcept override { return grape::length(delta) * u; }
    void append_flattened(double tolerance, std::vector<Vec2>& out) const override;
    DerivativeBounds derivative_bounds(double, double) const noexcept override { return {0.0, 0.0}; }

    const Vec2 a;      ///< start
    const Vec2 b;      ///< end
    const Vec2 delta;  ///< b − a (the constant derivative)

protected:
    bool closed_form_length() const noexcept override { return true; }
    Bounds compute_bounds() const override;
};

/// A cubic Bézier; evaluated from its power-basis coefficients (x = c0 + c1·t + c2·t² + c3·t³).
class CubicBezierNode final : public PathNode {
public:
    CubicBezierNode(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3) noexcept
        : PathNode(PathKind::cubic_bezier),
          p{p0, p1, p2, p3},
          c{p0, 3.0 * (p1 - p0), 3.0 * (p2 - 2.0 * p1 + p0), p3 - p0 + 3.0 * (p1 - p2)} {}
    Vec2 point(double t) const noexcept override { return ((c[3] * t + c[2]) * t + c[1]) * t + c[0]; }
    // Derivatives in Bernstein form: the power-basis coefficients carry factors of 3 and 6 that
    // overflow for control points near 1e307, and inf·0 at the ends would then give NaN.
    Vec2 d1(double t) const noexcept override {
        const double s = 1.0 - t;
        return 3.0 * (s * s * (p[1] - p[0]) + 2.0 * s * t * (p[2] - p[1]) + t * t * (p[3] - p[2]));
    }
    Vec2 d2(double t) const noexcept override {
        return 6.0 * ((1.0 - t) * (p[2] - 2.0 * p[1] + p[0]) + t * (p[3] - 2.0 * p[2] + p[1]));
    }
    // x″ is affine in t, so |x″| is largest at an end; x‴ is constant.
    DerivativeBounds derivative_bounds(double a, double b) const noexcept override {
        return {std::max(grape::length(d2(a)), grape::length(d2(b))),
                6.0 * grape::length(p[3] - p[0] + 3.0 * (p[1] - p[2]))};
    }

    const Vec2 p[4];  ///< control points
    const Vec2 c[4];  ///< power-basis coefficients

protected:
    Bounds compute_bounds() const override;
    void interior_breaks(std::vector<double>& out) const override;
};

/// The arc-length reparametrization of any node: u ↦ source parameter v with
/// s(v) = u·L to 1e-9·L. The table holds, per span of v, the quintic Hermite model of s(v)
/// (from s, |x′| and (x′·x″)/|x′|, checked against quadrature at construction) and the
/// quintic Hermite model of its inverse, checked against the forward model. Lookup is a
/// bucket index in s and one polynomial; spans where the source stops (|x′| = 0 at an end,
/// where the inverse has a square-root shape) solve the forward model by safeguarded Newton.
class ReparametrizedNode final : public PathNode {
public:
    /// One span of the table. With σ = (s − s0)·inv_ds in [0, 1]: t = σ·(j1 + σ·(j2 + ...)),
    /// v = v0 + dv·t; the forward model is s(t) = s0 + t·(k1 + t·(k2 + t·(k3 + t·(k4 + t·k5)))).
    struct Span {
        double s0, inv_ds, v0, dv;
        double j1, j2, j3, j4, j5;
        double ds, k1, k2, k3, k4, k5;
        bool newton;  ///< the inverse model is not accurate here: solve the forward one
    };

    explicit ReparametrizedNode(Path source);

    /// The source parameter v at which the arc length is u·length(), u in [0, 1].
    double source_u(double u) const noexcept {
        if (u >= 1.0) return 1.0;  // the ends are exact: animations land on the end point
        const double s = std::clamp(u, 0.0, 1.0) * scaled_length_;
        if (!(s > 0.0)) return 0.0;  // also catches NaN
        // Compared as a double before the conversion, which must not see a value past size_t.
        const double bucket = s * bucket_scale_;
        const std::size_t b = bucket < static_cast<double>(buckets_.size()) ? static_cast<std::size_t>(bucket)
                                                                            : buckets_.size() - 1;
        std::size_t i = buckets_[b];
        while (i + 1 < spans_.size() && spans_[i + 1].s0 <= s) ++i;
        const Span& sp = spans_[i];
        if (sp.newton) return solve_span(sp, s);
        const double g = std::clamp((s - sp.s0) * sp.inv_ds, 0.0, 1.0);
        const double t = g * (sp.j1 + g * (sp.j2 + g * (sp.j3 + g * (sp.j4 + g * sp.j5))));
        return sp.v0 + sp.dv * t;
    }
    Vec2 point(double u) const noexcept override { return source_node_->point(source_u(u)); }
    Vec2 d1(double u) const noexcept override;
    Vec2 d2(double u) const noexcept override;
    double length_at(double u) const noexcept override {
        return std::clamp(u, 0.0, 1.0) * source_node_->length();
    }
    void append_flattened(double tolerance, std::vector<Vec2>& out) const override;

    /// The path this one reparametrizes.
    const Path& source() const noexcept { return source_; }

protected:
    bool closed_form_length() const noexcept override { return true; }
    Bounds compute_bounds() const override { return source_node_->bounds(); }

private:
    static double solve_span(const Span& sp, double s) noexcept {
        const double target = s - sp.s0;
        double lo = 0.0, hi = 1.0;
        double t = sp.ds > 0.0 ? std::clamp(target / sp.ds, 0.0, 1.0) : 0.0;
        // Newton on the span's polynomial, kept inside the bracket by bisection; the
        // polynomial is increasing in practice, so 2–4 steps reach the rounding floor.
        for (int i = 0; i < 12; ++i) {
            const double f = t * (sp.k1 + t * (sp.k2 + t * (sp.k3 + t * (sp.k4 + t * sp.k5)))) - target;
            const double df = sp.k1 + t * (2.0 * sp.k2 + t * (3.0 * sp.k3 + t * (4.0 * sp.k4 + t * 5.0 * sp.k5)));
            if (f < 0.0) lo = t; else hi = t;
            if (std::abs(f) <= 1e-14 * (sp.s0 + sp.ds) + 1e-300) break;
            double next = t - f / df;
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (next == t) break;
            t = next;
        }
        return sp.v0 + sp.dv * t;
    }

    void build();
    double build_span_checked(double va, double vb, double sa, int depth, double total);
    // Fits the span's inverse model; false when it misses although the path moves at both
    // ends (splitting the span will help), true when done (inverse or Newton).
    static bool fit_inverse(Span& sp, double total, double noise) noexcept;

    Path source_;
    const PathNode* source_node_;
    std::vector<Span> spans_;
    std::vector<std::uint32_t> buckets_;  // buckets_[b]: the span holding s = b / bucket_scale_
    double bucket_scale_ = 0.0;
    std::size_t max_spans_ = 0;  // the span budget, set by build() from the number of pieces
    // The table's arc lengths (s0, ds, k1..k5 of every span) are in units of 2^−exponent_,
    // which puts the length in [1, 2): for a length of 1e-320 the spans would otherwise
    // underflow to zero length and the reciprocals overflow, and every lookup land on the end.
    int exponent_ = 0;
    double scaled_length_ = 0.0;
    double noise_ = 0.0;  // the rounding floor of the scaled arc lengths (denormal paths only)
};

}  // namespace grape::detail
