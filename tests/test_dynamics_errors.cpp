// Dynamics errors: bad input named by argument and reason, names that round-trip, degenerate
// starts that are refused and states that leave the finite range.
#include <grape/dynamics.hpp>

#include "error_text.hpp"
#include "seed_dynamics.hpp"

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

// ---------------------------------------------------------------------------------------
// Errors name the argument and the reason
// ---------------------------------------------------------------------------------------

TEST(Errors, BadInputsAreRejectedWithClearMessages) {
    ParticleSystem system;
    const auto a = system.create_particle({});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expect_error([&] { system.create_particle({.position = {nan, 0}}); }, "create_particle: position must be finite");
    expect_error([&] { system.create_particle({.velocity = {0, INFINITY}}); }, "create_particle: velocity must be finite");
    expect_error([&] { system.create_particle({.mass = 0}); }, "create_particle: mass must be positive");
    expect_error([&] { system.create_particle({.mass = -1}); }, "(got -1)");
    expect_error([&] { system.create_distance(a, {7}); }, "create_distance: particle 7 does not exist");
    expect_error([&] { system.create_distance(a, a, 1); }, "create_distance: a and b must be different");
    const auto b = system.create_particle({.position = {1, 0}});
    expect_error([&] { system.create_distance(a, b, 0); }, "create_distance: length must be positive");
    expect_error([&] { system.create_anchor(a, {0, 0}, -2); }, "create_anchor: length must be positive and finite (got -2)");
    expect_error([&] { system.create_anchor(a, {nan, 0}, 1); }, "create_anchor: anchor must be finite");
    expect_error([&] { system.create_fixed_point(a, {0, nan}); }, "create_fixed_point: point must be finite");
    expect_error([&] { system.create_constraint({}); }, "create_constraint: particles must not be empty");
    expect_error([&] { system.create_constraint({{a}, {}}); }, "create_constraint: evaluate must be a callable");
    expect_error([&] { system.create_constraint({{{9}}, {}}); }, "create_constraint: particle 9 does not exist");
    expect_error([&] { system.add_gravity({nan, 0}); }, "add_gravity: g must be finite");
    expect_error([&] { system.add_drag(-1); }, "add_drag: k must be finite and ≥ 0 (got -1)");
    expect_error([&] { system.add_spring(a, b, {.stiffness = -3}); }, "add_spring: stiffness must be finite and ≥ 0");
    expect_error([&] { system.add_spring(a, b, {.rest_length = nan}); }, "add_spring: rest_length");
    expect_error([&] { system.add_spring(a, b, {.damping = -1}); }, "add_spring: damping");
    expect_error([&] { system.add_force({}); }, "add_force: force must be a callable");
    expect_error([&] { system.exert_force(a, {nan, 0}); }, "exert_force: force must be finite");
    expect_error([&] { system.step(0); }, "step: dt must be positive and finite (got 0)");
    expect_error([&] { system.step(-1); }, "step: dt must be positive");
    expect_error([&] { system.position({42}); }, "position: particle 42 does not exist (2 particles)");
    expect_error([&] { system.set_position(a, {nan, 0}); }, "set_position: position must be finite");
    expect_error([&] { system.set_velocity(b, {0, nan}); }, "set_velocity: velocity must be finite");
    expect_error([&] { system.set_velocity({5}, {0, 0}); }, "set_velocity: particle 5 does not exist");
    expect_error([&] {
        std::vector<Vec2> too_few(1);
        system.evaluate(too_few);
    }, "evaluate: accelerations must hold one entry per particle (got 1 for 2)");
    expect_error([&] { ImplicitFunction(std::function<ImplicitSample(Vec2)>{}); }, "ImplicitFunction: evaluate must be a callable");
    expect_error([] { ParticleSystem({.drift = {.omega_dt = 0}}); }, "DriftDef: omega_dt must be positive and finite (got 0)");
    expect_error([] { ParticleSystem({.drift = {.stiffness = -1.0}}); }, "DriftDef: stiffness must be finite and ≥ 0");
    expect_error([] { ParticleSystem({.drift = {.damping = -1.0}}); }, "DriftDef: damping");
    expect_error([] { ParticleSystem({.drift = {.projection_iterations = 0}}); }, "DriftDef: projection_iterations");
    expect_error([] { ParticleSystem({.drift = {.projection_tolerance = -1}}); }, "DriftDef: projection_tolerance");
    expect_error([] { ParticleSystem({.solver = {.cg_tolerance = 0}}); }, "SolverDef: cg_tolerance");
    expect_error([] { ParticleSystem({.solver = {.cg_max_iterations = -1}}); }, "SolverDef: cg_max_iterations");
    expect_error([] { ParticleSystem({.rk45 = {.tolerance = -1}}); }, "Rk45Def: tolerance");
    expect_error([] { ParticleSystem({.rk45 = {.min_step = 0}}); }, "Rk45Def: min_step");
    expect_error([] { ParticleSystem({.rk45 = {.max_substeps = 0}}); }, "Rk45Def: max_substeps");
    expect_error([] { parse_integrator("leapfrog"); }, "integrator: unknown name 'leapfrog'");
    expect_error([] { parse_drift_control("magic"); }, "drift control: unknown name 'magic'");
    expect_error([] { parse_parabola_method("lagrange"); }, "method: unknown name 'lagrange'");
    expect_error([] { Bead(ParametricFunction{}, {}); }, "Bead: curve must be a callable");
    const ParametricFunction line = [](double u) { return ParametricSample{{u, 0}, {1, 0}, {0, 0}}; };
    expect_error([&] { Bead(line, {.mass = 0}); }, "BeadDef: mass must be positive and finite (got 0)");
    expect_error([&] { Bead(line, {.u = nan}); }, "BeadDef: u must be finite");
    expect_error([&] { Bead(line, {.speed = INFINITY}); }, "BeadDef: speed must be finite");
    expect_error([&] { Bead(line, {.drag = -1}); }, "BeadDef: drag");
    expect_error([&] { Bead(line, {.restitution = 2}); }, "BeadDef: restitution must be in [0, 1] (got 2)");
    expect_error([&] { Bead(line, {.gravity = {nan, 0}}); }, "BeadDef: gravity must be finite");
    expect_error([&] { Bead(line, {}).step(std::nan("")); }, "Bead::step: dt must be positive and finite");
    expect_error([] { Bead(LinearPath({0, 0}, {1, 0}), {.u = 1.5}); }, "BeadDef: u must be in [0, 1] on a path (got 1.5)");
    expect_error([] { run_parabola({.x0 = INFINITY}, 0.1, 1); }, "parabola: x0 must be finite");
    expect_error([] { run_parabola({.mass = -1}, 0.1, 1); }, "parabola: mass must be positive");
    expect_error([] { run_parabola({}, 0, 1); }, "parabola: dt must be positive");
}

// set_substeps validates as the constructor does, and the rule it sets is the one step() follows:
// a 100-link chain released horizontal needs several sub-steps per 1/60 s frame (ω·h ≤ 1 with
// ω of order √(n·g/L) ≈ 31 rad/s gives at least 1), one without the automatic rule.
TEST(Errors, SetSubstepsValidatesAndTakesEffect) {
    ParticleSystem system = chain(100, 1.0, 9.81, ParticleSystemDef{});  // one integrator step per step()
    expect_error([&] { system.set_substeps({.automatic = true, .omega_h = 0.0}); }, "SubstepDef: omega_h must be positive");
    expect_error([&] { system.set_substeps({.automatic = true, .max = 0}); }, "SubstepDef: max must be at least 1");
    EXPECT_FALSE(system.def().substeps.automatic);  // a refused rule changes nothing
    for (int k = 0; k < 30; ++k) EXPECT_EQ(system.step(1.0 / 60.0).substeps, 1);
    system.set_substeps({.automatic = true, .omega_h = 0.05});
    EXPECT_TRUE(system.def().substeps.automatic);
    int most = 0;
    for (int k = 0; k < 30; ++k) most = std::max(most, system.step(1.0 / 60.0).substeps);
    EXPECT_GT(most, 1);
}

TEST(Names, RoundTrip) {
    EXPECT_EQ(all_integrators().size(), 7u);
    for (Integrator i : all_integrators()) EXPECT_EQ(parse_integrator(to_string(i)), i);
    EXPECT_EQ(parse_integrator("symplectic"), Integrator::semi_implicit_euler);
    EXPECT_EQ(parse_integrator("verlet"), Integrator::velocity_verlet);
    EXPECT_EQ(all_drift_controls().size(), 3u);
    for (DriftControl d : all_drift_controls()) EXPECT_EQ(parse_drift_control(to_string(d)), d);
}

// --- degenerate starts and states that leave the finite range --------------------------------

TEST(DegenerateConstraints, APendulumStartingAtItsAnchorIsRefused) {
    // At its anchor the rod's gradient x − anchor is zero: no direction for the force, and
    // under Baumgarte feedback (−ks·C with C = −½L²) the particle was flung to |y| ~ 1e152
    // within 40 steps while every step reported ok.
    ParticleSystem system;
    const auto bob = system.create_particle({.position = {0, 0}});
    system.add_gravity({0, 500});
    expect_error([&] { system.create_anchor(bob, {0, 0}, 100); }, "create_anchor: particle 0 sits at the anchor");
    const auto other = system.create_particle({.position = {0, 0}});
    expect_error([&] { system.create_distance(bob, other, 10); }, "create_distance: particles 0 and 1 are at the same point");
    // Moved onto its anchor later: the step refuses, naming the constraint, and changes nothing.
    ParticleSystem moved;
    const auto p = moved.create_particle({.position = {100, 0}});
    moved.add_gravity({0, 500});
    moved.create_anchor(p, {0, 0}, 100);
    moved.set_position(p, {0, 0});
    expect_error([&] { moved.step(1.0 / 60); }, "step: constraint 0 (anchor) has a zero gradient");
    EXPECT_EQ(moved.position(p), (Vec2{0, 0}));
    EXPECT_EQ(moved.time(), 0.0);
}

TEST(DegenerateConstraints, AParticleAtTheCenterOfAnImplicitCircleIsRefused) {
    // C = x² + y² − 100²: ∇C = 2(x, y) vanishes at the center (conjugate gradient flung the
    // particle to 1e152 from there, reporting ok).
    ParticleSystem system({.solver = {.method = LinearSolver::conjugate_gradient}});
    const auto p = system.create_particle({.position = {0, 0}});
    system.add_gravity({0, 500});
    const auto circle = ImplicitFunction::from_function([](auto x, auto y) { return x * x + y * y - 10000.0; });
    expect_error([&] { system.create_implicit(p, circle); }, "create_implicit: the curve's gradient is zero at particle 0");
    // On the circle it runs, and stays on it (|C|/|∇C| small) and finite.
    system.set_position(p, {100, 0});
    system.create_implicit(p, circle);
    for (int i = 0; i < 40; ++i) EXPECT_EQ(system.step(1.0 / 60).status, SolveStatus::ok);
    EXPECT_NEAR(grape::length(system.position(p)), 100.0, 1.0);  // Baumgarte drift, far below a flung 1e152
}

TEST(NonFiniteStates, ADenormalMassIsRefused) {
    // 1/1e-310 = inf: every acceleration was inf·0 = NaN.
    ParticleSystem system;
    expect_error([&] { system.create_particle({.mass = 1e-310}); }, "create_particle: mass must be at least");
    EXPECT_NO_THROW(system.create_particle({.mass = 1e-300}));
}

TEST(NonFiniteStates, Rk45StopsAtOnceAndTheStateStaysAsItWas) {
    // A force that is NaN where the particle stands: before, rk45 rejected sub-steps until
    // max_substeps (10⁵ evaluations for one step) and reported nothing.
    for (const Integrator integrator : {Integrator::rk45, Integrator::rk4, Integrator::euler}) {
        SCOPED_TRACE(to_string(integrator));
        ParticleSystem system({.integrator = integrator});
        const auto p = system.create_particle({.position = {1, 0}, .velocity = {1, 0}});
        system.add_force([](const ForceContext& c) {
            if (c.positions[0].x > 0.5) c.forces[0].x += std::numeric_limits<double>::quiet_NaN();
        });
        const StepStats report = system.step(0.01);
        EXPECT_EQ(report.status, SolveStatus::non_finite);
        EXPECT_LE(report.substeps + report.rejected, 1);  // one Dormand–Prince attempt at most
        EXPECT_EQ(system.position(p), (Vec2{1, 0}));
        EXPECT_EQ(system.velocity(p), (Vec2{1, 0}));
        EXPECT_EQ(system.time(), 0.0);
    }
}

TEST(NonFiniteStates, AStepThatOverflowsSaysSo) {
    // An acceleration of 1e300 over dt = 1e10 leaves the doubles: the step is not taken.
    ParticleSystem system({.integrator = Integrator::rk4});
    const auto p = system.create_particle({.position = {1, 2}});
    system.add_gravity({0, 1e300});
    EXPECT_EQ(system.step(1e10).status, SolveStatus::non_finite);
    EXPECT_EQ(system.position(p), (Vec2{1, 2}));
    // A modest step still works.
    EXPECT_EQ(system.step(1e-160).status, SolveStatus::ok);
}

TEST(DegenerateConstraints, ABeadNeedsAPathOfPositiveLength) {
    // SVG data that draws nothing is a valid path of length 0; a bead's equation divides by
    // |x′|², zero everywhere on it, so the bead is refused instead of producing NaN.
    expect_error([] { Bead(parse_svg_path("M5 7"), {}); }, "Bead: the path has length 0");
    expect_error([] { Bead(Path(parse_svg_path("M5 7")).reparametrized(), {}); }, "Bead: the path has length 0");
}

}  // namespace
