// The timing model (play_at, progress_at, end_time) against the engine that plays by it, and
// the engine's limits: timings a double cannot hold are refused at creation, non-finite
// seeks are ignored, one tick's loop events are bounded, a throwing completion handler
// still completes its animation.
#include <grape/anim.hpp>
#include <grape/error.hpp>

#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using grape::Animation;
using grape::AnimationDef;
using grape::Engine;
using grape::testing::expect_error;

namespace {

struct Point {
    double x = -999.0;  // sentinel: "never written"
    double y = -999.0;
};

const grape::LinearPath unit_line({0, 0}, {1, 0});  // x is the progress u

// tick ≡ seek ≡ progress_at for random timings (delay, repeat, yoyo, reversed, time scale)
// and every curve: three computations of the same state.
TEST(TimingModel, TickSeekAndProgressAtAgreeForEveryCurve) {
    std::vector<grape::Curve> curves;
    for (const auto name : grape::curve_names()) curves.push_back(grape::parse_curve(name));
    curves.push_back(grape::parse_curve("back-out(2.5)"));
    curves.push_back(grape::parse_curve("elastic-in(1.2,0.4)"));
    curves.push_back(grape::parse_curve("cubic-bezier(0.25,0.1,0.25,1)"));
    curves.push_back(grape::parse_curve("monotone(0,0,0.5,0.8,1,1)"));
    std::mt19937_64 rng(grape::testing::test_seed(23));
    std::uniform_real_distribution<double> unit(0, 1);
    for (std::size_t round = 0; round < 3 * curves.size(); ++round) {
        const AnimationDef def{.curve = curves[round % curves.size()],
                               .delay = unit(rng),
                               .repeat = static_cast<int>(rng() % 4) - 1,
                               .reversed = rng() % 2 == 0,
                               .yoyo = rng() % 2 == 0,
                               .time_scale = 0.5 + unit(rng)};
        const double duration = 0.3 + 2.0 * unit(rng);
        Engine ticked, sought;
        Animation a = ticked.create_animation(unit_line, duration, def);
        Animation b = sought.create_animation(unit_line, duration, def);
        const double dt = 1.0 / 64.0;  // exact in binary
        for (int k = 1; k <= 64 * 6; ++k) {
            ticked.tick(dt);
            const double t = k * dt;
            const double expected = grape::progress_at(def, duration, t);
            // The engine adds dt·rate k ≤ 384 times to a phase of at most ~25 plays, progress_at
            // multiplies once: ≤ 384 ulps of 25 ≈ 2e-12 of phase, times a curve slope ≤ ~20
            // (elastic): 4e-11.
            if (a.alive()) {
                EXPECT_NEAR(a.progress(), expected, 1e-10) << to_string(def.curve) << " t = " << t;
            }
            b.seek(t * def.time_scale - def.delay);
            EXPECT_NEAR(b.progress(), expected, 1e-10) << to_string(def.curve) << " t = " << t;  // stays alive: never ticked
            if (!a.alive()) {
                // Completed: exactly at the end, and only once the model says the last play ended.
                EXPECT_TRUE(grape::play_at(def, duration, t).finished) << " t = " << t;
                EXPECT_LE(grape::end_time(def, duration), t + 1e-9);
                break;
            }
        }
    }
}

// Repeat delays: tick ≡ seek ≡ progress_at for random timings with a repeat delay, and the
// loop events arrive when the next play starts (after the delay), once each.
TEST(TimingModel, RepeatDelayTickSeekAndProgressAtAgree) {
    std::mt19937_64 rng(grape::testing::test_seed(29));
    std::uniform_real_distribution<double> unit(0, 1);
    for (int round = 0; round < 60; ++round) {
        const AnimationDef def{.curve = round % 2 ? grape::Curve::quad_in_out() : grape::Curve(),
                               .delay = unit(rng) < 0.3 ? 0.0 : unit(rng),
                               .repeat = static_cast<int>(rng() % 5) - 1,
                               .repeat_delay = 0.1 + unit(rng),
                               .reversed = rng() % 2 == 0,
                               .yoyo = rng() % 2 == 0,
                               .time_scale = 0.5 + unit(rng)};
        const double duration = 0.3 + 2.0 * unit(rng);
        Engine ticked, sought;
        Animation a = ticked.create_animation(unit_line, duration, def);
        Animation b = sought.create_animation(unit_line, duration, def);
        int loops = 0;
        a.on_loop([&](int play) { EXPECT_EQ(play, ++loops); });
        const double dt = 1.0 / 64.0;
        for (int k = 1; k <= 64 * 8; ++k) {
            ticked.tick(dt);
            const double t = k * dt;
            const grape::PlayState s = grape::play_at(def, duration, t);
            const double expected = grape::progress_at(def, duration, t);
            // As above: ≤ 512 ulps of a phase of ≤ ~40 plays, times a curve slope ≤ 2: 1e-11.
            if (a.alive()) {
                EXPECT_NEAR(a.progress(), expected, 1e-10) << "round " << round << " t = " << t;
                EXPECT_EQ(loops, static_cast<int>(s.play)) << "round " << round << " t = " << t;
            }
            b.seek(t * def.time_scale - def.delay);
            EXPECT_NEAR(b.progress(), expected, 1e-10) << "round " << round << " t = " << t;
            const double plays = def.repeat + 1.0;
            const double total = def.repeat < 0 ? INFINITY : plays * duration + (plays - 1.0) * def.repeat_delay;
            // Plays and delays summed back: a few ulps of ≤ 40 s.
            EXPECT_NEAR(b.time(), std::min(t * def.time_scale - def.delay, total), 1e-12 * 40) << "round " << round;
            if (!a.alive()) {
                EXPECT_TRUE(s.finished) << " t = " << t;
                EXPECT_LE(grape::end_time(def, duration), t + 1e-9);
                EXPECT_GT(grape::end_time(def, duration), t - dt - 1e-9);
                break;
            }
        }
    }
}

// Closed forms: 1 s plays, ½ s delay, ¼ s repeat delay, yoyo, 3 plays: plays run over
// [0.5, 1.5], [1.75, 2.75], [3, 4]; the end state holds in between.
TEST(TimingModel, RepeatDelayClosedForms) {
    const AnimationDef def{.delay = 0.5, .repeat = 2, .repeat_delay = 0.25, .yoyo = true};
    EXPECT_EQ(grape::end_time(def, 1.0), 4.0);
    EXPECT_EQ(grape::end_time({.delay = 0.5, .repeat = 2, .repeat_delay = 0.25, .time_scale = 2}, 1.0), 2.0);
    EXPECT_EQ(grape::end_time({.repeat = -1, .repeat_delay = 0.25}, 1.0), INFINITY);
    EXPECT_EQ(grape::end_time({.repeat_delay = 5}, 1.0), 1.0);  // one play: no delay after it
    struct Case {
        double t, progress, play;
        bool backward;
        double gap;
    };
    // Times chosen exact in binary away from the snap points.
    for (const Case c : {Case{0.25, 0.0, 0, false, 0}, Case{1.0, 0.5, 0, false, 0}, Case{1.625, 1.0, 0, false, 0.125},
                         Case{2.0, 0.75, 1, true, 0}, Case{2.875, 0.0, 1, true, 0.125}, Case{3.5, 0.5, 2, false, 0},
                         Case{4.5, 1.0, 2, false, 0}}) {
        const grape::PlayState s = grape::play_at(def, 1.0, c.t);
        EXPECT_EQ(grape::progress_at(def, 1.0, c.t), c.progress) << c.t;
        EXPECT_EQ(s.play, c.play) << c.t;
        EXPECT_EQ(s.backward, c.backward) << c.t;
        EXPECT_EQ(s.gap, c.gap) << c.t;
        EXPECT_EQ(s.finished, c.t >= 4.0) << c.t;
    }
    // gap 0 is the four-argument form; the end of a gap within play_snap starts the next play.
    const grape::PlayState same = grape::play_at_position(2.5, 4, true, true, 0.0);
    const grape::PlayState plain = grape::play_at_position(2.5, 4, true, true);
    EXPECT_EQ(same.play, plain.play);
    EXPECT_EQ(same.phase, plain.phase);
    EXPECT_EQ(same.backward, plain.backward);
    const grape::PlayState next = grape::play_at_position(1.5 - 1e-12, 3, false, false, 0.5);
    EXPECT_EQ(next.play, 1.0);
    EXPECT_EQ(next.phase, 0.0);
    EXPECT_EQ(next.gap, 0.0);
    // The engine on the same timing: the target holds the end through the delay, and the loop
    // event fires as the second play starts.
    Engine engine;
    Point p;
    Animation a = engine.create_2d_animation(p, unit_line, 1.0, def);
    std::vector<double> loops_at;
    double now = 0.0;
    a.on_loop([&](int) { loops_at.push_back(now); });
    const double dt = 1.0 / 8.0;
    for (int k = 1; k <= 40 && a.alive(); ++k) {
        now = k * dt;  // the tick's end, as the handlers see it
        engine.tick(dt);
        EXPECT_EQ(p.x, now < 0.5 ? -999.0 : grape::progress_at(def, 1.0, now)) << now;  // exact eighths
        if (now == 1.625) {
            EXPECT_EQ(a.time(), 1.125);  // 1 s of play, ⅛ s of its repeat delay
        }
    }
    EXPECT_FALSE(a.alive());
    EXPECT_EQ(loops_at, (std::vector<double>{1.75, 3.0}));
    EXPECT_EQ(now, 4.0);
}

TEST(EngineLimits, BadRepeatDelaysAreNamed) {
    Engine engine;
    expect_error([&] { engine.create_animation(unit_line, 1.0, {.repeat = 1, .repeat_delay = -1}); },
                 {"create_animation", "repeat_delay must be >= 0", "-1"});
    expect_error([&] { engine.create_animation(unit_line, 1.0, {.repeat = 1, .repeat_delay = NAN}); },
                 {"repeat_delay must be >= 0 and finite"});
    expect_error([&] { engine.create_animation(unit_line, 1e-10, {.repeat = 1, .repeat_delay = 1e300}); },
                 {"repeat_delay / duration overflows"});
    expect_error([&] { engine.create_animation(unit_line, 1.0, {.repeat = 2, .repeat_delay = 1.7e308}); },
                 {"repeat_delay · repeat overflows"});
    EXPECT_EQ(engine.size(), 0u);
}

TEST(TimingModel, PlaysSnapAndDirections) {
    using grape::play_at_position;
    // Within play_snap of a play's end counts as the next play; the last play's end is final.
    auto s = play_at_position(1.0 - 1e-10, 3, false, true);
    EXPECT_EQ(s.play, 1.0);
    EXPECT_TRUE(s.backward);  // yoyo: the second play runs back
    EXPECT_EQ(s.phase, 0.0);
    s = play_at_position(3.0 - 1e-10, 3, true, false);
    EXPECT_TRUE(s.finished);
    EXPECT_EQ(s.play, 2.0);
    EXPECT_EQ(s.phase, 1.0);
    EXPECT_TRUE(s.backward);  // reversed, no yoyo: every play backwards
    s = play_at_position(-0.25, 0, false, false);
    EXPECT_EQ(s.phase, -0.25);  // waiting
    EXPECT_EQ(s.play, 0.0);
    // Beyond 2⁵³ plays no fraction is left; +inf is a play's start, not NaN.
    s = play_at_position(std::ldexp(1.0, 60) + std::ldexp(1.0, 9), 0, false, true);
    EXPECT_EQ(s.phase, 0.0);
    EXPECT_FALSE(s.backward);  // an even count
    s = play_at_position(INFINITY, 0, false, true);
    EXPECT_EQ(s.phase, 0.0);
    EXPECT_FALSE(s.finished);
    s = play_at_position(INFINITY, 2, false, false);
    EXPECT_TRUE(s.finished);
    EXPECT_EQ(grape::end_time({.delay = 1, .repeat = 2, .time_scale = 2}, 3), (1 + 3 * 3) / 2.0);
    EXPECT_EQ(grape::end_time({.repeat = -1}, 3), INFINITY);
}

TEST(EngineLimits, TimingsThatOverflowAreRefusedNamingTheArgument) {
    Engine engine;
    Point p;
    // 1/duration overflows: the record's plays per second would be inf, phases NaN.
    expect_error([&] { engine.create_2d_animation(p, unit_line, 1e-310); }, {"duration", "overflows", "1e-310"});
    expect_error([&] { engine.create_animation(unit_line, 1e-10, {.time_scale = 1e300}); },
                 {"create_animation", "time_scale / duration overflows"});
    // A huge delay in plays of a tiny duration: the waiting phase would be −inf.
    expect_error([&] { engine.create_2d_animation(p, unit_line, 1e-10, {.delay = 1e300}); },
                 {"delay / duration overflows", "1e+300"});
    expect_error([&] { engine.create_2d_animation(p, unit_line, 1e308, {.delay = 1e308, .repeat = 1}); },
                 {"delay + duration · (repeat + 1) overflows"});
    EXPECT_EQ(engine.size(), 0u);
    EXPECT_EQ(p.x, -999.0);  // nothing written
    // The smallest durations that are still fine.
    engine.create_2d_animation(p, unit_line, 1e-300, {.repeat = -1});
    EXPECT_EQ(engine.size(), 1u);
}

TEST(EngineLimits, NonFiniteSeeksAreIgnored) {
    Engine engine;
    Point p;
    Animation a = engine.create_2d_animation(p, unit_line, 2.0, {.repeat = -1});
    engine.tick(0.5);
    const double x = p.x;
    EXPECT_EQ(x, 0.25);
    for (const double t : {INFINITY, -INFINITY, NAN}) {
        a.seek(t);
        EXPECT_EQ(p.x, x) << t;
        EXPECT_EQ(a.progress(), 0.25) << t;
        EXPECT_EQ(a.repetition(), 0) << t;
    }
    // A finite seek whose position in plays overflows lands at a play's start, not NaN.
    Animation tiny = engine.create_2d_animation(p, unit_line, 1e-300, {.repeat = -1});
    tiny.seek(1e300);
    EXPECT_EQ(p.x, 0.0);
    EXPECT_EQ(tiny.progress(), 0.0);
}

// One tick of 1e4 s on an endless 1e-6 s animation starts 1e10 plays: one loop event with the
// skipped count, and exactly the state the timing model gives.
TEST(EngineLimits, OneTickDeliversBoundedLoopEventsAndTheExactState) {
    Engine engine;
    Point p;
    const double duration = 1e-6;
    Animation a = engine.create_2d_animation(p, unit_line, duration, {.repeat = -1, .yoyo = true});
    int calls = 0;
    int last_play = 0;
    std::uint64_t skipped = 0;
    a.on_loop([&](int play, std::uint64_t s) {
        last_play = play;
        skipped = s;
        if (++calls > grape::max_loop_events) a.kill();  // an unbounded engine stops here
    });
    // The one-argument handler gets the same single event.
    Point q;
    Animation b = engine.create_2d_animation(q, unit_line, duration, {.repeat = -1});
    int plain_calls = 0;
    b.on_loop([&](int) {
        if (++plain_calls > grape::max_loop_events) b.kill();
    });
    const auto start = std::chrono::steady_clock::now();
    engine.tick(1e4);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(plain_calls, 1);
    EXPECT_TRUE(b.alive());
    EXPECT_LT(seconds, 1.0);  // a handful of operations; the unbounded engine took minutes
    const double position = 1e4 * (1.0 / duration);  // the engine's phase arithmetic
    const double crossed = std::floor(position + grape::play_snap);
    EXPECT_EQ(last_play, INT32_MAX);  // play numbers saturate
    EXPECT_EQ(skipped, static_cast<std::uint64_t>(crossed) - 1);
    const grape::PlayState s = grape::play_at_position(position, 0, false, true);
    EXPECT_EQ(a.progress(), s.backward ? 1.0 - s.phase : s.phase);
    EXPECT_EQ(a.repetition(), INT32_MAX);  // 1e10 plays: saturates, as play numbers do
    EXPECT_EQ(p.x, a.progress());
    // The next frame goes on from there as usual.
    calls = 0;
    engine.tick(0.25 * duration);
    EXPECT_EQ(calls, 0);
    EXPECT_NEAR(p.x, s.backward ? 0.75 - s.phase : s.phase + 0.25, 1e-6);  // phase rounding of 1e10 plays
}

// Plays are counted in 64 bits: past 2³² plays of an endless 1 s loop, time() is the time
// sought (2³² + 0.5 s is a double exactly), progress is the half play, repetition() and the
// next on_loop's play number saturate at INT32_MAX instead of starting again from 0.
TEST(EngineLimits, PlaysPastTwoToThe32DoNotWrap) {
    for (const bool yoyo : {false, true}) {
        Engine engine;
        Point p;
        Animation a = engine.create_2d_animation(p, unit_line, 1.0, {.repeat = -1, .yoyo = yoyo});
        int last_play = -1;
        a.on_loop([&](int play) { last_play = play; });
        a.seek(4294967296.5);
        Point q;  // without handlers: the engine's lean loop begins its next play
        Animation b = engine.create_2d_animation(q, unit_line, 1.0, {.repeat = -1, .yoyo = yoyo});
        b.seek(4294967296.5);
        EXPECT_EQ(a.time(), 4294967296.5) << yoyo;
        EXPECT_EQ(a.progress(), 0.5) << yoyo;
        EXPECT_EQ(a.repetition(), INT32_MAX) << yoyo;
        engine.tick(0.25);  // within the play (the lean update)
        EXPECT_EQ(a.time(), 4294967296.75) << yoyo;
        EXPECT_EQ(p.x, 0.75) << yoyo;  // play 2³² is even: forwards
        engine.tick(0.5);  // into play 2³² + 1 (odd: backwards under yoyo)
        EXPECT_EQ(last_play, INT32_MAX) << yoyo;
        EXPECT_EQ(a.time(), 4294967297.25) << yoyo;
        EXPECT_EQ(p.x, yoyo ? 0.75 : 0.25) << yoyo;
        EXPECT_EQ(b.time(), 4294967297.25) << yoyo;
        EXPECT_EQ(b.repetition(), INT32_MAX) << yoyo;
        EXPECT_EQ(q.x, p.x) << yoyo;
    }
}

TEST(EngineLimits, UpToMaxLoopEventsEachPlayHasItsOwnEvent) {
    for (const int plays : {grape::max_loop_events, grape::max_loop_events + 1}) {
        Engine engine;
        std::vector<std::pair<int, std::uint64_t>> events;
        Animation a = engine.create_animation(unit_line, 1.0, {.repeat = -1});
        a.on_loop([&](int play, std::uint64_t skipped) { events.emplace_back(play, skipped); });
        engine.tick(plays + 0.5);
        if (plays <= grape::max_loop_events) {
            ASSERT_EQ(events.size(), static_cast<std::size_t>(plays));
            for (int k = 0; k < plays; ++k) EXPECT_EQ(events[k], (std::pair<int, std::uint64_t>{k + 1, 0}));
        } else {
            ASSERT_EQ(events.size(), 1u);
            EXPECT_EQ(events[0], (std::pair<int, std::uint64_t>{plays, plays - 1}));
        }
        EXPECT_EQ(a.repetition(), plays);
        EXPECT_EQ(a.progress(), 0.5);
    }
}

// A tick whose phase overflows (infinitely many plays) lands on a play's start: no NaN, no
// out-of-range conversion (run under -fsanitize=float-cast-overflow).
TEST(EngineLimits, ATickAcrossInfinitelyManyPlaysStaysFinite) {
    Engine engine;
    Point p;
    Animation a = engine.create_2d_animation(p, unit_line, 1e-300, {.repeat = -1, .yoyo = true});
    std::uint64_t skipped = 0;
    int calls = 0;
    a.on_loop([&](int, std::uint64_t s) {
        skipped = s;
        ++calls;
    });
    engine.tick(1e300);  // 1e600 plays
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(skipped, UINT64_MAX);
    EXPECT_EQ(p.x, 0.0);
    EXPECT_EQ(a.progress(), 0.0);
    EXPECT_TRUE(a.alive());
    Animation finite = engine.create_2d_animation(p, unit_line, 1e-300, {.repeat = 3});
    engine.tick(1e300);
    EXPECT_FALSE(finite.alive());
    EXPECT_EQ(p.x, 1.0);  // completed at its end
}

TEST(EngineLimits, AThrowingCompletionHandlerStillCompletes) {
    Engine engine;
    Point p;
    int completes = 0;
    Animation a = engine.create_2d_animation(p, unit_line, 1.0);
    a.on_complete([&] {
        ++completes;
        throw std::runtime_error("handler failed");
    });
    EXPECT_THROW(engine.tick(2.0), std::runtime_error);
    EXPECT_EQ(completes, 1);
    EXPECT_FALSE(a.alive());
    EXPECT_EQ(engine.size(), 0u);
    EXPECT_EQ(p.x, 1.0);
    EXPECT_NO_THROW(engine.tick(1.0));  // gone: no second completion
    EXPECT_EQ(completes, 1);
}

}  // namespace
