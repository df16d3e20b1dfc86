// Dynamics: every claim checked against independent truth — closed forms (the seed's and
// the corrected constraint force, elliptic-integral periods), finite differences,
// conservation laws and the agreement of two independent methods.
#include <grape/dynamics.hpp>

#include "seed_dynamics.hpp"
#include "seed_paths.hpp"

#include "error_text.hpp"
#include "periods.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace grape;
using namespace grape::scenes;

using grape::testing::elliptic_e;
using grape::testing::ZeroCrossings;
using grape::testing::fast_build;

// E(m) by the arithmetic–geometric mean (0 ≤ m < 1), an independent check of the quadrature.
double elliptic_e_agm(double m) {
    double a = 1.0, b = std::sqrt(1.0 - m), c2 = m, sum = 0.5 * c2, power = 0.5;
    for (int i = 0; i < 30 && c2 > 1e-300; ++i) {
        const double an = 0.5 * (a + b);
        const double cn = 0.5 * (a - b);
        b = std::sqrt(a * b);
        a = an;
        c2 = cn * cn;
        power *= 2.0;
        sum += power * c2;
    }
    return pi / (2.0 * a) * (1.0 - sum);
}
// E(−k²) = √(1 + k²)·E(k²/(1 + k²)) (imaginary-modulus transformation).
double elliptic_e_negative_agm(double k2) { return std::sqrt(1.0 + k2) * elliptic_e_agm(k2 / (1.0 + k2)); }

// Exact period on the parabola released from rest at x0 (dynamics-anchors.md):
// T = 4·√(50/g)·E(−(x0/50)²).
double parabola_period(double x0, double g) { return 4.0 * std::sqrt(50.0 / g) * elliptic_e(-(x0 / 50.0) * (x0 / 50.0)); }

// Exact x(t) on the parabola released from rest at x0: with x = x0·sin φ, energy gives
// √(1 + k² sin²φ)·dφ = ω0·dt (k = x0/50, ω0 = √(g/50)), so E(φ | −k²) = E(−k²) + ω0·t,
// solved for φ by the safeguarded Newton of math.hpp (dE/dφ is the integrand).
double parabola_x(double x0, double g, double t) {
    const double k2 = (x0 / 50) * (x0 / 50), w0 = std::sqrt(g / 50);
    auto integrand = [k2](double p) { return std::sqrt(1.0 + k2 * std::sin(p) * std::sin(p)); };
    const double target = integrate(integrand, 0.0, pi / 2, 1e-15) + w0 * t;
    auto f = [&](double p) { return std::pair{integrate(integrand, 0.0, p, 1e-15) - target, integrand(p)}; };
    // 1 ≤ integrand ≤ √(1 + k²) brackets φ.
    const double lo = pi / 2 + w0 * t / std::sqrt(1 + k2) - 1e-9, hi = pi / 2 + w0 * t + 1e-9;
    return x0 * std::sin(find_root(f, lo, hi, 0.5 * (lo + hi), 1e-15).x);
}

// A valid state on the parabola: on the curve, velocity tangent to it.
struct ParabolaSample {
    Vec2 x, v;
};
ParabolaSample random_parabola_state(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> ux(-200.0, 200.0), uv(-400.0, 400.0);
    const double x = ux(rng), vx = uv(rng);
    return {{x, -x * x / 100.0}, {vx, -x * vx / 50.0}};
}

// Witkin's solver on one particle held on the parabola at the given state: constraint force
// and acceleration.
struct SolverResult {
    Vec2 force, acceleration;
};
SolverResult solver_force(const ParabolaSample& s, double mass, Vec2 applied) {
    ParticleSystem system({.drift = {.method = DriftControl::none}});
    const auto p = system.create_particle({.position = s.x, .velocity = s.v, .mass = mass});
    system.add_force([applied](const ForceContext& c) { c.forces[0] += applied; });
    system.create_implicit(p, seed_parabola_curve());
    std::vector<Vec2> a(1);
    EXPECT_EQ(system.evaluate(a), SolveStatus::ok);
    return {system.constraint_forces()[0], a[0]};
}

double relative(Vec2 a, Vec2 b) { return length(a - b) / std::max(length(a), length(b)); }

// ---------------------------------------------------------------------------------------
// Automatic differentiation
// ---------------------------------------------------------------------------------------

TEST(Jet2, GradientAndHessianMatchHandDerivatives) {
    // f = sin(x)·y² + exp(x·y)/(1 + x²) + √(x² + y²)·log(2 + y) + (1 + x)^2.5 and its
    // derivatives worked out by hand.
    auto f = [](auto x, auto y) { return sin(x) * y * y + exp(x * y) / (1.0 + x * x) + sqrt(x * x + y * y) * log(2.0 + y) + pow(1.0 + x, 2.5); };
    std::mt19937_64 rng(grape::testing::test_seed(7));
    std::uniform_real_distribution<double> u(0.1, 1.5);
    for (int i = 0; i < 200; ++i) {
        const double x = u(rng), y = u(rng);
        const Jet2 j = f(Jet2::x(x), Jet2::y(y));
        const double e = std::exp(x * y), q = 1.0 + x * x, r = std::sqrt(x * x + y * y), l = std::log(2.0 + y);
        const double fx = std::cos(x) * y * y + (y * e * q - 2 * x * e) / (q * q) + x / r * l + 2.5 * std::pow(1 + x, 1.5);
        const double fy = 2 * std::sin(x) * y + x * e / q + y / r * l + r / (2 + y);
        // second derivatives
        const double g = e / q;  // exp(xy)/(1+x²)
        const double gx = y * g - 2 * x * g / q;
        const double gxx = y * gx - 2 * g / q - 2 * x * (gx * q - g * 2 * x) / (q * q);
        const double gxy = g + x * y * g - 2 * x * x * g / q;
        const double gyy = x * x * g;
        const double r3 = r * r * r;
        const double fxx = -std::sin(x) * y * y + gxx + (y * y / r3) * l + 3.75 * std::pow(1 + x, 0.5);
        const double fxy = 2 * std::cos(x) * y + gxy + (-x * y / r3) * l + x / r / (2 + y);
        const double fyy = 2 * std::sin(x) + gyy + (x * x / r3) * l + 2 * y / r / (2 + y) - r / ((2 + y) * (2 + y));
        // All terms are O(1–10) here; 1e-13 is ~100 ulp of the largest, room for the different
        // evaluation orders.
        EXPECT_NEAR(j.v, f(x, y), 1e-13);
        EXPECT_NEAR(j.gx, fx, 1e-13);
        EXPECT_NEAR(j.gy, fy, 1e-13);
        EXPECT_NEAR(j.hxx, fxx, 1e-12);
        EXPECT_NEAR(j.hxy, fxy, 1e-12);
        EXPECT_NEAR(j.hyy, fyy, 1e-12);
    }
}

TEST(ImplicitFunction, AutomaticAndHandWrittenParabolaAgreeExactly) {
    const auto automatic = seed_parabola_curve();
    const auto hand = seed_parabola_curve_analytic();
    for (double x : {-200.0, -3.5, 0.0, 17.25, 150.0}) {
        const Vec2 p{x, 0.3 * x - 7};
        const auto a = automatic(p), h = hand(p);
        EXPECT_EQ(a.value, h.value);
        EXPECT_EQ(a.gradient, h.gradient);
        EXPECT_EQ(a.hxx, h.hxx);
        EXPECT_EQ(a.hxy, h.hxy);
        EXPECT_EQ(a.hyy, h.hyy);
    }
}

// ---------------------------------------------------------------------------------------
// Constraint derivatives: Ċ = J·v and J̇q̇ against finite differences, every kind
// ---------------------------------------------------------------------------------------

// Along the straight motion x(s) = x + s·v (zero acceleration), dC/ds = J·v = Ċ and
// d²C/ds² = J̇q̇. Central differences with step h have error O(h²·C⁽³⁾) + O(ε·C/h):
// h = 1e-4 keeps both near 1e-7 relative for the O(1) scales used here.
void check_rows_against_finite_differences(ParticleSystem& system, const std::string& what) {
    const std::size_t n = system.size();
    std::vector<Vec2> x(system.positions().begin(), system.positions().end());
    std::vector<Vec2> v(system.velocities().begin(), system.velocities().end());
    const auto rows = system.constraint_rows();
    auto values_at = [&](double s) {
        for (std::size_t i = 0; i < n; ++i) system.set_position({static_cast<std::uint32_t>(i)}, x[i] + s * v[i]);
        std::vector<double> c;
        for (const auto& r : system.constraint_rows()) c.push_back(r.value);
        return c;
    };
    const double h = 1e-4;
    const auto cp = values_at(h), cm = values_at(-h), c0 = values_at(0.0);
    ASSERT_FALSE(rows.empty());
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const double rate = (cp[r] - cm[r]) / (2 * h);
        const double second = (cp[r] - 2 * c0[r] + cm[r]) / (h * h);
        const double scale = 1.0 + std::abs(rows[r].rate) + std::abs(rows[r].jdot_v);
        EXPECT_NEAR(rows[r].rate, rate, 1e-7 * scale) << what << " row " << r;
        EXPECT_NEAR(rows[r].jdot_v, second, 1e-5 * scale) << what << " row " << r;  // second difference: ε·C/h² ≈ 1e-8·C
        EXPECT_EQ(rows[r].value, c0[r]);
    }
}

TEST(Constraints, RateAndCurvatureTermMatchFiniteDifferencesForEveryKind) {
    std::mt19937_64 rng(grape::testing::test_seed(11));
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    auto rv = [&] { return Vec2{u(rng), u(rng)}; };
    for (int trial = 0; trial < 20; ++trial) {
        ParticleSystem system;
        const auto a = system.create_particle({.position = rv(), .velocity = rv()});
        const auto b = system.create_particle({.position = rv() + Vec2{2, 0}, .velocity = rv()});
        const auto c = system.create_particle({.position = rv() - Vec2{2, 0}, .velocity = rv()});
        system.create_distance(a, b, 1.5);
        system.create_anchor(c, {0.3, -0.2}, 0.7);
        system.create_fixed_point(a, {0.1, 0.2});
        system.create_implicit(b, ImplicitFunction::from_function([](auto x, auto y) { return x * x * y + sin(x) - 0.5 * y * y; }));
        system.create_implicit(c, ImplicitFunction([](Vec2 p) {  // a hand-written ellipse
            return ImplicitSample{p.x * p.x / 4 + p.y * p.y - 1, {p.x / 2, 2 * p.y}, 0.5, 0.0, 2.0};
        }));
        // A user constraint: the signed area of triangle (a, b, c) held constant.
        system.create_constraint({{a, b, c}, [](std::span<const Vec2> x, std::span<const Vec2> v, UserConstraintOutput& out) {
                                   const Vec2 e1 = x[1] - x[0], e2 = x[2] - x[0];
                                   out.value = 0.5 * cross(e1, e2) - 0.25;
                                   // ∂/∂x1 = ½ perp-ish terms of the cross product
                                   const Vec2 g1{0.5 * e2.y, -0.5 * e2.x}, g2{-0.5 * e1.y, 0.5 * e1.x};
                                   out.jacobian[1] = g1;
                                   out.jacobian[2] = g2;
                                   out.jacobian[0] = -(g1 + g2);
                                   out.jdot_v = cross(v[1] - v[0], v[2] - v[0]);
                               }});
        check_rows_against_finite_differences(system, "trial " + std::to_string(trial));
    }
}

// ---------------------------------------------------------------------------------------
// The seed's closed forms and its defect
// ---------------------------------------------------------------------------------------

TEST(Seed, GravityOnlySeedCorrectedAndSolverAgreeAtRandomStates) {
    std::mt19937_64 rng(grape::testing::test_seed(2026));
    std::uniform_real_distribution<double> um(0.5, 3.0);
    double worst = 0.0;
    for (int i = 0; i < 1000; ++i) {
        const auto s = random_parabola_state(rng);
        const double m = um(rng);
        const Vec2 weight{0.0, m * 500.0};
        const Vec2 seed = seed_constraint_force(m, s.x, s.v, weight);
        const Vec2 corrected = corrected_constraint_force(m, s.x, s.v, weight);
        const Vec2 solver = solver_force(s, m, weight).force;
        worst = std::max({worst, relative(seed, corrected), relative(seed, solver)});
    }
    // Each force is a handful of operations on O(1e5) terms: a few ulp relative, so 1e-12
    // leaves three orders of margin.
    EXPECT_LT(worst, 1e-12);
}

TEST(Seed, SidewaysForceBreaksTheSeedFormulaButNotTheCorrectedOne) {
    std::mt19937_64 rng(grape::testing::test_seed(99));
    std::uniform_real_distribution<double> uf(-800.0, 800.0);
    int seed_off_curve = 0;
    for (int i = 0; i < 1000; ++i) {
        const auto s = random_parabola_state(rng);
        const double m = 1.5;
        const Vec2 applied{uf(rng), m * 500.0};
        const Vec2 corrected = corrected_constraint_force(m, s.x, s.v, applied);
        const auto solved = solver_force(s, m, applied);
        EXPECT_LT(relative(corrected, solved.force), 1e-12);
        // C̈ = 2vx² + 2x·ax + 100·ay. Its terms are up to ~1e7 here, so round-off allows
        // ~1e-8 of absolute error: 1e-9 relative to the largest term.
        auto c_ddot = [&](Vec2 a) { return 2 * s.v.x * s.v.x + 2 * s.x.x * a.x + 100 * a.y; };
        auto c_scale = [&](Vec2 a) { return 2 * s.v.x * s.v.x + std::abs(2 * s.x.x * a.x) + std::abs(100 * a.y); };
        const Vec2 a_corrected = (applied + corrected) / m;
        EXPECT_NEAR(c_ddot(a_corrected), 0.0, 1e-12 * c_scale(a_corrected));
        EXPECT_NEAR(c_ddot(solved.acceleration), 0.0, 1e-12 * c_scale(solved.acceleration));
        // The seed's force leaves exactly C̈ = −2·x·Fext.x/m.
        const Vec2 a_seed = (applied + seed_constraint_force(m, s.x, s.v, applied)) / m;
        const double expected = -2.0 * s.x.x * applied.x / m;
        EXPECT_NEAR(c_ddot(a_seed), expected, 1e-12 * c_scale(a_seed));
        if (std::abs(c_ddot(a_seed)) > 1e-6 * c_scale(a_seed)) ++seed_off_curve;
    }
    EXPECT_GT(seed_off_curve, 990);  // nonzero except where x·Fx happens to be tiny
}

TEST(Seed, SidewaysForceSimulationSeedLeavesTheCurveSolverStaysOn) {
    // Same run, 5 s with a constant wind of 100: the seed's formula drifts off by C̈ ≠ 0, the
    // general solver (with projection) stays at round-off.
    const ParabolaSetup seed{.method = ParabolaMethod::seed, .force_x = 100.0};
    ParabolaSetup solver = seed;
    solver.method = ParabolaMethod::implicit;
    solver.drift = {.method = DriftControl::projection};
    const auto a = run_parabola(seed, 1.0 / 240, 5.0);
    const auto b = run_parabola(solver, 1.0 / 240, 5.0);
    EXPECT_GT(a.max_distance, 1.0);     // pixels off the curve
    EXPECT_LT(b.max_distance, 1e-9);
    EXPECT_LT(std::abs(b.final.energy - b.initial.energy), 1e-6 * std::abs(b.initial.energy));
}

TEST(Seed, ParametricFormulaIsTheGeneralBeadFormula) {
    std::mt19937_64 rng(grape::testing::test_seed(5));
    std::uniform_real_distribution<double> uq(-300.0, 300.0), ur(-500.0, 500.0), ug(1.0, 1000.0), um(0.1, 10.0);
    for (int i = 0; i < 1000; ++i) {
        const double q = uq(rng), r = ur(rng), g = ug(rng), m = um(rng);
        const double general = bead_acceleration(seed_parabola_frame(q), {0.0, m * g}, m, r);
        const double seed = seed_parametric_acceleration(q, r, g);
        EXPECT_NEAR(general, seed, 1e-13 * (std::abs(q * r * r) + 50 * g * std::abs(q)) / (2500 + q * q));
        // And Witkin's x-acceleration on the same state is the same number.
        const ParabolaSample s{{q, -q * q / 100}, {r, -q * r / 50}};
        const double ax = solver_force(s, m, {0.0, m * g}).acceleration.x;
        EXPECT_NEAR(ax, seed, 1e-12 * (1 + std::abs(seed)) * (1 + r * r / 1e4));
    }
}

// ---------------------------------------------------------------------------------------
// Integrators
// ---------------------------------------------------------------------------------------

TEST(Integrators, MeasuredOrderOfConvergence) {
    // Constrained motion (implicit parabola, no feedback, x0 = 200, 1 s): halving dt divides
    // the error in x(1) by 2^order. The reference is the exact elliptic-integral solution.
    const double exact = parabola_x(200, 500, 1.0);
    struct Case {
        Integrator integrator;
        double dt;  // coarse enough for the error to stay far above round-off
    };
    for (Case c : {Case{Integrator::euler, 1.0 / 400}, Case{Integrator::semi_implicit_euler, 1.0 / 400},
                   Case{Integrator::midpoint, 1.0 / 200}, Case{Integrator::velocity_verlet, 1.0 / 200},
                   Case{Integrator::rk4, 1.0 / 40}, Case{Integrator::rk45, 1.0 / 40}}) {
        ParabolaSetup s{.integrator = c.integrator, .x0 = 200};
        s.rk45.tolerance = 0.0;  // fixed step: measure the formula, not the controller
        const double e1 = std::abs(run_parabola(s, c.dt, 1.0).final.x.x - exact);
        const double e2 = std::abs(run_parabola(s, c.dt / 2, 1.0).final.x.x - exact);
        const double e3 = std::abs(run_parabola(s, c.dt / 4, 1.0).final.x.x - exact);
        const double p1 = std::log2(e1 / e2), p2 = std::log2(e2 / e3);
        const int expected = order(c.integrator);
        // Asymptotic: the second ratio is within 0.2 of the formal order.
        EXPECT_NEAR(p2, expected, 0.2) << to_string(c.integrator) << " first ratio " << p1 << " errors " << e1 << " " << e2
                                       << " " << e3;
    }
}

TEST(Integrators, Rk45MeetsItsToleranceAndAdaptsItsStep) {
    const double exact = parabola_x(100, 500, 2.0);
    double previous = 1.0;
    for (double tol : {1e-6, 1e-8, 1e-10}) {
        ParabolaSetup s{.method = ParabolaMethod::parametric, .integrator = Integrator::rk45};
        s.rk45.tolerance = tol;
        const double error = std::abs(run_parabola(s, 0.5, 2.0).final.x.x - exact);
        // Local tolerance relative to 1 + |y| (|y| ≤ ~300 here), accumulated over ~tens of
        // sub-steps: the global error stays within 1e4·tol and falls as tol does.
        EXPECT_LT(error, 1e4 * tol) << tol;
        EXPECT_LT(error, previous);
        previous = error;
    }
}

TEST(Integrators, StepperWorksOnAUserSystem) {
    // Harmonic oscillator q̈ = −q: exact q = cos t. RK4 at dt = 0.01 over 2π: error ~ dt⁴·t/120.
    struct Oscillator final : SecondOrderSystem {
        std::size_t size() const noexcept override { return 1; }
        void acceleration(double, std::span<const double> q, std::span<const double>, std::span<double> a) noexcept override {
            a[0] = -q[0];
        }
    } oscillator;
    Stepper stepper(Integrator::rk4);
    double q = 1.0, v = 0.0;
    const int n = 628;
    for (int i = 0; i < n; ++i) stepper.step(oscillator, i * 0.01, {&q, 1}, {&v, 1}, 0.01);
    EXPECT_NEAR(q, std::cos(6.28), 1e-9);
    EXPECT_NEAR(v, -std::sin(6.28), 1e-9);
}

// ---------------------------------------------------------------------------------------
// The parabola: both methods, periods, drift
// ---------------------------------------------------------------------------------------

TEST(Parabola, ImplicitAndParametricGiveTheSameXOverSixtySeconds) {
    // Without feedback, λ depends only on (x, vx) for this curve, so the implicit (x, vx)
    // subsystem is the Lagrange ODE: same integrator, same dt → same x(t) up to round-off.
    for (Integrator integrator : {Integrator::euler, Integrator::semi_implicit_euler, Integrator::midpoint,
                                  Integrator::rk4, Integrator::velocity_verlet}) {
        ParabolaRun implicit({.method = ParabolaMethod::implicit, .integrator = integrator});
        ParabolaRun parametric({.method = ParabolaMethod::parametric, .integrator = integrator});
        double worst = 0.0;
        for (int i = 0; i < 3600; ++i) {
            implicit.step(1.0 / 60);
            parametric.step(1.0 / 60);
            worst = std::max(worst, std::abs(implicit.state().x.x - parametric.state().x.x));
        }
        EXPECT_LT(worst, 1e-9 * 100.0) << to_string(integrator);
    }
}

TEST(Parabola, ExactSolutionIsConsistent) {
    // Released from rest at x0: x(0) = x0, x(T/2) = −x0, x(T/4) = 0.
    const double period = parabola_period(100, 500);
    EXPECT_NEAR(parabola_x(100, 500, 0.0), 100, 1e-12);
    EXPECT_NEAR(parabola_x(100, 500, period / 2), -100, 1e-9);
    EXPECT_NEAR(parabola_x(100, 500, period / 4), 0, 1e-9);
    // RK4 at dt = 1/60 reproduces the anchors note's reference x(1) = −45.1141795561444 by
    // both methods (15 digits quoted: 1e-12 absolute).
    for (auto method : {ParabolaMethod::implicit, ParabolaMethod::parametric})
        EXPECT_NEAR(run_parabola({.method = method}, 1.0 / 60, 1.0).final.x.x, -45.1141795561444, 1e-12);
}

TEST(Parabola, EllipticIntegralsByQuadratureAndByAgmAgree) {
    for (double x0 : {10.0, 100.0, 200.0}) {
        const double k2 = (x0 / 50) * (x0 / 50);
        EXPECT_NEAR(elliptic_e(-k2), elliptic_e_negative_agm(k2), 1e-14 * elliptic_e(-k2));
    }
    // Series T/T0 = 1 + k²/4 − 3k⁴/64 + … at x0 = 10 (k² = 0.04): 1.009926 (anchors note).
    EXPECT_NEAR(parabola_period(10, 500) / (2 * pi * std::sqrt(50.0 / 500)), 1.009926, 5e-7);
}

TEST(Parabola, PeriodMatchesTheEllipticIntegralClosedForm) {
    for (auto method : {ParabolaMethod::implicit, ParabolaMethod::parametric}) {
        for (double x0 : {10.0, 100.0, 200.0}) {
            ParabolaSetup setup{.method = method, .x0 = x0};
            ParabolaRun run(setup);
            ZeroCrossings vx;
            const double dt = 1.0 / 240;
            const int steps = fast_build ? 30 * 240 : 10 * 240;
            // vx and its derivative ax = q̈ (the parametric x is q; the implicit x-equation is the same ODE)
            auto sample = [&] {
                const auto s = run.state();
                const double ax = seed_parametric_acceleration(s.x.x, s.v.x, setup.g);
                vx.add(s.t, s.v.x, ax);
            };
            sample();
            for (int i = 0; i < steps; ++i) {
                run.step(dt);
                sample();
            }
            const double expected = parabola_period(x0, setup.g);
            ASSERT_GE(vx.times.size(), 3u);
            // RK4's phase error at dt = 1/240 is ~1e-9 s per period; the interpolation's
            // error O(dt⁴·|vx⁗|) ~1e-9: 1e-6 s leaves a 1000× margin.
            EXPECT_NEAR(vx.period(), expected, 1e-6) << to_string(method) << " x0 " << x0;
        }
    }
    // x0 = 10 is already 1% off the small-amplitude limit.
    EXPECT_GT(parabola_period(10, 500) / (2 * pi * std::sqrt(50.0 / 500)), 1.0099);
}

TEST(Parabola, DriftMatchesTheExpectedOrders) {
    const double dt = 1.0 / 60;
    const double long_run = fast_build ? 600.0 : 120.0;
    auto rel = [](const ParabolaSummary& s) { return (s.final.energy - s.initial.energy) / std::abs(s.initial.energy); };
    // Implicit RK4 without control: ~65 px² after 60 s, growing as t².
    const auto none60 = run_parabola({}, dt, 60.0);
    EXPECT_GT(none60.max_residual, 30.0);
    EXPECT_LT(none60.max_residual, 130.0);
    const auto none_long = run_parabola({}, dt, long_run);
    const double growth = none_long.max_residual / none60.max_residual;
    const double t2 = (long_run / 60) * (long_run / 60);
    EXPECT_GT(growth, 0.5 * t2);
    EXPECT_LT(growth, 2.0 * t2);
    // Baumgarte, ω·dt = 0.05: a plateau below 2e-2 px² and |ΔE/E| < 1e-3.
    const auto baumgarte = run_parabola({.drift = {.method = DriftControl::baumgarte}}, dt, long_run);
    EXPECT_LT(baumgarte.max_residual, 2e-2);
    EXPECT_LT(std::abs(rel(baumgarte)), 1e-3);
    // Projection: at round-off (C ~ ulp(1e4) ≈ 2e-12 px², distance ~1e-14 px).
    const auto projection = run_parabola({.drift = {.method = DriftControl::projection}}, dt, long_run);
    EXPECT_LT(projection.max_distance, 1e-9);
    // Parametric RK4: on the curve, slightly dissipative (−3e-4 < ΔE/E < 0 at 600 s).
    const auto parametric = run_parabola({.method = ParabolaMethod::parametric}, dt, long_run);
    EXPECT_LT(parametric.max_distance, 1e-12);
    EXPECT_LT(rel(parametric), 0.0);
    EXPECT_GT(rel(parametric), -3e-4 * long_run / 600);
    // Adaptive RK45 at tolerance 1e-10.
    const auto rk45 = run_parabola({.method = ParabolaMethod::parametric, .integrator = Integrator::rk45}, dt, long_run);
    EXPECT_LT(std::abs(rel(rk45)), 1e-8);
}

}  // namespace
