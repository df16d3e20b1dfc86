// Colours against references written here from the published definitions: the sRGB transfer
// curve of IEC 61966-2-1, and OKLab from Björn Ottosson's forward matrices with the inverse
// found by solving the 3×3 systems here (Cramer's rule), not from the published inverse the
// library uses. CSS text both ways, and its errors.
#include <grape/color.hpp>

#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>

using grape::Color;
using grape::ColorSpace;

namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

// Extended to negative values by symmetry, as CSS Color 4 extends them (OKLab midpoints can
// leave the sRGB gamut).
double ref_to_linear(double c) {
    if (c < 0) return -ref_to_linear(-c);
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
double ref_to_encoded(double l) {
    if (l < 0) return -ref_to_encoded(-l);
    return l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
}

// Ottosson, "A perceptual color space for image processing" (2020): linear sRGB -> LMS (M1),
// cube root, LMS' -> Lab (M2).
constexpr Mat3 m1{{{0.4122214708, 0.5363325363, 0.0514459929},
                   {0.2119034982, 0.6806995451, 0.1073969566},
                   {0.0883024619, 0.2817188376, 0.6299787005}}};
constexpr Mat3 m2{{{0.2104542553, 0.7936177850, -0.0040720468},
                   {1.9779984951, -2.4285922050, 0.4505937099},
                   {0.0259040371, 0.7827717662, -0.8086757660}}};

Vec3 times(const Mat3& m, const Vec3& v) {
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}
double det(const Mat3& m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}
// x with m·x = v, by Cramer's rule.
Vec3 solve(const Mat3& m, const Vec3& v) {
    const double d = det(m);
    Vec3 x{};
    for (int k = 0; k < 3; ++k) {
        Mat3 mk = m;
        for (int r = 0; r < 3; ++r) mk[r][k] = v[r];
        x[k] = det(mk) / d;
    }
    return x;
}

Vec3 ref_oklab(const Color& c) {
    const Vec3 lms = times(m1, {ref_to_linear(c.r), ref_to_linear(c.g), ref_to_linear(c.b)});
    return times(m2, {std::cbrt(lms[0]), std::cbrt(lms[1]), std::cbrt(lms[2])});
}
Color ref_from_oklab(const Vec3& lab, double alpha) {
    const Vec3 root = solve(m2, lab);
    const Vec3 lin = solve(m1, {root[0] * root[0] * root[0], root[1] * root[1] * root[1], root[2] * root[2] * root[2]});
    return {ref_to_encoded(lin[0]), ref_to_encoded(lin[1]), ref_to_encoded(lin[2]), alpha};
}

void expect_color_near(const Color& got, const Color& want, double tol) {
    EXPECT_NEAR(got.r, want.r, tol);
    EXPECT_NEAR(got.g, want.g, tol);
    EXPECT_NEAR(got.b, want.b, tol);
    EXPECT_NEAR(got.a, want.a, tol);
}

Color random_color(std::mt19937_64& rng, bool opaque) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return {u(rng), u(rng), u(rng), opaque ? 1.0 : u(rng)};
}

}  // namespace

TEST(Color, TransferCurveMatchesTheStandardAndRoundTrips) {
    for (int k = 0; k <= 1000; ++k) {
        const double c = k / 1000.0;
        // 2e-16: pow and the division round once or twice on values <= 1.
        EXPECT_NEAR(grape::srgb_to_linear(c), ref_to_linear(c), 2e-16) << c;
        EXPECT_NEAR(grape::linear_to_srgb(grape::srgb_to_linear(c)), c, 1e-15) << c;
    }
    // Odd, so extrapolated (negative) values stay defined.
    EXPECT_EQ(grape::srgb_to_linear(-0.5), -grape::srgb_to_linear(0.5));
    EXPECT_EQ(grape::linear_to_srgb(-0.2), -grape::linear_to_srgb(0.2));
}

TEST(Color, LinearLightMidpointsMatchAnIndependentMix) {
    // Not the encoded midpoint: red to green passes #bcbc00 in linear light, #808000 in sRGB.
    const Color mid = grape::mix(grape::parse_color("#ff0000"), grape::parse_color("#00ff00"), 0.5);
    EXPECT_EQ(grape::to_hex(mid), "#bcbc00");
    EXPECT_NEAR(mid.r, ref_to_encoded(0.5), 1e-15);
    std::mt19937_64 rng(grape::testing::test_seed(13));
    for (int i = 0; i < 500; ++i) {
        const Color a = random_color(rng, i % 2 == 0), b = random_color(rng, i % 3 == 0);
        const double t = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
        // Premultiplied alpha (CSS Color 4): channels weigh by their alpha.
        const double alpha = a.a * (1 - t) + b.a * t;
        auto ref = [&](double ca, double cb) {
            return ref_to_encoded((ref_to_linear(ca) * a.a * (1 - t) + ref_to_linear(cb) * b.a * t) / alpha);
        };
        // 1e-13: a few roundings of values <= 1 through pow and a division by alpha >= ~1e-3.
        expect_color_near(grape::mix(a, b, t), {ref(a.r, b.r), ref(a.g, b.g), ref(a.b, b.b), alpha}, 1e-13);
        expect_color_near(grape::lerp(a, b, t), grape::mix(a, b, t, ColorSpace::linear_srgb), 0.0);
    }
}

TEST(Color, OklabMidpointsMatchAnIndependentMix) {
    // Black to white through L = 0.5: linear 0.125, encoded 0.3886 (#636363).
    const Color grey = grape::mix({0, 0, 0, 1}, {1, 1, 1, 1}, 0.5, ColorSpace::oklab);
    EXPECT_EQ(grape::to_hex(grey), "#636363");
    std::mt19937_64 rng(grape::testing::test_seed(7));
    for (int i = 0; i < 500; ++i) {
        const Color a = random_color(rng, i % 2 == 0), b = random_color(rng, true);
        const double t = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
        const double alpha = a.a * (1 - t) + b.a * t;
        const Vec3 la = ref_oklab(a), lb = ref_oklab(b);
        Vec3 lab{};
        for (int k = 0; k < 3; ++k) lab[k] = (la[k] * a.a * (1 - t) + lb[k] * b.a * t) / alpha;
        // 1e-12: both invert the same forward matrices in double (condition numbers ~10 and
        // ~50: ~1e-14 in linear light), times the encoding's slope (at most 12.92) and pow's
        // rounding.
        expect_color_near(grape::mix(a, b, t, ColorSpace::oklab), ref_from_oklab(lab, alpha), 1e-12);
        const Vec3 got = {grape::to_oklab(a).L, grape::to_oklab(a).a, grape::to_oklab(a).b};
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], la[k], 1e-15);  // the same forward matrices
        expect_color_near(grape::ColorLerp{}(a, b, t), grape::mix(a, b, t, ColorSpace::oklab), 0.0);
    }
}

TEST(Color, OklabRoundTripsToRoundOff) {
    std::mt19937_64 rng(grape::testing::test_seed(11));
    for (int i = 0; i < 1000; ++i) {
        const Color c = random_color(rng, true);
        // 1e-13: the inverses are exact to double round-off (the published float-precision
        // inverse matrices would leave ~1e-7 here).
        expect_color_near(grape::from_oklab(grape::to_oklab(c)), c, 1e-13);
    }
    EXPECT_NEAR(grape::to_oklab({1, 1, 1, 1}).L, 1.0, 1e-7);  // white: L = 1 to the matrices' precision
}

TEST(Color, MixIsExactAtTheEndsAndTransparentEndsLendNoColour) {
    const Color a{0.2, 0.4, 0.6, 0.8}, b{0.9, 0.1, 0.3, 1.0};
    for (ColorSpace space : {ColorSpace::linear_srgb, ColorSpace::oklab}) {
        EXPECT_EQ(grape::mix(a, b, 0.0, space), a);
        EXPECT_EQ(grape::mix(a, b, 1.0, space), b);
    }
    // A fully transparent end: only b's colour shows, fading in.
    const Color clear{1.0, 0.0, 0.0, 0.0};
    const Color m = grape::mix(clear, b, 0.3);
    EXPECT_NEAR(m.r, b.r, 1e-15);
    EXPECT_NEAR(m.g, b.g, 1e-15);
    EXPECT_NEAR(m.a, 0.3, 1e-16);
}

TEST(Color, ParsesCssText) {
    expect_color_near(grape::parse_color("#f00"), {1, 0, 0, 1}, 0.0);
    expect_color_near(grape::parse_color("#0F08"), {0, 1, 0, 0x88 / 255.0}, 0.0);
    expect_color_near(grape::parse_color("#12ABef"), {0x12 / 255.0, 0xab / 255.0, 0xef / 255.0, 1}, 0.0);
    expect_color_near(grape::parse_color("#ff000080"), {1, 0, 0, 128 / 255.0}, 0.0);
    expect_color_near(grape::parse_color(" rgb(255, 0, 51) "), {1, 0, 0.2, 1}, 0.0);
    expect_color_near(grape::parse_color("rgba(0,0,255,0.5)"), {0, 0, 1, 0.5}, 0.0);
    expect_color_near(grape::parse_color("RGB(0 51 255 / 25%)"), {0, 0.2, 1, 0.25}, 0.0);
    expect_color_near(grape::parse_color("rgb(100%, 0%, 50%)"), {1, 0, 0.5, 1}, 0.0);
    expect_color_near(grape::parse_color("rgb(300, -5, 0, 2)"), {1, 0, 0, 1}, 0.0);  // clamped as CSS does
}

TEST(Color, FormatsCssTextThatReadsBack) {
    EXPECT_EQ(grape::to_hex({1, 0, 0.2, 1}), "#ff0033");
    EXPECT_EQ(grape::to_hex({1, 0, 0, 0.5}), "#ff000080");
    EXPECT_EQ(grape::to_hex({2, -1, 0.5, 1}), "#ff0080");  // clamped
    EXPECT_EQ(grape::to_css({1, 0, 0.2, 1}), "rgb(255, 0, 51)");
    EXPECT_EQ(grape::to_css({0, 0, 1, 0.5}), "rgba(0, 0, 255, 0.5)");
    EXPECT_EQ(grape::to_css({0, 0, 1, 0.25}), "rgba(0, 0, 255, 0.25)");
    EXPECT_EQ(grape::to_css({0, 0, 1, 0}), "rgba(0, 0, 255, 0)");
    for (int k = 0; k < 256; ++k) {  // every byte reads back exactly
        const Color c{k / 255.0, (255 - k) / 255.0, (k * 7 % 256) / 255.0, (k * 3 % 256) / 255.0};
        expect_color_near(grape::parse_color(grape::to_hex(c)), c, 0.0);
        const Color css = grape::parse_color(grape::to_css(c));
        expect_color_near(css, {c.r, c.g, c.b, css.a}, 0.0);
        EXPECT_NEAR(css.a, c.a, 5e-4);  // three decimals
    }
}

TEST(Color, BadTextIsNamed) {
    using grape::testing::expect_error;
    expect_error([] { grape::parse_color(""); }, {"parse_color", "empty"});
    expect_error([] { grape::parse_color("#ff000"); }, {"\"#ff000\"", "3, 4, 6 or 8 digits", "got 5"});
    expect_error([] { grape::parse_color("#gg0000"); }, {"'g' is not a hex digit"});
    expect_error([] { grape::parse_color("rgb(1, 2)"); }, {"3 components", "got 2"});
    expect_error([] { grape::parse_color("rgb(1, 2, x)"); }, {"component 3 is not a number", "\"x\""});
    expect_error([] { grape::parse_color("rgba(1, 2, 3, nan)"); }, {"alpha is not a number"});
    expect_error([] { grape::parse_color("rgb(1, 2, 3"); }, {"missing ')'"});
    expect_error([] { grape::parse_color("hsl(0, 100%, 50%)"); }, {"expected #rgb"});
}
