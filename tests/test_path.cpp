// path: every kind against independent truth — finite differences for the analytic
// derivatives, closed forms and independent quadrature for lengths, the seed's examples,
// reparametrization error, flattening distance, bounds, and every bad input's message.
#include <grape/error.hpp>
#include <grape/path.hpp>

#include "path/kernel.hpp"
#include "seed_paths.hpp"

#include "error_text.hpp"
#include "polyline_distance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <new>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "count_allocations.hpp"
#include "seeds.hpp"

namespace {

using grape::Path;
using grape::Vec2;
using grape::pi;
using grape::NamedPath;

constexpr double eps = std::numeric_limits<double>::epsilon();

// Every kind, plus the hard cases: stops (zero speed) inside and at the ends, several turns
// backwards, tiny and huge coordinates.
std::vector<NamedPath> all_paths() {
    auto paths = grape::scenes::path_gallery();
    for (auto& p : grape::scenes::seed_paths()) paths.push_back({"seed_" + p.name, p.path});
    paths.push_back({"circle_backwards_turns", grape::CirclePath({5, -3}, 2, 0, -5 * pi)});
    paths.push_back({"projectile_up_and_down", grape::PhysicsPath({0, 0}, {0, -10}, {0, 10}, 2)});
    paths.push_back({"bezier_cusp", grape::CubicBezierPath({0, 0}, {100, 100}, {0, 100}, {100, 0})});
    paths.push_back({"bezier_tiny", grape::CubicBezierPath({0, 0}, {1e-6, 2e-6}, {3e-6, -1e-6}, {4e-6, 0})});
    paths.push_back({"spiral_outwards", grape::SpiralPath({0, 0}, 0, 100, 1, -3)});
    paths.push_back({"nearly_circular_spiral", grape::SpiralPath({0, 0}, 100, 100.5, 0, 2 * pi)});
    paths.push_back({"nearly_straight_quadratic", grape::QuadraticBezierPath({0, 0}, {50, 0.01}, {100, 0})});
    paths.push_back({"ellipse_full_turns", grape::EllipticalArcPath({10, 20}, 30, 5, 0.3, 1, 1 + 4 * pi)});
    paths.push_back({"hermite_two_points", grape::HermiteSplinePath({0, 0, 10, 0}, {0, 20, 0, -20})});
    // Tangents that force a cusp inside the first segment (the cubic of bezier_cusp).
    paths.push_back({"hermite_cusp", grape::HermiteSplinePath({0, 0, 100, 0, 200, 50}, {300, 300, 300, -300, 100, 0})});
    return paths;
}

// The pieces [a, b] on which a path is smooth.
std::vector<std::pair<double, double>> pieces(const Path& p) {
    const auto br = grape::detail::smooth_breaks(p);
    std::vector<std::pair<double, double>> out;
    for (std::size_t i = 0; i + 1 < br.size(); ++i) out.emplace_back(br[i], br[i + 1]);
    return out;
}

// 8th-order central difference weights for f′ at offsets ±1..±4 (antisymmetric).
constexpr double fd8[4] = {4.0 / 5.0, -1.0 / 5.0, 4.0 / 105.0, -1.0 / 280.0};
constexpr double fd8_abs_sum = 2.0 * (4.0 / 5.0 + 1.0 / 5.0 + 4.0 / 105.0 + 1.0 / 280.0);

template <class F>
Vec2 central_difference(F f, double u, double h) {
    Vec2 sum;
    for (int k = 1; k <= 4; ++k) sum += (f(u + k * h) - f(u - k * h)) * fd8[k - 1];
    return sum / h;
}

double max_abs_coordinate(const Path& p) {
    const auto b = p.bounds();
    return std::max({std::abs(b.min.x), std::abs(b.min.y), std::abs(b.max.x), std::abs(b.max.y)});
}

// Composite 10-point Gauss–Legendre on 512 equal sub-intervals of every smooth piece: an
// independent check of the adaptive scheme (error far below 1e-14 for the smooth kinds).
double reference_length(const Path& p, double to = 1.0) {
    double total = 0.0;
    auto speed = [&p](double u) { return grape::length(p.d1(u)); };
    for (auto [a, b] : pieces(p)) {
        if (a >= to) break;
        b = std::min(b, to);
        const int n = 512;
        for (int i = 0; i < n; ++i) total += grape::gauss_legendre(speed, a + (b - a) * i / n, a + (b - a) * (i + 1) / n);
    }
    return total;
}

using grape::testing::error_text;

#define EXPECT_ERROR(statement, text) EXPECT_EQ(error_text([&] { (void)(statement); }), std::string(text))

// --- derivatives ---------------------------------------------------------------------------

TEST(PathDerivatives, MatchEighthOrderFiniteDifferencesForEveryKind) {
    std::mt19937_64 rng(grape::testing::test_seed(2024));
    for (const auto& [name, kind_path] : all_paths()) {
        const auto& path = kind_path;  // a plain reference: lambdas below capture it (clang 14 cannot capture a binding)
        if (path.kind() == grape::PathKind::reparametrized) continue;  // its own test below
        const double scale = max_abs_coordinate(path);
        for (auto [a, b] : pieces(path)) {
            // The stencil spans 8h and must stay inside one smooth piece.
            const double h = 1e-3 * (b - a);
            std::uniform_real_distribution<double> pick(a + 4 * h, b - 4 * h);
            for (int i = 0; i < 40; ++i) {
                const double u = pick(rng);
                // Rounding: each point carries ~4 ulp of the coordinate scale, amplified by
                // Σ|w|/h; truncation h⁸·|x⁽⁹⁾|/630 is far below it at h = 1e-3 of the piece.
                const Vec2 fd1 = central_difference([&](double v) { return path.point(v); }, u, h);
                const double d1_scale = grape::length(path.d1(u)) + 1e-300;
                const double tol1 = 4 * eps * scale * fd8_abs_sum / h + 1e-9 * d1_scale;
                EXPECT_LE(grape::distance(fd1, path.d1(u)), tol1) << name << " d1 at u=" << u;
                const Vec2 fd2 = central_difference([&](double v) { return path.d1(v); }, u, h);
                double d1_max = 0.0;
                for (int k = -4; k <= 4; ++k) d1_max = std::max(d1_max, grape::length(path.d1(u + k * h)));
                const double tol2 = 4 * eps * d1_max * fd8_abs_sum / h + 1e-9 * grape::length(path.d2(u));
                EXPECT_LE(grape::distance(fd2, path.d2(u)), tol2) << name << " d2 at u=" << u;
            }
        }
    }
}

TEST(PathDerivatives, EndTangentExtensionOutsideZeroOne) {
    for (const auto& [name, path] : all_paths()) {
        const Vec2 p0 = path.point(0), p1 = path.point(1), t0 = path.d1(0), t1 = path.d1(1);
        for (double u : {-2.0, -0.5, -1e-9}) {
            EXPECT_EQ(path.point(u), p0 + t0 * u) << name;
            EXPECT_EQ(path.d1(u), t0) << name;
            EXPECT_EQ(path.d2(u), Vec2{}) << name;
        }
        for (double u : {1.0 + 1e-9, 1.25, 3.0}) {
            EXPECT_EQ(path.point(u), p1 + t1 * (u - 1.0)) << name;
            EXPECT_EQ(path.d1(u), t1) << name;
        }
        // Continuous at the ends: the extension starts where the path stops.
        EXPECT_LE(grape::distance(path.point(-1e-12), p0), grape::length(t0) * 1e-12 * 2 + 1e-300) << name;
    }
}

TEST(PathDerivatives, NaNParameterNeverCrashes) {
    for (const auto& [name, path] : all_paths()) {
        const double nan = std::nan("");
        (void)path.point(nan);
        (void)path.d1(nan);
        (void)path.d2(nan);
        EXPECT_EQ(path.length_at(nan), 0.0) << name;
        EXPECT_EQ(path.u_at_length(nan), 0.0) << name;
    }
}

// --- lengths -------------------------------------------------------------------------------

TEST(PathLength, ClosedForms) {
    EXPECT_EQ(grape::LinearPath({0, 0}, {3, 4}).length(), 5.0);
    // r·|Δθ| (one multiplication: 1 ulp).
    EXPECT_NEAR(grape::CirclePath({0, 0}, 50, 0, pi / 2).length(), 78.539816339744830962, 2 * eps * 80);
    EXPECT_NEAR(grape::CirclePath({5, -3}, 2, 0, -5 * pi).length(), 10 * pi, 4 * eps * 32);
    // Archimedean spiral r = θ over one turn: ½[θ√(1+θ²) + asinh θ] at 2π.
    const double t = 2 * pi;
    const grape::SpiralPath archimedes({0, 0}, 0, t, 0, t);
    EXPECT_NEAR(archimedes.length(), 0.5 * (t * std::sqrt(1 + t * t) + std::asinh(t)), 1e-13 * 21.3);
    EXPECT_NEAR(archimedes.length(), 21.256294148, 1e-9);  // the anchors' reference value
    // Projectile v = (10, −10) (up, screen y down), g = 9.81, until it lands: with slope
    // w = (v_y − g·t)/v_x running from 1 to −1, L = (v_x²/g)·[w√(1+w²) + asinh w]/2 |₋₁¹.
    const double g = 9.81, T = 20.0 / g;
    const grape::PhysicsPath shot({0, 0}, {10, -10}, {0, g}, T);
    const double expected = (100.0 / g) * (std::sqrt(2.0) + std::asinh(1.0));
    EXPECT_NEAR(shot.length(), expected, 1e-13 * expected);
    EXPECT_NEAR(shot.point(0.5).y, -5.096839959, 1e-9);  // apex height
    EXPECT_NEAR(shot.point(1.0).x, 20.387359837, 1e-9);  // range
    EXPECT_NEAR(shot.point(1.0).y, 0.0, 1e-13);
    // Cubic A: speed 300(1 − 2t + 2t²) is a polynomial, so L = 200 exactly.
    EXPECT_NEAR(grape::CubicBezierPath({0, 0}, {0, 100}, {100, 100}, {100, 0}).length(), 200.0, 1e-13 * 200);
    // Reference values printed to 12 digits: compare to half a unit of the last digit.
    EXPECT_NEAR(grape::CubicBezierPath({0, 0}, {100, 0}, {0, 100}, {100, 100}).length(), 167.654262742, 5e-10);
    EXPECT_NEAR(grape::QuadraticBezierPath({0, 0}, {50, 100}, {100, 0}).length(), 147.894285754, 5e-10);
    const double k = 4 * (std::sqrt(2.0) - 1) / 3;
    EXPECT_NEAR(grape::CubicBezierPath({1, 0}, {1, k}, {k, 1}, {0, 1}).length(), 1.5710166981, 5e-11);
    EXPECT_NEAR(grape::SineWavePath({0, 0}, {100, 0}, 2, 10).length(), 132.065822669, 5e-10);
    // A cosine spline runs along its polyline: the length is the polyline's.
    const auto cosine = grape::scenes::seed_cosine_spline();
    const auto linear = grape::LinearSplinePath(std::span<const double>(grape::scenes::seed_p2));
    EXPECT_NEAR(cosine.length(), linear.length(), 4 * eps * linear.length());
}

// The complete elliptic integral of the second kind by the arithmetic-geometric mean:
// E(k) = K(k)·(1 − Σ 2ⁿ⁻¹·cₙ²), K(k) = π / (2·AGM(1, k')), c₀ = k, cₙ₊₁ = (aₙ − bₙ)/2. Written
// here (libc++ has no std::comp_ellint_2); k' = √(1 − k²) is passed exactly by the caller,
// since 1 − k² cancels near k = 1. Within 1e-15 relative of mpmath's ellipe on the cases below.
double elliptic_e(double k, double k_prime) {
    double a = 1.0, b = k_prime, c = k, sum = 0.5 * k * k, weight = 0.5;
    for (int i = 0; i < 64 && c > 1e-17 * a; ++i) {
        c = (a - b) / 2;
        const double mean = (a + b) / 2;
        b = std::sqrt(a * b);
        a = mean;
        weight *= 2;
        sum += weight * c * c;
    }
    return std::numbers::pi / (2 * a) * (1 - sum);
}

// A sine wave of whole half waves has the closed-form length (2/π)·√(D² + B²)·E(k), k² =
// B²/(D² + B²), B = A·2πf, D = |end − start| (complete elliptic integral of the second kind).
// At a million waves it is built in constant time (integrating every wave took ~40 s).
TEST(PathLength, SineWaveOfAMillionWavesIsExactAndQuick) {
    const auto start = std::chrono::steady_clock::now();
    const grape::SineWavePath wave({0, 0}, {100, 0}, 1e6, 5);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 5.0);
    for (const double f : {1e6, 2.0, 0.25}) {
        const grape::SineWavePath w({0, 0}, {100, 0}, f, 5);
        const double d = 100.0, b = 5 * 2 * std::numbers::pi * f;
        const double h = std::hypot(d, b);
        if (f >= 0.5) {  // whole half waves
            const double exact = 2.0 / std::numbers::pi * h * elliptic_e(b / h, d / h);
            EXPECT_NEAR(w.length(), exact, 1e-13 * exact) << f;
            EXPECT_NEAR(w.length_at(0.25), exact / 4, 1e-13 * exact) << f;  // a whole number of waves
        }
        // The length is additive and increasing wherever it is asked.
        double last = 0.0;
        for (int k = 1; k <= 64; ++k) {
            const double l = w.length_at(k / 64.0);
            EXPECT_GT(l, last) << f << " " << k;
            last = l;
        }
        EXPECT_EQ(last, w.length()) << f;
    }
    EXPECT_GT(wave.length(), 0.0);
}

TEST(PathLength, MatchesIndependentQuadratureTo1e12) {
    for (const auto& [name, path] : all_paths()) {
        if (name == "projectile_up_and_down" || name == "bezier_cusp" || name == "hermite_cusp") continue;  // kinks
        const auto reparametrized = grape::path_cast<grape::ReparametrizedSpec>(path);
        const double ref = reference_length(reparametrized ? reparametrized->source : path);
        EXPECT_NEAR(path.length(), ref, 1e-12 * ref) << name;
    }
}

TEST(PathLength, StopsInsideThePathKeepTheirClosedForm) {
    // Straight up 10 units and back down: the parabola degenerates to a segment walked twice.
    EXPECT_NEAR(grape::PhysicsPath({0, 0}, {0, -10}, {0, 10}, 2).length(), 10.0, 1e-13 * 10);
    // The cusp Bézier: x′ = 0 at t = ½ with a kink in the speed; adaptive quadrature on both sides.
    const grape::CubicBezierPath cusp({0, 0}, {100, 100}, {0, 100}, {100, 0});
    const double half = reference_length(cusp, 0.5);
    EXPECT_NEAR(cusp.length(), 2 * half, 1e-12 * cusp.length());  // symmetric about t = ½
}

TEST(PathLength, LengthAtAndUAtLengthAreInverse) {
    std::mt19937_64 rng(grape::testing::test_seed(99));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& [name, path] : all_paths()) {
        const double L = path.length();
        EXPECT_EQ(path.length_at(0.0), 0.0) << name;
        EXPECT_EQ(path.length_at(1.0), L) << name;
        EXPECT_EQ(path.length_at(-3.0), 0.0) << name;
        EXPECT_EQ(path.length_at(7.0), L) << name;
        double previous = 0.0;
        for (int i = 1; i <= 20; ++i) {
            const double u = i / 20.0;
            const double s = path.length_at(u);
            EXPECT_GE(s, previous - 1e-13 * L) << name;  // monotone
            previous = s;
        }
        for (int i = 0; i < 30; ++i) {
            const double s = unit(rng) * L;
            const double u = path.u_at_length(s);
            EXPECT_NEAR(path.length_at(u), s, 1e-12 * L) << name << " s=" << s;
        }
    }
}

TEST(PathLength, LengthAtAgreesWithIndependentQuadrature) {
    for (const char* name : {"spiral", "sine_wave", "cubic_bezier", "hermite_spline", "elliptical_arc", "physics"}) {
        for (const auto& p : grape::scenes::path_gallery()) {
            if (p.name != name) continue;
            for (double u : {0.1, 0.37, 0.5, 0.81}) {
                const double ref = reference_length(p.path, u);
                EXPECT_NEAR(p.path.length_at(u), ref, 1e-12 * p.path.length()) << name << " u=" << u;
            }
        }
    }
}

// --- the seed's examples ---------------------------------------------------------------------

TEST(SeedPaths, SpiralGoesFromRadius200ToTheCenter) {
    const auto spiral = grape::scenes::seed_spiral();
    EXPECT_EQ(spiral.point(0.0), (Vec2{300, 100}));
    EXPECT_NEAR(grape::distance(spiral.point(1.0), Vec2{100, 100}), 0.0, 1e-12);
    EXPECT_NEAR(grape::distance(spiral.point(0.5), Vec2{100, 100}), 100.0, 1e-12);  // half way: radius 100
    // Closed form: speed √(ρ² + (2π·r)²), ρ = −200; L = [H(2π·200) − H(0)]/(2π·200), H = ∫√(τ² + 200²).
    const double k = 2 * pi, rho = 200.0, x = k * 200.0;
    const double expected = 0.5 * (x * std::hypot(x, rho) + rho * rho * std::asinh(x / rho)) / (k * rho);
    EXPECT_NEAR(spiral.length(), expected, 1e-13 * expected);
}

TEST(SeedPaths, FourPartComplexGivesEachPartItsShare) {
    const auto complex = grape::scenes::seed_complex();
    const auto spiral = grape::scenes::seed_spiral();
    // Spiral over [0, 0.25): the whole's u = 0.125 is the spiral's u = 0.5.
    EXPECT_EQ(complex.point(0.125), spiral.point(0.5));
    EXPECT_NEAR(grape::distance(complex.point(0.25), Vec2{100, 100}), 0.0, 1e-12);
    // Cues like 0.55 and 0.6 are not exact in binary: the local parameter carries a few ulp,
    // times the part's 100-unit extent over its span of 0.1: allow 64 ulp of 200.
    const double tol = 64 * eps * 200;
    auto near = [&](double u, Vec2 expected) { return grape::distance(complex.point(u), expected) <= tol; };
    EXPECT_TRUE(near(0.375, {150, 150}));  // linear1 over [0.25, 0.5): 25%
    EXPECT_TRUE(near(0.5, {200, 200}));
    EXPECT_TRUE(near(0.55, {200, 150}));   // linear2 over [0.5, 0.6): 10%
    EXPECT_TRUE(near(0.6, {200, 100}));
    EXPECT_TRUE(near(0.8, {150, 100}));    // linear3 over [0.6, 1]: 40%
    EXPECT_EQ(complex.point(1.0), (Vec2{100, 100}));
    // Chain rule: linear2 moves 100 units in 0.1 of u.
    EXPECT_NEAR(complex.d1(0.55).y, -1000.0, 1e-9);
    EXPECT_EQ(complex.d2(0.55), Vec2{});
    EXPECT_NEAR(complex.length(), spiral.length() + 100 * std::sqrt(2.0) + 200, 1e-12 * complex.length());
}

TEST(SeedPaths, NestedComplexOfThreeCirclesBezierAndSine) {
    const auto nested = grape::scenes::seed_nested_complex();
    // Circles over [0, 0.5) split 25% / 25% / 50% of that: c1 [0, .125), c2 [.125, .25), c3 [.25, .5).
    // c1 runs from 2π down to 0 around (150, 200), r = 50: half way it is at angle π.
    EXPECT_NEAR(grape::distance(nested.point(0.0625), Vec2{100, 200}), 0.0, 1e-12);
    EXPECT_NEAR(grape::distance(nested.point(0.1875), Vec2{300, 200}), 0.0, 1e-12);  // c2 at 2π
    EXPECT_NEAR(grape::distance(nested.point(0.375), Vec2{400, 200}), 0.0, 1e-12);   // c3 at 2π
    const grape::CubicBezierPath bez({200, 200}, {350, 0}, {350, 500}, {350, 200});
    EXPECT_EQ(nested.point(0.625), bez.point(0.5));
    const grape::SineWavePath sine({350, 200}, {200, 200}, 3, 50);
    EXPECT_EQ(nested.point(0.875), sine.point(0.5));
    // Derivatives through two levels: dv/du = 1/(0.5·0.25) in c1.
    const grape::CirclePath c1({150, 200}, 50, 2 * pi, 0);
    EXPECT_NEAR(grape::distance(nested.d1(0.0625), c1.d1(0.5) * 8.0), 0.0, 1e-9);
    EXPECT_NEAR(grape::distance(nested.d2(0.0625), c1.d2(0.5) * 64.0), 0.0, 1e-8);
    const double circles = 2 * pi * 50 * 2 + 2 * pi * 100 * 2 / 2;  // c2 and c3 span 2π each, c1 2π
    EXPECT_NEAR(grape::scenes::seed_circles().length(), 2 * pi * 50 + 2 * pi * 50 + 2 * pi * 100, 1e-12 * circles);
}

TEST(SeedPaths, ComplexPathsAreContinuousAtEveryCue) {
    for (const auto& path : {Path(grape::scenes::seed_complex()), Path(grape::scenes::seed_nested_complex()),
                             Path(grape::scenes::seed_circles())}) {
        for (const double cue : grape::detail::smooth_breaks(path)) {
            if (cue == 0.0 || cue == 1.0) continue;
            const double before = std::nextafter(cue, 0.0);
            // Rounding of both sides' evaluations: a few ulp of the coordinates (≤ 600).
            EXPECT_LE(grape::distance(path.point(before), path.point(cue)),
                      grape::length(path.d1(before)) * (cue - before) + 64 * eps * 600)
                << "cue " << cue;
        }
    }
}

TEST(SeedPaths, ComplexPathsEndExactlyWhereTheirLastPartEnds) {
    for (const auto& c : {grape::scenes::seed_complex(), grape::scenes::seed_nested_complex(),
                          grape::ComplexPath({grape::LinearPath({0, 0}, {1, 1}), grape::LinearPath({1, 1}, {0.3, 0.7})},
                                             {0, 0.7000000000000001})}) {
        EXPECT_EQ(c.point(1.0), c.parts().back().point(1.0));
        EXPECT_EQ(c.point(0.0), c.parts().front().point(0.0));
    }
}

TEST(SeedPaths, SplinesPassThroughTheSeedPoints) {
    const auto check = [](const Path& p, const std::array<double, 12>& xy) {
        for (int i = 0; i < 6; ++i) {
            const Vec2 expected{xy[2 * i], xy[2 * i + 1]};
            EXPECT_LE(grape::distance(p.point(i / 5.0), expected), 8 * eps * 500) << i;
        }
    };
    check(grape::scenes::seed_linear_spline(), grape::scenes::seed_p1);
    check(grape::scenes::seed_cosine_spline(), grape::scenes::seed_p2);
    check(grape::scenes::seed_catmull_rom_spline(), grape::scenes::seed_p3);
    check(grape::scenes::seed_catmull_rom_spline(grape::CatmullRom::centripetal), grape::scenes::seed_p3);
    // Cosine interpolation has zero velocity at every point.
    EXPECT_EQ(grape::scenes::seed_cosine_spline().d1(0.4), Vec2{});
}

TEST(SeedPaths, CatalogueHasEveryKind) {
    std::vector<bool> seen(static_cast<int>(grape::PathKind::reparametrized) + 1, false);
    for (const auto& p : grape::scenes::path_gallery()) seen[static_cast<int>(p.path.kind())] = true;
    for (std::size_t k = 0; k < seen.size(); ++k) {
        EXPECT_TRUE(seen[k]) << grape::to_string(static_cast<grape::PathKind>(k));
    }
}

// --- spline reference values -----------------------------------------------------------------

TEST(Splines, ReferenceValues) {
    // Uniform Catmull–Rom, tension ½: (0,0),(1,1),(2,0),(3,1) at the middle segment's u = ½.
    const grape::CatmullRomSplinePath uniform({0, 0, 1, 1, 2, 0, 3, 1});
    EXPECT_NEAR(grape::distance(uniform.point(0.5), Vec2{1.5, 0.5}), 0.0, 4 * eps * 3);
    // Uneven points: uniform overshoots out of [10, 10.5]; centripetal stays inside.
    const std::vector<double> uneven{0, 0, 10, 0, 10.5, 0.5, 20, 0};
    const grape::CatmullRomSplinePath u0(uneven), u1(uneven, grape::CatmullRom::centripetal),
        u2(uneven, grape::CatmullRom::chordal);
    EXPECT_NEAR(u0.point(0.5).x, 10.28125, 1e-12);
    EXPECT_NEAR(u0.point(0.5).y, 0.28125, 1e-12);
    EXPECT_NEAR(u1.point(0.5).x, 10.250725, 5e-7);  // reference printed to 6 decimals
    EXPECT_NEAR(u1.point(0.5).y, 0.253911, 5e-7);
    EXPECT_NEAR(u2.point(0.5).x, 10.249927, 5e-7);
    EXPECT_NEAR(u2.point(0.5).y, 0.250518, 5e-7);
    double lo = 1e9, hi = -1e9, lo_uniform = 1e9, hi_uniform = -1e9;
    for (int i = 0; i <= 1000; ++i) {
        const double u = 1.0 / 3.0 + i / 3000.0;
        lo = std::min(lo, u1.point(u).x);
        hi = std::max(hi, u1.point(u).x);
        lo_uniform = std::min(lo_uniform, u0.point(u).x);
        hi_uniform = std::max(hi_uniform, u0.point(u).x);
    }
    EXPECT_GE(lo, 10.0 - 1e-12);
    EXPECT_LE(hi, 10.5 + 1e-12);
    EXPECT_LT(lo_uniform, 9.97);  // 9.9641 per the reference
    EXPECT_GT(hi_uniform, 10.58);  // 10.5820
    // Hermite basis at ½: h00 = ½, h10 = ⅛, h01 = ½, h11 = −⅛.
    const grape::HermiteSplinePath h(std::vector<Vec2>{{0, 0}, {8, 0}}, std::vector<Vec2>{{0, 8}, {0, 16}});
    EXPECT_EQ(h.point(0.5), (Vec2{4, 0.125 * 8 - 0.125 * 16}));
    // Cosine easing (1 − cos πμ)/2 at μ = ¼.
    EXPECT_NEAR(grape::CosineSplinePath({0, 0, 1, 0}).point(0.25).x, 0.146446609406726, 1e-15);
}

TEST(Splines, JoinsAreSmoothAsEachKindPromises) {
    const std::vector<Vec2> pts{{0, 0}, {30, 40}, {35, 38}, {90, 10}, {100, 100}};
    const std::vector<Vec2> tangents{{10, 0}, {20, 5}, {-3, 7}, {0, 30}, {5, 5}};
    const grape::HermiteSplinePath hermite(pts, tangents);
    const double n = 4.0;  // segments: d/du = n·d/dt
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const double u = static_cast<double>(i) / n;
        EXPECT_LE(grape::distance(hermite.point(u), pts[i]), 8 * eps * 100);
        // The tangent is d/dt of the local parameter at the point, on both sides of a join.
        EXPECT_LE(grape::distance(hermite.d1(u), tangents[i] * n), 64 * eps * 400) << i;
        if (i > 0 && i + 1 < pts.size()) {
            // One ulp before the join the previous segment ends: d1 moves by |x″|·ulp ≪ 1e-9·|x′|.
            const double before = std::nextafter(u, 0.0);
            EXPECT_LE(grape::distance(hermite.d1(before), tangents[i] * n), 1e-9 * 400) << i;
        }
    }
    for (auto type : {grape::CatmullRom::uniform, grape::CatmullRom::centripetal, grape::CatmullRom::chordal}) {
        const grape::CatmullRomSplinePath cr(pts, type);
        for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
            const double u = static_cast<double>(i) / n;
            const Vec2 left = cr.d1(std::nextafter(u, 0.0)), right = cr.d1(u);
            // G1 everywhere: the same direction on both sides (the knot spacing scales the
            // speed per segment); uniform is C1: the same vector.
            EXPECT_LE(std::abs(grape::cross(left, right)), 1e-9 * grape::length(left) * grape::length(right)) << i;
            EXPECT_GT(grape::dot(left, right), 0.0) << i;
            if (type == grape::CatmullRom::uniform) {
                EXPECT_LE(grape::distance(left, right), 1e-9 * grape::length(right));
            }
        }
    }
}

// --- arc-length reparametrization ------------------------------------------------------------

TEST(Reparametrized, ArcLengthErrorBelow1e9ForEveryKind) {
    std::mt19937_64 rng(grape::testing::test_seed(5));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& [name, path] : all_paths()) {
        const Path r = path.reparametrized();
        const Path source = grape::path_cast<grape::ReparametrizedSpec>(r)->source;
        const double L = source.length();
        EXPECT_EQ(r.length(), L) << name;
        double worst = 0.0;
        for (int i = 0; i <= 2000; ++i) {
            const double u = i < 1000 ? i / 1000.0 : unit(rng);
            // s(v(u)) by the source's own length_at (checked against independent quadrature above).
            worst = std::max(worst, std::abs(source.length_at(grape::detail::source_parameter(r, u)) - u * L));
        }
        EXPECT_LE(worst, 1e-9 * L) << name;
        EXPECT_EQ(r.point(0.0), source.point(0.0)) << name;
        EXPECT_EQ(r.point(1.0), source.point(1.0)) << name;  // animations land exactly
        EXPECT_EQ(r.bounds().min, source.bounds().min) << name;
    }
}

TEST(Reparametrized, SpeedIsConstantAndDerivativesAreConsistent) {
    std::mt19937_64 rng(grape::testing::test_seed(11));
    int compared = 0, unresolved = 0;
    for (const auto& [name, path] : all_paths()) {
        const Path r = path.reparametrized();
        const double L = r.length();
        if (!(L > 0.0)) continue;
        const double h = 1e-4;
        std::uniform_real_distribution<double> pick(4 * h, 1 - 4 * h);
        for (int i = 0; i < 200; ++i) {
            const double u = pick(rng);
            const Vec2 d1 = r.d1(u);
            EXPECT_NEAR(grape::length(d1), L, 4 * eps * L) << name;  // |x′| = L by construction
            const Vec2 d2 = r.d2(u);
            // Constant speed ⇒ x″ ⟂ x′ exactly by the chain rule; the rounding is that of the
            // two terms |X″|·(L/σ)² whose difference x″ is.
            const Path source = grape::path_cast<grape::ReparametrizedSpec>(r)->source;
            const double v = grape::detail::source_parameter(r, u);
            const double sigma = grape::length(source.d1(v));
            const double terms = grape::length(source.d2(v)) * (L / sigma) * (L / sigma);
            EXPECT_LE(std::abs(grape::dot(d1, d2)), 64 * eps * L * terms + 1e-300) << name;
            // Positions carry ≤ 1e-9·L of table error; a difference over the 8h stencil turns
            // that into ≤ Σ|w|·1e-9·L/h of derivative error (plus rounding). Stencils that
            // straddle a kink of the source (spline joins, cusps) are not smooth: skip them.
            bool smooth = true;
            const double va = grape::detail::source_parameter(r, u - 4 * h);
            const double vb = grape::detail::source_parameter(r, u + 4 * h);
            for (double b : grape::detail::smooth_breaks(source)) smooth = smooth && !(b > va && b < vb);
            if (!smooth) continue;
            // Nor are stencils across which the tangent turns by more than 0.9 rad (the crest of
            // a tight sine wave; a throw straight up reverses at its apex). The 9-point
            // difference's truncation is h⁸·|x⁽⁹⁾|/630; at constant speed L along curvature κ
            // (a circle's derivatives: |x⁽ⁿ⁾| = L·(Lκ)ⁿ⁻¹) and a turn θ = 8hLκ across the
            // stencil, that is L·(θ/8)⁸/630: 1.4e-15·L at θ = 0.25, 4e-11·L at 0.9, against
            // the tolerance's fd8_abs_sum·1e-9·L/h = 2.1e-5·L. The circle's estimate holds while
            // κ varies little across the stencil; at a turn near π the curvature peaks inside
            // it (the apex) and the estimate says nothing, so the cut stays well below that.
            // Measured: the few stencils turning 0.25–0.9 rad here come within 4 % of the
            // tolerance (those below 0.25 within 0.6 %).
            double turn = 0.0;
            for (int k = -4; k < 4; ++k) {
                const Vec2 a = r.d1(u + k * h), b = r.d1(u + (k + 1) * h);
                turn += std::abs(std::atan2(a.x * b.y - a.y * b.x, grape::dot(a, b)));
            }
            if (turn > 0.9) {
                ++unresolved;
                continue;
            }
            ++compared;
            const Vec2 fd = central_difference([&](double v) { return r.point(v); }, u, h);
            const double scale = max_abs_coordinate(r);
            const double tol = fd8_abs_sum * (1e-9 * L + 4 * eps * scale) / h;
            EXPECT_LE(grape::distance(fd, d1), tol) << name << " u=" << u;
        }
    }
    EXPECT_GT(compared, 20 * unresolved) << compared << " compared, " << unresolved << " unresolved";  // few skipped
}

// The bulk evaluators' table (anim's tick): table.point(u) against Path::point at random u,
// on random cubics (tame ones, S-curves as the animation benchmark bends them, loops near a
// cusp) and lines. 2e-10·L: the build checks 1e-10·L at 23 points per piece; between them a
// degree-11 interpolant's error cannot double without its next derivative being large
// enough to fail a check point too. The float coefficients are part of what is checked:
// the table's own evaluation is compared, not the fit.
TEST(ArcLengthTable, MatchesThePathWithin2e10OfItsLength) {
    std::mt19937_64 rng(grape::testing::test_seed(31));
    std::uniform_real_distribution<double> coordinate(0.0, 1000.0), unit(0.0, 1.0);
    int built = 0, refused = 0;
    double most_steps = 0.0;
    for (int n = 0; n < 300; ++n) {
        const Vec2 a{coordinate(rng), coordinate(rng)}, d{coordinate(rng), coordinate(rng)};
        Vec2 b{coordinate(rng), coordinate(rng)}, c{coordinate(rng), coordinate(rng)};
        if (n % 3 == 1) {  // the benchmark's S-curve: controls off the chord by 0.4 of it
            const Vec2 side = grape::perpendicular(d - a) * 0.4;
            b = a + (d - a) / 3.0 + side;
            c = a + (d - a) * (2.0 / 3.0) - side;
        }
        const Path r = n % 10 == 9 ? grape::LinearPath(a, d).reparametrized() : Path(grape::CubicBezierPath(a, b, c, d, true));
        const auto table = grape::detail::ArcLengthTable::build(r);
        if (!table) {
            // The kernel then evaluates through Path::point: that, checked here instead. The
            // point at u must stand u·L along the source cubic; the source parameter found by
            // bisection of its own adaptive length_at (checked against composite Gauss–Legendre
            // in PathLength) to 1e-15 in parameter, independently of the reparametrization's
            // inversion. 1e-9·L: Path::point's bound on reparametrized paths (Reparametrized,
            // ArcLengthErrorBelow1e9ForEveryKind); the bisection adds ≤ 1e-15 times the top speed.
            ++refused;
            const Path source = grape::path_cast<grape::ReparametrizedSpec>(r)->source;
            const double L = source.length();
            double worst = 0.0;
            for (int i = 0; i <= 40; ++i) {
                const double u = i < 20 ? i / 20.0 : unit(rng);
                double lo = 0.0, hi = 1.0;
                while (hi - lo > 1e-15) {
                    const double mid = 0.5 * (lo + hi);
                    (source.length_at(mid) < u * L ? lo : hi) = mid;
                }
                worst = std::max(worst, grape::distance(r.point(u), source.point(0.5 * (lo + hi))));
            }
            EXPECT_LE(worst, 1e-9 * L) << n;
            std::printf("ArcLengthTable: cubic %d refused (%.17g, %.17g) (%.17g, %.17g) (%.17g, %.17g) (%.17g, %.17g); "
                        "Path::point within %.3g·L of the bisected arc length\n",
                        n, a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y, worst / L);
            continue;
        }
        ++built;
        most_steps = std::max(most_steps, table->steps());
        EXPECT_EQ(table->values().size(), grape::detail::ArcLengthTable::stride * static_cast<std::size_t>(table->steps()));
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(table->values().data()) % 64, 0u);  // a piece is whole lines
        const double L = r.length();
        double worst = 0.0;
        for (int i = 0; i < 4000; ++i) {
            const double u = unit(rng);
            worst = std::max(worst, grape::distance(table->point(u), r.point(u)));
        }
        EXPECT_LE(worst, 2e-10 * L) << n;
        EXPECT_EQ(table->point(1.0), r.point(1.0)) << n;  // the ends exactly
        EXPECT_EQ(table->point(0.0), r.point(0.0)) << n;
        EXPECT_EQ(table->point(std::nan("")), r.point(0.0)) << n;
        if (n % 3 == 1) {
            EXPECT_LE(table->steps(), 8.0) << n;  // ≤ 1.5 KB for the benchmark's shape
        }
        if (n % 10 == 9) {
            EXPECT_EQ(table->steps(), 1.0) << n;  // a line moves evenly already
        }
    }
    // All but cubics that (nearly) stop somewhere: about 2.6 % of these random cubics (2 to 13
    // of the 270, over 41 draws of GRAPE_TEST_SEED), so 20 refused is the binomial mean (7)
    // plus five standard deviations (2.6 each).
    std::printf("ArcLengthTable: %d tables built, %d refused (checked through Path::point)\n", built, refused);
    EXPECT_EQ(built + refused, 300);
    EXPECT_GE(built, 280);
    EXPECT_LE(most_steps, 4096.0);
}

// The arc-length lanes take a record's table from its path kernel without testing it: the
// reparametrized kernels must exist only with a table, and a path whose table is refused
// (a cubic that stops at a cusp) must get the generic kernel. The same random cubics as
// above, cusps among them.
TEST(ArcLengthTable, ReparametrizedKernelsCarryTheirTable) {
    std::mt19937 rng(static_cast<std::uint32_t>(grape::testing::test_seed(17)));
    std::uniform_real_distribution<double> coordinate(0.0, 1000.0);
    int refused = 0;
    for (int n = 0; n < 300; ++n) {
        const Vec2 a{coordinate(rng), coordinate(rng)}, d{coordinate(rng), coordinate(rng)};
        Vec2 b{coordinate(rng), coordinate(rng)}, c{coordinate(rng), coordinate(rng)};
        if (n % 4 == 3) c = b;         // coincident controls
        if (n % 5 == 4) b = d, c = a;  // controls swapped onto the ends: the curve stops and turns
        const Path r = n % 10 == 9 ? grape::LinearPath(a, d).reparametrized() : Path(grape::CubicBezierPath(a, b, c, d, true));
        const grape::detail::PathKernel k = grape::detail::make_kernel(r);
        const bool reparam =
            k.kind == grape::detail::KernelKind::reparam_cubic || k.kind == grape::detail::KernelKind::reparam_linear;
        EXPECT_EQ(reparam, k.table.has_value()) << n;
        if (!k.table) {
            ++refused;
            EXPECT_EQ(k.kind, grape::detail::KernelKind::generic) << n;
        }
    }
    EXPECT_GT(refused, 0);  // both cases met
    EXPECT_LT(refused, 300);
}

// The storage order (slot) against the polynomial it stands for: a piece whose only
// coefficients are x^i's, (1, 2), gives (x^i, 2·x^i) exactly at x = ±½ and ±1 (powers of two:
// every product exact, every other term an exact zero), in both evaluations.
TEST(ArcLengthTable, EachSlotHoldsItsPowerOfX) {
    using grape::detail::ArcLengthTable;
    alignas(64) double c[ArcLengthTable::stride];
    for (int i = 0; i <= ArcLengthTable::degree; ++i) {
        std::fill(std::begin(c), std::end(c), 0.0);
        c[ArcLengthTable::slot(i)] = 1.0;
        c[ArcLengthTable::slot(i) + 1] = 2.0;
        for (const double x : {0.5, -0.5, 1.0, -1.0}) {
            const double power = std::pow(x, i);
            EXPECT_EQ(ArcLengthTable::evaluate_piece(c, x), (Vec2{power, 2.0 * power})) << i << " " << x;
#if GRAPE_WIDE
            if (grape::detail::wide_lanes()) {
                EXPECT_EQ(ArcLengthTable::evaluate_piece_wide(c, x), (Vec2{power, 2.0 * power})) << i << " " << x;
            }
#endif
        }
    }
    std::vector<std::size_t> slots;  // every word of a piece belongs to one coefficient
    for (int i = 0; i <= ArcLengthTable::degree; ++i) slots.push_back(ArcLengthTable::slot(i) / 2);
    std::sort(slots.begin(), slots.end());
    for (std::size_t k = 0; k < slots.size(); ++k) EXPECT_EQ(slots[k], k);
}

// The four-lane evaluation the tick uses where the processor has AVX2 does the two-lane one's
// operations on the same values (no fused multiply-adds), so the bits agree: on fitted tables
// and on random coefficients of every size, at random x in [−1, 1] and at its ends.
#if GRAPE_WIDE
// ArcLengthTable::four_pieces_at on arrays (its lanes are AVX2 registers).
GRAPE_AVX2 void four_pieces_at(const double* const tables[4], const double* steps, const double* u,
                               grape::detail::ArcLengthTable::Piece out[4]) {
    grape::detail::ArcLengthTable::four_pieces_at(tables, _mm256_loadu_pd(steps), _mm256_loadu_pd(u), out);
}
#endif

TEST(ArcLengthTable, FourLanesGiveTheBitsOfTwo) {
#if GRAPE_WIDE
    using grape::detail::ArcLengthTable;
    if (!grape::detail::wide_lanes()) GTEST_SKIP() << "no AVX2 here";
    std::mt19937_64 rng(grape::testing::test_seed(77));
    std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-30.0, 30.0);
    alignas(64) double c[ArcLengthTable::stride];
    int compared = 0;
    for (int n = 0; n < 2000; ++n) {
        for (double& w : c) w = unit(rng) * std::exp2(exponent(rng));
        for (int k = 0; k < 50; ++k) {
            const double x = k == 0 ? -1.0 : k == 1 ? 1.0 : unit(rng);
            const Vec2 two = ArcLengthTable::evaluate_piece(c, x), four = ArcLengthTable::evaluate_piece_wide(c, x);
            EXPECT_EQ(std::memcmp(&two, &four, sizeof two), 0) << n << " " << x;
            ++compared;
        }
    }
    // two pieces at once (each of a random pair, at random places) and four pieces found at
    // once give the bits of one at a time
    std::vector<double, grape::detail::LineAllocator<double>> many(ArcLengthTable::stride * 64);
    for (double& w : many) w = unit(rng) * std::exp2(exponent(rng));
    std::uniform_int_distribution<int> which(0, 63);
    for (int n = 0; n < 20000; ++n) {
        const double* a = many.data() + ArcLengthTable::stride * static_cast<std::size_t>(which(rng));
        const double* b = many.data() + ArcLengthTable::stride * static_cast<std::size_t>(which(rng));
        const double xa = n % 11 == 0 ? -1.0 : unit(rng), xb = n % 7 == 0 ? xa : n % 13 == 0 ? 1.0 : unit(rng);
        Vec2 pa, pb;
        ArcLengthTable::evaluate_two_pieces_wide(a, xa, b, xb, pa, pb);
        const Vec2 ta = ArcLengthTable::evaluate_piece(a, xa), tb = ArcLengthTable::evaluate_piece(b, xb);
        EXPECT_EQ(std::memcmp(&pa, &ta, sizeof pa), 0) << n << " " << xa;
        EXPECT_EQ(std::memcmp(&pb, &tb, sizeof pb), 0) << n << " " << xb;
        ++compared;
    }
    std::uniform_real_distribution<double> fraction(0.0, 1.0);
    for (int n = 0; n < 20000; ++n) {
        double u[4], steps[4];
        const double* tables[4];
        for (int j = 0; j < 4; ++j) {
            steps[j] = std::exp2(std::uniform_int_distribution<int>(0, 12)(rng));  // K = 1 … 4096
            u[j] = n % 5 == 0 ? std::nextafter(1.0, 0.0) : fraction(rng);  // u < 1, the largest too
            if (!(u[j] > 0.0)) u[j] = 0.5;
            tables[j] = many.data() + j;
        }
        ArcLengthTable::Piece four[4];
        four_pieces_at(tables, steps, u, four);
        for (int j = 0; j < 4; ++j) {
            const ArcLengthTable::Piece one = ArcLengthTable::piece_at(tables[j], steps[j], u[j]);
            EXPECT_EQ(four[j].c, one.c) << u[j] << " " << steps[j];
            EXPECT_EQ(std::memcmp(&four[j].x, &one.x, sizeof one.x), 0) << u[j] << " " << steps[j];
        }
    }
    const auto table = ArcLengthTable::build(Path(grape::CubicBezierPath({0, 0}, {0, 300}, {400, -200}, {500, 90}, true)));
    ASSERT_TRUE(table);
    const auto values = table->values();
    for (std::size_t piece = 0; piece < values.size(); piece += ArcLengthTable::stride) {
        for (int k = 0; k < 200; ++k) {
            const double x = unit(rng);
            const Vec2 two = ArcLengthTable::evaluate_piece(values.data() + piece, x);
            const Vec2 four = ArcLengthTable::evaluate_piece_wide(values.data() + piece, x);
            EXPECT_EQ(std::memcmp(&two, &four, sizeof two), 0) << piece << " " << x;
            ++compared;
        }
    }
    EXPECT_GE(compared, 100000);
#else
    GTEST_SKIP() << "no four-lane evaluation on this target";
#endif
}

TEST(Reparametrized, CubicAArcLengthPointsAndFlag) {
    const grape::CubicBezierPath raw({0, 0}, {0, 100}, {100, 100}, {100, 0});
    const grape::CubicBezierPath even({0, 0}, {0, 100}, {100, 100}, {100, 0}, true);
    EXPECT_EQ(even.kind(), grape::PathKind::reparametrized);
    EXPECT_EQ(raw.kind(), grape::PathKind::cubic_bezier);
    EXPECT_EQ(even.control(2), (Vec2{100, 100}));
    // s(t) = 300(t − t² + ⅔t³): s = 50 at t = 0.201964181 → (10.589254, 48.352395).
    EXPECT_NEAR(even.point(0.25).x, 10.589254, 5e-7);
    EXPECT_NEAR(even.point(0.25).y, 48.352395, 5e-7);
    EXPECT_NEAR(grape::distance(even.point(0.5), Vec2{50, 75}), 0.0, 1e-9 * 200);
    EXPECT_EQ(raw.point(0.25), (Vec2{15.625, 56.25}));
    // Reparametrizing again returns the same shape object.
    EXPECT_TRUE(even.reparametrized() == even);
    const grape::QuadraticBezierPath q({0, 0}, {50, 100}, {100, 0}, true);
    EXPECT_EQ(q.control(1), (Vec2{50, 100}));
    EXPECT_NEAR(q.d1(0.3).x * q.d1(0.3).x + q.d1(0.3).y * q.d1(0.3).y, q.length() * q.length(),
                16 * eps * q.length() * q.length());
}

TEST(Reparametrized, CircleStaysExactAndZeroLengthPathsStayPut) {
    // A circle is already at constant speed: the table reproduces it to rounding.
    const grape::CirclePath c({0, 0}, 10, 0, 2 * pi);
    const Path r = c.reparametrized();
    for (double u : {0.1, 0.3, 0.77}) {
        EXPECT_NEAR(grape::distance(r.point(u), c.point(u)), 0.0, 1e-9 * c.length());
        EXPECT_NEAR(grape::distance(r.d2(u), c.d2(u)), 0.0, 1e-6);  // |x″| = L²/r ≈ 395
    }
    const grape::LinearPath dot({3, 4}, {3, 4});
    const Path still = dot.reparametrized();
    EXPECT_EQ(still.length(), 0.0);
    EXPECT_EQ(still.point(0.5), (Vec2{3, 4}));
    EXPECT_EQ(still.d1(0.5), Vec2{});
}

// --- bounds and flattening ----------------------------------------------------------------------

TEST(PathBounds, TightAroundDenseSamples) {
    for (const auto& [name, path] : all_paths()) {
        const grape::Bounds box = path.bounds();
        grape::Bounds sampled;
        double d2_max = 0.0;
        const int n = 20000;
        for (int i = 0; i <= n; ++i) {
            sampled.add(path.point(i / double(n)));
            d2_max = std::max(d2_max, grape::length(path.d2(i / double(n))));
        }
        for (double b : grape::detail::smooth_breaks(path)) sampled.add(path.point(b));
        for (const auto& [a, b] : pieces(path)) sampled.add(path.point(std::nextafter(b, a)));
        // Every sample inside (rounding slack); the box no larger than the samples' own box
        // plus how far a coordinate can move past a sample near its extreme: |x″|·Δu²/8.
        const double size = max_abs_coordinate(path);
        const double slack = 16 * eps * size;
        EXPECT_TRUE(box.contains(sampled.min, slack) && box.contains(sampled.max, slack)) << name;
        const double reach = d2_max / (8.0 * n * n) + slack;
        EXPECT_LE(sampled.min.x - box.min.x, reach) << name;
        EXPECT_LE(sampled.min.y - box.min.y, reach) << name;
        EXPECT_LE(box.max.x - sampled.max.x, reach) << name;
        EXPECT_LE(box.max.y - sampled.max.y, reach) << name;
    }
}

using grape::testing::distance_to_polyline;

TEST(PathFlatten, StaysWithinToleranceOfDenseSamples) {
    for (const auto& [name, path] : all_paths()) {
        for (double tolerance : {0.5, 0.02}) {
            const double tol = std::max(tolerance, 1e-6 * max_abs_coordinate(path)) * (name == "bezier_tiny" ? 1e-8 : 1.0);
            const auto line = path.flatten(tol);
            ASSERT_GE(line.size(), 2u) << name;
            EXPECT_EQ(line.front(), path.point(0.0)) << name;
            EXPECT_LE(grape::distance(line.back(), path.point(1.0)), 1e-9 * path.length() + 1e-300) << name;
            double worst = 0.0;
            const int n = 3000;
            for (int i = 0; i <= n; ++i) worst = std::max(worst, distance_to_polyline(path.point(i / double(n)), line));
            EXPECT_LE(worst, tol * (1 + 1e-9)) << name << " tolerance " << tol << " points " << line.size();
        }
    }
}

TEST(PathFlatten, UsesFewPoints) {
    // Chords of length √(8·tol/κ) are the longest within tolerance, so ∫√(κ/(8·tol)) ds is
    // a lower bound on the chord count; halving subdivision may overshoot it by up to 2×.
    for (const char* name : {"circle", "cubic_bezier", "spiral", "sine_wave", "hermite_spline", "elliptical_arc"}) {
        for (const auto& p : grape::scenes::path_gallery()) {
            if (p.name != name) continue;
            const double tol = 0.05;
            auto density = [&](double u) {
                const Vec2 d1 = p.path.d1(u), d2 = p.path.d2(u);
                const double speed = grape::length(d1);
                const double curvature = speed > 0 ? std::abs(grape::cross(d1, d2)) / (speed * speed * speed) : 0.0;
                return std::sqrt(curvature / (8 * tol)) * speed;
            };
            double ideal = 0.0;
            for (auto [a, b] : pieces(p.path)) ideal += grape::integrate(density, a, b, 1e-6);
            const auto line = p.path.flatten(tol);
            EXPECT_LE(static_cast<double>(line.size()), 2.0 * ideal + 2.0 * pieces(p.path).size() + 2) << name;
        }
    }
}

TEST(PathFlatten, StraightKindsGiveTheirCorners) {
    EXPECT_EQ(grape::LinearPath({0, 0}, {5, 5}).flatten(0.1).size(), 2u);
    const auto spline = grape::scenes::seed_cosine_spline().flatten(0.01);
    EXPECT_EQ(spline.size(), 6u);
    EXPECT_EQ(spline[3], (Vec2{300, 400}));
}

// --- evaluation cost ----------------------------------------------------------------------------

TEST(PathEvaluation, AllocatesNothing) {
    const auto paths = all_paths();
    std::vector<Path> reparametrized;
    for (const auto& p : paths) reparametrized.push_back(p.path.reparametrized());
    double sink = 0.0;
    const long before = g_allocations.load();
    for (int i = 0; i <= 100; ++i) {
        const double u = i / 100.0 * 1.2 - 0.1;
        for (const auto& p : paths) {
            sink += p.path.point(u).x + p.path.d1(u).y + p.path.d2(u).x + p.path.heading(u);
        }
        for (const auto& r : reparametrized) sink += r.point(u).x + r.d1(u).y + r.d2(u).x;
    }
    EXPECT_EQ(g_allocations.load() - before, 0);
    EXPECT_TRUE(std::isfinite(sink));
}

// --- the handle, accessors, Path1D and PathND ---------------------------------------------------

TEST(PathHandle, DefaultStaysAtTheOriginAndCopiesShare) {
    const Path p;
    EXPECT_EQ(p.point(0.3), Vec2{});
    EXPECT_EQ(p.length(), 0.0);
    EXPECT_EQ(p.kind(), grape::PathKind::linear);
    const Path a = grape::scenes::seed_spiral();
    const Path b = a;
    EXPECT_TRUE(a == b);
    EXPECT_FALSE(a == Path(grape::scenes::seed_spiral()));
    EXPECT_EQ(grape::to_string(grape::PathKind::catmull_rom_spline), "catmull_rom_spline");
    // Heading: a circle with increasing angle moves along +y at angle 0 (y down: clockwise).
    EXPECT_NEAR(grape::CirclePath({0, 0}, 1, 0, pi).heading(0.0), pi / 2, 1e-15);
    EXPECT_EQ(grape::scenes::seed_cosine_spline().heading(0.0), 0.0);  // standing still
}

TEST(PathHandle, AccessorsReturnTheInputs) {
    const grape::CirclePath c({1, 2}, 3, 4, 5);
    EXPECT_EQ(c.center(), (Vec2{1, 2}));
    EXPECT_EQ(c.radius(), 3);
    EXPECT_EQ(c.start_angle(), 4);
    EXPECT_EQ(c.end_angle(), 5);
    const grape::EllipticalArcPath e({1, 2}, 3, 4, 0.5, 6, 7);
    EXPECT_EQ(e.rx(), 3);
    EXPECT_EQ(e.ry(), 4);
    EXPECT_EQ(e.rotation(), 0.5);
    EXPECT_EQ(e.start_angle(), 6);
    EXPECT_EQ(e.end_angle(), 7);
    const grape::SpiralPath s({1, 2}, 3, 4, 5, 6);
    EXPECT_EQ(s.start_radius(), 3);
    EXPECT_EQ(s.end_radius(), 4);
    EXPECT_EQ(s.end_angle(), 6);
    const grape::SineWavePath w({0, 0}, {1, 0}, 2, 3);
    EXPECT_EQ(w.frequency(), 2);
    EXPECT_EQ(w.amplitude(), 3);
    const grape::PhysicsPath ph({1, 2}, {3, 4}, {5, 6}, 7);
    EXPECT_EQ(ph.velocity(), (Vec2{3, 4}));
    EXPECT_EQ(ph.acceleration(), (Vec2{5, 6}));
    EXPECT_EQ(ph.seconds(), 7);
    // t = u·seconds: x = p + v·t + ½·a·t².
    EXPECT_NEAR(ph.point(0.5).x, 1 + 3 * 3.5 + 0.5 * 5 * 3.5 * 3.5, 1e-12);
    const grape::LinearSplinePath ls({1, 2, 3, 4});
    EXPECT_EQ(ls.points()[1], (Vec2{3, 4}));
    const auto cr = grape::scenes::seed_catmull_rom_spline(grape::CatmullRom::chordal);
    EXPECT_EQ(cr.type(), grape::CatmullRom::chordal);
    const auto complex = grape::scenes::seed_complex();
    EXPECT_EQ(complex.parts().size(), 4u);
    EXPECT_EQ(complex.cues()[3], 0.6);
}

TEST(ComplexPath, EmptySpansAreSkippedAndByLengthSharesEvenly) {
    const grape::LinearPath a({0, 0}, {10, 0}), b({10, 0}, {10, 30}), c({10, 30}, {0, 30});
    const grape::ComplexPath skip({a, b, c}, {0, 0.5, 0.5});  // b has an empty span
    EXPECT_EQ(skip.point(0.75), (Vec2{5, 30}));
    EXPECT_EQ(skip.length(), 20.0);  // b is not travelled
    const auto even = grape::ComplexPath::by_length({a, b, c});
    EXPECT_EQ(even.cues()[1], 0.2);
    EXPECT_EQ(even.cues()[2], 0.8);
    const Path r = even.reparametrized();
    EXPECT_NEAR(grape::distance(even.point(0.5), Vec2{10, 15}), 0.0, 1e-12);  // by length: constant speed
    EXPECT_NEAR(grape::distance(r.point(0.5), Vec2{10, 15}), 0.0, 1e-9 * 50);
    const auto zeros = grape::ComplexPath::by_length({grape::LinearPath({1, 1}, {1, 1}), grape::LinearPath({1, 1}, {1, 1})});
    EXPECT_EQ(zeros.cues()[1], 0.5);
    EXPECT_EQ(zeros.point(0.7), (Vec2{1, 1}));
    // Nested: a complex path inside a complex path, by length.
    const auto nested = grape::ComplexPath::by_length({skip, grape::LinearPath({0, 30}, {0, 50})});
    EXPECT_EQ(nested.length(), 40.0);
    EXPECT_EQ(nested.point(1.0), (Vec2{0, 50}));
}

TEST(Path1DAndND, ValuesDerivativesAndExtension) {
    const grape::Path1D p(2, 6);
    EXPECT_EQ(p.value(0.25), 3);
    EXPECT_EQ(p.d1(0.5), 4);
    EXPECT_EQ(p.value(1.5), 8);
    const std::vector<double> from{0, 10}, to{4, 30};
    const grape::PathND n(from, to);
    EXPECT_EQ(n.dimension(), 2u);
    double out[2];
    n.point(0.25, out);
    EXPECT_EQ(out[0], 1);
    EXPECT_EQ(out[1], 15);
    n.point(1.5, out);
    EXPECT_EQ(out[0], 6);
    const std::vector<double> keys{0, 10, 100};
    const grape::PathND k(1, keys);
    EXPECT_EQ(k.keyframe_count(), 3u);
    k.point(0.75, std::span<double>(out, 1));
    EXPECT_EQ(out[0], 55);
    k.d1(0.75, std::span<double>(out, 1));
    EXPECT_EQ(out[0], 180);  // 90 per segment, two segments
    k.point(-0.5, std::span<double>(out, 1));
    EXPECT_EQ(out[0], -10);
}

// --- bad input -----------------------------------------------------------------------------------

TEST(PathErrors, EveryBadInputNamesTheArgumentAndReason) {
    const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
    EXPECT_ERROR(grape::LinearPath({nan, 0}, {1, 1}), "LinearPath: start must be finite (got (nan, 0))");
    EXPECT_ERROR(grape::LinearPath({0, 0}, {1, inf}), "LinearPath: end must be finite (got (1, inf))");
    EXPECT_ERROR(grape::CirclePath({0, 0}, -1, 0, 1), "CirclePath: radius must be positive and finite (got -1)");
    EXPECT_ERROR(grape::CirclePath({0, 0}, 0, 0, 1), "CirclePath: radius must be positive and finite (got 0)");
    EXPECT_ERROR(grape::CirclePath({0, 0}, 1, nan, 1), "CirclePath: start_angle must be finite (got nan)");
    EXPECT_ERROR(grape::CirclePath({0, nan}, 1, 0, 1), "CirclePath: center must be finite (got (0, nan))");
    EXPECT_ERROR(grape::EllipticalArcPath({0, 0}, 1, 0, 0, 0, 1),
                 "EllipticalArcPath: ry must be positive and finite (got 0)");
    EXPECT_ERROR(grape::EllipticalArcPath({0, 0}, 1, 1, inf, 0, 1), "EllipticalArcPath: rotation must be finite (got inf)");
    EXPECT_ERROR(grape::SpiralPath({0, 0}, -5, 0), "SpiralPath: start_radius must be non-negative and finite (got -5)");
    EXPECT_ERROR(grape::SpiralPath({0, 0}, 5, inf), "SpiralPath: end_radius must be non-negative and finite (got inf)");
    EXPECT_ERROR(grape::SpiralPath({0, 0}, 5, 0, 0, nan), "SpiralPath: end_angle must be finite (got nan)");
    EXPECT_ERROR(grape::SineWavePath({1, 1}, {1, 1}, 1, 1),
                 "SineWavePath: start and end must differ (both (1, 1)): the wave needs a direction");
    EXPECT_ERROR(grape::SineWavePath({0, 0}, {1, 1}, nan, 1), "SineWavePath: frequency must be finite (got nan)");
    EXPECT_ERROR(grape::SineWavePath({0, 0}, {1, 1}, 1, inf), "SineWavePath: amplitude must be finite (got inf)");
    EXPECT_ERROR(grape::SineWavePath({0, 0}, {1, 1}, 2e6, 1),
                 "SineWavePath: frequency must be at most a million waves (got 2e+06)");
    EXPECT_ERROR(grape::CirclePath({0, 0}, 1, 0, 1e7 * pi),
                 "CirclePath: end_angle − start_angle must be at most a million turns (got 31415926.535897933 radians)");
    EXPECT_ERROR(grape::SpiralPath({0, 0}, 1, 2, 0, -1e7 * pi),
                 "SpiralPath: end_angle − start_angle must be at most a million turns (got -31415926.535897933 radians)");
    EXPECT_ERROR(grape::LinearPath({-1e308, 0}, {1e308, 0}),
                 "Path (linear): the length overflows a double; coordinates or parameters are too large");
    EXPECT_ERROR(grape::PhysicsPath({0, 0}, {1, 1}, {0, 1e300}, 1e200),
                 "PhysicsPath: position, velocity·seconds and acceleration·seconds² are too large to evaluate in "
                 "double precision (coefficients overflow)");
    EXPECT_ERROR(grape::CubicBezierPath({0, 0}, {0, 0}, {1.4e307, 0}, {0, 0}),
                 "CubicBezierPath: control points are too large to evaluate in double precision (coefficients overflow)");
    EXPECT_ERROR(grape::QuadraticBezierPath({-1e308, 0}, {1e308, 0}, {-1e308, 0}),
                 "QuadraticBezierPath: control points are too large to evaluate in double precision (coefficients overflow)");
    EXPECT_ERROR(grape::QuadraticBezierPath({0, 0}, {nan, 0}, {1, 1}), "QuadraticBezierPath: p1 must be finite (got (nan, 0))");
    EXPECT_ERROR(grape::CubicBezierPath({0, 0}, {0, 0}, {0, 0}, {inf, 0}), "CubicBezierPath: p3 must be finite (got (inf, 0))");
    EXPECT_ERROR(grape::LinearSplinePath({1, 2, 3}),
                 "LinearSplinePath: xy must hold x, y pairs: an even number of coordinates (got 3)");
    EXPECT_ERROR(grape::LinearSplinePath({1, 2}), "LinearSplinePath: points needs at least 2 points (got 1)");
    EXPECT_ERROR(grape::LinearSplinePath(std::span<const Vec2>()), "LinearSplinePath: points needs at least 2 points (got 0)");
    EXPECT_ERROR(grape::CosineSplinePath({1, 2, nan, 4}), "CosineSplinePath: points[1] must be finite (got (nan, 4))");
    EXPECT_ERROR(grape::CatmullRomSplinePath({1, 2}), "CatmullRomSplinePath: points needs at least 2 points (got 1)");
    EXPECT_ERROR(grape::CatmullRomSplinePath({1, 2, 3, 4, 5}),
                 "CatmullRomSplinePath: xy must hold x, y pairs: an even number of coordinates (got 5)");
    EXPECT_ERROR(grape::CatmullRomSplinePath({1, 2, 3, 4}, static_cast<grape::CatmullRom>(7)),
                 "CatmullRomSplinePath: type must be uniform, centripetal or chordal (got 7)");
    const std::vector<Vec2> pts{{0, 0}, {1, 1}, {2, 0}};
    const std::vector<Vec2> two{{0, 0}, {1, 1}};
    EXPECT_ERROR(grape::HermiteSplinePath(pts, two),
                 "HermiteSplinePath: tangents needs one tangent per point (got 2 tangents for 3 points)");
    const std::vector<Vec2> bad_tangents{{0, 0}, {inf, 1}, {2, 0}};
    EXPECT_ERROR(grape::HermiteSplinePath(pts, bad_tangents), "HermiteSplinePath: tangents[1] must be finite (got (inf, 1))");
    const std::vector<double> odd{1, 2, 3};
    const std::vector<double> four{1, 2, 3, 4};
    EXPECT_ERROR(grape::HermiteSplinePath(four, odd),
                 "HermiteSplinePath: tangent_xy must hold x, y pairs: an even number of coordinates (got 3)");
    EXPECT_ERROR(grape::PhysicsPath({0, 0}, {1, 1}, {0, 1}, -1), "PhysicsPath: seconds must be positive and finite (got -1)");
    EXPECT_ERROR(grape::PhysicsPath({0, 0}, {1, 1}, {0, 1}, 0), "PhysicsPath: seconds must be positive and finite (got 0)");
    EXPECT_ERROR(grape::PhysicsPath({0, 0}, {nan, 1}, {0, 1}, 1), "PhysicsPath: velocity must be finite (got (nan, 1))");

    const grape::LinearPath l({0, 0}, {1, 0});
    EXPECT_ERROR(grape::ComplexPath({}, {}), "ComplexPath: parts must not be empty");
    EXPECT_ERROR(grape::ComplexPath::by_length({}), "ComplexPath::by_length: parts must not be empty");
    EXPECT_ERROR(grape::ComplexPath({l, l}, {0}), "ComplexPath: cues needs one cue per part (got 1 cues for 2 parts)");
    EXPECT_ERROR(grape::ComplexPath({l, l}, {0.1, 0.5}),
                 "ComplexPath: cues[0] must be 0: the first part starts the path (got 0.1)");
    EXPECT_ERROR(grape::ComplexPath({l, l, l}, {0, 0.5, 0.25}), "ComplexPath: cues must not decrease (cues[2] = 0.25 < cues[1] = 0.5)");
    EXPECT_ERROR(grape::ComplexPath({l, l}, {0, 1.5}), "ComplexPath: cues[1] must lie in [0, 1] (got 1.5)");
    EXPECT_ERROR(grape::ComplexPath({l, l}, {0, -0.5}), "ComplexPath: cues[1] must lie in [0, 1] (got -0.5)");
    EXPECT_ERROR(grape::ComplexPath({l, l}, {0, nan}), "ComplexPath: cues[1] must be finite (got nan)");

    EXPECT_ERROR(l.flatten(0), "Path::flatten: tolerance must be positive and finite (got 0)");
    EXPECT_ERROR(l.flatten(nan), "Path::flatten: tolerance must be positive and finite (got nan)");
    EXPECT_ERROR(l.flatten(inf), "Path::flatten: tolerance must be positive and finite (got inf)");

    EXPECT_ERROR(grape::Path1D(nan, 1), "Path1D: from must be finite (got nan)");
    EXPECT_ERROR(grape::Path1D(0, inf), "Path1D: to must be finite (got inf)");
    const std::vector<double> a2{1, 2}, a3{1, 2, 3};
    EXPECT_ERROR(grape::PathND(a2, a3), "PathND: from and to must have the same size (got 2 and 3)");
    EXPECT_ERROR(grape::PathND(std::span<const double>(), std::span<const double>()), "PathND: dimension must be at least 1 (got 0)");
    EXPECT_ERROR(grape::PathND(2, a3), "PathND: keyframes must hold a multiple of dimension 2 values (got 3)");
    EXPECT_ERROR(grape::PathND(2, a2), "PathND: keyframes needs at least 2 keyframes (got 1)");
    const std::vector<double> with_nan{1, nan};
    EXPECT_ERROR(grape::PathND(1, with_nan), "PathND: keyframes[1] must be finite (got nan)");
}

// A part squeezed into a span of 1e-160: its chain-rule factor 1/width² (1e320) overflows a
// double, but d2 must stay finite (exactly 0 for a straight part) and d1 exact.
TEST(ComplexPath, TinySpansKeepDerivativesFinite) {
    const grape::ComplexPath c({grape::LinearPath({0, 0}, {1, 0}), grape::LinearPath({1, 0}, {2, 0})},
                               {0, 1e-160});
    const Vec2 d2 = c.d2(0.5e-160);
    EXPECT_EQ(d2.x, 0.0);
    EXPECT_EQ(d2.y, 0.0);
    EXPECT_TRUE(grape::is_finite(c.d1(0.5e-160)));
}

// Control points near the largest the constructor accepts (6·Σ|power-basis coefficient| must
// be finite): the derivatives stay exact at the ends, d2(0) = 6(p0 − 2p1 + p2) and
// d2(1) = 6(p1 − 2p2 + p3), each computed here with the same operations.
TEST(CubicBezierPath, HugeControlPointsKeepEndDerivativesExact) {
    const double big = 2e306;
    const grape::CubicBezierPath b({0, 0}, {0, 0}, {big, 0}, {0, 0});
    EXPECT_EQ(b.d2(0.0).x, 6.0 * big);
    EXPECT_EQ(b.d2(1.0).x, 6.0 * (-2.0 * big));
    EXPECT_EQ(b.d1(0.0).x, 0.0);
    EXPECT_EQ(b.d1(1.0).x, 3.0 * -big);
    EXPECT_TRUE(grape::is_finite(b.point(0.5)));
}

// A fuzz finding: a cubic spanning 6e113 with a few hundred units of detail at its start.
// The arc-length model cannot reach 1e-10·L everywhere there, and the table once split
// spans until memory ran out; the span budget bounds it. The ends stay exact.
TEST(Reparametrized, ExtremeScalesBuildInBoundedTime) {
    const grape::CubicBezierPath b({40, 20}, {798, 200}, {200, 600}, {6.1e113, 600}, true);
    EXPECT_EQ(b.point(0.0), (Vec2{40, 20}));
    EXPECT_EQ(b.point(1.0), (Vec2{6.1e113, 600}));
    EXPECT_TRUE(grape::is_finite(b.point(0.5)));
}

// The contract holds whatever the number of segments: a 10,000-segment SVG path (cubics,
// quadratics, elliptical arcs, lines) once ran out of a fixed span budget at ~6,700 segments
// and left the rest on coarse spans (3.5e-3 px of error on 7e6 px, 4.3× over 1e-9·L).
TEST(Reparametrized, ArcLengthContractHoldsAtTenThousandSegments) {
    const Path source = grape::parse_svg_path(grape::scenes::segments_svg(10000, 17));
    const Path r = source.reparametrized();
    const double L = source.length();
    std::mt19937_64 rng(grape::testing::test_seed(23));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i <= 20000; ++i) {
        // Evenly over the whole path (every segment seen twice), then at random.
        const double u = i < 10000 ? i / 10000.0 : unit(rng);
        worst = std::max(worst, std::abs(source.length_at(grape::detail::source_parameter(r, u)) - u * L));
    }
    EXPECT_LE(worst, 1e-9 * L);
    EXPECT_EQ(r.point(1.0), source.point(1.0));
}

TEST(Reparametrized, DenormalLengthsGiveTheRightPoint) {
    // A segment of length L moves at constant speed already: point(u) = u·L exactly in
    // exact arithmetic. At L = 3e-320 the table's spans underflowed to zero length and
    // count/L overflowed (converted to size_t: undefined), so every u landed on the end.
    // Denormals carry few digits: the tolerance is a few of their ulps (4.9e-324 each).
    for (const double length : {1e-310, 3e-320, 1e-322}) {
        SCOPED_TRACE(length);
        const Path r = grape::LinearPath({0, 0}, {length, 0}).reparametrized();
        for (const double u : {0.125, 0.25, 0.5, 0.75}) {
            EXPECT_NEAR(r.point(u).x, u * length, 4e-324 + 1e-15 * length) << "u = " << u;
            EXPECT_EQ(r.point(u).y, 0.0);
        }
    }
    // A cubic of denormal size, against its own arc length at the same fraction.
    const double l = 3e-320;
    const grape::CubicBezierPath c({0, 0}, {l, l}, {2 * l, 0}, {3 * l, l});
    const Path r = c.reparametrized();
    EXPECT_NEAR(r.point(0.5).x, c.point(0.5).x, 0.01 * 3 * l);  // symmetric about u = ½
}

}  // namespace
