// roll3: roll tracks in arc length against closed forms (a hand-solved natural spline, the
// clamped spline reproducing a cubic, per-interval easing written out), keys hit exactly, the
// rolled frame against its base, and automatic banking on circles and lines.
#include <grape/curve.hpp>
#include <grape/error.hpp>
#include <grape/frames3.hpp>
#include <grape/path3.hpp>
#include <grape/roll3.hpp>
#include <grape/vec3.hpp>

#include "count_allocations.hpp"
#include "error_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

using namespace grape;
using grape::testing::expect_error;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

std::vector<RollKey> random_keys(std::mt19937_64& rng, std::size_t n) {
    std::uniform_real_distribution<double> gap(0.1, 3.0), angle(-3.0, 3.0);
    std::vector<RollKey> keys;
    double s = gap(rng) - 0.1;
    for (std::size_t i = 0; i < n; ++i) {
        keys.push_back({s, angle(rng)});
        s += gap(rng);
    }
    return keys;
}

Path3 circle(double radius, bool clockwise) {
    return Path3::arc({.center = {1.0, 2.0, 3.0}, .radius = radius, .start_angle = 0.0,
                       .end_angle = clockwise ? -2.0 * std::numbers::pi : 2.0 * std::numbers::pi});
}

}  // namespace

TEST(RollTrack, RefusesBadKeys) {
    const std::vector<RollKey> none;
    expect_error([&] { RollTrack t(none); }, {"RollTrack", "keys", "at least 1"});
    const std::vector<RollKey> back{{0.0, 0.0}, {2.0, 1.0}, {2.0, 0.0}};
    expect_error([&] { RollTrack t(back); }, {"keys[2]", "greater than the previous"});
    const std::vector<RollKey> negative{{-1.0, 0.0}, {2.0, 1.0}};
    expect_error([&] { RollTrack t(negative); }, {"keys[0]", ">= 0"});
    const std::vector<RollKey> nan_roll{{0.0, std::nan("")}, {2.0, 1.0}};
    expect_error([&] { RollTrack t(nan_roll); }, {"keys[0]", "roll must be finite"});
    const std::vector<RollKey> two{{0.0, 0.0}, {2.0, 1.0}};
    expect_error([&] { RollTrack t(two, {.curves = {Curve::linear(), Curve::linear()}}); }, {"curves", "one curve per interval, 1 (got 2)"});
    expect_error([&] { RollTrack t(two, {.interpolation = RollInterpolation::clamped_spline, .end_slope = std::numeric_limits<double>::infinity()}); },
                 {"end_slope", "finite"});
}

TEST(RollTrack, HitsEveryKeyExactlyInEveryMode) {
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 50; ++trial) {
        const auto keys = random_keys(rng, 2 + static_cast<std::size_t>(trial % 9));
        std::vector<Curve> curves;
        for (std::size_t i = 0; i + 1 < keys.size(); ++i) curves.push_back(i % 2 ? Curve::back_out() : Curve::quad_in_out());
        const RollTrack eased(keys, {.curves = curves});
        const RollTrack natural(keys, {.interpolation = RollInterpolation::natural_spline});
        const RollTrack clamped(keys, {.interpolation = RollInterpolation::clamped_spline, .start_slope = 0.3, .end_slope = -2.0});
        for (const RollKey& k : keys) {
            EXPECT_EQ(eased.roll_at(k.s), k.roll);
            EXPECT_EQ(natural.roll_at(k.s), k.roll);
            EXPECT_EQ(clamped.roll_at(k.s), k.roll);
        }
        // Before and after the keys the end rolls hold.
        EXPECT_EQ(natural.roll_at(keys.front().s - 1.0), keys.front().roll);
        EXPECT_EQ(clamped.roll_at(keys.back().s + 1.0), keys.back().roll);
    }
}

TEST(RollTrack, CurvesEaseEachInterval) {
    const std::vector<RollKey> keys{{0.0, 0.0}, {4.0, 1.0}, {6.0, -1.0}};
    const RollTrack t(keys, {.curves = {Curve::quad_in(), Curve::cubic_out()}});
    // quad in on [0, 4]: 0 + 1·(s/4)²; cubic out on [4, 6]: 1 − 2·(1 − (1 − x)³), x = (s − 4)/2.
    for (double s = 0.0; s <= 6.0; s += 0.125) {
        double want;
        if (s < 4.0) {
            want = (s / 4.0) * (s / 4.0);
        } else {
            const double y = 1.0 - (s - 4.0) / 2.0;
            want = 1.0 - 2.0 * (1.0 - y * y * y);
        }
        // A few roundings of numbers ≤ 2 in size each way.
        EXPECT_NEAR(t.roll_at(s), want, 8 * eps) << s;
    }
    // Without curves: linear, and equal keys give exactly their roll.
    const std::vector<RollKey> flat{{0.0, 0.7}, {1.0, 0.7}, {3.0, 0.7}};
    const RollTrack f(flat);
    for (double s = 0.0; s <= 3.0; s += 0.01) EXPECT_EQ(f.roll_at(s), 0.7);
}

TEST(RollTrack, NaturalSplineMatchesHandSolution) {
    // Keys (0, 0), (1, 1), (2, 0), natural ends: 4·M1 = 6·((0 − 1) − (1 − 0)) so M1 = −3, and
    // on [0, 1] r(s) = s + ((s³ − s)·(−3))/6 = s − (s³ − s)/2; at s = ½: 0.6875.
    const std::vector<RollKey> keys{{0.0, 0.0}, {1.0, 1.0}, {2.0, 0.0}};
    const RollTrack t(keys, {.interpolation = RollInterpolation::natural_spline});
    EXPECT_NEAR(t.roll_at(0.5), 0.6875, 2 * eps);
    for (double s = 0.0; s <= 1.0; s += 1.0 / 64) EXPECT_NEAR(t.roll_at(s), s - (s * s * s - s) / 2.0, 4 * eps) << s;
    // Symmetric about s = 1.
    for (double s = 0.0; s <= 1.0; s += 1.0 / 64) EXPECT_NEAR(t.roll_at(2.0 - s), t.roll_at(s), 4 * eps) << s;
    // Natural splines reproduce straight lines (their second derivative is 0 throughout).
    std::mt19937_64 rng(3);
    auto line = random_keys(rng, 9);
    for (RollKey& k : line) k.roll = 0.25 - 0.5 * k.s;
    const RollTrack l(line, {.interpolation = RollInterpolation::natural_spline});
    // Values ≤ 12 in size; the solve's right side is rounding only, so M is ~eps·(values/h²).
    for (double s = line.front().s; s <= line.back().s; s += 0.01) EXPECT_NEAR(l.roll_at(s), 0.25 - 0.5 * s, 64 * eps * 12);
}

TEST(RollTrack, ClampedSplineReproducesACubic) {
    // A clamped cubic spline is exact for a cubic given its end slopes: the cubic itself meets
    // every condition, and the system has one solution.
    auto p = [](double s) { return 0.5 - 0.3 * s + 0.07 * s * s - 0.004 * s * s * s; };
    auto dp = [](double s) { return -0.3 + 0.14 * s - 0.012 * s * s; };
    std::mt19937_64 rng(11);
    for (int trial = 0; trial < 20; ++trial) {
        auto keys = random_keys(rng, 3 + static_cast<std::size_t>(trial));
        for (RollKey& k : keys) k.roll = p(k.s);
        const RollTrack t(keys, {.interpolation = RollInterpolation::clamped_spline, .start_slope = dp(keys.front().s),
                                 .end_slope = dp(keys.back().s)});
        double scale = 0.0;
        for (double s = keys.front().s; s <= keys.back().s; s += 0.05) scale = std::max(scale, std::abs(p(s)));
        // The strictly diagonally dominant system (ratio ≥ 2) keeps the rounding of its right
        // side, ~eps·|r|/h², at that size in M; the cubic term M·h²/6 then adds ~eps·|r|, so a
        // few dozen roundings of the values' size bound the error.
        for (double s = keys.front().s; s <= keys.back().s; s += 0.05) {
            EXPECT_NEAR(t.roll_at(s), p(s), 256 * eps * (scale + 1.0)) << trial << " " << s;
        }
    }
}

TEST(RolledFrames3, TurnsTheBaseFrameByTheRollAtItsArcLength) {
    const Path3 path = Path3::catmull_rom(std::vector<Vec3>{{0, 0, 0}, {3, 1, 0}, {5, 4, 2}, {4, 8, 3}, {0, 9, 1}},
                                          CatmullRom::centripetal);
    const double total = path.length();
    const std::vector<RollKey> keys{{0.0, 0.0}, {0.3 * total, 1.2}, {0.7 * total, -0.4}, {total, 2.0}};
    const RolledFrames3 rolled(path, RollTrack(keys, {.interpolation = RollInterpolation::natural_spline}));
    for (int i = 0; i <= 200; ++i) {
        const double u = i / 200.0;
        const Frame3 f = rolled.frame(u);
        const Frame3 b = rolled.base().frame(u);
        const double phi = rolled.track().roll_at(path.length_at(u));
        // The table's arc length is within ~1e-15·L of length_at; the roll's slope is below
        // 10 rad per length here, so the roll agrees within 1e-13 and cos/sin within that.
        EXPECT_NEAR(dot(f.normal, b.normal), std::cos(phi), 1e-13) << u;
        EXPECT_NEAR(dot(f.normal, b.binormal), std::sin(phi), 1e-13) << u;
        EXPECT_NEAR(length(f.normal), 1.0, 4 * eps);
        EXPECT_NEAR(dot(f.normal, f.tangent), 0.0, 8 * eps);
        EXPECT_EQ(f.point, b.point);
    }
    // Keys: at s itself (frame_at_length) the roll is the key's exactly.
    for (const RollKey& k : keys) {
        const Frame3 f = rolled.frame_at_length(k.s);
        const Frame3 b = rolled.base().frame(path.u_at_length(k.s));
        EXPECT_NEAR(dot(f.normal, b.binormal), std::sin(k.roll), 4 * eps);
    }
    // The panel table against Path3::length_at (both resolve the length to ~1e-15 per unit u).
    for (int i = 0; i <= 100; ++i) EXPECT_NEAR(rolled.base().length_at(i / 100.0), path.length_at(i / 100.0), 1e-14 * total);
    const long before = g_allocations.load();
    double sum = 0.0;
    for (int i = 0; i <= 100; ++i) sum += rolled.frame(i / 100.0).normal.x;
    EXPECT_EQ(g_allocations.load(), before);
    EXPECT_TRUE(std::isfinite(sum));
    const std::vector<RollKey> past{{0.0, 0.0}, {2.0 * total, 1.0}};
    expect_error([&] { RolledFrames3 r(path, RollTrack(past)); }, {"RolledFrames3", "beyond the path's length"});
}

TEST(Bank, HorizontalCircleBanksByTheClosedFormInward) {
    for (const bool clockwise : {false, true}) {
        for (const double radius : {5.0, 20.0, 300.0}) {  // banks of 1.36, 0.85 and 0.08 rad
            const double v = 15.0, g = 9.81;
            const Path3 path = circle(radius, clockwise);
            const double want = std::atan(v * v / (g * radius));
            const BankDef def{.speed = v, .gravity = g, .max_angle = 1.5};
            const RollTrack track = bank_track(path, def);
            const RolledFrames3 banked(Frames3(path, {.mode = FrameMode::reference_up}), track);
            for (int i = 0; i <= 64; ++i) {
                const double u = i / 64.0;
                // κ = |r′×r″|/|r′|³ and n·side carry ~10 roundings; atan's relative condition
                // x/((1 + x²)·atan x) is ≤ 1, and atan itself rounds once or twice: 32 eps.
                EXPECT_NEAR(std::abs(bank_angle(path, u, def)), want, 32 * eps * want) << radius << " " << u;
                EXPECT_NEAR(std::abs(banked.roll(u)), want, 32 * eps * want);
                // Leaning inward: the banked normal's horizontal part points to the centre.
                const Frame3 f = banked.frame(u);
                const Vec3 to_centre = normalized(Vec3{1.0, 2.0, 3.0} - f.point);
                EXPECT_NEAR(dot(f.normal, to_centre), std::sin(want), 1e-13) << clockwise;
                EXPECT_NEAR(f.normal.z, std::cos(want), 1e-13);
            }
        }
    }
}

TEST(Bank, StraightLineIsLevelAndTheClampHolds) {
    const Path3 line = Path3::line({0, 0, 0}, {10, 3, 1});
    for (int i = 0; i <= 10; ++i) EXPECT_EQ(bank_angle(line, i / 10.0, {.speed = 50.0}), 0.0);
    const Path3 tight = circle(1.0, false);
    for (int i = 0; i <= 10; ++i) {
        EXPECT_EQ(std::abs(bank_angle(tight, i / 10.0, {.speed = 100.0, .max_angle = 0.5})), 0.5);
        EXPECT_EQ(bank_angle(tight, i / 10.0, {.speed = 0.0}), 0.0);
    }
    expect_error([&] { bank_track(line, {.gravity = 0.0}); }, {"bank_track", "gravity"});
    expect_error([&] { bank_track(line, {.max_angle = 2.0}); }, {"max_angle"});
    expect_error([&] { bank_track(line, {.samples = 1}); }, {"samples"});
    expect_error([&] { bank_track(line, {.up = {0, 0, 0}}); }, {"up"});
    expect_error([&] { (void)bank_angle(line, 0.5, {.speed = -1.0}); }, {"bank_angle", "speed"});
    expect_error([&] { (void)bank_angle(line, 0.5, {.gravity = std::nan("")}); }, {"bank_angle", "gravity"});
    expect_error([&] { (void)bank_angle(line, 0.5, {.up = {0, 0, 0}}); }, {"bank_angle", "up"});
}

TEST(Bank, SmoothingRemovesTheJumpAtAJoin) {
    // A line then a quarter circle of radius 10 (tangent-continuous, κ jumps 0 → 0.1).
    const Path3 path = Path3::complex_by_length(
        {Path3::line({-20, -10, 0}, {0, -10, 0}),
         Path3::arc({.center = {0, 0, 0}, .start = {0, -1, 0}, .radius = 10.0, .start_angle = 0.0, .end_angle = 0.5 * std::numbers::pi})});
    const double v = 10.0, g = 9.81, full = std::atan(v * v / (g * 10.0));
    const double join = 20.0;  // arc length of the join
    const RollTrack raw = bank_track(path, {.speed = v, .max_angle = 1.5, .samples = 2049});
    const RollTrack smooth = bank_track(path, {.speed = v, .max_angle = 1.5, .smoothing = 8.0, .samples = 2049});
    // Unsmoothed, the roll steps by the full bank within one sample spacing of the join.
    const double h = path.length() / 2048.0;
    EXPECT_NEAR(std::abs(raw.roll_at(join + h)) - std::abs(raw.roll_at(join - h)), full, 1e-12);
    // Smoothed over 8 units, no step of h changes it by more than full·h/(8 − 2h) (a box
    // average changes by at most the range over the window per window width) plus rounding.
    double worst = 0.0;
    for (double s = 0.0; s + h <= path.length(); s += h / 3) worst = std::max(worst, std::abs(smooth.roll_at(s + h) - smooth.roll_at(s)));
    EXPECT_LE(worst, full * h / (8.0 - 2.0 * h) + 1e-12);
    // Far from the join the smoothed bank is the full one and the level one.
    EXPECT_NEAR(std::abs(smooth.roll_at(join + 10.0)), full, 1e-14);
    EXPECT_EQ(smooth.roll_at(join - 10.0), 0.0);
}
