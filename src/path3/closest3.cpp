// grape — the global closest point of a 3-D path: branch and bound on second-order bounds.
#include "node3.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace grape {
namespace {

struct Search3 {
    const detail::Path3Node& node;
    Vec3 q;
    Closest3 best;

    void offer(double u, Vec3 p) noexcept {
        const double d = distance(p, q);
        // Ties go to the smaller u.
        if (d < best.distance || (d == best.distance && u < best.u)) best = {u, p, d, 0.0};
    }

    // Newton on g(u) = (p − q)·p′ from u, kept in [a, b]; every iterate is offered.
    void polish(double u, double a, double b) noexcept {
        for (int i = 0; i < 16; ++i) {
            const Vec3 p = node.point(u), d1 = node.d1(u), d2 = node.d2(u);
            const Vec3 e = p - q;
            const double g = dot(e, d1), dg = dot(d1, d1) + dot(e, d2);
            if (!(dg > 0.0)) return;  // not convex here: the subdivision covers it
            const double next = std::clamp(u - g / dg, a, b);
            offer(next, node.point(next));
            if (std::abs(next - u) <= 4.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(u))) return;
            u = next;
        }
    }
};

// Distance from q to the segment c + d·t, |t| ≤ half.
double segment_distance3(Vec3 q, Vec3 c, Vec3 d, double half) noexcept {
    const double dd = dot(d, d);
    const double t = dd > 0.0 ? std::clamp(dot(q - c, d) / dd, -half, half) : 0.0;
    return distance(q, c + d * t);
}

}  // namespace

Closest3 closest_point(const Path3& path, Vec3 query) noexcept {
    const detail::Path3Node& node = detail::Path3Access::node(path);
    Search3 s{node, query, {0.0, node.point(0.0), distance(node.point(0.0), query), 0.0}};
    const auto& breaks = node.breaks();
    for (const double b : breaks) s.offer(b, node.point(b));
    // Leaves stop once the bound's slack is this small: far below the 1e-12 promised.
    const double slack = 1e-14 * (node.length() + s.best.distance);
    struct Item {
        double a, b;
        int depth;
    };
    // One pass of subdivision to at most `cap` levels; false if it ran out of budget first.
    // Returns the least lower bound over the leaves kept in `lowest`.
    auto pass = [&](int cap, long budget, double& lowest) noexcept {
        std::array<Item, 128> stack{};
        lowest = s.best.distance;
        for (std::size_t piece = 0; piece + 1 < breaks.size(); ++piece) {
            std::size_t top = 0;
            stack[top++] = {breaks[piece], breaks[piece + 1], 0};
            while (top > 0) {
                const Item it = stack[--top];
                const double m = 0.5 * (it.a + it.b), h = it.b - it.a;
                const Vec3 pm = node.point(m);
                s.offer(m, pm);
                // Taylor at m: |p(u) − p(m) − p′(m)(u − m)| ≤ sup|p″|·(h/2)²/2.
                const double remainder = node.d2_bound(it.a, it.b) * h * h / 8.0;
                const double lower = segment_distance3(query, pm, node.d1(m), 0.5 * h) - remainder;
                if (lower > s.best.distance) continue;
                if (--budget <= 0) return false;
                if (remainder <= slack || it.depth >= cap || top + 2 > stack.size() || !(h > 0.0)) {
                    s.polish(m, it.a, it.b);
                    lowest = std::min(lowest, lower);
                    continue;
                }
                stack[top++] = {m, it.b, it.depth + 1};
                stack[top++] = {it.a, m, it.depth + 1};  // the left half first: ties to the smaller u
            }
        }
        return true;
    };
    // Where a long stretch is equidistant from the query (a circle about it) nothing can be
    // pruned: the work is capped, and a second pass subdivides every piece evenly to the depth
    // the budget allows, so the gap proven is as small as that work can make it.
    constexpr long budget = 1L << 15;
    double lowest = 0.0;
    if (!pass(60, budget, lowest)) {
        int cap = 14;
        for (std::size_t n = breaks.size() - 1; n > 1 && cap > 1; n >>= 1) --cap;
        pass(cap, std::numeric_limits<long>::max(), lowest);
    }
    s.best.gap = std::max(0.0, s.best.distance - std::min(lowest, s.best.distance));
    return s.best;
}

}  // namespace grape
