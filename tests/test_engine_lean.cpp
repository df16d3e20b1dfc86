// The tick's lean lane (runs of records sharing a formula curve on lines, cubics or
// arc-length paths, each run in a loop compiled for its kind) against the general update,
// bit for bit: the same animations, each with an update handler that does nothing, take
// the general path on every tick and are the reference.
#include <grape/anim.hpp>

#include "path/kernel.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <random>
#include <string_view>
#include <vector>

namespace {

using grape::Animation;
using grape::AnimationDef;
using grape::Curve;
using grape::Engine;
using grape::Path;

struct Target {
    double x = 0, y = 0;
};
struct FloatTarget {
    float x = 0, y = 0;
};
// y not right after x (the lanes write an adjacent (x, y) as one pair, these member by
// member); z must keep its value. The float one's y lies 8 bytes on, a double's step.
struct SpacedTarget {
    double y = 0, z = 7, x = 0;
};
struct SpacedFloatTarget {
    float x = 0, z = 7, y = 0;
};

struct World {
    Engine engine;
    std::vector<Target> doubles;
    std::vector<FloatTarget> floats;
    std::vector<SpacedTarget> spaced;
    std::vector<SpacedFloatTarget> spaced_floats;
    std::vector<Animation> anims;
};

std::vector<Curve> lean_curves() {
    std::vector<Curve> curves;
    for (std::string_view name : grape::curve_names()) {
        const Curve c = grape::parse_curve(name);
        if (!grape::has_parameters(c.kind())) curves.push_back(c);
    }
    return curves;
}

// n animations: every formula curve and two with parameters; lines, cubics and a path of
// another kind; double and float targets; delays, repeats, yoyo, reversed, time scales
// (zero included), paused, reversed at run time. `runs`: in runs of one kind, as a game's
// batches are (long lean runs); else shuffled (runs of one or two records). `only`: every
// animation on one of the two lines (1) or the two cubics (2), so that each formula kind has
// runs on that kernel (where the processor has AVX2, the four-lane runs), or on the two
// arc-length paths (3).
void build(World& w, std::size_t n, unsigned seed, bool runs, bool general, int only = 0) {
    static const std::vector<Curve> formulas = lean_curves();
    const Path paths[] = {grape::LinearPath({3, -4}, {280, 380}), grape::LinearPath({-10, 7}, {-10.5, 900}),
                          grape::CubicBezierPath({0, 0}, {10, 40}, {60, -20}, {100, 0}),
                          grape::CubicBezierPath({5, 5}, {-30, 8}, {12, 99}, {70, 70}),
                          grape::QuadraticBezierPath({0, 0}, {50, 90}, {100, 0}),
                          grape::CirclePath({50, 50}, 30, 0.0, 5.0),
                          grape::CubicBezierPath({0, 0}, {0, 100}, {100, 100}, {100, 0}, true),
                          grape::LinearPath({1, 2}, {30, -40}).reparametrized()};
    std::mt19937 r(static_cast<std::uint32_t>(grape::testing::test_seed(seed)));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    w.doubles.resize(n);
    w.floats.resize(n);
    w.spaced.resize(n);
    w.spaced_floats.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        AnimationDef def;
        const std::size_t group = runs ? i / 97 : static_cast<std::size_t>(unit(r) * 1000.0);
        if (unit(r) < 0.05) def.curve = unit(r) < 0.5 ? Curve::back(grape::EaseDirection::out) : Curve::steps(4);
        else def.curve = formulas[group % formulas.size()];
        if (unit(r) < 0.15) def.delay = unit(r) * 0.8;
        def.repeat = unit(r) < 0.5 ? -1 : static_cast<int>(unit(r) * 4);
        def.yoyo = unit(r) < 0.5;
        def.reversed = unit(r) < 0.2;
        def.time_scale = unit(r) < 0.05 ? 0.0 : 0.5 + 1.5 * unit(r);
        def.paused = unit(r) < 0.03;
        const std::size_t pick = runs ? group / 3 : static_cast<std::size_t>(unit(r) * 97.0);
        constexpr std::size_t first[] = {0, 0, 2, 6};  // of the pair of paths `only` picks
        const Path& path = paths[only ? first[only] + pick % 2 : pick % std::size(paths)];
        const double duration = 0.2 + 1.8 * unit(r);
        const double v = unit(r);  // the target: doubles, floats, spaced doubles or floats, none
        const std::size_t layout = runs ? (group % 5 == 0 ? 1 : group % 5 == 1 ? 2 + group / 5 % 3 : 0)
                                        : v < 0.2 ? 1 : v < 0.3 ? 2 : v < 0.35 ? 3 : v < 0.4 ? 4 : 0;
        Animation a = layout == 4   ? w.engine.create_animation(path, duration, def)
                      : layout == 1 ? w.engine.create_2d_animation(w.floats[i], path, duration, def)
                      : layout == 2 ? w.engine.create_2d_animation(w.spaced[i], path, duration, def)
                      : layout == 3 ? w.engine.create_2d_animation(w.spaced_floats[i], path, duration, def)
                                    : w.engine.create_2d_animation(w.doubles[i], path, duration, def);
        if (unit(r) < 0.05) a.reverse();
        if (general) a.on_update([] {});
        w.anims.push_back(a);
    }
}

void expect_same(const World& a, const World& b, int tick) {
    for (std::size_t k = 0; k < a.doubles.size(); ++k) {
        ASSERT_EQ(0, std::memcmp(&a.doubles[k], &b.doubles[k], sizeof(Target)))
            << "tick " << tick << " animation " << k << ": " << a.doubles[k].x << " " << b.doubles[k].x;
        ASSERT_EQ(0, std::memcmp(&a.floats[k], &b.floats[k], sizeof(FloatTarget))) << "tick " << tick << " animation " << k;
        ASSERT_EQ(0, std::memcmp(&a.spaced[k], &b.spaced[k], sizeof(SpacedTarget))) << "tick " << tick << " animation " << k;
        ASSERT_EQ(0, std::memcmp(&a.spaced_floats[k], &b.spaced_floats[k], sizeof(SpacedFloatTarget)))
            << "tick " << tick << " animation " << k;
        ASSERT_EQ(7.0, a.spaced[k].z) << "animation " << k;
        ASSERT_EQ(7.0f, a.spaced_floats[k].z) << "animation " << k;
    }
    for (std::size_t k = 0; k < a.anims.size(); ++k) {
        ASSERT_EQ(a.anims[k].alive(), b.anims[k].alive()) << "tick " << tick << " animation " << k;
        const double ta = a.anims[k].time(), tb = b.anims[k].time();
        ASSERT_EQ(0, std::memcmp(&ta, &tb, sizeof ta)) << "tick " << tick << " animation " << k;
        const grape::Vec2 va = a.anims[k].value(), vb = b.anims[k].value();  // those bound to nothing too
        ASSERT_EQ(0, std::memcmp(&va, &vb, sizeof va)) << "tick " << tick << " animation " << k;
    }
}

// One change applied to animation k of both worlds.
void poke(World& w, std::size_t k, int what, double value) {
    const Animation& a = w.anims[k];
    switch (what) {
        case 0: a.reverse(); break;
        case 1: a.play(); break;
        case 2: a.pause(); break;
        case 3: a.resume(); break;
        case 4: a.seek(value); break;
        case 5: a.set_time_scale(value); break;
        default: a.kill(); break;
    }
}

void run_pair(unsigned seed, bool runs, int only = 0) {
    constexpr std::size_t n = 4000;
    auto lean = std::make_unique<World>();
    auto reference = std::make_unique<World>();  // every record on the general path
    build(*lean, n, seed, runs, false, only);
    build(*reference, n, seed, runs, true, only);
    std::mt19937 r(static_cast<std::uint32_t>(grape::testing::test_seed(seed + 1000u)));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int tick = 0; tick < 240; ++tick) {
        const double u = unit(r);
        const double dt = u < 0.7 ? 1.0 / 60.0 : u < 0.9 ? unit(r) * 0.3 : u < 0.95 ? 0.0 : 2.0 + unit(r) * 5.0;
        lean->engine.tick(dt);
        reference->engine.tick(dt);
        ASSERT_NO_FATAL_FAILURE(expect_same(*lean, *reference, tick));
        for (int p = 0; p < 20; ++p) {  // run-time changes between ticks, the same in both
            const auto k = static_cast<std::size_t>(unit(r) * static_cast<double>(n)) % n;
            const int what = static_cast<int>(unit(r) * 6.05);
            const double value = what == 4 ? -0.3 + 3.0 * unit(r) : 3.0 * unit(r);
            poke(*lean, k, what, value);
            poke(*reference, k, what, value);
        }
    }
}

TEST(EngineLean, RunsOfOneKindGiveTheBitsOfTheGeneralUpdate) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
        SCOPED_TRACE(seed);
        ASSERT_NO_FATAL_FAILURE(run_pair(seed, true));
    }
}

// Runs of every formula kind on lines, on cubics, on arc-length paths: where the processor
// has AVX2, the polynomial kinds on lines and cubics run four records at a time in lanes
// (engine_lean_wide.hpp), on arc-length paths too (engine_lean_arc.hpp: their pieces found
// four and evaluated two at a time), which must give the same bits.
TEST(EngineLean, RunsOnEachKernelGiveTheBitsOfTheGeneralUpdate) {
    for (int only = 1; only <= 3; ++only) {
        for (unsigned seed = 21; seed <= 23; ++seed) {
            SCOPED_TRACE(::testing::Message() << "kernel " << only << " seed " << seed);
            ASSERT_NO_FATAL_FAILURE(run_pair(seed, true, only));
        }
    }
}

TEST(EngineLean, ShuffledKindsGiveTheBitsOfTheGeneralUpdate) {
    for (unsigned seed = 11; seed <= 13; ++seed) {
        SCOPED_TRACE(seed);
        ASSERT_NO_FATAL_FAILURE(run_pair(seed, false));
    }
}

// Plays that end on the same tick all through long runs (three runs of 500: on a line, on a
// cubic, on an arc-length path; endless and of 6 plays), so that far more new plays than the
// run's log holds (64) come in one run: each record's play count (its time), whether it is
// alive and its target as the general update has them. Plays of 4.5 ticks, so that each new
// play begins half a tick in, where the arc-length run takes it too (it leaves the path's
// exact ends, u = 0 and 1, to Path::point).
TEST(EngineLean, PlaysEndingTogetherInLongRunsAreAllCounted) {
    constexpr std::size_t n = 1500;
    const Path line = grape::LinearPath({3, -4}, {280, 380});
    const Path cubic = grape::CubicBezierPath({0, 0}, {10, 40}, {60, -20}, {100, 0});
    const Path arc = cubic.reparametrized();
    const Path* const paths[] = {&line, &cubic, &arc};  // runs of 500 on each kernel
    auto make = [&](World& w, bool general) {
        w.doubles.resize(n);
        w.floats.resize(n);
        w.spaced.resize(n);
        w.spaced_floats.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            // a quarter with 6 plays: the run leads into their next play until the last, which ends them
            const AnimationDef def{
                .curve = Curve::quad_in_out(), .repeat = i % 4 == 1 ? 5 : -1, .reversed = i % 3 == 0, .yoyo = i % 2 == 0};
            Animation a = w.engine.create_2d_animation(w.doubles[i], *paths[i / 500], 0.45, def);
            if (general) a.on_update([] {});
            w.anims.push_back(a);
        }
    };
    auto lean = std::make_unique<World>();
    auto reference = std::make_unique<World>();
    make(*lean, false);
    make(*reference, true);
    for (int tick = 0; tick < 60; ++tick) {
        lean->engine.tick(0.1);
        reference->engine.tick(0.1);
        ASSERT_NO_FATAL_FAILURE(expect_same(*lean, *reference, tick));
    }
    EXPECT_NEAR(lean->anims[7].time(), 6.0, 1e-12);  // 60 sums of 0.1: a few ulps of 6
}

// Every formula kind on a line and on a cubic, double and float targets, mid-play: the value
// curve.hpp's formula and Path::point give (lines: a + (b − a)·u where Path::point has lerp,
// within an ulp of the coordinates' size; cubics: Path::point's own formula, exactly).
TEST(EngineLean, EveryFormulaKindWritesItsOwnFormulaOnLinesAndCubics) {
    const Path line = grape::LinearPath({3, -4}, {280, 380});
    const Path cubic = grape::CubicBezierPath({0, 0}, {10, 40}, {60, -20}, {100, 0});
    for (const Curve& curve : lean_curves()) {
        Engine engine;
        std::vector<Target> d(64);
        std::vector<FloatTarget> f(64);
        for (std::size_t i = 0; i < 64; ++i) {
            const Path& path = i % 2 ? line : cubic;
            if (i < 32) engine.create_2d_animation(d[i], path, 1.0, {.curve = curve});
            else engine.create_2d_animation(f[i], path, 1.0, {.curve = curve});
        }
        for (int k = 1; k <= 50; ++k) {
            engine.tick(0.015);
            double t = 0.0;
            for (int j = 0; j < k; ++j) t += 0.015;  // the engine's sum, in the same order
            const double u = curve(t);
            for (std::size_t i = 0; i < 64; ++i) {
                const grape::Vec2 truth = (i % 2 ? line : cubic).point(u);
                // 1e-13: an ulp of coordinates below 400 is 5.7e-14
                const double tol = i % 2 ? 1e-13 : 0.0;
                if (i < 32) {
                    ASSERT_NEAR(d[i].x, truth.x, tol) << to_string(curve) << " t " << t;
                    ASSERT_NEAR(d[i].y, truth.y, tol) << to_string(curve) << " t " << t;
                } else {
                    ASSERT_NEAR(f[i].x, static_cast<float>(truth.x), i % 2 ? 4e-5 : 0.0) << to_string(curve);
                    ASSERT_NEAR(f[i].y, static_cast<float>(truth.y), i % 2 ? 4e-5 : 0.0) << to_string(curve);
                }
            }
        }
    }
}

}  // namespace

// GRAPE_WIDE_LANES=0 (the ctest engine_lean.one_record_at_a_time) keeps the one-record loops;
// without it, a processor with AVX2 takes the four-lane ones.
TEST(EngineLean, WideLanesFollowTheEnvironment) {
    const char* value = std::getenv("GRAPE_WIDE_LANES");
    if (value && std::string_view(value) == "0") {
        EXPECT_FALSE(grape::detail::wide_lanes());
    } else {
#if GRAPE_WIDE
        EXPECT_EQ(grape::detail::wide_lanes(), __builtin_cpu_supports("avx2") != 0);
#else
        EXPECT_FALSE(grape::detail::wide_lanes());
#endif
    }
}
