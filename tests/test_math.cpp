// math: Vec2 identities, Gauss–Legendre exactness and accuracy, the safeguarded root finder.
#include <grape/math.hpp>

#include "seeds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

namespace {

using grape::Vec2;
constexpr double eps = std::numeric_limits<double>::epsilon();

TEST(Vec2, ArithmeticIdentitiesOverRandomVectors) {
    std::mt19937_64 rng(grape::testing::test_seed(7));
    std::uniform_real_distribution<double> d(-1e3, 1e3);
    for (int i = 0; i < 10000; ++i) {
        const Vec2 a{d(rng), d(rng)}, b{d(rng), d(rng)};
        const double s = d(rng);
        // Commutativity is exact in IEEE arithmetic; so are negation and the
        // componentwise definition of the products.
        EXPECT_EQ(a + b, b + a);
        EXPECT_EQ(a - b, -(b - a));
        EXPECT_EQ(a * s, s * a);
        EXPECT_EQ(grape::dot(a, b), grape::dot(b, a));
        EXPECT_EQ(grape::cross(a, b), -grape::cross(b, a));
        // a·a⊥ = −x·y + y·x is exactly 0; a × a⊥ = x² + y² = |a|² exactly.
        EXPECT_EQ(grape::dot(a, grape::perpendicular(a)), 0.0);
        EXPECT_EQ(grape::cross(a, grape::perpendicular(a)), grape::length_squared(a));
        EXPECT_EQ(grape::length(grape::perpendicular(a)), grape::length(a));
        // hypot is correctly rounded to within 1 ulp; normalizing adds one division.
        EXPECT_NEAR(grape::length(grape::normalized(a)), 1.0, 4 * eps);
        // Lagrange: |a|²|b|² = (a·b)² + (a×b)²; each side rounds at ~4 ulp of |a|²|b|².
        const double lhs = grape::length_squared(a) * grape::length_squared(b);
        const double rhs = grape::dot(a, b) * grape::dot(a, b) + grape::cross(a, b) * grape::cross(a, b);
        EXPECT_NEAR(lhs, rhs, 8 * eps * lhs);
        // Triangle inequality (with one rounding of slack).
        EXPECT_LE(grape::distance(a, b), (grape::length(a) + grape::length(b)) * (1 + 2 * eps));
        Vec2 c = a;
        c += b;
        c -= b;
        EXPECT_TRUE(grape::approx_equal(c, a, 4 * eps * 2e3));  // two roundings at magnitude ≤ 2e3
        c = a;
        c *= 2.0;
        c /= 2.0;
        EXPECT_EQ(c, a);  // scaling by a power of two is exact
    }
}

TEST(Vec2, LerpIsExactAtTheEndsAndExtrapolates) {
    const Vec2 a{0.1, -3.7}, b{0.3, 1e-9};
    EXPECT_EQ(grape::lerp(a, b, 0.0), a);
    EXPECT_EQ(grape::lerp(a, b, 1.0), b);
    EXPECT_EQ(grape::lerp(0.1, 0.3, 1.0), 0.3);
    EXPECT_TRUE(grape::approx_equal(grape::lerp(Vec2{0, 0}, Vec2{2, 4}, 1.5), Vec2{3, 6}, 0.0));
    EXPECT_TRUE(grape::approx_equal(grape::lerp(Vec2{0, 0}, Vec2{2, 4}, -0.5), Vec2{-1, -2}, 0.0));
}

TEST(Vec2, LengthNeitherOverflowsNorUnderflowsAndZeroStaysZero) {
    EXPECT_DOUBLE_EQ(grape::length(Vec2{3e200, 4e200}), 5e200);
    EXPECT_DOUBLE_EQ(grape::length(Vec2{3e-200, 4e-200}), 5e-200);
    EXPECT_EQ(grape::normalized(Vec2{}), Vec2{});
    EXPECT_FALSE(grape::is_finite(Vec2{std::nan(""), 0}));
    EXPECT_FALSE(grape::is_finite(Vec2{0, std::numeric_limits<double>::infinity()}));
    EXPECT_TRUE(grape::is_finite(Vec2{1, 2}));
    EXPECT_FALSE(grape::approx_equal(Vec2{std::nan(""), 0}, Vec2{0, 0}, 1.0));
}

TEST(Bounds, GrowsToHoldPointsAndBoxes) {
    grape::Bounds b;
    b.add(Vec2{1, 2});
    b.add(Vec2{-1, 5});
    EXPECT_EQ(b.min, (Vec2{-1, 2}));
    EXPECT_EQ(b.max, (Vec2{1, 5}));
    grape::Bounds c;
    c.add(Vec2{10, -10});
    b.add(c);
    EXPECT_EQ(b.min, (Vec2{-1, -10}));
    EXPECT_EQ(b.max, (Vec2{10, 5}));
    EXPECT_TRUE(b.contains(Vec2{0, 0}));
    EXPECT_FALSE(b.contains(Vec2{11, 0}));
    EXPECT_TRUE(b.contains(Vec2{11, 0}, 1.0));
    EXPECT_EQ(b.size(), (Vec2{11, 15}));
}

TEST(GaussLegendre, ExactOnPolynomialsUpToDegree19) {
    // ∫_a^b x^k dx = (b^{k+1} − a^{k+1})/(k+1); nodes and weights carry ~1 ulp each, the
    // sum of 10 terms of size ≤ max|x^k|·(b − a): allow 50 ulp of that scale.
    const double a = -0.7, b = 1.3;
    for (int k = 0; k <= 19; ++k) {
        auto f = [k](double x) { return std::pow(x, k); };
        const double exact = (std::pow(b, k + 1) - std::pow(a, k + 1)) / (k + 1);
        const double scale = std::pow(std::max(std::abs(a), std::abs(b)), k) * (b - a);
        EXPECT_NEAR(grape::gauss_legendre(f, a, b), exact, 50 * eps * scale) << "degree " << k;
    }
    // Degree 20 is beyond a 10-point rule: the error is visible (the test above can fail).
    auto f20 = [](double x) { return std::pow(x, 20); };
    const double exact20 = (std::pow(b, 21) - std::pow(a, 21)) / 21;
    EXPECT_GT(std::abs(grape::gauss_legendre(f20, a, b) - exact20), 1e-9 * exact20);
}

TEST(Integrate, SmoothFunctionsTo1e13AgainstClosedForms) {
    struct Case {
        double (*f)(double);
        double a, b, exact;
    };
    const Case cases[] = {
        {[](double x) { return std::sin(x); }, 0.0, grape::pi, 2.0},
        {[](double x) { return std::exp(x); }, 0.0, 1.0, std::exp(1.0) - 1.0},
        {[](double x) { return 1.0 / (1.0 + 25.0 * x * x); }, -1.0, 1.0, 2.0 * std::atan(5.0) / 5.0},  // Runge
        {[](double x) { return std::cos(40.0 * x); }, 0.0, 1.0, std::sin(40.0) / 40.0},             // oscillating
        {[](double x) { return std::sqrt(1.0 + x * x); }, 0.0, 3.0,
         0.5 * (3.0 * std::sqrt(10.0) + std::asinh(3.0))},
    };
    for (const Case& c : cases) {
        const double value = grape::integrate(c.f, c.a, c.b, 1e-15 * std::abs(c.exact));
        EXPECT_NEAR(value, c.exact, 1e-13 * std::abs(c.exact));
    }
    EXPECT_EQ(grape::integrate([](double) { return 1.0; }, 2.0, 2.0), 0.0);
    // Reversed limits change the sign.
    EXPECT_NEAR(grape::integrate([](double x) { return std::exp(x); }, 1.0, 0.0, 1e-15),
                -(std::exp(1.0) - 1.0), 1e-13);
}

TEST(Integrate, KinkAndEndpointSingularityConverge) {
    // |x − 1/3| has a kink off the bisection points: adaptive refinement around it.
    const double kink = grape::integrate([](double x) { return std::abs(x - 1.0 / 3.0); }, 0.0, 1.0, 1e-15);
    EXPECT_NEAR(kink, (1.0 / 9.0 + 4.0 / 9.0) / 2.0, 1e-13);
    // √x has an unbounded derivative at 0; the depth limit bounds the work.
    const double root = grape::integrate([](double x) { return std::sqrt(x); }, 0.0, 1.0, 1e-14);
    EXPECT_NEAR(root, 2.0 / 3.0, 1e-12);
}

auto with_derivative(double (*f)(double), double (*df)(double)) {
    return [f, df](double x) { return std::pair<double, double>{f(x), df(x)}; };
}

TEST(FindRoot, SmoothRootToMachinePrecision) {
    const auto r = grape::find_root(
        with_derivative([](double x) { return std::cos(x) - x; }, [](double x) { return -std::sin(x) - 1.0; }), 0.0,
        1.0, 0.5);
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.x, 0.7390851332151607, 2 * eps);  // the Dottie number
    EXPECT_LT(r.iterations, 10);                      // Newton: quadratic convergence
}

TEST(FindRoot, SteepFunction) {
    // atan(1e6·(x − 0.3)): Newton from far away overshoots wildly; bisection takes over.
    const auto r = grape::find_root(
        with_derivative([](double x) { return std::atan(1e6 * (x - 0.3)); },
                        [](double x) { return 1e6 / (1.0 + 1e12 * (x - 0.3) * (x - 0.3)); }),
        -10.0, 10.0, 9.0);
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.x, 0.3, 4 * eps);
}

TEST(FindRoot, FlatRootWithZeroDerivative) {
    // (x − 0.5)³: f′ vanishes at the root, Newton converges only linearly; the bracket
    // still closes to adjacent doubles.
    const auto r = grape::find_root(
        with_derivative([](double x) { return (x - 0.5) * (x - 0.5) * (x - 0.5); },
                        [](double x) { return 3.0 * (x - 0.5) * (x - 0.5); }),
        0.0, 2.0, 1.9);
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.x, 0.5, 1e-5);  // |f| < 1e-15 already within 1e-5 of the root
    EXPECT_LE(r.iterations, 200);
}

TEST(FindRoot, NewtonCycleIsBroken) {
    // x³ − 2x + 2 from 0: pure Newton cycles 0 → 1 → 0 forever.
    const auto r = grape::find_root(
        with_derivative([](double x) { return x * x * x - 2.0 * x + 2.0; },
                        [](double x) { return 3.0 * x * x - 2.0; }),
        -3.0, 1.5, 0.0);
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.x, -1.7692923542386314, 8 * eps);
}

TEST(FindRoot, DiscontinuousSignChangeFindsTheJump) {
    const auto r = grape::find_root(
        with_derivative([](double x) { return x < 0.3 ? -1.0 : 1.0; }, [](double) { return 0.0; }), 0.0, 1.0, 0.9);
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.x, 0.3, 1e-15);
}

TEST(FindRoot, NonBracketingReportsFailureAndTheBetterEnd) {
    const auto r = grape::find_root(
        with_derivative([](double x) { return x * x + 1.0; }, [](double x) { return 2.0 * x; }), -1.0, 3.0, 0.0);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.x, -1.0);
    const auto n = grape::find_root(
        with_derivative([](double) { return std::nan(""); }, [](double) { return 0.0; }), 0.0, 1.0, 0.5);
    EXPECT_FALSE(n.converged);
}

TEST(FindRoot, RootAtAnEndAndReversedBracket) {
    const auto end = grape::find_root(with_derivative([](double x) { return x - 1.0; }, [](double) { return 1.0; }),
                                      0.0, 1.0, 0.5);
    EXPECT_TRUE(end.converged);
    EXPECT_EQ(end.x, 1.0);
    const auto rev = grape::find_root(
        with_derivative([](double x) { return 2.0 - x * x; }, [](double x) { return -2.0 * x; }), 2.0, 0.0, 1.0);
    EXPECT_TRUE(rev.converged);
    EXPECT_NEAR(rev.x, std::sqrt(2.0), 2 * eps);
}

// An integrand whose rounding noise (~1e-13 relative, far above a 1e-20 target) can never
// satisfy the error test: the noise floor must stop the bisection instead of running it to
// max_depth on every branch (2^40 intervals, which never finishes).
TEST(Integrate, NoisyIntegrandStopsAtTheNoiseFloor) {
    long evaluations = 0;
    auto noisy = [&evaluations](double x) {
        ++evaluations;
        std::uint64_t bits = 0;
        std::memcpy(&bits, &x, sizeof bits);
        bits *= 0x9E3779B97F4A7C15ull;  // a hash of x: deterministic, not smooth
        return 1.0 + 1e-13 * (static_cast<double>(bits >> 11) * 0x1.0p-53 - 0.5);
    };
    const double value = grape::integrate(noisy, 0.0, 1.0, 1e-20, 40);
    // The noise averages to within 1e-13 of its mean: the integral is 1 to that bound.
    EXPECT_NEAR(value, 1.0, 1e-13);
    // At most the 2^16-interval work bound times two 10-point rules per split.
    EXPECT_LE(evaluations, 20L * (1L << 16) + 10);
}

}  // namespace
