// Typed animations against closed forms: every type through one interpolation point (double,
// float, Vec2, colours, angles, user structs), from-current and relative starts captured once
// (exact under seek, reverse and yoyo), the heading's offset, unwrapping and cusps, and the
// engine's small contracts (exact time_scale, pause from on_loop, value() while waiting,
// a float rotation beside double x/y).
#include <grape/anim.hpp>
#include <grape/color.hpp>
#include <grape/timeline.hpp>

#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using grape::Animation;
using grape::Color;
using grape::Curve;
using grape::Engine;
using grape::Vec2;

namespace game {
// A user type with its own lerp, found by argument-dependent lookup.
struct Hsv {
    double h = 0, s = 0, v = 0;
};
Hsv lerp(const Hsv& a, const Hsv& b, double t) noexcept {
    return {a.h + (b.h - a.h) * t, a.s + (b.s - a.s) * t, a.v + (b.v - a.v) * t};
}
Hsv operator+(const Hsv& a, const Hsv& b) noexcept { return {a.h + b.h, a.s + b.s, a.v + b.v}; }

// A type from "someone else's" namespace, taught through the trait.
struct Scale {
    float k = 1.0f;
};
}  // namespace game

template <>
struct grape::Interpolate<game::Scale> {
    static game::Scale lerp(const game::Scale& a, const game::Scale& b, double t) noexcept {
        return {static_cast<float>(a.k * std::pow(static_cast<double>(b.k) / a.k, t))};  // geometric
    }
};

namespace {

struct Thing {
    double value = -1.0;
    float f = -1.0f;
    Vec2 pos{-1, -1};
    Color tint{};
    double angle = 0.0;
    game::Hsv hsv{};
    game::Scale scale{};
};

struct DoubleXYFloatRotation {
    double x = 0, y = 0;
    float rotation = 0.0f;
};

}  // namespace

TEST(TypedValues, EveryTypeFollowsItsLerpOfTheCurve) {
    Engine engine;
    Thing t;
    const Curve curve = Curve::quad_in_out();
    engine.animate(t, &Thing::value, grape::from_to(2.0, 10.0), 1.0, {.curve = curve});
    engine.animate(t, &Thing::f, grape::from_to(1.0f, 3.0f), 1.0, {.curve = curve});
    engine.animate(t, &Thing::pos, grape::from_to(Vec2{0, 0}, Vec2{4, -8}), 1.0, {.curve = curve});
    const Color red = grape::parse_color("#ff0000"), green = grape::parse_color("#00ff00");
    engine.animate(t, &Thing::tint, grape::from_to(red, green), 1.0, {.curve = curve});
    engine.animate(t, &Thing::hsv, grape::from_to(game::Hsv{0, 1, 1}, game::Hsv{120, 0.5, 0}), 1.0, {.curve = curve});
    engine.animate(t, &Thing::scale, grape::from_to(game::Scale{1}, game::Scale{4}), 1.0, {.curve = curve});
    // At creation (no delay) the start is written.
    EXPECT_EQ(t.value, 2.0);
    EXPECT_EQ(t.tint, red);
    for (int k = 1; k <= 8; ++k) {
        engine.tick(0.125);
        const double u = curve(k * 0.125);
        // 1e-15: one lerp of values ~10; the tick's phase sums eighths exactly.
        EXPECT_NEAR(t.value, grape::lerp(2.0, 10.0, u), 1e-14);
        EXPECT_FLOAT_EQ(t.f, static_cast<float>(grape::lerp(1.0, 3.0, u)));
        EXPECT_NEAR(t.pos.x, 4 * u, 1e-15);
        EXPECT_NEAR(t.pos.y, -8 * u, 1e-15);
        EXPECT_EQ(t.tint, grape::mix(red, green, u));
        EXPECT_NEAR(t.hsv.h, 120 * u, 1e-13);
        EXPECT_NEAR(t.hsv.v, 1 - u, 1e-15);
        EXPECT_FLOAT_EQ(t.scale.k, static_cast<float>(std::pow(4.0, u)));
    }
    EXPECT_EQ(t.value, 10.0);  // exact ends
    EXPECT_EQ(t.tint, green);
    EXPECT_EQ(engine.size(), 0u);
}

TEST(TypedValues, ColoursInOklabThroughTheInterpolator) {
    Engine engine;
    Thing t;
    const Color black{0, 0, 0, 1}, white{1, 1, 1, 1};
    Animation a = engine.animate(t, &Thing::tint, grape::from_to(black, white), 2.0, {},
                                 grape::ColorLerp{grape::ColorSpace::oklab});
    engine.tick(1.0);
    EXPECT_EQ(grape::to_hex(t.tint), "#636363");  // L = 0.5 (linear light would give #bcbcbc)
    EXPECT_EQ(a.value(), Vec2{});                  // not a 2-D animation
    a.seek(0.5);
    EXPECT_EQ(t.tint, grape::mix(black, white, 0.25, grape::ColorSpace::oklab));
}

TEST(TypedValues, AnglesTakeTheShortestTurnAcrossPi) {
    const grape::AngleLerp shortest{};
    // From 3 rad to −3 rad: 2π − 6 ≈ 0.283 rad through π, never the long way through 0.
    EXPECT_NEAR(shortest(3.0, -3.0, 0.5), grape::pi, 1e-15);
    EXPECT_NEAR(shortest(3.0, -3.0, 1.0), 2 * grape::pi - 3.0, 1e-15);
    EXPECT_NEAR(shortest(-3.0, 3.0, 0.5), -grape::pi, 1e-15);
    EXPECT_EQ(shortest(0.25, 1.0, 1.0), 1.0);  // within half a turn: b itself
    EXPECT_EQ(grape::AngleLerp{.shortest = false}(3.0, -3.0, 0.5), 0.0);  // the long way
    std::mt19937_64 rng(grape::testing::test_seed(3));
    std::uniform_real_distribution<double> angle(-20.0, 20.0), t(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        const double a = angle(rng), b = angle(rng), s = t(rng);
        const double end = shortest(a, b, 1.0);
        EXPECT_LE(std::abs(end - a), grape::pi + 1e-12);  // at most half a turn
        // 1e-13: remainder is exact; angles up to 20 rad carry 4e-15 of rounding each.
        EXPECT_NEAR(std::remainder(end - b, 2 * grape::pi), 0.0, 1e-13);  // b's direction
        EXPECT_NEAR(shortest(a, b, s), a + (end - a) * s, 1e-13);         // evenly
    }
    Engine engine;
    Thing th;
    th.angle = 3.0;
    engine.animate(th, &Thing::angle, grape::to(-3.0), 1.0, {}, grape::AngleLerp{});
    engine.tick(0.5);
    EXPECT_NEAR(th.angle, grape::pi, 1e-15);
}

TEST(TypedValues, FromCurrentReadsTheMemberWhenTheFirstPlayBegins) {
    Engine engine;
    Thing t;
    t.value = 1.0;
    Animation a = engine.animate(t, &Thing::value, grape::to(11.0), 1.0, {.delay = 0.5});
    t.value = 5.0;  // moved by something else during the delay
    engine.tick(0.25);
    EXPECT_EQ(t.value, 5.0);  // waiting: nothing written, nothing read
    engine.tick(0.5);         // 0.25 s into the play
    EXPECT_DOUBLE_EQ(t.value, 5.0 + 6.0 * 0.25);
    t.value = 100.0;  // read once: a later change does not move the start
    a.seek(0.0);
    EXPECT_EQ(t.value, 5.0);
    a.seek(-0.2);  // back into the delay and out again: still the captured start
    a.seek(0.5);
    EXPECT_DOUBLE_EQ(t.value, 8.0);
    a.seek(1.0);
    EXPECT_EQ(t.value, 11.0);
}

TEST(TypedValues, RelativeMovesByTheAmountOnceUnderYoyoAndReverse) {
    Engine engine;
    Thing t;
    t.value = 5.0;
    Animation a = engine.animate(t, &Thing::value, grape::by(10.0), 1.0, {.repeat = 3, .yoyo = true});
    for (int k = 0; k < 16; ++k) {
        engine.tick(0.25);
        const double phase = std::fmod((k + 1) * 0.25, 2.0);
        const double u = phase <= 1.0 ? phase : 2.0 - phase;  // yoyo: back and forth, never drifting
        EXPECT_NEAR(t.value, 5.0 + 10.0 * u, 1e-14) << k;
    }
    EXPECT_FALSE(a.alive());
    EXPECT_EQ(t.value, 5.0);  // four plays: back where it began

    // Reversed: from start + amount back to the start.
    t.value = 2.0;
    Animation r = engine.animate(t, &Thing::value, grape::by(3.0), 1.0, {.reversed = true});
    EXPECT_EQ(t.value, 5.0);
    engine.tick(0.5);
    EXPECT_DOUBLE_EQ(t.value, 3.5);
    r.seek(1.0);
    EXPECT_EQ(t.value, 2.0);
    // User types with + work relatively too.
    t.hsv = {10, 0, 0};
    engine.animate(t, &Thing::hsv, grape::by(game::Hsv{20, 0, 0}), 1.0);
    engine.tick(1.0);
    EXPECT_EQ(t.hsv.h, 30.0);
    grape::testing::expect_error([&] { engine.animate(t, &Thing::scale, grape::by(game::Scale{2}), 1.0); },
                                 {"animate", "grape::by needs a type with +"});
}

TEST(TypedValues, FromCurrentInASequenceStartsWhereThePreviousOneLeft) {
    // A queue: the second starts (after its delay) from wherever the first ended, the third
    // from where the second did: ends 10, then 10 + 5, then 15 + 5. (Starts that coincide with
    // the previous end to the tick would depend on the order the engine visits its records.)
    Engine engine;
    Thing t;
    t.value = 0.0;
    engine.animate(t, &Thing::value, grape::to(10.0), 1.0);
    engine.animate(t, &Thing::value, grape::by(5.0), 1.0, {.delay = 1.1});
    engine.animate(t, &Thing::value, grape::by(5.0), 0.5, {.delay = 2.2});
    for (int k = 0; k < 60; ++k) engine.tick(0.05);  // 3 s
    EXPECT_NEAR(t.value, 20.0, 1e-12);
    EXPECT_EQ(engine.size(), 0u);
}

TEST(TypedValues, FromCurrentAndRelativeInATimelineStartWhereThePreviousChildLeft) {
    // A sequence in a timeline: to(10) from 0, then by(+5), then to(-1); each placed at the
    // previous end (">"), so each captures the member the previous child left: 10, 15, then
    // back to -1. Exact values at play boundaries: linear curves, durations of 1 s and 0.5 s
    // and ticks of 1/8 s are all dyadic, so every product and sum here is exact.
    Engine engine;
    Thing t;
    t.value = 0.0;
    grape::Timeline line = engine.create_timeline();
    line.add(engine.animate(t, &Thing::value, grape::to(10.0), 1.0))
        .add(engine.animate(t, &Thing::value, grape::by(5.0), 1.0), ">")
        .add(engine.animate(t, &Thing::value, grape::to(-1.0), 0.5), ">");
    EXPECT_EQ(line.duration(), 2.5);
    for (int k = 0; k < 8; ++k) engine.tick(0.125);  // 1 s: the first child has ended at 10
    EXPECT_EQ(t.value, 10.0);
    for (int k = 0; k < 4; ++k) engine.tick(0.125);  // halfway through by(5)
    EXPECT_EQ(t.value, 12.5);
    for (int k = 0; k < 4; ++k) engine.tick(0.125);  // 2 s: by(5) ended at 15
    EXPECT_EQ(t.value, 15.0);
    engine.tick(0.25);                                // halfway from 15 to -1
    EXPECT_EQ(t.value, 7.0);
    engine.tick(0.25);
    EXPECT_EQ(t.value, -1.0);
}

TEST(TypedValues, BadArgumentsAreNamed) {
    Engine engine;
    Thing t;
    grape::testing::expect_error([&] { engine.animate(t, &Thing::value, grape::to(1.0), -1.0); },
                                 {"animate", "duration must be positive"});
    auto gone = std::shared_ptr<Thing>();
    grape::testing::expect_error([&] { engine.animate(gone, &Thing::value, grape::to(1.0), 1.0); },
                                 {"animate", "gone"});
}

// --- heading -----------------------------------------------------------------------------------

TEST(Heading, ContinuousOnASpinningCircleGrowsLinearly) {
    // Three turns counter-clockwise (in y-up terms): heading = π/2 + 6π·t, never wrapped.
    Engine engine;
    const grape::CirclePath circle({0, 0}, 1.0, 0.0, 6 * grape::pi);
    struct Ship {
        double x = 0, y = 0, rotation = 0;
    } ship;
    engine.create_2d_animation(ship, circle, 1.0, {.heading = true, .heading_continuous = true});
    double last = ship.rotation;
    EXPECT_NEAR(ship.rotation, grape::pi / 2, 1e-15);
    for (int k = 1; k <= 64; ++k) {
        engine.tick(1.0 / 64);
        // 1e-12: atan2 of the analytic derivative, unwrapped by whole turns of ~20 rad.
        EXPECT_NEAR(ship.rotation, grape::pi / 2 + 6 * grape::pi * k / 64.0, 1e-12) << k;
        EXPECT_GT(ship.rotation, last);
        last = ship.rotation;
    }
    // Wrapped (the default) it stays in (−π, π].
    Ship other;
    engine.create_2d_animation(other, circle, 1.0, {.heading = true});
    engine.tick(0.5);
    EXPECT_LE(std::abs(other.rotation), grape::pi);
}

TEST(Heading, OffsetTurnsTheWrittenHeading) {
    Engine engine;
    const grape::LinearPath line({0, 0}, {0, 10});  // along +y: atan2 = π/2
    struct Ship {
        double x = 0, y = 0, rotation = 0;
    } ship;
    Animation a = engine.create_2d_animation(ship, line, 1.0, {.heading = true, .heading_offset = -grape::pi / 2});
    engine.tick(0.5);
    EXPECT_NEAR(ship.rotation, 0.0, 1e-15);
    EXPECT_NEAR(a.heading(), 0.0, 1e-15);
    // Backwards with an offset: π/2 + π − π/2 = π, wrapped into (−π, π].
    Ship back;
    engine.create_2d_animation(back, line, 1.0, {.reversed = true, .heading = true, .heading_offset = -grape::pi / 2});
    engine.tick(0.25);
    EXPECT_NEAR(std::abs(back.rotation), grape::pi, 1e-15);
}

TEST(Heading, KeepsTheLastHeadingThroughACusp) {
    // B(u) from (0,0) with controls (1,1), (0,1) to (1,0): d1(1/2) = 0 exactly, a cusp.
    const grape::CubicBezierPath cusp({0, 0}, {1, 1}, {0, 1}, {1, 0});
    ASSERT_EQ(cusp.d1(0.5), Vec2{});
    Engine engine;
    struct Ship {
        double x = 0, y = 0, rotation = 0;
    } ship;
    Animation a = engine.create_2d_animation(ship, cusp, 1.0, {.heading = true});
    engine.tick(0.25);
    const Vec2 d = cusp.d1(0.25);
    const double before = std::atan2(d.y, d.x);
    EXPECT_NEAR(ship.rotation, before, 1e-15);
    engine.tick(0.25);  // exactly on the cusp: the heading it came in with, not atan2(0, 0) = 0
    EXPECT_EQ(ship.rotation, before);
    EXPECT_EQ(a.heading(), before);
    engine.tick(0.25);  // past it: the path's own direction again
    const Vec2 d3 = cusp.d1(0.75);
    EXPECT_NEAR(ship.rotation, std::atan2(d3.y, d3.x), 1e-15);
    // Starting on a cusp (P0 = P1: d1(0) = 0): the direction leaving it, along d2(0) = 6·(1, 1).
    const grape::CubicBezierPath starts({0, 0}, {0, 0}, {1, 1}, {2, 0});
    ASSERT_EQ(starts.d1(0.0), Vec2{});
    Ship start;
    engine.create_2d_animation(start, starts, 1.0, {.heading = true});
    EXPECT_NEAR(start.rotation, grape::pi / 4, 1e-15);
}

// --- small contracts ---------------------------------------------------------------------------

TEST(EngineContracts, TimeScaleReadsBackExactlyAsSet) {
    Engine engine;
    const grape::LinearPath line({0, 0}, {1, 0});
    EXPECT_EQ(engine.create_animation(line, 0.09).time_scale(), 1.0);  // rate·duration: 0.99999999999999989
    std::mt19937_64 rng(grape::testing::test_seed(5));
    std::uniform_real_distribution<double> duration(0.01, 10.0), scale(0.0, 4.0);
    int inexact = 0;
    for (int i = 0; i < 2000; ++i) {
        const double d = duration(rng), s = i % 3 == 0 ? 1.0 : scale(rng);
        Animation a = engine.create_animation(line, d, {.time_scale = s});
        if ((s / d) * d != s) ++inexact;
        EXPECT_EQ(a.time_scale(), s) << d << " " << s;
        const double s2 = scale(rng);
        a.set_time_scale(s2);
        EXPECT_EQ(a.time_scale(), s2);
    }
    EXPECT_GT(inexact, 100);  // the case that used to read back an ulp off is common
    // Tiny scales whose rate underflows toward subnormals still read back.
    Animation tiny = engine.create_animation(line, 1e10, {.time_scale = 1e-300});
    EXPECT_EQ(tiny.time_scale(), 1e-300);
}

TEST(EngineContracts, PauseInOnLoopStopsTheTicksAdvance) {
    Engine engine;
    const grape::LinearPath line({0, 0}, {1, 0});
    Animation a = engine.create_animation(line, 0.25, {.repeat = 10});
    std::vector<int> loops;
    a.on_loop([&](int play) {
        loops.push_back(play);
        if (play == 2) a.pause();
    });
    engine.tick(1.6);  // crosses the starts of plays 1 to 6
    EXPECT_EQ(loops, (std::vector<int>{1, 2}));
    EXPECT_TRUE(a.paused());
    EXPECT_EQ(a.time(), 0.5);  // held where play 2 began
    EXPECT_EQ(a.repetition(), 2);
    EXPECT_EQ(a.value(), Vec2{});
    engine.tick(1.0);
    EXPECT_EQ(a.time(), 0.5);
    a.resume();
    engine.tick(0.3);  // to 0.8: play 3 begins at 0.75
    EXPECT_EQ(loops, (std::vector<int>{1, 2, 3}));
    EXPECT_NEAR(a.time(), 0.8, 1e-15);
}

TEST(EngineContracts, ValueWhileWaitingIsWhereTheFirstPlayStarts) {
    Engine engine;
    const grape::LinearPath line({1, 2}, {5, 6});
    EXPECT_EQ(engine.create_animation(line, 1.0, {.delay = 1.0}).value(), (Vec2{1, 2}));
    Animation r = engine.create_animation(line, 1.0, {.delay = 1.0, .reversed = true});
    EXPECT_TRUE(r.waiting());
    EXPECT_EQ(r.value(), (Vec2{5, 6}));  // a reversed play starts at the path's end
}

TEST(EngineContracts, HeadingReachesAFloatRotationBesideDoubleXY) {
    Engine engine;
    const grape::LinearPath line({0, 0}, {0, 10});
    DoubleXYFloatRotation s;
    engine.create_2d_animation(s, line, 1.0, {.heading = true});
    engine.tick(0.5);
    EXPECT_EQ(s.y, 5.0);
    EXPECT_EQ(s.rotation, static_cast<float>(grape::pi / 2));
}
