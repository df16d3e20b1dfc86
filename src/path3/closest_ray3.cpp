// grape — the global closest point of a 3-D path to a ray, by branch and bound as
// closest_point does for a point, and a warm-started local closest point.
#include <grape/path3_closest.hpp>

#include "node3.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace grape {
namespace {

constexpr double eps_ray3 = std::numeric_limits<double>::epsilon();

struct RaySearch3 {
    const detail::Path3Node& node;
    Vec3 o, d;  // origin, unit direction (or zero)
    RayClosest3 best;

    // Distance from p to the ray, and where along it.
    double to_ray(Vec3 p, double& t) const noexcept {
        t = std::max(0.0, dot(p - o, d));
        return distance(p, o + d * t);
    }
    void offer(double u, Vec3 p) noexcept {
        double t = 0.0;
        const double dist = to_ray(p, t);
        // Ties go to the smaller u.
        if (dist < best.distance || (dist == best.distance && u < best.u)) best = {u, p, dist, t, 0.0};
    }

    // Newton on g(u) = e·p′, e = p − (o + t·d) ⟂ d where t > 0, kept in [a, b]; every iterate
    // is offered. g′ = |p′|² − (p′·d)² + e·p″ (t > 0) or |p′|² + e·p″ (t = 0, the origin).
    void polish(double u, double a, double b) noexcept {
        for (int i = 0; i < 16; ++i) {
            const Vec3 p = node.point(u), d1 = node.d1(u), d2 = node.d2(u);
            double t = 0.0;
            to_ray(p, t);
            const Vec3 e = p - (o + d * t);
            const double along = t > 0.0 ? dot(d1, d) : 0.0;
            const double g = dot(e, d1), dg = dot(d1, d1) - along * along + dot(e, d2);
            if (!(dg > 0.0)) return;  // not convex here: the subdivision covers it
            const double next = std::clamp(u - g / dg, a, b);
            offer(next, node.point(next));
            if (std::abs(next - u) <= 4.0 * eps_ray3 * std::max(1.0, std::abs(u))) return;
            u = next;
        }
    }
};

// Distance between the segments [p1, q1] and [p2, q2] (Ericson, Real-Time Collision Detection
// 5.1.9), less a few roundings of their size so that it stays a lower bound.
double segments_distance3(Vec3 p1, Vec3 q1, Vec3 p2, Vec3 q2) noexcept {
    const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
    double s = 0.0, t = 0.0;
    if (a > 0.0 || e > 0.0) {
        if (!(a > 0.0)) {
            t = std::clamp(f / e, 0.0, 1.0);
        } else {
            const double c = dot(d1, r);
            if (!(e > 0.0)) {
                s = std::clamp(-c / a, 0.0, 1.0);
            } else {
                const double b = dot(d1, d2), denom = a * e - b * b;
                s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
                t = (b * s + f) / e;
                if (t < 0.0) {
                    t = 0.0;
                    s = std::clamp(-c / a, 0.0, 1.0);
                } else if (t > 1.0) {
                    t = 1.0;
                    s = std::clamp((b - c) / a, 0.0, 1.0);
                }
            }
        }
    }
    const double scale = length(r) + std::sqrt(a) + std::sqrt(e);
    return distance(p1 + d1 * s, p2 + d2 * t) - 16.0 * eps_ray3 * scale;
}

}  // namespace

RayClosest3 closest_point_to_ray(const Path3& path, Vec3 origin, Vec3 direction) noexcept {
    const detail::Path3Node& node = detail::Path3Access::node(path);
    RaySearch3 s{node, origin, normalized(direction), {}};
    {
        double t = 0.0;
        const Vec3 p0 = node.point(0.0);
        const double d0 = s.to_ray(p0, t);
        s.best = {0.0, p0, d0, t, 0.0};
    }
    const auto& breaks = node.breaks();
    for (const double b : breaks) s.offer(b, node.point(b));
    // Leaves stop once the bound's slack is this small: far below the 1e-12 promised.
    const double slack = 1e-14 * (node.length() + s.best.distance);
    struct Item {
        double a, b;
        int depth;
    };
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
                const Vec3 half = node.d1(m) * (0.5 * h);
                const Vec3 e0 = pm - half, e1 = pm + half;
                // The ray's nearest point to any point of the segment lies within this reach.
                const double reach = std::max({0.0, dot(e0 - s.o, s.d), dot(e1 - s.o, s.d)});
                const double lower = segments_distance3(e0, e1, s.o, s.o + s.d * reach) - remainder;
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
    // A stretch equidistant from the ray (a circle about it) prunes nothing: as closest_point,
    // the work is capped and a second pass subdivides evenly to the depth the budget allows.
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

Closest3 closest_point_near(const Path3& path, Vec3 query, double u_hint) noexcept {
    double u = std::isfinite(u_hint) ? std::clamp(u_hint, 0.0, 1.0) : 0.0;
    Vec3 p = path.point(u);
    double dist = distance(p, query);
    for (int i = 0; i < 32; ++i) {
        const Vec3 d1 = path.d1(u), d2 = path.d2(u), e = p - query;
        const double g = dot(e, d1), speed2 = dot(d1, d1);
        if (!(speed2 > 0.0) || g == 0.0) break;
        // Newton where the distance is convex, else a Gauss–Newton step (|p′|² > 0); a step
        // moves the point by at most half the distance, so that it stays in the hint's valley.
        const double dg = speed2 + dot(e, d2);
        const double reach = 0.5 * dist / std::sqrt(speed2);
        double step = std::clamp(-g / (dg > 0.0 ? dg : speed2), -reach, reach);
        bool moved = false;
        for (int k = 0; k < 30 && !moved; ++k, step *= 0.5) {
            const double next = std::clamp(u + step, 0.0, 1.0);
            if (next == u) break;
            const Vec3 pn = path.point(next);
            const double dn = distance(pn, query);
            // Not farther, up to the rounding of a distance: near the minimum it is flat.
            if (dn <= dist + 8.0 * eps_ray3 * (dist + length(pn))) {
                moved = true;
                const double change = std::abs(next - u);
                u = next, p = pn, dist = dn;
                if (change <= 4.0 * eps_ray3) i = 32;
            }
        }
        if (!moved) break;
    }
    return {u, p, dist, dist};
}

}  // namespace grape
