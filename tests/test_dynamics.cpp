// Dynamics: every claim checked against independent truth — closed forms (the seed's and
// the corrected constraint force, elliptic-integral periods), finite differences,
// conservation laws and the agreement of two independent methods.
#include <grape/dynamics.hpp>

#include "seed_dynamics.hpp"
#include "seed_paths.hpp"

#include "error_text.hpp"

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

using grape::testing::expect_error;
using grape::testing::fast_build;

// Complete elliptic integrals in parameter form by adaptive Gauss–Legendre quadrature of
// their defining integrals (smooth integrands for m < 1).
double elliptic_e(double m) {
    return integrate([m](double t) { return std::sqrt(1.0 - m * std::sin(t) * std::sin(t)); }, 0.0, pi / 2, 1e-15);
}
double elliptic_k(double m) {
    return integrate([m](double t) { return 1.0 / std::sqrt(1.0 - m * std::sin(t) * std::sin(t)); }, 0.0, pi / 2,
                     1e-15);
}
// The same by the arithmetic–geometric mean (0 ≤ m < 1), an independent check of the quadrature.
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

// Times where a sampled signal s(t) (with derivative ds) crosses zero, each located by the
// root of the cubic Hermite interpolant over its step.
struct ZeroCrossings {
    std::vector<double> times;
    bool have = false;
    double t0 = 0, s0 = 0, d0 = 0;
    void add(double t, double s, double d) {
        if (have && ((s0 < 0.0 && s >= 0.0) || (s0 > 0.0 && s <= 0.0))) {
            const double h = t - t0;
            auto hermite = [&](double u) {
                const double u2 = u * u, u3 = u2 * u;
                return std::pair{(2 * u3 - 3 * u2 + 1) * s0 + (u3 - 2 * u2 + u) * h * d0 + (-2 * u3 + 3 * u2) * s +
                                     (u3 - u2) * h * d,
                                 (6 * u2 - 6 * u) * s0 + (3 * u2 - 4 * u + 1) * h * d0 + (-6 * u2 + 6 * u) * s +
                                     (3 * u2 - 2 * u) * h * d};
            };
            times.push_back(t0 + h * find_root(hermite, 0.0, 1.0, 0.5, 1e-15).x);
        }
        have = true;
        t0 = t;
        s0 = s;
        d0 = d;
    }
    // Full period from the first and last crossing (crossings are half a period apart).
    double period() const { return 2.0 * (times.back() - times.front()) / static_cast<double>(times.size() - 1); }
};

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
    std::mt19937_64 rng(7);
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
    std::mt19937_64 rng(11);
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
    std::mt19937_64 rng(2026);
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
    std::mt19937_64 rng(99);
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
    std::mt19937_64 rng(5);
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
    ParticleSystem anchor, user;
    for (ParticleSystem* s : {&anchor, &user}) {
        const auto p = s->create_particle({.position = {0.6, 0.8}, .velocity = {-1, 0.75}});
        s->add_gravity({0, 9.81});
        if (s == &anchor) s->create_anchor(p, {0, 0}, 1.0);
        else
            s->create_constraint({{p}, [](std::span<const Vec2> x, std::span<const Vec2> v, UserConstraintOutput& out) {
                                   out.value = 0.5 * (dot(x[0], x[0]) - 1.0);
                                   out.jacobian[0] = x[0];
                                   out.jdot_v = dot(v[0], v[0]);
                               }});
    }
    for (int i = 0; i < 240; ++i) {
        anchor.step(1.0 / 240);
        user.step(1.0 / 240);
    }
    EXPECT_EQ(anchor.positions()[0], user.positions()[0]);
    // A fixed point holds against gravity and a spring.
    ParticleSystem fixed;
    const auto a = fixed.create_particle({.position = {0, 0}});
    const auto b = fixed.create_particle({.position = {1, 0}});
    fixed.add_gravity({0, 9.81});
    fixed.add_spring(a, b, {.rest_length = 0.5, .stiffness = 50});
    fixed.create_fixed_point(a, {0, 0});
    for (int i = 0; i < 240; ++i) fixed.step(1.0 / 240);
    EXPECT_LT(length(fixed.positions()[0]), 1e-9);
    EXPECT_GT(length(fixed.positions()[1] - Vec2{1, 0}), 0.1);
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

TEST(Names, RoundTrip) {
    EXPECT_EQ(all_integrators().size(), 7u);
    for (Integrator i : all_integrators()) EXPECT_EQ(parse_integrator(to_string(i)), i);
    EXPECT_EQ(parse_integrator("symplectic"), Integrator::semi_implicit_euler);
    EXPECT_EQ(parse_integrator("verlet"), Integrator::velocity_verlet);
    EXPECT_EQ(all_drift_controls().size(), 3u);
    for (DriftControl d : all_drift_controls()) EXPECT_EQ(parse_drift_control(to_string(d)), d);
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
