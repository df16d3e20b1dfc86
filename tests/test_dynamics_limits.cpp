// Bounded work per step: rk45's sub-steps are capped per step and a step that reaches the
// cap says so (before, one step of dt = 1e10 ran 10⁵ sub-steps and reported ok).
#include <grape/dynamics.hpp>

#include "error_text.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace grape;

namespace {

// q̈ = −q: smooth, so the sub-step is set by the tolerance alone (~0.01 s at 1e-10).
struct Oscillator final : SecondOrderSystem {
    std::size_t size() const noexcept override { return 1; }
    void acceleration(double, std::span<const double> q, std::span<const double>, std::span<double> a) noexcept override {
        a[0] = -q[0];
    }
};

}  // namespace

TEST(Rk45Limit, AStepFarLongerThanTheToleranceAllowsStopsAtTheCapAndSaysSo) {
    Oscillator oscillator;
    Stepper stepper(Integrator::rk45, {.tolerance = 1e-10, .max_substeps = 50});
    double q = 1.0, v = 0.0;
    const StepStats stats = stepper.step(oscillator, 0.0, {&q, 1}, {&v, 1}, 1e10);
    EXPECT_EQ(stats.status, SolveStatus::substep_limit);
    // The cap counts accepted and rejected sub-steps; then one more finishes the step.
    EXPECT_LE(stats.substeps + stats.rejected, 51);
    // 6 evaluations a sub-step (first same as last), 7 for the first: bounded work.
    EXPECT_LE(stats.evaluations, 7 * 51);
    // A step the tolerance can carry does not reach it.
    Stepper fresh(Integrator::rk45, {.tolerance = 1e-10, .max_substeps = 50});
    q = 1.0, v = 0.0;
    const StepStats normal = fresh.step(oscillator, 0.0, {&q, 1}, {&v, 1}, 0.1);
    EXPECT_EQ(normal.status, SolveStatus::ok);
    EXPECT_NEAR(q, std::cos(0.1), 1e-9);  // 10× the tolerance
}

TEST(Rk45Limit, AParticleSystemReportsTheCapAsItsStatus) {
    ParticleSystem system({.integrator = Integrator::rk45});
    const auto bob = system.create_particle({.position = {100, 0}});
    system.add_gravity({0, 500});
    system.create_anchor(bob, {0, 0}, 100);
    EXPECT_EQ(system.step(1.0 / 60).status, SolveStatus::ok);
    system.set_rk45({.max_substeps = 1000});
    const StepStats report = system.step(1e10);
    EXPECT_EQ(report.status, SolveStatus::substep_limit);
    EXPECT_EQ(to_string(report.status), "substep_limit");
    EXPECT_LE(report.evaluations, 7 * 1001);
    grape::testing::expect_error([&] { system.set_rk45({.max_substeps = 0}); }, {"Rk45Def: max_substeps must be at least 1 (got 0)"});
    EXPECT_EQ(system.def().rk45.max_substeps, 1000);  // a refused setting changes nothing
}
