// Path queries against independent truth: the nearest point against dense sampling refined by
// golden-section search (which uses point() only), over thousands of random points near, far,
// on the path, at cusps, at arc centers and inside loops; curvature against closed forms
// (circle 1/r, spiral, parabola) and against the turning of heading(u) by finite differences.
#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/path_query.hpp>

#include "path/kernel.hpp"
#include "seed_paths.hpp"

#include "error_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <new>
#include <random>
#include <string>
#include <vector>

#include "count_allocations.hpp"
#include "seeds.hpp"

namespace {

using grape::ClosestPoint;
using grape::Path;
using grape::pi;
using grape::Vec2;
using grape::lerp;
using grape::NamedPath;

// A loop (the cubic crosses itself), SVG data with arcs, separate subpaths and a cusp.
const char* const svg_loops = "M100 300 C 400 0 -100 0 200 300 L 300 300 A 50 50 0 1 1 300 200 "
                              "Q 350 100 400 200 M 500 500 C 600 400 500 400 600 500 Z";

std::vector<NamedPath> query_paths() {
    auto paths = grape::scenes::path_gallery();
    for (auto& p : grape::scenes::seed_paths()) paths.push_back({"seed_" + p.name, p.path});
    paths.push_back({"circle_backwards_turns", grape::CirclePath({5, -3}, 2, 0, -5 * pi)});
    paths.push_back({"projectile_up_and_down", grape::PhysicsPath({0, 0}, {0, -10}, {0, 10}, 2)});
    paths.push_back({"bezier_cusp", grape::CubicBezierPath({0, 0}, {100, 100}, {0, 100}, {100, 0})});
    paths.push_back({"bezier_loop", grape::CubicBezierPath({0, 0}, {300, 200}, {-100, 200}, {200, 0})});
    paths.push_back({"bezier_tiny", grape::CubicBezierPath({0, 0}, {1e-6, 2e-6}, {3e-6, -1e-6}, {4e-6, 0})});
    paths.push_back({"spiral_outwards", grape::SpiralPath({0, 0}, 0, 100, 1, -3)});
    paths.push_back({"spiral_constant_radius", grape::SpiralPath({10, 10}, 40, 40, 0, 3 * pi)});
    paths.push_back({"ellipse_full_turns", grape::EllipticalArcPath({10, 20}, 30, 5, 0.3, 1, 1 + 4 * pi)});
    paths.push_back({"sine_many_waves", grape::SineWavePath({0, 0}, {300, 100}, 12, 15)});
    paths.push_back({"hermite_cusp", grape::HermiteSplinePath({0, 0, 100, 0, 200, 50}, {300, 300, 300, -300, 100, 0})});
    paths.push_back({"svg_loops", grape::parse_svg_path(svg_loops)});
    paths.push_back({"svg_hundred_segments", grape::parse_svg_path(grape::scenes::hundred_segments_svg())});
    paths.push_back({"svg_reparametrized", grape::parse_svg_path(svg_loops).reparametrized()});
    paths.push_back({"spiral_reparametrized", grape::scenes::seed_spiral().reparametrized()});
    return paths;
}

double extent(const Path& p) {
    const Vec2 s = p.bounds().size();
    return std::max(s.x, s.y);
}

// The contract: within 1e-12 of the path's size of the true minimum distance.
double tolerance(const Path& p) { return 1e-12 * extent(p); }

// Independent reference: samples over each smooth piece (ends taken from inside, so a part's
// end where complex parts do not meet is its left limit), then golden-section search around
// the best few sampled minima, on point() alone.
ClosestPoint brute_force(const Path& p, Vec2 q, double lo = 0.0, double hi = 1.0, int samples = 4000) {
    const auto& br = grape::detail::smooth_breaks(p);
    std::vector<double> us;
    const int per_piece = std::max(48, samples / static_cast<int>(br.size() - 1));
    for (std::size_t i = 0; i + 1 < br.size(); ++i) {
        const double a = std::max(lo, br[i]), b = std::min(hi, br[i + 1]);
        if (a > b) continue;
        for (int k = 0; k <= per_piece; ++k) us.push_back(a + (b - a) * k / per_piece);
        us.back() = std::max(a, b - (b - a) * 1e-13);
    }
    std::vector<double> d(us.size());
    for (std::size_t i = 0; i < us.size(); ++i) d[i] = grape::distance(q, p.point(us[i]));
    std::vector<std::size_t> minima;
    for (std::size_t i = 0; i < us.size(); ++i) {
        const bool left = i == 0 || d[i] <= d[i - 1];
        const bool right = i + 1 == us.size() || d[i] <= d[i + 1];
        if (left && right) minima.push_back(i);
    }
    std::sort(minima.begin(), minima.end(), [&](std::size_t a, std::size_t b) { return d[a] < d[b]; });
    ClosestPoint best{us[minima[0]], p.point(us[minima[0]]), d[minima[0]]};
    for (std::size_t k = 0; k < std::min<std::size_t>(6, minima.size()); ++k) {
        const std::size_t i = minima[k];
        double a = us[i > 0 ? i - 1 : i], b = us[i + 1 < us.size() ? i + 1 : i];
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        double x1 = b - g * (b - a), x2 = a + g * (b - a);
        double f1 = grape::distance(q, p.point(x1)), f2 = grape::distance(q, p.point(x2));
        for (int it = 0; it < 80; ++it) {
            if (f1 < f2) {
                b = x2, x2 = x1, f2 = f1;
                x1 = b - g * (b - a), f1 = grape::distance(q, p.point(x1));
            } else {
                a = x1, x1 = x2, f1 = f2;
                x2 = a + g * (b - a), f2 = grape::distance(q, p.point(x2));
            }
        }
        const double u = f1 < f2 ? x1 : x2;
        const double du = grape::distance(q, p.point(u));
        if (du < best.distance) best = {u, p.point(u), du};
    }
    return best;
}

void expect_consistent(const Path& p, Vec2 q, const ClosestPoint& c) {
    EXPECT_GE(c.u, 0.0);
    EXPECT_LE(c.u, 1.0);
    EXPECT_EQ(c.point, p.point(c.u));
    EXPECT_EQ(c.distance, grape::distance(q, c.point));
}

// Random points in and around the path's box, near the path (small normal offsets), on it
// and far away.
std::vector<Vec2> query_points(const Path& p, std::mt19937_64& rng, int count) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const grape::Bounds box = p.bounds();
    const double size = std::max(extent(p), 1e-300);
    const Vec2 center = 0.5 * (box.min + box.max);
    std::vector<Vec2> out;
    for (int i = 0; i < count; ++i) {
        const double u = unit(rng);
        switch (i % 4) {
            case 0: out.push_back({box.min.x + (unit(rng) * 1.4 - 0.2) * size, box.min.y + (unit(rng) * 1.4 - 0.2) * size}); break;
            case 1: {
                const grape::PathFrame f = grape::frame(p, u);
                out.push_back(f.point + f.normal * (size * std::pow(10.0, -6.0 * unit(rng)) * (unit(rng) < 0.5 ? -0.1 : 0.1)));
                break;
            }
            case 2: out.push_back(p.point(u)); break;
            default: {
                const double a = 2.0 * pi * unit(rng);
                out.push_back(center + Vec2{std::cos(a), std::sin(a)} * (size * (2.0 + 20.0 * unit(rng))));
            }
        }
    }
    return out;
}

TEST(ClosestPoint, GlobalOnEveryKindAgainstDenseSampling) {
    std::mt19937_64 rng(grape::testing::test_seed(14));
    int checked = 0;
    for (const auto& [name, path] : query_paths()) {
        SCOPED_TRACE(name);
        const double tol = tolerance(path);
        for (const Vec2 q : query_points(path, rng, 240)) {
            const ClosestPoint c = grape::closest_point(path, q);
            expect_consistent(path, q, c);
            const ClosestPoint ref = brute_force(path, q);
            // Ours is a point of the path, so it cannot beat the true minimum; the reference is
            // one too, so ours may not lose to it by more than the contract.
            EXPECT_LE(c.distance, ref.distance + tol) << "q = (" << q.x << ", " << q.y << ") ours u = " << c.u
                                                      << ", reference u = " << ref.u;
            ++checked;
        }
    }
    EXPECT_GT(checked, 8000);
}

TEST(ClosestPoint, PointsOnThePathAreFoundAtDistanceZero) {
    std::mt19937_64 rng(grape::testing::test_seed(3));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& [name, path] : query_paths()) {
        SCOPED_TRACE(name);
        for (int i = 0; i < 50; ++i) {
            const Vec2 q = path.point(unit(rng));
            // 1e-12 of the size: q is a path point, so only rounding separates them.
            EXPECT_LE(grape::closest_point(path, q).distance, tolerance(path));
        }
    }
}

TEST(ClosestPoint, ArcCenterTiesGoToTheStart) {
    const grape::CirclePath circle({300, 80}, 50, 0, 1.5 * pi);
    const ClosestPoint c = grape::closest_point(circle, {300, 80});
    EXPECT_EQ(c.u, 0.0);
    EXPECT_DOUBLE_EQ(c.distance, 50.0);
    // The same inside a complex path of concentric arcs (the seed's circles share no center;
    // two half circles here do): the first part's start.
    const grape::ComplexPath halves({grape::CirclePath({0, 0}, 10, 0, pi), grape::CirclePath({0, 0}, 10, pi, 2 * pi)},
                                    {0, 0.5});
    const ClosestPoint h = grape::closest_point(halves, {0, 0});
    EXPECT_EQ(h.u, 0.0);
    EXPECT_DOUBLE_EQ(h.distance, 10.0);
    // Two points tie (the ends of an ellipse's minor axis seen from its center): smaller u wins.
    const grape::EllipticalArcPath ellipse({0, 0}, 20, 10, 0, 0, 2 * pi);
    const ClosestPoint e = grape::closest_point(ellipse, {0, 0});
    EXPECT_NEAR(e.u, 0.25, 1e-9);
    EXPECT_NEAR(e.distance, 10.0, 1e-12 * 40);
}

TEST(ClosestPoint, ArcCentersAndNearCentersAgainstClosedForm) {
    // The nearest point of a full circle to q is center + r·(q − c)/|q − c|, at distance |r − |q − c||.
    const Vec2 c{5, -3};
    const double r = 2;
    const grape::CirclePath circle(c, r, 0, -5 * pi);
    std::mt19937_64 rng(grape::testing::test_seed(5));
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 500; ++i) {
        const Vec2 q = c + Vec2{unit(rng), unit(rng)} * std::pow(10.0, -8.0 * std::abs(unit(rng)));
        const ClosestPoint p = grape::closest_point(circle, q);
        EXPECT_NEAR(p.distance, r - grape::distance(q, c), 1e-12 * 4);
    }
}

TEST(ClosestPoint, AtCuspsAndInsideLoops) {
    const grape::CubicBezierPath cusp({0, 0}, {100, 100}, {0, 100}, {100, 0});
    const Vec2 tip = cusp.point(0.5);  // the cusp (speed 0 at t = ½)
    EXPECT_LE(grape::closest_point(cusp, tip).distance, 1e-12 * 100);
    const Path loops = grape::parse_svg_path(svg_loops);
    std::mt19937_64 rng(grape::testing::test_seed(9));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    // Inside the loop of the first cubic (its crossing is near (150, 180)) and inside the arc.
    for (int i = 0; i < 400; ++i) {
        const Vec2 q = i % 2 ? Vec2{120 + 60 * unit(rng), 110 + 60 * unit(rng)}
                             : Vec2{320 + 40 * unit(rng), 230 + 40 * unit(rng)};
        const ClosestPoint c = grape::closest_point(loops, q);
        expect_consistent(loops, q, c);
        EXPECT_LE(c.distance, brute_force(loops, q, 0.0, 1.0, 20000).distance + tolerance(loops));
    }
}

TEST(ClosestPoint, SubpathsThatDoNotMeetEndJustBeforeTheNextCue) {
    // "M0 0 H10 M20 0 H30": from (12, 5) the nearest point is the end of the first segment
    // (10, 0), reached just before the cue ½ (the path jumps to (20, 0) there).
    const grape::ComplexPath path = grape::parse_svg_path("M0 0 H10 M20 0 H30");
    const ClosestPoint c = grape::closest_point(path, {12, 5});
    EXPECT_LT(c.u, 0.5);
    EXPECT_NEAR(c.point.x, 10.0, 1e-12 * 30);
    EXPECT_NEAR(c.distance, std::hypot(2.0, 5.0), 1e-12 * 30);
}

TEST(ClosestPoint, ExtremeScales) {
    // Coordinates near 1e200 (squares overflow: the search falls back to hypot) and near 1e-200
    // (squares underflow), against the same independent reference.
    std::mt19937_64 rng(grape::testing::test_seed(12));
    for (const double scale : {1e200, 1e-200}) {
        const grape::CubicBezierPath bez(Vec2{0, 0} * scale, Vec2{300, 200} * scale, Vec2{-100, 200} * scale,
                                         Vec2{200, 0} * scale);
        const grape::ComplexPath both({bez, grape::CirclePath(Vec2{100, 50} * scale, 40 * scale, 0, 4)}, {0, 0.5});
        for (const Path& path : {Path(bez), Path(both)}) {
            for (const Vec2 q : query_points(path, rng, 40)) {
                const ClosestPoint c = grape::closest_point(path, q);
                expect_consistent(path, q, c);
                EXPECT_LE(c.distance, brute_force(path, q).distance + tolerance(path));
            }
        }
    }
}

TEST(ClosestPoint, WithinARange) {
    std::mt19937_64 rng(grape::testing::test_seed(21));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& [name, path] : query_paths()) {
        SCOPED_TRACE(name);
        for (const Vec2 q : query_points(path, rng, 24)) {
            double u0 = unit(rng), u1 = unit(rng);
            if (u0 > u1) std::swap(u0, u1);
            const ClosestPoint c = grape::closest_point(path, q, u0, u1);
            expect_consistent(path, q, c);
            EXPECT_GE(c.u, u0);
            EXPECT_LE(c.u, u1);
            EXPECT_LE(c.distance, brute_force(path, q, u0, u1).distance + tolerance(path));
        }
    }
    const Path line = grape::LinearPath({0, 0}, {10, 0});
    const ClosestPoint one = grape::closest_point(line, {3, 1}, 0.5, 0.5);
    EXPECT_EQ(one.u, 0.5);
    grape::testing::expect_error([&] { (void)grape::closest_point(line, {0, 0}, 0.6, 0.5); },
                                 {"closest_point", "0 ≤ u0 ≤ u1 ≤ 1", "u0 = 0.6", "u1 = 0.5"});
    grape::testing::expect_error([&] { (void)grape::closest_point(line, {0, 0}, -0.1, 0.5); }, {"u0 = -0.1"});
    grape::testing::expect_error([&] { (void)grape::closest_point(line, {0, 0}, 0, std::nan("")); }, {"u1 = nan"});
}

TEST(ClosestPoint, FromTheLastAnswerGivesTheSameAnswer) {
    // A point dragged along a wavy line: each query starts from the last answer.
    std::mt19937_64 rng(grape::testing::test_seed(8));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& [name, path] : query_paths()) {
        SCOPED_TRACE(name);
        const grape::Bounds box = path.bounds();
        const double size = extent(path);
        double last = 0.0;
        for (int i = 0; i < 100; ++i) {
            const double t = i / 99.0;
            const Vec2 q = box.min + (box.max - box.min) * t + Vec2{0.1 * size * std::sin(9 * t), 0.05 * size};
            const ClosestPoint warm = grape::closest_point_from(path, q, last);
            const ClosestPoint cold = grape::closest_point(path, q);
            expect_consistent(path, q, warm);
            EXPECT_NEAR(warm.distance, cold.distance, tolerance(path));
            last = warm.u;
        }
        // A hint that is no help (far off, outside [0, 1], NaN) still gives the global answer.
        const Vec2 q = box.min + (box.max - box.min) * unit(rng);
        for (const double hint : {1.0 - unit(rng), -3.0, 7.0, std::nan("")}) {
            EXPECT_NEAR(grape::closest_point_from(path, q, hint).distance, grape::closest_point(path, q).distance,
                        tolerance(path));
        }
    }
}

TEST(ClosestPoint, NonFiniteQueryAndAllocationFree) {
    const Path path = grape::scenes::seed_nested_complex();
    const ClosestPoint c = grape::closest_point(path, {std::nan(""), 0});
    EXPECT_EQ(c.u, 0.0);
    EXPECT_EQ(c.distance, std::numeric_limits<double>::infinity());
    EXPECT_EQ(grape::closest_point(path, {std::numeric_limits<double>::infinity(), 0}).u, 0.0);
    const Path svg = grape::parse_svg_path(svg_loops).reparametrized();
    const long before = g_allocations.load();
    double sum = 0.0;
    for (int i = 0; i < 100; ++i) {
        sum += grape::closest_point(path, {i * 5.0, 300.0 - i}).distance;
        sum += grape::closest_point_from(svg, {i * 5.0, 300.0 - i}, 0.5).distance;
        sum += grape::frame(svg, i / 99.0).curvature;
    }
    EXPECT_EQ(g_allocations.load(), before);
    EXPECT_TRUE(std::isfinite(sum));
}

// --- curvature and frames --------------------------------------------------------------------

TEST(Frame, CircleCurvatureIsOneOverRadiusSignedByDirection) {
    for (const double r : {0.5, 50.0, 3e4}) {
        const grape::CirclePath ccw({1, 2}, r, 0.3, 2.0);
        const grape::CirclePath cw({1, 2}, r, 2.0, -4.0);
        for (double u = 0; u <= 1.0; u += 0.125) {
            // ~40 ulps of 1/r: cos and sin round in x′ and x″, and cross/|x′|³ compounds them.
            EXPECT_NEAR(grape::curvature(ccw, u), 1.0 / r, 1e-14 / r);
            EXPECT_NEAR(grape::curvature(cw, u), -1.0 / r, 1e-14 / r);
            const grape::PathFrame f = grape::frame(ccw, u);
            // The normal of an increasing-angle circle points to its center.
            const Vec2 inward = grape::normalized(Vec2{1, 2} - f.point);
            EXPECT_NEAR(f.normal.x, inward.x, 1e-12);
            EXPECT_NEAR(f.normal.y, inward.y, 1e-12);
        }
    }
}

TEST(Frame, SpiralAndParabolaAgainstClosedForms) {
    // Polar curve r(θ) with r′ = dr/dθ = ρ/s constant: κ = (r² + 2r′²)/(r² + r′²)^{3/2}.
    const grape::SpiralPath spiral({100, 100}, 200, 0, 0, 2 * pi);
    const double rp = -200 / (2 * pi);
    for (double u = 0; u < 1.0; u += 0.0625) {
        const double r = 200 * (1 - u);
        const double expected = (r * r + 2 * rp * rp) / std::pow(r * r + rp * rp, 1.5);
        EXPECT_NEAR(grape::curvature(spiral, u), expected, 1e-13 * expected);
    }
    // The seed's parabola x² + 100y = 0 as a quadratic Bézier, x increasing: κ = y″/(1 + y′²)^{3/2}
    // with y′ = −x/50, y″ = −1/50.
    const grape::QuadraticBezierPath wire({-200, -400}, {0, 400}, {200, -400});
    for (double u = 0; u <= 1.0; u += 0.0625) {
        const double x = wire.point(u).x;
        const double expected = (-1.0 / 50) / std::pow(1 + x * x / 2500, 1.5);
        EXPECT_NEAR(grape::curvature(wire, u), expected, 1e-14 / 50);
    }
}

TEST(Frame, ConsistentWithHeadingOnEveryKind) {
    // d(heading)/du = κ·|x′| (the turning of the tangent per unit length is κ); checked by a
    // central difference of heading on smooth stretches, where the O(h²) error stays below
    // 1e-5 of the turning rate scale for h = 1e-5 of a piece.
    for (const auto& [name, path] : query_paths()) {
        SCOPED_TRACE(name);
        const auto& br = grape::detail::smooth_breaks(path);
        for (std::size_t i = 0; i + 1 < br.size(); ++i) {
            const double a = br[i], b = br[i + 1];
            const double h = 1e-5 * (b - a);
            for (int k = 1; k < 8; ++k) {
                const double u = a + (b - a) * k / 8.0;
                const grape::PathFrame f = grape::frame(path, u);
                const Vec2 d1 = path.d1(u);
                const double speed = grape::length(d1);
                if (speed < 1e-6 * extent(path)) continue;  // near a stop heading turns abruptly
                EXPECT_NEAR(grape::length(f.tangent), 1.0, 1e-15 * 4);
                EXPECT_NEAR(grape::dot(f.tangent, f.normal), 0.0, 1e-15);
                EXPECT_NEAR(std::atan2(f.tangent.y, f.tangent.x), path.heading(u), 1e-14);
                double turn = path.heading(u + h) - path.heading(u - h);
                turn = std::remainder(turn, 2 * pi);
                const double rate = f.curvature * speed;
                EXPECT_NEAR(turn / (2 * h), rate, 1e-5 * (std::abs(rate) + speed / extent(path)));
            }
        }
    }
}

TEST(Frame, StandingStillLeavesAlongTheSecondDerivative) {
    // A cosine spline stops at every point; it leaves (100, 100) towards (120, 50).
    const grape::CosineSplinePath spline({20, 20, 100, 100, 120, 50});
    const grape::PathFrame f = grape::frame(spline, 0.5);
    const Vec2 expected = grape::normalized(Vec2{20, -50});
    EXPECT_NEAR(f.tangent.x, expected.x, 1e-15);
    EXPECT_NEAR(f.tangent.y, expected.y, 1e-15);
    EXPECT_EQ(f.curvature, 0.0);
    // The cusp of a Bézier: tangent along x″ there, no NaN.
    const grape::CubicBezierPath cusp({0, 0}, {100, 100}, {0, 100}, {100, 0});
    const grape::PathFrame c = grape::frame(cusp, 0.5);
    EXPECT_TRUE(grape::is_finite(c.tangent));
    EXPECT_NEAR(grape::length(c.tangent), 1.0, 1e-15);
}

// --- slices, offsets, SVG data ---------------------------------------------------------------

// Whether slicing [u0, u1] of p meets a sine wave or cosine spline (which have no exact slice).
bool meets_unsliceable(const Path& p, double u0, double u1) {
    switch (p.kind()) {
        case grape::PathKind::sine_wave:
        case grape::PathKind::cosine_spline: return true;
        case grape::PathKind::reparametrized: {
            const auto r = grape::path_cast<grape::ReparametrizedSpec>(p);
            return meets_unsliceable(r->source, grape::detail::source_parameter(p, u0),
                                     grape::detail::source_parameter(p, u1));
        }
        case grape::PathKind::complex: {
            const grape::ComplexPath c = static_cast<const grape::ComplexPath&>(p);
            const auto parts = c.parts();
            const auto cues = c.cues();
            for (std::size_t i = 0; i < parts.size(); ++i) {
                const double start = cues[i], end = i + 1 < parts.size() ? cues[i + 1] : 1.0;
                if (!(end > start) || u1 <= start || u0 >= end) continue;
                const double lo = std::max(0.0, (u0 - start) / (end - start)), hi = std::min(1.0, (u1 - start) / (end - start));
                if ((lo > 0.0 || hi < 1.0) && meets_unsliceable(parts[i], lo, hi)) return true;
            }
            return false;
        }
        default: return false;
    }
}

bool reparametrized_inside(const Path& p) {
    if (p.kind() == grape::PathKind::reparametrized) return true;
    if (p.kind() != grape::PathKind::complex) return false;
    for (const Path& part : static_cast<const grape::ComplexPath&>(p).parts()) {
        if (reparametrized_inside(part)) return true;
    }
    return false;
}

TEST(Slice, MatchesTheOriginalPointwiseAndRejoins) {
    std::mt19937_64 rng(grape::testing::test_seed(31));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int sliced = 0, refused = 0;
    for (const auto& [name, path] : query_paths()) {
        SCOPED_TRACE(name);
        // 1e-12 of the size (rounding of the blossoms and angle products); through an arc-length
        // table 3e-9 of the length (each table holds s(u) to 1e-9·L).
        const double tol = reparametrized_inside(path) ? 3e-9 * path.length() : tolerance(path);
        for (int trial = 0; trial < 12; ++trial) {
            double u0 = unit(rng), u1 = unit(rng);
            if (trial == 0) u0 = 0.0;
            if (trial == 1) u1 = 1.0;
            if (u0 > u1) std::swap(u0, u1);
            if (!(u1 > u0)) continue;
            if (meets_unsliceable(path, u0, u1)) {
                const Path& whole = path;  // (a lambda may not capture a structured binding in clang 14)
                grape::testing::expect_error([&] { (void)grape::slice(whole, u0, u1); }, {"slice", "no exact slice"});
                ++refused;
                continue;
            }
            const Path part = grape::slice(path, u0, u1);
            for (int k = 0; k <= 64; ++k) {
                const double v = k / 64.0;
                const Vec2 expected = path.point(u0 + v * (u1 - u0));
                EXPECT_LE(grape::distance(part.point(v), expected), tol) << "u0 " << u0 << " u1 " << u1 << " v " << v;
            }
            // Rejoined at u0: the two slices as one complex path are the original.
            if (u0 > 0.0) {
                const grape::ComplexPath joined({grape::slice(path, 0.0, u0), grape::slice(path, u0, 1.0)}, {0.0, u0});
                for (int k = 0; k <= 64; ++k) {
                    const double u = k / 64.0;
                    EXPECT_LE(grape::distance(joined.point(u), path.point(u)), tol) << "u " << u;
                }
                EXPECT_NEAR(joined.length(), path.length(), reparametrized_inside(path) ? tol : 1e-12 * path.length());
            }
            ++sliced;
        }
    }
    EXPECT_GT(sliced, 300);
    EXPECT_GT(refused, 5);
}

TEST(Slice, KeepsTheKindWhereOneExists) {
    const grape::CubicBezierPath bez({0, 0}, {0, 100}, {100, 100}, {100, 0});
    const Path half = grape::slice(bez, 0.0, 0.5);
    EXPECT_EQ(half.kind(), grape::PathKind::cubic_bezier);
    // de Casteljau at ½: (0, 0), (0, 50), (25, 75), (50, 75), exactly.
    const grape::CubicBezierPath& h = static_cast<const grape::CubicBezierPath&>(half);
    EXPECT_EQ(h.control(1), (Vec2{0, 50}));
    EXPECT_EQ(h.control(2), (Vec2{25, 75}));
    EXPECT_EQ(h.control(3), (Vec2{50, 75}));
    const grape::CirclePath circle({0, 0}, 10, 0, pi);
    const Path arc = grape::slice(circle, 0.25, 0.5);
    EXPECT_EQ(arc.kind(), grape::PathKind::circle);
    EXPECT_NEAR(arc.length(), 10 * pi / 4, 1e-14 * 10);
    EXPECT_EQ(grape::slice(grape::SpiralPath({0, 0}, 10, 0), 0.5, 1.0).kind(), grape::PathKind::spiral);
    EXPECT_EQ(grape::slice(grape::PhysicsPath({0, 0}, {1, -10}, {0, 10}, 2), 0.5, 1.0).kind(), grape::PathKind::physics);
    EXPECT_EQ(grape::slice(bez.reparametrized(), 0.2, 0.4).kind(), grape::PathKind::reparametrized);
    // By length: the middle half of a segment.
    const Path mid = grape::slice_by_length(grape::LinearPath({0, 0}, {8, 0}), 2, 6);
    EXPECT_EQ(mid.point(0), (Vec2{2, 0}));
    EXPECT_EQ(mid.point(1), (Vec2{6, 0}));
    grape::testing::expect_error([&] { (void)grape::slice(bez, 0.5, 0.5); }, {"slice", "0 ≤ u0 < u1 ≤ 1", "u0 = 0.5"});
    grape::testing::expect_error([&] { (void)grape::slice(bez, 0.5, 1.5); }, {"u1 = 1.5"});
    grape::testing::expect_error([&] { (void)grape::slice_by_length(bez, 0, 1e6); }, {"slice_by_length", "s1 = 1e+06"});
}

TEST(Slice, OffsetPointsLieAtTheDistanceAlongTheNormal) {
    for (const auto& [name, path] : query_paths()) {
        SCOPED_TRACE(name);
        for (int k = 0; k <= 16; ++k) {
            const double u = k / 16.0;
            const grape::PathFrame f = grape::frame(path, u);
            const Vec2 beside = grape::offset_point(path, u, 7.5);
            // beside = point + 7.5·normal is rounded to the ulp of the coordinates (up to 1000
            // here, ulp 1.1e-13): a few ulps of |point| + 7.5 bound both the distance and the
            // tangential part.
            const double tol = 4.0 * std::numeric_limits<double>::epsilon() * (std::abs(f.point.x) + std::abs(f.point.y) + 7.5);
            EXPECT_NEAR(grape::distance(beside, f.point), 7.5, tol);
            EXPECT_NEAR(grape::dot(beside - f.point, f.tangent), 0.0, tol);
        }
    }
    // Beside a circle turning with increasing angle, the positive side is the inside.
    const grape::CirclePath circle({0, 0}, 10, 0, 2 * pi);
    EXPECT_NEAR(grape::length(grape::offset_point(circle, 0.3, 2)), 8.0, 1e-14 * 10);
}

TEST(SvgData, DrawsTheSameShape) {
    for (const auto& [name, path] : query_paths()) {
        SCOPED_TRACE(name);
        std::string data;
        try {
            data = grape::svg_path_data(path);
        } catch (const grape::Error& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("has no SVG form"), std::string::npos) << what;
            continue;
        }
        const Path back = grape::parse_svg_path(data);
        // Every point of each lies on the other (the parameters differ: SVG cues by length).
        for (int k = 0; k <= 200; ++k) {
            const double u = k / 200.0;
            EXPECT_LE(grape::closest_point(back, path.point(u)).distance, 1e-10 * extent(path)) << data;
            EXPECT_LE(grape::closest_point(path, back.point(u)).distance, 1e-10 * extent(path)) << data;
        }
    }
    EXPECT_EQ(grape::svg_path_data(grape::parse_svg_path("M0 0 H10 M20 0 H30")), "M0 0 L10 0 M20 0 L30 0");
    EXPECT_EQ(grape::svg_path_data(grape::CubicBezierPath({0, 0}, {0, 100}, {100, 100}, {100, 0})), "M0 0 C0 100 100 100 100 0");
    grape::testing::expect_error([] { (void)grape::svg_path_data(grape::SpiralPath({0, 0}, 1, 0)); },
                                 {"svg_path_data", "spiral has no SVG form"});
}

// --- closed loops ------------------------------------------------------------------------------

TEST(Closed, LoopsMeetAtTheSeamWithWrappedTangents) {
    const std::vector<Vec2> pts{{20, 20}, {100, 100}, {120, 50}, {300, 300}, {400, 50}, {500, 200}};
    const std::vector<Vec2> tangents{{50, 0}, {0, 50}, {-20, 30}, {40, 40}, {10, -60}, {-80, 0}};
    // 1e-12 of the size: the seam's point comes from a cubic at t = 1 (rounding of its sum).
    const double tol = 1e-12 * 500;
    for (const grape::CatmullRom type : {grape::CatmullRom::uniform, grape::CatmullRom::centripetal, grape::CatmullRom::chordal}) {
        const Path loop = grape::closed_catmull_rom_spline(pts, type);
        EXPECT_TRUE(grape::closed(loop));
        EXPECT_LE(grape::distance(loop.point(1.0), pts[0]), tol);
        EXPECT_EQ(loop.point(0.0), pts[0]);
        for (std::size_t i = 0; i < pts.size(); ++i) {
            EXPECT_LE(grape::distance(loop.point(static_cast<double>(i) / 6.0), pts[i]), tol);
        }
        // Interior segments are the open spline's (the same neighbours), in the loop's u.
        const grape::CatmullRomSplinePath open(pts, type);
        for (int seg = 1; seg <= 3; ++seg) {
            for (double t = 0; t < 1.0; t += 0.125) {
                EXPECT_LE(grape::distance(loop.point((seg + t) / 6.0), open.point((seg + t) / 5.0)), tol);
            }
        }
        // Smooth in direction at the seam (and uniform: the same derivative).
        const Vec2 in = loop.d1(1.0), out = loop.d1(0.0);
        EXPECT_NEAR(grape::cross(grape::normalized(in), grape::normalized(out)), 0.0, 1e-12);
        EXPECT_GT(grape::dot(in, out), 0.0);
        if (type == grape::CatmullRom::uniform) {
            EXPECT_LE(grape::distance(in, out), 1e-12 * grape::length(out));
            // Wrapped: the seam's tangent is half the chord from the last point to the second.
            const Vec2 expected = 0.5 * (pts[1] - pts[5]) * 6.0;  // d/du = d/dt · segments
            EXPECT_LE(grape::distance(out, expected), 1e-12 * grape::length(expected));
        }
    }
    const Path hermite = grape::closed_hermite_spline(pts, tangents);
    EXPECT_TRUE(grape::closed(hermite));
    EXPECT_LE(grape::distance(hermite.d1(1.0), hermite.d1(0.0)), 1e-12 * grape::length(hermite.d1(0.0)));
    EXPECT_EQ(hermite.d1(0.0), tangents[0] * 6.0);
    const Path cosine = grape::closed_cosine_spline(pts);
    EXPECT_TRUE(grape::closed(cosine));
    EXPECT_EQ(cosine.point(1.0), pts[0]);
    EXPECT_FALSE(grape::closed(grape::CatmullRomSplinePath(pts)));
    EXPECT_TRUE(grape::closed(grape::CirclePath({0, 0}, 5, 1, 1 + 2 * pi)));
    EXPECT_FALSE(grape::closed(grape::CirclePath({0, 0}, 5, 1, 1 + 1.9 * pi)));
    EXPECT_TRUE(grape::closed(grape::parse_svg_path("M0 0 H10 V10 Z")));
    grape::testing::expect_error([&] { (void)grape::closed_cosine_spline(std::span<const Vec2>(pts).first(2)); },
                                 {"closed_cosine_spline", "at least 3 points", "got 2"});
    grape::testing::expect_error([&] { (void)grape::closed_hermite_spline(pts, std::span<const Vec2>(tangents).first(5)); },
                                 {"closed_hermite_spline", "one tangent per point", "got 5 tangents for 6 points"});
}

// --- fitting ------------------------------------------------------------------------------------

// The largest distance of any input point from the fitted path, measured with closest_point.
double deviation(const Path& fit, const std::vector<Vec2>& pts) {
    double worst = 0.0;
    for (const Vec2 p : pts) worst = std::max(worst, grape::closest_point(fit, p).distance);
    return worst;
}

TEST(Fit, NoisyCircleWithinToleranceWithFewSegments) {
    // One fixed noise draw, whatever GRAPE_TEST_SEED says: the segment counts below are this
    // draw's (over 300 draws a tolerance of 1 takes 4 to 11 segments, of 0.5 7 to 22).
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> noise(-0.2, 0.2);
    std::vector<Vec2> pts;
    for (int i = 0; i <= 400; ++i) {
        const double a = 2 * pi * i / 400.0;
        pts.push_back(Vec2{300, 300} + Vec2{std::cos(a), std::sin(a)} * 100.0 + Vec2{noise(rng), noise(rng)});
    }
    for (const double tol : {0.5, 1.0, 3.0}) {
        SCOPED_TRACE(tol);
        const grape::ComplexPath fit = grape::fit_path(pts, {.tolerance = tol});
        EXPECT_LE(deviation(fit, pts), tol);
        // Few: a cubic holds about a third of a circle within 0.2% of r, so a tolerance well
        // above the noise (±0.28 at most) needs a handful; at 0.5 the noise eats half of it.
        EXPECT_LE(fit.parts().size(), tol >= 1.0 ? 8u : 24u);
        // On the input's end points: the first and last control points are those points
        // exactly. (point(1) evaluates the power basis, which may land an ulp from the last
        // control point: EXPECT_EQ on it held for one noise draw and not for others.)
        EXPECT_EQ(fit.point(0), pts.front());
        EXPECT_EQ(std::get<grape::CubicBezierSpec>(grape::describe(fit.parts().front())).control[0], pts.front());
        EXPECT_EQ(std::get<grape::CubicBezierSpec>(grape::describe(fit.parts().back())).control[3], pts.back());
        // Joined smoothly: each part leaves in the direction the previous one arrived.
        for (std::size_t i = 1; i < fit.parts().size(); ++i) {
            const Vec2 in = grape::normalized(fit.parts()[i - 1].d1(1.0)), out = grape::normalized(fit.parts()[i].d1(0.0));
            EXPECT_NEAR(grape::cross(in, out), 0.0, 1e-12);
            EXPECT_GT(grape::dot(in, out), 0.0);
        }
    }
    // A looser tolerance never needs more segments here (four quarter arcs fit within 0.03 r).
    EXPECT_LE(grape::fit_path(pts, {.tolerance = 3.0}).parts().size(), grape::fit_path(pts, {.tolerance = 0.5}).parts().size());
}

TEST(Fit, CornersAreKept) {
    // A square drawn by hand: 50 points per side, the corners sharp (90° turns).
    std::vector<Vec2> pts;
    const Vec2 corners[5] = {{0, 0}, {200, 0}, {200, 200}, {0, 200}, {0, 0}};
    for (int side = 0; side < 4; ++side) {
        for (int k = 0; k < 50; ++k) pts.push_back(lerp(corners[side], corners[side + 1], k / 50.0));
    }
    pts.push_back(corners[4]);
    const grape::ComplexPath fit = grape::fit_path(pts, {.tolerance = 0.5});
    EXPECT_LE(deviation(fit, pts), 0.5);
    EXPECT_EQ(fit.parts().size(), 4u);
    for (std::size_t i = 0; i < fit.parts().size(); ++i) EXPECT_EQ(fit.parts()[i].point(0), corners[i]);
    // With the corner angle above 90° the turns are smoothed instead (more segments, still within).
    const grape::ComplexPath smooth = grape::fit_path(pts, {.tolerance = 0.5, .corner_angle = 0.6 * pi});
    EXPECT_LE(deviation(smooth, pts), 0.5);
    EXPECT_GT(smooth.parts().size(), 4u);
}

TEST(Fit, RandomTrajectoriesWithinEveryTolerance) {
    std::mt19937_64 rng(grape::testing::test_seed(77));
    std::uniform_real_distribution<double> coord(0.0, 600.0);
    for (int trial = 0; trial < 12; ++trial) {
        std::vector<Vec2> knots;
        for (int k = 0; k < 6; ++k) knots.push_back({coord(rng), coord(rng)});
        const grape::CatmullRomSplinePath truth(knots, grape::CatmullRom::centripetal);
        std::vector<Vec2> pts;
        for (int i = 0; i <= 300; ++i) pts.push_back(truth.point(i / 300.0));
        for (const double tol : {0.05, 0.5, 4.0}) {
            const grape::ComplexPath fit = grape::fit_path(pts, {.tolerance = tol, .corner_angle = pi});
            EXPECT_LE(deviation(fit, pts), tol) << "trial " << trial << " tolerance " << tol;
            EXPECT_LT(fit.parts().size(), 120u);
        }
    }
}

TEST(Fit, BadInput) {
    const std::vector<Vec2> same{{1, 1}, {1, 1}, {1, 1}};
    grape::testing::expect_error([&] { (void)grape::fit_path(same); }, {"fit_path", "at least 2 distinct points", "got 1"});
    const std::vector<Vec2> two{{0, 0}, {3, 4}};
    grape::testing::expect_error([&] { (void)grape::fit_path(two, {.tolerance = 0}); }, {"fit_path", "tolerance must be positive", "got 0"});
    grape::testing::expect_error([&] { (void)grape::fit_path(two, {.corner_angle = 4}); }, {"corner_angle must lie in (0, π]"});
    const std::vector<Vec2> bad{{0, 0}, {std::nan(""), 4}};
    grape::testing::expect_error([&] { (void)grape::fit_path(bad); }, {"points[1] must be finite"});
    const grape::ComplexPath line = grape::fit_path(two);
    EXPECT_EQ(line.parts().size(), 1u);
    EXPECT_NEAR(line.length(), 5.0, 1e-12 * 5);
}

}  // namespace
