// The timelines' fast tick against the general update, bit for bit: twin engines, one of which
// has every timeline forced onto the general path before each tick. The fast tick covers
// timelines with one animation active inside a play (one cache line per timeline, the child's
// record written only when something looks at it) and the hand-over from one child of a
// sequence to the next; anything it leaves to the general path must come out the same.
#include <grape/timeline.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

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

}  // namespace

TEST(TimelineScale, FastTickGivesTheBitsOfTheGeneralUpdate) {
    for (std::uint64_t seed = 700; seed < 760; ++seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> unit(0, 1);
        Engine fast, slow;
        std::vector<Point> fast_points(64), slow_points(64);
        std::vector<Timeline> fast_lines, slow_lines;
        std::vector<Animation> fast_children, slow_children;
        std::size_t next = 0;
        for (int t = 0; t < 4; ++t) {
            const TimelineDef def{.delay = unit(rng) < 0.5 ? 0.0 : 0.3 * unit(rng),
                                  .repeat = rng() % 3 == 0 ? -1 : static_cast<int>(rng() % 3),
                                  .repeat_delay = unit(rng) < 0.5 ? 0.0 : 0.2 * unit(rng),
                                  .yoyo = rng() % 2 == 0,
                                  .time_scale = 0.5 + unit(rng)};
            Timeline a = fast.create_timeline(def), b = slow.create_timeline(def);
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
                Animation fa = fast.create_2d_animation(fast_points[next], unit_line, duration, child);
                Animation sa = slow.create_2d_animation(slow_points[next], unit_line, duration, child);
                ++next;
                a.add(fa, at);
                b.add(sa, at);
                fast_children.push_back(fa);
                slow_children.push_back(sa);
            }
            fast_lines.push_back(a);
            slow_lines.push_back(b);
        }
        for (int step = 0; step < 400; ++step) {
            const double dt = unit(rng) < 0.05 ? unit(rng) : 0.02 * unit(rng);
            const auto event = rng() % 200;
            const std::size_t which = rng() % fast_lines.size();
            const std::size_t child = rng() % fast_children.size();
            if (event == 0) {
                fast_lines[which].reverse();
                slow_lines[which].reverse();
            } else if (event == 1) {
                fast_lines[which].play();
                slow_lines[which].play();
            } else if (event == 2) {
                fast_children[child].kill();
                slow_children[child].kill();
            } else if (event == 3) {
                fast_lines[which].pause();
                slow_lines[which].pause();
            } else if (event == 4) {
                fast_lines[which].resume();
                slow_lines[which].resume();
            } else if (event < 40) {  // the engine moves its records: create, and kill (compaction)
                for (Engine* engine : {&fast, &slow}) {
                    Animation a = engine->create_animation(unit_line, 0.5);
                    if (event % 2 == 0) a.kill();
                    if (event % 3 == 0) engine->create_animation(unit_line, 0.05);  // completes: removed
                }
            }
            for (const Timeline& b : slow_lines) b.on_start(nullptr);  // a command: the general path
            fast.tick(dt);
            slow.tick(dt);
            for (std::size_t k = 0; k < next; ++k) {
                ASSERT_EQ(fast_points[k].x, slow_points[k].x) << "seed " << seed << " step " << step << " child " << k;
                ASSERT_EQ(fast_points[k].y, slow_points[k].y);
            }
            for (std::size_t k = 0; k < fast_lines.size(); ++k) ASSERT_EQ(fast_lines[k].time(), slow_lines[k].time());
            for (std::size_t k = 0; k < fast_children.size(); ++k)
                ASSERT_EQ(fast_children[k].progress(), slow_children[k].progress());
        }
    }
}

// A child placed behind the playhead goes to its end at once, with many timelines in the
// store (the window's rebuild is given its timeline, it does not look for it).
// Sequences as games write them (no delays, time scale 1, children one after another, some
// with gaps, some sharing a target): the lean entries and the hand-over between children. The
// handles are read every step (the child's phase is written out when looked at); now and then
// a child gets a handler, a timeline is sought, reversed or paused, or a child is killed.
TEST(TimelineScale, SequencesHandOverWithTheBitsOfTheGeneralUpdate) {
    for (std::uint64_t seed = 900; seed < 940; ++seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> unit(0, 1);
        Engine fast, slow;
        std::vector<Point> fast_points(96), slow_points(96);
        std::vector<FloatPoint> fast_floats(96), slow_floats(96);
        std::vector<Timeline> fast_lines, slow_lines;
        std::vector<Animation> fast_children, slow_children;
        std::size_t next = 0;
        for (int t = 0; t < 6; ++t) {
            const TimelineDef def{.repeat = rng() % 2 == 0 ? -1 : static_cast<int>(rng() % 3)};
            Timeline a = fast.create_timeline(def), b = slow.create_timeline(def);
            const int count = 2 + static_cast<int>(rng() % 6);
            const bool shared = rng() % 3 == 0;  // every child moves the same object
            const std::size_t first = next;
            for (int k = 0; k < count; ++k) {
                const double duration = 0.05 + 0.5 * unit(rng);
                const auto roll = rng() % 6;
                const AnimationDef child{.curve = roll == 0 ? grape::Curve::cubic_bezier(0.3, 0.1, 0.2, 1.0)
                                                            : grape::Curve::quad_in_out(),
                                         .reversed = roll == 1};
                const std::string at = rng() % 4 == 0 ? "+=0.1" : ">";
                const std::size_t target = shared ? first : next;
                Animation fa, sa;
                if (rng() % 5 == 0) {
                    fa = fast.create_2d_animation(fast_floats[target], unit_line, duration, child);
                    sa = slow.create_2d_animation(slow_floats[target], unit_line, duration, child);
                } else {
                    fa = fast.create_2d_animation(fast_points[target], unit_line, duration, child);
                    sa = slow.create_2d_animation(slow_points[target], unit_line, duration, child);
                }
                ++next;
                a.add(fa, at);
                b.add(sa, at);
                fast_children.push_back(fa);
                slow_children.push_back(sa);
            }
            fast_lines.push_back(a);
            slow_lines.push_back(b);
        }
        int completions_fast = 0, completions_slow = 0;
        for (int step = 0; step < 600; ++step) {
            const double dt = unit(rng) < 0.03 ? 0.3 * unit(rng) : 1.0 / 60.0;
            const auto event = rng() % 300;
            const std::size_t which = rng() % fast_lines.size();
            const std::size_t child = rng() % fast_children.size();
            if (event == 0) {
                fast_lines[which].reverse();
                slow_lines[which].reverse();
            } else if (event == 1) {
                fast_lines[which].play();
                slow_lines[which].play();
            } else if (event == 2) {
                fast_children[child].kill();
                slow_children[child].kill();
            } else if (event == 3) {
                const double at = 3.0 * unit(rng);
                fast_lines[which].seek(at);
                slow_lines[which].seek(at);
            } else if (event == 4) {
                fast_children[child].on_complete([&] { ++completions_fast; });
                slow_children[child].on_complete([&] { ++completions_slow; });
            } else if (event == 5) {
                fast_lines[which].pause();
                slow_lines[which].pause();
            } else if (event == 6) {
                fast_lines[which].resume();
                slow_lines[which].resume();
            } else if (event < 20) {  // the engine moves its records: create, and kill (compaction)
                for (Engine* engine : {&fast, &slow}) {
                    Animation a = engine->create_animation(unit_line, 0.5);
                    if (event % 2 == 0) a.kill();
                }
            }
            for (const Timeline& b : slow_lines) b.on_start(nullptr);  // a command: the general path
            fast.tick(dt);
            slow.tick(dt);
            for (std::size_t k = 0; k < next; ++k) {
                ASSERT_EQ(fast_points[k].x, slow_points[k].x) << "seed " << seed << " step " << step << " child " << k;
                ASSERT_EQ(fast_points[k].y, slow_points[k].y);
                ASSERT_EQ(fast_floats[k].x, slow_floats[k].x) << "seed " << seed << " step " << step << " child " << k;
                ASSERT_EQ(fast_floats[k].y, slow_floats[k].y);
            }
            for (std::size_t k = 0; k < fast_lines.size(); ++k) ASSERT_EQ(fast_lines[k].time(), slow_lines[k].time());
            if (step % 3 == 0)  // and sometimes not looked at for a while
                for (std::size_t k = 0; k < fast_children.size(); ++k) {
                    ASSERT_EQ(fast_children[k].progress(), slow_children[k].progress()) << "seed " << seed << " step " << step;
                    ASSERT_EQ(fast_children[k].time(), slow_children[k].time());
                    ASSERT_EQ(fast_children[k].repetition(), slow_children[k].repetition());
                }
            ASSERT_EQ(completions_fast, completions_slow);
        }
    }
}
