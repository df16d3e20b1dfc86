// The engine against independent truth: states computed straight from the path and curve,
// tick-versus-seek equality over random dt sequences, event counts, handle inertness, safety
// of handlers that change the engine mid-tick (run this file under AddressSanitizer too), and
// zero allocations per tick counted by a global operator new hook.
#include <grape/anim.hpp>
#include <grape/error.hpp>

#include "seed_animations.hpp"
#include "seed_paths.hpp"

#include "anim/engine_impl.hpp"  // the test hook for generations

#include "count_allocations.hpp"
#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <random>
#include <string>
#include <vector>

using grape::Animation;
using grape::AnimationDef;
using grape::Curve;
using grape::Engine;
using grape::Vec2;

namespace {

struct Point {
    double x = -999.0;  // sentinel: "never written"
    double y = -999.0;
};

struct FloatPoint {
    float x = 0.0f;
    float y = 0.0f;
};

// A unit-sized cubic Bézier, so absolute position errors read as relative ones.
grape::CubicBezierPath unit_bezier(bool reparametrize = false) {
    return grape::CubicBezierPath({0, 0}, {0, 1}, {1, 1}, {1, 0}, reparametrize);
}

// The state an animation must show at local time t (seconds since its first play began),
// computed from the definition without the engine: which play, which direction, the curve,
// the path.
Vec2 expected_state(const grape::Path& path, double duration, const AnimationDef& def, double t) {
    const double total = def.repeat < 0 ? INFINITY : duration * (def.repeat + 1);
    int play;
    double x;
    if (t >= total) {
        play = def.repeat;
        x = 1.0;
    } else {
        play = static_cast<int>(std::floor(t / duration));
        x = t / duration - play;
    }
    const bool backward = def.reversed != (def.yoyo && play % 2 == 1);
    return path.point(def.curve(backward ? 1.0 - x : x));
}

using grape::testing::error_text;

}  // namespace

TEST(Engine, PlainStructsFollowThePathAndCompleteOnce) {
    Engine engine;
    Point p;
    const grape::LinearPath line({0, 0}, {10, 20});
    int completes = 0;
    Animation a = engine.create_2d_animation(p, line, 2.0);
    a.on_complete([&] { ++completes; });
    // No delay: the start state is written at creation.
    EXPECT_EQ(p.x, 0.0);
    EXPECT_EQ(p.y, 0.0);
    engine.tick(0.5);
    EXPECT_NEAR(p.x, 2.5, 1e-15);  // 10·(0.5/2)
    EXPECT_NEAR(p.y, 5.0, 1e-15);
    engine.tick(1.5);
    EXPECT_EQ(p.x, 10.0);
    EXPECT_EQ(p.y, 20.0);
    EXPECT_EQ(completes, 1);
    EXPECT_FALSE(a.alive());
    engine.tick(1.0);
    EXPECT_EQ(completes, 1);
    EXPECT_EQ(engine.size(), 0u);
}

TEST(Engine, FloatMembersAndValueQueries) {
    Engine engine;
    FloatPoint p;
    const auto bez = unit_bezier();
    Animation a = engine.create_2d_animation(p, bez, 1.0, {.curve = Curve::quad_in_out()});
    engine.tick(0.3);
    const Vec2 truth = bez.point(grape::ease::quad_in_out(0.3));
    EXPECT_EQ(p.x, static_cast<float>(truth.x));
    EXPECT_EQ(p.y, static_cast<float>(truth.y));
    EXPECT_TRUE(grape::approx_equal(a.value(), truth, 1e-15));
    EXPECT_NEAR(a.progress(), grape::ease::quad_in_out(0.3), 1e-15);
    EXPECT_NEAR(a.time(), 0.3, 1e-15);
    EXPECT_EQ(a.duration(), 1.0);
}

TEST(Engine, TickingAnyDtSequenceEqualsSeek) {
    // Every combination of repeat, yoyo, reversed, delay and time scale, with curves that
    // are asymmetric (so a wrong direction shows) and overshooting.
    std::mt19937_64 rng(grape::testing::test_seed(42));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto bez = unit_bezier();
    const Curve curves[] = {Curve::quad_out(), grape::parse_curve("back-in-out"), grape::parse_curve("ease")};
    int cases = 0;
    for (int repeat : {0, 2, -1})
        for (bool yoyo : {false, true})
            for (bool reversed : {false, true})
                for (double delay : {0.0, 0.7})
                    for (double scale : {1.0, 2.5})
                        for (const Curve& curve : curves) {
                            const AnimationDef def{.curve = curve, .delay = delay, .repeat = repeat,
                                                   .reversed = reversed, .yoyo = yoyo, .time_scale = scale};
                            const double duration = 0.9;
                            Engine ticked, sought;
                            Point a, b;
                            Animation ta = ticked.create_2d_animation(a, bez, duration, def);
                            Animation sb = sought.create_2d_animation(b, bez, duration, def);
                            double total = 0.0;
                            const int steps = 1 + static_cast<int>(unit(rng) * 300);
                            for (int k = 0; k < steps; ++k) {
                                const double dt = unit(rng) * unit(rng) * 0.05;
                                ticked.tick(dt);
                                total += dt;
                            }
                            const double local = total * scale - delay;
                            sb.seek(local);
                            ++cases;
                            if (local < 0.0) {
                                EXPECT_EQ(a.x, -999.0);  // still waiting: nothing written
                                EXPECT_TRUE(ta.waiting());
                                continue;
                            }
                            // Unit-sized path, O(300) additions of times ≤ 0.05 whose rounding
                            // is ≤ 1e-17 each, times path speed ≤ 3 and curve slope ≤ 4:
                            // well under 1e-12.
                            EXPECT_NEAR(a.x, b.x, 1e-12) << to_string(curve) << " r" << repeat << " y" << yoyo << " rev" << reversed;
                            EXPECT_NEAR(a.y, b.y, 1e-12);
                            if (ta.alive()) {
                                const Vec2 truth = expected_state(bez, duration, def, local);
                                EXPECT_NEAR(a.x, truth.x, 1e-12);
                                EXPECT_NEAR(a.y, truth.y, 1e-12);
                            }
                        }
    EXPECT_EQ(cases, 3 * 2 * 2 * 2 * 2 * 3);
}

TEST(Engine, EveryCurveKindPlaysItsOwnFormula) {
    // Each named curve and a few with parameters, ticked and sought, against the path at
    // the curve's own value. Nine sums of 0.1 differ from 0.1·i by a few ulp; the steepest
    // curve here (elastic, slope < 30) on a path of speed ≤ 3 turns that into < 1e-13.
    std::vector<Curve> curves;
    for (std::string_view name : grape::curve_names()) curves.push_back(grape::parse_curve(name));
    for (const char* name : {"back-out(2.5)", "elastic-in(1.5,0.4)", "ease", "steps(4,jump-both)", "monotone(0,0,0.3,0.8,1,1)"})
        curves.push_back(grape::parse_curve(name));
    const auto bez = unit_bezier();
    for (const Curve& curve : curves) {
        Engine engine;
        Point p;
        Animation a = engine.create_2d_animation(p, bez, 1.0, {.curve = curve, .repeat = -1});
        for (int i = 1; i <= 9; ++i) {
            engine.tick(0.1);
            const Vec2 truth = bez.point(curve(0.1 * i));
            ASSERT_NEAR(p.x, truth.x, 1e-12) << to_string(curve) << " t = " << 0.1 * i;
            ASSERT_NEAR(p.y, truth.y, 1e-12) << to_string(curve);
        }
        a.seek(0.35);
        EXPECT_NEAR(a.value().x, bez.point(curve(0.35)).x, 1e-12) << to_string(curve);
    }
}

TEST(Engine, SixtyFramesOfOneSixtiethFinishAOneSecondPlayExactlyOnce) {
    // 60 × (1/60) sums to 1 − 1.1e-16 in doubles; the play must still end on that frame.
    for (int steps : {1, 60, 1000, 10000}) {
        Engine engine;
        Point p;
        int completes = 0;
        engine.create_2d_animation(p, grape::LinearPath({0, 0}, {1, 0}), 1.0).on_complete([&] { ++completes; });
        for (int i = 0; i < steps; ++i) engine.tick(1.0 / steps);
        EXPECT_EQ(completes, 1) << steps;
        EXPECT_EQ(p.x, 1.0) << steps;
    }
}

TEST(Engine, ArcLengthBezierMatchesThePathWithinItsTolerance) {
    // Cubic A of the reference set: length 200 exactly. The engine evaluates arc-length
    // paths from its own table of the source parameter, checked at build time to 1e-10·L;
    // between the checked points the interpolant's error stays of the same size: 2e-10·L.
    const grape::CubicBezierPath rep({0, 0}, {0, 100}, {100, 100}, {100, 0}, true);
    const double tolerance = 2e-10 * 200.0;
    Engine engine;
    Point p;
    engine.create_2d_animation(p, rep, 1.0, {.repeat = -1});
    std::mt19937_64 rng(grape::testing::test_seed(5));
    std::uniform_real_distribution<double> unit(0.0, 0.01);
    double t = 0.0;
    for (int i = 0; i < 2000; ++i) {
        const double dt = unit(rng);
        engine.tick(dt);
        t += dt;
        const double u = t - std::floor(t);
        if (u < 1e-6 || u > 1 - 1e-6) continue;  // at a play boundary the two sides differ
        const Vec2 truth = rep.point(u);
        ASSERT_NEAR(p.x, truth.x, tolerance + 1e-12) << u;
        ASSERT_NEAR(p.y, truth.y, tolerance + 1e-12) << u;
    }
    // A quarter of the length is at (10.589254, 48.352395) (closed-form reference).
    Animation a = engine.create_animation(rep, 1.0);
    a.seek(0.25);
    EXPECT_NEAR(a.value().x, 10.589254, 1e-6);
    EXPECT_NEAR(a.value().y, 48.352395, 1e-6);
}

TEST(Engine, ManyArcLengthAnimationsAtSpreadPhasesMatchTheirPaths) {
    // The tick advances records in batches and reads each arc-length path's table piece
    // found ahead of the write; here arc-length, plain cubic and linear paths alternate,
    // phases are spread, curves differ (formulas, one with parameters), and every fifth
    // animation takes the general path each play (loop handlers) or sits paused, so batches
    // stop anywhere. Each target against Path::point at the animation's own progress:
    // 2e-10·L for arc length (the table's contract), equal for cubics, rounding for lines.
    std::mt19937_64 rng(grape::testing::test_seed(17));
    std::uniform_real_distribution<double> coordinate(0.0, 1000.0), unit(0.0, 1.0);
    std::vector<grape::Path> paths;
    for (int k = 0; k < 48; ++k) {
        const Vec2 a{coordinate(rng), coordinate(rng)}, d{coordinate(rng), coordinate(rng)};
        const Vec2 side = grape::perpendicular(d - a) * (0.2 + 0.3 * unit(rng));
        const Vec2 b = a + (d - a) / 3.0 + side, c = a + (d - a) * (2.0 / 3.0) - side;
        if (k % 3 == 2) paths.push_back(grape::LinearPath(a, d));
        else paths.push_back(grape::CubicBezierPath(a, b, c, d, k % 3 == 0));
    }
    const Curve curves[] = {Curve::quad_in_out(), Curve::linear(), grape::parse_curve("back-in-out"),
                            grape::parse_curve("cubic-bezier(0.3, 0.1, 0.2, 1)")};
    constexpr int count = 700;
    std::vector<Point> targets(count);
    std::vector<Animation> anims;
    int loops = 0;
    Engine engine;
    for (int i = 0; i < count; ++i) {
        const AnimationDef def{.curve = curves[i % 4], .delay = i % 7 == 3 ? 0.5 : 0.0, .repeat = -1, .yoyo = i % 2 == 0};
        anims.push_back(engine.create_2d_animation(targets[i], paths[i % paths.size()], 0.5 + 2.0 * unit(rng), def));
        if (i % 5 == 1) anims.back().on_loop([&loops](int, std::uint64_t) { ++loops; });
    }
    engine.tick(123.456);  // spread the phases
    for (int i = 4; i < count; i += 10) anims[i].pause();
    int arc_checked = 0;
    for (int frame = 0; frame < 120; ++frame) {
        engine.tick(0.04 * unit(rng));
        for (int i = 0; i < count; ++i) {
            const grape::Path& path = paths[i % paths.size()];
            const Vec2 truth = path.point(anims[i].progress());
            const Vec2 got{targets[i].x, targets[i].y};
            if (path.kind() == grape::PathKind::reparametrized) {
                ASSERT_LE(grape::distance(got, truth), 2e-10 * path.length()) << i << " frame " << frame;
                ++arc_checked;
            } else if (path.kind() == grape::PathKind::cubic_bezier) {
                ASSERT_EQ(got.x, truth.x) << i << " frame " << frame;
                ASSERT_EQ(got.y, truth.y) << i << " frame " << frame;
            } else {  // a + (b − a)·u against lerp's a·(1 − u) + b·u: 2e-12, 4 ulps of 2000
                ASSERT_NEAR(got.x, truth.x, 2e-12) << i << " frame " << frame;
                ASSERT_NEAR(got.y, truth.y, 2e-12) << i << " frame " << frame;
            }
        }
    }
    EXPECT_GT(loops, 100);                  // the general path ran between the batches
    EXPECT_GT(arc_checked, 120 * count / 4);  // a third of the paths are arc-length ones
}

TEST(Engine, ReversedPlaysTheSameStatesBackwards) {
    const auto bez = unit_bezier();
    const Curve curve = grape::parse_curve("cubic-in");
    Engine engine;
    Point fwd, back;
    engine.create_2d_animation(fwd, bez, 2.0, {.curve = curve});
    Animation r = engine.create_2d_animation(back, bez, 2.0, {.curve = curve, .reversed = true});
    for (int i = 1; i < 20; ++i) {
        const double t = 0.1 * i;
        r.seek(2.0 - t);
        engine.tick(0.0);
        Engine other;
        Point f;
        other.create_2d_animation(f, bez, 2.0, {.curve = curve}).seek(t);
        EXPECT_NEAR(back.x, f.x, 1e-15);
        EXPECT_NEAR(back.y, f.y, 1e-15);
    }
}

// Running back with reverse(): on_reverse_complete fires once at the first play's start, also
// when a tick lands exactly on it (0.5 s forward, then 0.25 + 0.25 s back: both exact in
// binary), and again after running forward and back a second time.
TEST(Engine, ReverseCompleteFiresWhenATickLandsExactlyOnTheStart) {
    const auto bez = unit_bezier();
    Engine engine;
    Point p;
    int back = 0;
    Animation a = engine.create_2d_animation(p, bez, 1.0);
    a.on_reverse_complete([&] { ++back; });
    engine.tick(0.5);
    a.reverse();
    engine.tick(0.25);
    EXPECT_EQ(back, 0);
    engine.tick(0.25);
    EXPECT_EQ(back, 1);
    EXPECT_EQ(p.x, bez.point(0.0).x);
    EXPECT_EQ(p.y, bez.point(0.0).y);
    engine.tick(0.25);  // held at the start: no second event
    EXPECT_EQ(back, 1);
    EXPECT_TRUE(a.alive());
    a.play();
    engine.tick(0.5);
    a.reverse();
    engine.tick(0.125);
    engine.tick(0.375);
    EXPECT_EQ(back, 2);

    // Many alike records go through the engine's lean runs (four at a time where the CPU has
    // the lanes): each fires once all the same.
    Engine many;
    std::vector<Point> points(600);  // more than the lanes look ahead (hot_ahead, 256)
    std::vector<int> fired(points.size(), 0);
    std::vector<Animation> all;
    for (std::size_t i = 0; i < points.size(); ++i) {
        all.push_back(many.create_2d_animation(points[i], bez, 1.0));
        all.back().on_reverse_complete([&fired, i] { ++fired[i]; });
    }
    many.tick(0.5);
    for (const Animation& r : all) r.reverse();
    many.tick(0.25);
    many.tick(0.25);
    many.tick(0.25);
    for (std::size_t i = 0; i < points.size(); ++i) {
        EXPECT_EQ(fired[i], 1) << i;
        EXPECT_EQ(points[i].x, bez.point(0.0).x) << i;
    }
}

TEST(Engine, YoyoAndLoopsAcrossOneLargeTick) {
    const auto bez = unit_bezier();
    Engine engine;
    Point p, q;
    // Three plays with yoyo at 1.25·D equal the state at 0.75·D (second leg runs backwards).
    engine.create_2d_animation(p, bez, 1.0, {.curve = Curve::quad_out(), .repeat = 2, .yoyo = true});
    engine.create_2d_animation(q, bez, 1.0, {.curve = Curve::quad_out()});
    engine.tick(0.75);
    const Point at_075 = q;
    engine.tick(0.5);
    EXPECT_NEAR(p.x, at_075.x, 1e-15);
    EXPECT_NEAR(p.y, at_075.y, 1e-15);

    // One tick of 3.5·D on an endless yoyo: loop events 1, 2, 3 in order, then it sits half
    // way through a backward leg.
    Engine e2;
    Point s;
    std::vector<int> loops;
    Animation a = e2.create_2d_animation(s, bez, 2.0, {.repeat = -1, .yoyo = true});
    a.on_loop([&](int play) { loops.push_back(play); });
    e2.tick(7.0);
    EXPECT_EQ(loops, (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(a.repetition(), 3);
    EXPECT_NEAR(a.progress(), 0.5, 1e-15);
    EXPECT_NEAR(a.time(), 7.0, 1e-15);
}

TEST(Engine, RepeatNMeansNPlusOnePlaysNLoopsOneComplete) {
    Engine engine;
    Point p;
    int loops = 0, completes = 0;
    Animation a = engine.create_2d_animation(p, grape::LinearPath({0, 0}, {1, 0}), 0.1, {.repeat = 4});
    a.on_loop([&](int) { ++loops; });
    a.on_complete([&] { ++completes; });
    for (int i = 0; i < 100; ++i) engine.tick(1.0 / 60.0);
    EXPECT_EQ(loops, 4);
    EXPECT_EQ(completes, 1);
    EXPECT_EQ(p.x, 1.0);  // ends on the end state of the last play
    // One tick across all of it fires every loop too.
    Engine e2;
    loops = completes = 0;
    Animation b = e2.create_2d_animation(p, grape::LinearPath({0, 0}, {1, 0}), 0.1, {.repeat = 4});
    b.on_loop([&](int) { ++loops; });
    b.on_complete([&] { ++completes; });
    e2.tick(100.0);
    EXPECT_EQ(loops, 4);
    EXPECT_EQ(completes, 1);
}

TEST(Engine, DelayWritesNothingUntilTheFirstPlayStarts) {
    Engine engine;
    Point p;
    const grape::LinearPath line({5, 5}, {15, 5});
    Animation a = engine.create_2d_animation(p, line, 1.0, {.delay = 0.5});
    EXPECT_TRUE(a.waiting());
    EXPECT_EQ(a.value(), (Vec2{5, 5}));  // its state is the start state, readable
    engine.tick(0.3);
    EXPECT_EQ(p.x, -999.0);  // the target is untouched while waiting
    EXPECT_NEAR(a.time(), -0.2, 1e-15);
    engine.tick(0.3);
    EXPECT_FALSE(a.waiting());
    EXPECT_NEAR(p.x, 6.0, 1e-14);  // 0.1 s into the play
    // The delay is applied once, not per loop.
    Engine e2;
    Point q;
    Animation b = e2.create_2d_animation(q, line, 1.0, {.delay = 0.5, .repeat = 1});
    e2.tick(1.75);
    EXPECT_EQ(b.repetition(), 1);
    EXPECT_NEAR(q.x, 7.5, 1e-14);
}

TEST(Engine, OvershootingCurvesRunPastTheEndsAlongTheTangents) {
    const auto bez = unit_bezier();  // ends at (1, 0) heading straight down (+y is d1(1)·−1...)
    Engine engine;
    Point p;
    const Curve back = Curve::back(grape::EaseDirection::out);
    engine.create_2d_animation(p, bez, 1.0, {.curve = back});
    double furthest = 0.0;
    for (int i = 0; i < 100; ++i) {
        engine.tick(0.01);
        const double progress = back(0.01 * (i + 1));
        if (progress > 1.0) {
            // Past the end: on the tangent line through point(1), by (progress − 1)·d1(1).
            const Vec2 end = bez.point(1.0);
            const Vec2 tangent = bez.d1(1.0);
            const Vec2 expected = end + tangent * (progress - 1.0);
            EXPECT_NEAR(p.x, expected.x, 1e-12);
            EXPECT_NEAR(p.y, expected.y, 1e-12);
            furthest = std::max(furthest, grape::distance(Vec2{p.x, p.y}, end));
        }
    }
    // back-out peaks 10 % past the end; d1(1) = 3·(p3 − p2) has length 3.
    EXPECT_GT(furthest, 0.25);
}

TEST(Engine, HandlesGoInertAndStayInert) {
    Engine engine;
    Point p;
    Animation a = engine.create_2d_animation(p, grape::LinearPath({0, 0}, {1, 1}), 1.0);
    Animation copy = a;
    a.kill();
    EXPECT_FALSE(copy.alive());
    EXPECT_EQ(copy.value(), Vec2{});
    copy.pause();
    copy.seek(0.5);
    copy.kill();
    copy.on_complete([] { FAIL(); });
    // The slot is reused by the next animation; the old handle must not reach it.
    Point q;
    Animation b = engine.create_2d_animation(q, grape::LinearPath({0, 0}, {2, 2}), 1.0);
    EXPECT_TRUE(b.alive());
    EXPECT_FALSE(a.alive());
    a.pause();
    engine.tick(0.5);
    EXPECT_FALSE(b.paused());
    EXPECT_NEAR(q.x, 1.0, 1e-15);
    EXPECT_FALSE(Animation().alive());
    Animation().kill();  // a default handle is inert too
}

// Generations never wrap: a slot whose generation reaches 2³² − 1 is retired instead of reused,
// so a handle from any earlier life of it stays inert for good. The hook sets one slot's
// generation to the last but one, where the next kill takes it to the last: without the
// retirement the slot's next life would have that generation, the kill after it would wrap it
// to 0, and the slot's first handle (generation 0) would name its third life.
TEST(Engine, AStaleHandleStaysInertWhereItsSlotsGenerationWouldWrap) {
    using grape::detail::EngineImpl;
    Engine engine;
    const grape::LinearPath line({0, 0}, {1, 0});
    Point a, b, c;
    const Animation first = engine.create_2d_animation(a, line, 1.0);
    const std::uint32_t slot = EngineImpl::slot_for_test(first);
    const Animation late = EngineImpl::with_generation_for_test(first, grape::detail::last_generation - 1);
    EXPECT_FALSE(first.alive());  // a different generation: the first handle is stale already
    EXPECT_TRUE(late.alive());
    late.kill();  // generation 2³² − 1: the slot retires
    EXPECT_FALSE(late.alive());
    for (int round = 0; round < 3; ++round) {
        const Animation next = engine.create_2d_animation(b, line, 1.0);
        EXPECT_NE(EngineImpl::slot_for_test(next), slot) << round;
        EXPECT_FALSE(first.alive()) << round;  // would name the slot's life after the wrap
        next.kill();
    }
    const Animation kept = engine.create_2d_animation(c, line, 1.0);
    EXPECT_NE(EngineImpl::slot_for_test(kept), slot);
    EXPECT_FALSE(first.alive());
    EXPECT_FALSE(late.alive());
    first.kill();  // inert: kills nothing
    first.seek(0.5);
    EXPECT_TRUE(kept.alive());
    engine.tick(0.25);
    EXPECT_EQ(c.x, 0.25);
    EXPECT_EQ(engine.size(), 1u);
}

TEST(Engine, PauseResumeAndTimeScale) {
    Engine engine;
    Point p;
    const grape::LinearPath line({0, 0}, {8, 0});
    Animation a = engine.create_2d_animation(p, line, 4.0, {.time_scale = 2.0});
    engine.tick(1.0);
    EXPECT_NEAR(p.x, 4.0, 1e-15);
    a.pause();
    engine.tick(1.0);
    EXPECT_NEAR(p.x, 4.0, 1e-15);
    a.resume();
    a.set_time_scale(0.5);
    engine.tick(2.0);
    EXPECT_NEAR(p.x, 6.0, 1e-15);
    EXPECT_NEAR(a.time_scale(), 0.5, 1e-15);
}

TEST(Engine, PropertyAnimationsDriveAnyFloatOrDoubleMembers) {
    struct Widget {
        double alpha = 0;
        float scale = 0;
        int unrelated = 7;
        double width = 0;
    } w;
    Engine engine;
    Animation a = engine.create_property_animation(w, {&Widget::alpha, &Widget::scale, &Widget::width}, {0, 1, 100},
                                                   {1, 3, 200}, 2.0, {.curve = Curve::quad_in()});
    engine.tick(1.0);
    EXPECT_NEAR(w.alpha, 0.25, 1e-15);
    EXPECT_EQ(w.scale, 1.5f);
    EXPECT_NEAR(w.width, 125.0, 1e-13);
    EXPECT_EQ(w.unrelated, 7);
    ASSERT_EQ(a.values().size(), 3u);
    EXPECT_NEAR(a.values()[2], 125.0, 1e-13);
    EXPECT_NE(error_text([&] { engine.create_property_animation(w, {&Widget::alpha}, {0, 1}, {1, 2}, 1.0); })
                  .find("members and values must match (1 members, 2 values)"),
              std::string::npos);
}

TEST(Engine, NumberAnimationsReportTheirValuesToACallback) {
    Engine engine;
    std::vector<double> last;
    const grape::PathND keys(2, std::vector<double>{0, 10, 1, 20, 3, 40});  // two keyframe segments
    Animation a = engine.create_animation(keys, 2.0, {.delay = 0.5}, [&](std::span<const double> v) {
        last.assign(v.begin(), v.end());
    });
    ASSERT_EQ(a.values().size(), 2u);
    EXPECT_EQ(a.values()[0], 0.0);  // the start values, readable while waiting
    engine.tick(0.25);
    EXPECT_TRUE(last.empty());      // nothing delivered during the delay
    engine.tick(1.75);              // 1.5 s into the play: u = 0.75, half way through segment 2
    ASSERT_EQ(last.size(), 2u);
    EXPECT_NEAR(last[0], 2.0, 1e-14);
    EXPECT_NEAR(last[1], 30.0, 1e-13);
    EXPECT_EQ(a.value(), Vec2{});   // not a 2-D animation
}

TEST(Engine, NumberAnimationsFollowASplinePathND) {
    // A uniform Catmull–Rom PathND through three keyframes: at u = ½ the middle keyframe
    // exactly, at u = ¼ the Hermite midpoint (p0 + p1)/2 + (m0 − m1)/8 with the tangents
    // m0 = p1 − p0 (mirrored end) and m1 = (p2 − p0)/2.
    Engine engine;
    std::vector<double> last;
    const std::vector<double> k{0, 10, 1, 20, 3, 40};
    const grape::PathND keys = grape::PathND::catmull_rom(2, k);
    Animation a = engine.create_animation(keys, 2.0, {}, [&](std::span<const double> v) { last.assign(v.begin(), v.end()); });
    engine.tick(0.5);  // u = ¼
    ASSERT_EQ(last.size(), 2u);
    for (std::size_t d = 0; d < 2; ++d) {
        const double m0 = k[2 + d] - k[d], m1 = 0.5 * (k[4 + d] - k[d]);
        EXPECT_NEAR(last[d], 0.5 * (k[d] + k[2 + d]) + (m0 - m1) / 8.0, 1e-13) << d;
    }
    engine.tick(0.5);  // u = ½
    EXPECT_EQ(last[0], 1.0);
    EXPECT_EQ(last[1], 20.0);
    (void)a;
}

TEST(Engine, CallbackAnimationsAndHeading) {
    Engine engine;
    const grape::CirclePath circle({0, 0}, 1.0, 0.0, grape::pi);
    std::vector<Vec2> seen;
    double last_heading = 0.0;
    Animation a = engine.create_animation(circle, 1.0, {.heading = true}, [&](Vec2 p, double h) {
        seen.push_back(p);
        last_heading = h;
    });
    engine.tick(0.25);
    ASSERT_EQ(seen.size(), 2u);  // the start state at creation, then the tick
    EXPECT_NEAR(seen[1].x, std::cos(grape::pi / 4), 1e-12);
    EXPECT_NEAR(last_heading, circle.heading(0.25), 1e-15);
    EXPECT_NEAR(a.heading(), last_heading, 1e-15);
    // A sprite's rotation member receives the heading.
    grape::scenes::Sprite s;
    engine.create_2d_animation(s, circle, 1.0, {.heading = true});
    engine.tick(0.5);
    EXPECT_NEAR(s.rotation, circle.heading(0.5), 1e-15);
}

TEST(Engine, BadArgumentsAreNamed) {
    Engine engine;
    Point p;
    const grape::LinearPath line({0, 0}, {1, 0});
    EXPECT_NE(error_text([&] { engine.create_2d_animation(p, line, 0.0); }).find("duration must be positive and finite (got 0)"),
              std::string::npos);
    EXPECT_NE(error_text([&] { engine.create_2d_animation(p, line, 1.0, {.delay = -1}); }).find("delay must be >= 0"),
              std::string::npos);
    EXPECT_NE(error_text([&] { engine.create_2d_animation(p, line, 1.0, {.repeat = -2}); }).find("repeat must be >= 0, or -1"),
              std::string::npos);
    EXPECT_NE(error_text([&] { engine.create_2d_animation(p, line, 1.0, {.time_scale = NAN}); }).find("time_scale must be"),
              std::string::npos);
    struct Far {
        double x = 0;
        char gap[40000] = {};
        double y = 0;
    };
    auto far = std::make_unique<Far>();
    EXPECT_NE(error_text([&] { engine.create_2d_animation(*far, line, 1.0); }).find("must lie within 32 KiB of each other"),
              std::string::npos);
    EXPECT_NE(error_text([&] { engine.create_animation(grape::PathND(std::vector<double>{0}, std::vector<double>{1}), -1.0); })
                  .find("create_animation: duration must be positive"),
              std::string::npos);
    EXPECT_NE(error_text([&] { engine.tick(-0.1); }).find("dt must be finite and >= 0 (got -0.1)"), std::string::npos);
    EXPECT_NE(error_text([&] { engine.tick(INFINITY); }).find("dt must be finite"), std::string::npos);
    engine.on_tick([&](double) { engine.tick(0.1); });
    EXPECT_NE(error_text([&] { engine.tick(0.1); }).find("inside one of the engine's own handlers"), std::string::npos);
}

// --- handlers that change the engine mid-tick (run under AddressSanitizer) --------------------

TEST(EngineHandlers, KillSelfKillOthersAndCreateDuringATick) {
    Engine engine;
    const grape::LinearPath line({0, 0}, {1, 0});
    constexpr int n = 50;
    std::vector<Point> targets(n + 10);
    std::vector<int> updates(n, 0);
    std::vector<Animation> anims(n);
    // Callback animations count their own updates: none may be skipped or doubled.
    for (int i = 0; i < n; ++i)
        anims[i] = engine.create_animation(line, i % 2 ? 0.05 : 1e9, {.repeat = -1},
                                           [&updates, i](Vec2, double) { ++updates[i]; });
    // Animation 11 kills itself, one earlier (3) and one later (41) on its first loop and
    // creates a new one.
    Animation created;
    anims[11].on_loop([&](int) {
        anims[11].kill();
        anims[3].kill();
        anims[41].kill();
        created = engine.create_2d_animation(targets[n], line, 1.0);
    });
    std::vector<int> before(n);
    std::vector<bool> was_alive(n, true);
    int kills = 0;
    for (int tick = 0; tick < 10; ++tick) {
        before = updates;
        for (int i = 0; i < n; ++i) was_alive[i] = anims[i].alive();
        const bool new_one_alive = created.alive();
        engine.tick(0.02);
        for (int i = 0; i < n; ++i) {
            const int delta = updates[i] - before[i];
            // Alive ones update exactly once per tick. In the tick of the kill (the third:
            // 11 loops at 0.06 s), 3 had advanced before 11's handler ran and 11 was in its
            // own update: one each; 41, which the tick had not reached, none (anim.hpp: a
            // change to an animation the tick has not reached applies before its update).
            // After that tick, none.
            int expected = anims[i].alive() ? 1 : 0;
            if (was_alive[i] && !anims[i].alive()) {
                ++kills;
                EXPECT_EQ(tick, 2) << "animation " << i;
                expected = i <= 11 ? 1 : 0;
            }
            EXPECT_EQ(delta, expected) << "animation " << i << " tick " << tick;
        }
        if (created.alive() && !new_one_alive) {
            EXPECT_EQ(targets[n].x, 0.0);  // written at creation, first advanced next tick
        }
    }
    EXPECT_EQ(kills, 3);
    EXPECT_FALSE(anims[3].alive());
    EXPECT_FALSE(anims[11].alive());
    EXPECT_FALSE(anims[41].alive());
    EXPECT_TRUE(created.alive());
    EXPECT_GT(targets[n].x, 0.0);
    EXPECT_EQ(engine.size(), static_cast<std::size_t>(n - 3 + 1));
}

TEST(EngineHandlers, PauseSeekAndRestartFromHandlers) {
    Engine engine;
    const grape::LinearPath line({0, 0}, {1, 0});
    Point a, b;
    Animation first = engine.create_2d_animation(a, line, 1.0);
    Animation second = engine.create_2d_animation(b, line, 1.0);
    int completes = 0;
    // On completion the first restarts itself (seek back to 0) twice, and pauses the second.
    first.on_complete([&] {
        ++completes;
        second.pause();
        if (completes < 3) first.seek(0.0);
    });
    for (int i = 0; i < 50; ++i) engine.tick(0.1);
    EXPECT_EQ(completes, 3);  // once per play it finished, never twice for one ending
    EXPECT_FALSE(first.alive());
    EXPECT_TRUE(second.paused());
    EXPECT_EQ(a.x, 1.0);
    // Killing yourself from your own complete handler is harmless.
    Point c;
    Animation third = engine.create_2d_animation(c, line, 0.5);
    int count = 0;
    third.on_complete([&] {
        ++count;
        third.kill();
        third.on_complete([] {});  // replacing the running handler is safe too
    });
    engine.tick(1.0);
    engine.tick(1.0);
    EXPECT_EQ(count, 1);
}

TEST(EngineHandlers, TickListenersRemovedInsideDispatchSkipNobody) {
    // [one-shot, persistent, one-shot] over 5 ticks: 1, 5, 1 (tweeny gives 1, 1, 2).
    Engine engine;
    int a = 0, b = 0, c = 0;
    std::size_t ida = 0, idc = 0;
    ida = engine.on_tick([&](double) { ++a; engine.remove_tick_listener(ida); });
    engine.on_tick([&](double) { ++b; });
    idc = engine.on_tick([&](double) { ++c; engine.remove_tick_listener(idc); });
    for (int i = 0; i < 5; ++i) engine.tick(0.016);
    EXPECT_EQ(a, 1);
    EXPECT_EQ(b, 5);
    EXPECT_EQ(c, 1);
    // A listener added during a dispatch is first called on the next tick.
    int d = 0;
    engine.on_tick([&](double) {
        static bool added = false;
        if (!added) {
            added = true;
            engine.on_tick([&](double) { ++d; });
        }
    });
    engine.tick(0.016);
    EXPECT_EQ(d, 0);
    engine.tick(0.016);
    EXPECT_EQ(d, 1);
}

TEST(EngineHandlers, KillingThousandsInsideOneTick) {
    Engine engine;
    const grape::LinearPath line({0, 0}, {1, 0});
    std::vector<Point> targets(10000);
    std::vector<Animation> anims;
    for (auto& t : targets) anims.push_back(engine.create_2d_animation(t, line, 1.0, {.repeat = -1}));
    engine.on_tick([&](double) {
        for (std::size_t i = 0; i < anims.size(); i += 2) anims[i].kill();
    });
    engine.tick(0.1);
    EXPECT_EQ(engine.size(), 5000u);
    for (std::size_t i = 0; i < anims.size(); ++i) EXPECT_EQ(anims[i].alive(), i % 2 == 1);
    engine.kill_all();
    EXPECT_EQ(engine.size(), 0u);
}

// --- scale ------------------------------------------------------------------------------------

// The counter sees every form of new the code under test can reach: plain, array, nothrow and
// the aligned ones that alignas(64) records (the engine's path table, the line allocator's
// vectors, the parallel tick's slice counters) go through. The pointers escape into `sink`,
// so no new-expression below may be elided.
void* volatile sink = nullptr;

TEST(CountAllocations, SeesEveryFormOfNew) {
    struct alignas(64) Wide {
        double x[8];
    };
    const long before = g_allocations.load();
    int* i = new int(1);
    sink = i;
    delete i;
    int* is = new int[3];
    sink = is;
    delete[] is;
    int* n = new (std::nothrow) int(1);
    sink = n;
    delete n;
    int* ns = new (std::nothrow) int[3];
    sink = ns;
    delete[] ns;
    EXPECT_EQ(g_allocations.load() - before, 4);
    Wide* w = new Wide;
    sink = w;
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(w) % 64, 0u);
    delete w;
    Wide* ws = new Wide[3];
    sink = ws;
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(ws) % 64, 0u);
    delete[] ws;
    Wide* wn = new (std::nothrow) Wide;
    sink = wn;
    delete wn;
    Wide* wns = new (std::nothrow) Wide[3];
    sink = wns;
    delete[] wns;
    EXPECT_EQ(g_allocations.load() - before, 8);
    {
        std::vector<Wide> v(5);  // std::allocator: ::operator new(bytes, std::align_val_t{64})
        sink = v.data();
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % 64, 0u);
    }
    EXPECT_EQ(g_allocations.load() - before, 9);
    sink = nullptr;
}

TEST(EngineScale, NoAllocationPerTick) {
    Engine engine;
    const grape::LinearPath line({0, 0}, {100, 0});
    const auto bez = unit_bezier();
    const auto rep = unit_bezier(true);
    const grape::CirclePath circle({0, 0}, 5, 0, 3);
    std::vector<Point> targets(4000);
    std::vector<grape::scenes::Sprite> sprites(500);
    struct Widget { double a = 0; float b = 0; };
    std::vector<Widget> widgets(500);
    int events = 0;
    for (std::size_t i = 0; i < targets.size(); ++i) {
        const grape::Path& path = i % 3 == 0 ? static_cast<const grape::Path&>(line) : i % 3 == 1 ? bez : rep;
        Animation a = engine.create_2d_animation(targets[i], path, 0.05 + 0.001 * (i % 97),
                                                 {.curve = i % 2 ? Curve::quad_in_out() : grape::parse_curve("ease"),
                                                  .repeat = i % 5 == 0 ? 3 : -1, .yoyo = i % 2 == 0});
        a.on_loop([&](int) { ++events; });
        a.on_complete([&] { ++events; });
    }
    for (auto& s : sprites) engine.create_2d_animation(s, circle, 0.3, {.repeat = -1, .heading = true});
    for (auto& w : widgets) engine.create_property_animation(w, {&Widget::a, &Widget::b}, {0, 0}, {1, 1}, 0.2, {.repeat = -1});
    engine.create_animation(circle, 0.1, {.repeat = -1}, [&](Vec2, double) { ++events; });
    engine.on_tick([&](double) { ++events; });
    engine.tick(0.01);  // warm-up
    const long before = g_allocations.load();
    for (int i = 0; i < 600; ++i) engine.tick(1.0 / 60.0);
    EXPECT_EQ(g_allocations.load() - before, 0);
    EXPECT_GT(events, 1000);
    EXPECT_LT(engine.size(), 5001u);  // the finite ones completed and were removed
}

TEST(EngineScale, SixtyFourBytesPerAnimation) {
    EXPECT_LE(Engine::bytes_per_animation(), 64u);
    Engine engine;
    std::vector<Point> targets(1000);
    const grape::LinearPath line({0, 0}, {1, 0});
    for (auto& t : targets) engine.create_2d_animation(t, line, 1.0);
    // Vectors grow geometrically: at most twice the payload.
    EXPECT_LE(engine.storage_bytes(), 2 * 1000 * Engine::bytes_per_animation());
}

// --- the seed's examples ------------------------------------------------------------------------

TEST(SeedAnimations, SpiralForTwoSecondsWithCompleteAndLoopListeners) {
    Engine engine;
    grape::scenes::Sprite view;
    Animation anim = grape::scenes::seed_spiral_animation(engine, view, {.repeat = 1});
    int completes = 0, loops = 0, ticks = 0;
    anim.on_complete([&] { ++completes; });
    anim.on_loop([&](int) { ++loops; });
    engine.on_tick([&](double) { ++ticks; });
    for (int i = 0; i < 4 * 60; ++i) engine.tick(1.0 / 60.0);
    EXPECT_EQ(loops, 1);
    EXPECT_EQ(completes, 1);
    EXPECT_EQ(ticks, 240);
    const Vec2 end = grape::scenes::seed_spiral().point(1.0);
    EXPECT_NEAR(view.x, end.x, 1e-12);
    EXPECT_NEAR(view.y, end.y, 1e-12);
}

TEST(SeedAnimations, ComplexPathPartsFollowTheirCues) {
    Engine engine;
    grape::scenes::Sprite view;
    grape::scenes::seed_complex_animation(engine, view);
    // At 50 % of 4 s the third part (200,200)→(200,100) begins; at 60 % the fourth.
    engine.tick(2.0);
    EXPECT_NEAR(view.x, 200.0, 1e-9);
    EXPECT_NEAR(view.y, 200.0, 1e-9);
    engine.tick(0.4);
    EXPECT_NEAR(view.x, 200.0, 1e-9);
    EXPECT_NEAR(view.y, 100.0, 1e-9);
    engine.tick(1.6);
    EXPECT_NEAR(view.x, 100.0, 1e-9);
    EXPECT_NEAR(view.y, 100.0, 1e-9);
}
