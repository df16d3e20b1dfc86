// Timelines in the engine: placement, play structure (delay, repeats, repeat delays, yoyo,
// time scale), run-time reverse, callbacks and events in order, seek, nesting, handlers that
// change anything (the fast tick, allocation and storage at scale: test_timeline_fast.cpp).
#include <grape/error.hpp>
#include <grape/timeline.hpp>

#include "anim/timeline_impl.hpp"  // the test hook for generations
#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

using grape::Animation;
using grape::AnimationDef;
using grape::Engine;
using grape::Timeline;
using grape::TimelineDef;
using grape::testing::expect_error;

namespace {

struct Point {
    double x = -999.0;  // sentinel: "never written"
    double y = -999.0;
};

const grape::LinearPath unit_line({0, 0}, {1, 0});  // x is the progress u

TEST(Timeline, SequenceDrivesOneChildAfterAnother) {
    Engine engine;
    Point a, b, c;
    Timeline tl = engine.create_timeline();
    tl.add(engine.create_2d_animation(a, unit_line, 1.0))
        .add(engine.create_2d_animation(b, unit_line, 2.0))
        .add(engine.create_2d_animation(c, unit_line, 1.0), "<+0.5");  // with b, ½ s in
    EXPECT_EQ(tl.duration(), 3.0);
    EXPECT_EQ(b.x, 0.0);  // resting at their starts
    EXPECT_EQ(c.x, 0.0);
    std::vector<std::string> events;
    tl.on_start([&] { events.push_back("start"); });
    tl.on_complete([&] { events.push_back("complete"); });
    engine.tick(0.25);
    EXPECT_EQ(a.x, 0.25);
    EXPECT_EQ(b.x, 0.0);
    engine.tick(1.0);  // 1.25
    EXPECT_EQ(a.x, 1.0);  // at its end
    EXPECT_EQ(b.x, 0.125);
    EXPECT_EQ(c.x, 0.0);  // starts at 1.5
    engine.tick(0.5);  // 1.75
    EXPECT_EQ(c.x, 0.25);
    engine.tick(10.0);
    EXPECT_EQ(b.x, 1.0);
    EXPECT_EQ(c.x, 1.0);
    EXPECT_EQ(events, (std::vector<std::string>{"start", "complete"}));
    EXPECT_TRUE(tl.alive());  // timelines stay until killed: they can be reversed or sought
    EXPECT_EQ(tl.time(), 3.0);
    EXPECT_EQ(engine.size(), 3u);  // children stay alive with it
    tl.kill();
    EXPECT_FALSE(tl.alive());
    EXPECT_EQ(engine.size(), 0u);
}

// --- random trees -----------------------------------------------------------------------------

// A timeline tree described as data, built into an engine, and laid out by the pure layout
// (the reference side of the tests below).
struct Item {
    enum Kind { animation, timeline, callback, label, gap } kind;
    std::string at{};
    double duration = 0.0;  // animation per play, gap
    AnimationDef def{};     // animation
    int node = -1;          // timeline: the child node
    int id = -1;            // callback: its number in the log
    std::string name{};     // label
};
struct Node {
    TimelineDef def;
    std::vector<Item> items;
};

struct Tree {
    std::vector<Node> nodes;  // nodes[0] is the root
    int callbacks = 0;
};

std::string number(double x) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return buffer;
}

int make_node(Tree& tree, std::mt19937_64& rng, int depth, bool root) {
    std::uniform_real_distribution<double> unit(0, 1);
    const int index = static_cast<int>(tree.nodes.size());
    tree.nodes.emplace_back();
    Node node;
    node.def = {.delay = unit(rng) < 0.5 ? 0.0 : 0.5 * unit(rng),
                .repeat = root && rng() % 4 == 0 ? -1 : static_cast<int>(rng() % 3),
                .repeat_delay = unit(rng) < 0.5 ? 0.0 : 0.3 * unit(rng),
                .yoyo = rng() % 2 == 0,
                .time_scale = 0.5 + 1.5 * unit(rng)};
    std::vector<std::string> labels;
    const int count = 2 + static_cast<int>(rng() % 4);
    for (int k = 0; k < count; ++k) {
        Item item{};
        const auto roll = rng() % 10;
        if (roll < 4) item.kind = Item::animation;
        else if (roll < 6) item.kind = depth < 3 ? Item::timeline : Item::animation;
        else if (roll < 8) item.kind = Item::callback;
        else if (roll < 9) item.kind = Item::label;
        else item.kind = Item::gap;
        // Positions: every form, offsets ≥ 0 so that no start is negative.
        switch (rng() % 5) {
            case 0: item.at = ">"; break;
            case 1: item.at = "<+" + number(0.5 * unit(rng)); break;
            case 2: item.at = "+=" + number(0.3 * unit(rng)); break;
            case 3: item.at = number(2.0 * unit(rng) + 0.01); break;
            default:
                if (labels.empty()) {
                    item.at = ">+" + number(0.01 + 0.1 * unit(rng));
                } else {  // one draw after the other: the order of operands of + is unspecified
                    const std::string& label = labels[rng() % labels.size()];
                    item.at = label + "+" + number(0.01 + unit(rng));
                }
                break;
        }
        // Nothing at exactly 0 or at a previous end (which may be 0), and no two points at one
        // time (their order would depend on the direction the inner timeline runs).
        if (item.at == ">") item.at = ">+" + number(0.01 + 0.1 * unit(rng));
        // Nested timelines after everything before them: two running side by side deliver
        // their own callbacks one child after the other within an update (timeline.hpp).
        if (item.kind == Item::timeline) item.at = "+=" + number(0.01 + 0.3 * unit(rng));
        switch (item.kind) {
            case Item::animation:
                item.duration = 0.2 + unit(rng);
                item.def = {.curve = rng() % 2 ? grape::Curve::quad_in_out() : grape::Curve(),
                            .delay = unit(rng) < 0.5 ? 0.0 : 0.2 * unit(rng),
                            .repeat = static_cast<int>(rng() % 3),
                            .repeat_delay = unit(rng) < 0.5 ? 0.0 : 0.2 * unit(rng),
                            .reversed = rng() % 4 == 0,
                            .yoyo = rng() % 2 == 0,
                            .time_scale = 0.5 + 1.5 * unit(rng)};
                break;
            case Item::timeline: item.node = make_node(tree, rng, depth + 1, false); break;
            case Item::callback: item.id = tree.callbacks++; break;
            case Item::label:
                item.name = "l" + std::to_string(index) + "_" + std::to_string(k);
                labels.push_back(item.name);
                break;
            case Item::gap: item.duration = 0.3 * unit(rng); break;
        }
        node.items.push_back(item);
    }
    // A trailing gap: no callback sits at a play's end, where a loop's reset would tie with it.
    node.items.push_back({.kind = Item::gap, .at = "+=0", .duration = 0.05 + 0.2 * unit(rng)});
    tree.nodes[static_cast<std::size_t>(index)] = node;
    return index;
}

Tree random_tree(std::uint64_t seed) {
    std::mt19937_64 rng(grape::testing::test_seed(seed));
    Tree tree;
    make_node(tree, rng, 1, true);
    return tree;
}

struct Built {
    Timeline root;
    std::vector<Animation> animations;
    std::vector<Point> targets;
};

Timeline build_node(Engine& engine, const Tree& tree, int index, Built& out, std::vector<int>& log) {
    const Node& node = tree.nodes[static_cast<std::size_t>(index)];
    Timeline tl = engine.create_timeline(node.def);
    for (const Item& item : node.items) {
        switch (item.kind) {
            case Item::animation: {
                out.targets.emplace_back();
                Animation a = engine.create_animation(unit_line, item.duration, item.def);
                out.animations.push_back(a);
                tl.add(a, item.at);
                break;
            }
            case Item::timeline: tl.add(build_node(engine, tree, item.node, out, log), item.at); break;
            case Item::callback: tl.call([&log, id = item.id] { log.push_back(id); }, item.at); break;
            case Item::label: tl.label(item.name, item.at); break;
            case Item::gap: tl.gap(item.duration, item.at); break;
        }
    }
    return tl;
}

Built build(Engine& engine, const Tree& tree, std::vector<int>& log) {
    Built out;
    out.targets.reserve(1000);
    out.root = build_node(engine, tree, 0, out, log);
    return out;
}

// The reference: every time a callback is crossed, as seconds of the root's own time (delay
// included), found by unfolding each timeline's plays, independently of the engine's sweep.
struct Occurrence {
    double tau;
    int id;
};

struct Laid {
    std::vector<double> start;
    double duration = 0.0;
};

std::vector<Laid> lay_out(const Tree& tree) {
    std::vector<Laid> laid(tree.nodes.size());
    // Children first: a node's entries need its nested timelines' lengths.
    std::function<double(int)> length = [&](int index) -> double {
        const Node& node = tree.nodes[static_cast<std::size_t>(index)];
        std::vector<grape::TimelineEntry> entries;
        for (const Item& item : node.items) {
            grape::TimelineEntry e{.at = grape::parse_timeline_position(item.at)};
            switch (item.kind) {
                case Item::animation:
                    e.duration = grape::end_time(item.def, item.duration);
                    break;
                case Item::timeline: e.duration = length(item.node); break;
                case Item::callback: e.kind = grape::TimelineEntry::Kind::callback; break;
                case Item::label:
                    e.kind = grape::TimelineEntry::Kind::label;
                    e.label = item.name;
                    break;
                case Item::gap:
                    e.kind = grape::TimelineEntry::Kind::gap;
                    e.duration = item.duration;
                    break;
            }
            entries.push_back(e);
        }
        const grape::TimelineLayout layout = grape::layout_timeline(entries);
        laid[static_cast<std::size_t>(index)] = {layout.start, layout.duration};
        const TimelineDef& d = node.def;
        const double plays = d.repeat + 1.0;
        return (d.delay + plays * layout.duration + (plays - 1.0) * d.repeat_delay) / d.time_scale;
    };
    length(0);
    return laid;
}

// The times (in node `index`'s own seconds) at which its local time `x` is reached, up to
// `horizon`.
std::vector<double> unfold(const Tree& tree, const std::vector<Laid>& laid, int index, double x, double horizon) {
    const TimelineDef& d = tree.nodes[static_cast<std::size_t>(index)].def;
    const double duration = laid[static_cast<std::size_t>(index)].duration;
    std::vector<double> out;
    const double plays = d.repeat < 0 ? 1e9 : d.repeat + 1.0;
    for (double k = 0; k < plays; k += 1.0) {
        const double begin = d.delay + k * (duration + d.repeat_delay);
        // Only endless plays (the root's) are cut: `horizon` is in root seconds, and a nested
        // timeline's own seconds run ahead of them by its parents' time scales.
        if (d.repeat < 0 && begin > horizon) break;
        const bool back = d.yoyo && std::fmod(k, 2.0) == 1.0;
        out.push_back(begin + (back ? duration - x : x));
    }
    return out;
}


// All crossings of every callback in the tree, in root seconds.
std::vector<Occurrence> reference_crossings(const Tree& tree, double horizon) {
    const std::vector<Laid> laid = lay_out(tree);
    // parent of each node and its start there
    std::vector<int> parent(tree.nodes.size(), -1);
    std::vector<double> start_in_parent(tree.nodes.size(), 0.0);
    for (std::size_t n = 0; n < tree.nodes.size(); ++n)
        for (std::size_t k = 0; k < tree.nodes[n].items.size(); ++k)
            if (tree.nodes[n].items[k].kind == Item::timeline) {
                parent[static_cast<std::size_t>(tree.nodes[n].items[k].node)] = static_cast<int>(n);
                start_in_parent[static_cast<std::size_t>(tree.nodes[n].items[k].node)] = laid[n].start[k];
            }
    std::vector<Occurrence> out;
    for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
        for (std::size_t k = 0; k < tree.nodes[n].items.size(); ++k) {
            const Item& item = tree.nodes[n].items[k];
            if (item.kind != Item::callback) continue;
            // Local time in node n → its own seconds → parent local → ... → root seconds.
            std::vector<double> taus = unfold(tree, laid, static_cast<int>(n), laid[n].start[k], horizon);
            for (int node = static_cast<int>(n); parent[static_cast<std::size_t>(node)] >= 0;
                 node = parent[static_cast<std::size_t>(node)]) {
                const int up = parent[static_cast<std::size_t>(node)];
                const double ts = tree.nodes[static_cast<std::size_t>(node)].def.time_scale;
                std::vector<double> next;
                for (const double tau : taus)
                    for (const double t : unfold(tree, laid, up, start_in_parent[static_cast<std::size_t>(node)] + tau / ts, horizon))
                        next.push_back(t);
                taus = std::move(next);
            }
            for (const double tau : taus) out.push_back({tau, item.id});
        }
    }
    std::stable_sort(out.begin(), out.end(), [](const Occurrence& a, const Occurrence& b) { return a.tau < b.tau; });
    return out;
}

double root_total(const Tree& tree) {
    const std::vector<Laid> laid = lay_out(tree);
    const TimelineDef& d = tree.nodes[0].def;
    if (d.repeat < 0) return INFINITY;
    const double plays = d.repeat + 1.0;
    return d.delay + plays * laid[0].duration + (plays - 1.0) * d.repeat_delay;
}

// Callbacks fire in time order in the direction of travel, once per crossing, under random
// trees three deep, random dt (large ones crossing many) and run-time reverses: the engine's
// log equals the reference's crossings between successive root times.
TEST(TimelineEvents, CallbacksMatchTheReferenceUnderRandomTrees) {
    std::mt19937_64 rng(grape::testing::test_seed(5));
    std::uniform_real_distribution<double> unit(0, 1);
    int compared = 0;
    for (std::uint64_t seed = 1; seed <= 400; ++seed) {
        const Tree tree = random_tree(seed);
        Engine engine;
        std::vector<int> log;
        Built built = build(engine, tree, log);
        const double total = root_total(tree);
        const double horizon = std::min(total, 60.0) + 1.0;
        const std::vector<Occurrence> crossings = reference_crossings(tree, horizon);
        std::vector<int> expected;
        double tau = 0.0;
        const double delay = tree.nodes[0].def.delay;
        // A tick that starts more than max_loop_events plays of the root goes straight to the
        // last one (timeline.hpp): only the crossings in the play it leaves and in the one it
        // reaches fire. (Nested timelines play at most three times: never capped.)
        const TimelineDef& root_def = tree.nodes[0].def;
        const double cycle = lay_out(tree)[0].duration + root_def.repeat_delay;
        const double last_play = root_def.repeat < 0 ? INFINITY : root_def.repeat;
        auto play_of = [&](double t) { return t <= delay ? 0.0 : std::min(std::floor((t - delay) / cycle), last_play); };
        for (int step = 0; step < 120; ++step) {
            if (rng() % 8 == 0) {
                if (built.root.reversed()) built.root.play();
                else built.root.reverse();
            }
            const double dt = unit(rng) < 0.1 ? 3.0 * unit(rng) : 0.1 * unit(rng);
            engine.tick(dt);
            const double now = built.root.time() + delay;
            // The reference's crossings between the two times, in the order of travel.
            const double from_play = play_of(tau), to_play = play_of(now);
            const bool skips = std::fabs(to_play - from_play) > grape::max_loop_events;
            auto fires = [&](double t) { return !skips || play_of(t) == from_play || play_of(t) == to_play; };
            if (now > tau) {
                for (const Occurrence& o : crossings)
                    if (o.tau > tau && o.tau <= now && fires(o.tau)) expected.push_back(o.id);
            } else {
                for (auto it = crossings.rbegin(); it != crossings.rend(); ++it)
                    if (it->tau < tau && it->tau >= now && fires(it->tau)) expected.push_back(it->id);
            }
            tau = now;
            if (tau >= horizon - 1.0) break;
        }
        if (log != expected) {
            for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
                const Node& nd = tree.nodes[n];
                std::printf("node %zu: delay %g repeat %d rd %g yoyo %d ts %g\n", n, nd.def.delay, nd.def.repeat,
                            nd.def.repeat_delay, nd.def.yoyo, nd.def.time_scale);
                const auto laid = lay_out(tree);
                for (std::size_t k = 0; k < nd.items.size(); ++k)
                    std::printf("  item %d at %s start %g dur %g node %d id %d\n", nd.items[k].kind, nd.items[k].at.c_str(),
                                laid[n].start[k], nd.items[k].duration, nd.items[k].node, nd.items[k].id);
                std::printf("  duration %g\n", laid[n].duration);
            }
            for (const Occurrence& o : crossings) std::printf("occ %.17g id %d\n", o.tau, o.id);
        }
        ASSERT_EQ(log, expected) << "seed " << seed;
        compared += static_cast<int>(log.size());
    }
    EXPECT_GT(compared, 2000);  // the trees do cross their callbacks
}

// Work per update is bounded: up to max_loop_events plays started in one tick, every crossing
// fires; beyond, the callbacks of the play the tick leaves and of the play it reaches fire and
// the plays between are crossed silently, forward and backward (the random trees above reach
// this only with a few seeds in thousands).
TEST(TimelineEvents, ATickAcrossManyPlaysFiresItsFirstAndLastPlayBeyondMaxLoopEvents) {
    static_assert(grape::max_loop_events == 16);  // the ticks below start 16 and 17 plays
    Engine engine;
    std::vector<double> at;
    std::vector<int> loops;
    Timeline tl = engine.create_timeline({.repeat = -1});
    tl.gap(1.0, 0.0).call([&] { at.push_back(tl.time()); }, 0.5);  // plays of 1 s, a callback halfway
    tl.on_loop([&](int play) { loops.push_back(play); });
    engine.tick(0.25);
    engine.tick(16.0);  // 0.25 → 16.25: 16 plays start, all fire
    std::vector<double> every;
    std::vector<int> each;
    for (int k = 0; k < 16; ++k) every.push_back(k + 0.5), each.push_back(k + 1);
    EXPECT_EQ(at, every);
    EXPECT_EQ(loops, each);
    at.clear();
    loops.clear();
    engine.tick(17.5);  // 16.25 → 33.75: 17 plays start
    EXPECT_EQ(at, (std::vector<double>{16.5, 33.5}));
    EXPECT_EQ(loops, std::vector<int>{33});  // once, for the last play (as for animations)
    EXPECT_EQ(tl.time(), 33.75);
    at.clear();
    loops.clear();
    tl.reverse();
    engine.tick(17.5);  // back to 16.25: play 33's part, then play 16's
    EXPECT_EQ(at, (std::vector<double>{33.5, 16.5}));
    EXPECT_TRUE(loops.empty());  // no loop events going backward
    EXPECT_EQ(tl.time(), 16.25);
    at.clear();
    engine.tick(16.0);  // 16.25 → 0.25 backward: 16 plays, all fire
    std::reverse(every.begin(), every.end());
    EXPECT_EQ(at, every);
}

// Determinism: random trees three deep (repeats, yoyo, repeat delays, time scales at every
// level, reversed and delayed animations), random dt sequences with run-time reverses: the
// state equals what one seek to the same time gives on an identical tree. Both go through
// the same pure functions of the root's time; the root's time differs only by t − delay +
// delay (an ulp of ≤ 100 s, 1.4e-14) times the fastest child speed (three time scales ≤ 2,
// a 0.2 s play, curve slope ≤ 2: 80 per second), 1.1e-12 at most; 1e-12 holds in practice
// because the ulp is of the root's time, not of its bound.
TEST(TimelineDeterminism, AnyDtSequenceGivesTheStateSeekGives) {
    std::mt19937_64 rng(grape::testing::test_seed(17));
    std::uniform_real_distribution<double> unit(0, 1);
    for (std::uint64_t seed = 1000; seed < 1300; ++seed) {
        const Tree tree = random_tree(seed);
        Engine ticked, sought;
        std::vector<int> log_a, log_b;
        Built a = build(ticked, tree, log_a);
        Built b = build(sought, tree, log_b);
        const double total = root_total(tree);
        const double scale = tree.nodes[0].def.time_scale;
        double expected = 0.0;  // the root's own seconds (delay included), modelled separately
        double direction = 1.0;
        const int steps = 1 + static_cast<int>(rng() % 150);
        for (int step = 0; step < steps; ++step) {
            if (rng() % 10 == 0) {
                direction = -direction;
                if (direction < 0) a.root.reverse();
                else a.root.play();
            }
            const double dt = unit(rng) < 0.05 ? 5.0 * unit(rng) : 0.05 * unit(rng);
            ticked.tick(dt);
            expected = std::clamp(expected + dt * scale * direction, 0.0, total);
        }
        const double delay = tree.nodes[0].def.delay;
        // The root's clock: base + Σdt·scale·direction per run-time direction, vs summing each
        // tick: a few ulps per tick of ≤ 100 s.
        ASSERT_NEAR(a.root.time() + delay, expected, 1e-13 * 100 * steps) << "seed " << seed;
        b.root.seek(a.root.time());
        ASSERT_EQ(a.animations.size(), b.animations.size());
        for (std::size_t k = 0; k < a.animations.size(); ++k) {
            EXPECT_NEAR(a.animations[k].value().x, b.animations[k].value().x, 1e-12) << "seed " << seed << " animation " << k;
            EXPECT_EQ(a.animations[k].repetition(), b.animations[k].repetition()) << "seed " << seed << " animation " << k;
        }
        EXPECT_TRUE(log_b.empty());  // a seek fires nothing
    }
}

// seek(T, true) fires what ticking to T fires, in the same order.
TEST(TimelineEvents, SeekWithEventsFiresTheCrossedCallbacksInOrder) {
    for (std::uint64_t seed = 2000; seed < 2100; ++seed) {
        const Tree tree = random_tree(seed);
        Engine ticked, sought;
        std::vector<int> log_a, log_b;
        Built a = build(ticked, tree, log_a);
        Built b = build(sought, tree, log_b);
        const double t = std::min(root_total(tree), 20.0) * 0.7;
        ticked.tick(t / a.root.time_scale());
        b.root.seek(a.root.time(), true);
        EXPECT_EQ(log_a, log_b) << "seed " << seed;
        for (std::size_t k = 0; k < a.animations.size(); ++k)
            EXPECT_EQ(a.animations[k].value().x, b.animations[k].value().x) << "seed " << seed;
    }
}

// Closed forms: a 2 s timeline of one linear child, delay ½, repeat 2 with ¼ s repeat delay,
// yoyo, time scale 2: in engine seconds plays run over [0.25, 1.25], [1.375, 2.375],
// [2.5, 3.5]; the child follows timeline_local_time.
TEST(Timeline, PlayStructureFollowsTheTimingModel) {
    Engine engine;
    Point p;
    const TimelineDef def{.delay = 0.5, .repeat = 2, .repeat_delay = 0.25, .yoyo = true, .time_scale = 2.0};
    Timeline tl = engine.create_timeline(def);
    tl.add(engine.create_2d_animation(p, unit_line, 2.0));
    std::vector<std::pair<std::string, double>> events;
    double now = 0.0;
    tl.on_start([&] { events.emplace_back("start", now); });
    tl.on_loop([&](int play) { events.emplace_back("loop" + std::to_string(play), now); });
    tl.on_complete([&] { events.emplace_back("complete", now); });
    const AnimationDef model{.delay = def.delay, .repeat = def.repeat, .repeat_delay = def.repeat_delay, .yoyo = def.yoyo,
                             .time_scale = def.time_scale};
    const double dt = 1.0 / 16.0;
    for (int k = 1; k <= 64; ++k) {
        now = k * dt;
        engine.tick(dt);
        // Local seconds / 2 s is the child's progress; the same arithmetic up to rounding.
        EXPECT_NEAR(p.x, grape::timeline_local_time(model, 2.0, now) / 2.0, 1e-15) << now;
    }
    EXPECT_EQ(events, (std::vector<std::pair<std::string, double>>{
                          {"start", 0.3125}, {"loop1", 1.375}, {"loop2", 2.5}, {"complete", 3.5}}));
    EXPECT_EQ(tl.total_duration(), 6.5);  // 3 plays of 2 s, 2 delays of ¼ s (timeline seconds)
    EXPECT_EQ(tl.time(), 6.5);
}

TEST(Timeline, ReverseRunsBackToTheStartAndPlayForwardAgain) {
    Engine engine;
    Point a, b;
    Timeline tl = engine.create_timeline();
    Animation first = engine.create_2d_animation(a, unit_line, 1.0);
    Animation second = engine.create_2d_animation(b, unit_line, 1.0);
    tl.add(first).add(second);
    std::vector<std::string> events;
    tl.on_reverse_complete([&] { events.push_back("timeline back"); });
    first.on_reverse_complete([&] { events.push_back("first back"); });
    second.on_reverse_complete([&] { events.push_back("second back"); });
    first.on_complete([&] { events.push_back("first done"); });
    tl.call([&] { events.push_back("call"); }, 1.5);
    engine.tick(1.75);
    EXPECT_EQ(a.x, 1.0);
    EXPECT_EQ(b.x, 0.75);
    tl.reverse();
    EXPECT_TRUE(tl.reversed());
    engine.tick(0.5);  // 1.25
    EXPECT_EQ(b.x, 0.25);
    engine.tick(0.5);  // 0.75
    EXPECT_EQ(b.x, 0.0);
    EXPECT_EQ(a.x, 0.75);
    engine.tick(5.0);  // stops at the start
    EXPECT_EQ(a.x, 0.0);
    EXPECT_EQ(tl.time(), 0.0);
    engine.tick(1.0);  // stays: nothing more fires
    EXPECT_EQ(events, (std::vector<std::string>{"first done", "call", "call", "second back", "first back", "timeline back"}));
    tl.play();
    engine.tick(0.5);
    EXPECT_EQ(a.x, 0.5);
    EXPECT_TRUE(first.alive());
}

TEST(Timeline, LabelsCallbacksGapsAndSeek) {
    Engine engine;
    Point a, b;
    Timeline tl = engine.create_timeline();
    std::vector<double> fired;
    tl.add(engine.create_2d_animation(a, unit_line, 1.0))
        .gap(0.5)
        .label("hit")
        .add(engine.create_2d_animation(b, unit_line, 1.0), "hit+0.25")
        .call([&] { fired.push_back(tl.time()); }, "hit-0.25")
        .call([&] { fired.push_back(tl.time()); }, grape::TimelinePosition{.anchor = grape::TimelinePosition::Anchor::start, .offset = 0.5});
    EXPECT_EQ(tl.label_time("hit"), 1.5);
    EXPECT_TRUE(std::isnan(tl.label_time("nope")));
    EXPECT_EQ(tl.duration(), 2.75);
    tl.seek("hit");
    EXPECT_EQ(a.x, 1.0);
    EXPECT_EQ(b.x, 0.0);
    EXPECT_TRUE(fired.empty());  // seek fires nothing by default
    tl.seek(0.0);
    tl.seek(2.0, true);  // crossing both callbacks, in time order
    EXPECT_EQ(fired, (std::vector<double>{0.5, 1.25}));
    EXPECT_EQ(b.x, 0.25);
    EXPECT_EQ(tl.progress(), 2.0 / 2.75);
    engine.tick(100.0);  // one large tick: nothing left to cross forward
    EXPECT_EQ(fired.size(), 2u);
    expect_error([&] { tl.seek("nope"); }, {"Timeline::seek", "unknown label 'nope'"});
}

TEST(Timeline, BadPlacementsAreNamed) {
    Engine engine;
    Point p;
    Timeline tl = engine.create_timeline();
    Timeline other = engine.create_timeline();
    Animation a = engine.create_2d_animation(p, unit_line, 1.0);
    tl.add(a);
    expect_error([&] { other.add(a); }, {"Timeline::add", "already in a timeline"});
    expect_error([&] { tl.add(engine.create_animation(unit_line, 1.0, {.repeat = -1})); }, {"endless"});
    expect_error([&] { tl.add(engine.create_animation(unit_line, 1.0), "nope+1"); }, {"unknown label 'nope'"});
    expect_error([&] { tl.add(engine.create_animation(unit_line, 1.0), "-=2"); }, {"negative start"});
    expect_error([&] { tl.add(engine.create_animation(unit_line, 1.0), ">+"); }, {"timeline position"});
    expect_error([&] { tl.label("x").label("x"); }, {"duplicate label 'x'"});
    expect_error([&] { tl.gap(-1); }, {"Timeline::gap", "-1"});
    expect_error([&] { tl.add(tl); }, {"cycle"});
    other.add(engine.create_animation(unit_line, 1.0));
    tl.add(other);
    expect_error([&] { other.add(tl); }, {"cycle"});  // tl contains other
    Timeline third = engine.create_timeline();
    third.add(engine.create_animation(unit_line, 1.0));
    other.add(third);
    Timeline top = engine.create_timeline();
    expect_error([&] { third.add(top), top.add(tl); }, {"cycle"});  // tl contains other contains third contains top
    expect_error([&] { engine.create_timeline({.repeat_delay = -1}); }, {"create_timeline", "repeat_delay"});
    expect_error([&] { engine.create_timeline({.time_scale = NAN}); }, {"time_scale"});
    Animation dead = engine.create_animation(unit_line, 1.0);
    dead.kill();
    expect_error([&] { top.add(dead); }, {"not alive"});
    Timeline killed = engine.create_timeline();
    killed.kill();
    expect_error([&] { killed.add(engine.create_animation(unit_line, 1.0)); }, {"not alive"});
    // Nested timelines grow their parents.
    EXPECT_EQ(tl.duration(), 3.0);
    third.add(engine.create_animation(unit_line, 2.0));
    EXPECT_EQ(tl.duration(), 5.0);
}

// Handlers that create, kill, pause, seek, reverse and re-time anything (the running
// timeline included) at random, under random trees: nothing dangles (run under ASan/UBSan).
// With `round_trip`, afterwards every surviving timeline's state must still be a function of
// its time: seeking away and back restores it.
void random_mutations(bool round_trip) {
    for (std::uint64_t seed = 3000; seed < 3060; ++seed) {
        std::mt19937_64 rng(grape::testing::test_seed(seed));
        std::uniform_real_distribution<double> unit(0, 1);
        Engine engine;
        std::vector<Timeline> timelines;
        std::vector<Animation> animations;
        std::vector<Point> targets(4000);
        std::size_t next_target = 0;
        bool chaos = true;
        std::function<void()> mutate;
        auto any_timeline = [&]() -> Timeline { return timelines.empty() ? Timeline() : timelines[rng() % timelines.size()]; };
        mutate = [&] {
            if (!chaos) return;
            Timeline t = any_timeline();
            switch (rng() % 12) {
                case 0: t.kill(); break;
                case 1: t.pause(); break;
                case 2: t.resume(); break;
                case 3: {  // draws in a fixed order (function arguments are unsequenced)
                    const double to = unit(rng) * 3.0;
                    const bool fire = rng() % 4 == 0;
                    t.seek(to, fire);
                    break;
                }
                case 4: t.reverse(); break;
                case 5: t.play(); break;
                case 6: t.set_time_scale(0.5 + unit(rng)); break;
                case 7: {  // a new child, anywhere
                    if (!t.alive() || next_target >= targets.size()) break;
                    Animation a = engine.create_2d_animation(targets[next_target++], unit_line, 0.1 + unit(rng));
                    animations.push_back(a);
                    t.add(a, unit(rng) * 2.0);
                    break;
                }
                case 8: {
                    if (!t.alive()) break;
                    t.call(mutate, unit(rng) * 3.0);
                    break;
                }
                case 9:
                    if (!animations.empty()) animations[rng() % animations.size()].kill();
                    break;
                case 10: {  // a new top-level timeline
                    Timeline n = engine.create_timeline({.repeat = static_cast<int>(rng() % 3), .yoyo = rng() % 2 == 0});
                    if (next_target < targets.size()) {
                        Animation a = engine.create_2d_animation(targets[next_target++], unit_line, 0.5);
                        animations.push_back(a);
                        n.add(a);
                    }
                    n.call(mutate, 0.25);
                    timelines.push_back(n);
                    break;
                }
                default: engine.create_animation(unit_line, 0.2).on_complete(mutate); break;
            }
        };
        std::vector<int> log;  // the trees' callbacks write here as long as the engine runs
        for (int k = 0; k < 6; ++k) {
            const Tree tree = random_tree(seed * 10 + static_cast<std::uint64_t>(k));
            Built b = build(engine, tree, log);
            b.root.on_update([&] {
                if (rng() % 8 == 0) mutate();
            });
            b.root.on_loop([&](int) { mutate(); });
            b.root.call(mutate, 0.3);
            timelines.push_back(b.root);
            for (const Animation& a : b.animations) {
                animations.push_back(a);
                a.on_complete(mutate);
                a.on_start(mutate);
            }
        }
        for (int step = 0; step < 200; ++step) engine.tick(unit(rng) < 0.1 ? 2.0 * unit(rng) : 0.05 * unit(rng));
        chaos = false;
        // Still a function of time: away and back gives the same state.
        for (const Timeline& t : timelines) {
            if (!round_trip) break;
            if (!t.alive()) continue;
            std::vector<double> before;
            for (const Animation& a : animations) before.push_back(a.value().x);
            const double time = t.time();
            t.seek(time + 0.37);
            t.seek(time);
            for (std::size_t k = 0; k < animations.size(); ++k) {
                // exact: the same pure functions of the same time
                EXPECT_EQ(animations[k].value().x, before[k]) << "seed " << seed << " animation " << k << " timeline "
                                                              << (&t - timelines.data()) << " time " << time
                                                              << " total " << t.total_duration() << " dur " << t.duration();
            }
        }
        engine.tick(0.1);
    }
}

TEST(TimelineHandlers, RandomMutationsFromHandlers) { random_mutations(false); }

TEST(TimelineHandlers, SeekAwayAndBackAfterMutationsRestoresTheState) { random_mutations(true); }

// A handler that pauses its timeline ends the update; the timeline keeps the time the update
// had reached and its state is the pure function of that time, the children it had not
// driven yet included (the one beside the child whose handler ran; the siblings and parents
// of a nested timeline whose child's handler ran), and rounding included: a point's time in
// a later play, tau = play start + point, maps back to the point within an ulp, not exactly.
TEST(TimelineHandlers, AnUpdateEndedByAHandlerLeavesTheStateOfItsTime) {
    auto away_and_back = [](const Timeline& tl, const std::vector<const Point*>& points) {
        std::vector<double> before;
        for (const Point* p : points) before.push_back(p->x);
        const double time = tl.time();
        tl.seek(time + 0.37);
        tl.seek(time);
        for (std::size_t k = 0; k < points.size(); ++k) EXPECT_EQ(points[k]->x, before[k]) << k;
    };
    {  // flat: b (from 0.5) runs beside a, whose completion at 1 pauses the timeline
        Engine engine;
        Point a, b;
        Timeline tl = engine.create_timeline();
        Animation first = engine.create_2d_animation(a, unit_line, 1.0);
        tl.add(first).add(engine.create_2d_animation(b, unit_line, 1.0), 0.5);
        first.on_complete([&] { tl.pause(); });
        engine.tick(1.25);
        EXPECT_TRUE(tl.paused());
        EXPECT_EQ(tl.time(), 1.0);  // the point where the handler ran
        EXPECT_EQ(a.x, 1.0);
        EXPECT_EQ(b.x, 0.5);  // exact: 0.5 s into a 1 s line
        away_and_back(tl, {&a, &b});
    }
    {  // nested: the inner timeline's child pauses the outer one, whose update had reached 1.25
        Engine engine;
        Point a, b, c;
        Timeline outer = engine.create_timeline();
        Timeline inner = engine.create_timeline();
        Animation first = engine.create_2d_animation(a, unit_line, 1.0);
        inner.add(first).add(engine.create_2d_animation(b, unit_line, 1.0), 0.5);
        outer.add(inner).add(engine.create_2d_animation(c, unit_line, 2.0), 0.0);
        first.on_complete([&] { outer.pause(); });
        engine.tick(1.25);
        EXPECT_EQ(outer.time(), 1.25);
        EXPECT_EQ(inner.time(), 1.25);
        EXPECT_EQ(a.x, 1.0);
        EXPECT_EQ(b.x, 0.75);
        EXPECT_EQ(c.x, 0.625);
        away_and_back(outer, {&a, &b, &c});
    }
    {  // rounding: a callback at 0.3 in the second play of a 2.75 s timeline pauses it
        auto make = [](Engine& engine, Point& p, int* calls) {
            Timeline tl = engine.create_timeline({.repeat = 1});
            tl.add(engine.create_2d_animation(p, unit_line, 1.0)).gap(1.75);
            if (calls) tl.call([calls, tl] { if (++*calls == 2) tl.pause(); }, 0.3);
            return tl;
        };
        Engine engine, reference;
        Point a, r;
        int calls = 0;
        Timeline tl = make(engine, a, &calls);
        engine.tick(2.5);
        engine.tick(1.0);  // crosses 0.3 in play 1
        EXPECT_TRUE(tl.paused());
        EXPECT_EQ(tl.repetition(), 1);
        EXPECT_NEAR(tl.time(), 3.05, 1e-15);  // 2.75 + 0.3, rounded once
        make(reference, r, nullptr).seek(tl.time());
        EXPECT_EQ(a.x, r.x);  // the state seek gives, to the bit (0.3 + 1 ulp here)
        away_and_back(tl, {&a});
    }
}

// Children placed from the timeline's own on_update, after the last point its update crosses,
// take the state of the time before the tick returns: one behind the playhead at its end, one
// across it where the time falls in it (a timeline built with them from the start and sought
// there gives the reference).
TEST(TimelineHandlers, ChildrenPlacedFromOnUpdateTakeTheirStateInThatTick) {
    auto make = [](Engine& engine, Point& a, Point& b, Point& c, bool all) {
        Timeline tl = engine.create_timeline();
        tl.add(engine.create_2d_animation(a, unit_line, 4.0));
        if (all) {
            tl.add(engine.create_2d_animation(b, unit_line, 0.5), 0.25);  // ends at 0.75
            tl.add(engine.create_2d_animation(c, unit_line, 2.0), 1.5);   // runs 1.5 … 3.5
        }
        return tl;
    };
    Engine engine, reference;
    Point a, b, c, ra, rb, rc;
    Timeline tl = make(engine, a, b, c, false);
    engine.tick(2.0);
    bool placed = false;
    tl.on_update([&] {
        if (placed) return;
        placed = true;
        tl.add(engine.create_2d_animation(b, unit_line, 0.5), 0.25);
        tl.add(engine.create_2d_animation(c, unit_line, 2.0), 1.5);
    });
    engine.tick(0.5);
    EXPECT_EQ(tl.time(), 2.5);
    EXPECT_EQ(b.x, 1.0);  // at its end
    EXPECT_EQ(c.x, 0.5);  // 1 s into 2 s: exact
    make(reference, ra, rb, rc, true).seek(2.5);
    EXPECT_EQ(a.x, ra.x);
    EXPECT_EQ(b.x, rb.x);
    EXPECT_EQ(c.x, rc.x);
}

// Children that lengthen the play move where the time falls in it, never the time: placed
// from outside (the window goes there at once, and the time is not rebuilt from the new local
// time, which would round: 2·1.1 + 0.7 is 2.9 + 1 ulp), and placed from the timeline's own
// on_update (the window goes there before the update ends).
TEST(TimelineHandlers, PlacingChildrenKeepsTheTimeAndGivesItsState) {
    auto make = [](Engine& engine, Point& a, Point& b, bool grow) {
        Timeline tl = engine.create_timeline({.repeat = 3});
        tl.add(engine.create_2d_animation(a, unit_line, 1.0));
        if (grow) tl.add(engine.create_2d_animation(b, unit_line, 0.1));
        return tl;
    };
    {
        Engine engine, reference;
        Point a, b, ra, rb;
        Timeline tl = make(engine, a, b, false);
        engine.tick(2.9);
        EXPECT_EQ(tl.repetition(), 2);
        tl.add(engine.create_2d_animation(b, unit_line, 0.1));  // plays of 1.1 s: 2.9 is 0.7 into play 2
        EXPECT_EQ(tl.time(), 2.9);
        EXPECT_EQ(tl.repetition(), 2);
        make(reference, ra, rb, true).seek(2.9);
        EXPECT_EQ(a.x, ra.x);
        EXPECT_EQ(b.x, rb.x);
    }
    {
        Engine engine, reference;
        Point a, b, ra, rb;
        Timeline tl = make(engine, a, b, false);
        bool placed = false;
        tl.on_update([&] {
            if (placed) return;
            placed = true;
            tl.add(engine.create_2d_animation(b, unit_line, 0.1));
        });
        engine.tick(2.9);
        EXPECT_EQ(tl.time(), 2.9);
        make(reference, ra, rb, true).seek(2.9);
        EXPECT_EQ(a.x, ra.x);  // 0.7 into play 2 of 1.1 s (before the end of the update: 0.9 of 1 s)
        EXPECT_EQ(b.x, rb.x);
    }
}

// A child placed behind the playhead goes to its end at once, with many timelines in the
// store (the window's rebuild is given its timeline, it does not look for it).
TEST(Timeline, ChildPlacedBehindThePlayheadGoesToItsEnd) {
    Engine engine;
    std::vector<Timeline> others;
    for (int k = 0; k < 200; ++k) others.push_back(engine.create_timeline());
    Point a, b, late;
    Timeline tl = engine.create_timeline();
    tl.add(engine.create_2d_animation(a, unit_line, 4.0));
    engine.tick(3.0);
    EXPECT_EQ(a.x, 0.75);
    tl.add(engine.create_2d_animation(b, unit_line, 1.0), 0.5);   // ended at 1.5
    tl.add(engine.create_2d_animation(late, unit_line, 2.0), 2.0);  // 1 s in
    EXPECT_EQ(b.x, 1.0);
    EXPECT_EQ(late.x, 0.5);
    EXPECT_EQ(a.x, 0.75);
    engine.tick(0.5);
    EXPECT_EQ(late.x, 0.75);
}

// A nested timeline that grows moves its end in its parent's order of ends: crossing both
// ends in one tick, the sibling that now ends first completes first.
TEST(Timeline, GrowingNestedTimelineKeepsTheOrderOfEnds) {
    Engine engine;
    std::vector<std::string> events;
    Timeline parent = engine.create_timeline();
    Timeline inner = engine.create_timeline();
    inner.add(engine.create_animation(unit_line, 1.0));
    Animation sibling = engine.create_animation(unit_line, 1.0);
    Animation early = engine.create_animation(unit_line, 1.1);
    sibling.on_complete([&] { events.push_back("sibling"); });
    early.on_complete([&] { events.push_back("early"); });
    inner.on_complete([&] { events.push_back("inner"); });
    parent.add(inner, 0.0).add(sibling, 0.25).add(early, 0.0);  // ends: inner 1, early 1.1, sibling 1.25
    inner.add(engine.create_animation(unit_line, 0.5));           // inner now ends at 1.5
    EXPECT_EQ(parent.duration(), 1.5);
    engine.tick(2.0);
    EXPECT_EQ(events, (std::vector<std::string>{"early", "sibling", "inner"}));
    inner.add(engine.create_animation(unit_line, 0.25), 0.0);  // inside its length: no change
    EXPECT_EQ(parent.duration(), 1.5);
}

// Timeline generations never wrap either: a slot at the last generation is retired, so the
// first handle of a slot stays inert after 2³² lives of it (the hook skips all but the last).
// Without the retirement the slot's next two lives would take generations 2³² − 1 and 0, and
// the first handle (generation 0) would name the second of them.
TEST(Timeline, AStaleHandleStaysInertWhereItsSlotsGenerationWouldWrap) {
    using grape::detail::TimelineStore;
    Engine engine;
    const Timeline first = engine.create_timeline();
    const Timeline late = TimelineStore::with_generation_for_test(first, grape::detail::last_generation - 1);
    EXPECT_FALSE(first.alive());
    EXPECT_TRUE(late.alive());
    late.kill();  // generation 2³² − 1: retired
    for (int round = 0; round < 3; ++round) {
        Timeline next = engine.create_timeline();
        next.gap(1.0);
        EXPECT_FALSE(first.alive()) << round;
        EXPECT_FALSE(late.alive()) << round;
        next.kill();
    }
    Timeline kept = engine.create_timeline();
    kept.gap(2.0);
    first.kill();  // inert: kills nothing
    EXPECT_TRUE(kept.alive());
    EXPECT_EQ(first.duration(), 0.0);
    EXPECT_EQ(kept.duration(), 2.0);
}

// --- equal times ---------------------------------------------------------------------------------
// Ties on dyadic times (every time below is exact in binary, so the points coincide bit for
// bit): inside P (placed at 0.5 in the root R) A ends at 1, nested M ends at 1 with a callback at
// its own end, P's callback sits at 1, B starts at 1 and nested N starts at 1 with a callback at
// its own start; R's callback at 1.5 is P's 1. timeline.hpp: forward, ends, then callbacks, then
// starts; backward the mirror (starts, callbacks, ends); the children running meanwhile (P in R)
// are brought to the point first, so all of P's events at its 1 precede R's callback either way.
struct Ties {
    Engine engine;
    Point a, b;
    std::vector<std::string> log;
    Timeline root, p, m, n;
    Animation first, second;
    double a_at_call = NAN, b_at_call = NAN, p_at_root_call = NAN;

    explicit Ties(const TimelineDef& def = {}) {
        root = engine.create_timeline(def);
        p = engine.create_timeline();
        m = engine.create_timeline();
        n = engine.create_timeline();
        first = engine.create_2d_animation(a, unit_line, 1.0);
        second = engine.create_2d_animation(b, unit_line, 0.5);
        first.on_start([this] { log.push_back("A start"); });
        first.on_complete([this] { log.push_back("A complete"); });
        first.on_reverse_complete([this] { log.push_back("A back"); });
        first.on_update([this] { log.push_back("A update " + std::to_string(a.x)); });
        second.on_start([this] { log.push_back("B start"); });
        second.on_complete([this] { log.push_back("B complete"); });
        second.on_reverse_complete([this] { log.push_back("B back"); });
        m.gap(0.5, 0.0).call([this] { log.push_back("M call"); }, 0.5);
        m.on_complete([this] { log.push_back("M complete"); });
        m.on_update([this] { log.push_back("M update " + std::to_string(m.time())); });
        n.gap(0.5, 0.0).call([this] { log.push_back("N call"); }, 0.0);
        n.on_start([this] { log.push_back("N start"); });
        n.on_reverse_complete([this] { log.push_back("N back"); });
        p.add(first, 0.0).add(m, 0.5);
        p.call(
            [this] {
                log.push_back("P call");
                a_at_call = a.x;
                b_at_call = b.x;
            },
            1.0);
        p.add(second, 1.0).add(n, 1.0).gap(0.5, 1.5);  // P lasts 2
        root.add(p, 0.5).call(
            [this] {
                log.push_back("R call");
                p_at_root_call = p.time();
            },
            1.5);
    }
    // Where `what` is in the log (it must be there exactly once).
    std::ptrdiff_t at(const std::string& what) const {
        EXPECT_EQ(std::count(log.begin(), log.end(), what), 1) << what;
        return std::find(log.begin(), log.end(), what) - log.begin();
    }
};

std::string joined(const std::vector<std::string>& log) {
    std::string out;
    for (const std::string& s : log) out += s + "; ";
    return out;
}

// Forward through P's 1: the ends (A, M and M's callback at its end), then P's callback, then
// the starts (B; with `nested_start` also N and N's callback at its start), then R's callback.
void expect_forward_tie_order(const Ties& t, bool nested_start) {
    const auto call = t.at("P call");
    for (const char* end : {"A complete", "M call", "M complete", "A update 1.000000"})
        EXPECT_LT(t.at(end), call) << end << " | " << joined(t.log);
    std::vector<const char*> starts{"B start"};
    if (nested_start) starts.insert(starts.end(), {"N start", "N call"});
    for (const char* start : starts) {
        EXPECT_GT(t.at(start), call) << start << " | " << joined(t.log);
        EXPECT_LT(t.at(start), t.at("R call")) << start << " | " << joined(t.log);
    }
    for (const char* any : {"P call", "A complete", "M complete"})
        EXPECT_LT(t.at(any), t.at("R call")) << any << " | " << joined(t.log);
    EXPECT_LT(t.at("M call"), t.at("M complete"));
    EXPECT_EQ(t.a_at_call, 1.0);  // A was brought to its end before the callback
    EXPECT_EQ(t.p_at_root_call, 1.0);
}

// Backward through P's 1: the starts (B and N come back to their starts, N's callback at its
// start), then P's callback, then the ends (A and M run back from their ends: their first
// change of state after the point), then R's callback before P goes on to 0.75.
void expect_backward_tie_order(const Ties& t) {
    const auto call = t.at("P call");
    for (const char* start : {"B back", "N call", "N back"})
        EXPECT_LT(t.at(start), call) << start << " | " << joined(t.log);
    EXPECT_LT(call, t.at("R call")) << joined(t.log);
    for (const char* end : {"A update 0.750000", "M update 0.250000"})
        EXPECT_GT(t.at(end), t.at("R call")) << end << " | " << joined(t.log);
    EXPECT_GT(t.at("M call"), call) << joined(t.log);  // crossed as M runs back from its end
    EXPECT_EQ(t.a_at_call, 1.0);  // A still at its end
    EXPECT_EQ(t.b_at_call, 0.0);  // B brought back to its start before the callback
    EXPECT_EQ(t.p_at_root_call, 1.0);
    // Nothing ends or starts forward on the way back.
    for (const char* never : {"A complete", "M complete", "B start", "N start"})
        EXPECT_EQ(std::count(t.log.begin(), t.log.end(), never), 0) << never << " | " << joined(t.log);
}

void drop(std::vector<std::string>& log, const std::string& what) {
    log.erase(std::remove(log.begin(), log.end(), what), log.end());
}

// The forward cases: a tick across the tie, a tick landing exactly on it, and seek with events.
void forward_ties(bool nested_start) {
    Ties ticked;
    ticked.engine.tick(0.25);
    ticked.log.clear();
    ticked.engine.tick(1.5);  // R 0.25 → 1.75: P 0 → 1.25 (A's start is before the tie)
    drop(ticked.log, "A start");
    expect_forward_tie_order(ticked, nested_start);
    EXPECT_EQ(ticked.b.x, 0.5);
    // Landing exactly on the tie fires all of it in that tick, in the same order.
    Ties landed;
    landed.engine.tick(0.25);
    landed.engine.tick(1.25);  // R 1.5 exactly
    drop(landed.log, "A start");
    expect_forward_tie_order(landed, nested_start);
    // seek with events fires what the tick fired, in the same order.
    Ties sought;
    sought.root.seek(0.25, true);
    sought.log.clear();
    sought.root.seek(1.75, true);
    drop(sought.log, "A start");
    EXPECT_EQ(sought.log, ticked.log);
}

TEST(TimelineTies, ForwardEndsThenCallbacksThenStartsAndNestedBeforeTheParent) { forward_ties(false); }

// A nested timeline that starts at the tie (N) fires its on_start and its callback at its own
// time 0 only once its time moves past 0: after R's callback at the same instant when the
// tick goes on, and not at all in a tick that lands on the tie (they come in the next one),
// where the reference's crossings (tau, now] and the order above put them before R's callback.
// A nested timeline resting before its start and one at its start both have time 0, so its
// update from 0 to 0 does nothing. Fails today; enable once a nested timeline tells the two apart.
TEST(TimelineTies, DISABLED_ANestedTimelineStartingAtTheTieFiresItsStartThere) { forward_ties(true); }

TEST(TimelineTies, BackwardTheMirrorByReverseSeekAndYoyo) {
    Ties reversed;
    reversed.engine.tick(1.75);
    EXPECT_EQ(reversed.b.x, 0.5);
    reversed.log.clear();
    reversed.a_at_call = reversed.b_at_call = reversed.p_at_root_call = NAN;
    reversed.root.reverse();
    reversed.engine.tick(0.5);  // R 1.75 → 1.25: P 1.25 → 0.75
    expect_backward_tie_order(reversed);
    EXPECT_EQ(reversed.a.x, 0.75);
    // seek back with events: the same events in the same order.
    Ties sought;
    sought.engine.tick(1.75);
    sought.log.clear();
    sought.a_at_call = sought.b_at_call = sought.p_at_root_call = NAN;
    sought.root.seek(1.25, true);
    expect_backward_tie_order(sought);
    EXPECT_EQ(sought.log, reversed.log);
    // A yoyo root's second play runs back: R's local 1.5 is its time 2.5 + 1 = 3.5.
    Ties yoyo({.repeat = 1, .yoyo = true});
    EXPECT_EQ(yoyo.root.duration(), 2.5);
    yoyo.engine.tick(3.25);
    yoyo.log.clear();
    yoyo.a_at_call = yoyo.b_at_call = yoyo.p_at_root_call = NAN;
    yoyo.engine.tick(0.5);  // R 3.25 → 3.75: local 1.75 → 1.25
    expect_backward_tie_order(yoyo);
    EXPECT_EQ(yoyo.log, reversed.log);
}

// Animations on their own: reverse() runs back through earlier plays (exact: the state is
// the timing model's at the position reached), reaching the start fires on_reverse_complete
// once and holds; on_start fires when the first play begins; on_update after every change.
TEST(AnimationRunTime, ReversePlayAndEvents) {
    Engine engine;
    Point p;
    const AnimationDef def{.delay = 0.25, .repeat = 2, .repeat_delay = 0.125, .yoyo = true};
    Animation a = engine.create_2d_animation(p, unit_line, 1.0, def);
    std::vector<std::string> events;
    int updates = 0;
    a.on_start([&] { events.push_back("start"); });
    a.on_loop([&](int play) { events.push_back("loop" + std::to_string(play)); });
    a.on_reverse_complete([&] { events.push_back("back"); });
    a.on_update([&] { ++updates; });
    engine.tick(0.125);  // waiting
    EXPECT_EQ(p.x, -999.0);
    engine.tick(0.25);  // 0.375: the first play began 0.125 ago
    EXPECT_EQ(p.x, 0.125);
    engine.tick(1.5);  // 1.875: play 1 (backward) since 1.375, 0.5 in
    EXPECT_EQ(p.x, 0.5);
    EXPECT_EQ(a.repetition(), 1);
    a.reverse();
    EXPECT_TRUE(a.reversed());
    engine.tick(0.25);  // back to 1.625: 0.25 into play 1
    EXPECT_EQ(p.x, 0.75);
    engine.tick(0.3125);  // 1.3125: in the repeat delay after play 0, holding its end
    EXPECT_EQ(p.x, 1.0);
    EXPECT_EQ(a.repetition(), 0);
    engine.tick(0.5);  // 0.8125: 0.5625 into play 0
    EXPECT_EQ(p.x, 0.5625);
    engine.tick(10.0);  // back at the start, holding
    EXPECT_EQ(p.x, 0.0);
    engine.tick(1.0);
    EXPECT_TRUE(a.alive());
    a.play();
    engine.tick(0.5);
    EXPECT_EQ(p.x, 0.5);
    EXPECT_EQ(events, (std::vector<std::string>{"start", "loop1", "back"}));
    EXPECT_GE(updates, 6);
    EXPECT_EQ(a.time_scale(), 1.0);  // the direction is not a negative scale
}

}  // namespace

