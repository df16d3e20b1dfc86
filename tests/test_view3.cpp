// View3 against the projections written out by hand: the oblique map x + r·cos(a)·y,
// −(z + r·sin(a)·y); the pinhole h / (d·tan(fov/2)); straight lines staying straight; the
// orbit's eye at its distance; and errors naming the argument.
#include <grape/view3.hpp>

#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using grape::Projected;
using grape::Vec2;
using grape::Vec3;
using grape::View3;
using grape::testing::error_text;

constexpr double pi = 3.141592653589793;

TEST(View3, ObliqueIsTheCabinetFormula) {
    const View3 v = View3::oblique(pi / 4, 0.5);
    const double r = 0.5 * std::cos(pi / 4);  // = 0.5 sin(pi / 4)
    std::mt19937_64 rng(grape::testing::test_seed(31));
    std::uniform_real_distribution<double> c(-10, 10);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 p{c(rng), c(rng), c(rng)};
        const Projected q = v.project(p);
        // 1e-14: three products and two sums of values below 20 (a few ulps of 20).
        EXPECT_NEAR(q.point.x, p.x + r * p.y, 1e-14);
        EXPECT_NEAR(q.point.y, -(p.z + r * p.y), 1e-14);
        EXPECT_TRUE(q.visible);
    }
    EXPECT_FALSE(v.is_perspective());
}

TEST(View3, ObliqueViewDirectionProjectsToOnePointAndOrdersDepth) {
    const View3 v = View3::oblique(0.7, 0.8);
    const Vec3 f = v.view_direction({});
    EXPECT_NEAR(grape::length(f), 1.0, 1e-15);
    const Vec3 p{1, 2, 3};
    const Projected a = v.project(p), b = v.project(p + f * 5.0);
    EXPECT_NEAR(a.point.x, b.point.x, 1e-14);
    EXPECT_NEAR(a.point.y, b.point.y, 1e-14);
    EXPECT_NEAR(b.depth - a.depth, 5.0, 1e-14);  // farther along the view is deeper
}

TEST(View3, PerspectiveIsThePinholeFormula) {
    // Eye on −y looking at the origin with a 90° field: focal length 1.
    const View3 v = View3::perspective({0, -10, 0}, {0, 0, 0}, {0, 0, 1}, pi / 2);
    EXPECT_TRUE(v.is_perspective());
    std::mt19937_64 rng(grape::testing::test_seed(31));
    std::uniform_real_distribution<double> c(-5, 5);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 p{c(rng), c(rng), c(rng)};
        const double d = p.y + 10.0;  // depth along +y
        const Projected q = v.project(p);
        ASSERT_TRUE(q.visible);
        EXPECT_NEAR(q.depth, d, 1e-13);
        // 1e-13: tan(π/4) = 1 to an ulp, so the focal length is 1 within 2e-16; the
        // quotients are below 2 and carry a few ulps.
        EXPECT_NEAR(q.point.x, p.x / d, 1e-13);
        EXPECT_NEAR(q.point.y, -p.z / d, 1e-13);
    }
    EXPECT_FALSE(v.project({0, -10, 0}).visible);
    EXPECT_FALSE(v.project({0, -20, 0}).visible);
}

TEST(View3, PerspectiveKeepsLinesStraight) {
    const View3 v = View3::perspective({3, -7, 4}, {0.5, 1, -0.2}, {0, 0, 1}, 1.0);
    std::mt19937_64 rng(grape::testing::test_seed(31));
    std::uniform_real_distribution<double> c(-2, 2), t(0, 1);
    for (int i = 0; i < 200; ++i) {
        const Vec3 a{c(rng), c(rng), c(rng)}, b{c(rng), c(rng), c(rng)};
        const Vec3 m = a + (b - a) * t(rng);
        const Vec2 pa = v.project(a).point, pb = v.project(b).point, pm = v.project(m).point;
        const Vec2 ab = pb - pa, am = pm - pa;
        // Twice the triangle's area over |ab|²: the distance of pm from the line, relative;
        // 1e-12 covers the rounding of three projections of magnitude ~1.
        const double cross = ab.x * am.y - ab.y * am.x;
        EXPECT_NEAR(cross / std::max(1e-3, ab.x * ab.x + ab.y * ab.y), 0.0, 1e-12);
    }
}

TEST(View3, OrbitPutsTheEyeAtItsDistance) {
    const Vec3 target{1, 2, 3};
    for (double az : {0.0, 1.0, 2.5, -2.0})
        for (double el : {-1.0, 0.0, 0.4, 1.5}) {
            const View3 v = View3::orbit(target, 7.0, az, el);
            EXPECT_NEAR(grape::distance(v.eye(), target), 7.0, 1e-13);
            const Projected q = v.project(target);
            EXPECT_NEAR(q.depth, 7.0, 1e-13);
            EXPECT_NEAR(q.point.x, 0.0, 1e-14);
            EXPECT_NEAR(q.point.y, 0.0, 1e-14);
            // +z shows up the picture (y down) whatever the orbit.
            EXPECT_LT(v.project(target + Vec3{0, 0, 0.1}).point.y, 0.0);
            EXPECT_NEAR(v.eye().z - target.z, 7.0 * std::sin(el), 1e-13);
        }
    // Straight above: clamped short of the pole, still a picture.
    const View3 top = View3::orbit(target, 5.0, 0.3, 10.0);
    EXPECT_TRUE(std::isfinite(top.project({0, 0, 0}).point.x));
}

TEST(View3, BadArgumentsAreNamed) {
    const double nan = std::nan("");
    EXPECT_EQ(error_text([&] { View3::oblique(nan); }), "View3::oblique: angle is not finite");
    EXPECT_EQ(error_text([&] { View3::oblique(0.5, 0.0); }), "View3::oblique: recede is not in (0, 1]");
    EXPECT_EQ(error_text([&] { View3::perspective({1, 1, 1}, {1, 1, 1}); }),
              "View3::perspective: target equals eye (no view direction)");
    EXPECT_EQ(error_text([&] { View3::perspective({0, 0, 5}, {0, 0, 0}, {0, 0, 1}); }),
              "View3::perspective: up is parallel to the view direction");
    EXPECT_EQ(error_text([&] { View3::perspective({0, -5, 0}, {0, 0, 0}, {0, 0, 0}); }), "View3::perspective: up is zero");
    EXPECT_EQ(error_text([&] { View3::perspective({0, -5, 0}, {0, 0, 0}, {0, 0, 1}, pi); }),
              "View3::perspective: fov_y is not in (0, pi)");
    EXPECT_EQ(error_text([&] { View3::perspective({nan, 0, 0}, {0, 0, 0}); }), "View3::perspective: eye is not finite");
    EXPECT_EQ(error_text([&] { View3::orbit({}, -1.0, 0, 0); }), "View3::orbit: distance is not positive");
}

TEST(View3, ProjectDoesNotMisbehaveOnValidObjects) {
    const View3 v = View3::perspective({0, -10, 0}, {0, 0, 0});
    static_assert(noexcept(v.project(Vec3{})));
    static_assert(noexcept(v.view_direction(Vec3{})));
    EXPECT_NEAR(grape::length(v.view_direction({4, 5, 6})), 1.0, 1e-15);
}

}  // namespace
