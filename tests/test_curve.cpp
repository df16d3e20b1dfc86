// Curves against independent truth: Penner's published (t, b, c, d) formulas written out
// here separately, the identities that tie in, out and in-out together, an independent
// bisection solve of CSS cubic-bezier, and the CSS spec's steps() examples.
#include <grape/curve.hpp>
#include <grape/error.hpp>

#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <functional>
#include <random>
#include <string>
#include <vector>

using grape::Curve;
using grape::CurveKind;
using grape::EaseDirection;
using grape::EaseFamily;

namespace {

constexpr double pi = 3.141592653589793;

// Penner's equations in their original form: time t in [0, d], start b, change c.
// Written from the 2001 formulas with b = 0, c = 1, d = 1, not from grape's code.
namespace penner {
double in_quad(double t) { return t * t; }
double out_quad(double t) { return -t * (t - 2); }
double in_out_quad(double t) { t *= 2; if (t < 1) return 0.5 * t * t; t -= 1; return -0.5 * (t * (t - 2) - 1); }
double in_cubic(double t) { return t * t * t; }
double out_cubic(double t) { t -= 1; return t * t * t + 1; }
double in_out_cubic(double t) { t *= 2; if (t < 1) return 0.5 * t * t * t; t -= 2; return 0.5 * (t * t * t + 2); }
double in_quart(double t) { return t * t * t * t; }
double out_quart(double t) { t -= 1; return -(t * t * t * t - 1); }
double in_out_quart(double t) { t *= 2; if (t < 1) return 0.5 * t * t * t * t; t -= 2; return -0.5 * (t * t * t * t - 2); }
double in_quint(double t) { return t * t * t * t * t; }
double out_quint(double t) { t -= 1; return t * t * t * t * t + 1; }
double in_out_quint(double t) { t *= 2; if (t < 1) return 0.5 * t * t * t * t * t; t -= 2; return 0.5 * (t * t * t * t * t + 2); }
double in_sine(double t) { return -std::cos(t * (pi / 2)) + 1; }
double out_sine(double t) { return std::sin(t * (pi / 2)); }
double in_out_sine(double t) { return -0.5 * (std::cos(pi * t) - 1); }
double in_expo(double t) { return t == 0 ? 0 : std::pow(2, 10 * (t - 1)); }
double out_expo(double t) { return t == 1 ? 1 : -std::pow(2, -10 * t) + 1; }
double in_out_expo(double t) {
    if (t == 0 || t == 1) return t;
    t *= 2;
    if (t < 1) return 0.5 * std::pow(2, 10 * (t - 1));
    t -= 1;
    return 0.5 * (-std::pow(2, -10 * t) + 2);
}
double in_circ(double t) { return -(std::sqrt(1 - t * t) - 1); }
double out_circ(double t) { t -= 1; return std::sqrt(1 - t * t); }
double in_out_circ(double t) { t *= 2; if (t < 1) return -0.5 * (std::sqrt(1 - t * t) - 1); t -= 2; return 0.5 * (std::sqrt(1 - t * t) + 1); }
double in_back(double t, double s = 1.70158) { return t * t * ((s + 1) * t - s); }
double out_back(double t, double s = 1.70158) { t -= 1; return t * t * ((s + 1) * t + s) + 1; }
double in_out_back(double t, double s = 1.70158) {
    s *= 1.525;
    t *= 2;
    if (t < 1) return 0.5 * (t * t * ((s + 1) * t - s));
    t -= 2;
    return 0.5 * (t * t * ((s + 1) * t + s) + 2);
}
double in_elastic(double t, double a = 0, double p = 0) {
    if (t == 0) return 0;
    if (t == 1) return 1;
    if (p == 0) p = 0.3;
    double s;
    if (a < 1) { a = 1; s = p / 4; } else s = p / (2 * pi) * std::asin(1 / a);
    t -= 1;
    return -(a * std::pow(2, 10 * t) * std::sin((t - s) * (2 * pi) / p));
}
double out_elastic(double t, double a = 0, double p = 0) {
    if (t == 0) return 0;
    if (t == 1) return 1;
    if (p == 0) p = 0.3;
    double s;
    if (a < 1) { a = 1; s = p / 4; } else s = p / (2 * pi) * std::asin(1 / a);
    return a * std::pow(2, -10 * t) * std::sin((t - s) * (2 * pi) / p) + 1;
}
double in_out_elastic(double t) {
    if (t == 0) return 0;
    t *= 2;
    if (t == 2) return 1;
    const double p = 0.3 * 1.5;
    const double a = 1;
    const double s = p / 4;
    if (t < 1) { t -= 1; return -0.5 * (a * std::pow(2, 10 * t) * std::sin((t - s) * (2 * pi) / p)); }
    t -= 1;
    return a * std::pow(2, -10 * t) * std::sin((t - s) * (2 * pi) / p) * 0.5 + 1;
}
double out_bounce(double t) {
    if (t < (1 / 2.75)) return 7.5625 * t * t;
    if (t < (2 / 2.75)) { t -= (1.5 / 2.75); return 7.5625 * t * t + .75; }
    if (t < (2.5 / 2.75)) { t -= (2.25 / 2.75); return 7.5625 * t * t + .9375; }
    t -= (2.625 / 2.75);
    return 7.5625 * t * t + .984375;
}
double in_bounce(double t) { return 1 - out_bounce(1 - t); }
double in_out_bounce(double t) { if (t < 0.5) return in_bounce(t * 2) * .5; return out_bounce(t * 2 - 1) * .5 + .5; }
}  // namespace penner

struct Reference {
    CurveKind kind;
    std::function<double(double)> f;
};

std::vector<Reference> penner_references() {
    return {
        {CurveKind::quad_in, penner::in_quad}, {CurveKind::quad_out, penner::out_quad},
        {CurveKind::quad_in_out, penner::in_out_quad}, {CurveKind::cubic_in, penner::in_cubic},
        {CurveKind::cubic_out, penner::out_cubic}, {CurveKind::cubic_in_out, penner::in_out_cubic},
        {CurveKind::quart_in, penner::in_quart}, {CurveKind::quart_out, penner::out_quart},
        {CurveKind::quart_in_out, penner::in_out_quart}, {CurveKind::quint_in, penner::in_quint},
        {CurveKind::quint_out, penner::out_quint}, {CurveKind::quint_in_out, penner::in_out_quint},
        {CurveKind::sine_in, penner::in_sine}, {CurveKind::sine_out, penner::out_sine},
        {CurveKind::sine_in_out, penner::in_out_sine}, {CurveKind::expo_in, penner::in_expo},
        {CurveKind::expo_out, penner::out_expo}, {CurveKind::expo_in_out, penner::in_out_expo},
        {CurveKind::circ_in, penner::in_circ}, {CurveKind::circ_out, penner::out_circ},
        {CurveKind::circ_in_out, penner::in_out_circ},
        {CurveKind::back_in, [](double t) { return penner::in_back(t); }},
        {CurveKind::back_out, [](double t) { return penner::out_back(t); }},
        {CurveKind::back_in_out, [](double t) { return penner::in_out_back(t); }},
        {CurveKind::elastic_in, [](double t) { return penner::in_elastic(t); }},
        {CurveKind::elastic_out, [](double t) { return penner::out_elastic(t); }},
        {CurveKind::elastic_in_out, penner::in_out_elastic},
        {CurveKind::bounce_in, penner::in_bounce}, {CurveKind::bounce_out, penner::out_bounce},
        {CurveKind::bounce_in_out, penner::in_out_bounce},
    };
}

// Every value here is O(1) and computed in a handful of operations, so both sides round to
// within a few ulp of 1 (2.2e-16 each); the steepest curve (elastic, slope ≤ 2π/0.3·… ≈ 25
// near its lively end) turns a 1-ulp difference in an intermediate into ≈ 25 ulp.
// 64 ulp of 1 covers that with margin: 1.5e-14.
constexpr double formula_tolerance = 64 * 2.220446049250313e-16;

using grape::testing::error_text;

}  // namespace

TEST(Curve, DefaultIsLinear) {
    const Curve c;
    EXPECT_EQ(c.kind(), CurveKind::linear);
    for (double t : {-0.5, 0.0, 0.3, 1.0, 1.7}) EXPECT_EQ(c(t), t);
}

TEST(Curve, EveryPennerCurveMapsZeroToZeroAndOneToOneExactly) {
    for (int k = 0; k <= static_cast<int>(CurveKind::bounce_out_in); ++k) {
        const Curve c(static_cast<CurveKind>(k));
        SCOPED_TRACE(grape::to_string(c));
        EXPECT_EQ(c(0.0), 0.0);
        EXPECT_EQ(c(1.0), 1.0);
    }
    // Adjusted parameters keep the ends exact too.
    for (auto d : {EaseDirection::in, EaseDirection::out, EaseDirection::in_out}) {
        for (const Curve& c : {Curve::back(d, 3.0), Curve::elastic(d, 1.7, 0.2), Curve::back(d, 0.0)}) {
            SCOPED_TRACE(grape::to_string(c));
            EXPECT_EQ(c(0.0), 0.0);
            EXPECT_EQ(c(1.0), 1.0);
        }
    }
}

TEST(Curve, MatchesPennersPublishedFormulas) {
    for (const Reference& r : penner_references()) {
        const Curve c(r.kind);
        SCOPED_TRACE(grape::to_string(c));
        for (int i = 0; i <= 1000; ++i) {
            const double t = i / 1000.0;
            EXPECT_NEAR(c(t), r.f(t), formula_tolerance) << "t = " << t;
        }
    }
}

TEST(Curve, SpotValuesFromTheReferenceTable) {
    // Computed independently to 6 decimals (animation-anchors, table (c)); half a unit in
    // the 6th decimal is 5e-7, and exact ties (0.1171875 printed 0.117188) sit on it: 5.001e-7.
    struct Row { const char* name; double a, b, c; };
    const Row rows[] = {
        {"quad-in-out", 0.125, 0.5, 0.875},        {"cubic-out", 0.578125, 0.875, 0.984375},
        {"quart-in", 0.003906, 0.0625, 0.316406},  {"quint-in-out", 0.015625, 0.5, 0.984375},
        {"sine-in", 0.076120, 0.292893, 0.617317}, {"expo-out", 0.823223, 0.96875, 0.994476},
        {"circ-in-out", 0.066987, 0.5, 0.933013},  {"back-in", -0.064137, -0.087698, 0.182590},
        {"back-in-out", -0.099682, 0.5, 1.099682}, {"elastic-out", 0.911612, 1.015625, 1.005524},
        {"elastic-in-out", 0.011969, 0.5, 0.988031}, {"bounce-out", 0.472656, 0.765625, 0.972656},
        {"bounce-in-out", 0.117188, 0.5, 0.882812},
    };
    for (const Row& r : rows) {
        const Curve c = grape::parse_curve(r.name);
        SCOPED_TRACE(r.name);
        EXPECT_NEAR(c(0.25), r.a, 5.001e-7);
        EXPECT_NEAR(c(0.5), r.b, 5.001e-7);
        EXPECT_NEAR(c(0.75), r.c, 5.001e-7);
    }
}

TEST(Curve, OutIsTheMirrorOfInForEveryFamily) {
    std::vector<std::pair<Curve, Curve>> pairs;
    for (int f = 0; f < 10; ++f) {
        const auto family = static_cast<EaseFamily>(f);
        pairs.emplace_back(Curve(family, EaseDirection::in), Curve(family, EaseDirection::out));
    }
    pairs.emplace_back(Curve::back(EaseDirection::in, 2.5), Curve::back(EaseDirection::out, 2.5));
    pairs.emplace_back(Curve::elastic(EaseDirection::in, 1.6, 0.2), Curve::elastic(EaseDirection::out, 1.6, 0.2));
    for (const auto& [in, out] : pairs) {
        SCOPED_TRACE(grape::to_string(out));
        for (int i = 0; i <= 1000; ++i) {
            const double t = i / 1000.0;
            EXPECT_NEAR(out(t), 1.0 - in(1.0 - t), formula_tolerance) << "t = " << t;
        }
    }
}

TEST(Curve, InOutIsTheJoinOfInAndOutForEveryFamily) {
    for (int f = 0; f < 10; ++f) {
        const auto family = static_cast<EaseFamily>(f);
        const Curve in_out(family, EaseDirection::in_out);
        // Penner's in-out halves use their own constants: back's overshoot ×1.525 and
        // elastic's period 0.45 instead of 0.3.
        Curve in(family, EaseDirection::in);
        Curve out(family, EaseDirection::out);
        if (family == EaseFamily::back) {
            in = Curve::back(EaseDirection::in, 1.70158 * 1.525);
            out = Curve::back(EaseDirection::out, 1.70158 * 1.525);
        }
        if (family == EaseFamily::elastic) {
            in = Curve::elastic(EaseDirection::in, 1.0, 0.45);
            out = Curve::elastic(EaseDirection::out, 1.0, 0.45);
        }
        SCOPED_TRACE(grape::to_string(in_out));
        for (int i = 0; i <= 1000; ++i) {
            const double t = i / 1000.0;
            const double join = t < 0.5 ? 0.5 * in(2.0 * t) : 0.5 + 0.5 * out(2.0 * t - 1.0);
            EXPECT_NEAR(in_out(t), join, formula_tolerance) << "t = " << t;
        }
        EXPECT_EQ(in_out(0.5), 0.5);
    }
}

TEST(Curve, BackUndershootsTenPercentAndBounceTouchesOne) {
    // Back in: minimum at x = 2s/(3(s + 1)) = 0.41990 with value −0.1000 (anchors, (c)).
    const Curve back = Curve::back(EaseDirection::in);
    const double s = 1.70158;
    const double x_min = 2 * s / (3 * (s + 1));
    EXPECT_NEAR(x_min, 0.41990, 1e-5);
    EXPECT_NEAR(back(x_min), -0.1, 1e-4);  // Penner rounded s to give 10 % to 4 digits
    EXPECT_GT(back(x_min - 1e-3), back(x_min));
    EXPECT_GT(back(x_min + 1e-3), back(x_min));
    // Bounce out is 1 at 4/11, 8/11, 10/11, and continuous there (parabolas meet).
    const Curve bounce = Curve::bounce_out();
    for (double x : {4.0 / 11.0, 8.0 / 11.0, 10.0 / 11.0}) {
        EXPECT_NEAR(bounce(x), 1.0, 1e-15);
        EXPECT_NEAR(bounce(std::nextafter(x, 0.0)), bounce(x), 1e-14);
    }
}

TEST(Curve, ParametersChangeTheShape) {
    const Curve strong = Curve::back(EaseDirection::in, 3.0);
    EXPECT_NEAR(strong(0.5), penner::in_back(0.5, 3.0), formula_tolerance);
    const Curve wide = Curve::elastic(EaseDirection::out, 1.5, 0.5);
    for (double t : {0.1, 0.37, 0.8}) EXPECT_NEAR(wide(t), 1.0 - penner::in_elastic(1.0 - t, 1.5, 0.5), formula_tolerance);
    // a = 1 with the default period is Penner's out exactly.
    const Curve plain = Curve::elastic(EaseDirection::out, 1.0, 0.3);
    EXPECT_EQ(plain, Curve(CurveKind::elastic_out));
}

TEST(Curve, BadParametersNameTheArgument) {
    EXPECT_NE(error_text([] { (void)Curve::back(EaseDirection::in, -1.0); }).find("overshoot must be >= 0"), std::string::npos);
    EXPECT_NE(error_text([] { (void)Curve::back(EaseDirection::in, NAN); }).find("overshoot must be finite"), std::string::npos);
    EXPECT_NE(error_text([] { (void)Curve::elastic(EaseDirection::in, 0.5); }).find("amplitude must be >= 1"), std::string::npos);
    EXPECT_NE(error_text([] { (void)Curve::elastic(EaseDirection::in, 1.0, INFINITY); }).find("period must be finite"), std::string::npos);
    EXPECT_NE(error_text([] { (void)Curve(CurveKind::steps); }).find("needs its parameters"), std::string::npos);
}

// A subnormal period made 2π/p infinite and every value NaN: refused, naming the period; the
// shortest period accepted stays finite over t ∈ [0, 1], and non-positive ones are the default.
TEST(Curve, ElasticPeriodTooShortToComputeIsRefused) {
    for (EaseDirection d : {EaseDirection::in, EaseDirection::out, EaseDirection::in_out})
        EXPECT_NE(error_text([d] { (void)Curve::elastic(d, 1.0, 1e-310); }).find("period must be >= 1e-15"), std::string::npos);
    EXPECT_NE(error_text([] { (void)grape::parse_curve("elastic-out(1,1e-310)"); }).find("period must be >= 1e-15"),
              std::string::npos);
    const Curve shortest = Curve::elastic(EaseDirection::out, 1.0, 1e-15);
    for (int k = 0; k <= 1000; ++k) EXPECT_TRUE(std::isfinite(shortest(k / 1000.0))) << k;
    EXPECT_EQ(Curve::elastic(EaseDirection::out, 1.0, -1.0), Curve(CurveKind::elastic_out));
}

// --- CSS cubic-bezier ----------------------------------------------------------------------

namespace {
// Independent truth: bisection on u in [0, 1] for x(u) = x, 200 halvings (far below 1e-15),
// then y(u); Bernstein form rather than grape's power form.
double bezier_by_bisection(double x1, double y1, double x2, double y2, double x) {
    auto bx = [&](double u) { return 3 * (1 - u) * (1 - u) * u * x1 + 3 * (1 - u) * u * u * x2 + u * u * u; };
    auto by = [&](double u) { return 3 * (1 - u) * (1 - u) * u * y1 + 3 * (1 - u) * u * u * y2 + u * u * u; };
    double lo = 0, hi = 1;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (bx(mid) < x ? lo : hi) = mid;
    }
    return by(0.5 * (lo + hi));
}
double bezier_slope(double x1, double y1, double x2, double y2, double u) {
    auto d = [&](double p1, double p2) { return 3 * (1 - u) * (1 - u) * p1 + 6 * (1 - u) * u * (p2 - p1) + 3 * u * u * (1 - p2); };
    const double dx = d(x1, x2);
    return dx > 0 ? std::abs(d(y1, y2) / dx) : 1e300;
}
}  // namespace

TEST(CubicBezier, CssKeywordValues) {
    // Reference values from a 200-step bisection (anchors (c)), printed to 9 decimals: ±5e-10.
    const Curve ease = grape::parse_curve("ease");
    EXPECT_NEAR(ease(0.1), 0.094796306, 5e-10);
    EXPECT_NEAR(ease(0.25), 0.408510591, 5e-10);
    EXPECT_NEAR(ease(0.5), 0.802403388, 5e-10);
    EXPECT_NEAR(ease(0.9), 0.994316477, 5e-10);
    EXPECT_NEAR(grape::parse_curve("ease-in")(0.5), 0.315356813, 5e-10);
    EXPECT_NEAR(grape::parse_curve("ease-out")(0.25), 0.378138131, 5e-10);
    EXPECT_NEAR(grape::parse_curve("ease-in-out")(0.25), 0.129161931, 5e-10);
    EXPECT_NEAR(grape::parse_curve("cubic-bezier(0.68,-0.6,0.32,1.6)")(0.25), -0.097707742, 5e-10);
    EXPECT_NEAR(grape::parse_curve("cubic-bezier(0,0,1,0.5)")(0.5), 0.3125, 1e-15);
    EXPECT_EQ(ease(0.0), 0.0);
    EXPECT_EQ(ease(1.0), 1.0);
}

TEST(CubicBezier, ExtendsAlongTheEndTangentsLikeCss) {
    const Curve ease = grape::parse_curve("ease");
    EXPECT_NEAR(ease(-0.5), -0.2, 1e-15);  // start slope y1/x1 = 0.4
    EXPECT_EQ(ease(1.5), 1.0);             // end slope (y2 − 1)/(x2 − 1) = 0
    const Curve flat_start = Curve::cubic_bezier(0.0, 0.0, 0.0, 0.5);
    EXPECT_EQ(flat_start(-1.0), 0.0);  // x1 = x2 = 0: CSS says the output stays 0
}

TEST(CubicBezier, AgreesWithAnIndependentBisectionOnRandomControlPoints) {
    std::mt19937_64 rng(grape::testing::test_seed(12345));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_real_distribution<double> wide(-1.0, 2.0);
    int checked = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const double x1 = unit(rng), y1 = wide(rng), x2 = unit(rng), y2 = wide(rng);
        const Curve c = Curve::cubic_bezier(x1, y1, x2, y2);
        for (int i = 0; i <= 200; ++i) {
            const double x = i / 200.0;
            const double truth = bezier_by_bisection(x1, y1, x2, y2, x);
            // A loose check against a plain double bisection (itself off by |dy/dx| times its
            // x rounding): |dy/dx|·2e-12 plus 16 ulp of the O(1) value. The round-off check
            // against a long double reference is WithinAFewUlpOfAHighPrecisionReference... below.
            double lo = 0, hi = 1;
            for (int k = 0; k < 200; ++k) {
                const double mid = 0.5 * (lo + hi);
                const double xm = 3 * (1 - mid) * (1 - mid) * mid * x1 + 3 * (1 - mid) * mid * mid * x2 + mid * mid * mid;
                (xm < x ? lo : hi) = mid;
            }
            const double slope = bezier_slope(x1, y1, x2, y2, lo);
            // Near a vertical tangent (slope > 1e6) y is ill-conditioned in x; those few
            // inputs are covered by the monotonicity test instead.
            if (slope > 1e6) continue;
            ++checked;
            const double tolerance = 2e-12 * slope + 16 * 2.220446049250313e-16 * 3;
            ASSERT_NEAR(c(x), truth, tolerance) << x1 << " " << y1 << " " << x2 << " " << y2 << " x=" << x;
        }
    }
    EXPECT_GT(checked, 59000);  // almost all of the 300 × 201 inputs
}

TEST(CubicBezier, MonotoneWhenYControlsAreInTheUnitInterval) {
    std::mt19937_64 rng(grape::testing::test_seed(777));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const Curve c = Curve::cubic_bezier(unit(rng), unit(rng), unit(rng), unit(rng));
        double previous = c(0.0);
        for (int i = 1; i <= 10000; ++i) {
            const double v = c(i / 10000.0);
            // y is non-decreasing in u and u in x; the 1e-12 solve allows tiny reversals of
            // size slope·1e-12, bounded here by 1e-9 for these well-behaved controls.
            ASSERT_GE(v, previous - 1e-9);
            previous = v;
        }
    }
}

TEST(CubicBezier, RejectsXOutsideTheUnitInterval) {
    EXPECT_NE(error_text([] { (void)Curve::cubic_bezier(1.5, 0, 0.5, 1); }).find("x1 must be in [0, 1] (got 1.5)"), std::string::npos);
    EXPECT_NE(error_text([] { (void)Curve::cubic_bezier(0.5, 0, -0.1, 1); }).find("x2 must be in [0, 1]"), std::string::npos);
    EXPECT_NE(error_text([] { (void)Curve::cubic_bezier(0.5, NAN, 0.5, 1); }).find("y1 must be finite"), std::string::npos);
}

// --- CSS steps -----------------------------------------------------------------------------

TEST(Steps, ReproduceTheCssSpecRows) {
    const double xs[] = {0, 0.1, 0.25, 0.5, 0.74, 0.75, 0.99, 1};
    struct Row { const char* name; double v[8]; };
    const Row rows[] = {
        {"steps(4,jump-end)", {0, 0, .25, .5, .5, .75, .75, 1}},
        {"steps(4,jump-start)", {.25, .25, .5, .75, .75, 1, 1, 1}},
        {"steps(4,jump-none)", {0, 0, 1.0 / 3, 2.0 / 3, 2.0 / 3, 1, 1, 1}},
        {"steps(4,jump-both)", {.2, .2, .4, .6, .6, .8, .8, 1}},
    };
    for (const Row& r : rows) {
        const Curve c = grape::parse_curve(r.name);
        SCOPED_TRACE(r.name);
        for (int i = 0; i < 8; ++i) EXPECT_EQ(c(xs[i]), r.v[i]) << "x = " << xs[i];
    }
    EXPECT_EQ(grape::parse_curve("steps(4)"), Curve::steps(4, grape::StepPosition::jump_end));
    EXPECT_EQ(grape::parse_curve("step-start"), Curve::steps(1, grape::StepPosition::jump_start));
    EXPECT_EQ(grape::parse_curve("steps(2, start)"), Curve::steps(2, grape::StepPosition::jump_start));
}

TEST(Steps, JumpNoneNeedsTwoSteps) {
    EXPECT_NE(error_text([] { (void)Curve::steps(1, grape::StepPosition::jump_none); }).find("n must be >= 2 for jump-none (got 1)"),
              std::string::npos);
    EXPECT_NE(error_text([] { (void)Curve::steps(0); }).find("n must be >= 1"), std::string::npos);
    EXPECT_NE(error_text([] { (void)grape::parse_curve("steps(2.5)"); }).find("whole number"), std::string::npos);
    EXPECT_NE(error_text([] { (void)grape::parse_curve("steps(2,middle)"); }).find("unknown steps position 'middle'"),
              std::string::npos);
}

// --- monotone custom curve ------------------------------------------------------------------

TEST(Monotone, PassesThroughItsPointsAndNeverOvershootsMonotoneData) {
    std::mt19937_64 rng(grape::testing::test_seed(2024));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const int n = 2 + static_cast<int>(unit(rng) * 8);
        std::vector<double> x(n), y(n);
        for (int i = 0; i < n; ++i) x[i] = static_cast<double>(i) / (n - 1);
        // Random non-decreasing data with flat runs, so plateaus are tested too.
        y[0] = 0;
        for (int i = 1; i < n; ++i) y[i] = y[i - 1] + (unit(rng) < 0.2 ? 0.0 : unit(rng));
        const Curve c = Curve::monotone(x, y);
        for (int i = 0; i < n; ++i) EXPECT_NEAR(c(x[i]), y[i], 1e-15 * (1 + y[i]));
        for (int k = 0; k + 1 < n; ++k) {
            double previous = y[k];
            for (int j = 1; j <= 100; ++j) {
                const double v = c(x[k] + (x[k + 1] - x[k]) * j / 100.0);
                // Between its knots the piece stays inside [y_k, y_k+1] and keeps rising;
                // a few ulp of the value for rounding of the Hermite sum.
                const double ulps = 8 * 2.220446049250313e-16 * (1 + y[n - 1]);
                ASSERT_GE(v, y[k] - ulps);
                ASSERT_LE(v, y[k + 1] + ulps);
                ASSERT_GE(v, previous - ulps);
                previous = v;
            }
        }
    }
}

TEST(Monotone, ReproducesStraightLinesAndExtendsAlongEndTangents) {
    const std::vector<double> x{0, 0.3, 1}, y{0, 0.6, 2};
    const Curve c = Curve::monotone(x, y);
    for (double t : {0.1, 0.5, 0.9}) EXPECT_NEAR(c(t), 2 * t, 1e-15);
    EXPECT_NEAR(c(1.5), 3.0, 1e-15);
    EXPECT_NEAR(c(-0.5), -1.0, 1e-15);
}

TEST(Monotone, BadPointsAreErrors) {
    const std::vector<double> ok{0, 1};
    EXPECT_NE(error_text([&] { (void)Curve::monotone(std::vector<double>{0, 0.5, 0.5, 1}, std::vector<double>{0, 1, 1, 1}); })
                  .find("x must increase strictly (x[2] = 0.5 after 0.5)"),
              std::string::npos);
    EXPECT_NE(error_text([&] { (void)Curve::monotone(std::vector<double>{0.1, 1}, ok); }).find("x must start at 0"), std::string::npos);
    EXPECT_NE(error_text([&] { (void)Curve::monotone(std::vector<double>{0, 0.9}, ok); }).find("x must end at 1"), std::string::npos);
    EXPECT_NE(error_text([&] { (void)Curve::monotone(std::vector<double>{0}, std::vector<double>{0}); }).find("at least 2 points"),
              std::string::npos);
    EXPECT_NE(error_text([&] { (void)Curve::monotone(ok, std::vector<double>{0, NAN}); }).find("y[1] must be finite"), std::string::npos);
}

// --- names ---------------------------------------------------------------------------------

TEST(CurveNames, RoundTripEveryCurve) {
    std::vector<Curve> curves;
    for (int k = 0; k <= static_cast<int>(CurveKind::bounce_out_in); ++k) curves.emplace_back(static_cast<CurveKind>(k));
    curves.push_back(Curve::back(EaseDirection::out, 2.5));
    curves.push_back(Curve::elastic(EaseDirection::in_out, 1.25, 0.6));
    curves.push_back(Curve::steps(7, grape::StepPosition::jump_both));
    curves.push_back(Curve::monotone(std::vector<double>{0, 0.25, 1}, std::vector<double>{0, 0.8, 1}));
    std::mt19937_64 rng(grape::testing::test_seed(99));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 100; ++i) curves.push_back(Curve::cubic_bezier(unit(rng), unit(rng) * 3 - 1, unit(rng), unit(rng)));
    for (const Curve& c : curves) {
        const std::string name = grape::to_string(c);
        EXPECT_EQ(grape::parse_curve(name), c) << name;
        EXPECT_EQ(grape::to_string(grape::parse_curve(name)), name);
    }
    EXPECT_EQ(grape::to_string(Curve::quad_in_out()), "quad-in-out");
    EXPECT_EQ(grape::to_string(grape::parse_curve("ease")), "cubic-bezier(0.25,0.1,0.25,1)");
    EXPECT_EQ(grape::to_string(Curve::steps(4)), "steps(4,jump-end)");
    EXPECT_EQ(grape::parse_curve(" cubic-bezier( 0.25 , 0.1, 0.25 ,1 ) "), grape::parse_curve("ease"));
    EXPECT_EQ(grape::parse_curve("QUAD_IN_OUT"), Curve::quad_in_out());
    EXPECT_EQ(grape::curve_names().size(), 41u);
}

TEST(CurveNames, EveryNameHasItsFactory) {
    // Written out by hand (not generated from the names), so a name without a factory, or a
    // factory giving another curve, fails here.
    const std::vector<std::pair<std::string_view, Curve (*)()>> factories{
        {"linear", &Curve::linear},
        {"quad-in", &Curve::quad_in},
        {"quad-out", &Curve::quad_out},
        {"quad-in-out", &Curve::quad_in_out},
        {"quad-out-in", &Curve::quad_out_in},
        {"cubic-in", &Curve::cubic_in},
        {"cubic-out", &Curve::cubic_out},
        {"cubic-in-out", &Curve::cubic_in_out},
        {"cubic-out-in", &Curve::cubic_out_in},
        {"quart-in", &Curve::quart_in},
        {"quart-out", &Curve::quart_out},
        {"quart-in-out", &Curve::quart_in_out},
        {"quart-out-in", &Curve::quart_out_in},
        {"quint-in", &Curve::quint_in},
        {"quint-out", &Curve::quint_out},
        {"quint-in-out", &Curve::quint_in_out},
        {"quint-out-in", &Curve::quint_out_in},
        {"sine-in", &Curve::sine_in},
        {"sine-out", &Curve::sine_out},
        {"sine-in-out", &Curve::sine_in_out},
        {"sine-out-in", &Curve::sine_out_in},
        {"expo-in", &Curve::expo_in},
        {"expo-out", &Curve::expo_out},
        {"expo-in-out", &Curve::expo_in_out},
        {"expo-out-in", &Curve::expo_out_in},
        {"circ-in", &Curve::circ_in},
        {"circ-out", &Curve::circ_out},
        {"circ-in-out", &Curve::circ_in_out},
        {"circ-out-in", &Curve::circ_out_in},
        {"back-in", &Curve::back_in},
        {"back-out", &Curve::back_out},
        {"back-in-out", &Curve::back_in_out},
        {"back-out-in", &Curve::back_out_in},
        {"elastic-in", &Curve::elastic_in},
        {"elastic-out", &Curve::elastic_out},
        {"elastic-in-out", &Curve::elastic_in_out},
        {"elastic-out-in", &Curve::elastic_out_in},
        {"bounce-in", &Curve::bounce_in},
        {"bounce-out", &Curve::bounce_out},
        {"bounce-in-out", &Curve::bounce_in_out},
        {"bounce-out-in", &Curve::bounce_out_in},
    };
    ASSERT_EQ(factories.size(), grape::curve_names().size());
    for (const std::string_view name : grape::curve_names()) {
        const auto it = std::find_if(factories.begin(), factories.end(), [&](const auto& f) { return f.first == name; });
        ASSERT_NE(it, factories.end()) << name << " has no factory";
        EXPECT_EQ(it->second(), grape::parse_curve(name)) << name;
    }
}

TEST(CurveNames, UnknownNamesListTheValidOnes) {
    const std::string m = error_text([] { (void)grape::parse_curve("wobble"); });
    EXPECT_NE(m.find("unknown curve name 'wobble'"), std::string::npos) << m;
    EXPECT_NE(m.find("quad-in-out"), std::string::npos);
    EXPECT_NE(m.find("cubic-bezier(x1,y1,x2,y2)"), std::string::npos);
    EXPECT_NE(m.find("steps(n"), std::string::npos);
    EXPECT_NE(error_text([] { (void)grape::parse_curve("cubic-bezier(0.1,0.2,0.3)"); }).find("takes 4 arguments (got 3)"),
              std::string::npos);
    EXPECT_NE(error_text([] { (void)grape::parse_curve("cubic-bezier(0.1,x,0.3,1)"); }).find("'x' is not a finite number"),
              std::string::npos);
    EXPECT_NE(error_text([] { (void)grape::parse_curve("quad-in(2)"); }).find("takes no arguments"), std::string::npos);
    EXPECT_NE(error_text([] { (void)grape::parse_curve("ease(1"); }).find("missing ')'"), std::string::npos);
}

TEST(Curve, EveryCurveStaysFiniteOutsideTheUnitInterval) {
    std::vector<Curve> curves;
    for (int k = 0; k <= static_cast<int>(CurveKind::bounce_out_in); ++k) curves.emplace_back(static_cast<CurveKind>(k));
    curves.push_back(grape::parse_curve("ease"));
    curves.push_back(Curve::steps(3));
    for (const Curve& c : curves)
        for (int i = -100; i <= 200; ++i) {
            EXPECT_TRUE(std::isfinite(c(i / 100.0))) << grape::to_string(c) << " at " << i / 100.0;
        }
}

// --- out-in --------------------------------------------------------------------------------

TEST(Curve, OutInIsPennersOutThenInForEveryFamily) {
    // Tweener's easeOutIn*: out over the first half scaled by ½, then in from ½ (Penner's
    // published in and out above, not grape's). Back and elastic keep their in/out constants.
    std::vector<std::function<double(double)>> in(10), out(10);
    const auto refs = penner_references();
    for (int f = 0; f < 10; ++f) {
        in[f] = refs[3 * f].f;
        out[f] = refs[3 * f + 1].f;
    }
    for (int f = 0; f < 10; ++f) {
        const Curve c = Curve::out_in(static_cast<EaseFamily>(f));
        SCOPED_TRACE(grape::to_string(c));
        EXPECT_EQ(c.kind(), static_cast<CurveKind>(1 + 4 * f + 3));
        EXPECT_EQ(c, Curve(static_cast<EaseFamily>(f), EaseDirection::out_in));
        for (int i = 0; i <= 1000; ++i) {
            const double t = i / 1000.0;
            const double truth = t < 0.5 ? 0.5 * out[f](2 * t) : 0.5 + 0.5 * in[f](2 * t - 1);
            EXPECT_NEAR(c(t), truth, formula_tolerance) << "t = " << t;
        }
        EXPECT_EQ(c(0.0), 0.0);
        EXPECT_EQ(c(0.5), 0.5);
        EXPECT_EQ(c(1.0), 1.0);
        // Point symmetry about (½, ½): out-in(t) = 1 − out-in(1 − t), as out(x) = 1 − in(1 − x).
        for (int i = 0; i <= 100; ++i) EXPECT_NEAR(c(i / 100.0), 1.0 - c(1.0 - i / 100.0), formula_tolerance);
    }
    // Adjusted constants reach both halves; names read back.
    const Curve back = Curve::back(EaseDirection::out_in, 2.5);
    EXPECT_NEAR(back(0.3), 0.5 * penner::out_back(0.6, 2.5), formula_tolerance);
    EXPECT_NEAR(back(0.8), 0.5 + 0.5 * penner::in_back(0.6, 2.5), formula_tolerance);
    const Curve elastic = Curve::elastic(EaseDirection::out_in, 1.5, 0.4);
    EXPECT_NEAR(elastic(0.3), 0.5 * penner::out_elastic(0.6, 1.5, 0.4), formula_tolerance);
    EXPECT_EQ(grape::to_string(back), "back-out-in(2.5)");
    EXPECT_EQ(grape::parse_curve("elastic-out-in(1.5,0.4)"), elastic);
    EXPECT_EQ(grape::to_string(Curve::elastic_out_in()), "elastic-out-in");
    EXPECT_EQ(grape::parse_curve("bounce-out-in"), Curve::bounce_out_in());
    EXPECT_EQ(Curve(CurveKind::sine_out_in), Curve::sine_out_in());
}

// --- cubic-bezier to round-off ---------------------------------------------------------------

namespace {

constexpr double eps = 2.220446049250313e-16;

// Independent reference in long double (64-bit significand on x86, 2048× finer than a
// double): bisection over [0, 1] of the plain Bernstein sum until the bracket is 2⁻⁶⁶ of its
// lower end (a quarter ulp of a long double there), no Newton. Above ½ it bisects on w = 1 − s
// for 1 − x = w³ + 3w²(1 − w)(1 − x1) + 3w(1 − w)²(1 − x2) = 1 − t: near 1 a long double x has
// only 1e-19 absolute resolution, which next to a flat end (1 − x ∝ w²) would move w by
// 1e-19/|dx/dw| and y by far more than a double's ulp.
struct BezierReference {
    long double y;
    long double slope;  // dy/dx at the solution
};
BezierReference bezier_reference(double x1, double y1, double x2, double y2, double t) {
    using L = long double;
    auto b = [](L p1, L p2, L s) { const L m = 1 - s; return 3 * m * m * s * p1 + 3 * m * s * s * p2 + s * s * s; };
    auto d = [](L p1, L p2, L s) { const L m = 1 - s; return 3 * m * m * p1 + 6 * m * s * (p2 - p1) + 3 * s * s * (1 - p2); };
    // From the end: w³ + 3w²(1 − w)(1 − p1) + 3w(1 − w)²(1 − p2) = 1 − b(p1, p2, 1 − w).
    auto e = [](L p1, L p2, L w) { const L m = 1 - w; return w * w * w + 3 * w * w * m * (1 - p1) + 3 * w * m * m * (1 - p2); };
    const bool upper = t > 0.5;
    const L target = upper ? 1 - static_cast<L>(t) : static_cast<L>(t);
    L lo = 0, hi = 1;
    for (int i = 0; i < 20000 && hi - lo > std::ldexp(lo, -66); ++i) {
        const L mid = (lo + hi) / 2;
        if (mid == lo || mid == hi) break;
        ((upper ? e(x1, x2, mid) : b(x1, x2, mid)) < target ? lo : hi) = mid;
    }
    const L u = (lo + hi) / 2;
    const L s = upper ? 1 - u : u;
    const L dx = d(x1, x2, s);
    return {upper ? 1 - e(y1, y2, u) : b(y1, y2, s), dx > 0 ? std::fabs(d(y1, y2, s) / dx) : 1e300L};
}

// Dense in the middle and geometric towards both ends, where the flat ends live.
std::vector<double> dense_grid() {
    std::vector<double> t;
    for (int i = 1; i < 4000; ++i) t.push_back(i / 4000.0);
    for (int j = 1; j <= 60; ++j) t.push_back(std::ldexp(1.0, -j));
    for (int j = 1; j <= 52; ++j) t.push_back(1.0 - std::ldexp(1.0, -j));
    for (double x : {1e-300, 1e-100, 3e-17, 0.5 - 1e-16, 0.5 + 1.1e-16, 1.0 - 1.1e-16}) t.push_back(x);
    return t;
}

// The bound the solver states: s exact for a t within 8 ulp (of min(t, 1 − t), the exact
// input on the half it solves), so y within 8 ulp · (min(t, 1 − t)·|dy/dt|) from the solve,
// plus the evaluation of y: 8 ulp of its Bernstein terms (|y| for y controls in [0, 1], and
// max(1, |y1|, |y2|) when they overshoot) and half an ulp of 1 for 1 − y on the upper half.
// Twice that, 16 ulp, for margin.
double bezier_tolerance(double y1, double y2, double t, const BezierReference& r) {
    const double near = std::min(t, 1.0 - t);
    const bool unit = y1 >= 0 && y1 <= 1 && y2 >= 0 && y2 <= 1;
    const double scale = unit ? static_cast<double>(std::fabs(r.y)) : std::max({1.0, std::abs(y1), std::abs(y2)}) * 3;
    return 16 * eps * (scale + near * static_cast<double>(r.slope)) + (t > 0.5 ? eps : 0.0);
}

}  // namespace

TEST(CubicBezier, WithinAFewUlpOfAHighPrecisionReferenceIncludingFlatEnds) {
    struct Controls { double x1, y1, x2, y2; };
    std::vector<Controls> cases = {
        {0.25, 0.1, 0.25, 1},  {0.42, 0, 1, 1},   {0, 0, 0.58, 1},    {0.42, 0, 0.58, 1},  // CSS keywords
        {0, 0, 1, 1},          {0, 1, 1, 0},      {1, 0, 1, 1},       {0, 0, 0, 1},        // flat ends
        {0.68, -0.6, 0.32, 1.6}, {0.5, 0, 0.5, 1}, {0.1, 0.9, 0.2, 1}, {0.9, 0, 0.9, 0.1},
    };
    std::mt19937_64 rng(grape::testing::test_seed(4242));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_real_distribution<double> wide(-1.0, 2.0);
    for (int i = 0; i < 40; ++i) cases.push_back({unit(rng), unit(rng), unit(rng), unit(rng)});
    for (int i = 0; i < 20; ++i) cases.push_back({unit(rng), wide(rng), unit(rng), wide(rng)});
    const std::vector<double> grid = dense_grid();
    double worst = 0;  // in units of the tolerance
    for (const Controls& k : cases) {
        const Curve c = Curve::cubic_bezier(k.x1, k.y1, k.x2, k.y2);
        for (double t : grid) {
            const BezierReference r = bezier_reference(k.x1, k.y1, k.x2, k.y2, t);
            if (r.slope > 1e12) continue;  // vertical tangent: y is not a function of t to round-off
            const double tolerance = bezier_tolerance(k.y1, k.y2, t, r);
            const double error = std::abs(c(t) - static_cast<double>(r.y));
            worst = std::max(worst, error / tolerance);
            ASSERT_LE(error, tolerance) << grape::to_string(c) << " t=" << t << " reference " << static_cast<double>(r.y);
        }
    }
    std::printf("cubic-bezier: worst error %.3g of the tolerance over %zu curves x %zu t\n", worst, cases.size(), grid.size());
}

TEST(CubicBezier, FlatEndsThatStoppedAt1e12AreNowExact) {
    // ease-in near its flat end (x2 = 1, y2 = 1): 1 − x ≈ 3(1 − x1)·w² ... with w = 1 − s, so a
    // solve stopped at |x − t| ≤ 1e-12 missed s by ~1e-6 and y by ~1e-6 relative to 1 − y.
    // Here both 1 − y and y next to the flat start (ease-out at t = 2^-40) keep full relative
    // precision.
    const Curve ease_in = grape::parse_curve("ease-in");
    const Curve ease_out = grape::parse_curve("ease-out");
    for (int j = 20; j <= 52; ++j) {
        const double t = 1.0 - std::ldexp(1.0, -j);
        const BezierReference r = bezier_reference(0.42, 0, 1, 1, t);
        EXPECT_NEAR(1.0 - ease_in(t), static_cast<double>(1.0L - r.y), 4 * eps * static_cast<double>(1.0L - r.y) + eps) << j;
        const double u = std::ldexp(1.0, -j);
        const BezierReference q = bezier_reference(0, 0, 0.58, 1, u);
        EXPECT_NEAR(ease_out(u), static_cast<double>(q.y), 16 * eps * static_cast<double>(q.y)) << j;
    }
}

TEST(CubicBezier, InteriorFlatPointStaysWithinItsStatedBound) {
    // cubic-bezier(1, 0, 0, 1): x(s) = ½ + 4(s − ½)³ exactly and y(s) = 3s² − 2s³, so the
    // exact answer is s = ½ + ∛((t − ½)/4) (t − ½ exact in long double). Away from t = ½ the
    // solve is exact to a few ulp; next to it the header's bound ∛(8 ulp(t)/4)·|y′(s)| holds,
    // y′(½) = 3/2: ∛(8·2⁻⁵³/4)·1.5 = 9.1e-6.
    const Curve c = Curve::cubic_bezier(1, 0, 0, 1);
    EXPECT_EQ(c(0.5), 0.5);
    for (double t : {0.5 - 1e-16, 0.5 + 1.2e-16, 0.5 - 1e-12, 0.5 + 1e-9, 0.25, 0.75, 0.1, 0.999}) {
        using L = long double;
        const L w = std::cbrt((static_cast<L>(t) - 0.5L) / 4);
        const L s = 0.5L + w;
        const L y = 3 * s * s - 2 * s * s * s;
        const double near_flat = std::cbrt(8 * std::ldexp(1.0, -53) / 4) * 1.5 * 1.01;  // 1 % for rounding of the bound
        const double slope = static_cast<double>((6 * s - 6 * s * s) / (12 * w * w));  // dy/dt = y′(s)/x′(s)
        const double ordinary = 16 * eps * (1 + std::min(t, 1 - t) * slope);
        EXPECT_NEAR(c(t), static_cast<double>(y), std::min(near_flat, ordinary) > 0 && std::abs(t - 0.5) > 1e-6 ? ordinary : near_flat)
            << "t = " << t;
    }
}

// Both branch-free selects (SSE2 masks, and the integer masks wasm builds use) give the
// ternary's bits, NaN payloads, signed zeros and infinities included, and a NaN x selects b
// as x < edge is false.
TEST(Curve, BranchFreeSelectsGiveTheTernarysBits) {
    auto bits = [](double v) {
        std::uint64_t u;
        std::memcpy(&u, &v, sizeof u);
        return u;
    };
    std::mt19937_64 rng(grape::testing::test_seed(17));
    std::uniform_real_distribution<double> any(-4.0, 4.0);
    const double specials[] = {0.0, -0.0, 0.5, std::nextafter(0.5, 0.0), std::nextafter(0.5, 1.0),
                               HUGE_VAL, -HUGE_VAL, std::nan("7"), -std::nan("3"), 4.9e-324};
    auto pick = [&](std::size_t k) { return k < std::size(specials) ? specials[k] : any(rng); };
    int below = 0, above = 0;
    for (std::size_t k = 0; k < 20000; ++k) {
        const double x = pick(k % 40), edge = pick((k / 40) % 40 < 10 ? (k / 40) % 40 : 40), a = pick(k % 13 + 7),
                     b = pick(k % 17 + 5);
        const double want = x < edge ? a : b;
        (x < edge ? below : above) += 1;
        ASSERT_EQ(bits(grape::detail::pick_below(x, edge, a, b)), bits(want)) << x << " " << edge;
        ASSERT_EQ(bits(grape::detail::pick_below_bits(x, edge, a, b)), bits(want)) << x << " " << edge;
    }
    EXPECT_GT(below, 1000);
    EXPECT_GT(above, 1000);
}

// The anim tick's lean runs skip the test for points beyond a path's ends on linear and the
// polynomial kinds (engine_lean.hpp, stays_on_path): their values for x in [0, 1] stay in
// [0, 1]. Checked at the ends, around ½, at the smallest doubles and at random x.
TEST(Curve, PolynomialKindsStayInTheUnitIntervalOnIt) {
    std::mt19937_64 rng(grape::testing::test_seed(5));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> xs = {0.0, -0.0, 1.0, 0.5, std::nextafter(0.5, 0.0), std::nextafter(0.5, 1.0),
                              std::nextafter(1.0, 0.0), 4.9e-324, 1e-300, 1e-160};
    for (int k = 0; k < 100000; ++k) xs.push_back(unit(rng));
    for (int kind = 0; kind <= static_cast<int>(grape::CurveKind::quint_out_in); ++kind) {
        const auto ck = static_cast<grape::CurveKind>(kind);
        for (const double x : xs) {
            const double u = grape::detail::ease_formula(ck, x);
            ASSERT_TRUE(u >= 0.0 && u <= 1.0) << kind << " at " << x << " gives " << u;
        }
    }
}
