// Tests for grape::SpritePlayer, TileSheet and TileSheetSprite.
//
// The reference for the remainder algorithm is exact integer arithmetic. Rates are dyadic
// rationals m / 2^d, so every value the player computes is exact in double: the fraction
// rate − trunc(rate) is a multiple of 2^−d below 1, and the remainder is a sum of such
// multiples kept in (−1, 1) (|remainder + fraction| < 2), i.e. at most d + 1 significant
// bits (d ≤ 20 here). The total move after k steps is then exactly trunc(m·k / 2^d), which
// int64 division (truncating toward zero) computes without rounding, and the remainder is
// exactly (m·k − 2^d·trunc(m·k / 2^d)) / 2^d. So the comparisons below are equalities.
#include <grape/error.hpp>
#include <grape/sprite.hpp>

#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace {

using grape::FrameRect;
using grape::PlayMode;
using grape::SpritePlayer;
using grape::TileSheet;
using grape::TileSheetDef;
using grape::TileSheetSprite;

using grape::testing::expect_error;

std::int64_t floor_mod(std::int64_t a, std::int64_t n) { return ((a % n) + n) % n; }
std::int64_t floor_div(std::int64_t a, std::int64_t n) { return (a - floor_mod(a, n)) / n; }

// A rate m / 2^d with |rate| < frames.
struct DyadicRate {
    std::int64_t m;
    int d;
    double value() const { return std::ldexp(static_cast<double>(m), -d); }
    // trunc(rate·k), exactly.
    std::int64_t moved(std::int64_t k) const { return (m * k) / (std::int64_t{1} << d); }
    // rate·k − trunc(rate·k), exactly (a dyadic rational with d bits).
    double left(std::int64_t k) const {
        return std::ldexp(static_cast<double>(m * k - moved(k) * (std::int64_t{1} << d)), -d);
    }
};

DyadicRate random_rate(std::mt19937_64& rng, std::int64_t frames) {
    const int d = std::uniform_int_distribution<int>(0, 20)(rng);
    const std::int64_t limit = frames << d;  // |m| < frames·2^d, i.e. |rate| < frames
    std::int64_t m;
    switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
        case 0:  // near the cap
            m = std::max<std::int64_t>(limit - std::uniform_int_distribution<std::int64_t>(1, 3)(rng), 0);
            break;
        case 1:  // slow: |rate| < 1
            m = std::uniform_int_distribution<std::int64_t>(0, (std::int64_t{1} << d) - 1)(rng);
            break;
        default:
            m = std::uniform_int_distribution<std::int64_t>(0, limit - 1)(rng);
    }
    if (std::bernoulli_distribution(0.5)(rng)) m = -m;
    return {m, d};
}

// For thousands of random (rate, steps, frame count, start), every step's frame and
// remainder equal the exact reference: frame = wrap(start + trunc(rate·k)).
TEST(SpritePlayer, LoopMatchesExactReferenceForRandomRates) {
    std::mt19937_64 rng(grape::testing::test_seed(20261122));
    for (int trial = 0; trial < 4000; ++trial) {
        const std::int64_t frames = trial % 10 == 0 ? 1 + trial % 3 : std::uniform_int_distribution<std::int64_t>(1, 300)(rng);
        const DyadicRate rate = random_rate(rng, frames);
        const std::int64_t start = std::uniform_int_distribution<std::int64_t>(0, frames - 1)(rng);
        const std::int64_t steps = std::uniform_int_distribution<std::int64_t>(1, 1500)(rng);
        SpritePlayer player(static_cast<std::size_t>(frames),
                            {.rate = rate.value(), .start_frame = static_cast<std::size_t>(start)});
        ASSERT_EQ(player.rate(), rate.value());  // below the cap: not clamped
        for (std::int64_t k = 1; k <= steps; ++k) {
            player.advance();
            ASSERT_EQ(static_cast<std::int64_t>(player.frame()), floor_mod(start + rate.moved(k), frames))
                << "rate " << rate.m << "/2^" << rate.d << " frames " << frames << " start " << start << " step " << k;
            ASSERT_EQ(player.remainder(), rate.left(k));
            ASSERT_GT(player.remainder(), -1.0);
            ASSERT_LT(player.remainder(), 1.0);
        }
    }
}

TEST(SpritePlayer, SeedRates) {
    // 1 normal, 0.5 half speed, −2 reverse at double speed, on 8 frames.
    auto frames_of = [](double rate, int steps) {
        SpritePlayer player(8, {.rate = rate});
        std::vector<std::size_t> seen;
        for (int k = 0; k < steps; ++k) {
            player.advance();
            seen.push_back(player.frame());
        }
        return seen;
    };
    EXPECT_EQ(frames_of(1, 9), (std::vector<std::size_t>{1, 2, 3, 4, 5, 6, 7, 0, 1}));
    EXPECT_EQ(frames_of(0.5, 6), (std::vector<std::size_t>{0, 1, 1, 2, 2, 3}));
    EXPECT_EQ(frames_of(-2, 5), (std::vector<std::size_t>{6, 4, 2, 0, 6}));
    // Reverse is the mirror image of forward play: −0.5 holds the start frame as long as 0.5 does.
    EXPECT_EQ(frames_of(-0.5, 6), (std::vector<std::size_t>{0, 7, 7, 6, 6, 5}));
}

TEST(SpritePlayer, RemainderStaysInsideForNonDyadicRates) {
    // 0.1, 1/3, ... are not exact in binary, so the frame may lag the rational reference by
    // one at the exact multiples; the remainder must still stay in (−1, 1) and the frame
    // within one of the reference.
    std::mt19937_64 rng(grape::testing::test_seed(4));
    for (int trial = 0; trial < 200; ++trial) {
        const std::int64_t frames = std::uniform_int_distribution<std::int64_t>(2, 64)(rng);
        const double rate = std::uniform_real_distribution<double>(-static_cast<double>(frames), frames)(rng);
        SpritePlayer player(static_cast<std::size_t>(frames), {.rate = rate});
        for (std::int64_t k = 1; k <= 20000; ++k) {
            player.advance();
            ASSERT_GT(player.remainder(), -1.0);
            ASSERT_LT(player.remainder(), 1.0);
        }
        const long double exact = static_cast<long double>(rate) * 20000;
        const auto reference = static_cast<std::int64_t>(std::trunc(exact));
        const std::int64_t difference =
            floor_mod(static_cast<std::int64_t>(player.frame()) - floor_mod(reference, frames), frames);
        EXPECT_TRUE(difference == 0 || difference == 1 || difference == frames - 1) << "rate " << rate;
    }
}

TEST(SpritePlayer, RateIsCappedBelowTheFrameCount) {
    SpritePlayer player(8);
    const double cap = std::nextafter(8.0, 0.0);
    player.set_rate(100);
    EXPECT_EQ(player.rate(), cap);
    player.set_rate(-8);
    EXPECT_EQ(player.rate(), -cap);
    player.set_rate(7.5);
    EXPECT_EQ(player.rate(), 7.5);
    // At the cap, cap = 8 − 2^−50, each step moves 7 frames and carries once: trunc(k·cap) =
    // 8k − 1 for 1 ≤ k < 2^50, so the frame settles one behind the start (the wagon-wheel
    // effect of a rate near a full cycle per step).
    SpritePlayer fast(8, {.rate = 1e9, .start_frame = 3});
    for (int k = 1; k <= 1000; ++k) {
        fast.advance();
        ASSERT_EQ(fast.frame(), 2u);
        // fraction 1 − 2^−50 each step, one carry per step after the first: 1 − k·2^−50 (exact).
        ASSERT_EQ(fast.remainder(), 1.0 - std::ldexp(static_cast<double>(k), -50));
    }
    expect_error([&] { player.set_rate(std::nan("")); }, {"rate", "finite", "nan"});
    expect_error([&] { player.set_rate(INFINITY); }, {"rate", "finite", "inf"});
    expect_error([] { SpritePlayer p(4, {.rate = -INFINITY}); }, {"rate", "finite"});
    EXPECT_EQ(player.rate(), 7.5);  // a rejected rate changes nothing
}

TEST(SpritePlayer, OnceStopsAtTheEndAndReportsCompletionOnce) {
    std::mt19937_64 rng(grape::testing::test_seed(8));
    for (int trial = 0; trial < 1500; ++trial) {
        const std::int64_t frames = std::uniform_int_distribution<std::int64_t>(1, 40)(rng);
        const DyadicRate rate = random_rate(rng, frames);
        const std::int64_t start = std::uniform_int_distribution<std::int64_t>(0, frames - 1)(rng);
        SpritePlayer player(static_cast<std::size_t>(frames), {.rate = rate.value(), .mode = PlayMode::once,
                                                               .start_frame = static_cast<std::size_t>(start)});
        int completions = 0;
        player.on_complete([&] { ++completions; });
        bool done = false;
        for (std::int64_t k = 1; k <= 300; ++k) {
            player.advance();
            const std::int64_t target = start + rate.moved(k);
            if (!done && (target >= frames || target < 0)) done = true;
            if (done) {
                // Stopped at the end it ran into, remainder cleared.
                ASSERT_EQ(static_cast<std::int64_t>(player.frame()), rate.m > 0 ? frames - 1 : 0);
                ASSERT_FALSE(player.playing());
                ASSERT_EQ(completions, 1);
                ASSERT_EQ(player.remainder(), 0.0);
            } else {
                ASSERT_EQ(static_cast<std::int64_t>(player.frame()), target);
                ASSERT_TRUE(player.playing());
                ASSERT_EQ(completions, 0);
            }
        }
    }
    // Four frames at rate 1 take four steps: frame 3 is shown for a full step before the end.
    SpritePlayer player(4, {.mode = PlayMode::once});
    bool complete = false;
    player.on_complete([&] { complete = true; });
    for (std::size_t expected : {1u, 2u, 3u}) {
        player.advance();
        EXPECT_EQ(player.frame(), expected);
        EXPECT_FALSE(complete);
    }
    player.advance();
    EXPECT_TRUE(complete);
    EXPECT_EQ(player.frame(), 3u);
    player.play();  // restarts from the beginning
    EXPECT_EQ(player.frame(), 0u);
    EXPECT_TRUE(player.playing());
}

TEST(SpritePlayer, PingPongBouncesBetweenTheEnds) {
    SpritePlayer player(4, {.mode = PlayMode::ping_pong});
    std::vector<std::size_t> seen;
    for (int k = 0; k < 8; ++k) {
        player.advance();
        seen.push_back(player.frame());
    }
    EXPECT_EQ(seen, (std::vector<std::size_t>{1, 2, 3, 2, 1, 0, 1, 2}));
    // Random rates against the reference: fold(wrap(start + trunc(rate·k), 2n − 2)).
    std::mt19937_64 rng(grape::testing::test_seed(9));
    for (int trial = 0; trial < 1500; ++trial) {
        const std::int64_t frames = std::uniform_int_distribution<std::int64_t>(1, 40)(rng);
        const DyadicRate rate = random_rate(rng, frames);
        const std::int64_t start = std::uniform_int_distribution<std::int64_t>(0, frames - 1)(rng);
        const std::int64_t cycle = frames > 1 ? 2 * frames - 2 : 1;
        SpritePlayer p(static_cast<std::size_t>(frames), {.rate = rate.value(), .mode = PlayMode::ping_pong,
                                                          .start_frame = static_cast<std::size_t>(start)});
        for (std::int64_t k = 1; k <= 400; ++k) {
            p.advance();
            std::int64_t q = floor_mod(start + rate.moved(k), cycle);
            if (q >= frames) q = cycle - q;
            ASSERT_EQ(static_cast<std::int64_t>(p.frame()), q) << "frames " << frames << " step " << k;
        }
    }
}

TEST(SpritePlayer, FrameCallbackReportsEveryFrameEnteredAndLoopsAreCounted) {
    std::mt19937_64 rng(grape::testing::test_seed(10));
    for (PlayMode mode : {PlayMode::loop, PlayMode::ping_pong}) {
        for (int trial = 0; trial < 500; ++trial) {
            const std::int64_t frames = std::uniform_int_distribution<std::int64_t>(1, 30)(rng);
            const DyadicRate rate = random_rate(rng, frames);
            const std::int64_t start = std::uniform_int_distribution<std::int64_t>(0, frames - 1)(rng);
            const std::int64_t cycle = mode == PlayMode::loop ? frames : (frames > 1 ? 2 * frames - 2 : 1);
            SpritePlayer player(static_cast<std::size_t>(frames),
                                {.rate = rate.value(), .mode = mode, .start_frame = static_cast<std::size_t>(start)});
            std::vector<std::size_t> reported;
            std::size_t loops = 0;
            player.on_frame([&](std::size_t f) { reported.push_back(f); });
            player.on_loop([&](std::size_t cycle, std::size_t skipped) {
                EXPECT_EQ(cycle, loops + skipped + 1);  // every completed cycle counted once
                loops = cycle;
            });
            const std::int64_t steps = 200;
            for (std::int64_t k = 0; k < steps; ++k) player.advance();
            // Every position between the start and the end, one by one, in the direction of travel.
            const std::int64_t moved = rate.moved(steps);
            const std::int64_t direction = moved >= 0 ? 1 : -1;
            std::vector<std::size_t> expected;
            for (std::int64_t s = 1; s <= moved * direction; ++s) {
                std::int64_t q = floor_mod(start + direction * s, cycle);
                if (q >= frames) q = cycle - q;
                expected.push_back(static_cast<std::size_t>(q));
            }
            ASSERT_EQ(reported, expected) << "frames " << frames << " rate " << rate.value();
            ASSERT_EQ(static_cast<std::int64_t>(loops), std::abs(floor_div(start + moved, cycle)));
        }
    }
}

TEST(SpritePlayer, TimeBasedAdvance) {
    // dt·fps = 1 exactly (1/64 s at 64 fps): identical to one advance() per call.
    std::mt19937_64 rng(grape::testing::test_seed(12));
    for (int trial = 0; trial < 300; ++trial) {
        const std::int64_t frames = std::uniform_int_distribution<std::int64_t>(1, 50)(rng);
        const DyadicRate rate = random_rate(rng, frames);
        SpritePlayer stepped(static_cast<std::size_t>(frames), {.rate = rate.value()});
        SpritePlayer timed(static_cast<std::size_t>(frames), {.rate = rate.value()});
        for (int k = 0; k < 200; ++k) {
            stepped.advance();
            timed.advance(1.0 / 64, 64);
            ASSERT_EQ(timed.frame(), stepped.frame());
            ASSERT_EQ(timed.remainder(), stepped.remainder());
        }
    }
    // 0.25 s at 10 fps is 2.5 frames.
    SpritePlayer player(8);
    player.advance(0.25, 10);
    EXPECT_EQ(player.frame(), 2u);
    EXPECT_EQ(player.remainder(), 0.5);
    player.advance(0.25, 10);
    EXPECT_EQ(player.frame(), 5u);
    EXPECT_EQ(player.remainder(), 0.0);
    // A long hitch: 10 s at 8 fps is 80 frames, ten whole cycles of 8 frames.
    std::size_t loops = 0, reported = 0;
    std::size_t skipped = 0;
    player.on_loop([&](std::size_t cycle, std::size_t s) {
        loops = cycle;
        skipped = s;
    });
    player.on_frame([&](std::size_t) { ++reported; });
    player.advance(10, 8);
    EXPECT_EQ(player.frame(), 5u);
    EXPECT_EQ(loops, 10u);
    EXPECT_EQ(skipped, 9u);   // one call for the ten cycles
    EXPECT_EQ(reported, 8u);  // at most one cycle of frame events per call
    player.advance(1, 8);     // one more cycle of 8 frames: the count goes on
    EXPECT_EQ(loops, 11u);
    EXPECT_EQ(skipped, 0u);
    player.on_loop([&](std::size_t cycle) { loops = cycle; });  // a new callback counts from 0
    player.advance(1, 8);
    EXPECT_EQ(loops, 1u);
    // Once mode: a long step ends the playback.
    SpritePlayer once(8, {.mode = PlayMode::once});
    bool complete = false;
    once.on_complete([&] { complete = true; });
    once.advance(1000, 60);
    EXPECT_TRUE(complete);
    EXPECT_EQ(once.frame(), 7u);
    expect_error([&] { player.advance(-0.1, 60); }, {"advance", "dt", "-0.1"});
    expect_error([&] { player.advance(std::nan(""), 60); }, {"dt", "nan"});
    expect_error([&] { player.advance(0.1, 0); }, {"fps", "> 0", "got 0"});
    expect_error([&] { player.advance(0.1, INFINITY); }, {"fps", "inf"});
    expect_error([&] { player.advance(1e300, 1e300); }, {"overflows"});
}

// A time step over whole cycles reports one cycle of frames in the direction of travel, also
// when the rest after dropping the cycles is zero (a move with no sign of its own): checked
// against the frames a unit-rate walk enters, for both directions and every multiple.
TEST(SpritePlayer, LongTimeStepsReportFramesInTheDirectionOfTravel) {
    SpritePlayer seed_case(3, {.rate = -1});
    std::vector<std::size_t> seen;
    seed_case.on_frame([&](std::size_t f) { seen.push_back(f); });
    seed_case.advance(2.0, 3.0);  // six frames back: exactly two cycles
    EXPECT_EQ(seen, (std::vector<std::size_t>{2, 1, 0}));
    for (PlayMode mode : {PlayMode::loop, PlayMode::ping_pong}) {
        for (std::int64_t frames = 2; frames <= 6; ++frames) {
            const std::int64_t cycle = mode == PlayMode::loop ? frames : 2 * frames - 2;
            for (double rate : {1.0, -1.0}) {
                for (std::int64_t moved = cycle; moved <= 3 * cycle; ++moved) {
                    SpritePlayer player(static_cast<std::size_t>(frames), {.rate = rate, .mode = mode});
                    std::vector<std::size_t> reported;
                    player.on_frame([&](std::size_t f) { reported.push_back(f); });
                    player.advance(static_cast<double>(moved), 1.0);  // moved·rate frames in one call
                    // The last `cycle` positions a one-frame-at-a-time walk enters, in its order.
                    std::vector<std::size_t> walk;
                    for (std::int64_t s = 1; s <= moved; ++s) {
                        std::int64_t q = floor_mod(static_cast<std::int64_t>(rate) * s, cycle);
                        if (q >= frames) q = cycle - q;
                        walk.push_back(static_cast<std::size_t>(q));
                    }
                    const std::vector<std::size_t> tail(walk.end() - cycle, walk.end());
                    ASSERT_EQ(reported, tail) << "frames " << frames << " rate " << rate << " moved " << moved;
                }
            }
        }
    }
}

// The header's note on rates that are not binary-exact, as stated there.
TEST(SpritePlayer, InexactRatesMayTrailOrLeadByOneAtExactMultiples) {
    SpritePlayer tenth(8, {.rate = 0.1});
    for (int k = 0; k < 10; ++k) tenth.advance();
    EXPECT_EQ(tenth.frame(), 0u);  // trunc(0.1·10) = 1: one behind
    tenth.advance();
    EXPECT_EQ(tenth.frame(), 1u);
    SpritePlayer third(8, {.rate = 1.0 / 3.0});
    for (int k = 0; k < 3; ++k) third.advance();
    EXPECT_LT(std::fma(third.rate(), 3.0, -1.0), 0.0);  // rounded once, so the sign is exact: the stored rate times 3 is below 1 ...
    EXPECT_EQ(third.frame(), 1u);                      // ... yet the frame is already 1: one ahead
}

// Records what the player shows.
struct RecordingPlayable : grape::Playable {
    std::size_t frames;
    std::vector<std::size_t> shown;
    explicit RecordingPlayable(std::size_t n) : frames(n) {}
    std::size_t frame_count() const noexcept override { return frames; }
    void show_frame(std::size_t k) noexcept override { shown.push_back(k); }
};

TEST(SpritePlayer, ShowsFramesOnThePlayableOnlyWhenTheyChange) {
    RecordingPlayable clip(5);
    SpritePlayer player(clip, {.rate = 0.5, .start_frame = 2});
    EXPECT_EQ(clip.shown, (std::vector<std::size_t>{2}));  // the start frame is shown at once
    for (int k = 0; k < 6; ++k) player.advance();
    EXPECT_EQ(clip.shown, (std::vector<std::size_t>{2, 3, 4, 0}));
    EXPECT_EQ(player.playable(), &clip);
    player.set_frame(1);
    EXPECT_EQ(clip.shown.back(), 1u);
    EXPECT_EQ(player.remainder(), 0.0);
    // Attaching a shorter playable clamps the frame and the rate cap.
    RecordingPlayable shorter(2);
    player.set_frame(4);
    player.set_rate(4.5);
    player.set_playable(shorter);
    EXPECT_EQ(player.frame(), 1u);
    EXPECT_EQ(shorter.shown, (std::vector<std::size_t>{1}));
    EXPECT_EQ(player.rate(), std::nextafter(2.0, 0.0));
    RecordingPlayable empty(0);
    expect_error([&] { player.set_playable(empty); }, {"set_playable", "no frames"});
    expect_error([&] { SpritePlayer p(empty); }, {"playable", "no frames"});
}

TEST(SpritePlayer, PauseSetFrameAndModeChanges) {
    SpritePlayer player(6, {.rate = 1});
    player.pause();
    player.advance();
    player.advance(1.0, 60);
    EXPECT_EQ(player.frame(), 0u);
    player.play();
    player.advance();
    EXPECT_EQ(player.frame(), 1u);
    player.set_frame(5);
    player.set_mode(PlayMode::ping_pong);
    EXPECT_EQ(player.frame(), 5u);
    player.advance();
    EXPECT_EQ(player.frame(), 4u);  // 5 is the last frame: the forward leg bounces back
    player.set_mode(PlayMode::loop);
    player.set_frame(5);
    player.advance();
    EXPECT_EQ(player.frame(), 0u);
}

TEST(SpritePlayer, CallbacksMayReplaceThemselves) {
    SpritePlayer player(4);
    int first = 0, second = 0;
    player.on_frame([&](std::size_t) {
        ++first;
        player.on_frame([&](std::size_t) { ++second; });  // replaces the running callback
    });
    player.advance();
    player.advance();
    player.advance();
    EXPECT_EQ(first, 1);
    EXPECT_EQ(second, 2);
    int removed = 0;
    player.on_frame([&](std::size_t) {
        ++removed;
        player.on_frame({});  // removes itself
    });
    player.advance();
    player.advance();
    EXPECT_EQ(removed, 1);
    // A copy carries its own callbacks.
    int count = 0;
    player.on_frame([&](std::size_t) { ++count; });
    SpritePlayer copy = player;
    copy.advance();
    player.advance();
    EXPECT_EQ(count, 2);
}

// The playable and the callbacks share one word of the player (40 bytes): the playable
// follows it into and out of the callbacks' block, through copies, moves and set_playable.
TEST(SpritePlayer, PlayableAndCallbacksSurviveCopiesAndMoves) {
    EXPECT_LE(sizeof(SpritePlayer), 40u);
    RecordingPlayable a(4), b(6);
    SpritePlayer player(a, {.rate = 1.0});
    int frames = 0;
    player.on_frame([&](std::size_t) { ++frames; });
    EXPECT_EQ(player.playable(), &a);  // now kept in the callbacks' block
    player.advance();
    EXPECT_EQ(a.shown, (std::vector<std::size_t>{0, 1}));
    EXPECT_EQ(frames, 1);
    player.set_playable(b);
    EXPECT_EQ(player.playable(), &b);
    player.advance();
    EXPECT_EQ(b.shown, (std::vector<std::size_t>{1, 2}));
    EXPECT_EQ(frames, 2);

    SpritePlayer copy = player;  // its own callbacks, the same playable
    EXPECT_EQ(copy.playable(), &b);
    copy.advance();
    EXPECT_EQ(frames, 3);
    SpritePlayer moved = std::move(copy);
    EXPECT_EQ(moved.playable(), &b);
    moved.advance();
    EXPECT_EQ(frames, 4);
    EXPECT_EQ(copy.playable(), &b);  // the moved-from player keeps its playable ...
    copy.advance();                  // ... and steps without the callbacks
    EXPECT_EQ(frames, 4);

    SpritePlayer bare(a);  // no callbacks: assigned over one that has them, and back
    bare = player;
    EXPECT_EQ(bare.playable(), &b);
    bare.advance();
    EXPECT_EQ(frames, 5);
    bare = SpritePlayer(a);
    EXPECT_EQ(bare.playable(), &a);
    bare.advance();
    EXPECT_EQ(frames, 5);
    SpritePlayer counter(3);  // a bare frame counter with callbacks has no playable
    counter.on_loop([&](std::size_t) { ++frames; });
    EXPECT_EQ(counter.playable(), nullptr);
}

TEST(SpritePlayer, ConstructionErrorsNameTheArgument) {
    expect_error([] { SpritePlayer p(0); }, {"frame_count", "at least 1", "got 0"});
    expect_error([] { SpritePlayer p(4, {.start_frame = 4}); }, {"start_frame 4", "frame_count 4"});
    expect_error([] { SpritePlayer p((std::size_t{1} << 30) + 1); }, {"frame_count 1073741825", "too large", "2^30"});
    SpritePlayer largest(std::size_t{1} << 30, {.rate = -1e12, .mode = PlayMode::ping_pong});
    largest.advance();  // the largest cycle, 2^31 − 2, still fits in the 32-bit position
    // The clamped rate is −(2^30 − 2^−23): one step moves −(2^30 − 1) (no carry yet), which
    // from 0 on the 2^31 − 2 cycle lands on 2^30 − 1, the last frame.
    EXPECT_EQ(largest.frame(), (std::size_t{1} << 30) - 1);

    SpritePlayer player(3);
    expect_error([&] { player.set_frame(3); }, {"set_frame", "k 3", "frame_count 3"});
}

TEST(SpritePlayer, SingleFrameNeverMoves) {
    for (PlayMode mode : {PlayMode::loop, PlayMode::once, PlayMode::ping_pong}) {
        SpritePlayer player(1, {.rate = -0.75, .mode = mode});
        for (int k = 0; k < 50; ++k) {
            player.advance();
            ASSERT_EQ(player.frame(), 0u);
        }
    }
}

// ---- TileSheet ----

TEST(TileSheet, GridWithMarginAndSpacing) {
    // 3 columns of 20 px and 2 rows of 10 px, margin 2, spacing 1: 2+20+1+20+1+20+2 = 66 wide,
    // 2+10+1+10+2 = 25 high; frames derived from the sheet size.
    const TileSheet sheet({.width = 66, .height = 25, .columns = 3, .rows = 2, .margin = 2, .spacing = 1});
    ASSERT_EQ(sheet.frame_count(), 6u);
    for (std::size_t k = 0; k < 6; ++k) {
        const int column = static_cast<int>(k % 3), row = static_cast<int>(k / 3);
        EXPECT_EQ(sheet.frame(k), (FrameRect{2 + column * 21, 2 + row * 11, 20, 10})) << k;
    }
    EXPECT_EQ(sheet.at(5), (FrameRect{44, 13, 20, 10}));
    // The last frame ends exactly at the far margin.
    EXPECT_EQ(sheet.frame(5).x + sheet.frame(5).width, 66 - 2);
    // Given frame size with spare pixels at the right and bottom, and a partial last row.
    const TileSheet padded({.width = 128, .height = 128, .columns = 5, .rows = 3, .frame_width = 24,
                            .frame_height = 40, .frame_count = 13});
    ASSERT_EQ(padded.frame_count(), 13u);
    EXPECT_EQ(padded.frame(12), (FrameRect{48, 80, 24, 40}));
    // Texture coordinates on a power-of-two sheet are exact.
    const auto uv = padded.uv(12);
    EXPECT_EQ(uv.u0, 48.0 / 128);
    EXPECT_EQ(uv.v0, 80.0 / 128);
    EXPECT_EQ(uv.u1, 72.0 / 128);
    EXPECT_EQ(uv.v1, 120.0 / 128);
    expect_error([&] { (void)padded.at(13); }, {"TileSheet::at", "k 13", "frame_count 13"});
}

TEST(TileSheet, GridErrorsNameTheField) {
    expect_error([] { TileSheet s({.width = 0, .height = 10}); }, {"width", "positive", "got 0"});
    expect_error([] { TileSheet s({.width = 10, .height = -3}); }, {"height", "got -3"});
    expect_error([] { TileSheet s({.width = 10, .height = 10, .columns = 0}); }, {"columns", "got 0"});
    expect_error([] { TileSheet s({.width = 10, .height = 10, .rows = -1}); }, {"rows"});
    expect_error([] { TileSheet s({.width = 10, .height = 10, .margin = -1}); }, {"margin", ">= 0"});
    expect_error([] { TileSheet s({.width = 10, .height = 10, .spacing = -2}); }, {"spacing", "got -2"});
    expect_error([] { TileSheet s({.width = 10, .height = 10, .columns = 3}); }, {"width 10", "3 columns", "frame_width"});
    expect_error([] { TileSheet s({.width = 10, .height = 10, .margin = 5}); }, {"width 10", "leaves 0"});
    expect_error([] { TileSheet s({.width = 10, .height = 10, .columns = 2, .frame_width = 6}); },
                 {"2 columns", "frame_width 6", "need 12", "width 10"});
    expect_error([] { TileSheet s({.width = 10, .height = 10, .frame_height = -4}); }, {"frame_height", "got -4"});
    expect_error([] { TileSheet s({.width = 10, .height = 10, .columns = 2, .rows = 2, .frame_count = 5}); },
                 {"frame_count 5", "columns*rows (4)"});
}

#ifndef NDEBUG
TEST(TileSheetDeathTest, DebugBuildsAssertFrameIndices) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const TileSheet sheet({.width = 8, .height = 8, .columns = 2, .rows = 2});
    EXPECT_DEATH((void)sheet.frame(4), "frame index out of range");
}
#endif

TEST(TileSheet, RectangleList) {
    const TileSheet atlas(64, 32, {{0, 0, 16, 16}, {16, 0, 48, 32}, {0, 16, 8, 8}});
    EXPECT_EQ(atlas.frame_count(), 3u);
    EXPECT_EQ(atlas.frame(1), (FrameRect{16, 0, 48, 32}));
    expect_error([] { TileSheet s(64, 32, {}); }, {"frames is empty"});
    expect_error([] { TileSheet s(64, 32, {{0, 0, 16, 16}, {60, 0, 8, 8}}); }, {"frames[1]", "leaves the 64x32 sheet"});
    expect_error([] { TileSheet s(64, 32, {{-1, 0, 16, 16}}); }, {"frames[0]", "leaves"});
    expect_error([] { TileSheet s(64, 32, {{0, 0, 0, 16}}); }, {"frames[0]", "0x16", "positive"});
    expect_error([] { TileSheet s(0, 32, {{0, 0, 1, 1}}); }, {"width", "got 0"});
}

TEST(TileSheetSprite, PlayerDrivesTheRectangle) {
    const TileSheet sheet({.width = 256, .height = 64, .columns = 8, .rows = 2});
    TileSheetSprite hero(sheet);
    SpritePlayer player(hero, {.rate = -2});
    EXPECT_EQ(hero.frame_count(), 16u);
    for (int k = 1; k <= 20; ++k) {
        player.advance();
        const std::size_t expected = static_cast<std::size_t>(floor_mod(-2 * k, 16));
        ASSERT_EQ(hero.current_frame(), expected);
        ASSERT_EQ(hero.rect(), sheet.frame(expected));
    }
    hero.show_frame(99);  // a stale index is clamped, never read past the sheet
    EXPECT_EQ(hero.current_frame(), 15u);
    EXPECT_EQ(hero.uv().u1, 1.0);
    EXPECT_EQ(&hero.sheet(), &sheet);
}

}  // namespace
