// Unit quaternions against independent truth: rotation matrices written out from axis and
// angle, Rodrigues' formula, products of single-axis turns, the exponential-map form of slerp
// computed here with acos and sin, natural cubic splines of one angle; round trips over many
// random rotations; and typed animations of a Quat member through the engine.
#include <grape/anim.hpp>
#include <grape/quat.hpp>

#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using grape::Quat;
using grape::Vec3;
constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double pi = grape::pi;

// A uniformly random rotation (Shoemake's subgroup algorithm, 1992), written out here.
Quat random_rotation(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double u1 = u(rng), u2 = u(rng), u3 = u(rng);
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    return {a * std::sin(2 * pi * u2), a * std::cos(2 * pi * u2), b * std::sin(2 * pi * u3), b * std::cos(2 * pi * u3)};
}

Vec3 random_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> n(0.0, 1.0);
    for (;;) {
        const Vec3 v{n(rng), n(rng), n(rng)};
        if (grape::length(v) > 1e-3) return grape::normalized(v);
    }
}

// Rodrigues' formula: v rotated by angle about the unit axis n, with no quaternion.
Vec3 rodrigues(Vec3 n, double angle, Vec3 v) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + grape::cross(n, v) * s + n * (grape::dot(n, v) * (1.0 - c));
}

// The largest componentwise difference between a and b or −b, whichever is nearer.
double quat_distance(const Quat& a, const Quat& b) {
    const double s = grape::dot(a, b) < 0.0 ? -1.0 : 1.0;
    return std::max({std::abs(a.w - s * b.w), std::abs(a.x - s * b.x), std::abs(a.y - s * b.y), std::abs(a.z - s * b.z)});
}

double vec_distance(Vec3 a, Vec3 b) { return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)}); }

TEST(Quat, ProductComposesRotationsRightToLeft) {
    std::mt19937_64 rng(grape::testing::test_seed(11));
    std::uniform_real_distribution<double> d(-10.0, 10.0);
    for (int i = 0; i < 10000; ++i) {
        const Quat a = random_rotation(rng), b = random_rotation(rng);
        const Vec3 v{d(rng), d(rng), d(rng)};
        // Each rotate rounds at ~8 ulp of |v| ≤ 17.4; two of them and the product's rounding
        // (4 ulp per component) stay within 64 ulp of 17.4.
        EXPECT_LE(vec_distance(grape::rotate(a * b, v), grape::rotate(a, grape::rotate(b, v))), 64 * eps * 17.4) << i;
        // The conjugate undoes the rotation; |q| stays 1 within 2 ulp per product.
        EXPECT_LE(vec_distance(grape::rotate(grape::conjugate(a), grape::rotate(a, v)), v), 32 * eps * 17.4) << i;
        EXPECT_NEAR(grape::length(a * b), 1.0, 8 * eps);
        // Rotation keeps lengths.
        EXPECT_NEAR(grape::length(grape::rotate(a, v)), grape::length(v), 16 * eps * 17.4);
    }
}

TEST(Quat, AxisAngleAgreesWithRodrigues) {
    std::mt19937_64 rng(grape::testing::test_seed(12));
    std::uniform_real_distribution<double> ang(-2 * pi, 2 * pi);
    for (int i = 0; i < 10000; ++i) {
        const Vec3 n = random_unit(rng), v = random_unit(rng);
        const double angle = ang(rng);
        const Quat q = grape::from_axis_angle(n * 3.0, angle);  // any length of axis
        // Both sides are sums of a few products of unit-sized terms: within 16 ulp of 1.
        EXPECT_LE(vec_distance(grape::rotate(q, v), rodrigues(n, angle, v)), 16 * eps) << i;
        // axis_angle gives the angle folded into [0, π] and the axis turned to match.
        const grape::AxisAngle aa = grape::axis_angle(q);
        const double folded = std::abs(std::remainder(angle, 2 * pi));
        EXPECT_GE(aa.angle, 0.0);
        EXPECT_LE(aa.angle, pi);
        // atan2 of (|u|, w) is accurate to a few ulp of π in the angle.
        EXPECT_NEAR(aa.angle, folded, 16 * eps * pi) << i;
        EXPECT_LE(vec_distance(grape::rotate(grape::from_axis_angle(aa.axis, aa.angle), v), rodrigues(n, angle, v)),
                  32 * eps)
            << i;
    }
    EXPECT_EQ(grape::axis_angle(Quat{}).angle, 0.0);
    EXPECT_EQ(grape::axis_angle(Quat{}).axis, (Vec3{1, 0, 0}));
}

TEST(Quat, RotationVectorRoundTripsAndIsAccurateAtTinyAngles) {
    std::mt19937_64 rng(grape::testing::test_seed(13));
    std::uniform_real_distribution<double> ang(0.0, pi * 0.999);
    for (int i = 0; i < 10000; ++i) {
        // Angles from 1e-300 to π: the tiny ones test the series in place of division by |r|.
        const double angle = i % 2 ? ang(rng) : std::pow(10.0, -300.0 * ang(rng) / pi);
        const Vec3 r = random_unit(rng) * angle;
        const Quat q = grape::from_rotation_vector(r);
        // Against sin/cos of the half angle along the axis, written out.
        const Vec3 n = grape::normalized(r);
        const Quat ref{std::cos(angle / 2), std::sin(angle / 2) * n.x, std::sin(angle / 2) * n.y, std::sin(angle / 2) * n.z};
        EXPECT_LE(quat_distance(q, ref), 4 * eps) << i;
        // Back again, relative to the angle: log's atan2 is within 2 ulp of the half angle.
        EXPECT_LE(vec_distance(grape::rotation_vector(q), r), 16 * eps * angle) << i << " angle " << angle;
    }
    EXPECT_EQ(grape::from_rotation_vector({}), Quat{});
}

TEST(Quat, NormalizeAndValidatingFactories) {
    EXPECT_EQ(grape::unit_quat(2, 0, 0, 0), Quat{});
    const Quat q = grape::unit_quat(1, 1, 1, 1);
    EXPECT_EQ(q, (Quat{0.5, 0.5, 0.5, 0.5}));
    // Components of 1e300 and 1e-300 keep their ratios (no overflow, no underflow).
    EXPECT_EQ(grape::unit_quat(1e300, 1e300, 1e300, 1e300), (Quat{0.5, 0.5, 0.5, 0.5}));
    EXPECT_EQ(grape::unit_quat(0x3p-1030, 0, 0x4p-1030, 0), (Quat{0.6, 0, 0.8, 0}));  // subnormal, exact
    EXPECT_EQ(grape::normalized(Quat{0, 0, 0, 0}), Quat{});
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    grape::testing::expect_error([] { (void)grape::unit_quat(0, 0, 0, 0); }, {"unit_quat", "zero"});
    grape::testing::expect_error([&] { (void)grape::unit_quat(1, nan, 0, 0); }, {"unit_quat", "x", "not finite"});
    grape::testing::expect_error([&] { (void)grape::unit_quat(1, 0, 0, inf); }, {"unit_quat", "z", "not finite"});
    grape::testing::expect_error([] { (void)grape::from_axis_angle({0, 0, 0}, 1.0); }, {"from_axis_angle", "axis", "zero"});
    grape::testing::expect_error([&] { (void)grape::from_axis_angle({nan, 0, 0}, 1.0); }, {"from_axis_angle", "axis", "not finite"});
    grape::testing::expect_error([&] { (void)grape::from_axis_angle({1, 0, 0}, inf); }, {"from_axis_angle", "angle", "not finite"});
}

// The rotation matrix of angle about the unit axis n, written out entry by entry (columns are
// the images of the world axes), with no quaternion.
grape::Basis axis_angle_basis(Vec3 n, double angle) {
    return {rodrigues(n, angle, {1, 0, 0}), rodrigues(n, angle, {0, 1, 0}), rodrigues(n, angle, {0, 0, 1})};
}

TEST(Quat, ShepperdAgreesWithAxisAngleInEveryBranch) {
    std::mt19937_64 rng(grape::testing::test_seed(14));
    std::uniform_real_distribution<double> ang(-pi, pi);
    int branch_hits[4] = {};
    for (int i = 0; i < 20000; ++i) {
        // Every fourth angle near π, where the trace branch would divide by w ≈ 0.
        const double angle = i % 4 == 3 ? pi - 1e-9 * (i % 7) : ang(rng);
        const Vec3 n = random_unit(rng);
        const Quat q = grape::from_basis(axis_angle_basis(n, angle));
        const Quat ref{std::cos(angle / 2), std::sin(angle / 2) * n.x, std::sin(angle / 2) * n.y, std::sin(angle / 2) * n.z};
        // Rodrigues' entries are within ~4 ulp; the largest component is at least 1/2, so the
        // others, quotients of sums of two entries by 4·(largest), are within ~8 ulp.
        EXPECT_LE(quat_distance(q, ref), 8 * eps) << i << " angle " << angle;
        EXPECT_GE(q.w, 0.0);
        const double c[4] = {std::abs(ref.w), std::abs(ref.x), std::abs(ref.y), std::abs(ref.z)};
        ++branch_hits[std::max_element(c, c + 4) - c];
    }
    for (int k = 0; k < 4; ++k) EXPECT_GT(branch_hits[k], 1000) << k;  // every branch exercised
}

TEST(Quat, BasisRoundTripsWithinAFewUlp) {
    std::mt19937_64 rng(grape::testing::test_seed(15));
    for (int i = 0; i < 100000; ++i) {
        const Quat q = grape::normalized(random_rotation(rng));
        const grape::Basis b = grape::to_basis(q);
        // to_basis: each entry is 1 − 2(·) or 2(·) of products of unit components: ~4 ulp;
        // orthonormality within 8 ulp.
        EXPECT_NEAR(grape::dot(b.x, b.y), 0.0, 8 * eps);
        EXPECT_NEAR(grape::dot(b.x, b.x), 1.0, 8 * eps);
        EXPECT_LE(vec_distance(grape::cross(b.x, b.y), b.z), 8 * eps);
        // Shepperd's quotients of entries each within 4 ulp by 4·(largest ≥ 1/2): within 8 ulp.
        EXPECT_LE(quat_distance(grape::from_basis(b), q), 8 * eps) << i;
        // And the basis of that is within 8 ulp again of the first.
        const grape::Basis b2 = grape::to_basis(grape::from_basis(b));
        EXPECT_LE(std::max({vec_distance(b.x, b2.x), vec_distance(b.y, b2.y), vec_distance(b.z, b2.z)}), 16 * eps) << i;
    }
}

TEST(Quat, FromBasisRefusesWhatIsNotARotation) {
    grape::testing::expect_error([] { (void)grape::from_basis({1, 0, 0}, {0, 1, 0}, {0, 0, -1}); }, {"from_basis", "left-handed"});
    grape::testing::expect_error([] { (void)grape::from_basis({2, 0, 0}, {0, 1, 0}, {0, 0, 1}); }, {"from_basis", "x", "unit length"});
    grape::testing::expect_error([] { (void)grape::from_basis({1, 0, 0}, {0.1, 1, 0}, {0, 0, 1}); },
                                 {"from_basis", "x", "perpendicular", "y"});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    grape::testing::expect_error([&] { (void)grape::from_basis({1, 0, 0}, {0, 1, 0}, {0, nan, 1}); }, {"from_basis", "z", "not finite"});
    // A float basis (each entry rounded to float) passes.
    std::mt19937_64 rng(grape::testing::test_seed(16));
    for (int i = 0; i < 1000; ++i) {
        grape::Basis b = grape::to_basis(random_rotation(rng));
        for (Vec3* a : {&b.x, &b.y, &b.z}) *a = {static_cast<float>(a->x), static_cast<float>(a->y), static_cast<float>(a->z)};
        EXPECT_NO_THROW((void)grape::from_basis(b));
    }
}

// ---- slerp ----

// The exponential-map slerp, a·exp(t·log(a⁻¹b)), with log and exp written here from acos and
// sin: the independent reference (accurate away from angle 0, where acos loses digits).
Quat reference_slerp(const Quat& a, Quat b, double t) {
    if (grape::dot(a, b) < 0.0) b = -b;
    const Quat r = grape::conjugate(a) * b;
    const double s = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    const double half = std::acos(std::min(1.0, r.w));  // half the rotation angle of a⁻¹b
    if (s == 0.0) return a;
    const Vec3 n{r.x / s, r.y / s, r.z / s};
    const double h = t * half;
    return a * Quat{std::cos(h), std::sin(h) * n.x, std::sin(h) * n.y, std::sin(h) * n.z};
}

// The angle between two rotations, accurate at every size: 4·atan2(|a − b|, |a + b|) (a, b
// unit, b turned to a's side).
double rotation_angle(const Quat& a, Quat b) {
    if (grape::dot(a, b) < 0.0) b = -b;
    const Quat d{a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z}, s{a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
    return 4.0 * std::atan2(grape::length(d), grape::length(s));
}

TEST(Slerp, AgreesWithTheExponentialMapForm) {
    std::mt19937_64 rng(grape::testing::test_seed(21));
    std::uniform_real_distribution<double> tt(-0.5, 1.5);
    for (int i = 0; i < 20000; ++i) {
        const Quat a = random_rotation(rng), b = random_rotation(rng);
        const double t = tt(rng);
        // Both forms are a few products and sines of unit-sized numbers; acos near 1 loses
        // digits (its derivative is 1/√(1 − w²)), so random pairs (far from angle 0) only, and
        // 64 ulp for the reference's own rounding through one product and acos.
        EXPECT_LE(quat_distance(grape::slerp(a, b, t), reference_slerp(a, b, t)), 64 * eps) << i;
    }
}

TEST(Slerp, AngleGrowsLinearlyInTAtEverySize) {
    std::mt19937_64 rng(grape::testing::test_seed(22));
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        const Quat a = random_rotation(rng);
        // Rotation angles from 1e-12 rad to just below π (the flip's edge) and π itself.
        const double angle = i % 3 == 0 ? std::pow(10.0, -12.0 * uni(rng)) : i % 3 == 1 ? pi * uni(rng) : pi - 1e-10 * uni(rng);
        const Quat b = a * grape::from_axis_angle(random_unit(rng), angle);
        const grape::Slerp s(a, b);
        const double total = rotation_angle(a, b);
        for (double t : {0.0, 0.1, 0.25, 0.5, 0.7, 0.9, 1.0}) {
            const Quat q = s(t);
            EXPECT_NEAR(rotation_angle(a, q), t * total, 1e-12) << i << " t " << t;
            EXPECT_NEAR(rotation_angle(q, b), (1.0 - t) * total, 1e-12) << i << " t " << t;
            EXPECT_NEAR(grape::length(q), 1.0, 8 * eps);
        }
        EXPECT_EQ(s(0.0), a);  // exact ends
        EXPECT_EQ(s(1.0), grape::dot(a, b) < 0.0 ? -b : b);
        EXPECT_EQ(grape::slerp(a, b, 0.3), s(0.3));  // bit for bit
    }
    // Equal ends: no division by sin 0.
    const Quat a = grape::from_axis_angle({1, 2, 3}, 0.7);
    EXPECT_EQ(grape::slerp(a, a, 0.4), a);
}

TEST(Slerp, QAndMinusQGiveTheSameRotation) {
    std::mt19937_64 rng(grape::testing::test_seed(23));
    for (int i = 0; i < 10000; ++i) {
        const Quat a = random_rotation(rng), b = random_rotation(rng);
        for (double t : {0.2, 0.5, 0.8}) {
            const Quat q = grape::slerp(a, b, t);
            // Negating b changes nothing (the flip undoes it); negating a negates the result.
            EXPECT_EQ(grape::slerp(a, -b, t), q);
            EXPECT_EQ(grape::slerp(-a, b, t), -q);
        }
    }
}

// ---- typed animations ----

struct Ship {
    double x = 0.0;
    Quat orientation{};
};

TEST(QuatTween, FromToToAndByThroughTheEngine) {
    grape::Engine engine;
    Ship ship;
    const Quat q0 = grape::from_axis_angle({0, 0, 1}, 0.3), q1 = grape::from_axis_angle({1, 1, 0}, 2.0);
    engine.animate(ship, &Ship::orientation, grape::from_to(q0, q1), 2.0);
    EXPECT_EQ(ship.orientation, q0);
    engine.tick(0.5);  // a quarter of the way, linear curve
    EXPECT_LE(quat_distance(ship.orientation, reference_slerp(q0, q1, 0.25)), 64 * eps);
    engine.tick(1.5);
    EXPECT_EQ(ship.orientation, q1);  // a·b > 0 here: b itself
    EXPECT_EQ(engine.size(), 0u);

    // to: from the current value when the play begins (after its delay).
    const Quat q2 = grape::from_axis_angle({0, 1, 0}, -1.0);
    engine.animate(ship, &Ship::orientation, grape::to(q2), 1.0, {.delay = 0.5});
    engine.tick(0.5);
    EXPECT_EQ(ship.orientation, q1);
    engine.tick(0.5);
    EXPECT_LE(quat_distance(ship.orientation, reference_slerp(q1, q2, 0.5)), 64 * eps);
    engine.tick(0.5);
    EXPECT_EQ(ship.orientation, grape::dot(q1, q2) < 0 ? -q2 : q2);

    // by: composes in the object's own axes, from · by; its end is not from + by.
    ship.orientation = q0;
    const Quat d = grape::from_axis_angle({1, 0, 0}, pi / 2);
    engine.animate(ship, &Ship::orientation, grape::by(d), 1.0);
    engine.tick(0.5);
    EXPECT_LE(quat_distance(ship.orientation, q0 * grape::from_axis_angle({1, 0, 0}, pi / 4)), 64 * eps);
    engine.tick(0.5);
    EXPECT_LE(quat_distance(ship.orientation, q0 * d), 4 * eps);
    // In the ship's own axes: its x axis stays put under a turn about x.
    EXPECT_LE(vec_distance(grape::rotate(ship.orientation, {1, 0, 0}), grape::rotate(q0, {1, 0, 0})), 8 * eps);
}

TEST(QuatTween, ByUnderYoyoReturnsToTheStart) {
    grape::Engine engine;
    Ship ship;
    ship.orientation = grape::from_axis_angle({0, 1, 1}, 0.5);
    const Quat start = ship.orientation;
    const Quat d = grape::from_axis_angle({0, 0, 1}, 1.0);
    engine.animate(ship, &Ship::orientation, grape::by(d), 1.0, {.repeat = 1, .yoyo = true});
    for (int k = 0; k < 8; ++k) {
        engine.tick(0.25);
        const double phase = std::fmod((k + 1) * 0.25, 2.0);
        const double u = phase <= 1.0 ? phase : 2.0 - phase;
        // The captured start composed once with a turn of u·1 rad about the ship's z.
        EXPECT_LE(quat_distance(ship.orientation, start * grape::from_axis_angle({0, 0, 1}, u)), 64 * eps) << k;
    }
    EXPECT_EQ(ship.orientation, start);
}

}  // namespace
