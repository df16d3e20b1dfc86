// Tests for grape::SpriteSheet and grape::ClipPlayer: clips with per-frame durations, the four
// directions and repeat counts, events and clip switches, against a reference model.
//
// The reference model is written separately from the player: it unrolls a clip pass by pass
// as Aseprite describes it (a ping-pong pass is one direction; later passes leave out the frame
// they share with the previous one) and finds the frame shown at an elapsed time by searching
// the cumulative durations, in exact integer arithmetic. Rates are m / 2^a, steps 1 / 2^b s and
// durations whole milliseconds, so every time the player forms is a multiple of 2^−(a+b) ms
// below 2^40 and exact in double: the comparisons are equalities.
#include <grape/error.hpp>
#include <grape/sprite.hpp>

#include "clip_reference.hpp"
#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <random>
#include <string>
#include <vector>

namespace {

using grape::ClipDirection;
using grape::ClipEvent;
using grape::ClipEventKind;
using grape::ClipPlayer;
using grape::ClipSwitch;
using grape::SpriteClip;
using grape::SpriteFrame;
using grape::SpriteSheet;
using grape::testing::expect_error;
using grape::testing::Reference;
using grape::testing::RefEvent;

// A sheet of n frames in a row, 16×16 each, with the given durations.
SpriteSheet row_sheet(const std::vector<int>& durations, std::vector<SpriteClip> clips) {
    std::vector<SpriteFrame> frames;
    for (std::size_t k = 0; k < durations.size(); ++k) {
        frames.push_back({.rect = {static_cast<int>(16 * k), 0, 16, 16}, .duration_ms = static_cast<double>(durations[k])});
    }
    return SpriteSheet({.width = static_cast<int>(16 * durations.size()), .height = 16, .frames = std::move(frames),
                        .clips = std::move(clips)});
}

// For many random clips (every direction, with and without repeats), rates m/2^a of either
// sign and steps 1/2^b s: after every step the frame and the events equal the reference's.
TEST(ClipPlayer, MatchesTheReferenceModelExactly) {
    std::mt19937_64 rng(grape::testing::test_seed(20261201));
    const ClipDirection directions[] = {ClipDirection::forward, ClipDirection::reverse, ClipDirection::ping_pong,
                                        ClipDirection::ping_pong_reverse};
    int completed = 0, backwards = 0, looped = 0;
    for (int trial = 0; trial < 1500; ++trial) {
        const int n = std::uniform_int_distribution<int>(1, 9)(rng);
        std::vector<int> durations(static_cast<std::size_t>(n));
        for (int& d : durations) d = std::uniform_int_distribution<int>(10, 250)(rng);
        const auto from = std::uniform_int_distribution<std::size_t>(0, static_cast<std::size_t>(n - 1))(rng);
        const auto to = std::uniform_int_distribution<std::size_t>(from, static_cast<std::size_t>(n - 1))(rng);
        const int repeat = std::uniform_int_distribution<int>(0, 2)(rng) == 0 ? 0 : std::uniform_int_distribution<int>(1, 5)(rng);
        const SpriteClip clip{.name = "c", .from = from, .to = to, .direction = directions[trial % 4], .repeat = repeat};
        const SpriteSheet sheet = row_sheet(durations, {clip});
        const int a = std::uniform_int_distribution<int>(0, 6)(rng);
        const int b = std::uniform_int_distribution<int>(4, 6)(rng);
        std::int64_t m = std::uniform_int_distribution<std::int64_t>(1, 4 << a)(rng);
        const bool backward = repeat > 0 && std::bernoulli_distribution(0.4)(rng);  // forever clips: forwards here
        if (backward) m = -m;
        const double rate = std::ldexp(static_cast<double>(m), -a);
        const double dt = std::ldexp(1.0, -b);
        const std::int64_t scale = std::int64_t{1} << (a + b);  // times are N / scale ms
        const std::int64_t per_step = (backward ? -m : m) * 1000;  // |rate|·dt·1000·scale

        const int steps = 400;
        // Enough passes for a forever clip to cover the run: each pass lasts ≥ 10 ms.
        Reference ref(sheet, clip, 2 + (steps * per_step / scale) / 10 + 1, backward);
        ClipPlayer player(sheet, "c", {.rate = rate});
        std::vector<RefEvent> got;
        player.on_event([&](const ClipEvent& e) { got.push_back({e.kind, e.frame, e.pass}); });
        ASSERT_EQ(player.frame(), ref.frame());
        for (int k = 1; k <= steps && !ref.done; ++k) {
            got.clear();
            player.advance(dt);
            const std::vector<RefEvent> want = ref.play_to(per_step * k, scale);
            ASSERT_EQ(got, want) << "trial " << trial << " step " << k << " rate " << rate << " from " << from << " to "
                                 << to << " repeat " << repeat;
            ASSERT_EQ(player.frame(), ref.frame());
            ASSERT_EQ(player.finished(), ref.done);
        }
        const bool done = ref.done;
        const std::size_t at = ref.at;
        completed += done;
        backwards += backward;
        looped += ref.seq[at].pass > 0;
    }
    // The draw covers what it is meant to: completions, backward play, several passes.
    EXPECT_GT(completed, 300);
    EXPECT_GT(backwards, 200);
    EXPECT_GT(looped, 500);
}

// Time carries across frames: 0.5 at 1/64 s steps through 30, 50, 20 ms frames lands exactly on
// the boundaries the durations give (7.8125 ms of clip time per step).
TEST(ClipPlayer, TimeLeftOverCarriesIntoTheNextFrame) {
    const SpriteSheet sheet = row_sheet({30, 50, 20}, {{.name = "c", .from = 0, .to = 2}});
    ClipPlayer player(sheet, "c", {.rate = 0.5});
    player.advance(1.0 / 64);
    EXPECT_EQ(player.time_in_frame_ms(), 7.8125);
    for (int k = 0; k < 3; ++k) player.advance(1.0 / 64);  // 31.25 ms
    EXPECT_EQ(player.frame(), 1u);
    EXPECT_EQ(player.time_in_frame_ms(), 1.25);
    for (int k = 0; k < 8; ++k) player.advance(1.0 / 64);  // 93.75 ms: 100 is the loop
    EXPECT_EQ(player.frame(), 2u);
    EXPECT_EQ(player.time_in_frame_ms(), 13.75);
    player.advance(1.0 / 64);  // 101.5625 ms
    EXPECT_EQ(player.frame(), 0u);
    EXPECT_EQ(player.time_in_frame_ms(), 1.5625);
    EXPECT_EQ(player.pass(), 1);
}

// A fast rate enters every frame in one step, in order, loops included.
TEST(ClipPlayer, FastRatesSkipNoFrameEvents) {
    const SpriteSheet sheet = row_sheet({10, 20, 10, 40}, {{.name = "pp", .from = 0, .to = 3, .direction = ClipDirection::ping_pong}});
    ClipPlayer player(sheet, "pp", {.rate = 16});
    std::vector<std::size_t> frames;
    int loops = 0;
    player.on_event([&](const ClipEvent& e) {
        if (e.kind == ClipEventKind::frame) frames.push_back(e.frame);
        if (e.kind == ClipEventKind::loop) loops += static_cast<int>(e.count);
    });
    // 250 ms: steps start at 0 10 30 40 | 80 90 110 | 120 140 150 | 190 200 220 | 230 250: frame 2 at 250.
    player.advance(1.0 / 64);
    EXPECT_EQ(frames, (std::vector<std::size_t>{1, 2, 3, 2, 1, 0, 1, 2, 3, 2, 1, 0, 1, 2}));
    EXPECT_EQ(loops, 4);
    EXPECT_EQ(player.frame(), 2u);
}

// A huge step walks at most the budget and counts the rest of the loops in one event.
TEST(ClipPlayer, HugeStepsAreBoundedAndCountEveryLoop) {
    const SpriteSheet sheet = row_sheet({10, 20, 30}, {{.name = "c", .from = 0, .to = 2}});
    ClipPlayer player(sheet, "c");
    std::int64_t frames = 0, loops = 0;
    player.on_event([&](const ClipEvent& e) {
        if (e.kind == ClipEventKind::frame) ++frames;
        if (e.kind == ClipEventKind::loop) loops += e.count;
    });
    player.advance(6000.0 + 0.035);  // 6,000,035 ms = 100,000 loops of 60 ms + 35 ms (frame 2)
    EXPECT_EQ(player.frame(), 2u);
    EXPECT_EQ(loops, 100000);
    EXPECT_EQ(player.pass(), 100000);
    EXPECT_LE(frames, 3 * 65536 + 6);
    EXPECT_GE(frames, 3);
    EXPECT_NEAR(player.time_in_frame_ms(), 5.0, 1e-6);  // 6000.035 s is not binary-exact: 1e-6 ms ≫ its rounding (1e-9 ms)
    // An absurd step (10^303 ms) still returns after walking at most two periods.
    ClipPlayer absurd(sheet, "c", {.rate = 1e300});
    absurd.advance(1.0);
    EXPECT_LT(absurd.frame(), 3u);
    EXPECT_GE(absurd.time_in_frame_ms(), 0.0);
    absurd.set_rate(-1e300);
    absurd.advance(1.0);
    EXPECT_LE(absurd.time_in_frame_ms(), 30.0);
    // A finite clip ends exactly where its passes end, whatever the step.
    const SpriteSheet finite = row_sheet({10, 20, 30}, {{.name = "c", .from = 0, .to = 2, .repeat = 50000}});
    ClipPlayer once(finite, "c");
    bool complete = false;
    once.on_event([&](const ClipEvent& e) { complete |= e.kind == ClipEventKind::complete; });
    once.advance(1e6);
    EXPECT_TRUE(complete);
    EXPECT_EQ(once.frame(), 2u);
    EXPECT_EQ(once.pass(), 49999);
}

// Switching at the end of the pass carries the time left over into the new clip; switching now
// starts the new clip at once.
TEST(ClipPlayer, SwitchesNowOrAtTheEndOfThePass) {
    const SpriteSheet sheet = row_sheet({40, 40, 40, 25, 25},
                                        {{.name = "walk", .from = 0, .to = 2}, {.name = "jump", .from = 3, .to = 4, .repeat = 1}});
    ClipPlayer player(sheet, "walk");
    std::vector<std::string> log;
    player.on_event([&](const ClipEvent& e) {
        const char* names[] = {"frame", "loop", "complete", "switched"};
        log.push_back(std::string(names[static_cast<int>(e.kind)]) + " " + std::to_string(e.frame));
    });
    player.advance(0.0625);  // 62.5 ms: frame 1
    player.play("jump", ClipSwitch::at_loop_end);
    EXPECT_EQ(player.clip(), 0u);
    player.advance(0.0625);  // 125 ms: walk ended at 120, jump 5 ms in
    EXPECT_EQ(player.clip(), 1u);
    EXPECT_EQ(player.frame(), 3u);
    EXPECT_EQ(player.time_in_frame_ms(), 5.0);
    EXPECT_EQ(log, (std::vector<std::string>{"frame 1", "frame 2", "switched 3", "frame 3"}));
    log.clear();
    player.advance(0.0625);  // 67.5 ms into jump (50 ms long, once): completes at its last frame
    EXPECT_TRUE(player.finished());
    EXPECT_EQ(player.frame(), 4u);
    EXPECT_EQ(log, (std::vector<std::string>{"frame 4", "complete 4"}));
    player.play("walk", ClipSwitch::at_loop_end);  // finished: switches at once
    EXPECT_FALSE(player.finished());
    EXPECT_EQ(player.frame(), 0u);
    player.advance(0.015625);
    player.play("jump");
    EXPECT_EQ(player.frame(), 3u);
    EXPECT_EQ(player.time_in_frame_ms(), 0.0);
}

// Backwards, a finite clip starts at its end and completes at its start; a forever ping-pong
// counts passes down.
TEST(ClipPlayer, BackwardsIsTheMirrorImage) {
    const SpriteSheet sheet = row_sheet({10, 10, 10}, {{.name = "pp", .from = 0, .to = 2, .direction = ClipDirection::ping_pong}});
    ClipPlayer player(sheet, "pp", {.rate = -1});
    std::vector<std::size_t> frames;
    std::vector<std::int64_t> passes;
    player.on_event([&](const ClipEvent& e) {
        if (e.kind == ClipEventKind::frame) frames.push_back(e.frame);
        if (e.kind == ClipEventKind::loop) passes.push_back(e.pass);
    });
    // The start sits at the end of step −1 (frame 1): going back 0.0625 s = 62.5 ms enters
    // steps −2 … −7: frames 2, 1, 0, 1, 2, 1.
    player.advance(0.0625);
    EXPECT_EQ(frames, (std::vector<std::size_t>{2, 1, 0, 1, 2, 1}));
    EXPECT_EQ(passes, (std::vector<std::int64_t>{-2, -3, -4}));
    // Exactly on a boundary, forwards shows the later frame and backwards the earlier one.
    const SpriteSheet row = row_sheet({125, 125}, {{.name = "c", .from = 0, .to = 1}});
    ClipPlayer fwd(row, "c");
    fwd.advance(0.125);  // exactly the boundary
    EXPECT_EQ(fwd.frame(), 1u);
    fwd.advance(0.0009765625);  // 125.9765625 ms
    fwd.set_rate(-1);
    fwd.advance(0.0009765625);  // back to exactly 125 ms
    EXPECT_EQ(fwd.frame(), 0u);
    EXPECT_EQ(fwd.time_in_frame_ms(), 125.0);
}

TEST(ClipPlayer, PauseRateAndErrors) {
    const SpriteSheet sheet = row_sheet({10, 10}, {{.name = "c", .from = 0, .to = 1}});
    ClipPlayer player(sheet, "c");
    player.pause();
    player.advance(1.0);
    EXPECT_EQ(player.time_in_frame_ms(), 0.0);
    EXPECT_FALSE(player.playing());
    player.resume();
    player.advance(0.0078125);
    EXPECT_EQ(player.time_in_frame_ms(), 7.8125);
    expect_error([&] { player.advance(-1); }, {"ClipPlayer::advance", "dt", "-1"});
    expect_error([&] { player.set_rate(NAN); }, {"rate must be finite", "nan"});
    expect_error([&] { player.play("run"); }, {"no clip named 'run'", "clips: 'c'"});
    expect_error([&] { player.play(std::size_t{3}); }, {"clip 3", "has 1"});
    expect_error([&] { ClipPlayer bad(sheet, "c", {.rate = INFINITY}); }, {"rate must be finite"});
    player.set_rate(1e300);
    expect_error([&] { player.advance(1e300); }, {"overflows"});
}

TEST(SpriteSheet, ChecksFramesClipsAndSlices) {
    using grape::SpriteSheetDef;
    const SpriteFrame ok{.rect = {0, 0, 8, 8}};
    expect_error([] { SpriteSheet s(SpriteSheetDef{.width = 8, .height = 8}); }, {"frames is empty"});
    expect_error([&] { SpriteSheet s({.width = 0, .height = 8, .frames = {ok}}); }, {"width and height must be positive"});
    expect_error([] { SpriteSheet s({.width = 8, .height = 8, .frames = {{.rect = {4, 0, 8, 8}}}}); },
                 {"frames[0].rect", "leaves the 8x8 sheet"});
    expect_error([] { SpriteSheet s({.width = 8, .height = 8, .frames = {{.rect = {0, 0, 8, 8}, .duration_ms = 0}}}); },
                 {"frames[0].duration_ms", "positive", "got 0"});
    expect_error([] { SpriteSheet s({.width = 8, .height = 8, .frames = {{.rect = {0, 0, 8, 8}, .offset_x = 2, .source_width = 9}}}); },
                 {"frames[0].offset", "outside the 9x8 untrimmed image"});
    // A frame that is its whole untrimmed image may sit anywhere (a crop that keeps its place).
    EXPECT_EQ(SpriteSheet({.width = 8, .height = 8, .frames = {{.rect = {0, 0, 8, 8}, .offset_x = -3, .offset_y = 40}}}).frame(0).offset_x, -3);
    expect_error([&] { SpriteSheet s({.width = 8, .height = 8, .scale = 0.0, .frames = {ok}}); }, {"scale must be positive and finite (got 0)"});
    expect_error([&] { SpriteSheet s({.width = 8, .height = 8, .frames = {ok}, .clips = {{.from = 0, .to = 1}}}); },
                 {"clips[0].to", "frame count 1"});
    expect_error([&] { SpriteSheet s({.width = 8, .height = 8, .frames = {ok}, .clips = {{.repeat = -1}}}); },
                 {"clips[0].repeat", ">= 0"});
    expect_error([&] { SpriteSheet s({.width = 8, .height = 8, .frames = {ok}, .slices = {{.name = "hit", .keys = {{.frame = 2}}}}}); },
                 {"slices[0].keys", "frame 2"});
}

TEST(SpriteSheet, TrimmedRotatedFramesAndSliceKeys) {
    // A 10×6 frame trimmed from a 16×16 image, stored turned on the sheet (a 6×10 region).
    const SpriteSheet sheet({.width = 32, .height = 16,
                             .frames = {{.rect = {0, 0, 6, 10}, .rotated = true, .offset_x = 3, .offset_y = 5, .source_width = 16, .source_height = 16},
                                        {.rect = {16, 0, 16, 16}}},
                             .slices = {{.name = "hit", .keys = {{.frame = 1, .bounds = {1, 2, 3, 4}, .has_pivot = true, .pivot = {1, 1}}}}}});
    const SpriteFrame& f = sheet.frame(0);
    EXPECT_EQ(f.width(), 10);
    EXPECT_EQ(f.height(), 6);
    EXPECT_TRUE(f.trimmed());
    EXPECT_FALSE(sheet.frame(1).trimmed());
    EXPECT_EQ(sheet.frame(1).source_width, 16);  // 0 became the frame's own size
    EXPECT_EQ(sheet.slice_key("hit", 0), nullptr);
    ASSERT_NE(sheet.slice_key("hit", 1), nullptr);
    EXPECT_EQ(sheet.slice_key("hit", 1)->bounds, (grape::FrameRect{1, 2, 3, 4}));
    EXPECT_EQ(sheet.slice_key("box", 1), nullptr);
    const grape::TileSheet tiles = sheet.tile_sheet();
    EXPECT_EQ(tiles.frame(1), (grape::FrameRect{16, 0, 16, 16}));
}

}  // namespace
