// Constraints near their degenerate points: a pendulum started next to its anchor, a bead near
// the center of an implicit circle, Baumgarte gains beyond what a step can carry. Every state
// must stay finite and bounded, and a step whose constraint could not be trusted says so.
#include <grape/dynamics.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace grape;

namespace {

constexpr double rod = 100.0;  // L, px
constexpr double g = 500.0;    // px/s²
constexpr double dt = 1.0 / 60;

std::string name(Integrator integrator, DriftControl drift, double start) {
    return std::string(to_string(integrator)) + " / " + std::string(to_string(drift)) + " / start " + std::to_string(start);
}

bool finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// The anchor's conditioning κ = |C|·h/|∇C|² with C = ½(r² − L²), ∇C = x − anchor, h = 1:
// κ = (L² − r²)/(2r²) inside the rod. Position corrections are limited for κ > 1
// (r < L/√3) and the row is dropped for κ ≥ 100 (r ≤ L/√201).
double kappa(double r) { return std::abs(0.5 * (r * r - rod * rod)) / (r * r); }

}  // namespace

TEST(NearAnchor, EveryIntegratorAndDriftControlStaysFiniteAndBoundedAndSaysSo) {
    // Before: a particle 1e-3 … 1e-12 from its anchor ran away to |y| ~ 1e160 within 200
    // steps (Baumgarte's −ks·C along a gradient of length r ≪ L is an acceleration of
    // ks·L²/(2r)); drift none and RATTLE blew up too (a tiny, stiff orbit).
    for (DriftControl drift : all_drift_controls())
        for (Integrator integrator : all_integrators())
            for (int e = 1; e <= 15; ++e) {
                const double start = std::pow(10.0, -e);
                SCOPED_TRACE(name(integrator, drift, start));
                ParticleSystem system({.integrator = integrator, .drift = {.method = drift}});
                const auto bob = system.create_particle({.position = {start, 0}});
                system.add_gravity({0, g});
                system.create_anchor(bob, {0, 0}, rod);
                double farthest = 0.0;
                for (int k = 0; k < 600; ++k) {
                    const double r = length(system.position(bob));
                    const StepStats report = system.step(dt);
                    ASSERT_NE(report.status, SolveStatus::non_finite) << "step " << k;
                    ASSERT_TRUE(finite(system.position(bob)) && finite(system.velocity(bob))) << "step " << k;
                    // A step that starts where the rod cannot be trusted is not ok: without
                    // position corrections (drift none) only the dropped row counts; RATTLE
                    // drops any row whose Newton step could pass a vanishing gradient.
                    const bool position_level = integrator == Integrator::rattle || drift != DriftControl::none;
                    const bool untrusted = position_level ? kappa(r) > 1.0 : kappa(r) >= 100.0;
                    if (untrusted) {
                        EXPECT_EQ(report.status, SolveStatus::singular) << "step " << k << ", r = " << r;
                    }
                    farthest = std::max(farthest, length(system.position(bob)));
                }
                // Bounded: a controlled rod holds the particle within L once it reaches it
                // (measured: ≤ 100.4 px). Drift none holds C̈ = 0 only, so the Ċ of the free
                // fall the row took hold with carries on (r² grows linearly, ≤ 115 px after
                // 10 s); 2L bounds both.
                EXPECT_LT(farthest, (drift == DriftControl::none && integrator != Integrator::rattle ? 2.0 : 1.05) * rod);
                const double r = length(system.position(bob));
                // Where the drift is controlled the pendulum ends on its rod: projection and
                // RATTLE at round-off (1e-12 of L), Baumgarte, ω·dt = 0.05 (e-folding in 20
                // steps), within 1e-3 of L after 10 s.
                if (integrator == Integrator::rattle || drift == DriftControl::projection) {
                    EXPECT_NEAR(r, rod, 1e-12 * rod);
                } else if (drift == DriftControl::baumgarte) {
                    EXPECT_NEAR(r, rod, 1e-3 * rod);
                }
                // Well inside its trusted region, the last step is ok.
                if (kappa(r) < 0.5) {
                    EXPECT_EQ(system.step(dt).status, SolveStatus::ok);
                }
            }
}

TEST(NearAnchor, ARodBetweenTwoParticlesCompressedToAPointRecovers) {
    // The same for a distance constraint (∇C = ±d, h = 2, κ = (L² − |d|²)/(2|d|²)):
    // two particles 1e-9 apart with a 10 px rod, one pinned.
    for (DriftControl drift : all_drift_controls()) {
        SCOPED_TRACE(std::string(to_string(drift)));
        ParticleSystem system({.drift = {.method = drift}});
        const auto a = system.create_particle({.position = {0, 0}, .mass = std::numeric_limits<double>::infinity()});
        const auto b = system.create_particle({.position = {1e-9, 0}});
        system.add_gravity({0, g});
        system.create_distance(a, b, 10.0);
        EXPECT_EQ(system.step(dt).status, SolveStatus::singular);
        for (int k = 0; k < 600; ++k) {
            ASSERT_NE(system.step(dt).status, SolveStatus::non_finite);
            ASSERT_TRUE(finite(system.position(b)));
            ASSERT_LT(length(system.position(b)), drift == DriftControl::none ? 20.0 : 10.5);  // as above
        }
        if (drift != DriftControl::none) {
            EXPECT_NEAR(length(system.position(b)), 10.0, 1e-2);
        }
    }
}

TEST(NearCenter, AnImplicitCircleSolvedByConjugateGradientStaysFiniteAndBounded) {
    // C = x² + y² − R²: ∇C = 2x, H = 2I, κ = |r² − R²|/(2r²), the anchor's. Before, a
    // particle at the center was flung to 1e152 with every step ok.
    constexpr double radius = 100.0;
    const auto circle = ImplicitFunction::from_function([](auto x, auto y) { return x * x + y * y - radius * radius; });
    for (DriftControl drift : all_drift_controls())
        for (Integrator integrator : {Integrator::rk4, Integrator::velocity_verlet, Integrator::rk45, Integrator::rattle})
            for (int e = 1; e <= 15; e += 2) {
                const double start = std::pow(10.0, -e);
                SCOPED_TRACE(name(integrator, drift, start));
                ParticleSystem system({.integrator = integrator,
                                       .drift = {.method = drift},
                                       .solver = {.method = LinearSolver::conjugate_gradient}});
                const auto p = system.create_particle({.position = {0, start}});
                system.add_gravity({0, g});
                system.create_implicit(p, circle);
                EXPECT_EQ(system.step(dt).status, SolveStatus::singular);
                for (int k = 0; k < 600; ++k) {
                    ASSERT_NE(system.step(dt).status, SolveStatus::non_finite) << "step " << k;
                    ASSERT_TRUE(finite(system.position(p))) << "step " << k;
                    ASSERT_LT(length(system.position(p)), 2.0 * radius) << "step " << k;  // as for the anchor
                }
                if (integrator == Integrator::rattle || drift != DriftControl::none) {
                    EXPECT_NEAR(length(system.position(p)), radius, 1e-3 * radius);
                }
            }
}

TEST(BaumgarteGains, FeedbackStrongerThanAStepCanCarryIsHeldAtOmegaDtOneHalf) {
    // ks = 1e9/s² at dt = 1/60 is ω·dt ≈ 527: uncapped, each step would overshoot the
    // violation ~10⁵ times. Held at ks ≤ 1/(4dt²), kd ≤ 1/dt (critical damping at ω·dt = ½),
    // a pendulum started 10 px long of its rod settles onto it.
    for (Integrator integrator : all_integrators()) {
        if (integrator == Integrator::rattle) continue;  // RATTLE has no Baumgarte feedback
        SCOPED_TRACE(std::string(to_string(integrator)));
        ParticleSystem system({.integrator = integrator, .drift = {.stiffness = 1e9}});
        const auto bob = system.create_particle({.position = {rod + 10.0, 0}});
        system.add_gravity({0, g});
        system.create_anchor(bob, {0, 0}, rod);
        for (int k = 0; k < 300; ++k) {
            ASSERT_EQ(system.step(dt).status, SolveStatus::ok) << "step " << k;
            ASSERT_LT(length(system.position(bob)), rod + 10.0 + 1e-9) << "step " << k;
        }
        // Critically damped at ω = 30/s the violation decays by ~e per two steps, down to the
        // truncation error that gravity and the swing feed in each step (well below 0.1 px).
        EXPECT_NEAR(length(system.position(bob)), rod, 0.1);
    }
}
