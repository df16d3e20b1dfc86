// Two-phase and parallel ticks (Engine::set_parallel): the same results bit for bit on one
// thread and on two, over random engines with handlers that seek, pause, kill, reverse and
// create animations; the one-pass tick's results when handlers touch only their own
// animation; events and function curves on the calling thread; no allocation per tick.
#include <grape/anim.hpp>
#include <grape/error.hpp>

#include "count_allocations.hpp"
#include "error_text.hpp"
#include "seed_paths.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <thread>
#include <vector>

namespace {

struct Target {
    double x = 0, y = 0;
};
struct FloatTarget {
    float x = 0, y = 0;
};

// One random engine: its targets, handles and everything its handlers saw, in order.
struct World {
    grape::Engine engine;
    std::vector<Target> targets;
    std::vector<FloatTarget> floats;
    std::vector<grape::Animation> anims;
    std::vector<double> log;  // event codes, play numbers, values read by handlers
    std::mt19937 rng;
    bool off_thread = false;  // a handler or a function curve ran off the calling thread
    std::thread::id owner = std::this_thread::get_id();
};

std::vector<grape::Path> test_paths() {
    std::vector<grape::Path> paths;
    for (const auto& named : grape::scenes::path_gallery()) {
        paths.push_back(named.path);
        paths.push_back(named.path.reparametrized());
    }
    return paths;
}

// What a handler of `w` does when `touch_others`: one random change to a random animation
// (possibly itself), after logging what it reads of another one. Otherwise only logs.
void act(World& w, double code, bool touch_others) {
    w.log.push_back(code);
    if (std::this_thread::get_id() != w.owner) w.off_thread = true;
    if (!touch_others) return;
    std::uniform_int_distribution<std::size_t> pick(0, w.anims.size() - 1);
    const grape::Animation other = w.anims[pick(w.rng)];
    w.log.push_back(other.value().x);
    w.log.push_back(other.progress());
    const std::size_t k = pick(w.rng);
    w.log.push_back(k < w.targets.size() ? w.targets[k].x : 0.0);
    const grape::Animation a = w.anims[pick(w.rng)];
    switch (std::uniform_int_distribution<int>(0, 7)(w.rng)) {
        case 0: a.seek(std::uniform_real_distribution<double>(-0.5, 4.0)(w.rng)); break;
        case 1: a.pause(); break;
        case 2: a.resume(); break;
        case 3: a.kill(); break;
        case 4: a.reverse(); break;
        case 5: a.play(); break;
        case 6: a.set_time_scale(std::uniform_real_distribution<double>(0.0, 3.0)(w.rng)); break;
        default: break;
    }
}

// n animations of every sort the tick tells apart: plain (double and float targets, every
// path kind, formula and parameter curves), waiting, paused, reversed, yoyo, repeat delays,
// finite and endless, reversed at run time, function curves, update callbacks, unbound
// animations, and handlers (loop, complete, start, reverse complete, tick listener).
void build(World& w, std::size_t n, unsigned seed, bool touch_others) {
    static const std::vector<grape::Path> paths = test_paths();
    w.rng.seed(grape::testing::test_seed(seed));
    std::mt19937 r(static_cast<std::uint32_t>(grape::testing::test_seed(seed * 7919u + 1u)));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    w.targets.resize(n);
    w.floats.resize(n);
    const grape::Curve curves[] = {grape::Curve::linear(),
                                   grape::Curve::quad_in_out(),
                                   grape::Curve::bounce_out(),
                                   grape::Curve::back(grape::EaseDirection::out),
                                   grape::Curve::cubic_bezier(0.3, 0.1, 0.2, 1.0),
                                   grape::Curve::steps(5),
                                   grape::Curve::from_function([&w](double t) {
                                       if (std::this_thread::get_id() != w.owner) w.off_thread = true;
                                       return t * t * (3.0 - 2.0 * t);
                                   })};
    World* world = &w;
    for (std::size_t i = 0; i < n; ++i) {
        grape::AnimationDef def;
        const double pick_curve = unit(r);
        // mostly the cheap kinds, as in a game; one in 50 a function curve
        def.curve = curves[pick_curve < 0.5 ? 1 : pick_curve < 0.6 ? 0 : pick_curve < 0.98 ? 2 + static_cast<int>(unit(r) * 4) : 6];
        if (unit(r) < 0.2) def.delay = unit(r) * 1.5;
        def.repeat = unit(r) < 0.3 ? -1 : static_cast<int>(unit(r) * 6);
        if (unit(r) < 0.1) def.repeat_delay = unit(r) * 0.3;
        def.yoyo = unit(r) < 0.5;
        def.reversed = unit(r) < 0.2;
        def.time_scale = unit(r) < 0.1 ? 0.0 : 0.5 + 1.5 * unit(r);
        def.paused = unit(r) < 0.05;
        const grape::Path& path = paths[static_cast<std::size_t>(unit(r) * static_cast<double>(paths.size())) % paths.size()];
        const double duration = 0.2 + 1.8 * unit(r);
        const double form = unit(r);
        grape::Animation a;
        if (form < 0.03) {
            a = w.engine.create_animation(path, duration, def, [world, i](grape::Vec2 p, double) {
                world->log.push_back(static_cast<double>(i));
                world->log.push_back(p.x);
                world->log.push_back(p.y);
            });
        } else if (form < 0.15) {
            a = w.engine.create_2d_animation(w.floats[i], path, duration, def);
        } else {
            a = w.engine.create_2d_animation(w.targets[i], path, duration, def);
        }
        if (unit(r) < 0.05) a.reverse();
        const double handlers = unit(r);
        const double code = static_cast<double>(i);
        if (handlers < 0.05) {
            a.on_loop([world, code, touch_others](int play) {
                world->log.push_back(play);
                act(*world, code + 0.1, touch_others);
            });
        } else if (handlers < 0.08) {
            a.on_complete([world, code, touch_others, &path = paths.front()] {
                act(*world, code + 0.2, touch_others);
                // a new animation from a handler: first advances on the next tick
                if (touch_others) world->anims.push_back(world->engine.create_animation(path, 0.5, {.repeat = 2}));
            });
        } else if (handlers < 0.10) {
            a.on_start([world, code, touch_others] { act(*world, code + 0.3, touch_others); });
        } else if (handlers < 0.11) {
            a.on_reverse_complete([world, code, touch_others] { act(*world, code + 0.4, touch_others); });
        } else if (handlers < 0.12) {
            a.on_update([world, code] { world->log.push_back(code + 0.5); });
        }
        w.anims.push_back(a);
    }
    w.anims.reserve(w.anims.size() + 4 * n);  // handles never move while a handler reads them
    w.engine.on_tick([world](double dt) {
        world->log.push_back(dt);
        world->log.push_back(world->targets.empty() ? 0.0 : world->targets.back().x);
    });
}

std::vector<double> random_steps(unsigned seed, int count) {
    std::mt19937 r(static_cast<std::uint32_t>(grape::testing::test_seed(seed)));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> dts;
    for (int k = 0; k < count; ++k) {
        const double u = unit(r);
        dts.push_back(u < 0.6 ? 1.0 / 60.0 : u < 0.8 ? unit(r) * 0.4 : u < 0.95 ? 0.0 : 3.0 + unit(r) * 40.0);
    }
    return dts;
}

// Everything observable: targets (as bytes), the handles' state, what handlers saw.
void expect_same(const World& a, const World& b, int tick) {
    ASSERT_EQ(a.targets.size(), b.targets.size());
    ASSERT_EQ(0, std::memcmp(a.targets.data(), b.targets.data(), a.targets.size() * sizeof(Target))) << "tick " << tick;
    ASSERT_EQ(0, std::memcmp(a.floats.data(), b.floats.data(), a.floats.size() * sizeof(FloatTarget))) << "tick " << tick;
    ASSERT_EQ(a.log.size(), b.log.size()) << "tick " << tick;
    for (std::size_t k = 0; k < a.log.size(); ++k) {
        // bit for bit (NaN never appears: values and progress of live or stale handles are finite)
        ASSERT_EQ(std::memcmp(&a.log[k], &b.log[k], sizeof(double)), 0) << "tick " << tick << " entry " << k;
    }
    ASSERT_EQ(a.anims.size(), b.anims.size());
    for (std::size_t k = 0; k < a.anims.size(); ++k) {
        const grape::Animation &x = a.anims[k], &y = b.anims[k];
        ASSERT_EQ(x.alive(), y.alive()) << "tick " << tick << " animation " << k;
        ASSERT_EQ(x.paused(), y.paused());
        ASSERT_EQ(x.repetition(), y.repetition());
        const double tx = x.time(), ty = y.time();
        ASSERT_EQ(std::memcmp(&tx, &ty, sizeof tx), 0) << "tick " << tick << " animation " << k;
        const grape::Vec2 vx = x.value(), vy = y.value();
        ASSERT_EQ(std::memcmp(&vx, &vy, sizeof vx), 0) << "tick " << tick << " animation " << k;
    }
    ASSERT_EQ(a.engine.size(), b.engine.size());
}

// 3,000 animations in blocks of 256 records: two threads share phase 1 for real.
constexpr std::size_t test_size = 3000;

// Two worlds of one seed, one ticked on one thread and one as `def` says, `ticks` random steps
// compared after each; `gap(tick)` is the wall time to wait before each tick. Returns the
// one-thread world's log size (what the handlers recorded).
template <class Gap>
std::size_t expect_twins(unsigned seed, grape::ParallelDef def, int ticks, Gap&& gap) {
    auto one = std::make_unique<World>();
    auto two = std::make_unique<World>();
    build(*one, test_size, seed, true);
    build(*two, test_size, seed, true);
    one->engine.set_parallel({.threads = 1});
    two->engine.set_parallel(def);
    EXPECT_EQ(one->engine.tick_threads(), 1);
    EXPECT_EQ(two->engine.tick_threads(), def.threads);
    int tick = 0;
    for (const double dt : random_steps(seed, ticks)) {
        std::this_thread::sleep_for(gap(tick));
        one->engine.tick(dt);
        two->engine.tick(dt);
        expect_same(*one, *two, tick++);
        if (::testing::Test::HasFatalFailure()) break;
    }
    EXPECT_FALSE(two->off_thread);
    EXPECT_FALSE(one->off_thread);
    return one->log.size();
}

// Two and three threads (slices of 6 and 4 blocks), workers that stay awake between ticks
// and workers that sleep after each.
TEST(EngineParallel, TwoThreadsMatchOneBitForBitWithHandlersTouchingOthers) {
    for (unsigned seed = 1; seed <= 12; ++seed) {
        SCOPED_TRACE(seed);
        const int threads = 2 + static_cast<int>(seed % 2);
        const std::size_t logged =
            expect_twins(seed, {.threads = threads, .min_animations = 0, .awake = seed % 3 ? 200e-6 : 0.0}, 90,
                         [](int) { return std::chrono::microseconds(0); });
        ASSERT_FALSE(HasFatalFailure());
        EXPECT_GT(logged, 1000u);  // the runs did what they are meant to test
    }
}

// Ticks with gaps longer than `awake` between them, as once a frame: sleeping workers wake by
// themselves before the next tick is due (regular gaps) or sleep until a tick opens
// (irregular ones), and every tick still gives the one-thread bits. Seed 4: awake = 0, no
// timed wake, the workers woken by each tick alone.
TEST(EngineParallel, TicksAfterGapsMatchOneBitForBit) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
        SCOPED_TRACE(seed);
        // 1 ms apart, then every fourth gap 3 ms: the wake the pool expects comes early
        expect_twins(seed, {.threads = 2, .min_animations = 0, .awake = seed == 4 ? 0.0 : 100e-6}, 40,
                     [](int tick) { return std::chrono::microseconds(tick % 4 == 3 ? 3000 : 1000); });
        ASSERT_FALSE(HasFatalFailure());
    }
}

TEST(EngineParallel, BelowTheThresholdTheSameAsAboveIt) {
    auto above = std::make_unique<World>();
    auto below = std::make_unique<World>();
    build(*above, test_size, 99, true);
    build(*below, test_size, 99, true);
    above->engine.set_parallel({.threads = 2, .min_animations = 0});
    below->engine.set_parallel({.threads = 2, .min_animations = test_size + 1});
    int tick = 0;
    for (const double dt : random_steps(99, 60)) {
        above->engine.tick(dt);
        below->engine.tick(dt);
        ASSERT_NO_FATAL_FAILURE(expect_same(*above, *below, tick++));
    }
}

// Handlers that touch only their own animation (and create new ones) cannot tell the two
// orders apart: the one-pass tick gives the same results.
TEST(EngineParallel, MatchesTheOnePassTickWhenHandlersKeepToThemselves) {
    for (unsigned seed = 20; seed <= 25; ++seed) {
        SCOPED_TRACE(seed);
        auto serial = std::make_unique<World>();
        auto parallel = std::make_unique<World>();
        build(*serial, test_size, seed, false);
        build(*parallel, test_size, seed, false);
        parallel->engine.set_parallel({.threads = 2, .min_animations = 0});
        ASSERT_EQ(serial->engine.tick_threads(), 0);
        int tick = 0;
        for (const double dt : random_steps(seed, 90)) {
            serial->engine.tick(dt);
            parallel->engine.tick(dt);
            ASSERT_NO_FATAL_FAILURE(expect_same(*serial, *parallel, tick++));
        }
    }
}

// The documented difference: a handler's change to a plain animation applies after that
// animation's update in the tick. Animation b (plain) is seeked by a's on_loop handler; a is
// created first, so the one-pass tick applies the seek before b advances.
TEST(EngineParallel, AHandlersChangeToAPlainAnimationAppliesAfterItsUpdate) {
    for (const bool two_phase : {false, true}) {
        grape::Engine engine;
        if (two_phase) engine.set_parallel({.threads = 2, .min_animations = 0});
        Target ta, tb;
        const grape::LinearPath line({0, 0}, {100, 0});
        const grape::Animation a = engine.create_2d_animation(ta, line, 1.0, {.repeat = -1});
        const grape::Animation b = engine.create_2d_animation(tb, line, 10.0, {.repeat = -1});
        a.on_loop([b](int) { b.seek(0.0); });
        engine.tick(0.75);
        engine.tick(0.5);  // a loops: b goes back to 0, then (one-pass) advances by 0.5 s
        EXPECT_DOUBLE_EQ(b.time(), two_phase ? 0.0 : 0.5);
        EXPECT_DOUBLE_EQ(tb.x, two_phase ? 0.0 : 5.0);
    }
}

TEST(EngineParallel, NoAllocationPerTick) {
    grape::Engine engine;
    std::vector<Target> targets(40000);
    const grape::Path line = grape::LinearPath({0, 0}, {100, 50});
    const grape::Path cubic = grape::CubicBezierPath({0, 0}, {10, 40}, {60, -20}, {100, 0});
    for (std::size_t i = 0; i < targets.size(); ++i) {
        engine.create_2d_animation(targets[i], i % 2 ? line : cubic, 0.5 + static_cast<double>(i % 7) * 0.25,
                                   {.curve = grape::Curve::quad_in_out(), .repeat = i % 5 ? -1 : 3, .yoyo = true,
                                    .paused = i % 11 == 0});
    }
    engine.set_parallel({.threads = 2, .min_animations = 0});
    engine.tick(1.0 / 60.0);  // the first tick sizes phase 1's lists
    const long before = g_allocations.load();
    for (int k = 0; k < 200; ++k) engine.tick(1.0 / 60.0);  // loops and completions included
    EXPECT_EQ(g_allocations.load(), before);
}

TEST(EngineParallel, SwitchingModesKeepsTheState) {
    grape::Engine engine;
    Target t;
    const grape::LinearPath line({0, 0}, {60, 0});
    engine.create_2d_animation(t, line, 1.0);
    engine.tick(0.25);
    engine.set_parallel({.threads = 3, .min_animations = 0});
    EXPECT_EQ(engine.tick_threads(), 3);
    engine.tick(0.25);
    engine.set_parallel({.threads = 2});  // fewer workers: the pool is replaced
    engine.tick(0.25);
    engine.set_parallel({.threads = 2, .awake = 0.0});  // and for another wait
    EXPECT_EQ(engine.tick_threads(), 2);
    engine.set_serial();
    EXPECT_EQ(engine.tick_threads(), 0);
    engine.tick(0.125);
    EXPECT_DOUBLE_EQ(t.x, 52.5);  // 0.875 s of a 1 s linear play over 60 px
}

TEST(EngineParallel, BadThreadCountsAndCallsFromHandlersThrow) {
    grape::Engine engine;
    EXPECT_EQ(grape::testing::error_text([&] { engine.set_parallel({.threads = 0}); }),
              "Engine::set_parallel: threads must be in [1, 256] (got 0)");
    EXPECT_EQ(grape::testing::error_text([&] { engine.set_parallel({.threads = 257}); }),
              "Engine::set_parallel: threads must be in [1, 256] (got 257)");
    EXPECT_EQ(grape::testing::error_text([&] { engine.set_parallel({.awake = -1e-6}); }),
              "Engine::set_parallel: awake must be in [0, 1] seconds (got -1e-06)");
    EXPECT_EQ(grape::testing::error_text([&] { engine.set_parallel({.awake = 1.5}); }),
              "Engine::set_parallel: awake must be in [0, 1] seconds (got 1.5)");
    EXPECT_EQ(grape::testing::error_text([&] { engine.set_parallel({.awake = std::nan("")}); }),
              "Engine::set_parallel: awake must be in [0, 1] seconds (got nan)");
    EXPECT_EQ(engine.tick_threads(), 0);
    Target t;
    const grape::LinearPath line({0, 0}, {1, 0});
    const grape::Animation a = engine.create_2d_animation(t, line, 0.1);
    bool threw_parallel = false, threw_serial = false;
    a.on_complete([&] {
        try {
            engine.set_parallel();
        } catch (const grape::Error&) {
            threw_parallel = true;
        }
        try {
            engine.set_serial();
        } catch (const grape::Error&) {
            threw_serial = true;
        }
    });
    engine.tick(1.0);
    EXPECT_TRUE(threw_parallel);
    EXPECT_TRUE(threw_serial);
    EXPECT_EQ(engine.tick_threads(), 0);
}

}  // namespace
