// Cut-scene scripts: resumption order against hand-made timelines, exact waits under random
// dt sequences, cancellation at every suspension point, nesting, errors, lifetimes.
#include <grape/script.hpp>

#include <grape/error.hpp>

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "count_allocations.hpp"
#include "seeds.hpp"

using grape::Animation;
using grape::Engine;
using grape::OnCancel;
using grape::Script;

namespace {

const grape::LinearPath line({0, 0}, {1, 0});

/// What happened, at which tick (0: inside start()).
struct Log {
    int tick = 0;
    std::vector<std::pair<std::string, int>> events;
    void operator()(std::string what) { events.emplace_back(std::move(what), tick); }
};

/// Ticks the engine `count` times by dt, numbering the ticks in the log.
void run(Engine& engine, Log& log, int count, double dt) {
    for (int i = 0; i < count; ++i) {
        ++log.tick;
        engine.tick(dt);
    }
}

/// Sets a flag when destroyed: proves a coroutine frame (its locals) went away.
struct Sentinel {
    bool* destroyed;
    ~Sentinel() { *destroyed = true; }
};

Script child_waits(Log& log, double a, double b) {
    log("child begins");
    co_await grape::wait(a);
    log("child waited a");
    co_await grape::wait(b);
    log("child ends");
}

Script sequence(Engine& engine, Log& log, const bool& flag) {
    log("begins");
    co_await engine.create_animation(line, 1.0);
    log("animation completed");
    co_await grape::wait(0.5);
    log("waited 0.5");
    co_await grape::until([&] { return flag; });
    log("flag seen");
    co_await child_waits(log, 0.25, 0.5);
    log("child returned");
    co_await 0.25;  // a plain number: seconds
    log("ends");
}

}  // namespace

// With dt = 1/4 s every time is a tick boundary: the 1 s animation completes on tick 4 and
// the script resumes in that tick (listeners run after the animations); 0.5 s later is tick
// 6; the flag, raised before tick 9, is seen in tick 9; the child runs at once on the
// parent's clock (2.25 s): its waits end at 2.5 and 3.0 (ticks 10 and 12), then 3.25 (13).
TEST(Script, ResumesInTheTicksOfAHandMadeTimeline) {
    Engine engine;
    Log log;
    bool flag = false;
    Script s = sequence(engine, log, flag);
    EXPECT_FALSE(s.alive());  // created suspended
    s.start(engine);
    EXPECT_TRUE(s.alive());
    run(engine, log, 8, 0.25);
    flag = true;
    run(engine, log, 8, 0.25);
    const std::vector<std::pair<std::string, int>> expected = {
        {"begins", 0},      {"animation completed", 4}, {"waited 0.5", 6}, {"flag seen", 9},      {"child begins", 9},
        {"child waited a", 10}, {"child ends", 12},    {"child returned", 12}, {"ends", 13}};
    EXPECT_EQ(log.events, expected);
    EXPECT_TRUE(s.done());
    EXPECT_FALSE(s.alive());
    EXPECT_EQ(s.error(), nullptr);
}

namespace {

struct Resumption {
    int tick;
    double overshoot;
};

Script waits(const std::vector<double>& seconds, std::vector<Resumption>& out, const int& tick) {
    for (double s : seconds) {
        const double overshoot = co_await grape::wait(s);  // before reading tick: it has moved on
        out.push_back({tick, overshoot});
    }
}

}  // namespace

// Dyadic times (multiples of 2⁻¹⁰ s, sums far below 2⁴³) add exactly in doubles, so the tick
// each wait ends in and its overshoot are known exactly: wait k ends in the first tick whose
// summed dt reaches the summed waits W_k, with overshoot S_i − W_k. Waits of 0 and several
// ends crossed by one dt resume in the same tick, in order.
TEST(Script, WaitsEndInTheTickThatCrossesTheirSummedTimeExactly) {
    std::mt19937_64 rng(grape::testing::test_seed(12));
    for (int run_index = 0; run_index < 300; ++run_index) {
        std::uniform_int_distribution<int> wait_units(0, 512);  // up to 0.5 s
        std::uniform_int_distribution<int> dt_units(0, 100);    // up to ~0.1 s, zeros included
        std::vector<double> seconds(1 + run_index % 20);
        for (double& s : seconds) s = wait_units(rng) / 1024.0;
        std::vector<double> dts(400);
        for (double& dt : dts) dt = dt_units(rng) / 1024.0;

        // The reference: plain exact sums.
        std::vector<Resumption> expected;
        double total_wait = 0.0;
        double clock = 0.0;
        std::size_t i = 0;  // ticks done
        for (double s : seconds) {
            total_wait += s;
            while (clock < total_wait && i < dts.size()) clock += dts[i++];
            if (clock < total_wait) break;
            expected.push_back({static_cast<int>(i), clock - total_wait});
        }

        Engine engine;
        std::vector<Resumption> got;
        int tick = 0;
        Script s = waits(seconds, got, tick);
        s.start(engine);
        for (double dt : dts) {
            ++tick;
            engine.tick(dt);
        }
        ASSERT_EQ(got.size(), expected.size()) << "run " << run_index;
        for (std::size_t k = 0; k < got.size(); ++k) {
            EXPECT_EQ(got[k].tick, expected[k].tick) << "run " << run_index << ", wait " << k;
            EXPECT_EQ(got[k].overshoot, expected[k].overshoot) << "run " << run_index << ", wait " << k;
        }
        EXPECT_EQ(s.done(), expected.size() == seconds.size());
    }
}

// Arbitrary doubles: the reference sums in long double (64-bit mantissa: ~1e-16 relative
// over 400 terms of < 0.05 s). A wait ends once the clock is within script_snap of its end;
// runs where a sum falls within 1e-11 of that threshold are ambiguous at the reference's
// precision and skipped. Overshoots agree to 1e-12 (the reference's error is ~1e-15).
TEST(Script, WaitsAgreeWithALongDoubleReferenceForRandomDt) {
    std::mt19937_64 rng(grape::testing::test_seed(34));
    int checked = 0;
    for (int run_index = 0; run_index < 300; ++run_index) {
        std::uniform_real_distribution<double> wait_seconds(0.0, 0.3);
        std::uniform_real_distribution<double> dt_seconds(0.0, 0.05);
        std::vector<double> seconds(1 + run_index % 15);
        for (double& s : seconds) s = wait_seconds(rng);
        std::vector<double> dts(400);
        for (double& dt : dts) dt = dt_seconds(rng);

        struct Expected {
            int tick;
            long double overshoot;
        };
        std::vector<Expected> expected;
        long double total_wait = 0.0L;
        long double clock = 0.0L;
        std::size_t i = 0;
        bool ambiguous = false;
        for (double s : seconds) {
            total_wait += s;
            const long double threshold = total_wait - static_cast<long double>(grape::script_snap);
            while (clock < threshold && i < dts.size()) {
                clock += dts[i++];
                if (std::abs(static_cast<double>(clock - threshold)) < 1e-11) ambiguous = true;
            }
            if (clock < threshold) break;
            expected.push_back({static_cast<int>(i), std::max(clock - total_wait, 0.0L)});
        }
        if (ambiguous) continue;
        ++checked;

        Engine engine;
        std::vector<Resumption> got;
        int tick = 0;
        Script s = waits(seconds, got, tick);
        s.start(engine);
        for (double dt : dts) {
            ++tick;
            engine.tick(dt);
        }
        ASSERT_EQ(got.size(), expected.size()) << "run " << run_index;
        for (std::size_t k = 0; k < got.size(); ++k) {
            EXPECT_EQ(got[k].tick, expected[k].tick) << "run " << run_index << ", wait " << k;
            EXPECT_NEAR(got[k].overshoot, static_cast<double>(expected[k].overshoot), 1e-12) << "run " << run_index;
        }
    }
    EXPECT_GT(checked, 250);
}

namespace {

Script every_second(int count, std::vector<int>& ticks, const int& tick) {
    for (int k = 0; k < count; ++k) {
        co_await grape::wait(1.0);
        ticks.push_back(tick);
    }
}

}  // namespace

// An hour at 60 frames a second: 1/60 is not a double, and a plain double clock drifts by
// ~1e-10 s over 216,000 additions; the script's clock keeps the error at an ulp, so every
// 1 s wait still ends on a multiple of 60 ticks.
TEST(Script, AnHourOfSixtiethsEndsEverySecondOnTheSixtiethTick) {
    Engine engine;
    std::vector<int> ticks;
    int tick = 0;
    Script s = every_second(3600, ticks, tick);
    s.start(engine);
    for (int i = 0; i < 3600 * 60; ++i) {
        ++tick;
        engine.tick(1.0 / 60.0);
    }
    ASSERT_EQ(ticks.size(), 3600u);
    for (int k = 0; k < 3600; ++k) ASSERT_EQ(ticks[k], 60 * (k + 1)) << "second " << k + 1;
    EXPECT_TRUE(s.done());
}

namespace {

// Eight suspension points of every kind; `current` names the animation awaited now.
Script nested_part(Engine& engine, Animation& current, int& progress, bool& destroyed) {
    Sentinel sentinel{&destroyed};
    current = engine.create_animation(line, 0.5);
    co_await current;  // 3
    ++progress;
    co_await grape::wait(0.25);  // 4
    ++progress;
}

Script side_script(Animation& side) { co_await side; }

Script every_kind(Engine& engine, Animation& current, Animation& side, int& progress, bool& destroyed,
                  bool& child_destroyed, const int& tick) {
    Sentinel sentinel{&destroyed};
    current = engine.create_animation(line, 0.5);
    co_await current;  // 0
    ++progress;
    co_await grape::wait(0.5);  // 1
    ++progress;
    co_await grape::until([&] { return tick >= 5; });  // 2
    ++progress;
    co_await nested_part(engine, current, progress, child_destroyed);  // 3, 4
    ++progress;
    side = engine.create_animation(line, 1.0);
    Script other = side_script(side);
    other.start(engine);
    co_await other;  // 5: a started script, polled
    ++progress;
    current = {};
    co_await grape::wait(0.25);  // 6
    ++progress;
}

}  // namespace

// Cancelling after every number of ticks reaches every suspension point: the frames are gone
// (their locals destroyed), nothing resumes afterwards, and the awaited animation is killed
// or left as chosen. Run under ASan/UBSan (build-asan) this also proves no frame is touched
// after it is freed.
TEST(Script, CancelAtEverySuspensionPointFreesTheFrames) {
    for (OnCancel mode : {OnCancel::kill_awaited, OnCancel::leave_awaited}) {
        for (bool by_destruction : {false, true}) {
            for (int stop_after = 0; stop_after <= 16; ++stop_after) {
                Engine engine;
                Animation current;
                Animation side;
                int progress = 0;
                bool destroyed = false;
                bool child_destroyed = false;
                int tick = 0;
                auto s = std::make_unique<Script>(every_kind(engine, current, side, progress, destroyed, child_destroyed, tick));
                s->start(engine, {.on_cancel = mode});
                for (; tick < stop_after;) {
                    ++tick;
                    engine.tick(0.25);
                }
                const bool was_alive = s->alive();
                const bool current_alive = current.alive();
                const bool side_alive = side.alive();
                const int at = progress;
                if (by_destruction) s.reset();
                else s->cancel();
                EXPECT_TRUE(destroyed) << stop_after;
                if (at >= 3) {
                    EXPECT_TRUE(child_destroyed) << stop_after;
                }
                if (!by_destruction) {
                    EXPECT_EQ(s->cancelled(), was_alive) << stop_after;
                }
                if (was_alive && current_alive) {
                    EXPECT_EQ(current.alive(), mode == OnCancel::leave_awaited) << stop_after;
                }
                if (was_alive && at == 6 && side_alive) {
                    // The started script is a local of the frame: its destructor cancels it with
                    // its own on_cancel (kill_awaited), whatever this cancel chose.
                    EXPECT_FALSE(side.alive()) << stop_after;
                }
                for (int i = 0; i < 20; ++i) engine.tick(0.25);
                EXPECT_EQ(progress, at) << "nothing resumes after cancel, stop_after " << stop_after;
            }
        }
    }
}

// The reference timeline of every_kind at dt = 1/4.
TEST(Script, EveryKindOfSuspensionRunsThroughInOrder) {
    Engine engine;
    Animation current;
    Animation side;
    int progress = 0;
    bool destroyed = false;
    bool child_destroyed = false;
    int tick = 0;
    std::vector<int> at_tick;
    Script s = every_kind(engine, current, side, progress, destroyed, child_destroyed, tick);
    s.start(engine);
    int last = progress;
    for (; tick < 14;) {
        ++tick;
        engine.tick(0.25);
        for (; last < progress; ++last) at_tick.push_back(tick);
    }
    // 0.5 s animation: tick 2; wait 0.5: tick 4; until tick >= 5: tick 5; nested 0.5 s
    // animation created at tick 5: tick 7; wait 0.25: tick 8 (the child ends, the parent
    // goes on: 5 and 6 in tick 8); the side script's 1 s animation, created in tick 8, runs
    // from tick 9 and ends in tick 12, where the side script's listener (registered later)
    // runs after this one's: seen in tick 13; wait 0.25 from 3.25: tick 14.
    EXPECT_EQ(at_tick, (std::vector<int>{2, 4, 5, 7, 8, 8, 13, 14}));
    EXPECT_TRUE(destroyed);
    EXPECT_TRUE(child_destroyed);
    EXPECT_TRUE(s.done());
}

namespace {

Script awaits_script(Script& other) { co_await other; }
Script awaits_then_counts(Engine& engine, int& progress);

}  // namespace

TEST(Script, KillAwaitedCancelsAnAwaitedStartedScript) {
    for (OnCancel mode : {OnCancel::kill_awaited, OnCancel::leave_awaited}) {
        Engine engine;
        int progress = 0;
        Script other = awaits_then_counts(engine, progress);
        other.start(engine);
        Script s = awaits_script(other);
        s.start(engine);
        engine.tick(0.1);
        s.cancel(mode);
        EXPECT_TRUE(s.cancelled());
        EXPECT_EQ(other.alive(), mode == OnCancel::leave_awaited);
        EXPECT_EQ(other.cancelled(), mode == OnCancel::kill_awaited);
    }
}

namespace {

Script awaits_dead(Animation a, int& progress) {
    co_await a;
    ++progress;
    co_await Animation{};  // default-constructed: never alive
    ++progress;
}

}  // namespace

TEST(Script, AwaitingAFinishedAnimationDoesNotSuspend) {
    Engine engine;
    Animation a = engine.create_animation(line, 0.1);
    engine.tick(0.2);
    ASSERT_FALSE(a.alive());
    int progress = 0;
    Script s = awaits_dead(a, progress);
    s.start(engine);
    EXPECT_EQ(progress, 2);  // ran to its end inside start()
    EXPECT_TRUE(s.done());
}

namespace {

Script awaits_then_counts(Engine& engine, int& progress) {
    co_await engine.create_animation(line, 10.0);
    ++progress;
    co_await engine.create_animation(line, 10.0);
    ++progress;
}

Script holds_a_started_script(Engine& engine, int& progress, bool& destroyed) {
    Sentinel sentinel{&destroyed};
    Script inner = awaits_then_counts(engine, progress);
    inner.start(engine);
    co_await inner;
}

}  // namespace

// kill_all kills what the script awaits: it resumes at the next tick's end, as for any death.
TEST(Script, KillAllResumesTheAwaitingScripts) {
    Engine engine;
    int progress = 0;
    Script s = awaits_then_counts(engine, progress);
    s.start(engine);
    engine.tick(1.0);
    EXPECT_EQ(progress, 0);
    engine.kill_all();
    engine.tick(0.0);
    EXPECT_EQ(progress, 1);
    engine.kill_all();
    engine.tick(0.0);
    EXPECT_EQ(progress, 2);
    EXPECT_TRUE(s.done());
}

// Destroying the engine first: its scripts stop (nothing is killed: the engine is gone);
// their frames, with a started script inside, are freed with the Script objects (ASan).
TEST(Script, TheEngineMayGoFirst) {
    for (bool cancel_before_destruction : {false, true}) {
        auto engine = std::make_unique<Engine>();
        int progress = 0;
        bool destroyed = false;
        Script s = holds_a_started_script(*engine, progress, destroyed);
        s.start(*engine);
        Log log;
        bool flag = false;
        Script nested = sequence(*engine, log, flag);
        nested.start(*engine);
        engine->tick(0.5);
        engine.reset();
        EXPECT_TRUE(s.cancelled());
        EXPECT_TRUE(nested.cancelled());
        EXPECT_FALSE(s.alive());
        EXPECT_FALSE(destroyed);  // the frame waits for its Script
        if (cancel_before_destruction) {
            s.cancel();
            EXPECT_TRUE(destroyed);
        }
    }
}

namespace {

Script grandchild_throws(Log& log) {
    co_await grape::wait(0.5);
    log("grandchild throws");
    throw std::runtime_error("boom");
}

Script child_passes(Log& log) {
    co_await grandchild_throws(log);
    log("never");
}

Script parent_catches(Log& log) {
    try {
        co_await child_passes(log);
    } catch (const std::runtime_error& e) {
        log(std::string("caught ") + e.what());
    }
    co_await grape::wait(0.25);
    log("parent ends");
}

Script three_deep(Log& log, int depth) {
    if (depth == 0) {
        co_await grape::wait(0.375);
        log("leaf");
        co_return;
    }
    co_await grape::wait(0.125);
    co_await three_deep(log, depth - 1);
    log("level " + std::to_string(depth));
}

}  // namespace

// Nested scripts share the parent's clock: 0.125 × 3 + 0.375 = 0.75 s ends in tick 3 at
// dt = 1/4 (not later, as restarting the count at each level's tick would).
TEST(Script, NestedScriptsRunOnTheParentsClock) {
    Engine engine;
    Log log;
    Script s = three_deep(log, 3);
    s.start(engine);
    run(engine, log, 4, 0.25);
    const std::vector<std::pair<std::string, int>> expected = {{"leaf", 3}, {"level 1", 3}, {"level 2", 3}, {"level 3", 3}};
    EXPECT_EQ(log.events, expected);
    EXPECT_TRUE(s.done());
}

TEST(Script, ExceptionsReachTheAwaitingScript) {
    Engine engine;
    Log log;
    Script s = parent_catches(log);
    s.start(engine);
    run(engine, log, 4, 0.25);
    const std::vector<std::pair<std::string, int>> expected = {
        {"grandchild throws", 2}, {"caught boom", 2}, {"parent ends", 3}};
    EXPECT_EQ(log.events, expected);
    EXPECT_TRUE(s.done());
}

namespace {

Script throws_after(double seconds) {
    co_await grape::wait(seconds);
    throw std::runtime_error("late");
}

Script predicate_throws(Log& log, const int& tick) {
    try {
        co_await grape::until([&]() -> bool {
            if (tick == 2) throw std::runtime_error("predicate");
            return false;
        });
    } catch (const std::runtime_error& e) {
        log(e.what());
    }
    try {
        co_await grape::wait(-1.0);
    } catch (const grape::Error& e) {
        log(e.what());
    }
}

}  // namespace

// Without a handler the exception leaves the tick (or start) running the script, once; the
// script has failed and its listener is gone, so later ticks are clean.
TEST(Script, AnUncaughtExceptionLeavesTickOnceOrGoesToTheHandler) {
    {
        Engine engine;
        Script s = throws_after(0.5);
        s.start(engine);
        engine.tick(0.25);
        EXPECT_THROW(engine.tick(0.25), std::runtime_error);
        EXPECT_TRUE(s.failed());
        ASSERT_NE(s.error(), nullptr);
        EXPECT_THROW(std::rethrow_exception(s.error()), std::runtime_error);
        EXPECT_NO_THROW(engine.tick(0.25));
    }
    {
        Engine engine;
        std::exception_ptr seen;
        Script s = throws_after(0.5);
        s.start(engine, {.on_error = [&](std::exception_ptr e) { seen = e; }});
        EXPECT_NO_THROW(engine.tick(1.0));
        EXPECT_NE(seen, nullptr);
        EXPECT_TRUE(s.failed());
    }
    {
        Engine engine;
        Script s = throws_after(0.0);
        EXPECT_THROW(s.start(engine), std::runtime_error);  // its first steps run in start()
        EXPECT_TRUE(s.failed());
    }
    {
        Engine engine;
        Log log;
        int tick = 0;
        Script s = predicate_throws(log, tick);
        s.start(engine);
        for (; tick < 3;) {
            ++tick;
            engine.tick(0.25);
        }
        ASSERT_EQ(log.events.size(), 2u);
        EXPECT_EQ(log.events[0].first, "predicate");
        EXPECT_EQ(log.events[1].first, "Script: wait seconds must be >= 0 (got -1)");
        EXPECT_TRUE(s.done());
    }
}

namespace {

Script cancels_itself(Script*& self, int& progress) {
    co_await grape::wait(0.25);
    self->cancel();
    ++progress;  // runs: the script stops at its next co_await
    co_await grape::wait(0.0);  // already over, but stopping: does not resume
    ++progress;
}

Script destroys_itself(std::unique_ptr<Script>& self, int& progress, bool& destroyed) {
    Sentinel sentinel{&destroyed};
    co_await grape::wait(0.25);
    self.reset();
    ++progress;
    co_await grape::wait(0.25);
    ++progress;
}

Script inner_cancels_outer(Script*& outer, Animation& awaited, Engine& engine, int& progress) {
    awaited = engine.create_animation(line, 5.0);
    co_await grape::wait(0.25);
    outer->cancel(OnCancel::kill_awaited);
    ++progress;
    co_await awaited;  // stopping: the outer script is cancelled here, its awaited animation killed
    ++progress;
}

Script outer_of(Script*& outer, Animation& awaited, Engine& engine, int& progress, bool& destroyed) {
    Sentinel sentinel{&destroyed};
    co_await inner_cancels_outer(outer, awaited, engine, progress);
    ++progress;
}

Script starts_and_kills(Engine& engine, int& progress) {
    Animation a = engine.create_animation(line, 5.0);
    Script other = awaits_then_counts(engine, progress);
    other.start(engine);
    a.kill();
    co_await a;  // killed from inside: no suspension
    other.cancel();
    co_await other;  // cancelled: over
    ++progress;
}

}  // namespace

TEST(Script, CancellingFromInsideStopsAtTheNextAwait) {
    Engine engine;
    {
        int progress = 0;
        Script* self = nullptr;
        Script s = cancels_itself(self, progress);
        self = &s;
        s.start(engine);
        engine.tick(0.25);
        EXPECT_EQ(progress, 1);
        EXPECT_TRUE(s.cancelled());
        engine.tick(0.25);
        EXPECT_EQ(progress, 1);
    }
    {
        int progress = 0;
        bool destroyed = false;
        auto self = std::make_unique<Script>();
        *self = destroys_itself(self, progress, destroyed);
        self->start(engine);
        engine.tick(0.25);
        EXPECT_EQ(progress, 1);
        EXPECT_TRUE(destroyed);  // freed by the driver once the script's code returned
        engine.tick(0.25);
        EXPECT_EQ(progress, 1);
    }
    {
        int progress = 0;
        bool destroyed = false;
        Animation awaited;
        Script* outer = nullptr;
        Script s = outer_of(outer, awaited, engine, progress, destroyed);
        outer = &s;
        s.start(engine);
        engine.tick(0.25);
        EXPECT_EQ(progress, 1);
        EXPECT_TRUE(destroyed);
        EXPECT_TRUE(s.cancelled());
        EXPECT_FALSE(awaited.alive());
    }
    {
        int progress = 0;
        Script s = starts_and_kills(engine, progress);
        s.start(engine);
        EXPECT_EQ(progress, 1);
        EXPECT_TRUE(s.done());
    }
}

namespace {

Script forever(Engine& engine, Animation long_one, bool& flag) {
    for (;;) {
        co_await grape::wait(0.1);
        co_await grape::until([&] { return flag; });
        flag = !flag;
        co_await grape::wait(0.05);
        co_await long_one;  // alive throughout: polled once per tick
        (void)engine;
    }
}

}  // namespace

// Once started, a script allocates nothing per tick: polling, waits, predicates, resumption.
TEST(Script, RunningAllocatesNothingPerTick) {
    Engine engine;
    Animation long_one = engine.create_animation(line, 1e6);
    bool flag = true;
    Script s = forever(engine, {}, flag);
    Script t = forever(engine, long_one, flag);
    s.start(engine);
    t.start(engine);
    engine.tick(0.01);
    const long before = g_allocations.load();
    for (int i = 0; i < 2000; ++i) {
        if (i % 7 == 0) flag = true;
        engine.tick(0.01);
    }
    EXPECT_EQ(g_allocations.load(), before);
    EXPECT_TRUE(s.alive());
}

TEST(Script, BadUseIsNamed) {
    Engine engine;
    Script empty;
    try {
        empty.start(engine);
        ADD_FAILURE();
    } catch (const grape::Error& e) {
        EXPECT_STREQ(e.what(), "Script::start: the script is empty (default-constructed, moved from or ended)");
    }
    Log log;
    Script s = child_waits(log, 1.0, 1.0);
    try {
        s.start(engine, {.elapsed = -1.0});
        ADD_FAILURE();
    } catch (const grape::Error& e) {
        EXPECT_STREQ(e.what(), "Script::start: def.elapsed must be finite and >= 0 (got -1)");
    }
    s.start(engine);
    try {
        s.start(engine);
        ADD_FAILURE();
    } catch (const grape::Error& e) {
        EXPECT_STREQ(e.what(), "Script::start: the script is already running or has ended");
    }
}

namespace {

Script starts_another_on_time(Engine& engine, Log& log, Script& other) {
    const double late = co_await grape::wait(0.3);
    other = child_waits(log, 0.2, 0.5);
    other.start(engine, {.elapsed = late});
}

}  // namespace

// The overshoot of a wait, passed as `elapsed`, starts another script on the first one's
// exact time: 0.3 + 0.2 = 0.5 s is tick 2 at dt = 1/4 (without it: 0.5 + 0.2, tick 3).
TEST(Script, ElapsedStartsAScriptOnTime) {
    Engine engine;
    Log log;
    Script other;
    Script s = starts_another_on_time(engine, log, other);
    s.start(engine);
    run(engine, log, 5, 0.25);
    const std::vector<std::pair<std::string, int>> expected = {{"child begins", 2}, {"child waited a", 2}, {"child ends", 4}};
    EXPECT_EQ(log.events, expected);
}

namespace {

Script awaits_and_logs(Script& child, Log& log) {
    co_await child;
    log(child.cancelled() ? "child cancelled" : "child done");
    co_await grape::wait(0.25);
    log("after");
}

Script awaits_twice(Script& child, Log& log) {
    try {
        co_await child;  // already awaited by another script
    } catch (const grape::Error& e) {
        log(e.what());
    }
}

}  // namespace

// A nested script cancelled from outside the chain resumes its parent at the next tick, on
// the clock (0.5 + 0.25 = 0.75: tick 3 at dt = 1/4).
TEST(Script, CancellingANestedScriptResumesItsParent) {
    Engine engine;
    Log log;
    Script child = child_waits(log, 10.0, 10.0);
    Script parent = awaits_and_logs(child, log);
    parent.start(engine);
    run(engine, log, 1, 0.25);
    EXPECT_TRUE(child.alive());  // running, nested
    Script other = awaits_twice(child, log);
    other.start(engine);
    child.cancel();
    EXPECT_TRUE(child.cancelled());
    EXPECT_TRUE(parent.alive());
    run(engine, log, 3, 0.25);
    const std::vector<std::pair<std::string, int>> expected = {
        {"child begins", 0},
        {"Script: co_await on a script another script is already awaiting", 1},
        {"child cancelled", 2},
        {"after", 3}};
    EXPECT_EQ(log.events, expected);
    EXPECT_TRUE(parent.done());
}

namespace {

Script cancels_its_parent(Script*& parent, Log& log) {
    co_await grape::wait(0.25);
    parent->cancel();
    log("asked");
    co_await grape::wait(0.0);  // the parent, and this script with it, stop here
    log("never");
}

Script middle(Script*& self, Log& log) {
    co_await cancels_its_parent(self, log);
    log("never");
}

Script outer_logs(Script& middle_script, Log& log) {
    co_await middle_script;
    log(middle_script.cancelled() ? "middle cancelled" : "middle done");
}

}  // namespace

// Cancelled by the chain's own code, a nested script stops at the next co_await and the
// script awaiting it resumes within the same tick.
TEST(Script, ANestedScriptCancelledFromWithinResumesItsParentAtOnce) {
    Engine engine;
    Log log;
    Script* middle_ptr = nullptr;
    Script m = middle(middle_ptr, log);
    middle_ptr = &m;
    Script outer = outer_logs(m, log);
    outer.start(engine);
    run(engine, log, 2, 0.25);
    const std::vector<std::pair<std::string, int>> expected = {{"asked", 1}, {"middle cancelled", 1}};
    EXPECT_EQ(log.events, expected);
    EXPECT_TRUE(outer.done());
    EXPECT_TRUE(m.cancelled());
}

namespace {

/// Counts the frames alive: each chaos script holds one.
struct FrameCount {
    int* live;
    explicit FrameCount(int* l) : live(l) { ++*live; }
    FrameCount(const FrameCount&) = delete;
    FrameCount& operator=(const FrameCount&) = delete;
    ~FrameCount() { --*live; }
};

struct World {
    std::unique_ptr<Engine> engine = std::make_unique<Engine>();
    std::mt19937_64 rng;
    std::vector<Animation> animations;
    bool flag = false;
    int live = 0;
    std::vector<std::unique_ptr<Script>> slots = std::vector<std::unique_ptr<Script>>(6);  // destroyed first
    std::size_t pick(std::size_t n) { return static_cast<std::size_t>(rng() % n); }
    double seconds(double max) { return std::uniform_real_distribution<double>(0.0, max)(rng); }
};

Script chaos(World& w, int depth);

void start_in_slot(World& w, std::size_t k, int depth) {
    auto s = std::make_unique<Script>(chaos(w, depth));
    Script& started = *s;
    w.slots[k] = std::move(s);  // may destroy the script running this very code
    started.start(*w.engine, {.on_cancel = w.rng() % 2 ? OnCancel::kill_awaited : OnCancel::leave_awaited});
}

// Every operation a script may do, in a random order: awaits of each kind, nested scripts
// (also ones held where other scripts reach them), starting, cancelling and destroying
// scripts (itself and its ancestors included), killing animations.
Script chaos(World& w, int depth) {
    FrameCount count(&w.live);
    for (int step = 0; step < 8; ++step) {
        switch (w.pick(11)) {
            case 0:
                w.animations.push_back(w.engine->create_animation(line, 0.05 + w.seconds(0.5)));
                co_await w.animations.back();
                break;
            case 1:
                co_await grape::wait(w.seconds(0.3));
                break;
            case 2:
                co_await grape::until([&w] { return w.flag; });
                break;
            case 3:
                if (depth < 3) co_await chaos(w, depth + 1);
                break;
            case 4:
                if (depth < 2) start_in_slot(w, w.pick(w.slots.size()), depth + 1);
                break;
            case 5:
                if (auto& s = w.slots[w.pick(w.slots.size())]) s->cancel(w.rng() % 2 ? OnCancel::kill_awaited : OnCancel::leave_awaited);
                break;
            case 6:
                w.slots[w.pick(w.slots.size())].reset();
                break;
            case 7:
                if (!w.animations.empty()) w.animations[w.pick(w.animations.size())].kill();
                break;
            case 8:
                if (!w.animations.empty()) co_await Animation(w.animations[w.pick(w.animations.size())]);
                break;
            case 9:
                if (depth < 3) {  // a nested script others can reach, cancel and destroy
                    const std::size_t k = w.pick(w.slots.size());
                    w.slots[k] = std::make_unique<Script>(chaos(w, depth + 1));
                    co_await *w.slots[k];
                }
                break;
            default:
                if (auto& s = w.slots[w.pick(w.slots.size())]; s && s->alive()) {
                    try {
                        co_await *s;  // a started script, or refused: a nested one
                    } catch (const grape::Error&) {
                    }
                }
                break;
        }
    }
}

}  // namespace

// Random scripts doing everything at once, under random dt and outside interference: no
// frame is used after it is freed (ASan/UBSan in build-asan), none leaks (the count returns
// to 0), also when the engine goes first.
TEST(Script, RandomScriptsDoingEverythingStaySound) {
    for (std::uint64_t seed = 0; seed < 400; ++seed) {
        World w;
        w.rng.seed(grape::testing::test_seed(seed));
        for (std::size_t k = 0; k < 3; ++k) start_in_slot(w, k, 0);
        for (int tick = 0; tick < 80; ++tick) {
            switch (w.pick(8)) {
                case 0: w.flag = !w.flag; break;
                case 1:
                    if (auto& s = w.slots[w.pick(w.slots.size())]) s->cancel();
                    break;
                case 2: w.slots[w.pick(w.slots.size())].reset(); break;
                case 3: start_in_slot(w, w.pick(w.slots.size()), 0); break;
                case 4:
                    if (w.pick(10) == 0) w.engine->kill_all();
                    break;
                default: break;
            }
            w.engine->tick(w.seconds(0.1));
        }
        if (seed % 3 == 0) {
            w.engine.reset();  // the engine first
            for (auto& s : w.slots) {
                if (s) {
                    EXPECT_FALSE(s->alive());
                }
            }
        }
        w.slots.clear();
        EXPECT_EQ(w.live, 0) << "seed " << seed;
    }
}
