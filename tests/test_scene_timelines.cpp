// scene timelines: the example cut-scene evaluated at times whose child times are derived by
// hand, random nested trees against a reference model that walks play after play, both
// against the engine's timelines ticking the same scene, save → load round trips, and every
// kind of bad timeline naming its JSON pointer.
#include <grape/anim.hpp>
#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/scene.hpp>
#include <grape/timeline.hpp>

#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using grape::Scene;
using grape::SceneTiming;

std::size_t index_of(const Scene& s, const std::string& name) {
    for (std::size_t i = 0; i < s.animations.size(); ++i)
        if (s.animations[i].name == name) return i;
    ADD_FAILURE() << "no animation " << name;
    return 0;
}

// The scene's timelines built as the engine's Timelines (children first, in placement
// order); each animation writes its position into `out`.
void build_in_engine(const Scene& s, grape::Engine& engine, std::vector<grape::Vec2>& out) {
    out.assign(s.animations.size(), grape::Vec2{std::numeric_limits<double>::quiet_NaN(), 0.0});
    std::vector<grape::Animation> animations;
    for (std::size_t i = 0; i < s.animations.size(); ++i) {
        const grape::SceneAnimation& a = s.animations[i];
        animations.push_back(engine.create_animation(a.path, a.duration, a.def(), [&out, i](grape::Vec2 p, double) { out[i] = p; }));
    }
    std::vector<grape::Timeline> timelines(s.timelines.size());
    const std::function<void(std::size_t)> build = [&](std::size_t k) {
        if (timelines[k]) return;
        const grape::SceneTimeline& tl = s.timelines[k];
        grape::Timeline t = engine.create_timeline({.delay = tl.delay, .repeat = tl.repeat, .repeat_delay = tl.repeat_delay,
                                                    .yoyo = tl.yoyo, .time_scale = tl.time_scale});
        for (const grape::SceneTimelineChild& c : tl.children) {
            switch (c.kind) {
                case grape::SceneTimelineChildKind::animation:
                    for (std::size_t i = 0; i < s.animations.size(); ++i)
                        if (s.animations[i].name == c.name) t.add(animations[i], c.at);
                    break;
                case grape::SceneTimelineChildKind::timeline:
                    for (std::size_t n = 0; n < s.timelines.size(); ++n)
                        if (s.timelines[n].name == c.name) {
                            build(n);
                            t.add(timelines[n], c.at);
                        }
                    break;
                case grape::SceneTimelineChildKind::label: t.label(c.name, c.at); break;
                case grape::SceneTimelineChildKind::gap: t.gap(c.gap, c.at); break;
                case grape::SceneTimelineChildKind::tween: break;  // properties: test_scene_values.cpp
                case grape::SceneTimelineChildKind::animation3: break;  // 3-D animations: test_scene3.cpp
            }
        }
        timelines[k] = t;
    };
    for (std::size_t k = 0; k < s.timelines.size(); ++k) build(k);
}

// scenes/timeline_cutscene.json by hand. flourish (time scale 2): spin 0 → 4.25 (two plays of
// 2 s, a repeat delay of 0.25 s between), pulse 0.25 → 2.25; one play 4.25 s, 2.125 s in
// intro. intro: slide 0 → 1, label landed at 1, drop at landed − 0.25 = 0.75 → 2.25, a gap
// 2.25 → 2.75, flourish 2.75 → 4.875. intro waits 0.5 s, plays forwards over scene time
// [0.5, 5.375], holds at its end for 0.5 s, then plays backwards over [5.875, 10.75].
// So intro's time i(t) is t − 0.5 on the first play and 4.875 − (t − 5.875) on the second;
// flourish's is (i − 2.75)·2 clamped to [0, 4.25] (before its start it rests at 0); each
// animation's is its parent's minus its start.
struct HandTime {
    double t;          // scene time
    const char* name;  // animation
    double child;      // the animation's own time, derived by hand
};
const HandTime hand_times[] = {
    {0.25, "slide", 0.0},    // intro still waiting: at i = 0
    {0.25, "drop", -0.75},
    {1.0, "slide", 0.5},     // i = 0.5
    {1.0, "drop", -0.25},    // not started: rests at its start
    {2.0, "slide", 1.5},     // i = 1.5: slide ended, at its end
    {2.0, "drop", 0.75},
    {3.5, "spin", 0.5},      // i = 3: flourish at 0.5
    {3.5, "pulse", 0.25},
    {4.0, "spin", 1.5},      // i = 3.5: flourish at 1.5
    {4.0, "pulse", 1.25},    // pulse's second play, backwards (yoyo)
    {4.3, "spin", 2.1},      // i = 3.8: flourish at 2.1, in spin's repeat delay: at the end of its first play
    {4.5, "spin", 2.5},      // i = 4: flourish at 2.5, spin 0.25 s into its second play
    {5.5, "spin", 4.25},     // intro's repeat delay: held at i = 4.875, everything at its end
    {5.5, "slide", 4.875},
    {6.0, "spin", 4.0},      // backwards: i = 4.875 − 0.125 = 4.75, flourish at 4
    {6.0, "drop", 4.0},
    {9.0, "drop", 1.0},      // i = 4.875 − 3.125 = 1.75
    {9.0, "slide", 1.75},
    {9.0, "spin", 0.0},      // intro at 1.75, before flourish's start 2.75: flourish rests at 0
    {20.0, "slide", 0.0},    // intro ended backwards, at i = 0
    {20.0, "drop", -0.75},
    {20.0, "spin", 0.0},
};

TEST(SceneTimelines, CutSceneMatchesChildTimesDerivedByHand) {
    const Scene s = grape::load_scene_file(std::filesystem::path(GRAPE_SCENES_DIR) / "timeline_cutscene.json");
    const SceneTiming timing(s);
    ASSERT_EQ(s.timelines.size(), 2u);
    EXPECT_EQ(timing.layout(1).duration, 4.875);
    EXPECT_EQ(timing.layout(0).duration, 4.25);
    EXPECT_EQ(timing.layout(0).parent, 1);
    EXPECT_EQ(timing.layout(1).parent, -1);
    EXPECT_EQ(timing.layout(1).end_time, 10.75);
    for (const HandTime& h : hand_times) {
        const std::size_t i = index_of(s, h.name);
        const grape::SceneAnimation& a = s.animations[i];
        const double expected = grape::progress_at(a.def(), a.duration, h.child);
        // The player composes timeline_local_time down two levels in its own order: times of
        // ~10 s carry a few ulps (1e-14 s), doubled by flourish's time scale; through a curve
        // slope ≤ π/2 per 1 s that is ≤ 1e-13 of u, and ≤ 1e-10 on paths of ≤ 510 units per u.
        EXPECT_NEAR(timing.animation_time(i, h.t), h.child, 1e-13) << h.name << " at " << h.t;
        EXPECT_NEAR(timing.progress(i, h.t), expected, 1e-13) << h.name << " at " << h.t;
        const grape::Vec2 p = a.path.point(timing.progress(i, h.t));
        const grape::Vec2 q = a.path.point(expected);
        EXPECT_NEAR(p.x, q.x, 1e-10) << h.name << " at " << h.t;
        EXPECT_NEAR(p.y, q.y, 1e-10) << h.name << " at " << h.t;
    }
    // Spot values: slide halfway at t = 1; spin 3/4 round at t = 4; in the repeat delays the
    // state holds (spin at the end of a play, u = 1).
    EXPECT_NEAR(timing.progress(index_of(s, "slide"), 1.0), 0.5, 1e-15);
    EXPECT_NEAR(timing.progress(index_of(s, "spin"), 4.0), 0.75, 1e-14);
    EXPECT_NEAR(timing.progress(index_of(s, "spin"), 4.3), 1.0, 1e-14);
    // The free animation plays by the scene's time.
    const std::size_t wave = index_of(s, "wave");
    EXPECT_EQ(timing.driver(wave), -1);
    for (double t : {0.0, 1.3, 5.0, 17.25}) EXPECT_EQ(timing.progress(wave, t), s.animations[wave].progress(t));
    EXPECT_EQ(timing.end_time(), HUGE_VAL);  // the wave repeats forever
}

// --- a reference model, written apart from the anim module: walk play after play --------

struct Timing {
    double delay = 0.0;
    int repeat = 0;
    double repeat_delay = 0.0;
    bool yoyo = false;
    bool reversed = false;
    double time_scale = 1.0;
};

// Seconds into one play of `length` (mirrored on backward plays: the distance from the
// play's start in the direction of travel turned back into the play's own time) at t
// seconds of the parent.
double reference_local(const Timing& g, double length, double t) {
    double s = t * g.time_scale - g.delay;
    const auto backward = [&](int k) { return g.reversed != (g.yoyo && k % 2 == 1); };
    if (s < 0.0) return backward(0) ? length : 0.0;
    for (int k = 0;; ++k) {
        const bool last = g.repeat >= 0 && k == g.repeat;
        if (s < length || last) {
            const double f = std::min(s, length);
            return backward(k) ? length - f : f;
        }
        s -= length;
        if (s < g.repeat_delay) return backward(k) ? 0.0 : length;  // holds where the play ended
        s -= g.repeat_delay;
    }
}

double reference_length(const Timing& g, double length) {
    const double plays = g.repeat + 1.0;
    return (g.delay + length * plays + g.repeat_delay * (plays - 1.0)) / g.time_scale;
}

// Random trees three timelines deep (root ⊃ middle ⊃ leaf), each holding a few animations at
// absolute starts, with random delays, repeats, repeat delays, yoyo and time scales; every
// animation's progress at random scene times against the reference model, and frame by
// frame against the engine's timelines built from the same scene.
TEST(SceneTimelines, RandomNestedTreesAgreeWithAReferenceModel) {
    std::mt19937_64 rng(grape::testing::test_seed(12));
    std::uniform_real_distribution<double> unit(0, 1);
    const char* curves[] = {"linear", "quad-in-out", "cubic-out"};
    for (int round = 0; round < 60; ++round) {
        Scene s;
        std::vector<Timing> anim_timing;
        const auto timing_of = [&](bool timeline) {
            Timing g;
            g.delay = rng() % 2 ? 0.0 : unit(rng);
            g.repeat = static_cast<int>(rng() % 3);
            g.repeat_delay = rng() % 2 ? 0.0 : 0.5 * unit(rng);
            g.yoyo = rng() % 2 == 0;
            g.reversed = !timeline && rng() % 3 == 0;
            g.time_scale = timeline ? 0.5 + 1.5 * unit(rng) : 1.0;
            return g;
        };
        const char* names[] = {"leaf", "middle", "root"};
        std::vector<Timing> tl_timing;
        std::vector<std::vector<double>> starts(3);
        std::vector<double> lengths(3);
        for (int level = 0; level < 3; ++level) {
            grape::SceneTimeline tl;
            tl.name = names[level];
            const Timing g = timing_of(true);
            tl.delay = g.delay, tl.repeat = g.repeat, tl.repeat_delay = g.repeat_delay, tl.yoyo = g.yoyo, tl.time_scale = g.time_scale;
            double length = 0.0;
            const int count = 1 + static_cast<int>(rng() % 3);
            for (int c = 0; c < count; ++c) {
                grape::SceneAnimation a;
                a.name = std::string(names[level]) + "_" + std::to_string(c);
                a.path = grape::LinearPath({0, 0}, {1, 0});
                a.curve = grape::parse_curve(curves[rng() % 3]);
                a.duration = 0.25 + unit(rng);
                const Timing ag = timing_of(false);
                a.delay = ag.delay, a.repeat = ag.repeat, a.repeat_delay = ag.repeat_delay, a.yoyo = ag.yoyo, a.reversed = ag.reversed;
                const double start = 2.0 * unit(rng);
                tl.children.push_back({.name = a.name, .at = grape::timeline_position_at(start)});
                length = std::max(length, start + reference_length(ag, a.duration));
                starts[level].push_back(start);
                anim_timing.push_back(ag);
                s.animations.push_back(a);
            }
            if (level > 0) {  // the level below, placed after this level's animations
                const double start = 2.0 * unit(rng);
                tl.children.push_back({.kind = grape::SceneTimelineChildKind::timeline, .name = names[level - 1],
                                       .at = grape::timeline_position_at(start)});
                length = std::max(length, start + reference_length(tl_timing.back(), lengths[level - 1]));
                starts[level].push_back(start);
            }
            lengths[level] = length;
            tl_timing.push_back(g);
            s.timelines.push_back(tl);
        }
        const SceneTiming timing(s);
        for (int level = 0; level < 3; ++level)
            ASSERT_NEAR(timing.layout(level).duration, lengths[level], 1e-12) << "round " << round << " level " << level;
        const double total = reference_length(tl_timing[2], lengths[2]);
        for (int k = 0; k < 200; ++k) {
            const double t = (total + 1.0) * unit(rng);
            // Each level's time, top down, by the reference model.
            double local[3];
            local[2] = reference_local(tl_timing[2], lengths[2], t);
            local[1] = reference_local(tl_timing[1], lengths[1], local[2] - starts[2].back());
            local[0] = reference_local(tl_timing[0], lengths[0], local[1] - starts[1].back());
            std::size_t i = 0;
            for (int level = 0; level < 3; ++level) {
                EXPECT_NEAR(timing.timeline_time(level, t), local[level], 1e-11) << "round " << round << " t " << t;
                for (std::size_t c = 0; c < s.timelines[level].children.size(); ++c, ++i) {
                    if (s.timelines[level].children[c].kind != grape::SceneTimelineChildKind::animation) {
                        --i;
                        continue;
                    }
                    const grape::SceneAnimation& a = s.animations[i];
                    const double f = reference_local(anim_timing[i], a.duration, local[level] - starts[level][c]);
                    const double expected = a.curve(f / a.duration);
                    // Times of ≤ 30 s carry a few ulps (1e-14 s) per level, scaled by time
                    // scales ≤ 2 at each of three levels: ≤ 1e-12 s, through a curve slope ≤ 3
                    // per duration ≥ 0.25 s: ≤ 1.2e-11 of u.
                    ASSERT_NEAR(timing.progress(i, t), expected, 2e-11)
                        << "round " << round << " t " << t << " " << a.name << " child time " << local[level] - starts[level][c];
                }
            }
        }
        // The engine's timelines, built from the same scene, tick to the same states.
        grape::Engine engine;
        std::vector<grape::Vec2> engine_at;
        build_in_engine(s, engine, engine_at);
        const double dt = 1.0 / 64.0;  // exact in binary: engine time is k/64 with no drift
        int compared = 0, frames = 0;
        for (int k = 1; k * dt <= total + 1.0; ++k, ++frames) {
            engine.tick(dt);
            for (std::size_t i = 0; i < s.animations.size(); ++i) {
                if (std::isnan(engine_at[i].x)) continue;  // not written yet
                ++compared;
                // The path runs from (0, 0) to (1, 0): x is u. The same bound as above.
                ASSERT_NEAR(engine_at[i].x, timing.progress(i, k * dt), 2e-11)
                    << "round " << round << " t " << k * dt << " " << s.animations[i].name;
            }
        }
        // Most frames of most animations: an animation is written once its timeline reaches it.
        EXPECT_GT(compared, frames * static_cast<int>(s.animations.size()) / 4) << "round " << round;
    }
}

// Three nested timelines at time scale 1e300: the outer one lasts 1e-900 s, which underflows
// to 0. After its start the animation has ended: at its end (u = 1) at any later time, at its
// start at time 0 itself, as exact arithmetic gives for every time a double can hold.
TEST(SceneTimelines, TimeScalesWhoseLengthsUnderflowStillReachTheEnd) {
    const Scene s = grape::load_scene(R"({
        "animations": [{"name": "a", "path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 1}],
        "timelines": [{"name": "inner", "time_scale": 1e300, "children": [{"animation": "a"}]},
                      {"name": "middle", "time_scale": 1e300, "children": [{"timeline": "inner"}]},
                      {"name": "outer", "time_scale": 1e300, "children": [{"timeline": "middle"}]}]})");
    const SceneTiming timing(s);
    EXPECT_EQ(timing.progress(0, 0.0), 0.0);
    for (const double t : {1e-300, 1.0, 2.0}) EXPECT_EQ(timing.progress(0, t), 1.0) << t;
    // Two levels underflow as well (the outer lasts 1e-600 s): the same answer.
    const Scene two = grape::load_scene(R"({
        "animations": [{"name": "a", "path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 1}],
        "timelines": [{"name": "inner", "time_scale": 1e300, "children": [{"animation": "a"}]},
                      {"name": "outer", "time_scale": 1e300, "children": [{"timeline": "inner"}]}]})");
    const SceneTiming timing_two(two);
    for (const double t : {1e-300, 1.0}) EXPECT_EQ(timing_two.progress(0, t), 1.0) << t;
    for (std::size_t k = 0; k < timing.timeline_count(); ++k)  // drawn playheads stay on their strips
        EXPECT_LE(timing.timeline_time(k, 1.0), timing.layout(k).duration) << k;
}

TEST(SceneTimelines, SaveAndLoadGiveTheSameTimelines) {
    const Scene s = grape::load_scene_file(std::filesystem::path(GRAPE_SCENES_DIR) / "timeline_cutscene.json");
    Scene edited = s;
    // Every position form, written back as text and read again.
    auto& children = edited.timelines[1].children;
    children[3].at = grape::parse_timeline_position("-=0.125");
    children.push_back({.kind = grape::SceneTimelineChildKind::label, .name = "end", .at = grape::parse_timeline_position(">+0.1")});
    children.push_back({.kind = grape::SceneTimelineChildKind::gap, .gap = 0.3, .at = grape::parse_timeline_position("<-0.2")});
    children.push_back({.kind = grape::SceneTimelineChildKind::label, .name = "late", .at = grape::parse_timeline_position("landed+=0.7")});
    children.push_back({.kind = grape::SceneTimelineChildKind::label, .name = "fixed", .at = grape::timeline_position_at(0.1)});
    edited.animations[0].repeat_delay = 0.2;
    for (const Scene& original : {s, edited}) {
        const Scene back = grape::load_scene(grape::save_scene(original));
        ASSERT_EQ(back.timelines.size(), original.timelines.size());
        for (std::size_t k = 0; k < original.timelines.size(); ++k) {
            const grape::SceneTimeline& a = original.timelines[k];
            const grape::SceneTimeline& b = back.timelines[k];
            EXPECT_EQ(a.name, b.name);
            EXPECT_EQ(a.delay, b.delay);
            EXPECT_EQ(a.repeat, b.repeat);
            EXPECT_EQ(a.repeat_delay, b.repeat_delay);
            EXPECT_EQ(a.yoyo, b.yoyo);
            EXPECT_EQ(a.time_scale, b.time_scale);
            ASSERT_EQ(a.children.size(), b.children.size());
            for (std::size_t c = 0; c < a.children.size(); ++c) {
                EXPECT_EQ(a.children[c].kind, b.children[c].kind) << k << " " << c;
                EXPECT_EQ(a.children[c].name, b.children[c].name) << k << " " << c;
                EXPECT_EQ(a.children[c].gap, b.children[c].gap) << k << " " << c;
                EXPECT_EQ(a.children[c].at.anchor, b.children[c].at.anchor) << k << " " << c;
                EXPECT_EQ(a.children[c].at.label, b.children[c].at.label) << k << " " << c;
                EXPECT_EQ(a.children[c].at.offset, b.children[c].at.offset) << k << " " << c;
            }
        }
        for (std::size_t i = 0; i < original.animations.size(); ++i)
            EXPECT_EQ(original.animations[i].repeat_delay, back.animations[i].repeat_delay);
        // The same layout, and the same state at every sampled time.
        const SceneTiming ta(original), tb(back);
        for (std::size_t i = 0; i < original.animations.size(); ++i)
            for (int k = 0; k <= 240; ++k) ASSERT_EQ(ta.progress(i, k / 20.0), tb.progress(i, k / 20.0)) << i << " " << k;
    }
}

// A driven animation's own repeat delay holds its end state between plays.
TEST(SceneTimelines, AnimationRepeatDelayHoldsTheEndOfThePlay) {
    const Scene s = grape::load_scene(R"({"animations": [
        {"name": "a", "path": {"kind": "linear", "start": [0, 0], "end": [8, 0]}, "duration": 1, "repeat": 2, "repeat_delay": 0.5}]})");
    const grape::SceneAnimation& a = s.animations[0];
    EXPECT_EQ(a.repeat_delay, 0.5);
    EXPECT_EQ(a.end_time(), 4.0);  // 3 plays of 1 s and 2 repeat delays of 0.5 s
    EXPECT_EQ(a.position(0.5).x, 4.0);
    EXPECT_EQ(a.position(1.25).x, 8.0);  // held at the end of the first play
    EXPECT_EQ(a.position(1.75).x, 2.0);  // 0.25 s into the second
    EXPECT_EQ(a.position(9.0).x, 8.0);
}

// The engine agrees: a top-level timeline playing once at time scale 1 drives each animation
// as the engine plays it created with the timeline's delay plus the animation's start added
// to its own delay (random starts, timings and curves; fixed seed).
TEST(SceneTimelines, AgreeWithTheEngineForOnePlay) {
    std::mt19937_64 rng(grape::testing::test_seed(7));
    std::uniform_real_distribution<double> unit(0, 1);
    for (int round = 0; round < 20; ++round) {
        Scene s;
        grape::SceneTimeline tl;
        tl.name = "t";
        tl.delay = unit(rng);
        grape::Engine engine;
        std::vector<grape::Vec2> last(3);
        std::vector<double> starts;
        for (int i = 0; i < 3; ++i) {
            grape::SceneAnimation a;
            a.name = "a" + std::to_string(i);
            a.path = grape::CubicBezierPath({20, 20}, {400, 200}, {400, 600}, {600, 600});
            a.curve = grape::parse_curve(i == 0 ? "quad-in-out" : i == 1 ? "back-out(2.5)" : "linear");
            a.duration = 0.3 + unit(rng);
            a.delay = rng() % 2 ? 0.0 : 0.5 * unit(rng);
            a.repeat = static_cast<int>(rng() % 3);
            a.repeat_delay = rng() % 2 ? 0.0 : 0.5 * unit(rng);
            a.yoyo = rng() % 2 == 0;
            a.reversed = rng() % 3 == 0;
            const double start = 2.0 * unit(rng);
            tl.children.push_back({.name = a.name, .at = grape::timeline_position_at(start)});
            grape::AnimationDef def = a.def();
            def.delay += tl.delay + start;
            engine.create_animation(a.path, a.duration, def, [&last, i](grape::Vec2 p, double) { last[i] = p; });
            starts.push_back(start);
            s.animations.push_back(a);
        }
        s.timelines.push_back(tl);
        const SceneTiming timing(s);
        const double dt = 1.0 / 64.0;  // exact in binary: engine time is k/64 with no drift
        for (int k = 1; k <= 64 * 10; ++k) {
            engine.tick(dt);
            for (int i = 0; i < 3; ++i) {
                if (k * dt <= tl.delay + starts[i] + s.animations[i].delay) continue;  // nothing written while waiting
                const grape::Vec2 p = s.animations[i].path.point(timing.progress(i, k * dt));
                // The same curve and path at a play fraction computed in different orders (the
                // timeline's time minus a start, against one delay): a few ulps of τ, times
                // |path′| ≤ ~1200 and the curve slope ≤ ~10, stays under 1e-9.
                ASSERT_NEAR(last[i].x, p.x, 1e-9) << "round " << round << " t " << k * dt << " animation " << i;
                ASSERT_NEAR(last[i].y, p.y, 1e-9) << "round " << round << " t " << k * dt << " animation " << i;
            }
        }
    }
}

// The scene's player and the engine's timelines agree on the cut-scene (nested, repeats,
// yoyo, repeat delays, time scale, labels, a gap), frame by frame.
TEST(SceneTimelines, CutSceneAgreesWithTheEnginesTimelines) {
    const Scene s = grape::load_scene_file(std::filesystem::path(GRAPE_SCENES_DIR) / "timeline_cutscene.json");
    const SceneTiming timing(s);
    grape::Engine engine;
    std::vector<grape::Vec2> engine_at;
    build_in_engine(s, engine, engine_at);
    const double dt = 1.0 / 64.0;  // exact in binary: engine time is k/64 with no drift
    int compared = 0;
    for (int k = 1; k <= 64 * 12; ++k) {
        engine.tick(dt);
        for (std::size_t i = 0; i < s.animations.size(); ++i) {
            if (std::isnan(engine_at[i].x)) continue;  // not written yet
            const grape::Vec2 p = s.animations[i].path.point(timing.progress(i, k * dt));
            // Both compose timeline_local_time and progress_at, in their own orders: a few ulps
            // of ~10 s of time (scaled by 2 in flourish) through curve slopes ≤ π/2 per second
            // and paths of ≤ 510 units per u: well under 1e-9.
            ASSERT_NEAR(engine_at[i].x, p.x, 1e-9) << s.animations[i].name << " at " << k * dt;
            ASSERT_NEAR(engine_at[i].y, p.y, 1e-9) << s.animations[i].name << " at " << k * dt;
            ++compared;
        }
    }
    EXPECT_GT(compared, 64 * 10 * 4);  // nearly every frame of every animation was compared
}

// Bad timelines: each error names the JSON pointer of the bad value and why.
void expect_error(const std::string& json, const std::string& pointer, const std::string& why) {
    try {
        (void)grape::load_scene(json);
        ADD_FAILURE() << "no error for " << json;
    } catch (const grape::Error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("scene: " + pointer + ": ", 0), 0u) << what;
        EXPECT_NE(what.find(why), std::string::npos) << what;
    }
}

std::string scene_with(const std::string& timelines) {
    return R"({"animations": [
        {"name": "a", "path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 1},
        {"name": "b", "path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 2},
        {"name": "forever", "path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 1, "repeat": -1}],
      "timelines": )" + timelines + "}";
}

TEST(SceneTimelines, ErrorsNameTheJsonPointer) {
    expect_error(scene_with(R"([{"name": "t", "children": [{"animation": "a"}, {"animation": "b", "at": "intro+1"}]}])"),
                 "/timelines/0/children/1/at", "intro");
    expect_error(scene_with(R"([{"name": "t", "children": [{"animation": "zz"}]}])"), "/timelines/0/children/0/animation",
                 "no animation named \"zz\"");
    expect_error(scene_with(R"([{"name": "t", "children": [{"timeline": "u"}]}])"), "/timelines/0/children/0/timeline",
                 "no timeline named \"u\"");
    expect_error(scene_with(R"([{"name": "t", "children": [{"timeline": "t"}]}])"), "/timelines/0/children/0/timeline",
                 "contains itself");
    expect_error(scene_with(R"([{"name": "t", "children": [{"timeline": "u"}]}, {"name": "u", "children": [{"timeline": "t"}]}])"),
                 "/timelines/1/children/0/timeline", "a cycle of timelines");
    expect_error(scene_with(R"([{"name": "t", "children": [{"animation": "a"}, {"animation": "b", "at": "<-0.5"}]}])"),
                 "/timelines/0/children/1/at", "negative");
    expect_error(scene_with(R"([{"name": "t", "children": [{"animation": "a"}, {"animation": "a"}]}])"),
                 "/timelines/0/children/1/animation", "is already placed at /timelines/0/children/0");
    expect_error(scene_with(R"([{"name": "t", "children": [{"animation": "a"}]}, {"name": "u", "children": [{"animation": "a"}]}])"),
                 "/timelines/1/children/0/animation", "is already placed at /timelines/0/children/0");
    expect_error(scene_with(R"([{"name": "t", "children": []}, {"name": "u", "children": [{"timeline": "t"}, {"timeline": "t"}]}])"),
                 "/timelines/1/children/1/timeline", "is already placed");
    expect_error(scene_with(R"([{"name": "t", "children": [{"animation": "forever"}]}])"), "/timelines/0/children/0/animation",
                 "repeats forever");
    expect_error(scene_with(R"([{"name": "t", "repeat": -1, "children": []}, {"name": "u", "children": [{"timeline": "t"}]}])"),
                 "/timelines/1/children/0/timeline", "repeats forever");
    expect_error(scene_with(R"([{"name": "t", "children": []}, {"name": "t", "children": []}])"), "/timelines/1/name",
                 "duplicate name");
    expect_error(scene_with(R"([{"name": "t", "children": [{"animation": "a", "label": "x"}]}])"), "/timelines/0/children/0",
                 "exactly one of");
    expect_error(scene_with(R"([{"name": "t", "children": [{"at": 1}]}])"), "/timelines/0/children/0", "exactly one of");
    expect_error(scene_with(R"([{"name": "t", "children": [{"animation": "a", "at": [1]}]}])"), "/timelines/0/children/0/at",
                 "expected a number");
    expect_error(scene_with(R"([{"name": "t", "children": [{"gap": -1}]}])"), "/timelines/0/children/0/gap", "must not be negative");
    expect_error(scene_with(R"([{"name": "t", "time_scale": 0, "children": []}])"), "/timelines/0/time_scale", "must be positive");
    expect_error(scene_with(R"([{"name": "t", "children": [], "speed": 2}])"), "/timelines/0/speed", "unknown field");
    expect_error(scene_with(R"([{"name": "t"}])"), "/timelines/0", "missing field \"children\"");
    expect_error(scene_with(R"([{"name": "t", "children": [{"label": "x"}, {"label": "x"}]}])"), "/timelines/0/children/1",
                 "x");
    expect_error(scene_with(R"([{"name": "t", "children": [{"animation": "a", "at": "later"}, {"label": "later"}]}])"),
                 "/timelines/0/children/0/at", "defined before use");
    expect_error(scene_with(R"([{"name": "t", "children": [{"label": "take-2"}]}])"), "/timelines/0/children/0/label",
                 "cannot be a label");
    expect_error(scene_with(R"([{"name": "t", "children": [{"animation": "a", "at": -1}]}])"), "/timelines/0/children/0/at",
                 "negative");
    expect_error(R"({"animations": [{"path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 1, "repeat_delay": -1}]})",
                 "/animations/0/repeat_delay", "must not be negative");
    // Two animations named alike cannot be told apart by a timeline.
    expect_error(R"({"animations": [{"name": "a", "path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 1},
                                     {"name": "a", "path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 1}],
                     "timelines": [{"name": "t", "children": [{"animation": "a"}]}]})",
                 "/timelines/0/children/0/animation", "ambiguous");
    // Nesting deeper than 32 is refused (the evaluation recurses once per level).
    std::string deep = "[";
    for (int k = 0; k < 40; ++k)
        deep += (k ? ", " : "") + std::string(R"({"name": "t)") + std::to_string(k) + R"(", "children": [)" +
                (k + 1 < 40 ? R"({"timeline": "t)" + std::to_string(k + 1) + "\"}" : std::string(R"({"animation": "a"})")) + "]}";
    expect_error(scene_with(deep + "]"), "/timelines/31/children/0/timeline", "nested deeper than 32");
}

// Built in code, a scene's timelines are checked the same way when timed.
TEST(SceneTimelines, TimingASceneBuiltInCodeChecksIt) {
    Scene s;
    grape::SceneTimeline t;
    t.name = "t";
    t.children.push_back({.name = "nobody"});
    s.timelines.push_back(t);
    EXPECT_THROW((void)SceneTiming(s), grape::Error);
}

}  // namespace
