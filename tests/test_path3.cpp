// path3: 3-D paths against independent truth — the helix's closed forms (length, curvature,
// torsion, the rotation-minimizing frame's roll), finite differences for the derivatives, a
// quadrature written here for lengths, the 2-D paths for planar curves, the convergence order
// of double reflection, and every bad input's message.
#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/path3.hpp>
#include <grape/vec3.hpp>

#include "error_text.hpp"
#include "count_allocations.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace grape;
using grape::testing::expect_error;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double two_pi = 2.0 * std::numbers::pi;

// Gauss–Legendre nodes and weights on [−1, 1] by Newton on P_n (Numerical Recipes' gauleg):
// the reference quadrature shares nothing with grape's own 10-point constants.
struct Rule {
    std::vector<double> x, w;
};
Rule gauss_rule(int n) {
    Rule r;
    for (int i = 1; i <= n; ++i) {
        double z = std::cos(std::numbers::pi * (i - 0.25) / (n + 0.5));
        double dp = 0.0;
        for (int it = 0; it < 100; ++it) {
            double p1 = 1.0, p2 = 0.0;
            for (int j = 1; j <= n; ++j) {
                const double p3 = p2;
                p2 = p1;
                p1 = ((2.0 * j - 1.0) * z * p2 - (j - 1.0) * p3) / j;
            }
            dp = n * (z * p1 - p2) / (z * z - 1.0);
            const double dz = p1 / dp;
            z -= dz;
            if (std::abs(dz) < 1e-17) break;
        }
        r.x.push_back(z);
        r.w.push_back(2.0 / ((1.0 - z * z) * dp * dp));
    }
    return r;
}

// ∫ |d1| over [a, b]: a 12-point rule on `panels` equal panels, summed with Neumaier's
// compensation (the rounding of 2·10⁴ terms stays near 1 ulp of the total).
double reference_length(const Path3& p, double a, double b, int panels = 2048) {
    static const Rule rule = gauss_rule(12);
    double sum = 0.0, carry = 0.0;
    const double h = (b - a) / panels;
    for (int k = 0; k < panels; ++k) {
        const double mid = a + (k + 0.5) * h;
        double panel = 0.0;
        for (std::size_t i = 0; i < rule.x.size(); ++i) panel += rule.w[i] * length(p.d1(mid + 0.5 * h * rule.x[i]));
        panel *= 0.5 * h;
        const double t = sum + panel;
        carry += std::abs(sum) >= std::abs(panel) ? (sum - t) + panel : (panel - t) + sum;
        sum = t;
    }
    return sum + carry;
}

// The test's helix: R = 1, c = 0.2 per radian (rise 2π·0.2 per turn), 3 turns about z.
constexpr double R = 1.0, c = 0.2, turns = 3.0;
Path3 test_helix() { return Path3::helix({.radius = R, .rise = two_pi * c, .turns = turns}); }

Vec3 random_point(std::mt19937_64& rng, double size) {
    std::uniform_real_distribution<double> d(-size, size);
    return {d(rng), d(rng), d(rng)};
}

// Rotation of v by angle a about the unit axis k (Rodrigues), to tilt planar test curves.
Vec3 rotate(Vec3 v, Vec3 k, double a) {
    return v * std::cos(a) + cross(k, v) * std::sin(a) + k * (dot(k, v) * (1.0 - std::cos(a)));
}

}  // namespace

TEST(Vec3, Operators) {
    constexpr Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    static_assert(cross(x, y) == z && cross(y, z) == x && cross(z, x) == y);
    static_assert(dot(Vec3{1, 2, 3}, Vec3{4, 5, 6}) == 32.0);
    static_assert(Vec3{1, 2, 3} + Vec3{1, 1, 1} == Vec3{2, 3, 4} && -Vec3{1, 2, 3} == Vec3{-1, -2, -3});
    static_assert(lerp(Vec3{1, 2, 3}, Vec3{5, 6, 7}, 1.0) == Vec3{5, 6, 7});
    EXPECT_EQ(length(Vec3{2, 3, 6}), 7.0);  // exact squares, an exact root
    // Scaled where the squares would overflow or vanish: within 2 ulp of the true 13·10^±200.
    EXPECT_NEAR(length(Vec3{3e200, 4e200, 12e200}), 13e200, 2 * eps * 13e200);
    EXPECT_NEAR(length(Vec3{3e-200, -4e-200, 12e-200}), 13e-200, 2 * eps * 13e-200);
    EXPECT_EQ(length(Vec3{0, -std::numeric_limits<double>::infinity(), 1}), std::numeric_limits<double>::infinity());
    EXPECT_TRUE(std::isnan(length(Vec3{0, std::numeric_limits<double>::quiet_NaN(), 1})));
    EXPECT_EQ(normalized(Vec3{}), Vec3{});
    EXPECT_FALSE(is_finite(Vec3{0, std::numeric_limits<double>::quiet_NaN(), 0}));
    for (const Vec3 a : {x, y, z, normalized(Vec3{1, 2, 3}), normalized(Vec3{-3, 0.1, 0.2})}) {
        const Vec3 p = any_perpendicular(a);
        EXPECT_NEAR(dot(p, a), 0.0, 4 * eps);
        EXPECT_NEAR(length(p), 1.0, 4 * eps);
    }
}

// Every kind's d1, d2, d3 against central differences of the one below. Step h = 1e-5: the
// relative truncation error is h²/6·|f‴|/|f′|, at most (ωh)²/6 ≈ 1e-8 for the fastest helix
// here (ω = 2π·3/0.9 rad per unit u), and the rounding ε·|f|/(h·|f′|) ≤ 1e-10: both well
// below the 1e-7 allowed.
TEST(Path3, DerivativesMatchFiniteDifferences) {
    const Vec3 pts[] = {{0, 0, 0}, {1, 2, 0.5}, {3, 1, -1}, {4, 3, 2}, {2, 5, 1}};
    const std::vector<Path3> paths = {
        Path3::line({1, 2, 3}, {4, -1, 2}),
        Path3::quadratic_bezier({0, 0, 0}, {2, 3, 1}, {4, 0, -1}),
        Path3::cubic_bezier({0, 0, 0}, {5, 0, 0}, {0, 5, 3}, {5, 5, 3}),
        Path3::catmull_rom(pts, CatmullRom::centripetal),
        Path3::catmull_rom(pts, CatmullRom::chordal, true),
        test_helix(),
        Path3::complex_by_length({Path3::line({0, 0, 0}, {1, 0, 0}), test_helix()}),
    };
    const double h = 1e-5;
    for (const Path3& p : paths) {
        const std::span<const double> br = p.breaks();
        for (int k = 1; k < 40; ++k) {
            const double u = k / 40.0;
            // Central differences need both sides in one piece.
            if (std::any_of(br.begin(), br.end(), [&](double b) { return std::abs(b - u) <= h; })) continue;
            const auto check = [&](Vec3 exact, Vec3 diff, Vec3 scale_of) {
                const double scale = std::max(1.0, length(scale_of));
                EXPECT_LE(distance(exact, diff), 1e-7 * scale) << to_string(p.kind()) << " u = " << u;
            };
            check(p.d1(u), (p.point(u + h) - p.point(u - h)) / (2 * h), p.d1(u));
            check(p.d2(u), (p.d1(u + h) - p.d1(u - h)) / (2 * h), p.d2(u));
            check(p.d3(u), (p.d2(u + h) - p.d2(u - h)) / (2 * h), p.d3(u));
        }
    }
}

// The helix point lies on its cylinder at height rise·turns·u (closed form, no path code).
TEST(Path3, HelixPointsAndLength) {
    const HelixSpec spec{.center = {1, -2, 3}, .axis = {0, 0, 2}, .start = {0, 1, 0.7}, .radius = 2.5, .rise = 1.5, .turns = 2.25};
    const Path3 p = Path3::helix(spec);
    for (int k = 0; k <= 100; ++k) {
        const double u = k / 100.0, th = two_pi * spec.turns * u;
        const Vec3 expected = spec.center + Vec3{-std::sin(th), std::cos(th), 0} * spec.radius + Vec3{0, 0, spec.rise * spec.turns * u};
        EXPECT_LE(distance(p.point(u), expected), 1e-14 * 8) << u;  // a few ulp of coordinates ~8
    }
    // L = T·√((2πR)² + H²); the independent quadrature of |d1| agrees to its own rounding
    // (~1e-15, 12-point rule on a constant).
    const double L = spec.turns * std::sqrt(std::pow(two_pi * spec.radius, 2) + spec.rise * spec.rise);
    EXPECT_NEAR(p.length(), L, 1e-15 * L);
    EXPECT_NEAR(reference_length(p, 0.0, 1.0, 64), L, 1e-14 * L);
    EXPECT_NEAR(p.length_at(0.3), 0.3 * L, 1e-15 * L);
    EXPECT_NEAR(p.u_at_length(0.3 * L), 0.3, 1e-15);
}

// κ = R/(R² + c²), τ = c/(R² + c²) for a helix of radius R advancing c per radian. Their
// inputs are exact derivatives computed with a few roundings: 1e-13 relative is ~500 ulp.
TEST(Path3, HelixCurvatureAndTorsion) {
    const Path3 p = test_helix();
    const double kappa = R / (R * R + c * c), tau = c / (R * R + c * c);
    for (int k = 0; k <= 50; ++k) {
        const Frenet3 f = p.frenet(k / 50.0);
        ASSERT_TRUE(f.normal_defined);
        EXPECT_NEAR(f.curvature, kappa, 1e-13 * kappa);
        EXPECT_NEAR(f.torsion, tau, 1e-13 * tau);
        // The normal points at the axis; the frame is right-handed and orthonormal.
        EXPECT_NEAR(f.normal.z, 0.0, 1e-15);
        EXPECT_NEAR(dot(f.normal, Vec3{f.point.x, f.point.y, 0}), -R, 1e-14);
        EXPECT_LE(distance(cross(f.tangent, f.normal), f.binormal), 4 * eps);
    }
    // A left-handed helix has negative torsion.
    EXPECT_NEAR(Path3::helix({.rise = -1.0}).frenet(0.5).torsion, -(1 / two_pi) / (1 + 1 / (two_pi * two_pi)), 1e-13);
}

// Where κ = 0 the normal is undefined: flagged, and still a unit vector ⟂ T (never NaN).
TEST(Path3, FrenetWhereCurvatureVanishes) {
    const Path3 line = Path3::line({0, 0, 0}, {1, 2, 3});
    const Frenet3 f = line.frenet(0.5);
    EXPECT_FALSE(f.normal_defined);
    EXPECT_EQ(f.curvature, 0.0);
    EXPECT_EQ(f.torsion, 0.0);
    EXPECT_NEAR(dot(f.normal, f.tangent), 0.0, 4 * eps);
    EXPECT_NEAR(length(f.normal), 1.0, 4 * eps);
    EXPECT_NEAR(length(f.binormal), 1.0, 4 * eps);
    // A cubic with a stop at u = 0 (p0 = p1): the tangent is the direction of d2 there.
    const Path3 stop = Path3::cubic_bezier({0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0});
    EXPECT_EQ(stop.tangent(0.0), (Vec3{1, 0, 0}));
    const Frenet3 g = stop.frenet(0.0);
    EXPECT_FALSE(g.normal_defined);
    EXPECT_TRUE(is_finite(g.normal) && is_finite(g.binormal));
    // A planar S-curve: the Frenet binormal flips across the inflection.
    const Path3 s = Path3::cubic_bezier({0, 0, 0}, {6, 0, 0}, {-1, 5, 0}, {5, 5, 0});
    EXPECT_GT(s.frenet(0.1).binormal.z * s.frenet(0.9).binormal.z, -1.0 - 1e-12);
    EXPECT_LT(s.frenet(0.1).binormal.z * s.frenet(0.9).binormal.z, 0.0);
}

// Random cubics (coordinates in [−10, 10]): length and length_at against the 12-point
// composite reference (its error is rounding, ~1e-15), within the 1e-13 contract; the round
// trip u → s → u within 1e-12 (1e-13 in s over the smallest speed seen here); the point at
// distance s within 1e-9·L (the contract).
TEST(Path3, RandomCubicLengths) {
    std::mt19937_64 rng(grape::testing::test_seed(3));
    double worst_length = 0.0, worst_at = 0.0, worst_round = 0.0;
    const int count = grape::testing::fast_build ? 200 : 20;
    for (int n = 0; n < count; ++n) {
        const Path3 p = Path3::cubic_bezier(random_point(rng, 10), random_point(rng, 10), random_point(rng, 10), random_point(rng, 10));
        const double L = reference_length(p, 0.0, 1.0);
        worst_length = std::max(worst_length, std::abs(p.length() - L) / L);
        for (double u : {0.1, 0.37, 0.5, 0.81}) {
            worst_at = std::max(worst_at, std::abs(p.length_at(u) - reference_length(p, 0.0, u)) / L);
            const double s = p.length_at(u);
            // In s: |length_at(u_at_length(s)) − s| is the contract's measure.
            worst_round = std::max(worst_round, std::abs(p.length_at(p.u_at_length(s)) - s) / L);
        }
    }
    EXPECT_LE(worst_length, 1e-13);
    EXPECT_LE(worst_at, 1e-13);
    EXPECT_LE(worst_round, 1e-13);
    std::printf("random cubics: length %.2g, length_at %.2g, s round trip %.2g (relative to L)\n", worst_length, worst_at, worst_round);
}

// A cubic in a plane (tilted in 3-D) has the length of the same cubic in 2-D, computed by
// grape's 2-D code (each ~1e-13 relative: their difference within 2e-13).
TEST(Path3, PlanarCubicMatches2D) {
    const Vec2 q[] = {{0, 0}, {6, 0}, {-1, 5}, {5, 5}};
    const CubicBezierPath flat(q[0], q[1], q[2], q[3]);
    const Vec3 ex = normalized(Vec3{1, 2, 2}), ey = normalized(cross(Vec3{0, 0, 1}, ex));
    auto lift = [&](Vec2 v) { return Vec3{1, 2, 3} + ex * v.x + ey * v.y; };
    const Path3 p = Path3::cubic_bezier(lift(q[0]), lift(q[1]), lift(q[2]), lift(q[3]));
    EXPECT_NEAR(p.length(), flat.length(), 2e-13 * flat.length());
    EXPECT_NEAR(p.length(), 8.907, 1e-3);  // the figure quoted for the S-curve
    for (double u : {0.2, 0.5, 0.9}) {
        EXPECT_NEAR(p.length_at(u), flat.length_at(u), 2e-13 * flat.length());
        EXPECT_LE(distance(p.point(u), lift(flat.point(u))), 1e-13 * 10);
    }
}

// The 3-D Catmull–Rom in the plane z = 0 is the 2-D one (same rule, written apart); a closed
// spline is C¹ at its seam and passes through every point.
TEST(Path3, CatmullRom) {
    const Vec2 q[] = {{0, 0}, {1, 2}, {1.5, 2.1}, {4, 0}, {5, 3}};
    std::vector<Vec3> pts;
    for (Vec2 v : q) pts.push_back({v.x, v.y, 0});
    for (CatmullRom type : {CatmullRom::uniform, CatmullRom::centripetal, CatmullRom::chordal}) {
        const CatmullRomSplinePath flat(q, type);
        const Path3 p = Path3::catmull_rom(pts, type);
        for (int k = 0; k <= 64; ++k) {
            const double u = k / 64.0;
            const Vec2 f = flat.point(u), g = flat.d1(u);
            EXPECT_LE(distance(p.point(u), Vec3{f.x, f.y, 0}), 1e-13 * 5) << u;
            EXPECT_LE(distance(p.d1(u), Vec3{g.x, g.y, 0}), 1e-12 * length(g)) << u;
        }
        EXPECT_NEAR(p.length(), flat.length(), 2e-13 * flat.length());
    }
    const Vec3 ring[] = {{1, 0, 0}, {0, 1, 0.5}, {-1, 0, 1}, {0, -1, 0.5}};
    const Path3 closed = Path3::catmull_rom(ring, CatmullRom::centripetal, true);
    EXPECT_EQ(closed.point(0.0), ring[0]);
    EXPECT_EQ(closed.point(1.0), ring[0]);
    for (int i = 0; i < 4; ++i) EXPECT_LE(distance(closed.point(i / 4.0), ring[i]), 4 * eps);
    EXPECT_LE(distance(closed.d1(0.0), closed.d1(1.0)), 1e-14 * length(closed.d1(0.0)));
    EXPECT_EQ(closed.breaks().size(), 5u);
}

// Complex paths: u split by the cues, length additive, u_at_length across parts.
TEST(Path3, Complex) {
    const Path3 a = Path3::line({0, 0, 0}, {2, 0, 0});
    const Path3 b = test_helix();
    const Path3 p = Path3::complex({a, b}, {0.0, 0.25});
    EXPECT_EQ(p.point(0.25), b.point(0.0));
    EXPECT_EQ(p.point(0.125), a.point(0.5));
    EXPECT_LE(distance(p.d1(0.5), b.d1(1.0 / 3.0) / 0.75), 1e-13 * length(p.d1(0.5)));
    EXPECT_NEAR(p.length(), a.length() + b.length(), 1e-15 * p.length());
    const double s = 2.0 + 0.5 * b.length();
    EXPECT_NEAR(p.u_at_length(s), 0.25 + 0.75 * 0.5, 1e-15);
    EXPECT_NEAR(p.u_at_length(1.0), 0.125, 1e-15);
    const Path3 even = Path3::complex_by_length({a, a, a});
    EXPECT_NEAR(even.point(0.5).x, 1.0, 1e-15);
    // Zero-length parts get empty spans, and skipped.
    const Path3 holes = Path3::complex_by_length({Path3{}, a, Path3{}});
    EXPECT_EQ(holes.point(0.5), (Vec3{1, 0, 0}));
}

// The rotation-minimizing frame on a helix rolls against the Frenet frame at −τ per unit
// length: with r = cos φ·N + sin φ·B, φ(s) = φ(0) − τ·s (closed form: φ′ = −τ). Checked at
// 3001 points over 3 turns (φ reaches −211.8°) against the frames' contract of 1e-9 rad.
TEST(Path3, RmfRollOnHelix) {
    const Path3 p = test_helix();
    const double tau = c / (R * R + c * c), L = p.length();
    const RotationMinimizingFrames rmf(p, {-1, 0, 0});  // the Frenet normal at u = 0: φ(0) = 0
    double worst = 0.0, worst_ortho = 0.0, prev = 0.0, turn = 0.0;
    for (int k = 0; k <= 3000; ++k) {
        const double u = k / 3000.0;
        const Frame3 f = rmf.frame(u);
        const Frenet3 fr = p.frenet(u);
        double phi = std::atan2(dot(f.normal, fr.binormal), dot(f.normal, fr.normal));
        if (k > 0 && phi - prev > std::numbers::pi) turn -= two_pi;  // unwrap
        if (k > 0 && phi - prev < -std::numbers::pi) turn += two_pi;
        prev = phi;
        worst = std::max(worst, std::abs(phi + turn + tau * u * L));
        worst_ortho = std::max({worst_ortho, std::abs(length(f.normal) - 1.0), std::abs(dot(f.normal, f.tangent)),
                                std::abs(length(f.binormal) - 1.0), std::abs(dot(f.binormal, f.normal))});
    }
    EXPECT_LE(worst, 1e-9);
    EXPECT_LE(worst_ortho, 1e-14);  // each lookup normalizes: a few ulp
    std::printf("helix RMF: worst roll error %.3g rad over 3 turns, %zu knots, orthonormal within %.2g\n", worst,
                rmf.knot_count(), worst_ortho);
}

// On a planar curve with an inflection the transported binormal stays the plane's normal
// (the Frenet binormal flips, see FrenetWhereCurvatureVanishes). Each double-reflection step
// maps the plane to itself in exact arithmetic, so what leaves it is rounding: a few ulp per
// knot, bounded here by 8ε·knots.
TEST(Path3, RmfPlanarCurveKeepsPlaneNormal) {
    const Vec3 k = normalized(Vec3{1, -2, 0.5});
    const double angle = 0.7;
    auto tilt = [&](Vec3 v) { return rotate(v, k, angle); };
    const Vec3 normal = tilt({0, 0, 1});
    const Path3 p = Path3::cubic_bezier(tilt({0, 0, 0}), tilt({6, 0, 0}), tilt({-1, 5, 0}), tilt({5, 5, 0}));
    const RotationMinimizingFrames rmf(p, tilt({0, 1, 0}));
    double worst = 0.0;
    for (int i = 0; i <= 2000; ++i) worst = std::max(worst, distance(rmf.frame(i / 2000.0).binormal, normal));
    EXPECT_LE(worst, 8 * eps * static_cast<double>(rmf.knot_count()));
    // Untilted, every step is exact in z: the binormal is (0, 0, ±1) to the last bit but rounding of its length.
    const Path3 flat = Path3::cubic_bezier({0, 0, 0}, {6, 0, 0}, {-1, 5, 0}, {5, 5, 0});
    const RotationMinimizingFrames rf(flat, {0, 1, 0});
    for (int i = 0; i <= 2000; ++i) {
        const Frame3 f = rf.frame(i / 2000.0);
        EXPECT_EQ(f.binormal.x, 0.0);
        EXPECT_EQ(f.binormal.y, 0.0);
        EXPECT_NEAR(f.binormal.z, 1.0, 4 * eps);
    }
    std::printf("planar RMF: binormal off the plane normal by %.2g (%zu knots)\n", worst, rmf.knot_count());
}

// Double reflection is fourth order: N uniform steps over the 3-turn helix end with a roll
// error ∝ N⁻⁴, so each halving of the step divides it by ≈ 16. The errors (1e-5 … 1e-9 rad)
// are far above rounding; the ratio is checked within 10 % of 16.
TEST(Path3, DoubleReflectionIsFourthOrder) {
    const Path3 p = test_helix();
    const double tau = c / (R * R + c * c), L = p.length();
    auto end_error = [&](int n) {
        Vec3 r = p.frenet(0.0).normal;
        for (int i = 0; i < n; ++i) {
            const double a = static_cast<double>(i) / n, b = static_cast<double>(i + 1) / n;
            r = RotationMinimizingFrames::double_reflection(p.point(a), p.tangent(a), r, p.point(b), p.tangent(b));
        }
        const Frenet3 f = p.frenet(1.0);
        const double phi = std::atan2(dot(r, f.binormal), dot(r, f.normal));
        const double err = phi + tau * L;
        return std::abs(std::remainder(err, two_pi));
    };
    double prev = end_error(50);
    for (int n : {100, 200, 400}) {
        const double e = end_error(n);
        std::printf("double reflection: %d steps, end roll error %.3g rad, ratio %.2f\n", n, e, prev / e);
        EXPECT_GT(prev / e, 16 * 0.9);
        EXPECT_LT(prev / e, 16 * 1.1);
        prev = e;
    }
}

// The frame is continuous across the join of two parts that meet with a common tangent
// (a line continuing a cubic's end tangent), and turns by the least rotation at a corner.
TEST(Path3, RmfAcrossJoins) {
    const Path3 cubic = Path3::cubic_bezier({0, 0, 0}, {2, 0, 0}, {2, 1, 0.5}, {0, 1, 0.5});
    const Vec3 end = cubic.point(1.0), dir = normalized(cubic.d1(1.0));
    const Path3 smooth = Path3::complex({cubic, Path3::line(end, end + dir * 3.0)}, {0.0, 0.5});
    const RotationMinimizingFrames rmf(smooth, {0, 1, 0});
    const Frame3 before = rmf.frame(std::nextafter(0.5, 0.0)), at = rmf.frame(0.5);
    // C¹ join: the frames on both sides agree to the rounding of one step (~1e-15).
    EXPECT_LE(distance(before.normal, at.normal), 1e-13);
    // Along the line the normal is constant (no roll on a straight stretch).
    EXPECT_LE(distance(rmf.frame(0.75).normal, at.normal), 1e-14);
    EXPECT_LE(distance(rmf.frame(1.0).normal, at.normal), 1e-14);
    // A right-angle corner: the normal turns with the tangent, about their common normal.
    const Path3 corner = Path3::complex_by_length({Path3::line({0, 0, 0}, {1, 0, 0}), Path3::line({1, 0, 0}, {1, 1, 0})});
    const RotationMinimizingFrames rc(corner, {0, 1, 1});
    const Vec3 up = normalized(Vec3{0, 1, 1});
    EXPECT_LE(distance(rc.frame(0.25).normal, up), 1e-15);
    EXPECT_LE(distance(rc.frame(0.75).normal, normalized(Vec3{-1, 0, 1})), 1e-15);
}

TEST(Path3, BadInputNamesTheArgument) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expect_error([&] { Path3::line({nan, 0, 0}, {}); }, {"Path3::line", "a", "not finite"});
    expect_error([&] { Path3::cubic_bezier({}, {}, {0, 0, nan}, {}); }, {"Path3::cubic_bezier", "p2", "not finite"});
    expect_error([&] { Path3::quadratic_bezier({}, {}, {0, std::numeric_limits<double>::infinity(), 0}); }, {"p2", "not finite"});
    expect_error([&] { Path3::helix({.radius = 0.0}); }, {"Path3::helix", "radius", "> 0"});
    expect_error([&] { Path3::helix({.turns = -1.0}); }, {"turns", "> 0"});
    expect_error([&] { Path3::helix({.axis = {0, 0, 0}}); }, {"axis", "zero"});
    expect_error([&] { Path3::helix({.start = {0, 0, 3}}); }, {"start", "parallel to the axis"});
    expect_error([&] { Path3::helix({.rise = nan}); }, {"rise", "not finite"});
    const Vec3 two[] = {{0, 0, 0}, {1, 0, 0}};
    expect_error([&] { Path3::catmull_rom(std::span<const Vec3>(two, 1)); }, {"Path3::catmull_rom", "points", "at least 2"});
    expect_error([&] { Path3::catmull_rom(two, CatmullRom::uniform, true); }, {"points", "at least 3"});
    const Vec3 bad[] = {{0, 0, 0}, {nan, 0, 0}};
    expect_error([&] { Path3::catmull_rom(bad); }, {"points[1]", "not finite"});
    expect_error([&] { Path3::complex({}, {}); }, {"Path3::complex", "parts", "empty"});
    expect_error([&] { Path3::complex({Path3{}}, {0.0, 1.0}); }, {"cues", "one per part"});
    expect_error([&] { Path3::complex({Path3{}, Path3{}}, {0.0, 1.5}); }, {"cues[1]", "[0, 1]"});
    expect_error([&] { Path3::complex({Path3{}, Path3{}}, {0.5, 0.6}); }, {"cues[0]", "must be 0"});
    expect_error([&] { Path3::complex({Path3{}, Path3{}, Path3{}}, {0.0, 0.6, 0.5}); }, {"cues[2]", "decreases"});
    const Path3 line = Path3::line({0, 0, 0}, {1, 0, 0});
    expect_error([&] { RotationMinimizingFrames(line, {2, 0, 0}); }, {"RotationMinimizingFrames", "up", "parallel"});
    expect_error([&] { RotationMinimizingFrames(line, {0, nan, 0}); }, {"up", "not finite"});
    expect_error([&] { RotationMinimizingFrames(line, {0, 1, 0}, 0.0); }, {"tolerance"});
}

// An oracle written apart: 4000 samples, a golden-section search on the bracket around each
// sample that is a local minimum, and the ends. closest_point must match it within 1e-12 of
// (length + distance) (its own gap is ~1e-13 of that) and never lose to it.
namespace {
double oracle_distance(const Path3& p, Vec3 q) {
    const int n = 4000;
    std::vector<double> d(n + 1);
    for (int i = 0; i <= n; ++i) d[static_cast<std::size_t>(i)] = distance(p.point(static_cast<double>(i) / n), q);
    double best = std::min(d.front(), d.back());
    for (int i = 1; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (!(d[k] <= d[k - 1] && d[k] <= d[k + 1])) continue;
        double a = (i - 1.0) / n, b = (i + 1.0) / n;
        const double g = (std::sqrt(5.0) - 1.0) / 2.0;
        for (int it = 0; it < 80; ++it) {
            const double x1 = b - g * (b - a), x2 = a + g * (b - a);
            if (distance(p.point(x1), q) < distance(p.point(x2), q)) b = x2; else a = x1;
        }
        best = std::min(best, distance(p.point(0.5 * (a + b)), q));
    }
    return best;
}
}  // namespace

TEST(Path3, ClosestPointIsGlobal) {
    std::mt19937_64 rng(grape::testing::test_seed(5));
    const Vec3 pts[] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0.5}, {0, 1, 0.5}, {0, 3, -1}};
    const std::vector<Path3> paths = {
        Path3::cubic_bezier({0, 0, 0}, {2, 0, 0}, {2, 1, 0.5}, {0, 1, 0.5}),  // the hairpin
        Path3::cubic_bezier({0, 0, 0}, {5, 0, 0}, {0, 5, 3}, {5, 5, 3}),      // the twist
        Path3::catmull_rom(pts, CatmullRom::centripetal, true),
        test_helix(),
        Path3::complex_by_length({Path3::line({2, 0, 0}, {1, 0, 0}), Path3::quadratic_bezier({1, 0, 0}, {0, 0, 1}, {0, 2, 0})}),
    };
    double worst = 0.0, worst_gap = 0.0;
    const int queries = grape::testing::fast_build ? 200 : 20;
    for (const Path3& p : paths) {
        for (int k = 0; k < queries; ++k) {
            const Vec3 q = random_point(rng, 4.0);
            const Closest3 c = closest_point(p, q);
            const double scale = p.length() + c.distance;
            const double o = oracle_distance(p, q);
            worst = std::max(worst, (c.distance - o) / scale);
            worst_gap = std::max(worst_gap, c.gap / scale);
            EXPECT_LE(c.distance, o + 1e-12 * scale) << to_string(p.kind()) << " query " << q.x << ' ' << q.y << ' ' << q.z;
            EXPECT_LE(c.gap, 1e-12 * scale);
            EXPECT_EQ(c.point, p.point(c.u));
        }
    }
    // On the helix's axis every turn is at distance R: the nearest is level with the query.
    const Path3 h = test_helix();
    const double top = two_pi * c * turns;
    const Closest3 axis = closest_point(h, {0, 0, 0.4 * top});
    EXPECT_NEAR(axis.distance, R, 1e-12);
    EXPECT_NEAR(axis.u, 0.4, 1e-7);  // distance is flat to second order in u: √(1e-16) resolution
    std::printf("closest point: worst excess over the oracle %.2g, worst gap %.2g (relative to length + distance)\n",
                worst, worst_gap);
}

// At the centre of a circle (a helix with no rise) every point is nearest: nothing can be
// pruned, the work is capped and the second pass divides the circle evenly into 2¹⁴ leaves:
// each bound's slack is R·ω²·h²/8 ≈ 3.7e-8 (R = 2, ω = 2π, h = 2⁻¹⁴), so the gap is ≤ 1e-7.
TEST(Path3, ClosestPointEquidistant) {
    const Path3 circle = Path3::helix({.radius = 2.0, .turns = 1.0});
    const Closest3 c = closest_point(circle, {0, 0, 0});
    EXPECT_NEAR(c.distance, 2.0, 1e-14);
    EXPECT_LE(c.gap, 1e-7);
    std::printf("closest point at a circle's centre: gap %.2g\n", c.gap);
}

// Evaluation, lookup of frames and the closest point allocate nothing.
TEST(Path3, EvaluationDoesNotAllocate) {
    const Vec3 pts[] = {{0, 0, 0}, {1, 2, 0.5}, {3, 1, -1}, {4, 3, 2}};
    const Path3 p = Path3::complex_by_length({Path3::catmull_rom(pts), test_helix()});
    const RotationMinimizingFrames rmf(p, {0, 0, 1});
    const long before = g_allocations.load();
    double sink = 0.0;
    for (int k = 0; k <= 100; ++k) {
        const double u = k / 100.0;
        sink += p.point(u).x + p.d1(u).y + p.d2(u).z + p.d3(u).x + p.frenet(u).torsion + p.length_at(u);
        sink += p.u_at_length(u * p.length()) + rmf.frame(u).normal.x + closest_point(p, {u, 1, 2}).distance;
    }
    EXPECT_EQ(g_allocations.load(), before);
    EXPECT_TRUE(std::isfinite(sink));
}

// The knots follow the tolerance: a looser one needs fewer and still meets it.
TEST(Path3, RmfToleranceSetsTheKnots) {
    const Path3 p = test_helix();
    const double tau = c / (R * R + c * c), L = p.length();
    const RotationMinimizingFrames loose(p, {-1, 0, 0}, 1e-6), tight(p, {-1, 0, 0});
    EXPECT_LT(loose.knot_count(), tight.knot_count());
    const Frame3 f = loose.frame(1.0);
    const Frenet3 fr = p.frenet(1.0);
    const double phi = std::atan2(dot(f.normal, fr.binormal), dot(f.normal, fr.normal));
    EXPECT_LE(std::abs(std::remainder(phi + tau * L, two_pi)), 1e-6);
    std::printf("RMF knots on the 3-turn helix: %zu at 1e-6 rad, %zu at 1e-9 rad\n", loose.knot_count(), tight.knot_count());
}

// A long random spline (near-stops and sharp turns among 100 centripetal pieces) builds a
// bounded table whose frames stay orthonormal and perpendicular to the tangent; the error of
// the whole table is checked on the helix above, here its work and its invariants.
TEST(Path3, RmfOnALongRandomSplineIsBounded) {
    std::mt19937_64 rng(grape::testing::test_seed(17));
    std::uniform_real_distribution<double> coord(-10.0, 10.0);
    std::vector<Vec3> points(100);
    for (Vec3& p : points) p = {coord(rng), coord(rng), coord(rng)};
    const Path3 spline = Path3::catmull_rom(points, CatmullRom::centripetal);
    const RotationMinimizingFrames frames(spline, {0, 0, 1});
    EXPECT_LE(frames.knot_count(), RotationMinimizingFrames::max_knots);
    double worst = 0.0;
    for (int i = 0; i <= 10000; ++i) {
        const Frame3 f = frames.frame(i / 10000.0);
        worst = std::max({worst, std::abs(length(f.normal) - 1.0), std::abs(dot(f.normal, f.tangent)),
                          std::abs(length(f.binormal) - 1.0)});
    }
    EXPECT_LE(worst, 1e-14);  // a few roundings of unit vectors
    std::printf("RMF on a 100-point random centripetal spline: %zu knots\n", frames.knot_count());
}

// A cubic with a cusp (the tangent reverses where the speed is 0): the frame is undefined
// there; the build either ends with a bounded table or refuses the path, never runs away.
TEST(Path3, RmfAtACuspIsBoundedOrRefused) {
    const Path3 cusp = Path3::cubic_bezier({0, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0, 0});
    try {
        const RotationMinimizingFrames frames(cusp, {0, 0, 1});
        EXPECT_LE(frames.knot_count(), RotationMinimizingFrames::max_knots);
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("knots"), std::string::npos) << e.what();
    }
}
