// Dynamics of particle systems: pendulum periods against the elliptic integral, double
// pendulums and chains held by Baumgarte and projection, the solvers agreeing, redundant
// constraints, forces and pinned particles.
#include <grape/dynamics.hpp>

#include "periods.hpp"
#include "seed_dynamics.hpp"
#include "user_constraints.hpp"
#include "error_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace grape;
using namespace grape::scenes;

using grape::testing::elliptic_k;
using grape::testing::ZeroCrossings;
using grape::testing::fast_build;

// ---------------------------------------------------------------------------------------
// Pendulums and chains
// ---------------------------------------------------------------------------------------

TEST(Pendulum, SimplePeriodMatchesTheEllipticIntegral) {
    const double length = 1.0, g = 9.81, theta0 = pi / 6;
    const double expected = 4.0 * std::sqrt(length / g) * elliptic_k(std::sin(theta0 / 2) * std::sin(theta0 / 2));
    EXPECT_NEAR(elliptic_k(0.0), pi / 2, 1e-15);
    for (DriftControl drift : {DriftControl::none, DriftControl::baumgarte, DriftControl::projection}) {
        auto system = simple_pendulum(length, theta0, g, {.drift = {.method = drift}});
        ZeroCrossings vx;
        std::vector<Vec2> a(1);
        auto sample = [&] {
            system.evaluate(a);
            vx.add(system.time(), system.velocities()[0].x, a[0].x);
        };
        sample();
        for (int i = 0; i < 240 * 20; ++i) {
            system.step(1.0 / 240);
            sample();
        }
        EXPECT_NEAR(vx.period(), expected, 1e-6) << to_string(drift);
    }
}

TEST(Pendulum, DoubleBlowsUpWithoutControlAtSixtyHertz) {
    auto system = double_pendulum(1.0, 1.0, 9.81, {.drift = {.method = DriftControl::none}});
    double blow_up = -1.0;
    for (int i = 0; i < 60 * 60 && blow_up < 0; ++i) {
        system.step(1.0 / 60);
        const auto x = system.positions();
        const double error = std::max(std::abs(length(x[0]) - 1.0), std::abs(distance(x[0], x[1]) - 1.0));
        if (!(error < 0.1)) blow_up = system.time();
    }
    EXPECT_GT(blow_up, 0.0) << "did not blow up within a minute";
    std::cout << "[ info ] double pendulum without drift control blows up at t = " << blow_up << " s\n";
}

TEST(Pendulum, DoubleRodLengthsHeldByBaumgarteAndByProjection) {
    const double seconds = fast_build ? 60.0 : 15.0;
    for (DriftControl drift : {DriftControl::baumgarte, DriftControl::projection}) {
        auto system = double_pendulum(1.0, 1.0, 9.81, {.drift = {.method = drift}});
        double worst = 0.0;
        const double e0 = system.energy();
        for (int i = 0; i < static_cast<int>(seconds * 240); ++i) {
            system.step(1.0 / 240);
            const auto x = system.positions();
            worst = std::max({worst, std::abs(length(x[0]) - 1.0), std::abs(distance(x[0], x[1]) - 1.0)});
        }
        EXPECT_LT(worst, drift == DriftControl::baumgarte ? 1e-6 : 1e-12) << to_string(drift);
        std::cout << "[ info ] double pendulum " << to_string(drift) << ": worst rod error " << worst
                  << ", energy change " << system.energy() - e0 << " J\n";
    }
}

TEST(Chain, HundredLinksHeldByProjection) {
    auto system = chain(100, 1.0, 9.81, {.drift = {.method = DriftControl::projection}});
    double worst = 0.0;
    const int steps = fast_build ? 600 : 120;
    for (int i = 0; i < steps; ++i) {
        const auto report = system.step(1.0 / 60);
        ASSERT_EQ(report.status, SolveStatus::ok);
        worst = std::max(worst, chain_link_error(system, 1.0));
    }
    EXPECT_LT(worst, 1e-9);
    EXPECT_EQ(system.positions()[0], (Vec2{0, 0}));  // the pin never moves
}

TEST(Chain, DenseSparseAndConjugateGradientSolversAgree) {
    // One evaluation of a 30-link chain (swinging: nonzero velocities) by each linear solver.
    std::vector<std::vector<Vec2>> results;
    for (LinearSolver solver : {LinearSolver::dense, LinearSolver::sparse_direct, LinearSolver::conjugate_gradient,
                                LinearSolver::automatic}) {
        auto system = chain(30, 1.0, 9.81, {.solver = {.method = solver}});
        for (int i = 0; i < 10; ++i) system.step(1.0 / 60);
        std::vector<Vec2> a(system.size());
        EXPECT_EQ(system.evaluate(a), SolveStatus::ok) << static_cast<int>(solver);
        results.push_back(a);
    }
    for (std::size_t i = 0; i < results[0].size(); ++i) {
        // Accelerations are O(10–100); a condition number of ~1e3 for J W Jᵀ and the CG
        // tolerance 1e-13 bound the difference by ~1e-9.
        EXPECT_NEAR(results[0][i].x, results[1][i].x, 1e-9);
        EXPECT_NEAR(results[0][i].y, results[1][i].y, 1e-9);
        EXPECT_NEAR(results[0][i].x, results[2][i].x, 1e-8);
        EXPECT_NEAR(results[0][i].y, results[2][i].y, 1e-8);
        EXPECT_NEAR(results[0][i].x, results[3][i].x, 1e-9);
        EXPECT_NEAR(results[0][i].y, results[3][i].y, 1e-9);
    }
}

TEST(Constraints, RedundantConstraintsAreSolvedWithoutNaN) {
    for (LinearSolver solver : {LinearSolver::dense, LinearSolver::sparse_direct, LinearSolver::conjugate_gradient,
                                LinearSolver::automatic}) {
        // A pendulum held twice (anchor + an identical user constraint) and a rod stated twice.
        ParticleSystem twice({.solver = {.method = solver}});
        ParticleSystem once({.solver = {.method = solver}});
        for (ParticleSystem* s : {&twice, &once}) {
            const auto a = s->create_particle({.position = {1, 0}});
            const auto b = s->create_particle({.position = {2, 0}});
            s->add_gravity({0, 9.81});
            s->create_anchor(a, {0, 0}, 1.0);
            s->create_distance(a, b, 1.0);
            if (s == &twice) {
                s->create_distance(b, a, 1.0);
                s->create_anchor(a, {0, 0}, 1.0);
            }
        }
        StepStats report;
        for (int i = 0; i < 120; ++i) {
            report = twice.step(1.0 / 240);
            once.step(1.0 / 240);
        }
        EXPECT_EQ(report.status, solver == LinearSolver::conjugate_gradient ? SolveStatus::ok : SolveStatus::singular);
        for (std::size_t i = 0; i < 2; ++i) {
            ASSERT_TRUE(is_finite(twice.positions()[i]));
            // The constraint force is unique even though λ is not: same motion to round-off
            // amplified over 120 steps.
            EXPECT_NEAR(twice.positions()[i].x, once.positions()[i].x, 1e-9);
            EXPECT_NEAR(twice.positions()[i].y, once.positions()[i].y, 1e-9);
        }
    }
}

TEST(Constraints, LargeRedundantChainFallsBackToConjugateGradient) {
    // 300 links, each stated twice in a row (600 rows, banded): the envelope Cholesky meets a
    // zero pivot and its conjugate-gradient fallback solves the consistent singular system.
    auto once = chain(300, 1.0, 9.81, {.drift = {.method = DriftControl::none}});
    ParticleSystem twice({.drift = {.method = DriftControl::none}});
    twice.create_particle({.mass = std::numeric_limits<double>::infinity()});
    for (std::uint32_t k = 1; k <= 300; ++k) {
        twice.create_particle({.position = {static_cast<double>(k), 0.0}});
        twice.create_distance({k - 1}, {k}, 1.0);
        twice.create_distance({k}, {k - 1}, 1.0);  // the same link again, next to it: still banded
    }
    twice.add_gravity({0, 9.81});
    for (int i = 0; i < 30; ++i) {  // swing a little so the velocity terms matter
        once.step(1.0 / 240);
    }
    for (std::size_t k = 0; k < once.size(); ++k) {
        twice.set_position({static_cast<std::uint32_t>(k)}, once.positions()[k]);
        twice.set_velocity({static_cast<std::uint32_t>(k)}, once.velocities()[k]);
    }
    std::vector<Vec2> a2(twice.size()), a1(once.size());
    EXPECT_EQ(twice.evaluate(a2), SolveStatus::singular);
    EXPECT_EQ(once.evaluate(a1), SolveStatus::ok);
    for (std::size_t i = 0; i < a1.size(); ++i) {
        // Accelerations O(10); CG to 1e-13 relative on a system of condition ~n² = 1e5.
        EXPECT_NEAR(a2[i].x, a1[i].x, 1e-6);
        EXPECT_NEAR(a2[i].y, a1[i].y, 1e-6);
    }
}

TEST(Constraints, FixedPointAndUserCircleBehaveLikeTheirBuiltInEquivalents) {
    // A user constraint written as Witkin's bead on a circle, C = ½(|x|² − r²), must give
    // exactly the anchor constraint's motion.
    const grape::testing::CircleTwins twins = grape::testing::circle_twins({});
    EXPECT_EQ(twins.anchor, twins.user);
    // A fixed point holds against gravity and a spring.
    const grape::testing::FixedAndFree held = grape::testing::fixed_point_against_spring({});
    EXPECT_LT(length(held.fixed), 1e-9);
    EXPECT_GT(length(held.free - Vec2{1, 0}), 0.1);
}

// A step evaluates its rows once per integrator stage: the rows it evaluates at the step's
// start (to refuse degenerate ones) are the first stage's, at the same values, and are not
// evaluated again. Counted on a user constraint (a bead on a circle of radius 2): euler and
// semi-implicit Euler 1, midpoint and velocity Verlet 2, RK4 4, over three steps. Baumgarte
// drift control, so that no projection adds evaluations; the motion itself is the anchor's
// bit for bit (FixedPointAndUserCircleBehaveLikeTheirBuiltInEquivalents).
TEST(Constraints, AStepEvaluatesTheRowsOncePerIntegratorStage) {
    const std::pair<Integrator, int> cases[] = {{Integrator::euler, 1},
                                                {Integrator::semi_implicit_euler, 1},
                                                {Integrator::midpoint, 2},
                                                {Integrator::velocity_verlet, 2},
                                                {Integrator::rk4, 4}};
    for (const auto& [integrator, stages] : cases) {
        ParticleSystem system({.integrator = integrator, .drift = {.method = DriftControl::baumgarte}});
        const auto p = system.create_particle({.position = {2, 0}, .velocity = {0, 1}});
        system.add_gravity({0, -9.81});
        int calls = 0;
        system.create_constraint({{p}, [&calls](std::span<const Vec2> x, std::span<const Vec2> v, UserConstraintOutput& out) {
                                      ++calls;
                                      out.value = 0.5 * (dot(x[0], x[0]) - 4.0);
                                      out.jacobian[0] = x[0];
                                      out.jdot_v = dot(v[0], v[0]);
                                  }});
        for (int step = 1; step <= 3; ++step) {
            const StepStats stats = system.step(1.0 / 60.0);
            EXPECT_EQ(stats.evaluations, stages) << to_string(integrator);
            EXPECT_EQ(calls, step * stages) << to_string(integrator) << " step " << step;
        }
        EXPECT_NEAR(length(system.position(p)), 2.0, 1e-3) << to_string(integrator);  // still on the circle
    }
}

// ---------------------------------------------------------------------------------------
// Forces and the particle system
// ---------------------------------------------------------------------------------------

TEST(Forces, SpringAndGravityConserveEnergyDragDissipates) {
    ParticleSystem system({.integrator = Integrator::rk4});
    const auto a = system.create_particle({.position = {0, 0}, .mass = std::numeric_limits<double>::infinity()});
    const auto b = system.create_particle({.position = {1.2, 0.3}, .velocity = {0, 1}, .mass = 2.0});
    system.add_gravity({0, 9.81});
    system.add_spring(a, b, {.rest_length = 1.0, .stiffness = 40.0});
    const double e0 = system.energy();
    for (int i = 0; i < 1000; ++i) system.step(1e-3);
    // RK4 at dt = 1e-3 with ω = √(k/m) ≈ 4.5 rad/s: relative energy error ~ (ω dt)⁴·t ≈ 4e-10.
    EXPECT_NEAR(system.energy(), e0, 1e-8 * std::abs(e0));
    EXPECT_EQ(system.positions()[0], (Vec2{0, 0}));
    system.add_drag(0.5);
    double previous = system.energy();
    for (int i = 0; i < 100; ++i) {
        system.step(1e-3);
        EXPECT_LT(system.energy(), previous);
        previous = system.energy();
    }
}

TEST(Forces, ExertedForceLastsOneStepAndUserForcesSeeAccumulatedForces) {
    ParticleSystem system({.integrator = Integrator::euler});
    const auto p = system.create_particle({.position = {0, 0}, .mass = 2.0});
    system.add_gravity({0, 10});
    Vec2 seen{};
    system.add_force([&seen](const ForceContext& c) { seen = c.forces[0]; });
    system.exert_force(p, {4, 0});
    system.step(0.5);
    EXPECT_EQ(seen, (Vec2{4, 20}));                    // exerted + weight, in that order
    EXPECT_EQ(system.velocities()[0], (Vec2{1, 5}));   // a = F/m = (2, 10), dt = 0.5
    system.step(0.5);
    EXPECT_EQ(system.velocities()[0], (Vec2{1, 10}));  // the exerted force is gone
}

TEST(Forces, PinnedParticlesNeverMove) {
    ParticleSystem system;
    const auto pin = system.create_particle({.position = {3, 4}, .velocity = {5, 5}, .mass = std::numeric_limits<double>::infinity()});
    const auto bob = system.create_particle({.position = {4, 4}});
    system.add_gravity({0, 9.81});
    system.create_distance(pin, bob);
    system.exert_force(pin, {100, 100});
    for (int i = 0; i < 60; ++i) system.step(1.0 / 60);
    EXPECT_EQ(system.position(pin), (Vec2{3, 4}));
    EXPECT_EQ(system.velocity(pin), (Vec2{0, 0}));
    EXPECT_EQ(system.mass(pin), std::numeric_limits<double>::infinity());
    EXPECT_NEAR(distance(system.position(pin), system.position(bob)), 1.0, 1e-4);
}

}  // namespace
