// Chains and cloth: RATTLE, the stiffness-aware sub-steps, the tridiagonal solve and the
// catalogue's chain and cloth strip, checked against closed forms (the hanging chain's
// tensions), a second integrator (RK4 with projection) within RATTLE's own measured error,
// the order of convergence, and energy over many periods.
#include <grape/dynamics.hpp>

#include "seed_dynamics.hpp"
#include "user_constraints.hpp"

#include "error_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using namespace grape;
using namespace grape::scenes;

using grape::testing::expect_error;
using grape::testing::fast_build;

double max_distance(std::span<const Vec2> a, std::span<const Vec2> b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, distance(a[i], b[i]));
    return worst;
}

// The catalogue's chain as given (RATTLE, automatic sub-steps) at 60 Hz from horizontal, the
// hardest start (the free end whips): every link within 1e-9 m all the way, which is far
// above where the projection stops (8ε·(1 + max |x|) ≈ 1.8e-13 m per metre of chain) and
// far below any visible error.
TEST(Chain, CatalogueChainRunsAtSixtyHertzAsGiven) {
    for (std::size_t links : {std::size_t{10}, std::size_t{100}, std::size_t{1000}}) {
        if (links == 1000 && !fast_build) continue;
        auto system = chain(links, 1.0, 9.81);
        double worst = 0.0;
        int most = 0;
        for (int frame = 0; frame < 600; ++frame) {
            const StepStats report = system.step(1.0 / 60);
            ASSERT_EQ(report.status, SolveStatus::ok) << links << " links, frame " << frame;
            worst = std::max(worst, chain_link_error(system, 1.0));
            most = std::max(most, report.substeps);
        }
        EXPECT_LT(worst, 1e-9) << links << " links";
        EXPECT_EQ(system.positions()[0], (Vec2{0, 0}));  // the pin never moves
        // The bound grows like 2√(n·g/L): the long chain needs several sub-steps per frame.
        if (links == 1000) {
            EXPECT_GT(most, 2);
        }
        std::cout << "[ info ] " << links << " links: worst link error " << worst << " m, up to " << most
                  << " sub-steps per frame\n";
    }
}

// A chain hanging at rest: link k carries the weight below it, T_k = (n − k + 1)·m·g, so
// its multiplier (force = λ·d, |d| = L) is T_k/L, and the bound at the first free particle,
// between the two most loaded links, is ω² = 2(T₁ + T₂)/(m·L²)·L = 2(2n − 1)·g/L.
TEST(Chain, StiffestModeOfAHangingChainIsTheClosedForm) {
    const std::size_t n = 50;
    const double link = 0.5, g = 9.81;
    auto system = chain(n, link, g, {}, 0.0);
    std::vector<Vec2> a(system.size());
    ASSERT_EQ(system.evaluate(a), SolveStatus::ok);
    for (std::size_t i = 1; i < a.size(); ++i) EXPECT_NEAR(length(a[i]), 0.0, 1e-12);  // at rest: no acceleration
    const double expected = std::sqrt(2.0 * (2.0 * double(n) - 1.0) * g / link);
    // 1e-12 relative: the multipliers come from one tridiagonal solve of condition ~n².
    EXPECT_NEAR(system.stiffest_mode(), expected, 1e-12 * expected);
}

// The tridiagonal LDLᵀ (a chain in creation order) and the dense Cholesky give the same
// constraint forces to round-off of the solve (condition ~n², here ~1e4, times ε).
TEST(Chain, TridiagonalSolveMatchesDense) {
    auto swinging = [](LinearSolver solver) {
        auto system = chain(100, 1.0, 9.81, {.solver = {.method = solver}}, 1.0);
        for (std::size_t i = 1; i < system.size(); ++i)
            system.set_velocity(ParticleId{std::uint32_t(i)}, {std::cos(0.1 * double(i)), std::sin(0.3 * double(i))});
        std::vector<Vec2> a(system.size());
        EXPECT_EQ(system.evaluate(a), SolveStatus::ok);
        return a;
    };
    const auto fast = swinging(LinearSolver::automatic), dense = swinging(LinearSolver::dense);
    double scale = 0.0;
    for (const Vec2& v : dense) scale = std::max(scale, length(v));
    EXPECT_LT(max_distance(fast, dense), 1e-10 * scale);
}

// RATTLE and RK4 with projection are independent integrators of the same equations. Over
// 1 s of a 5-link chain released at 60°, RATTLE's global error at h is measured by
// Richardson from h and h/2 (order 2: error(h) ≈ 4/3·|x_h − x_{h/2}|), and RK4 at h/4 is
// ~10⁴ times closer to the truth: the two agree within twice RATTLE's own estimate.
TEST(Rattle, AgreesWithRk4WithinItsOwnMeasuredError) {
    auto run = [](Integrator integrator, double h) {
        auto system = chain(5, 1.0, 9.81, {.integrator = integrator, .drift = {.method = DriftControl::projection}}, pi / 3);
        const int steps = static_cast<int>(std::lround(1.0 / h));
        for (int i = 0; i < steps; ++i) system.step(h);
        return std::vector<Vec2>(system.positions().begin(), system.positions().end());
    };
    const double h = 1.0 / 240;
    const auto coarse = run(Integrator::rattle, h), fine = run(Integrator::rattle, h / 2);
    const auto reference = run(Integrator::rk4, h / 4);
    const double estimate = 4.0 / 3.0 * max_distance(coarse, fine);
    const double error = max_distance(coarse, reference);
    EXPECT_GT(estimate, 0.0);
    EXPECT_LT(error, 2.0 * estimate);
    EXPECT_GT(error, 0.5 * estimate);  // and it is the error: not hidden by a larger one
    std::cout << "[ info ] RATTLE at 1/240 s: error " << error << " m, Richardson estimate " << estimate << " m\n";
}

// Order 2: halving h divides the error of a smooth run (a pendulum at 30°, 1 s) by 4.
TEST(Rattle, SecondOrder) {
    auto bob_at_one_second = [](double h) {
        auto system = simple_pendulum(1.0, pi / 6, 9.81, {.integrator = Integrator::rattle});
        const int steps = static_cast<int>(std::lround(1.0 / h));
        for (int i = 0; i < steps; ++i) system.step(h);
        return system.positions()[0];
    };
    const Vec2 a = bob_at_one_second(1.0 / 50), b = bob_at_one_second(1.0 / 100), c = bob_at_one_second(1.0 / 200);
    const double ratio = distance(a, b) / distance(b, c);
    EXPECT_GT(ratio, 3.6);  // 4 for order 2 (2 for order 1, 16 for order 4)
    EXPECT_LT(ratio, 4.4);
}

// Symplectic: on a pendulum at 60° the energy error oscillates with the swing and does not
// grow. Over 100 periods it stays within 1.2× its worst over the first 10, and at O(h²):
// a quarter at half the step.
TEST(Rattle, EnergyStaysBoundedOverManyPeriods) {
    auto worst_energy_error = [](double h, double seconds) {
        auto system = simple_pendulum(1.0, pi / 3, 9.81, {.integrator = Integrator::rattle});
        const double e0 = system.energy();
        double worst = 0.0;
        const int steps = static_cast<int>(std::lround(seconds / h));
        for (int i = 0; i < steps; ++i) {
            system.step(h);
            worst = std::max(worst, std::abs(system.energy() - e0));
        }
        return worst / std::abs(e0);
    };
    const double period = 2.15;  // s, about (elliptic K at 60°)
    const double first = worst_energy_error(1.0 / 60, 10 * period);
    const double long_run = worst_energy_error(1.0 / 60, 100 * period);
    EXPECT_LT(long_run, 1.2 * first);
    const double halved = worst_energy_error(1.0 / 120, 10 * period);
    EXPECT_NEAR(first / halved, 4.0, 0.5);
    // Rods at round-off all the while, energy to a few parts in 10⁴ at 60 Hz.
    EXPECT_LT(first, 1e-3);
}

// RATTLE on every other kind of constraint: a user constraint written as the anchor's
// C = ½(|x|² − r²) takes the general evaluation path and must give the anchor's motion
// (the same arithmetic: exactly); a fixed point holds against gravity and a spring; a
// particle on the seed's implicit parabola stays on it at round-off (|C|/|∇C| ≤ 1e-9 px for
// coordinates up to ~100 px) and moves as the parametric bead, within RATTLE's O(h²) error.
TEST(Rattle, UserFixedPointAndCurveConstraints) {
    const grape::testing::CircleTwins twins = grape::testing::circle_twins({.integrator = Integrator::rattle});
    EXPECT_EQ(twins.anchor, twins.user);
    EXPECT_LT(twins.anchor_residual, 1e-14);

    const grape::testing::FixedAndFree held = grape::testing::fixed_point_against_spring({.integrator = Integrator::rattle});
    EXPECT_LT(length(held.fixed), 1e-15);
    EXPECT_GT(length(held.free - Vec2{1, 0}), 0.1);

    auto run = [](ParabolaMethod method, Integrator integrator, double dt) {
        return run_parabola({.method = method, .integrator = integrator}, dt, 2.0);  // 2 s from x0 = 100 px
    };
    const ParabolaSummary implicit = run(ParabolaMethod::implicit, Integrator::rattle, 1.0 / 240);
    const ParabolaSummary half = run(ParabolaMethod::implicit, Integrator::rattle, 1.0 / 480);
    const ParabolaSummary exact = run(ParabolaMethod::parametric, Integrator::rk4, 1.0 / 960);
    EXPECT_LT(implicit.max_distance, 1e-9);
    const double error = std::abs(implicit.final.x.x - exact.final.x.x);
    const double estimate = 4.0 / 3.0 * std::abs(implicit.final.x.x - half.final.x.x);
    EXPECT_LT(error, 2.0 * estimate);
    EXPECT_GT(error, 0.5 * estimate);
}

// A system moved by hand between steps (set_position) starts its next step from a fresh
// factor: a rod stretched by hand is pulled back to its length in one step.
TEST(Rattle, SetPositionBetweenStepsIsHonoured) {
    auto system = chain(3, 1.0, 9.81, {.integrator = Integrator::rattle}, 0.5);
    system.step(1.0 / 60);
    system.set_position(ParticleId{3}, system.position(ParticleId{3}) + Vec2{0.3, 0.0});
    system.step(1.0 / 60);
    EXPECT_LT(chain_link_error(system, 1.0), 1e-12);
}

// Sub-steps: one step(dt) with automatic sub-steps lands exactly on t + dt, reports how many
// it took, and with max = 1 it is one step.
TEST(Substeps, LandOnTheFrameAndRespectTheirCap) {
    auto system = chain(200, 0.02, 9.81, {.integrator = Integrator::rattle, .substeps = {.automatic = true}}, 0.0);
    system.step(1.0 / 60);  // the first step has no multipliers yet: one sub-step
    const StepStats report = system.step(1.0 / 60);
    // Hanging: ω = √(2·399·9.81/0.02) ≈ 626 rad/s, so ω·dt ≈ 10.4 at 60 Hz: 11 sub-steps.
    EXPECT_EQ(report.substeps, 11);
    EXPECT_DOUBLE_EQ(system.time(), 2.0 / 60);
    auto capped = chain(200, 0.02, 9.81, {.integrator = Integrator::rattle, .substeps = {.automatic = true, .max = 4}}, 0.0);
    capped.step(1.0 / 60);
    EXPECT_EQ(capped.step(1.0 / 60).substeps, 4);
    expect_error([] { ParticleSystem({.substeps = {.omega_h = 0.0}}); }, "SubstepDef: omega_h must be positive");
    expect_error([] { ParticleSystem({.substeps = {.max = 0}}); }, "SubstepDef: max must be at least 1");
}

// RK4 with projection takes the same rule: the 1,000-link chain, which at one RK4 step per
// 1/60 s frame blows up within 10 s, holds with automatic sub-steps.
TEST(Substeps, AlsoKeepRk4Stable) {
    const std::size_t links = fast_build ? 1000 : 100;
    auto system = chain(links, 1.0, 9.81, {.drift = {.method = DriftControl::projection}, .substeps = {.automatic = true}});
    double worst = 0.0;
    for (int frame = 0; frame < 600; ++frame) {
        ASSERT_EQ(system.step(1.0 / 60).status, SolveStatus::ok) << frame;
        worst = std::max(worst, chain_link_error(system, 1.0));
    }
    EXPECT_LT(worst, 1e-9);
}

// The catalogue's cloth strip: every link its length at the start (the shear keeps them),
// the top row pinned, and held at 60 Hz as given.
TEST(Cloth, StripStartsWithEveryLinkAtItsLengthAndHolds) {
    const int columns = 8, rows = 6;
    const double spacing = 0.3;
    auto system = cloth_strip(columns, rows, spacing, 9.81);
    EXPECT_EQ(system.size(), std::size_t(columns * rows));
    EXPECT_EQ(system.constraint_count(), std::size_t((columns - 1) * (rows - 1) + columns * (rows - 1)));
    EXPECT_LT(system.max_residual().distance, 1e-15);
    for (int frame = 0; frame < 300; ++frame) ASSERT_EQ(system.step(1.0 / 60).status, SolveStatus::ok);
    EXPECT_LT(system.max_residual().distance, 1e-9);
    for (int c = 0; c < columns; ++c) EXPECT_EQ(system.inverse_masses()[std::size_t(c)], 0.0);
    expect_error([] { cloth_strip(1, 5, 0.1, 9.81); }, "cloth_strip: columns and rows must be at least 2");
}

// The grab spring on a free particle, critically damped (ζ = 1, ω = 2πf): from rest at
// distance d it closes as d·(1 + ωt)·e^(−ωt), the closed form. RK4 at 1/2000 s is within
// ~1e-12 of it (error ~ (ωh)⁴·d); 1e-9 of d leaves room for round-off of the exponential.
TEST(Grab, CriticallyDampedApproachMatchesTheClosedForm) {
    ParticleSystem system({.integrator = Integrator::rk4});
    const ParticleId p = system.create_particle({.position = {1.0, 0.0}, .mass = 2.0});
    const double hertz = 2.0, omega = 2.0 * pi * hertz;
    system.grab(p, {0.0, 0.0}, {.hertz = hertz});
    ASSERT_EQ(system.grabbed(), std::optional<ParticleId>(p));
    const double h = 1.0 / 2000;
    for (int i = 0; i < 1000; ++i) system.step(h);
    const double t = system.time();
    EXPECT_NEAR(system.position(p).x, (1.0 + omega * t) * std::exp(-omega * t), 1e-9);
    EXPECT_EQ(system.position(p).y, 0.0);
    system.release_grab();
    EXPECT_FALSE(system.grabbed());
    const Vec2 before = system.velocity(p);
    system.step(h);
    EXPECT_EQ(system.velocity(p), before);  // nothing pulls any more
}

// Tuned for a heavier mass M, the spring is k = M·ω² (its pull on a chain's end holds the
// chain) while ζ stays relative to the particle's own mass; the force is capped at max_force;
// and k is part of the stiffness bound: ω_p = √(k/m).
TEST(Grab, TunedMassCapAndStiffness) {
    ParticleSystem system;
    const ParticleId p = system.create_particle({.position = {3.0, 4.0}});
    const double omega = 2.0 * pi * 5.0;
    system.grab(p, {0.0, 0.0}, {.hertz = 5.0, .damping_ratio = 0.0, .mass = 100.0});
    std::vector<Vec2> a(1);
    system.evaluate(a);
    EXPECT_NEAR(a[0].x, -100.0 * omega * omega * 3.0, 1e-9 * 100.0 * omega * omega * 3.0);
    EXPECT_NEAR(system.stiffest_mode(), std::sqrt(100.0) * omega, 1e-12 * std::sqrt(100.0) * omega);
    EXPECT_NEAR(system.potential_energy(), 0.5 * 100.0 * omega * omega * 25.0, 1e-9 * 100.0 * omega * omega * 25.0);
    system.grab(p, {0.0, 0.0}, {.hertz = 5.0, .mass = 100.0, .max_force = 2.0});
    system.evaluate(a);
    EXPECT_NEAR(length(a[0]), 2.0, 1e-15);  // mass 1: |a| = |F| = the cap
    EXPECT_NEAR(a[0].x / a[0].y, 0.75, 1e-15);  // still towards the target
}

// A grabbed chain keeps its links at round-off (the pull is a force; the constraints decide
// how the rest follows). Undamped, the grab is a conservative spring: on a grabbed pendulum
// bob (spring and rod together) RATTLE at 60 Hz keeps the energy within its O(h²) swing,
// which does not grow: the worst over 60 s stays within 1.2× the worst over the first 6 s.
TEST(Grab, GrabbedChainKeepsItsLinksAndUndampedEnergyIsBounded) {
    auto system = chain(20, 0.1, 9.81, chain_def(), 0.0);
    const ParticleId end{20};
    system.grab(end, system.position(end) + Vec2{0.3, -0.2}, {.hertz = 1.0, .mass = 20.0});
    double worst = 0.0;
    for (int frame = 0; frame < 600; ++frame) {
        system.step(1.0 / 60);
        worst = std::max(worst, chain_link_error(system, 0.1));
    }
    EXPECT_LT(worst, 1e-12);

    auto energy_error = [](double seconds) {
        auto bob = simple_pendulum(1.0, pi / 4, 9.81, {.integrator = Integrator::rattle, .substeps = {.automatic = true}});
        bob.grab(ParticleId{0}, {0.5, 1.0}, {.hertz = 1.0, .damping_ratio = 0.0});
        const double e0 = bob.energy();
        double most = 0.0;
        for (int frame = 0; frame < static_cast<int>(seconds * 60); ++frame) {
            bob.step(1.0 / 60);
            most = std::max(most, std::abs(bob.energy() - e0));
        }
        return most / std::abs(e0);
    };
    const double first = energy_error(6.0), long_run = energy_error(60.0);
    EXPECT_LT(first, 1e-2);
    EXPECT_LT(long_run, 1.2 * first);
    std::cout << "[ info ] grabbed bob: energy within " << first << " (6 s), " << long_run << " (60 s)\n";
}

TEST(Grab, PickingAndErrors) {
    auto system = chain(3, 1.0, 9.81, chain_def(), pi / 2);  // particles at x = 0 (pinned), 1, 2, 3
    EXPECT_EQ(system.nearest_particle({1.9, 0.2}, 0.5), std::optional<ParticleId>(ParticleId{2}));
    EXPECT_FALSE(system.nearest_particle({0.0, 0.0}, 0.5));  // only the pin is near: skipped
    EXPECT_FALSE(system.nearest_particle({5.0, 0.0}, 0.5));
    expect_error([&] { system.grab(ParticleId{0}, {0, 0}); }, "grab: particle 0 is pinned");
    expect_error([&] { system.grab(ParticleId{9}, {0, 0}); }, "grab: particle 9 does not exist");
    expect_error([&] { system.grab(ParticleId{1}, {NAN, 0}); }, "grab: target must be finite");
    expect_error([&] { system.grab(ParticleId{1}, {0, 0}, {.hertz = 0}); }, "GrabDef: hertz must be positive");
    expect_error([&] { system.grab(ParticleId{1}, {0, 0}, {.damping_ratio = -1}); }, "GrabDef: damping_ratio must be");
    expect_error([&] { system.grab(ParticleId{1}, {0, 0}, {.max_force = 0}); }, "GrabDef: max_force must be positive");
    expect_error([&] { system.move_grab({INFINITY, 0}); }, "move_grab: target must be finite");
    system.move_grab({1, 1});  // nothing grabbed: nothing happens
    EXPECT_FALSE(system.grabbed());
}

}  // namespace
