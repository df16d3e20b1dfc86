// grape — the nearest point of a path: branch and bound over the smooth pieces of the leaf
// kinds, with bounds that are proven from sup |x″| and sup |x‴| per span, Newton where the
// squared distance is provably convex, circles in closed form, complex paths part by part and
// reparametrized paths through their source.
#include <grape/error.hpp>
#include <grape/path_query.hpp>

#include "geometry.hpp"
#include "kinds.hpp"
#include "path_node.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace grape {

namespace detail {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double eps = std::numeric_limits<double>::epsilon();

// |v| by a plain square root (std::hypot costs ~30 ns and dominated the search), falling back
// to hypot only where the squares overflow or underflow.
double norm(Vec2 v) noexcept {
    const double r = std::sqrt(v.x * v.x + v.y * v.y);
    return (r < infinity && r > 1e-150) ? r : std::hypot(v.x, v.y);
}

double gap(Vec2 a, Vec2 b) noexcept { return norm(a - b); }

double distance_to_box(Vec2 q, const Bounds& b) noexcept {
    const double dx = std::max({b.min.x - q.x, 0.0, q.x - b.max.x});
    const double dy = std::max({b.min.y - q.y, 0.0, q.y - b.max.y});
    return norm({dx, dy});
}

double distance_to_segment(Vec2 q, Vec2 a, Vec2 b) noexcept {
    const Vec2 ab = b - a;
    const double len = norm(ab);  // through the unit direction: |ab|² overflows near 1e154
    const double t = len > 0.0 ? std::clamp(dot(q - a, ab / len) / len, 0.0, 1.0) : 0.0;
    return gap(q, a + ab * t);
}


// From a node's parameter to the search's: u = offset + scale·v, scale > 0 (order kept).
struct Map {
    double offset = 0.0;
    double scale = 1.0;
    double operator()(double v) const noexcept { return offset + scale * v; }
};

// The best point so far. Of the points within `tol` of the least distance seen, the one with
// the smallest u is kept (ties go to the smallest u, and no chain of near-ties can drift).
struct Search {
    Search(Vec2 query, double tolerance, double unit) noexcept : q(query), tol(tolerance), inv(1.0 / unit) {}
    Vec2 q;
    double tol;
    double inv;  // 1 / the path's size: products of lengths are formed in units of it (no overflow)
    double bound = infinity;  // a distance already reached by an enclosing search
    long budget = 1L << 16;   // intervals left to examine: bounds the work
    double least = infinity;  // the least distance seen
    double u = 0.0;           // the answer's parameter (search coordinates), point and distance
    Vec2 point;
    double d = infinity;

    void offer(double gu, Vec2 p) noexcept {
        const double dist = gap(q, p);
        if (!(dist <= d + tol || dist < least)) return;  // also rejects NaN
        least = std::min(least, dist);
        if (!(dist <= least + tol)) return;
        if (d > least + tol || gu < u || dist < d - tol) {
            u = gu;
            point = p;
            d = dist;
        }
    }
    // True when nothing in a stretch starting at global parameter ga, none of whose points is
    // nearer than `lower`, could change the answer: a tie only matters left of the answer.
    bool discard(double lower, double ga) const noexcept {
        if (lower > bound + tol) return true;
        return ga < u ? lower > least + tol : lower >= least - tol;
    }
};

void search(const PathNode& node, double lo, double hi, Map map, Search& s) noexcept;

// Branch and bound over one leaf node (a kind with derivative bounds).
struct Leaf {
    const PathNode& n;
    Search& s;
    Map map;

    void offer(double v) noexcept { s.offer(map(v), n.point(v)); }
    // f′ for f = ½|x − q|², in units of the path's size squared.
    double slope(double v) const noexcept { return dot(n.d1(v) * s.inv, (n.point(v) - s.q) * s.inv); }

    void run(double lo, double hi) noexcept {
        const auto& br = n.breaks();
        for (std::size_t i = 0; i + 1 < br.size(); ++i) {
            const double a = std::max(lo, br[i]);
            const double b = std::min(hi, br[i + 1]);
            if (a > b) continue;
            if (b > a) {
                interval(a, b, 0);
            } else {
                offer(a);
            }
        }
    }

    // On [a, b] (m its middle, h its half width) Taylor's theorem with |x″| ≤ K puts every
    // point within K·h²/2 of the tangent segment pm ± dm·h: that distance less K·h²/2 bounds
    // the interval's distances from below. f″ = |x′|² + x″·(x − q) is bounded below with
    // |x′| ≥ |dm| − K·h, |x″(u) − x″(m)| ≤ K3·h and |x − pm| ≤ (|dm| + K·h)·h; where that is
    // positive f′ increases, and the one minimum is an end or the root of f′.
    void interval(double a, double b, int depth) noexcept {
        const double m = 0.5 * (a + b);
        const double h = 0.5 * (b - a);
        const Vec2 pm = n.point(m);
        const Vec2 dm = n.d1(m);
        const auto [k2, k3] = n.derivative_bounds(a, b);
        const double lower = distance_to_segment(s.q, pm - dm * h, pm + dm * h) - 0.5 * k2 * h * h;
        const double ga = map(a);
        if (s.discard(lower, ga)) return;
        if (depth == 0) {  // the piece's ends: inner intervals' ends are their parents' middles
            offer(a);
            offer(b);
        }
        s.offer(map(m), pm);
        if (--s.budget < 0) return;
        // In units of the path's size, so that the products neither overflow nor underflow.
        const double c = s.inv;
        const double speed = norm(dm) * c;
        const double slow = speed - k2 * c * h;
        const double curving = (slow > 0.0 ? slow * slow : 0.0) + dot(n.d2(m) * c, (pm - s.q) * c) -
                               k3 * c * h * (gap(pm, s.q) * c) - k2 * c * (speed + k2 * c * h) * h;
        if (curving > 0.0) {
            convex(a, b, m);
            return;
        }
        if (s.discard(lower, ga) || depth >= 64 || !(m > a && m < b)) return;
        // The nearer half first (where f decreases from m): its answer discards more of the other.
        if (dot(dm * c, (pm - s.q) * c) > 0.0) {
            interval(a, m, depth + 1);
            interval(m, b, depth + 1);
        } else {
            interval(m, b, depth + 1);
            interval(a, m, depth + 1);
        }
    }

    void convex(double a, double b, double guess) noexcept {
        const double br = inside_right(a, b);
        if (slope(a) >= 0.0) {
            offer(a);
            return;
        }
        if (slope(br) <= 0.0) {
            offer(b);
            return;
        }
        auto fd = [this](double v) noexcept {
            const Vec2 g = n.d1(v) * s.inv;
            const Vec2 r = (n.point(v) - s.q) * s.inv;
            return std::pair<double, double>{dot(g, r), length_squared(g) + dot(n.d2(v) * s.inv, r)};
        };
        offer(find_root(fd, a, br, guess, 2.0 * eps * std::abs(b)).x);
    }
};

// A circle arc (or a spiral of constant radius): the nearest angle is that of q − center,
// unimodally; the candidates are the first such angle in the range and the range's ends.
// At the center every point ties and the range's start wins.
void circle(const PathNode& n, Vec2 center, double rotation, double a0, double a1, double lo, double hi, Map map,
            Search& s) noexcept {
    auto offer = [&](double v) { s.offer(map(v), n.point(v)); };
    offer(lo);
    offer(hi);
    const double span = a1 - a0;
    const Vec2 d = s.q - center;
    if (span == 0.0 || (d.x == 0.0 && d.y == 0.0)) return;
    const double phi = std::atan2(d.y, d.x) - rotation;
    const double t_lo = a0 + span * lo, t_hi = a0 + span * hi;
    const double turn = 2.0 * pi;
    const double theta = span > 0.0 ? phi + turn * std::ceil((t_lo - phi) / turn)
                                    : phi + turn * std::floor((t_lo - phi) / turn);
    if (span > 0.0 ? theta <= t_hi : theta >= t_hi) offer(std::clamp((theta - a0) / span, lo, hi));
}

// Where complex parts do not meet, a part's end (the search's point) is reached only just
// before the next cue, where point(u) is already the next part's start: steps u down while
// that brings point(u) closer to `target` (a few ulps at most; through a reparametrized path's table, several u
// may share one source parameter).
template <class Point>
double settle(Point point, double u, double lo, Vec2 target) noexcept {
    double best = u;
    double best_d = distance(point(u), target);
    for (int k = 0; k < 8 && best_d > 0.0; ++k) {
        u = std::nextafter(u, -infinity);
        if (u < lo) break;
        const double d = distance(point(u), target);
        if (d < best_d) {
            best = u;
            best_d = d;
        }
    }
    return best;
}

// The u of a reparametrized node whose source parameter is v (source_u is increasing).
double reparametrized_u(const ReparametrizedNode& r, double v, double lo, double hi) noexcept {
    const PathNode& src = detail::NodeAccess::node(r.source());
    const double total = src.length();
    auto fd = [&](double u) noexcept {
        const double speed = length(src.d1(r.source_u(u)));
        return std::pair<double, double>{r.source_u(u) - v,
                                         speed > 0.0 ? total / speed : std::numeric_limits<double>::quiet_NaN()};
    };
    const double guess = total > 0.0 ? std::clamp(src.length_at(v) / total, lo, hi) : lo;
    return find_root(fd, lo, hi, guess, 2.0 * eps).x;
}

void complex(const ComplexNode& c, double lo, double hi, Map map, Search& s) noexcept {
    const auto pieces = c.pieces();
    struct Range {
        bool any;
        double v0, v1;
    };
    auto range = [&](const auto& p) {
        const double end = p.start + p.width;
        if (hi < p.start || lo > end) return Range{false, 0.0, 0.0};
        return Range{true, std::clamp((lo - p.start) * p.inv_width, 0.0, 1.0),
                     std::clamp((hi - p.start) * p.inv_width, 0.0, 1.0)};
    };
    auto visit = [&](const auto& p) {
        const Range r = range(p);
        if (!r.any) return;
        const Map inner{map(p.start), map.scale * p.width};
        if (s.discard(distance_to_box(s.q, p.node->bounds()), inner(r.v0))) return;
        search(*p.node, r.v0, r.v1, inner, s);
    };
    // A cheap bound first: each part's middle, where its box could beat the best so far. The
    // search then discards most parts by their boxes alone.
    for (const auto& p : pieces) {
        const Range r = range(p);
        if (!r.any || !(distance_to_box(s.q, p.node->bounds()) < s.least)) continue;
        const double v = 0.5 * (r.v0 + r.v1);
        s.offer(map(p.start + v * p.width), p.node->point(v));
    }
    for (const auto& p : pieces) visit(p);
}

void search(const PathNode& node, double lo, double hi, Map map, Search& s) noexcept {
    switch (node.kind()) {
        case PathKind::complex:
            complex(static_cast<const ComplexNode&>(node), lo, hi, map, s);
            return;
        case PathKind::reparametrized: {
            const auto& r = static_cast<const ReparametrizedNode&>(node);
            Search inner(s.q, s.tol, 1.0 / s.inv);
            inner.bound = std::min(s.bound, s.least);
            inner.budget = s.budget;
            search(detail::NodeAccess::node(r.source()), r.source_u(lo), r.source_u(hi), Map{}, inner);
            s.budget = inner.budget;
            if (inner.d < infinity) {
                const double u = settle([&r](double v) noexcept { return r.point(v); },
                                        reparametrized_u(r, inner.u, lo, hi), lo, inner.point);
                s.offer(map(u), r.point(u));
            }
            return;
        }
        case PathKind::circle:
        case PathKind::elliptical_arc: {
            const auto& arc = static_cast<const ArcNode&>(node);
            if (arc.rx == arc.ry) {
                circle(node, arc.center, arc.rotation, arc.a0, arc.a1, lo, hi, map, s);
                return;
            }
            break;
        }
        case PathKind::spiral: {
            const auto& sp = static_cast<const SpiralNode&>(node);
            if (sp.r0 == sp.r1) {
                circle(node, sp.center, 0.0, sp.a0, sp.a1, lo, hi, map, s);
                return;
            }
            break;
        }
        default: break;
    }
    Leaf{node, s, map}.run(lo, hi);
}

ClosestPoint nearest(const Path& path, Vec2 q, double lo, double hi, const double* from) noexcept {
    if (!is_finite(q)) return {lo, path.point(lo), infinity};
    const PathNode& node = detail::NodeAccess::node(path);
    const Bounds& box = node.bounds();
    const Vec2 size = box.size();
    const double extent = std::max(std::abs(size.x), std::abs(size.y));
    const double far = distance(q, 0.5 * (box.min + box.max));
    // 1e-13 of the path's size is the answer's target (a tenth of the promise); the rounding
    // of distances to a far q (a few ulps of it) is the floor no bound can beat.
    const double unit = extent > 0.0 && extent < infinity ? extent : 1.0;
    Search s(q, 1e-13 * extent + 16.0 * eps * (far + extent) + std::numeric_limits<double>::min(), unit);
    if (from) {
        // Newton from the last answer: a tight distance first, so the search discards early.
        double u = std::clamp(*from, lo, hi);
        if (!(u == u)) u = lo;
        s.offer(u, path.point(u));
        for (int i = 0; i < 8; ++i) {
            const Vec2 g = path.d1(u) * s.inv;
            const Vec2 r = (path.point(u) - q) * s.inv;
            const double f2 = length_squared(g) + dot(path.d2(u) * s.inv, r);
            if (!(f2 > 0.0)) break;
            const double next = std::clamp(u - dot(g, r) / f2, lo, hi);
            if (next == u) break;
            u = next;
            s.offer(u, path.point(u));
        }
    }
    search(node, lo, hi, Map{}, s);
    if (!(s.d < infinity)) return {lo, path.point(lo), distance(q, path.point(lo))};
    const double u = settle([&path](double v) noexcept { return path.point(v); }, std::clamp(s.u, lo, hi), lo, s.point);
    const Vec2 p = path.point(u);
    return {u, p, distance(q, p)};
}

}  // namespace
}  // namespace detail

ClosestPoint closest_point(const Path& path, Vec2 q) noexcept { return detail::nearest(path, q, 0.0, 1.0, nullptr); }

ClosestPoint closest_point(const Path& path, Vec2 q, double u0, double u1) {
    if (!(u0 >= 0.0 && u0 <= u1 && u1 <= 1.0)) {
        throw Error("closest_point: the range must satisfy 0 ≤ u0 ≤ u1 ≤ 1 (got u0 = " + detail::number_text(u0) +
                    ", u1 = " + detail::number_text(u1) + ")");
    }
    return detail::nearest(path, q, u0, u1, nullptr);
}

ClosestPoint closest_point_from(const Path& path, Vec2 q, double last_u) noexcept {
    return detail::nearest(path, q, 0.0, 1.0, &last_u);
}

}  // namespace grape
