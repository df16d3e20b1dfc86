// Your own easing against independent truth: SVG-data curves against a long double bisection
// on control points worked out here (S and T reflections by hand), springs against the ODE
// integrated by RK4 at a tiny step and against the closed forms' special points, function
// curves against the callable, and the engine's curve table keeping callables alive.
#include <grape/anim.hpp>
#include <grape/curve.hpp>
#include <grape/error.hpp>
#include <grape/path.hpp>

#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

using grape::Curve;
using grape::testing::expect_error;

namespace {

constexpr double eps = 2.220446049250313e-16;

// --- reference for SVG curves: y at x on absolute cubic pieces, long double bisection -------

struct Cubic {
    std::array<long double, 4> x, y;
};

long double bez(const std::array<long double, 4>& p, long double s) {
    const long double m = 1 - s;
    return m * m * m * p[0] + 3 * m * m * s * p[1] + 3 * m * s * s * p[2] + s * s * s * p[3];
}

double y_at(const std::vector<Cubic>& pieces, double t) {
    for (const Cubic& c : pieces) {
        if (t > c.x[3]) continue;
        long double lo = 0, hi = 1;
        for (int i = 0; i < 120; ++i) {
            const long double mid = (lo + hi) / 2;
            (bez(c.x, mid) < t ? lo : hi) = mid;
        }
        return static_cast<double>(bez(c.y, (lo + hi) / 2));
    }
    return static_cast<double>(pieces.back().y[3]);
}

}  // namespace

// --- SVG path data ---------------------------------------------------------------------------

TEST(SvgCurve, OneCubicIsCssCubicBezier) {
    const Curve svg = Curve::svg("M0,0 C0.42,0 0.58,1 1,1");
    const Curve css = Curve::cubic_bezier(0.42, 0, 0.58, 1);
    // Both solve from the nearer end with the same Bernstein sums: the same to a few ulp.
    for (int i = 0; i <= 1000; ++i) EXPECT_NEAR(svg(i / 1000.0), css(i / 1000.0), 4 * eps) << i;
    EXPECT_EQ(svg(0.0), 0.0);
    EXPECT_EQ(svg(1.0), 1.0);
    EXPECT_EQ(svg.kind(), grape::CurveKind::svg);
}

TEST(SvgCurve, MultiSegmentPathsWithReflectionsMatchABisectionOnTheirControlPoints) {
    // C then S (first control = reflection of (0.2, 0.7) about (0.4, 0.7): (0.6, 0.7)),
    // then Q and T (control reflected about (0.85, 1.05) from (0.8, 1.1): (0.9, 1.0)).
    const Curve c = Curve::svg("M0,0 C0.1,0.5 0.2,0.7 0.4,0.7 S0.7,1.2 0.75,1 Q0.8,1.1 0.85,1.05 T1,1");
    const auto quad = [](long double x0, long double y0, long double x1, long double y1, long double x2, long double y2) {
        return Cubic{{x0, x0 + 2 * (x1 - x0) / 3, x2 + 2 * (x1 - x2) / 3, x2}, {y0, y0 + 2 * (y1 - y0) / 3, y2 + 2 * (y1 - y2) / 3, y2}};
    };
    const std::vector<Cubic> pieces = {
        {{0, 0.1L, 0.2L, 0.4L}, {0, 0.5L, 0.7L, 0.7L}},
        {{0.4L, 0.6L, 0.7L, 0.75L}, {0.7L, 0.7L, 1.2L, 1}},
        quad(0.75L, 1, 0.8L, 1.1L, 0.85L, 1.05L),
        quad(0.85L, 1.05L, 0.9L, 1.0L, 1, 1),
    };
    // The pieces' slopes stay below 10 in |dy/dx| on this path; the solve is exact to a few
    // ulp of s, so y is within 10·(a few ulp) + a few ulp of O(1) values: 64 ulp.
    for (int i = 0; i <= 2000; ++i) {
        const double t = i / 2000.0;
        EXPECT_NEAR(c(t), y_at(pieces, t), 64 * eps) << "t = " << t;
    }
}

TEST(SvgCurve, RelativeCommandsGiveTheSameCurve) {
    const Curve absolute = Curve::svg("M0,0 C0.1,0.5 0.2,0.7 0.4,0.7 S0.7,1.2 1,1");
    const Curve relative = Curve::svg("m0,0 c0.1,0.5 0.2,0.7 0.4,0.7 s0.3,0.5 0.6,0.3");
    // 0.4 + 0.3 is 0.7 only to rounding: the control points differ by an ulp, y by a few.
    for (int i = 0; i <= 1000; ++i) EXPECT_NEAR(absolute(i / 1000.0), relative(i / 1000.0), 16 * eps) << i;
    EXPECT_EQ(relative(1.0), 1.0);
}

TEST(SvgCurve, LinesQuadraticsAndJumps) {
    // Q with its control at mid-x: x = s, y = s², so y = x² exactly.
    const Curve parabola = Curve::svg("M0,0 Q0.5,0 1,1");
    for (int i = 0; i <= 1000; ++i) {
        const double t = i / 1000.0;
        EXPECT_NEAR(parabola(t), t * t, 8 * eps) << t;
    }
    // H, V and L: flat to ½, a jump to 1 there (its top from ½ on), flat again.
    const Curve step = Curve::svg("M0,0 H0.5 V1 L1,1");
    EXPECT_EQ(step(0.25), 0.0);
    EXPECT_EQ(step(std::nextafter(0.5, 0.0)), 0.0);
    EXPECT_EQ(step(0.5), 1.0);
    EXPECT_EQ(step(0.75), 1.0);
    // Lines interpolate exactly to rounding; overshoot in y is allowed.
    const Curve zig = Curve::svg("M0,0 L0.25,1.5 L0.5,-0.5 L1,1");
    EXPECT_NEAR(zig(0.125), 0.75, 2 * eps);
    EXPECT_NEAR(zig(0.375), 0.5, 2 * eps);
    EXPECT_NEAR(zig(0.75), 0.25, 2 * eps);
    // Outside [0, 1]: the end values.
    EXPECT_EQ(zig(-0.5), 0.0);
    EXPECT_EQ(zig(1.5), 1.0);
    EXPECT_TRUE(std::isnan(zig(NAN)));
}

TEST(SvgCurve, MonotoneDataGivesAMonotoneCurve) {
    std::mt19937_64 rng(grape::testing::test_seed(31));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 50; ++trial) {
        // Three cubics with control points inside their boxes: monotone in x and y.
        std::string d = "M0,0";
        double x = 0, y = 0;
        for (int k = 1; k <= 3; ++k) {
            const double nx = k / 3.0, ny = y + unit(rng) * 0.5;
            const auto in = [&](double a, double b) { return a + (b - a) * unit(rng); };
            d += " C" + grape::detail::number_text(in(x, nx)) + "," + grape::detail::number_text(in(y, ny)) + " " +
                 grape::detail::number_text(in(x, nx)) + "," + grape::detail::number_text(in(y, ny)) + " " +
                 grape::detail::number_text(k == 3 ? 1.0 : nx) + "," + grape::detail::number_text(ny);
            x = nx;
            y = ny;
        }
        const Curve c = Curve::svg(d);
        double previous = c(0.0);
        for (int i = 1; i <= 5000; ++i) {
            const double v = c(i / 5000.0);
            // Exact y is non-decreasing; each value carries a few ulp of rounding.
            ASSERT_GE(v, previous - 8 * eps) << d << " at " << i / 5000.0;
            previous = v;
        }
    }
}

TEST(SvgCurve, BadDataNamesTheSegmentAndTheRule) {
    expect_error([] { (void)Curve::svg("M0,0 C1.2,0 -0.2,1 1,1"); },
                 {"Curve::svg: segment 1 (C from 0,0) goes back in x", "x must never decrease"});
    expect_error([] { (void)Curve::svg("M0,0 L0.5,0.5 C0.9,0.5 0.1,1 1,1"); }, {"segment 2 (C from 0.5,0.5) goes back in x"});
    expect_error([] { (void)Curve::svg("M0,0 L0.6,0.5 L0.4,0.6 L1,1"); }, {"segment 2 (L from 0.6,0.5) goes back in x"});
    expect_error([] { (void)Curve::svg("M0,0 L1,1 Z"); }, {"segment 2 (L from 1,1) goes back in x"});
    expect_error([] { (void)Curve::svg("M0.1,0 L1,1"); }, {"must start at x = 0 (got 0.1)"});
    expect_error([] { (void)Curve::svg("M0,0 L0.9,1"); }, {"must end at x = 1 (got 0.9)"});
    expect_error([] { (void)Curve::svg("M0,0 L0.5,0.5 M0.6,0.5 L1,1"); },
                 {"segment 2 (L from 0.6,0.5) does not start where segment 1 ends (0.5,0.5)", "one continuous path"});
    expect_error([] { (void)Curve::svg("M0,0 A0.5,0.5 0 0 1 1,1"); }, {"segment 1 is an arc"});
    expect_error([] { (void)Curve::svg("M0,0 L1"); }, {"Curve::svg: SVG path data:", "offset"});
    expect_error([] { (void)Curve::svg(""); }, {"draws nothing"});
    // A cubic whose control polygon doubles back but whose x still never decreases is fine:
    // x′/3 = (1−s)² − 2(1−s)s + s² ≥ 0 with b² = ac (a flat point at s = ½).
    EXPECT_NO_THROW((void)Curve::svg("M0,0 C1,0 0,1 1,1"));
}

TEST(SvgCurve, NamesRoundTripExactly) {
    for (const char* data : {"M0,0 C0.2,0 0.3,1 1,1", "m0,0 c0.1,0.5 0.2,0.7 0.4,0.7 s0.3,0.5 0.6,0.3",
                             "M0,0 Q0.5,0 1,1", "M0,0 H0.5 V1 L1,1", "M0,0 C0.1,0.5 0.2,0.7 0.4,0.7 T1,1"}) {
        const Curve c = Curve::svg(data);
        const std::string name = grape::to_string(c);
        SCOPED_TRACE(name);
        EXPECT_EQ(name.rfind("svg(M0,", 0), 0u);
        const Curve back = grape::parse_curve(name);
        EXPECT_EQ(back, c);
        EXPECT_EQ(grape::to_string(back), name);
        for (int i = 0; i <= 100; ++i) EXPECT_EQ(back(i / 100.0), c(i / 100.0));
    }
    EXPECT_EQ(grape::to_string(Curve::svg("M0,0 C0.2,0 0.3,1 1,1")), "svg(M0,0 C0.2,0 0.3,1 1,1)");
    EXPECT_EQ(grape::parse_curve("svg( M0 0 C 0.2 0 0.3 1 1 1 )"), Curve::svg("M0,0 C0.2,0 0.3,1 1,1"));
    EXPECT_FALSE(Curve::svg("M0,0 C0.2,0 0.3,1 1,1") == Curve::svg("M0,0 C0.2,0 0.3,0.9 1,1"));
}

// --- springs ---------------------------------------------------------------------------------

namespace {

// m·x″ + c·x′ + k·x = 0, x(0) = 1, x′(0) = −v0, by classic RK4 at h ≤ 1e-3 / ω0 (written
// here, independent of the closed form), sampled at n + 1 even times over [0, end]. RK4's
// global error on an oscillator is ≈ (hω)⁴·ωτ/120 ≈ 1e-14 for the ωτ ≲ 10³ used here.
struct Ode {
    double k, c, m, v0;
    std::vector<double> samples(double end, int n) const {
        const double omega = std::sqrt(k / m);
        const int per = std::max(1, static_cast<int>(std::ceil(end / n * omega / 1e-3)));
        const double h = end / n / per;
        double x = 1, v = -v0;
        const auto acc = [&](double xx, double vv) { return -(k * xx + c * vv) / m; };
        std::vector<double> out{x};
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < per; ++i) {
                const double k1x = v, k1v = acc(x, v);
                const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
                const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
                const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
                x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
                v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
            }
            out.push_back(x);
        }
        return out;
    }
    double at(double tau) const { return samples(tau, 1).back(); }
};

}  // namespace

TEST(Spring, MatchesTheOdeIntegratedByRk4InEveryRegime) {
    const std::vector<Ode> cases = {
        {100, 4, 1, 0},     // under-damped, ζ = 0.2
        {100, 20, 1, 0},    // critical
        {100, 50, 1, 0},    // over-damped, ζ = 2.5
        {100, 4, 1, 8},     // under, moving towards the target
        {100, 20, 1, -5},   // critical, moving away first
        {100, 50, 1, 30},   // over, fast start: overshoots once
        {170, 26, 2.5, 0},  // mass ≠ 1
        {100, 20.000001, 1, 0}, {100, 19.999999, 1, 0},  // either side of critical
        {100, 400, 1, 0},   // heavily over-damped, ζ = 20
    };
    for (const Ode& o : cases) {
        const Curve c = Curve::spring({.stiffness = o.k, .damping = o.c, .mass = o.m, .velocity = o.v0});
        SCOPED_TRACE(grape::to_string(c));
        const double T = c.settling_time();
        const std::vector<double> x = o.samples(T, 40);
        // The curve removes x(T) linearly: curve(t) = 1 − x(tT) + t·x(T).
        EXPECT_NEAR(std::abs(x[40]), grape::spring_settle_tolerance, 1e-12);
        for (int i = 1; i < 40; ++i) {
            const double t = i / 40.0;
            EXPECT_NEAR(c(t), 1 - x[i] + t * x[40], 1e-12) << "t = " << t;
        }
    }
}

TEST(Spring, ClosedFormsAtSpecialPoints) {
    // Under-damped from rest: the first overshoot peak is at τ = π/ωd, of height e^(−ζπ/√(1−ζ²)).
    const double k = 100, c = 4;
    const double zeta = c / (2 * std::sqrt(k));
    const double wd = std::sqrt(k) * std::sqrt(1 - zeta * zeta);
    const Curve under = Curve::spring({.stiffness = k, .damping = c});
    const double T = under.settling_time();
    const double tp = (3.141592653589793 / wd) / T;
    const double peak = 1 + std::exp(-zeta * 3.141592653589793 / std::sqrt(1 - zeta * zeta));
    // curve(tp) = 1 − x(π/ωd) + tp·x(T) with |x(T)| = tolerance: within tp·1e-3 of the peak.
    EXPECT_NEAR(under(tp), peak, tp * grape::spring_settle_tolerance + 1e-15);
    // It is the maximum: its neighbours are lower.
    EXPECT_LT(under(tp * (1 - 1e-4)), under(tp) + tp * 1e-7);
    // Critical from rest: x(1/ω0) = 2/e.
    const Curve critical = Curve::spring({.stiffness = 100, .damping = 20});
    const double Tc = critical.settling_time();
    const auto xc = [](double tau) { return std::exp(-10 * tau) * (1 + 10 * tau); };
    const double t1 = 0.1 / Tc;
    EXPECT_NEAR(critical(t1), 1 - 2 / std::exp(1.0) + t1 * xc(Tc), 1e-15);
    EXPECT_NEAR(xc(Tc), 1e-3, 1e-15);
    // Over-damped from rest: x = (r2·e^(−r1τ) − r1·e^(−r2τ)) / (r2 − r1), roots of m·r² − c·r + k.
    const Curve over = Curve::spring({.stiffness = 100, .damping = 50});
    const double r1 = (50 - std::sqrt(2500.0 - 400)) / 2, r2 = (50 + std::sqrt(2500.0 - 400)) / 2;
    const double To = over.settling_time();
    const auto x = [&](double tau) { return (r2 * std::exp(-r1 * tau) - r1 * std::exp(-r2 * tau)) / (r2 - r1); };
    for (double t : {0.01, 0.1, 0.5, 0.9}) EXPECT_NEAR(over(t), 1 - x(t * To) + t * x(To), 1e-14) << t;
    // Its settling time solves x(T) = 10⁻³ (monotone approach, no overshoot from rest).
    EXPECT_NEAR(x(To), 1e-3, 1e-15);
}

TEST(Spring, SettlesWhereItsOffsetLastLeavesTheTolerance) {
    for (const grape::SpringCurveDef& def : {grape::SpringCurveDef{.stiffness = 100, .damping = 2},
                                        grape::SpringCurveDef{.stiffness = 300, .damping = 10, .velocity = -20},
                                        grape::SpringCurveDef{.stiffness = 100, .damping = 20, .velocity = 40},
                                        grape::SpringCurveDef{.stiffness = 100, .damping = 60, .velocity = 100}}) {
        const Curve c = Curve::spring(def);
        SCOPED_TRACE(grape::to_string(c));
        const double T = c.settling_time();
        const Ode o{def.stiffness, def.damping, def.mass, def.velocity};
        // After T, |x| stays within the tolerance (sampled to 3T; 1e-12 for the RK4 error).
        const std::vector<double> x = o.samples(3 * T, 600);
        for (int i = 200; i <= 600; ++i) EXPECT_LE(std::abs(x[i]), 1e-3 + 1e-12) << i;
        // Just before T it is still outside: T is the last crossing, not a loose bound.
        EXPECT_GT(std::abs(o.at(T * (1 - 1e-6))), 1e-3);
        EXPECT_EQ(c(0.0), 0.0);
        EXPECT_EQ(c(1.0), 1.0);
        EXPECT_EQ(c(-1.0), 0.0);
        EXPECT_EQ(c(2.0), 1.0);
    }
}

TEST(Spring, ByDurationAndBounceAsSwiftUiGivesThem) {
    // SwiftUI: stiffness (2π/d)², damping 4π(1 − b)/d (b ≥ 0) or 4π/(d(1 + b)) (b < 0), mass 1.
    const double pi = 3.141592653589793;
    for (double b : {0.0, 0.3, 0.7, -0.5}) {
        const double d = 0.5;
        const Curve c = Curve::spring_duration(d, b);
        const double k = (2 * pi / d) * (2 * pi / d);
        const double damping = b >= 0 ? 4 * pi * (1 - b) / d : 4 * pi / (d * (1 + b));
        const Curve same = Curve::spring({.stiffness = k, .damping = damping});
        SCOPED_TRACE(grape::to_string(c));
        EXPECT_NEAR(c.settling_time(), same.settling_time(), 1e-12 * same.settling_time());
        for (int i = 0; i <= 100; ++i) EXPECT_NEAR(c(i / 100.0), same(i / 100.0), 1e-12);
        EXPECT_EQ(grape::parse_curve(grape::to_string(c)), c);
    }
    // bounce 0 is critical damping: no overshoot at all.
    const Curve critical = Curve::spring_duration(0.4);
    for (int i = 0; i <= 1000; ++i) EXPECT_LE(critical(i / 1000.0), 1.0);
    EXPECT_EQ(grape::to_string(Curve::spring_duration(0.5, 0.3)), "spring-duration(0.5,0.3,0)");
}

TEST(Spring, NamesAndErrors) {
    const Curve c = Curve::spring({.stiffness = 170, .damping = 26});
    EXPECT_EQ(grape::to_string(c), "spring(170,26,1,0)");
    EXPECT_EQ(grape::parse_curve("spring(170,26)"), c);
    EXPECT_EQ(grape::parse_curve("spring(170, 26, 1, 0)"), c);
    EXPECT_EQ(grape::parse_curve("spring-duration(0.5)"), Curve::spring_duration(0.5, 0.0));
    EXPECT_FALSE(grape::parse_curve("spring(170,26,1,0)") == grape::parse_curve("spring(170,26,1,1)"));
    expect_error([] { (void)Curve::spring({.stiffness = 100, .damping = 0}); }, {"damping must be finite and > 0 (got 0)"});
    expect_error([] { (void)Curve::spring({.stiffness = -1, .damping = 1}); }, {"stiffness must be finite and > 0"});
    expect_error([] { (void)Curve::spring({.mass = NAN}); }, {"mass must be finite and > 0"});
    expect_error([] { (void)Curve::spring({.velocity = INFINITY}); }, {"velocity must be finite"});
    // ζ ≈ 6e-38: ~1e38 swings before it settles (the count a loop of n ± 1 never got through)
    expect_error([] { (void)grape::parse_curve("spring(100,10,6.6e72,0)"); }, {"swings more than a million times"});
    expect_error([] { (void)Curve::spring({.stiffness = 1e6, .damping = 1e-6}); }, {"swings more than a million times"});
    expect_error([] { (void)Curve::spring_duration(0.5, 1.0); }, {"bounce must be in (-1, 1) (got 1)"});
    expect_error([] { (void)Curve::spring_duration(0.0); }, {"duration must be finite and > 0"});
    expect_error([] { (void)grape::parse_curve("spring(1)"); }, {"takes 2 to 4 arguments (got 1)"});
}

// --- function curves -------------------------------------------------------------------------

TEST(FunctionCurve, CallsTheCallableAndSharesItBetweenCopies) {
    const auto smoothstep = [](double t) { return t * t * (3 - 2 * t); };
    const Curve c = Curve::from_function(smoothstep);
    for (int i = -10; i <= 110; ++i) EXPECT_EQ(c(i / 100.0), smoothstep(i / 100.0));
    const Curve copy = c;
    EXPECT_EQ(copy.identity(), c.identity());
    EXPECT_EQ(copy, c);
    EXPECT_FALSE(Curve::from_function(smoothstep) == c);  // another callable
    EXPECT_EQ(grape::to_string(c), "function");
    expect_error([] { (void)grape::parse_curve("function"); }, {"has no text form"});
}

TEST(FunctionCurve, NonFiniteResultsBecomeTheNearerEndsValue) {
    const Curve c = Curve::from_function([](double t) {
        if (t > 0.25 && t < 0.35) return std::nan("");
        if (t > 0.65 && t < 0.75) return HUGE_VAL;
        return 0.1 + t;
    });
    EXPECT_EQ(c(0.3), 0.1);  // f(0)
    EXPECT_EQ(c(0.7), 1.1);  // f(1)
    EXPECT_EQ(c(0.5), 0.6);
    EXPECT_TRUE(std::isnan(c(NAN)));
    expect_error([] { (void)Curve::from_function({}); }, {"Curve::from_function: the function is empty"});
    expect_error([] { (void)Curve::from_function([](double t) { return 1 / t; }); }, {"f(0) and f(1) must be finite (got inf and 1)"});
}

TEST(FunctionCurve, TheEngineKeepsTheCallableAliveAndTellsCallablesApart) {
    auto alive = std::make_shared<int>(0);
    std::weak_ptr<int> watch = alive;
    grape::Engine engine;
    const grape::LinearPath line({0, 0}, {1, 0});
    grape::Animation a, b;
    {
        // Two callables with the same text ("function"): the engine must not merge them.
        const Curve square = Curve::from_function([keep = alive](double t) { return t * t; });
        const Curve root = Curve::from_function([](double t) { return std::sqrt(std::max(t, 0.0)); });
        a = engine.create_animation(line, 1.0, {.curve = square});
        b = engine.create_animation(line, 1.0, {.curve = root});
    }
    alive.reset();
    EXPECT_FALSE(watch.expired());  // the engine's table holds the square's callable
    engine.tick(0.25);
    EXPECT_NEAR(a.value().x, 0.0625, 1e-15);
    EXPECT_NEAR(b.value().x, 0.5, 1e-15);
    engine.tick(1.0);  // both complete: their curves leave the table
    EXPECT_FALSE(a.alive());
    EXPECT_TRUE(watch.expired());
}

TEST(CustomCurves, TheEnginePlaysEveryKindAsTheCurveGivesIt) {
    grape::Engine engine;
    const grape::LinearPath line({0, 0}, {1, 0});
    const std::vector<Curve> curves = {Curve::svg("M0,0 C0.2,0 0.3,1 1,1"), Curve::spring({.stiffness = 100, .damping = 4}),
                                       Curve::spring_duration(0.5, 0.3), Curve::quad_out_in(), Curve::elastic_out_in(),
                                       Curve::back(grape::EaseDirection::out_in, 2.5)};
    std::vector<grape::Animation> handles;
    for (const Curve& c : curves) handles.push_back(engine.create_animation(line, 2.0, {.curve = c}));
    for (int step = 1; step < 8; ++step) {
        engine.tick(0.25);
        for (std::size_t i = 0; i < curves.size(); ++i)
            EXPECT_DOUBLE_EQ(handles[i].value().x, curves[i](step * 0.125)) << grape::to_string(curves[i]);
    }
}
