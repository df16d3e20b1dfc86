// Timeline positions and layout: the position syntax read back and forth, start times of
// hand-computed sequences (every anchor), the errors, and timeline_local_time against its
// closed form under delay, repeat, repeat delay, yoyo, reversed and time scale.
#include <grape/error.hpp>
#include <grape/timeline_layout.hpp>

#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using grape::TimelineEntry;
using grape::TimelinePosition;
using grape::parse_timeline_position;
using grape::testing::expect_error;
using Anchor = TimelinePosition::Anchor;
using Kind = TimelineEntry::Kind;

namespace {

void expect_position(const std::string& text, Anchor anchor, double offset, const std::string& label = {}) {
    const TimelinePosition p = parse_timeline_position(text);
    EXPECT_EQ(p.anchor, anchor) << text;
    EXPECT_EQ(p.offset, offset) << text;  // decimal text → the nearest double, both sides
    EXPECT_EQ(p.label, label) << text;
    // Written back and read again: the same position.
    const TimelinePosition q = parse_timeline_position(to_string(p));
    EXPECT_EQ(q.anchor, p.anchor) << to_string(p);
    EXPECT_EQ(q.offset, p.offset) << to_string(p);
    EXPECT_EQ(q.label, p.label) << to_string(p);
}

TEST(TimelinePosition, EveryFormOfTheSyntax) {
    expect_position("1.5", Anchor::start, 1.5);
    expect_position("0", Anchor::start, 0.0);
    expect_position("2e-3", Anchor::start, 0.002);
    expect_position(">", Anchor::previous_end, 0.0);
    expect_position("<", Anchor::previous_start, 0.0);
    expect_position(">+0.5", Anchor::previous_end, 0.5);
    expect_position("<-0.2", Anchor::previous_start, -0.2);
    expect_position(">+=1", Anchor::previous_end, 1.0);
    expect_position("<-=0.25", Anchor::previous_start, -0.25);
    expect_position("+=0.5", Anchor::end, 0.5);
    expect_position("-=0.5", Anchor::end, -0.5);
    expect_position("intro", Anchor::label, 0.0, "intro");
    expect_position("intro+1", Anchor::label, 1.0, "intro");
    expect_position("intro-0.25", Anchor::label, -0.25, "intro");
    expect_position("intro-=0.25", Anchor::label, -0.25, "intro");
    expect_position("my-label", Anchor::label, 0.0, "my-label");       // "-label" is no number
    expect_position("my-label-1", Anchor::label, -1.0, "my-label");
    expect_position("a-1e-3", Anchor::label, -0.001, "a");             // the first sign that reads
    const TimelinePosition at = grape::timeline_position_at(3.25);
    EXPECT_EQ(at.anchor, Anchor::start);
    EXPECT_EQ(at.offset, 3.25);
}

TEST(TimelinePosition, BadTextIsNamedWithTheReason) {
    expect_error([] { parse_timeline_position(""); }, {"timeline position ''", "empty"});
    expect_error([] { parse_timeline_position("1.5x"); }, {"'1.5x'", "not a finite number"});
    expect_error([] { parse_timeline_position(">0.5"); }, {"'>0.5'", "followed by +N"});
    expect_error([] { parse_timeline_position("<+"); }, {"'<+'"});
    expect_error([] { parse_timeline_position("+0.5"); }, {"'+0.5'", "+=N or -=N"});
    expect_error([] { parse_timeline_position("-=nan"); }, {"'-=nan'"});
    expect_error([] { parse_timeline_position("+=inf"); }, {"'+=inf'"});
    expect_error([] { parse_timeline_position("=a"); }, {"'=a'", "cannot start with '='"});
    expect_error([] { parse_timeline_position("1e999"); }, {"'1e999'", "finite"});
}

TimelineEntry child(double duration, const std::string& at = "+=0") {
    return {.kind = Kind::child, .at = parse_timeline_position(at), .duration = duration};
}
TimelineEntry label(const std::string& name, const std::string& at = "+=0") {
    return {.kind = Kind::label, .at = parse_timeline_position(at), .label = name};
}

// Every anchor in one sequence, starts worked out by hand (all sums exact in binary).
TEST(TimelineLayout, StartsFollowTheAnchors) {
    const std::vector<TimelineEntry> entries = {
        child(1.0),                                         // 0: [0, 1]
        label("a"),                                         // 1: at 1 (the end so far)
        child(2.0, "<+0.25"),                               // 2: [0.25, 2.25] (previous start + ¼)
        child(0.5, ">"),                                    // 3: [2.25, 2.75]
        {.kind = Kind::gap, .at = {}, .duration = 0.75},    // 4: [2.75, 3.5]
        child(1.0, "<"),                                    // 5: [2.75, 3.75] (the gap's start)
        child(0.5, "a+1"),                                  // 6: [2, 2.5]
        {.kind = Kind::callback, .at = parse_timeline_position("a-0.5")},  // 7: at 0.5
        child(0.25, ">-0.25"),                              // 8: [2.25, 2.5] (6's end − ¼; 7 is no "previous")
        child(1.0, "-=0.5"),                                // 9: [3.25, 4.25]
        child(0.5, "0.125"),                                // 10: [0.125, 0.625]
        label("b", "10"),                                   // 11: at 10, a point that ends the timeline
    };
    const grape::TimelineLayout layout = grape::layout_timeline(entries);
    const std::vector<double> expected = {0, 1, 0.25, 2.25, 2.75, 2.75, 2, 0.5, 2.25, 3.25, 0.125, 10};
    ASSERT_EQ(layout.start.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(layout.start[i], expected[i]) << "entry " << i;
    ASSERT_EQ(layout.labels.size(), 2u);
    EXPECT_EQ(layout.labels[0], (std::pair<std::string, double>{"a", 1.0}));
    EXPECT_EQ(layout.labels[1], (std::pair<std::string, double>{"b", 10.0}));
    EXPECT_EQ(layout.duration, 10.0);
    // Without the last label the timeline ends with its last-ending child.
    EXPECT_EQ(grape::layout_timeline(std::span(entries).first(11)).duration, 4.25);
    EXPECT_EQ(grape::layout_timeline({}).duration, 0.0);
}

// Random sequences of "+=offset" children: each start is the previous end plus its offset
// when offsets are ≥ 0 (the end so far is the previous end), and the duration is the sum.
TEST(TimelineLayout, SequentialChildrenAddUp) {
    std::mt19937_64 rng(grape::testing::test_seed(7));
    std::uniform_real_distribution<double> unit(0, 1);
    for (int round = 0; round < 100; ++round) {
        std::vector<TimelineEntry> entries;
        double end = 0.0;
        std::vector<double> starts;
        const int n = 1 + static_cast<int>(rng() % 20);
        for (int i = 0; i < n; ++i) {
            const double gap = unit(rng) < 0.5 ? 0.0 : unit(rng);
            const double duration = unit(rng) * 3.0;
            entries.push_back({.at = {.anchor = Anchor::end, .offset = gap}, .duration = duration});
            starts.push_back(end + gap);
            end = end + gap + duration;
        }
        const grape::TimelineLayout layout = grape::layout_timeline(entries);
        for (int i = 0; i < n; ++i) EXPECT_EQ(layout.start[i], starts[i]);  // the same additions
        EXPECT_EQ(layout.duration, end);
    }
}

TEST(TimelineLayout, BadEntriesAreNamedByIndex) {
    expect_error([] { grape::layout_timeline(std::vector{child(1.0), child(1.0, "intro")}); },
                 {"entries[1]", "unknown label 'intro'"});
    expect_error([] { grape::layout_timeline(std::vector{label("x"), child(1), label("x")}); },
                 {"entries[2]", "duplicate label 'x'"});
    expect_error([] { grape::layout_timeline(std::vector{child(1.0), child(1.0, "-=1.5")}); },
                 {"entries[1]", "negative start", "-0.5"});
    expect_error([] { grape::layout_timeline(std::vector{child(1.0, "<-0.1")}); }, {"entries[0]", "negative start"});
    expect_error([] { grape::layout_timeline(std::vector{child(INFINITY)}); }, {"entries[0]", "duration", "inf"});
    expect_error([] { grape::layout_timeline(std::vector{child(-1)}); }, {"entries[0]", "duration", "-1"});
    expect_error([] { grape::layout_timeline(std::vector{TimelineEntry{.at = {.offset = NAN}, .duration = 1}}); },
                 {"entries[0]", "offset must be finite"});
    expect_error([] { grape::layout_timeline(std::vector{label("")}); }, {"entries[0]", "needs a name"});
    expect_error([] { grape::layout_timeline(std::vector{child(1.7e308), child(1.7e308)}); }, {"entries[1]", "overflows"});
}

// The closed form: seconds of own time τ = t·time_scale − delay; cycle c = duration +
// repeat_delay; play k = ⌊τ / c⌋; within it s = τ − k·c, held at duration during the repeat
// delay; odd plays run backwards under yoyo, all plays under reversed.
TEST(TimelineLayout, LocalTimeFollowsTheTimingModel) {
    std::mt19937_64 rng(grape::testing::test_seed(11));
    std::uniform_real_distribution<double> unit(0, 1);
    for (int round = 0; round < 200; ++round) {
        const grape::AnimationDef def{.delay = unit(rng) < 0.3 ? 0.0 : unit(rng),
                                      .repeat = static_cast<int>(rng() % 5) - 1,
                                      .repeat_delay = unit(rng) < 0.3 ? 0.0 : unit(rng),
                                      .reversed = rng() % 2 == 0,
                                      .yoyo = rng() % 2 == 0,
                                      .time_scale = 0.25 + 2.0 * unit(rng)};
        const double duration = 0.25 + 3.0 * unit(rng);
        const double c = duration + def.repeat_delay;
        const double plays = def.repeat < 0 ? INFINITY : def.repeat + 1.0;
        for (int k = 0; k < 200; ++k) {
            const double t = unit(rng) * 20.0;
            const double tau = t * def.time_scale - def.delay;
            double local;  // forward seconds into the play, then the direction
            bool backward = def.reversed;
            if (tau < 0.0) {
                local = 0.0;
            } else if (tau >= plays * duration + (plays - 1.0) * def.repeat_delay) {
                local = duration;
                if (def.yoyo && std::fmod(plays - 1.0, 2.0) == 1.0) backward = !backward;
            } else {
                const double play = std::floor(tau / c);
                local = std::min(tau - play * c, duration);
                if (def.yoyo && std::fmod(play, 2.0) == 1.0) backward = !backward;
            }
            if (backward) local = duration - local;
            // The model runs in plays (τ / duration, rounded twice) and snaps within 1e-9
            // plays of a play's end: |error| ≤ 1e-9·duration plus a few ulps of τ; near a
            // snap (or a direction change there) the two may lie on either side of it.
            const double got = grape::timeline_local_time(def, duration, t);
            const double snap_slack = 2e-9 * duration;
            const double to_edge = std::fmod(std::max(tau, 0.0), c);
            const bool near_edge = std::min({std::fabs(to_edge), std::fabs(to_edge - duration), std::fabs(c - to_edge)}) < snap_slack;
            if (!near_edge) {
                EXPECT_NEAR(got, local, 1e-12 * (1.0 + tau)) << "round " << round << " t " << t;
            }
        }
    }
    EXPECT_EQ(grape::timeline_local_time({}, 0.0, 5.0), 0.0);
    EXPECT_EQ(grape::timeline_local_time({.delay = 1}, 2.0, 0.5), 0.0);
    EXPECT_EQ(grape::timeline_local_time({.delay = 1, .reversed = true}, 2.0, 0.5), 2.0);
    EXPECT_EQ(grape::timeline_local_time({.repeat = 1, .repeat_delay = 0.5}, 2.0, 2.25), 2.0);  // holding the end
    EXPECT_EQ(grape::timeline_local_time({.repeat = 1, .repeat_delay = 0.5, .yoyo = true}, 2.0, 3.0), 1.5);
}

}  // namespace
