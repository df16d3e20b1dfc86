// Where an animation sits on its path: a sub-range of u (GSAP's start/end) and a sideways
// offset (Godot's h_offset), against closed forms (lines, circles), against slice() of the
// same path (de Casteljau's points, built independently of the range arithmetic) and against
// offset_point; bad values name their field.
#include <grape/anim.hpp>
#include <grape/error.hpp>
#include <grape/path_query.hpp>
#include <grape/timeline.hpp>

#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using grape::AnimationDef;
using grape::Engine;
using grape::Path;
using grape::Vec2;
using grape::testing::expect_error;

struct Sprite {
    double x = 0.0;
    double y = 0.0;
    double rotation = 0.0;
};

constexpr double pi = 3.14159265358979323846;

TEST(AnimationRange, CoversThePartOfALineBetweenItsEnds) {
    // Dyadic numbers throughout: every product and sum below is exact.
    Engine engine;
    Sprite s;
    const Path line = grape::LinearPath({0, 0}, {128, 0});
    engine.create_2d_animation(s, line, 1.0, {.range_start = 0.25, .range_end = 0.75});
    EXPECT_EQ(s.x, 32.0);  // written at creation: the range's start
    engine.tick(0.5);
    EXPECT_EQ(s.x, 64.0);
    engine.tick(0.25);
    EXPECT_EQ(s.x, 80.0);
    engine.tick(0.25);
    EXPECT_EQ(s.x, 96.0);
    EXPECT_EQ(s.y, 0.0);
}

TEST(AnimationRange, BelowItsStartItRunsBackwardsAndTurnsTheHeading) {
    Engine engine;
    Sprite s;
    const Path line = grape::LinearPath({0, 0}, {128, 0});
    const auto a = engine.create_2d_animation(s, line, 1.0, {.heading = true, .range_start = 0.75, .range_end = 0.25});
    EXPECT_EQ(s.x, 96.0);
    engine.tick(0.5);
    EXPECT_EQ(s.x, 64.0);
    EXPECT_EQ(a.value().x, 64.0);
    // Travelling towards −x: the heading is π (remainder keeps it in (−π, π]).
    EXPECT_NEAR(std::abs(s.rotation), pi, 1e-15);
    EXPECT_NEAR(std::abs(a.heading()), pi, 1e-15);
}

TEST(AnimationRange, MatchesTheSliceOfACubicAtRandomTimes) {
    // slice() blossoms the Bézier into the sub-curve's control points; the range evaluates the
    // whole curve at u0 + p·(u1 − u0). Both are the same curve: 1e-12 of a path ~300 long is
    // a few hundred ulps, far above either construction's round-off (a few ulps of 300).
    std::mt19937_64 rng(grape::testing::test_seed(1701));
    std::uniform_real_distribution<double> coordinate(-150.0, 150.0), unit(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const Vec2 p0{coordinate(rng), coordinate(rng)};
        const Vec2 p1{coordinate(rng), coordinate(rng)};
        const Vec2 p2{coordinate(rng), coordinate(rng)};
        const Vec2 p3{coordinate(rng), coordinate(rng)};
        const Path bezier = grape::CubicBezierPath(p0, p1, p2, p3);
        double a = unit(rng);
        double b = unit(rng);
        if (a == b) continue;
        const Path part = grape::slice(bezier, std::min(a, b), std::max(a, b));
        Engine engine;
        Sprite s;
        const auto anim = engine.create_2d_animation(s, bezier, 2.0, {.curve = grape::Curve::quad_in_out(), .range_start = a, .range_end = b});
        for (int k = 0; k < 8; ++k) {
            engine.tick(0.25 * unit(rng));
            const double p = anim.progress();
            const Vec2 expected = part.point(a < b ? p : 1.0 - p);
            EXPECT_NEAR(s.x, expected.x, 1e-12 * 300) << "trial " << trial;
            EXPECT_NEAR(s.y, expected.y, 1e-12 * 300) << "trial " << trial;
        }
    }
}

TEST(AnimationRange, AppliesToNDimensionalPaths) {
    Engine engine;
    const std::vector<double> from{0.0, 64.0}, to{128.0, 0.0};
    const auto a = engine.create_animation(grape::PathND(from, to), 1.0, {.range_start = 0.5, .range_end = 1.0});
    ASSERT_EQ(a.values().size(), 2u);
    EXPECT_EQ(a.values()[0], 64.0);  // readable while not yet ticked: the range's start
    engine.tick(0.5);
    EXPECT_EQ(a.values()[0], 96.0);
    EXPECT_EQ(a.values()[1], 16.0);
}

TEST(AnimationOffset, StaysAtTheOffsetFromACircle) {
    // A circle of radius 100 about (10, 20): the point beside it at offset d is on the
    // concentric circle of radius 100 ∓ d (the normal points inwards or outwards everywhere
    // alike), and the heading is the circle's tangent direction. 1e-12: ulps of 100.
    const Vec2 center{10, 20};
    const Path circle = grape::CirclePath(center, 100.0, 0.0, 2.0 * pi);
    for (const double d : {7.5, -7.5, 40.0}) {
        Engine engine;
        Sprite s;
        const auto a = engine.create_2d_animation(s, circle, 3.0, {.repeat = -1, .heading = true, .offset = d});
        const double r0 = std::hypot(s.x - center.x, s.y - center.y);
        EXPECT_TRUE(std::abs(r0 - (100.0 - d)) < 1e-12 || std::abs(r0 - (100.0 + d)) < 1e-12) << r0;
        for (int k = 0; k < 100; ++k) {
            engine.tick(0.07);
            const double r = std::hypot(s.x - center.x, s.y - center.y);
            EXPECT_NEAR(r, r0, 1e-12) << "d " << d << " tick " << k;
            // The tangent of a counter-clockwise circle is the radius turned a quarter turn (the
            // offset point lies on the radius through the path's point, at either offset sign).
            const double radial = std::atan2(s.y - center.y, s.x - center.x);
            const double tangent = radial + pi / 2;
            EXPECT_NEAR(std::remainder(s.rotation - tangent, 2.0 * pi), 0.0, 1e-12);
            const Vec2 expected = grape::offset_point(circle, a.progress(), d);
            EXPECT_EQ(s.x, expected.x);
            EXPECT_EQ(s.y, expected.y);
        }
    }
}

TEST(AnimationOffset, ALaneBesideAReparametrizedLine) {
    Engine engine;
    Sprite s;
    const Path road = grape::LinearPath({0, 0}, {0, 256}).reparametrized();
    const Vec2 n = grape::frame(road, 0.5).normal;
    engine.create_2d_animation(s, road, 1.0, {.offset = 4.0});
    for (int k = 0; k < 8; ++k) {
        engine.tick(0.125);
        EXPECT_NEAR(s.x, 4.0 * n.x, 1e-13);  // the lane is straight: x never moves
        EXPECT_NEAR(s.y, 32.0 * (k + 1) + 4.0 * n.y, 256 * 1e-12);  // arc-length: 1e-9·L contract
    }
}

TEST(AnimationRange, RangeAndOffsetTogetherInATimeline) {
    // A child placed at 1 s rests at the start of its range, beside the path, until then.
    Engine engine;
    Sprite s;
    const Path line = grape::LinearPath({0, 0}, {128, 0});
    const Vec2 n = grape::frame(line, 0.0).normal;
    auto tl = engine.create_timeline({});
    tl.add(engine.create_2d_animation(s, line, 1.0, {.range_start = 0.5, .range_end = 1.0, .offset = 2.0}), 1.0);
    engine.tick(0.5);
    EXPECT_EQ(s.x, 64.0 + 2.0 * n.x);
    EXPECT_EQ(s.y, 2.0 * n.y);
    engine.tick(1.0);
    EXPECT_EQ(s.x, 96.0 + 2.0 * n.x);
}

TEST(AnimationRange, DefaultsLeaveThePlainRecordBitForBit) {
    // range [0, 1] and offset 0 keep the record on the engine's fast path: the same numbers as
    // an animation made without them.
    std::mt19937_64 rng(grape::testing::test_seed(9));
    std::uniform_real_distribution<double> unit(0.0, 0.1);
    Engine a, b;
    Sprite sa, sb;
    const Path bezier = grape::CubicBezierPath({0, 0}, {30, 90}, {60, -40}, {100, 10});
    a.create_2d_animation(sa, bezier, 1.3, {.repeat = -1, .yoyo = true});
    b.create_2d_animation(sb, bezier, 1.3, {.repeat = -1, .yoyo = true, .range_start = 0.0, .range_end = 1.0, .offset = 0.0});
    for (int k = 0; k < 200; ++k) {
        const double dt = unit(rng);
        a.tick(dt);
        b.tick(dt);
        ASSERT_EQ(sa.x, sb.x);
        ASSERT_EQ(sa.y, sb.y);
    }
}

TEST(AnimationRange, BadValuesNameTheirField) {
    Engine engine;
    Sprite s;
    const Path line = grape::LinearPath({0, 0}, {1, 0});
    expect_error([&] { engine.create_2d_animation(s, line, 1.0, {.range_start = -0.25}); }, {"range_start", "[0, 1]", "-0.25"});
    expect_error([&] { engine.create_2d_animation(s, line, 1.0, {.range_end = NAN}); }, {"range_end", "nan"});
    expect_error([&] { engine.create_2d_animation(s, line, 1.0, {.range_end = 1.5}); }, {"range_end", "1.5"});
    expect_error([&] { engine.create_2d_animation(s, line, 1.0, {.offset = INFINITY}); }, {"offset", "finite"});
    const std::vector<double> from{0.0}, to{1.0};
    expect_error([&] { engine.create_animation(grape::PathND(from, to), 1.0, {.offset = 1.0}); }, {"offset", "2-D"});
    expect_error([&] { engine.animate(s, &Sprite::x, grape::to(5.0), 1.0, {.range_end = 0.5}); }, {"animate", "range"});
    EXPECT_EQ(engine.size(), 0u);
}

}  // namespace
