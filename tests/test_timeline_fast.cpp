// Timelines at scale: the fast tick against the general update, bit for bit (twin engines, one
// of which has every timeline forced onto the general path before each tick; the fast tick
// covers timelines with one animation active inside a play, one cache line per timeline, the
// child's record written only when something looks at it, and the hand-over from one child of
// a sequence to the next), no allocation per tick, and the storage reused.
#include <grape/timeline.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <new>
#include <random>
#include <string>
#include <vector>

#include "count_allocations.hpp"
#include "seeds.hpp"

using grape::Animation;
using grape::AnimationDef;
using grape::Engine;
using grape::Timeline;
using grape::TimelineDef;

namespace {

struct Point {
    double x = -999.0;  // sentinel: "never written"
    double y = -999.0;
};

struct FloatPoint {
    float x = -999.0f;
    float y = -999.0f;
};

const grape::LinearPath unit_line({0, 0}, {1, 0});  // x is the progress u
const grape::CubicBezierPath swoop({0, 0}, {40, 90}, {-30, 60}, {100, 10});
const grape::CubicBezierPath swoop_by_length({0, 0}, {40, 90}, {-30, 60}, {100, 10}, true);

// Two engines built and commanded alike. The slow one's timelines have an on_update handler
// (it does nothing), which keeps them on the general update: off the fast case and off the
// hand-over's short path; before every tick they also get a command.
struct Twins {
    Engine fast, slow;
    std::vector<Timeline> fast_lines, slow_lines;
    std::vector<Animation> fast_children, slow_children;

    void create(const TimelineDef& def) {
        fast_lines.push_back(fast.create_timeline(def));
        slow_lines.push_back(slow.create_timeline(def));
        slow_lines.back().on_update([] {});
    }
    // A child placed alike in the timelines made last.
    void add(const Animation& fa, const Animation& sa, const std::string& at) {
        fast_lines.back().add(fa, at);
        slow_lines.back().add(sa, at);
        fast_children.push_back(fa);
        slow_children.push_back(sa);
    }
    // A 2-D child made alike in both engines on the twin targets, placed alike.
    template <class T>
    void add_2d(T& fast_target, T& slow_target, const grape::Path& path, double duration, const AnimationDef& def,
                const std::string& at) {
        add(fast.create_2d_animation(fast_target, path, duration, def),
            slow.create_2d_animation(slow_target, path, duration, def), at);
    }
    template <class F>
    void on_line(std::size_t k, F f) {
        f(fast_lines[k]);
        f(slow_lines[k]);
    }
    template <class F>
    void on_child(std::size_t k, F f) {
        f(fast_children[k]);
        f(slow_children[k]);
    }
    // The run-time commands of both tests, by a roll of the dice; true when one was given.
    bool command(std::uint64_t event, std::size_t line, std::size_t child) {
        switch (event) {
            case 0: on_line(line, [](const Timeline& t) { t.reverse(); }); return true;
            case 1: on_line(line, [](const Timeline& t) { t.play(); }); return true;
            case 2: on_child(child, [](const Animation& a) { a.kill(); }); return true;
            case 3: on_line(line, [](const Timeline& t) { t.pause(); }); return true;
            case 4: on_line(line, [](const Timeline& t) { t.resume(); }); return true;
            default: return false;
        }
    }
    // The engine moves its records: animations created and killed (compaction) and, with
    // `completing`, one that completes and is removed.
    void churn(std::uint64_t event, bool completing) {
        for (Engine* engine : {&fast, &slow}) {
            Animation a = engine->create_animation(unit_line, 0.5);
            if (event % 2 == 0) a.kill();
            if (completing && event % 3 == 0) engine->create_animation(unit_line, 0.05);
        }
    }
    void tick(double dt) {
        for (const Timeline& b : slow_lines) b.on_start(nullptr);  // a command: the general path
        fast.tick(dt);
        slow.tick(dt);
    }
};

// After a tick: the first `count` targets of the twins written alike, and every timeline at
// the same time.
// The first `count` twin targets written alike.
template <class T>
void expect_targets(const std::vector<T>& fast_points, const std::vector<T>& slow_points, std::size_t count,
                    std::uint64_t seed, int step) {
    for (std::size_t k = 0; k < count; ++k) {
        ASSERT_EQ(fast_points[k].x, slow_points[k].x) << "seed " << seed << " step " << step << " child " << k;
        ASSERT_EQ(fast_points[k].y, slow_points[k].y) << "seed " << seed << " step " << step << " child " << k;
    }
}

void expect_agree(const Twins& w, const std::vector<Point>& fast_points, const std::vector<Point>& slow_points,
                  std::size_t count, std::uint64_t seed, int step) {
    ASSERT_NO_FATAL_FAILURE(expect_targets(fast_points, slow_points, count, seed, step));
    for (std::size_t k = 0; k < w.fast_lines.size(); ++k)
        ASSERT_EQ(w.fast_lines[k].time(), w.slow_lines[k].time()) << "seed " << seed << " step " << step << " timeline " << k;
}

}  // namespace

// The tick's fast case (one animation or none active, no point crossed, no handler) and the
// general update give the same bits: twin engines tick the same random flat timelines with
// the same dt, one of them kept on the general path, and every target and time must be equal
// after every tick, with sequences, overlaps, gaps, delays, repeats, repeat delays, yoyo, time
// scales, reversed and parametric-curve children, run-time reverses, kills and pauses, and the
// engine moving its records (animations created, killed and completing beside the timelines).
TEST(TimelineScale, FastTickGivesTheBitsOfTheGeneralUpdate) {
    for (std::uint64_t seed = 700; seed < 760; ++seed) {
        std::mt19937_64 rng(grape::testing::test_seed(seed));
        std::uniform_real_distribution<double> unit(0, 1);
        Twins w;
        std::vector<Point> fast_points(64), slow_points(64);
        std::size_t next = 0;
        for (int t = 0; t < 4; ++t) {
            const TimelineDef def{.delay = unit(rng) < 0.5 ? 0.0 : 0.3 * unit(rng),
                                  .repeat = rng() % 3 == 0 ? -1 : static_cast<int>(rng() % 3),
                                  .repeat_delay = unit(rng) < 0.5 ? 0.0 : 0.2 * unit(rng),
                                  .yoyo = rng() % 2 == 0,
                                  .time_scale = 0.5 + unit(rng)};
            w.create(def);
            const int count = 1 + static_cast<int>(rng() % 5);
            for (int k = 0; k < count; ++k) {
                const double duration = 0.2 + unit(rng);
                const AnimationDef child{.curve = rng() % 3 == 0 ? grape::Curve::cubic_bezier(0.3, 0.1, 0.2, 1.0)
                                                                 : grape::Curve::quad_in_out(),
                                         .delay = unit(rng) < 0.7 ? 0.0 : 0.2 * unit(rng),
                                         .repeat = static_cast<int>(rng() % 3),
                                         .repeat_delay = unit(rng) < 0.7 ? 0.0 : 0.1 * unit(rng),
                                         .reversed = rng() % 4 == 0,
                                         .yoyo = rng() % 2 == 0,
                                         .time_scale = 0.5 + unit(rng)};
                const auto roll = rng() % 4;
                const std::string at = roll == 0 ? "<+0.1" : roll == 1 ? "+=0.2" : ">";
                w.add_2d(fast_points[next], slow_points[next], unit_line, duration, child, at);
                ++next;
            }
        }
        for (int step = 0; step < 400; ++step) {
            const double dt = unit(rng) < 0.05 ? unit(rng) : 0.02 * unit(rng);
            const auto event = rng() % 200;
            const std::size_t which = rng() % w.fast_lines.size();
            const std::size_t child = rng() % w.fast_children.size();
            if (!w.command(event, which, child) && event < 40) w.churn(event, true);
            w.tick(dt);
            ASSERT_NO_FATAL_FAILURE(expect_agree(w, fast_points, slow_points, next, seed, step));
            for (std::size_t k = 0; k < w.fast_children.size(); ++k)
                ASSERT_EQ(w.fast_children[k].progress(), w.slow_children[k].progress());
        }
    }
}

// Sequences as games write them (no delays, time scale 1, children one after another, some
// with gaps, some sharing a target, some with float members, along lines, cubics and an
// arc-length cubic, with several formula curves): the lean entries and the
// hand-over between children. The children's handles are read every third step (a child's
// phase is written out when looked at); now and then a child gets a handler or is killed, a
// timeline is sought, reversed or paused, and the engine moves its records.
TEST(TimelineScale, SequencesHandOverWithTheBitsOfTheGeneralUpdate) {
    for (std::uint64_t seed = 900; seed < 940; ++seed) {
        std::mt19937_64 rng(grape::testing::test_seed(seed));
        std::uniform_real_distribution<double> unit(0, 1);
        Twins w;
        std::vector<Point> fast_points(96), slow_points(96);
        std::vector<FloatPoint> fast_floats(96), slow_floats(96);
        std::size_t next = 0;
        for (int t = 0; t < 6; ++t) {
            const TimelineDef def{.repeat = rng() % 2 == 0 ? -1 : static_cast<int>(rng() % 3)};
            w.create(def);
            const int count = 2 + static_cast<int>(rng() % 6);
            const bool shared = rng() % 3 == 0;  // every child moves the same object
            const std::size_t first = next;
            for (int k = 0; k < count; ++k) {
                const double duration = 0.05 + 0.5 * unit(rng);
                const auto roll = rng() % 6;
                // the lean entries' kinds: formula curves, each compiled on its own
                const grape::Curve formulas[] = {grape::Curve::quad_in_out(), grape::Curve::linear(),
                                                 grape::Curve::sine_in_out(), grape::Curve::expo_out(),
                                                 grape::Curve::bounce_out(), grape::Curve::circ_in()};
                const AnimationDef child{.curve = roll == 0 ? grape::Curve::cubic_bezier(0.3, 0.1, 0.2, 1.0)
                                                            : formulas[rng() % std::size(formulas)],
                                         .reversed = roll == 1};
                const std::string at = rng() % 4 == 0 ? "+=0.1" : ">";
                const std::size_t target = shared ? first : next;
                const auto shape = rng() % 4;  // lines, cubics and an arc-length cubic
                const grape::Path& path = shape < 2 ? static_cast<const grape::Path&>(unit_line)
                                          : shape == 2 ? static_cast<const grape::Path&>(swoop)
                                                       : static_cast<const grape::Path&>(swoop_by_length);
                if (rng() % 5 == 0) w.add_2d(fast_floats[target], slow_floats[target], path, duration, child, at);
                else w.add_2d(fast_points[target], slow_points[target], path, duration, child, at);
                ++next;
            }
        }
        int completions_fast = 0, completions_slow = 0;
        for (int step = 0; step < 600; ++step) {
            const double dt = unit(rng) < 0.03 ? 0.3 * unit(rng) : 1.0 / 60.0;
            const auto event = rng() % 300;
            const std::size_t which = rng() % w.fast_lines.size();
            const std::size_t child = rng() % w.fast_children.size();
            if (event == 5) {
                const double at = 3.0 * unit(rng);
                w.on_line(which, [at](const Timeline& t) { t.seek(at); });
            } else if (event == 6) {
                w.fast_children[child].on_complete([&] { ++completions_fast; });
                w.slow_children[child].on_complete([&] { ++completions_slow; });
            } else if (!w.command(event, which, child) && event < 20) {
                w.churn(event, false);
            }
            w.tick(dt);
            ASSERT_NO_FATAL_FAILURE(expect_targets(fast_points, slow_points, next, seed, step));
            ASSERT_NO_FATAL_FAILURE(expect_targets(fast_floats, slow_floats, next, seed, step));
            for (std::size_t k = 0; k < w.fast_lines.size(); ++k) ASSERT_EQ(w.fast_lines[k].time(), w.slow_lines[k].time());
            if (step % 3 == 0)
                for (std::size_t k = 0; k < w.fast_children.size(); ++k) {
                    ASSERT_EQ(w.fast_children[k].progress(), w.slow_children[k].progress()) << "seed " << seed << " step " << step;
                    ASSERT_EQ(w.fast_children[k].time(), w.slow_children[k].time());
                    ASSERT_EQ(w.fast_children[k].repetition(), w.slow_children[k].repetition());
                }
            ASSERT_EQ(completions_fast, completions_slow);
        }
    }
}

// y two members after x: the write that is not one (x, y) pair.
struct SpreadPoint {
    double x = -999.0;
    double z = 0.0;
    double y = -999.0;
};

// Many sequences side by side in blocks that share a formula curve, a path kernel and a target
// type, as a game's crowd of similar objects: the lean entries of a block run four at a time
// where the processor has four lanes (a group with any entry that hands over, of another kind
// or otherwise leaving the run goes one entry at a time). Blocks differ in curve (linear and
// the polynomials, which the lanes take, and others, which they do not), path (lines, cubics,
// an arc-length cubic), target type and layout (float members, y not right after x), and some
// children run reversed; now and then a timeline is reversed, paused, sought, or a child
// killed. Every target, time and child must have the general update's bits after every tick.
TEST(TimelineScale, LeanEntriesInLanesGiveTheBitsOfTheGeneralUpdate) {
    const grape::Curve curves[] = {grape::Curve::linear(),    grape::Curve::quad_in_out(), grape::Curve::cubic_out(),
                                   grape::Curve::quart_in(),  grape::Curve::quint_out_in(), grape::Curve::quad_out(),
                                   grape::Curve::sine_in_out()};
    for (std::uint64_t seed = 1400; seed < 1412; ++seed) {
        std::mt19937_64 rng(grape::testing::test_seed(seed));
        std::uniform_real_distribution<double> unit(0, 1);
        Twins w;
        constexpr std::size_t most = 400;
        std::vector<Point> fast_points(most), slow_points(most);
        std::vector<FloatPoint> fast_floats(most), slow_floats(most);
        std::vector<SpreadPoint> fast_spread(most), slow_spread(most);
        std::size_t next = 0;
        while (next + 12 * 5 <= most) {
            const grape::Curve curve = curves[rng() % std::size(curves)];
            const auto shape = rng() % 5;  // mostly lines and cubics
            const grape::Path& path = shape < 2   ? static_cast<const grape::Path&>(unit_line)
                                      : shape < 4 ? static_cast<const grape::Path&>(swoop)
                                                  : static_cast<const grape::Path&>(swoop_by_length);
            const auto type = rng() % 6;  // double pairs, float pairs, spread doubles
            const int lines = 1 + static_cast<int>(rng() % 12);
            for (int t = 0; t < lines; ++t) {
                w.create({.repeat = -1});
                const int count = 2 + static_cast<int>(rng() % 4);
                for (int k = 0; k < count; ++k) {
                    const double duration = 0.1 + 0.6 * unit(rng);
                    const AnimationDef child{.curve = curve, .reversed = rng() % 5 == 0};
                    if (type == 0) w.add_2d(fast_floats[next], slow_floats[next], path, duration, child, ">");
                    else if (type == 1) w.add_2d(fast_spread[next], slow_spread[next], path, duration, child, ">");
                    else w.add_2d(fast_points[next], slow_points[next], path, duration, child, ">");
                    ++next;
                }
            }
        }
        for (int step = 0; step < 300; ++step) {
            const auto event = rng() % 100;
            const double dt = event < 3 ? 0.25 * unit(rng) : 1.0 / 60.0;
            const std::size_t which = rng() % w.fast_lines.size();
            const std::size_t child = rng() % w.fast_children.size();
            if (event == 5) {
                const double at = 2.0 * unit(rng);
                w.on_line(which, [at](const Timeline& t) { t.seek(at); });
            } else if (event >= 10 && event < 15) {
                w.command(event - 10, which, child);  // reverse, play, kill a child, pause, resume
            }
            w.tick(dt);
            ASSERT_NO_FATAL_FAILURE(expect_targets(fast_points, slow_points, next, seed, step));
            ASSERT_NO_FATAL_FAILURE(expect_targets(fast_floats, slow_floats, next, seed, step));
            ASSERT_NO_FATAL_FAILURE(expect_targets(fast_spread, slow_spread, next, seed, step));
            for (std::size_t k = 0; k < next; ++k) ASSERT_EQ(fast_spread[k].z, 0.0);  // between x and y: never written
            for (std::size_t k = 0; k < w.fast_lines.size(); ++k) ASSERT_EQ(w.fast_lines[k].time(), w.slow_lines[k].time());
            if (step % 7 == 0)
                for (std::size_t k = 0; k < w.fast_children.size(); ++k) {
                    ASSERT_EQ(w.fast_children[k].progress(), w.slow_children[k].progress()) << "seed " << seed << " step " << step;
                    ASSERT_EQ(w.fast_children[k].time(), w.slow_children[k].time());
                }
        }
    }
}

// Children that last whole ticks (k/60 s, ticked at 1/60 s): every hand-over lands on a
// child's end or within rounding of it, just before (the child within 1e-7 plays of its end)
// or just past (the next within 1e-7 plays of its start), where the fast case does not
// hold; the short path takes those steps, and must give the general update's bits. Some
// timelines loop, some share one target, some are reversed, paused or sought now and then,
// and every few ticks a tick of another length moves the phase of the ticks.
TEST(TimelineScale, TickAlignedHandOversGiveTheBitsOfTheGeneralUpdate) {
    for (std::uint64_t seed = 1200; seed < 1230; ++seed) {
        std::mt19937_64 rng(grape::testing::test_seed(seed));
        Twins w;
        std::vector<Point> fast_points(64), slow_points(64);
        std::size_t next = 0;
        for (int t = 0; t < 6; ++t) {
            w.create({.repeat = rng() % 2 == 0 ? -1 : static_cast<int>(rng() % 3)});
            const int count = 2 + static_cast<int>(rng() % 6);
            const bool shared = rng() % 2 == 0;
            const std::size_t first = next;
            for (int k = 0; k < count; ++k) {
                const double duration = static_cast<double>(1 + rng() % 40) / 60.0;  // whole ticks
                const AnimationDef child{.curve = rng() % 2 == 0 ? grape::Curve::quad_in_out() : grape::Curve::linear()};
                const std::size_t target = shared ? first : next;
                const grape::Path& path = rng() % 3 == 0 ? static_cast<const grape::Path&>(swoop) : unit_line;
                w.add_2d(fast_points[target], slow_points[target], path, duration, child, ">");
                ++next;
            }
        }
        for (int step = 0; step < 500; ++step) {
            const auto event = rng() % 150;
            const double dt = event < 3 ? 1.0 / 120.0 : event < 5 ? 1.0 / 30.0 : 1.0 / 60.0;
            const std::size_t which = rng() % w.fast_lines.size();
            if (event == 7) {
                const double at = static_cast<double>(rng() % 120) / 60.0;  // a whole tick
                w.on_line(which, [at](const Timeline& t) { t.seek(at); });
            } else if (event >= 10 && event < 14) {
                constexpr std::uint64_t commands[] = {0, 1, 3, 4};  // reverse, play, pause, resume
                w.command(commands[event - 10], which, 0);
            }
            w.tick(dt);
            ASSERT_NO_FATAL_FAILURE(expect_agree(w, fast_points, slow_points, next, seed, step));
            if (step % 5 == 0)
                for (std::size_t k = 0; k < w.fast_children.size(); ++k) {
                    ASSERT_EQ(w.fast_children[k].progress(), w.slow_children[k].progress()) << "seed " << seed << " step " << step;
                    ASSERT_EQ(w.fast_children[k].time(), w.slow_children[k].time());
                }
        }
    }
}

// Playing timelines allocates nothing per tick (the window's storage is reserved when
// children are placed): sequences, overlaps, nesting, loops, yoyo, reverses, callbacks and
// child handlers.
TEST(TimelineScale, NoAllocationPerTick) {
    Engine engine;
    std::vector<Point> points(2000);
    std::vector<Timeline> timelines;
    int events = 0;
    for (int t = 0; t < 100; ++t) {
        Timeline tl = engine.create_timeline({.repeat = -1, .repeat_delay = 0.05 * (t % 3), .yoyo = t % 2 == 0});
        for (int k = 0; k < 10; ++k) {
            Animation a = engine.create_2d_animation(points[static_cast<std::size_t>(t * 10 + k)], unit_line, 0.1 + 0.01 * k,
                                                     {.repeat = k % 3});
            a.on_complete([&] { ++events; });
            tl.add(a, k % 4 == 0 ? "<+0.05" : ">");
        }
        Timeline inner = engine.create_timeline({.repeat = 1, .yoyo = true});
        inner.add(engine.create_2d_animation(points[static_cast<std::size_t>(1000 + t)], unit_line, 0.2));
        inner.call([&] { ++events; }, 0.1);
        tl.add(inner, "<");
        tl.call([&] { ++events; }, 0.5);
        timelines.push_back(tl);
    }
    engine.tick(0.01);
    const long before = g_allocations.load();
    for (int k = 0; k < 1000; ++k) {
        if (k % 100 == 50) timelines[static_cast<std::size_t>(k / 100)].reverse();
        engine.tick(k % 97 == 0 ? 3.0 : 1.0 / 60.0);
    }
    EXPECT_EQ(g_allocations.load() - before, 0);
    EXPECT_GT(events, 1000);
}

// Creating and killing a timeline of ten animations again and again allocates nothing beyond
// what the animations themselves allocate (the timeline's slot and its window's vectors are
// reused; which timeline drives an animation is kept by slot, not in nodes).
TEST(TimelineScale, CreatingAndKillingReusesTheStorage) {
    Engine engine;
    std::vector<Point> points(10);
    auto once = [&] {
        Timeline tl = engine.create_timeline();
        for (Point& p : points) tl.add(engine.create_2d_animation(p, unit_line, 0.5));
        engine.tick(0.1);
        tl.kill();
    };
    for (int k = 0; k < 3; ++k) once();
    const long start = g_allocations.load();
    for (int k = 0; k < 100; ++k) once();
    const long with_timelines = g_allocations.load() - start;
    // The same animations created, ticked and killed on their own: what the engine allocates.
    auto alone = [&] {
        std::vector<Animation> made;
        made.reserve(points.size());
        for (Point& p : points) made.push_back(engine.create_2d_animation(p, unit_line, 0.5));
        engine.tick(0.1);
        for (const Animation& a : made) a.kill();
    };
    alone();
    const long restart = g_allocations.load();
    for (int k = 0; k < 100; ++k) alone();
    EXPECT_LE(with_timelines, g_allocations.load() - restart - 100);  // less the vector `made`, once per round
    EXPECT_EQ(engine.size(), 0u);
}
