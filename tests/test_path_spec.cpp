// path specs: describe() reads any path's kind and parameters whatever its static type,
// from_spec() rebuilds it bit for bit, and path_cast reads one kind.
#include <grape/error.hpp>
#include <grape/path.hpp>

#include "seed_paths.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace {

using grape::Path;
using grape::PathKind;
using grape::Vec2;

// Every kind (the gallery has one of each), the seed's paths (nested complex ones included),
// SVG-imported paths, Béziers built by arc length, and the reparametrization of each.
std::vector<grape::NamedPath> every_path() {
    std::vector<grape::NamedPath> paths = grape::scenes::path_gallery();
    for (auto& p : grape::scenes::seed_paths()) paths.push_back(p);
    paths.push_back({"svg_mixed", grape::parse_svg_path("M10 10 L50 10 Q80 40 50 70 C20 100 0 60 10 40 "
                                                        "A30 20 30 0 1 60 90 H5 V5 Z M100 100 l20 0")});
    paths.push_back({"svg_arcs", grape::parse_svg_path("M0 0 a50 50 0 1 0 100 0 a25 40 -20 0 1 -50 0")});
    paths.push_back({"quadratic_by_length", grape::QuadraticBezierPath({0, 0}, {50, 100}, {100, 0}, true)});
    paths.push_back({"cubic_by_length", grape::CubicBezierPath({0, 0}, {0, 100}, {100, 100}, {100, 0}, true)});
    paths.push_back({"nested_twice", grape::ComplexPath({grape::scenes::seed_nested_complex(),
                                                         grape::LinearPath({0, 0}, {10, 10})},
                                                        {0.0, 0.9})});
    paths.push_back({"default", Path()});
    const std::size_t plain = paths.size();
    for (std::size_t i = 0; i < plain; ++i) paths.push_back({paths[i].name + "_reparametrized", paths[i].path.reparametrized()});
    return paths;
}

// u inside [0, 1] (ends and fixed-seed random values) and outside (the end-tangent extension).
std::vector<double> many_u() {
    std::vector<double> u{0.0, 1.0, -0.5, 1.5, 0.25, 0.5, 0.75, std::nextafter(1.0, 0.0)};
    std::mt19937_64 rng(grape::testing::test_seed(17));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 200; ++i) u.push_back(unit(rng));
    return u;
}

TEST(PathSpec, RoundTripIsBitIdenticalForEveryKind) {
    std::vector<bool> seen(static_cast<std::size_t>(PathKind::reparametrized) + 1, false);
    for (const auto& [name, path] : every_path()) {
        const grape::PathSpec spec = grape::describe(path);
        EXPECT_EQ(grape::kind_of(spec), path.kind()) << name;
        seen[static_cast<std::size_t>(path.kind())] = true;
        const Path back = grape::from_spec(spec);
        EXPECT_EQ(back.kind(), path.kind()) << name;
        EXPECT_EQ(back.length(), path.length()) << name;
        for (const double u : many_u()) {
            // Bit for bit: the rebuilt path runs the same constructor on the same numbers.
            EXPECT_EQ(back.point(u), path.point(u)) << name << " u = " << u;
            EXPECT_EQ(back.d1(u), path.d1(u)) << name << " u = " << u;
            EXPECT_EQ(back.d2(u), path.d2(u)) << name << " u = " << u;
        }
    }
    for (std::size_t k = 0; k < seen.size(); ++k) EXPECT_TRUE(seen[k]) << to_string(static_cast<PathKind>(k));
}

TEST(PathSpec, DescribeGivesTheConstructorsArguments) {
    const auto circle = grape::path_cast<grape::CircleSpec>(grape::CirclePath({1, 2}, 3, 0.5, 4));
    ASSERT_TRUE(circle);
    EXPECT_EQ(circle->center, (Vec2{1, 2}));
    EXPECT_EQ(circle->radius, 3.0);
    EXPECT_EQ(circle->start_angle, 0.5);
    EXPECT_EQ(circle->end_angle, 4.0);

    // A Bézier stored as a Path still gives its control points (no derivative arithmetic).
    const Path bezier = grape::CubicBezierPath({0.1, 0.2}, {1.3, 5.7}, {2.9, -3.3}, {4.1, 0.7});
    const auto cubic = grape::path_cast<grape::CubicBezierSpec>(bezier);
    ASSERT_TRUE(cubic);
    EXPECT_EQ(cubic->control[1], (Vec2{1.3, 5.7}));
    EXPECT_EQ(cubic->control[2], (Vec2{2.9, -3.3}));
    EXPECT_FALSE(grape::path_cast<grape::QuadraticBezierSpec>(bezier));

    // By arc length: a reparametrized path around the plain Bézier.
    const Path by_length = grape::CubicBezierPath({0, 0}, {1, 5}, {3, -3}, {4, 0}, true);
    const auto r = grape::path_cast<grape::ReparametrizedSpec>(by_length);
    ASSERT_TRUE(r);
    EXPECT_EQ(grape::path_cast<grape::CubicBezierSpec>(r->source)->control[3], (Vec2{4, 0}));

    const grape::CatmullRomSplinePath spline({0, 0, 10, 5, 20, 0}, grape::CatmullRom::chordal);
    const auto cr = grape::path_cast<grape::CatmullRomSplineSpec>(spline);
    ASSERT_TRUE(cr);
    EXPECT_EQ(cr->type, grape::CatmullRom::chordal);
    ASSERT_EQ(cr->points.size(), 3u);
    EXPECT_EQ(cr->points[1], (Vec2{10, 5}));

    const auto physics = grape::path_cast<grape::PhysicsSpec>(grape::PhysicsPath({1, 2}, {3, 4}, {0, 9.8}, 2.5));
    ASSERT_TRUE(physics);
    EXPECT_EQ(physics->velocity, (Vec2{3, 4}));
    EXPECT_EQ(physics->seconds, 2.5);

    // Parts are shared, not copied: the same shape objects come back.
    const grape::ComplexPath complex = grape::scenes::seed_complex();
    const auto parts = grape::path_cast<grape::ComplexSpec>(Path(complex));
    ASSERT_TRUE(parts);
    ASSERT_EQ(parts->parts.size(), complex.parts().size());
    for (std::size_t i = 0; i < parts->parts.size(); ++i) EXPECT_TRUE(parts->parts[i] == complex.parts()[i]);
    EXPECT_EQ(parts->cues, std::vector<double>(complex.cues().begin(), complex.cues().end()));
}

TEST(PathSpec, FromSpecValidatesLikeTheConstructors) {
    try {
        (void)grape::from_spec(grape::CircleSpec{.center = {0, 0}, .radius = -1});
        ADD_FAILURE() << "a negative radius was accepted";
    } catch (const grape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("radius"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)grape::from_spec(grape::LinearSplineSpec{{{0, 0}}}), grape::Error);  // one point
    EXPECT_THROW((void)grape::from_spec(grape::ComplexSpec{}), grape::Error);               // no parts
}

}  // namespace
