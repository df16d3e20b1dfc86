// ray3: the nearest point of a 3-D path to a ray, against a reference written here (the
// distance to the ray sampled densely, every sampled valley narrowed by golden sections, which
// shares nothing with grape's branch and bound or its Newton steps), on random and
// adversarial rays; and the warm-started local nearest point against the global one.
#include <grape/path3.hpp>
#include <grape/path3_closest.hpp>
#include <grape/vec3.hpp>

#include "count_allocations.hpp"
#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

using namespace grape;

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

struct Ray {
    Vec3 o, d;  // d unit
};

double ray_distance(const Ray& r, Vec3 p) {
    const double t = std::max(0.0, dot(p - r.o, r.d));
    return length(p - (r.o + r.d * t));
}

// Golden-section search for the least distance on [a, b]; returns that distance.
double golden(const Path3& p, const Ray& r, double a, double b) {
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    double x1 = b - g * (b - a), x2 = a + g * (b - a);
    double f1 = ray_distance(r, p.point(x1)), f2 = ray_distance(r, p.point(x2));
    double best = std::min({f1, f2, ray_distance(r, p.point(a)), ray_distance(r, p.point(b))});
    for (int i = 0; i < 90 && b - a > 1e-17; ++i) {
        if (f1 <= f2) {
            b = x2, x2 = x1, f2 = f1;
            x1 = b - g * (b - a), f1 = ray_distance(r, p.point(x1));
        } else {
            a = x1, x1 = x2, f1 = f2;
            x2 = a + g * (b - a), f2 = ray_distance(r, p.point(x2));
        }
        best = std::min({best, f1, f2});
    }
    return best;
}

// The reference: 512 samples per piece, each sampled valley (and each end) narrowed.
double reference_distance(const Path3& p, const Ray& r) {
    std::vector<double> u;
    const auto breaks = p.breaks();
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
        for (int i = 0; i < 512; ++i) u.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * i / 512.0);
    }
    u.push_back(1.0);
    std::vector<double> f;
    for (const double v : u) f.push_back(ray_distance(r, p.point(v)));
    double best = *std::min_element(f.begin(), f.end());
    for (std::size_t i = 0; i < u.size(); ++i) {
        const bool left = i == 0 || f[i] <= f[i - 1], right = i + 1 == u.size() || f[i] <= f[i + 1];
        if (left && right) best = std::min(best, golden(p, r, u[i == 0 ? 0 : i - 1], u[std::min(i + 1, u.size() - 1)]));
    }
    return best;
}

std::vector<Path3> test_paths() {
    const Vec3 pts[] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0.5}, {0, 1, 0.5}, {0, 3, -1}};
    return {
        Path3::cubic_bezier({0, 0, 0}, {2, 0, 0}, {2, 1, 0.5}, {0, 1, 0.5}),  // a hairpin
        Path3::cubic_bezier({0, 0, 0}, {5, 0, 0}, {0, 5, 3}, {5, 5, 3}),      // a twist
        Path3::catmull_rom(pts, CatmullRom::centripetal, true),
        Path3::helix({.radius = 1, .rise = two_pi * 0.2, .turns = 3}),
        Path3::complex_by_length({Path3::line({2, 0, 0}, {1, 0, 0}), Path3::quadratic_bezier({1, 0, 0}, {0, 0, 1}, {0, 2, 0})}),
        Path3::line({-1, -1, 0}, {3, 2, 1}),
    };
}

}  // namespace

// 10⁴ random rays (origins in a box about the paths, directions uniform on the sphere): none
// may be beaten by the reference by more than the promised 1e-12·(length + distance), the
// point and t must be those of u, and the gap must be proven within that.
TEST(Ray3, GlobalAgainstReference) {
    std::mt19937_64 rng(grape::testing::test_seed(21));
    std::uniform_real_distribution<double> box(-4.0, 4.0);
    std::normal_distribution<double> gauss;
    const std::vector<Path3> paths = test_paths();
    const int per_path = grape::testing::fast_build ? 1700 : 60;
    int misses = 0, total = 0;
    double worst = 0.0, worst_gap = 0.0;
    for (const Path3& p : paths) {
        for (int k = 0; k < per_path; ++k) {
            const Ray r{{box(rng), box(rng), box(rng)}, normalized(Vec3{gauss(rng), gauss(rng), gauss(rng)})};
            // Every fifth ray aims at a point of the path, so that many hit it (distance 0).
            const Vec3 dir = k % 5 == 0 ? normalized(p.point((k % 97) / 96.0) - r.o) : r.d;
            const Ray ray{r.o, dir};
            const RayClosest3 c = closest_point_to_ray(p, ray.o, ray.d * 3.0);  // any length
            const double ref = reference_distance(p, ray);
            const double scale = p.length() + c.distance;
            ++total;
            if (c.distance > ref + 1e-12 * scale) ++misses;
            worst = std::max(worst, (c.distance - ref) / scale);
            worst_gap = std::max(worst_gap, c.gap / scale);
            EXPECT_LE(c.gap, 1e-12 * scale);
            EXPECT_EQ(c.point, p.point(c.u));
            EXPECT_NEAR(c.distance, ray_distance(ray, c.point), 1e-15 * scale);
            EXPECT_GE(c.t, 0.0);
            EXPECT_LE(distance(ray.o + ray.d * c.t, c.point), c.distance * (1 + 1e-14) + 1e-15 * scale);
        }
    }
    EXPECT_EQ(misses, 0);
    std::printf("ray closest point: %d rays, %d misses, worst excess over the reference %.2g, worst gap %.2g "
                "(relative to length + distance)\n",
                total, misses, worst, worst_gap);
}

// The rays no sampling can be trusted with.
TEST(Ray3, Adversarial) {
    // Along a helix's axis: every point is at distance R; the capped pass still proves a gap.
    const Path3 h = Path3::helix({.radius = 1, .rise = two_pi * 0.2, .turns = 3});
    const RayClosest3 axis = closest_point_to_ray(h, {0, 0, -1}, {0, 0, 1});
    EXPECT_NEAR(axis.distance, 1.0, 1e-14);
    EXPECT_LE(axis.gap, 1e-6);  // as closest_point at a circle's centre: 2¹⁴ even leaves, slack R·ω²h²/8
    // Through a circle's centre, across its plane: every point at distance R again.
    const Path3 circle = Path3::helix({.radius = 2.0, .turns = 1.0});
    const RayClosest3 across = closest_point_to_ray(circle, {0, 0, 0}, {0, 0, 1});
    EXPECT_NEAR(across.distance, 2.0, 1e-14);
    // From the centre within the plane: it hits the circle at (2, 0, 0), u = 0, t = 2.
    const RayClosest3 in_plane = closest_point_to_ray(circle, {0, 0, 0}, {1, 0, 0});
    EXPECT_NEAR(in_plane.distance, 0.0, 1e-14);
    EXPECT_NEAR(in_plane.t, 2.0, 1e-14);
    EXPECT_NEAR(in_plane.u, 0.0, 1e-14);
    // Pointing away from the circle's plane: the ray's origin is the nearest point of the ray.
    const RayClosest3 away = closest_point_to_ray(circle, {0, 0, 1}, {0, 0, 1});
    EXPECT_EQ(away.t, 0.0);
    EXPECT_NEAR(away.distance, std::sqrt(5.0), 1e-14);
    // Inside a hairpin, between its legs and along them.
    const Path3 hairpin = test_paths()[0];
    for (const double y : {0.25, 0.5, 0.75}) {
        const Ray r{{-1, y, 0.5 * y}, {1, 0, 0}};
        const RayClosest3 c = closest_point_to_ray(hairpin, r.o, r.d);
        EXPECT_LE(c.distance, reference_distance(hairpin, r) + 1e-12 * hairpin.length()) << y;
    }
    // Parallel to a line at distance 1: every point ties exactly, and the least u wins.
    const Path3 line = Path3::line({0, 0, 0}, {4, 0, 0});
    const RayClosest3 par = closest_point_to_ray(line, {-1, 1, 0}, {1, 0, 0});
    EXPECT_EQ(par.distance, 1.0);
    EXPECT_EQ(par.u, 0.0);
    EXPECT_EQ(par.t, 1.0);
    // A zero direction is closest_point to the origin.
    const RayClosest3 zero = closest_point_to_ray(h, {0.3, 0.2, 1}, {0, 0, 0});
    EXPECT_NEAR(zero.distance, closest_point(h, {0.3, 0.2, 1}).distance, 1e-14);
}

// A dragged point: each query moves a little from the last, the hint is the last answer. The
// local answer must equal the global one (closest_point) wherever the hint lies in the global
// valley, here throughout; and when it does not, it is still a stationary point (g = 0).
TEST(Ray3, WarmStartedNearest) {
    const Path3 h = Path3::helix({.radius = 2, .rise = 1, .turns = 2});
    double u = 0.0, worst = 0.0;
    for (int k = 0; k <= 2000; ++k) {
        const double v = k / 2000.0;
        const Vec3 q = h.point(v) + Vec3{0.3 * std::cos(40 * v), 0.2, 0.3 * std::sin(40 * v)};
        const Closest3 local = closest_point_near(h, q, u);
        const Closest3 global = closest_point(h, q);
        const double scale = h.length() + global.distance;
        worst = std::max(worst, (local.distance - global.distance) / scale);
        EXPECT_LE(local.distance, global.distance + 1e-12 * scale) << k;
        EXPECT_EQ(local.gap, local.distance);  // nothing proven
        u = local.u;
    }
    // A hint on the wrong turn of a helix: that turn's valley, not the global one (the turn
    // below, 0.2 away, against ≈ 1.26 up).
    const Path3 coil = Path3::helix({.radius = 1, .rise = two_pi * 0.2, .turns = 3});
    const Vec3 q{1.2, 0, 0};
    const Closest3 wrong = closest_point_near(coil, q, 1.0 / 3.0);
    const double g = dot(wrong.point - q, coil.d1(wrong.u));
    EXPECT_LE(std::abs(g), 1e-12);
    EXPECT_NEAR(wrong.u, 1.0 / 3.0, 0.05);
    EXPECT_GT(wrong.distance, closest_point(coil, q).distance + 1.0);
    std::printf("warm-started nearest over a drag of 2001 steps: worst excess over the global %.2g\n", worst);
}

TEST(Ray3, QueriesDoNotAllocate) {
    const std::vector<Path3> paths = test_paths();
    const long before = g_allocations.load();
    double sink = 0.0;
    for (const Path3& p : paths) {
        for (int k = 0; k <= 20; ++k) {
            sink += closest_point_to_ray(p, {k * 0.1, 1, 2}, {1, -1, 0.5}).distance;
            sink += closest_point_near(p, {k * 0.1, 1, 2}, 0.5).distance;
        }
    }
    EXPECT_EQ(g_allocations.load(), before);
    EXPECT_TRUE(std::isfinite(sink));
}
