// frames3: constrained and world-up frames against independent truth — the helix's closed
// forms (Frenet frame and torsion), the least-energy twist being affine in arc length, a
// closed loop's frame closing up, roll continuity measured by transporting normals between
// samples, and equal arc-length sampling checked by length_at.
#include <grape/error.hpp>
#include <grape/frames3.hpp>
#include <grape/path3.hpp>
#include <grape/path3_sample.hpp>
#include <grape/vec3.hpp>

#include "count_allocations.hpp"
#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

using namespace grape;
using grape::testing::expect_error;

namespace {

constexpr double half_turn = std::numbers::pi;
constexpr double two_pi = 2.0 * half_turn;
constexpr double degree = half_turn / 180.0;

double wrap(double a) {
    a = std::remainder(a, two_pi);
    return a <= -half_turn ? a + two_pi : a;
}

// Roll about the unit t from n to m (both ⟂ t).
double roll(Vec3 t, Vec3 n, Vec3 m) { return std::atan2(dot(cross(n, m), t), dot(n, m)); }

// The least rotation taking the unit a to the unit b, applied to r (Rodrigues), written here.
Vec3 least_turn(Vec3 a, Vec3 b, Vec3 r) {
    const Vec3 k = cross(a, b);
    const double s = length(k), c = dot(a, b);
    if (s == 0.0) return r;
    const Vec3 axis = k / s;
    const double angle = std::atan2(s, c);
    return r * std::cos(angle) + cross(axis, r) * std::sin(angle) + axis * (dot(axis, r) * (1.0 - std::cos(angle)));
}

double orthonormal_error(const Frame3& f) {
    return std::max({std::abs(length(f.tangent) - 1.0), std::abs(length(f.normal) - 1.0),
                     std::abs(length(f.binormal) - 1.0), std::abs(dot(f.tangent, f.normal)),
                     std::abs(dot(f.normal, f.binormal)), std::abs(dot(f.tangent, f.binormal)),
                     length(cross(f.tangent, f.normal) - f.binormal)});
}

Path3 random_loop(std::mt19937_64& rng, int n) {
    std::uniform_real_distribution<double> d(-2.0, 2.0);
    std::vector<Vec3> pts;
    for (int k = 0; k < n; ++k) {
        const double a = two_pi * k / n;
        pts.push_back({3 * std::cos(a) + 0.5 * d(rng), 3 * std::sin(a) + 0.5 * d(rng), d(rng)});
    }
    return Path3::catmull_rom(pts, CatmullRom::centripetal, true);
}

}  // namespace

// A closed, non-planar loop: the RMF's end differs from its start by the holonomy; mode closed
// must remove it, with the least twist or with whole extra turns, and the end frame then
// equals the start frame (tangents equal at the join of a closed spline).
TEST(Frames3, ClosedLoopCloses) {
    std::mt19937_64 rng(grape::testing::test_seed(11));
    double worst = 0.0, worst_ortho = 0.0, worst_holonomy = 0.0;
    for (int trial = 0; trial < 8; ++trial) {
        const Path3 loop = random_loop(rng, 6 + trial);
        const RotationMinimizingFrames rmf(loop, {0, 0, 1}, 1e-11);
        const Frame3 r0 = rmf.frame(0.0), r1 = rmf.frame(1.0);
        worst_holonomy = std::max(worst_holonomy, std::abs(roll(r1.tangent, r1.normal, r0.normal)));
        for (const int turns : {0, 1, -2}) {
            const Frames3 fr(loop, {.mode = FrameMode::closed, .up = {0, 0, 1}, .extra_turns = turns, .tolerance = 1e-11});
            const Frame3 a = fr.frame(0.0), b = fr.frame(1.0);
            ASSERT_LE(distance(a.tangent, b.tangent), 1e-12);
            const double miss = std::abs(roll(b.tangent, b.normal, a.normal));
            worst = std::max(worst, miss);
            EXPECT_LE(miss, 1e-9) << "trial " << trial << " turns " << turns;
            // The least twist is the holonomy's negative, within a half turn, plus the turns.
            const double least = roll(r1.tangent, r1.normal, r0.normal);
            EXPECT_NEAR(fr.twist(), least + two_pi * turns, 1e-9);
            for (int k = 0; k <= 100; ++k) worst_ortho = std::max(worst_ortho, orthonormal_error(fr.frame(k / 100.0)));
        }
    }
    EXPECT_GT(worst_holonomy, 1e-3);  // the loops are non-planar: an RMF alone would not close
    EXPECT_LE(worst_ortho, 1e-14);
    std::printf("closed loops: end frame off by %.2g rad (holonomy removed up to %.2g rad), orthonormal within %.2g\n",
                worst, worst_holonomy, worst_ortho);
}

// The twist is spread linearly in arc length: the roll from the RMF (built separately, same
// start) to the twisted frame is twist·s/L. Both tables hold 1e-11 rad; each lookup rounds at
// a few ulp; so 1e-9 has two orders to spare. The end normal is end_up made ⟂ T.
TEST(Frames3, TwistIsAffineInArcLength) {
    std::mt19937_64 rng(grape::testing::test_seed(12));
    std::uniform_real_distribution<double> d(-3.0, 3.0);
    double worst = 0.0;
    for (int trial = 0; trial < 10; ++trial) {
        std::vector<Vec3> pts;
        for (int k = 0; k < 7; ++k) pts.push_back({d(rng), d(rng), d(rng)});
        const Path3 p = Path3::complex_by_length({Path3::catmull_rom(pts, CatmullRom::centripetal),
                                                  Path3::line(pts.back(), pts.back() + Vec3{1, 2, 3})});
        const Vec3 up{d(rng), d(rng), d(rng)}, end_up{d(rng), d(rng), d(rng)};
        const Frames3 fr(p, {.mode = FrameMode::ends, .up = up, .end_up = end_up, .extra_turns = trial % 3 - 1, .tolerance = 1e-11});
        const RotationMinimizingFrames rmf(p, up, 1e-11);
        const double L = p.length();
        for (int k = 0; k <= 400; ++k) {
            const double u = k / 400.0;
            const Frame3 f = fr.frame(u), r = rmf.frame(u);
            const double expected = fr.twist() * p.length_at(u) / L;
            const double e = std::abs(wrap(roll(r.tangent, r.normal, f.normal) - expected));
            worst = std::max(worst, e);
            EXPECT_LE(e, 1e-9) << "trial " << trial << " u " << u;
        }
        const Frame3 end = fr.frame(1.0);
        EXPECT_LE(distance(end.normal, normalized(end_up - end.tangent * dot(end_up, end.tangent))), 1e-9);
        EXPECT_LE(std::abs(fr.twist() - two_pi * (trial % 3 - 1)), half_turn + 1e-12);
    }
    std::printf("ends: roll against twist*s/L within %.2g rad\n", worst);
}

// A helix with both ends given as the Frenet normal: the RMF rolls against Frenet by −τ·s
// (closed form), the mismatch at the end is τ·L, so the twisted frame's roll against Frenet
// is φ(s) = −τ·s + Φ·s/L with Φ = wrap(τ·L) + 2πk. The Frenet frame is written here from the
// helix's formulas: p = (R cos θ, R sin θ, cθ), N = −(cos θ, sin θ, 0).
TEST(Frames3, HelixEndsMatchClosedForm) {
    constexpr double R = 1.0, c = 0.2, turns = 3.0;
    const Path3 h = Path3::helix({.radius = R, .rise = two_pi * c, .turns = turns});
    const double speed = std::sqrt(R * R + c * c), tau = c / (R * R + c * c), L = two_pi * turns * speed;
    auto frenet = [&](double u) {
        const double th = two_pi * turns * u;
        const Vec3 t = Vec3{-R * std::sin(th), R * std::cos(th), c} / speed;
        const Vec3 n{-std::cos(th), -std::sin(th), 0.0};
        return std::pair{t, n};
    };
    double worst = 0.0;
    for (const int k : {0, 1, -1, 3}) {
        const Frames3 fr(h, {.mode = FrameMode::ends, .up = frenet(0).second, .end_up = frenet(1).second, .extra_turns = k,
                             .tolerance = 1e-11});
        const double Phi = wrap(tau * L) + two_pi * k;
        EXPECT_NEAR(fr.twist(), Phi, 1e-9);
        for (int i = 0; i <= 3000; ++i) {
            const double u = i / 3000.0, s = u * L;
            const auto [t, n] = frenet(u);
            const Frame3 f = fr.frame(u);
            EXPECT_LE(distance(f.tangent, t), 1e-13);
            const double e = std::abs(wrap(roll(t, n, f.normal) - (-tau * s + Phi * s / L)));
            worst = std::max(worst, e);
            ASSERT_LE(e, 1e-9) << "k " << k << " u " << u;
        }
    }
    std::printf("helix with ends given: roll against the closed form within %.2g rad\n", worst);
}

// World up on a vertical loop-the-loop (a helix about a horizontal axis, rising sideways),
// a corkscrew (several turns about a horizontal axis) and a path that leaves the vertical:
// sampled at 2·10⁴ equal arc lengths, the roll between samples 1e-3·L apart (the normal carried
// by the least rotation of the tangent, written here) stays under 1°, and wherever the tangent
// is at least `cone` from vertical the normal is up made ⟂ T (computed here) to 1e-12.
TEST(Frames3, ReferenceUpNeverFlips) {
    const Vec3 up{0, 0, 1};
    struct Case {
        const char* name;
        Path3 path;
    };
    const Case cases[] = {
        {"loop", Path3::helix({.center = {0, 0, 10}, .axis = {0, 1, 0}, .start = {0, 0, -1}, .radius = 10, .rise = 3, .turns = 1})},
        {"corkscrew", Path3::helix({.axis = {1, 0, 0}, .start = {0, 0, -1}, .radius = 4, .rise = 30, .turns = 3})},
        {"lift", Path3::complex_by_length({Path3::line({0, 0, 0}, {10, 0, 0}), Path3::quadratic_bezier({10, 0, 0}, {20, 0, 0}, {20, 0, 10}),
                                           Path3::line({20, 0, 10}, {20, 0, 30}), Path3::quadratic_bezier({20, 0, 30}, {20, 0, 40}, {10, 5, 40})})},
    };
    constexpr int n = 20000, apart = 20;  // 20 samples of L/20000: 1e-3·L
    for (const Case& cs : cases) {
        const Frames3 fr(cs.path, {.mode = FrameMode::reference_up, .up = up});
        EXPECT_GE(fr.cone_count(), 1u) << cs.name;
        const std::vector<Frame3> f = frames_at(fr, equal_length_u(cs.path, n + 1));
        double worst_jump = 0.0, worst_away = 0.0, worst_ortho = 0.0;
        int away = 0;
        for (int i = 0; i <= n; ++i) {
            worst_ortho = std::max(worst_ortho, orthonormal_error(f[i]));
            const double alpha = std::atan2(length(cross(f[i].tangent, up)), std::abs(dot(f[i].tangent, up)));
            if (alpha >= 1.0) {
                ++away;
                const Vec3 want = normalized(up - f[i].tangent * dot(up, f[i].tangent));
                worst_away = std::max(worst_away, distance(f[i].normal, want));
            }
            if (i + apart <= n) {
                const Vec3 carried = least_turn(f[i].tangent, f[i + apart].tangent, f[i].normal);
                worst_jump = std::max(worst_jump, std::abs(roll(f[i + apart].tangent, carried, f[i + apart].normal)));
            }
        }
        EXPECT_LE(worst_jump, 1.0 * degree) << cs.name;
        EXPECT_LE(worst_away, 1e-12) << cs.name;
        EXPECT_GT(away, n / 10) << cs.name;
        EXPECT_LE(worst_ortho, 1e-14) << cs.name;
        std::printf("reference up, %s: %zu cones, worst roll over 1e-3 L %.3f deg, away from the cone off by %.2g, %d of %d samples away\n",
                    cs.name, fr.cone_count(), worst_jump / degree, worst_away, away, n + 1);
    }
    // The measure sees a fast roll: with a cone of 0.05 rad the loop turns its π within about
    // 0.1 rad of tangent direction, of the order of π·(2π·1e-3)/(2·0.05) ≈ 11° per 1e-3·L (the
    // mean over a planar loop; this one rises sideways, its tangent passes 0.048 rad from the
    // vertical, and 7.5° is measured): far over 1°.
    {
        const Path3& loop = cases[0].path;
        const Frames3 narrow(loop, {.mode = FrameMode::reference_up, .up = up, .cone = 0.05});
        const std::vector<Frame3> f = frames_at(narrow, equal_length_u(loop, n + 1));
        double worst = 0.0;
        for (int i = 0; i + apart <= n; ++i) {
            const Vec3 carried = least_turn(f[i].tangent, f[i + apart].tangent, f[i].normal);
            worst = std::max(worst, std::abs(roll(f[i + apart].tangent, carried, f[i + apart].normal)));
        }
        EXPECT_GT(worst, 5.0 * degree);
    }
    // A straight vertical path is inside the cone throughout: the RMF, a constant normal.
    const Frames3 vertical(Path3::line({0, 0, 0}, {0, 0, 5}), {.mode = FrameMode::reference_up});
    EXPECT_LE(distance(vertical.frame(0.0).normal, vertical.frame(1.0).normal), 1e-15);
    EXPECT_LE(std::abs(dot(vertical.frame(0.3).normal, {0, 0, 1})), 1e-15);
}

// The Frenet mode is Path3::frenet's frame; the RMF mode is RotationMinimizingFrames'.
TEST(Frames3, FrenetAndRmfModes) {
    const Path3 h = Path3::helix({.radius = 2, .rise = 1, .turns = 2});
    const Frames3 fr(h, {.mode = FrameMode::frenet});
    const Frames3 rm(h, {.up = {0, 0, 1}});
    const RotationMinimizingFrames rmf(h, {0, 0, 1});
    for (int k = 0; k <= 50; ++k) {
        const double u = k / 50.0;
        EXPECT_EQ(fr.frame(u).normal, h.frenet(u).normal);
        EXPECT_EQ(rm.frame(u).normal, rmf.frame(u).normal);
    }
}

// Frames across the joins of a complex path that is C¹ there (a helix, then a line along its
// end tangent, then a Bézier leaving along the line) stay continuous in every mode.
TEST(Frames3, ContinuousAcrossJoins) {
    const Path3 h = Path3::helix({.radius = 1, .rise = 0.5, .turns = 1.25});
    const Vec3 e = h.point(1.0), t = h.tangent(1.0);
    const Path3 p = Path3::complex_by_length(
        {h, Path3::line(e, e + t * 2.0), Path3::cubic_bezier(e + t * 2.0, e + t * 3.0, {0, 4, 2}, {-1, 4, 3})});
    const FramesDef defs[] = {{.mode = FrameMode::ends, .up = {1, 0, 0}, .end_up = {0, 1, 0}},
                              {.mode = FrameMode::reference_up, .cone = 0.5},
                              {.mode = FrameMode::rotation_minimizing, .up = {0, 0, 1}}};
    for (const FramesDef& def : defs) {
        const Frames3 fr(p, def);
        for (const double b : p.breaks()) {
            if (b == 0.0 || b == 1.0) continue;
            const Frame3 l = fr.frame(std::nextafter(b, 0.0) - 1e-12), r = fr.frame(b + 1e-12);
            // 2e-12 of u moves the frame by at most its rate times that: ≪ 1e-9.
            EXPECT_LE(distance(l.normal, r.normal), 1e-9) << static_cast<int>(def.mode) << " at " << b;
        }
    }
}

// length_at of each sample is its share of the length; spaced samples step by the spacing.
TEST(Frames3, EqualArcLengthSampling) {
    std::mt19937_64 rng(grape::testing::test_seed(13));
    std::uniform_real_distribution<double> d(-3.0, 3.0);
    std::vector<Vec3> pts;
    for (int k = 0; k < 9; ++k) pts.push_back({d(rng), d(rng), d(rng)});
    const Path3 paths[] = {Path3::catmull_rom(pts, CatmullRom::uniform),
                           Path3::helix({.radius = 2, .rise = 1, .turns = 3}),
                           Path3::cubic_bezier({0, 0, 0}, {0, 0, 0}, {1, 1, 0}, {3, 0, 1})};  // a stop at u = 0
    double worst = 0.0;
    for (const Path3& p : paths) {
        const double L = p.length();
        const std::vector<double> u = equal_length_u(p, 1001);
        ASSERT_EQ(u.size(), 1001u);
        EXPECT_EQ(u.front(), 0.0);
        EXPECT_EQ(u.back(), 1.0);
        for (std::size_t i = 0; i < u.size(); ++i) {
            const double e = std::abs(p.length_at(u[i]) - L * i / 1000.0) / L;
            worst = std::max(worst, e);
            EXPECT_LE(e, 1e-9);
        }
        const double spacing = L / 37.5;
        const std::vector<double> v = spaced_u(p, spacing);
        ASSERT_EQ(v.size(), 38u);  // 0, 1, …, 37 spacings; 37.5 does not reach the end
        for (std::size_t i = 0; i < v.size(); ++i) EXPECT_LE(std::abs(p.length_at(v[i]) - spacing * i), 1e-9 * L);
        EXPECT_EQ(spaced_u(p, L / 4).size(), 5u);  // the end reached exactly is included
    }
    EXPECT_EQ(equal_length_u(paths[0], 1), std::vector<double>{0.0});
    EXPECT_TRUE(equal_length_u(paths[0], 0).empty());
    const Frames3 fr(paths[1], {.up = {1, 0, 0}});
    const std::vector<double> u = equal_length_u(paths[1], 5);
    const std::vector<Frame3> f = frames_at(fr, u);
    ASSERT_EQ(f.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(f[i].normal, fr.frame(u[i]).normal);
    std::printf("equal arc-length samples: within %.2g of the length\n", worst);
}

// Looking up a frame allocates nothing, in every mode.
TEST(Frames3, LookupDoesNotAllocate) {
    const Path3 p = Path3::helix({.axis = {1, 0, 0}, .start = {0, 0, -1}, .radius = 4, .rise = 30, .turns = 2});
    const Frames3 modes[] = {Frames3(p, {.mode = FrameMode::reference_up}), Frames3(p, {.mode = FrameMode::ends, .up = {0, 1, 0}}),
                             Frames3(p, {.mode = FrameMode::frenet}), Frames3(p, {.up = {0, 1, 0}})};
    const long before = g_allocations.load();
    double sink = 0.0;
    for (const Frames3& f : modes) {
        for (int k = 0; k <= 100; ++k) sink += f.frame(k / 100.0).normal.x;
    }
    EXPECT_EQ(g_allocations.load(), before);
    EXPECT_TRUE(std::isfinite(sink));
}

TEST(Frames3, BadInputs) {
    const Path3 line = Path3::line({0, 0, 0}, {1, 0, 0});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expect_error([&] { Frames3(line, {.up = {nan, 0, 0}}); }, {"Frames3", "up", "not finite"});
    expect_error([&] { Frames3(line, {.up = {1, 0, 0}}); }, {"Frames3", "up", "parallel"});
    expect_error([&] { Frames3(line, {.mode = FrameMode::ends, .end_up = {2, 0, 0}}); }, {"Frames3", "end_up", "parallel"});
    expect_error([&] { Frames3(line, {.mode = FrameMode::ends, .end_up = {}}); }, {"Frames3", "end_up", "zero"});
    expect_error([&] { Frames3(line, {.mode = FrameMode::closed}); }, {"Frames3", "closed", "apart"});
    expect_error([&] { Frames3(line, {.mode = FrameMode::reference_up, .cone = 2.0}); }, {"Frames3", "cone", "[0.05, 1.5]"});
    expect_error([&] { Frames3(line, {.tolerance = 1.0}); }, {"tolerance"});
    expect_error([&] { spaced_u(line, 0.0); }, {"spaced_u", "spacing", "> 0"});
    expect_error([&] { spaced_u(line, 1e-9); }, {"spaced_u", "spacing", "more than"});
    expect_error([&] { equal_length_u(line, max_samples3 + 1); }, {"equal_length_u", "count"});
}
