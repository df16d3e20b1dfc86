// Beads: a particle held on a curve or a grape::Path, checked against the seed's parametric
// bead, energy conservation and the same motion on the same path whatever its parametrization.
#include <grape/dynamics.hpp>

#include "seed_dynamics.hpp"
#include "seed_paths.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using namespace grape;
using namespace grape::scenes;

// ---------------------------------------------------------------------------------------
// Beads on user curves
// ---------------------------------------------------------------------------------------

TEST(Bead, StartsWithTheRequestedSpeedAndConservesEnergy) {
    Bead bead(ParametricFunction(seed_parabola_frame), {.u = -120, .speed = 300, .gravity = {0, 500}, .integrator = Integrator::rk45});
    EXPECT_NEAR(bead.speed(), 300, 1e-12);
    EXPECT_NEAR(length(bead.velocity()), 300, 1e-12);
    const double e0 = bead.energy();
    for (int i = 0; i < 600; ++i) bead.step(1.0 / 60);
    EXPECT_NEAR(bead.energy(), e0, 1e-8 * std::abs(e0));
    EXPECT_NEAR(bead.position().y, -bead.position().x * bead.position().x / 100, 1e-12 * 400);
}

// ---------------------------------------------------------------------------------------
// Beads on grape::Path values
// ---------------------------------------------------------------------------------------

// The seed's parabola over x in [−200, 200] as a quadratic Bézier: x(u) = −200 + 400u is
// linear in u, so the bead ODE in u is an exact linear image of the one in q.
QuadraticBezierPath parabola_bezier(bool reparametrize = false) {
    return QuadraticBezierPath({-200, -400}, {0, 400}, {200, -400}, reparametrize);
}

TEST(BeadOnPath, BezierParabolaReproducesTheSeedsParametricBead) {
    const auto bezier = parabola_bezier();
    for (double q : {-150.0, 0.0, 75.0}) {  // the path is the parabola
        const Vec2 p = bezier.point((q + 200) / 400);
        EXPECT_NEAR(p.x, q, 1e-12);
        EXPECT_NEAR(p.y, -q * q / 100, 1e-11);
    }
    Bead on_path(bezier, {.u = 0.75, .gravity = {0, 500}});
    ParabolaRun seed({.method = ParabolaMethod::parametric});
    double worst = 0.0;
    for (int i = 0; i < 600; ++i) {
        on_path.step(1.0 / 60);
        seed.step(1.0 / 60);
        worst = std::max(worst, distance(on_path.position(), seed.state().x));
    }
    // Same ODE up to the linear change u = (q + 200)/400: only round-off separates them.
    EXPECT_LT(worst, 1e-9);
    EXPECT_EQ(on_path.crossings(), 0);
}

TEST(BeadOnPath, ArcLengthReparametrizedPathGivesTheSameMotion) {
    // The physics does not depend on the parametrization: on the arc-length reparametrized
    // Bézier the bead follows the same x(t). RK45 at 1e-12 makes the integration error small
    // next to the reparametrization's own accuracy (1e-9 of the length, ~1e-6 px).
    Bead plain(parabola_bezier(), {.u = 0.75, .gravity = {0, 500}, .integrator = Integrator::rk45, .rk45 = {.tolerance = 1e-12}});
    const QuadraticBezierPath arc = parabola_bezier(true);
    const double start = parabola_bezier().length_at(0.75) / parabola_bezier().length();
    Bead by_length(arc, {.u = start, .gravity = {0, 500}, .integrator = Integrator::rk45, .rk45 = {.tolerance = 1e-12}});
    EXPECT_LT(distance(plain.position(), by_length.position()), 1e-6);
    double worst = 0.0;
    for (int i = 0; i < 180; ++i) {
        plain.step(1.0 / 60);
        by_length.step(1.0 / 60);
        worst = std::max(worst, distance(plain.position(), by_length.position()));
    }
    EXPECT_LT(worst, 1e-5);
}

TEST(BeadOnPath, ComplexPathJoinsKeepTheSpeedAlongThePath) {
    // Two segments (100 px then 300 px) with cues giving each half of u: the parameter speed
    // changes ×3 at the join, the speed along the path must not. No forces: the bead moves at
    // exactly 50 px/s, so at t = 3 s it is 150 px along, 50 px into the second segment.
    const ComplexPath track({LinearPath({0, 0}, {100, 0}), LinearPath({100, 0}, {100, 300})}, {0.0, 0.5});
    Bead bead(track, {.u = 0.0, .speed = 50});
    for (int i = 0; i < 180; ++i) bead.step(1.0 / 60);
    EXPECT_NEAR(bead.speed(), 50, 1e-12);
    EXPECT_NEAR(bead.position().x, 100, 1e-9);
    EXPECT_NEAR(bead.position().y, 50, 1e-9);
    EXPECT_NEAR(bead.u(), 0.5 + 0.5 * 50.0 / 300.0, 1e-12);
    EXPECT_NEAR(bead.u_rate(), 0.5 * 50.0 / 300.0, 1e-15);  // the second half of u spans 300 px
    EXPECT_EQ(bead.crossings(), 1);
    // And back: a negative speed crosses the join the other way.
    Bead back(track, {.u = 0.5 + 0.5 * 30.0 / 300.0, .speed = -60});
    for (int i = 0; i < 60; ++i) back.step(1.0 / 60);  // 60 px: 30 on the second part, 30 on the first
    EXPECT_NEAR(back.position().x, 70, 1e-9);
    EXPECT_NEAR(back.position().y, 0, 1e-9);
    EXPECT_NEAR(back.speed(), -60, 1e-12);
}

TEST(BeadOnPath, EnergyIsConservedAcrossCurvedJoins) {
    // A bowl made of a quarter circle, a flat segment and another quarter circle (by length):
    // with gravity only, energy is conserved through every join.
    const ComplexPath bowl = ComplexPath::by_length({CirclePath({100, 0}, 100, pi, pi / 2),
                                                     LinearPath({100, 100}, {200, 100}),
                                                     CirclePath({200, 0}, 100, pi / 2, 0)});
    Bead bead(bowl, {.u = 0.02, .gravity = {0, 500}, .integrator = Integrator::rk45, .rk45 = {.tolerance = 1e-12}});
    const double e0 = bead.energy();
    double worst = 0.0;
    for (int i = 0; i < 600; ++i) {
        bead.step(1.0 / 60);
        worst = std::max(worst, std::abs(bead.energy() - e0));
    }
    EXPECT_GE(bead.crossings(), 8);  // it swings through both joins several times
    // Each crossing lands on the join by a cubic Hermite root (error ~dt⁴ in position,
    // ~1e-9 px at these speeds), plus RK45 at 1e-12: 1e-7 of the energy over 10 s.
    EXPECT_LT(worst, 1e-7 * std::abs(e0));
}

TEST(BeadOnPath, OpenEndsStopOrBounce) {
    const LinearPath rail({0, 0}, {100, 0});
    Bead stop(rail, {.u = 0.5, .speed = 50, .ends = BeadEnd::stop});
    Bead bounce(rail, {.u = 0.5, .speed = 50, .ends = BeadEnd::bounce});
    Bead soft(rail, {.u = 0.5, .speed = 50, .ends = BeadEnd::bounce, .restitution = 0.5});
    for (int i = 0; i < 120; ++i) {  // 2 s: the end is reached after 1 s
        stop.step(1.0 / 60);
        bounce.step(1.0 / 60);
        soft.step(1.0 / 60);
    }
    EXPECT_EQ(stop.u(), 1.0);
    EXPECT_EQ(stop.speed(), 0.0);
    EXPECT_NEAR(bounce.position().x, 50, 1e-9);
    EXPECT_NEAR(bounce.speed(), -50, 1e-12);
    EXPECT_NEAR(soft.position().x, 75, 1e-9);
    EXPECT_NEAR(soft.speed(), -25, 1e-12);
    // Gravity pulling past the end: the stopped bead rests there.
    Bead hanging(LinearPath({0, 0}, {0, 100}), {.u = 0.9, .gravity = {0, 500}});
    for (int i = 0; i < 60; ++i) hanging.step(1.0 / 60);
    EXPECT_EQ(hanging.position(), (Vec2{0, 100}));
}

TEST(BeadOnPath, ReparametrizedPolylineCarriesTheSpeedThroughCorners) {
    // A polyline's own parameter speed jumps ×3 at its corner (segments of 100 and 300 px share
    // u evenly); at constant |x′| the bead keeps 50 px/s: after 4 s it is 200 px along.
    const std::vector<Vec2> points{{0, 0}, {100, 0}, {100, 300}};
    const Path polyline = LinearSplinePath(points).reparametrized();
    Bead bead(polyline, {.u = 0.0, .speed = 50});
    for (int i = 0; i < 240; ++i) bead.step(1.0 / 60);
    // The reparametrization holds arc length to 1e-9 of the length (4e-7 px here) and |x′|
    // to the same relative accuracy.
    EXPECT_NEAR(bead.position().x, 100, 1e-6);
    EXPECT_NEAR(bead.position().y, 100, 1e-6);
    EXPECT_NEAR(std::abs(bead.speed()), 50, 50 * 1e-8);
}

TEST(BeadOnPath, ClosedPathsWrapAround) {
    // A full circle without gravity: constant speed, and after 2.5 turns the bead is opposite
    // its start.
    const double r = 50, v = 100;
    const CirclePath ring({0, 0}, r, 0, 2 * pi);
    Bead bead(ring, {.u = 0.0, .speed = v});
    const double seconds = 2.5 * 2 * pi * r / v;
    const int steps = 600;
    for (int i = 0; i < steps; ++i) bead.step(seconds / steps);
    EXPECT_NEAR(bead.position().x, -r, 1e-6);
    EXPECT_NEAR(bead.position().y, 0, 1e-6);
    EXPECT_NEAR(bead.speed(), v, 1e-9);
    EXPECT_EQ(bead.crossings(), 2);
}


// A Bead on a complex path carries its speed across joins whatever the static type it was
// given: stepping both the same way gives the same states.
TEST(PathSpec, BeadOnAComplexPathIgnoresItsStaticType) {
    const ComplexPath complex = seed_complex();
    const BeadDef def{.u = 0.2, .speed = 300.0};
    Bead typed(complex, def);
    Bead plain(static_cast<const Path&>(complex), def);
    for (int k = 0; k < 600; ++k) {
        typed.step(1.0 / 60.0);
        plain.step(1.0 / 60.0);
        ASSERT_EQ(typed.position(), plain.position()) << "step " << k;
        ASSERT_EQ(typed.u(), plain.u()) << "step " << k;
    }
}

}  // namespace
