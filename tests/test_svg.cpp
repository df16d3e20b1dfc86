// SVG path data: lengths against closed forms, the grammar's corners, S/T reflections, arcs by
// the SVG implementation notes, every error message, and random valid data.
#include <grape/error.hpp>
#include <grape/path.hpp>

#include <gtest/gtest.h>

#include "seeds.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace {

using grape::ComplexPath;
using grape::parse_svg_path;
using grape::Path;
using grape::PathKind;
using grape::pi;
using grape::Vec2;

constexpr double eps = std::numeric_limits<double>::epsilon();
// The path module's length contract: closed forms to 1e-12 relative.
constexpr double length_tolerance = 1e-12;

void expect_length(std::string_view data, double expected) {
    SCOPED_TRACE(std::string(data));
    const ComplexPath path = parse_svg_path(data);
    EXPECT_NEAR(path.length(), expected, length_tolerance * expected);
}

void expect_near(Vec2 a, Vec2 b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
}

// Perimeter of an ellipse by the Gauss–Kummer series π(a+b)·Σ C(½,n)² hⁿ, h = ((a−b)/(a+b))²:
// independent of any quadrature, and converging geometrically (h ≤ 1/9 for the axes used here).
double ellipse_perimeter(double a, double b) {
    const double h = (a - b) * (a - b) / ((a + b) * (a + b));
    double binomial = 1.0;  // C(½, n)
    double power = 1.0;     // hⁿ
    double sum = 1.0;
    for (int n = 1; n < 200; ++n) {
        binomial *= (0.5 - (n - 1)) / n;
        power *= h;
        const double term = binomial * binomial * power;
        sum += term;
        if (term < 1e-20 * sum) break;
    }
    return pi * (a + b) * sum;
}

// Message of the grape::Error thrown by parsing `data` ("" if none).
std::string error_of(std::string_view data) {
    try {
        (void)parse_svg_path(data);
    } catch (const grape::Error& e) {
        return e.what();
    }
    return "";
}

// Same points, bit for bit, at many u (including the cues, where parts change).
void expect_same_points(const Path& a, const Path& b) {
    for (int i = 0; i <= 1000; ++i) {
        const double u = i / 1000.0;
        EXPECT_EQ(a.point(u), b.point(u)) << "u = " << u;
        EXPECT_EQ(a.d1(u), b.d1(u)) << "u = " << u;
    }
}

// ---------------------------------------------------------------------------------------------
// Lengths against closed forms

TEST(Svg, LineAndRectangleLengths) {
    expect_length("M0 0 L3 4", 5.0);
    // Axis-aligned sides are exact; Z closes the fourth side.
    expect_length("M10 10 H90 V90 H10 Z", 320.0);
    expect_length("m10 10 h80 v80 h-80 z", 320.0);
}

TEST(Svg, SemicircleViaArcIsPiR) {
    const double r = 50.0;
    expect_length("M0 0 A 50 50 0 0 1 100 0", pi * r);
    expect_length("M0 0 A 50 50 0 0 0 100 0", pi * r);
    // Two large arcs make the whole circle.
    expect_length("M0 0 A 50 50 0 1 1 100 0 A 50 50 0 1 1 0 0", 2.0 * pi * r);
}

TEST(Svg, SpecArcExamplesHaveClosedFormLengths) {
    // SVG 1.1 §8.3.8's pie example: two radii of 150 and three quarters of a circle.
    expect_length("M300,200 h-150 a150,150 0 1,0 150,-150 z", 300.0 + 0.75 * 2.0 * pi * 150.0);
    // ... and its missing quarter.
    expect_length("M275,175 v-150 a150,150 0 0,0 -150,150 z", 300.0 + 0.25 * 2.0 * pi * 150.0);
    // SVG 1.1 §8.3.3's triangle.
    expect_length("M 100 100 L 300 100 L 200 300 z", 200.0 + 2.0 * std::sqrt(100.0 * 100.0 + 200.0 * 200.0));
}

TEST(Svg, EllipticalArcLengthsAgreeWithTheSeries) {
    // Half an ellipse between the ends of its major axis is half its perimeter.
    expect_length("M-2 0 A 2 1 0 0 1 2 0", 0.5 * ellipse_perimeter(2.0, 1.0));
    // The same ellipse turned by 30°, its endpoints turned with it.
    const double c = std::cos(pi / 6.0);
    const double s = std::sin(pi / 6.0);
    const std::string rotated = "M" + std::to_string(-2.0 * c) + " " + std::to_string(-2.0 * s) + " A 2 1 30 0 1 " +
                                std::to_string(2.0 * c) + " " + std::to_string(2.0 * s);
    // to_string keeps 6 decimals: the endpoints sit off the exact ellipse by ≤ 5e-7, which the
    // scale-up absorbs; the length moves by about as much.
    const ComplexPath path = parse_svg_path(rotated);
    EXPECT_NEAR(path.length(), 0.5 * ellipse_perimeter(2.0, 1.0), 4e-6);
    EXPECT_EQ(path.parts()[0].kind(), PathKind::elliptical_arc);
}

TEST(Svg, ArcRadiiTooSmallAreScaledUp) {
    // F.6.6: radius 1 cannot span a chord of 10, so it grows to 5: a semicircle.
    expect_length("M0 0 A 1 1 0 0 1 10 0", 5.0 * pi);
    expect_length("M0 0 A 1 1 0 1 0 10 0", 5.0 * pi);  // both flags give the same half
    // An ellipse keeps its axis ratio: rx 1, ry 2 across a horizontal chord of 10 becomes
    // rx 5, ry 10, and the arc is half of that ellipse.
    expect_length("M0 0 A 1 2 0 0 1 10 0", 0.5 * ellipse_perimeter(10.0, 5.0));
    // The scaled semicircle passes through (5, -5): sweep 1 turns clockwise on screen (y down).
    const ComplexPath path = parse_svg_path("M0 0 A 1 1 0 0 1 10 0");
    expect_near(path.point(0.5), {5.0, -5.0}, 1e-13 * 10.0);
}

TEST(Svg, ZeroRadiusArcIsAStraightLine) {
    const ComplexPath path = parse_svg_path("M0 0 A 0 5 0 0 1 3 4");
    ASSERT_EQ(path.parts().size(), 1u);
    EXPECT_EQ(path.parts()[0].kind(), PathKind::linear);
    EXPECT_EQ(path.length(), 5.0);
    EXPECT_EQ(path.point(0.5), (Vec2{1.5, 2.0}));
}

TEST(Svg, NegativeRadiiUseTheirMagnitude) {
    expect_same_points(parse_svg_path("M0 0 A -50 -50 0 0 1 100 0"), parse_svg_path("M0 0 A 50 50 0 0 1 100 0"));
}

TEST(Svg, ArcFlagsPickTheFourArcs) {
    // Radius 1 from (0,0) to (1,1): centers (1,0) and (0,1); quarter or three-quarter turns.
    const double quarter = 0.5 * pi;
    expect_length("M0 0 A 1 1 0 0 0 1 1", quarter);
    expect_length("M0 0 A 1 1 0 0 1 1 1", quarter);
    expect_length("M0 0 A 1 1 0 1 0 1 1", 3.0 * quarter);
    expect_length("M0 0 A 1 1 0 1 1 1 1", 3.0 * quarter);
    // Small arc, sweep 0 (counter-clockwise on screen) goes round the center (1, 0);
    // sweep 1 round (0, 1). Their midpoints lie on the circles, 1/√2 off each center.
    const double h = 1.0 - std::sqrt(0.5);
    expect_near(parse_svg_path("M0 0 A 1 1 0 0 0 1 1").point(0.5), {h, 1.0 - h}, 1e-15 * 8);
    expect_near(parse_svg_path("M0 0 A 1 1 0 0 1 1 1").point(0.5), {1.0 - h, h}, 1e-15 * 8);
}

// The frame where an ellipse (rx, ry, turned by φ) is a circle of radius rx: turn by −φ, then
// stretch y by rx/ry. There the arc's center can be found geometrically, independently of the
// SVG notes' formulas: on the chord's bisector, √(r² − (d/2)²) away from it.
struct CircleFrame {
    double c = 1.0, s = 0.0, stretch = 1.0;
    Vec2 to_circle(Vec2 p) const { return {c * p.x + s * p.y, stretch * (-s * p.x + c * p.y)}; }
};

TEST(Svg, ArcsHitTheirEndpointsAndLieOnTheirEllipses) {
    // The SVG 1.1 spec's arc example family: ellipses of growing ry turned by −30°, each
    // drawn with sweep 1 and large-arc 0 between two given corners (some need scaling up).
    const ComplexPath path = parse_svg_path(
        "M600,350 l 50,-25 a25,25 -30 0,1 50,-25 l 50,-25 a25,50 -30 0,1 50,-25 l 50,-25 a25,75 -30 0,1 50,-25 "
        "l 50,-25 a25,100 -30 0,1 50,-25 l 50,-25");
    ASSERT_EQ(path.parts().size(), 9u);
    const std::vector<Vec2> corners{{600, 350}, {650, 325}, {700, 300}, {750, 275}, {800, 250},
                                    {850, 225}, {900, 200}, {950, 175}, {1000, 150}, {1050, 125}};
    // Coordinates near 1000: 16 ulp of 1000 covers the rounding of the center and the angles.
    const double tolerance = 16 * eps * 1000.0;
    for (std::size_t i = 0; i < path.parts().size(); ++i) {
        SCOPED_TRACE(i);
        expect_near(path.parts()[i].point(0.0), corners[i], tolerance);
        expect_near(path.parts()[i].point(1.0), corners[i + 1], tolerance);
    }
    const double phi = -30.0 * pi / 180.0;
    for (std::size_t k = 0; k < 4; ++k) {
        const std::size_t i = 2 * k + 1;
        SCOPED_TRACE(i);
        const Path& part = path.parts()[i];
        EXPECT_EQ(part.kind(), k == 0 ? PathKind::circle : PathKind::elliptical_arc);
        const double rx = 25.0;
        const double ry = 25.0 * static_cast<double>(k + 1);
        const CircleFrame frame{std::cos(phi), std::sin(phi), rx / ry};
        const Vec2 q1 = frame.to_circle(corners[i]);
        const Vec2 q2 = frame.to_circle(corners[i + 1]);
        const double half = 0.5 * grape::distance(q1, q2);
        const double r = std::max(rx, half);  // F.6.6's scale-up
        const Vec2 n = grape::perpendicular(grape::normalized(q2 - q1));
        const double h = std::sqrt(std::max(0.0, r * r - half * half));
        Vec2 center = 0.5 * (q1 + q2) + h * n;
        if (grape::cross(q1 - center, q2 - center) < 0.0) center = 0.5 * (q1 + q2) - h * n;
        for (int j = 0; j <= 20; ++j) {
            const double u = j / 20.0;
            const Vec2 q = frame.to_circle(part.point(u));
            EXPECT_NEAR(grape::distance(q, center), r, tolerance);
            // Sweep 1: the angle about the center increases (clockwise on screen, y down).
            EXPECT_GT(grape::cross(q - center, frame.to_circle(part.point(u) + part.d1(u)) - frame.to_circle(part.point(u))), 0.0);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The grammar

TEST(Svg, RelativeAndAbsoluteGiveIdenticalPoints) {
    // Integer coordinates make every relative sum exact, so the parts (and the points) are the
    // same bit for bit.
    expect_same_points(
        parse_svg_path("M10 20 L30 40 H50 V10 C60 0 70 0 80 10 S100 20 110 10 Q120 0 130 10 T150 10 "
                       "A20 10 30 0 1 170 30 Z L0 0"),
        parse_svg_path("m10 20 l20 20 h20 v-30 c10 -10 20 -10 30 0 s20 10 30 0 q10 -10 20 0 t20 0 "
                       "a20 10 30 0 1 20 20 z l-10 -20"));
}

TEST(Svg, ImplicitRepeatsContinueTheCommand) {
    // After M the pairs are linetos; after m, relative linetos.
    expect_same_points(parse_svg_path("M0 0 10 0 10 10"), parse_svg_path("M0 0 L10 0 L10 10"));
    expect_same_points(parse_svg_path("m5 5 10 0 0 10"), parse_svg_path("M5 5 L15 5 L15 15"));
    expect_same_points(parse_svg_path("M0 0 C0 10 10 10 10 0 10 -10 20 -10 20 0"),
                       parse_svg_path("M0 0 C0 10 10 10 10 0 C10 -10 20 -10 20 0"));
    expect_same_points(parse_svg_path("M0 0 h10 20 v5 5"), parse_svg_path("M0 0 H10 H30 V5 V10"));
    expect_same_points(parse_svg_path("M0 0 a5 5 0 0 1 10 0 5 5 0 0 1 10 0"),
                       parse_svg_path("M0 0 A5 5 0 0 1 10 0 A5 5 0 0 1 20 0"));
}

TEST(Svg, NumberSyntax) {
    // ".5.5" is two numbers; a sign starts a new number; exponents in both cases; "1e1.5" is
    // 10 then .5; commas and any SVG whitespace separate.
    const ComplexPath path = parse_svg_path(" \t\r\nM.5.5L1e1.5-2E+1-.25e-0,+3-4\f");
    ASSERT_EQ(path.parts().size(), 3u);
    EXPECT_EQ(path.parts()[0].point(0.0), (Vec2{0.5, 0.5}));
    EXPECT_EQ(path.parts()[1].point(0.0), (Vec2{10.0, 0.5}));
    EXPECT_EQ(path.parts()[2].point(0.0), (Vec2{-20.0, -0.25}));
    EXPECT_EQ(path.parts()[2].point(1.0), (Vec2{3.0, -4.0}));
    // Numbers below the double range round to zero, as in browsers.
    EXPECT_EQ(parse_svg_path("M1e-400 0 L1 0").point(0.0), (Vec2{0.0, 0.0}));
    EXPECT_EQ(parse_svg_path("M0.000000000000000000000000000000001e-300 0 L1 0").point(0.0), (Vec2{0.0, 0.0}));
}

TEST(Svg, ArcFlagsNeedNoSeparators) {
    expect_same_points(parse_svg_path("M0 0 a1 1 0 00 1 1"), parse_svg_path("M0 0 a 1 1 0 0 0 1 1"));
    expect_same_points(parse_svg_path("M0 0 a1,1,0,1,1,1,1"), parse_svg_path("M0 0 a1 1 0 111 1"));
}

TEST(Svg, SmoothCubicReflectsThePreviousControlPoint) {
    const ComplexPath path = parse_svg_path("M0 0 C 10 20 30 20 40 0 S 70 -20 80 0 s 30 20 40 0");
    ASSERT_EQ(path.parts().size(), 3u);
    // The reflection of (30, 20) about (40, 0) is (50, −20); then of (70, −20) about (80, 0).
    expect_same_points(path.parts()[1], grape::CubicBezierPath({40, 0}, {50, -20}, {70, -20}, {80, 0}));
    expect_same_points(path.parts()[2], grape::CubicBezierPath({80, 0}, {90, 20}, {110, 20}, {120, 0}));
    // After anything but C or S the first control point is the current point.
    const ComplexPath after_line = parse_svg_path("M0 0 L10 0 S 20 10 30 0");
    expect_same_points(after_line.parts()[1], grape::CubicBezierPath({10, 0}, {10, 0}, {20, 10}, {30, 0}));
    const ComplexPath after_quad = parse_svg_path("M0 0 Q5 5 10 0 S 20 10 30 0");
    expect_same_points(after_quad.parts()[1], grape::CubicBezierPath({10, 0}, {10, 0}, {20, 10}, {30, 0}));
}

TEST(Svg, SmoothQuadraticReflectsThroughAChain) {
    const ComplexPath path = parse_svg_path("M0 0 Q 10 10 20 0 T 40 0 t 20 0");
    ASSERT_EQ(path.parts().size(), 3u);
    expect_same_points(path.parts()[1], grape::QuadraticBezierPath({20, 0}, {30, -10}, {40, 0}));
    expect_same_points(path.parts()[2], grape::QuadraticBezierPath({40, 0}, {50, 10}, {60, 0}));
    // T after a cubic does not reflect: its control point is the current point.
    const ComplexPath after_cubic = parse_svg_path("M0 0 C0 10 10 10 10 0 T 20 0");
    expect_same_points(after_cubic.parts()[1], grape::QuadraticBezierPath({10, 0}, {10, 0}, {20, 0}));
}

TEST(Svg, RoundTripAgainstHandBuiltPaths) {
    // Each drawn segment is one part, cues by length: the same as building it by hand.
    const ComplexPath parsed = parse_svg_path("M100,200 C100,100 250,100 250,200 S400,300 400,200 L 450 250 "
                                              "Q 500 300 550 250 A 25 25 0 0 1 600 250");
    std::vector<Path> parts{grape::CubicBezierPath({100, 200}, {100, 100}, {250, 100}, {250, 200}),
                            grape::CubicBezierPath({250, 200}, {250, 300}, {400, 300}, {400, 200}),
                            grape::LinearPath({400, 200}, {450, 250}),
                            grape::QuadraticBezierPath({450, 250}, {500, 300}, {550, 250}),
                            grape::CirclePath({575, 250}, 25, pi, 2.0 * pi)};
    const ComplexPath built = ComplexPath::by_length(parts);
    ASSERT_EQ(parsed.parts().size(), built.parts().size());
    for (std::size_t i = 0; i < 4; ++i) expect_same_points(parsed.parts()[i], built.parts()[i]);
    // The arc's angles come out of atan2 rather than being written: ulps of the radius 25·π.
    for (int k = 0; k <= 100; ++k) {
        expect_near(parsed.parts()[4].point(k / 100.0), built.parts()[4].point(k / 100.0), 16 * eps * 600.0);
    }
    ASSERT_EQ(parsed.cues().size(), built.cues().size());
    for (std::size_t i = 0; i < parsed.cues().size(); ++i) EXPECT_NEAR(parsed.cues()[i], built.cues()[i], 1e-15);
    EXPECT_NEAR(parsed.length(), built.length(), 1e-13 * built.length());
}

TEST(Svg, ClosePathReturnsToTheSubpathStart) {
    // z draws back to (10, 10); the following l starts there.
    const ComplexPath path = parse_svg_path("M10 10 h10 v10 z l 5 0");
    ASSERT_EQ(path.parts().size(), 4u);
    expect_same_points(path.parts()[2], grape::LinearPath({20, 20}, {10, 10}));
    expect_same_points(path.parts()[3], grape::LinearPath({10, 10}, {15, 10}));
    // After z, a relative moveto is relative to the subpath start too.
    const ComplexPath moved = parse_svg_path("M10 10 h10 z m5 5 h1");
    expect_same_points(moved.parts()[2], grape::LinearPath({15, 15}, {16, 15}));
}

TEST(Svg, MovesBetweenSubpathsAreNotDrawn) {
    // Two segments of 10 with a jump of 10 between them: the length is 20, and the path jumps
    // at u = ½ from the end of the first to the start of the second.
    const ComplexPath path = parse_svg_path("M0 0 H10 M20 0 H30");
    EXPECT_EQ(path.length(), 20.0);
    ASSERT_EQ(path.cues().size(), 2u);
    EXPECT_EQ(path.cues()[1], 0.5);
    EXPECT_EQ(path.point(0.5), (Vec2{20, 0}));
    expect_near(path.point(std::nextafter(0.5, 0.0)), {10, 0}, 1e-12);
    // A moveto that draws nothing before the next one is simply a new start.
    expect_same_points(parse_svg_path("M5 5 M0 0 L10 0"), parse_svg_path("M0 0 L10 0"));
}

TEST(Svg, ZeroLengthSegmentsAreSkipped) {
    const ComplexPath path = parse_svg_path("M0 0 L0 0 l0 0 h0 v0 C0 0 0 0 0 0 Q0 0 0 0 A5 5 0 0 1 0 0 L10 0 Z z");
    ASSERT_EQ(path.parts().size(), 2u);  // the line to (10, 0) and the closing line
    for (const double cue : path.cues()) EXPECT_TRUE(std::isfinite(cue));
    EXPECT_EQ(path.length(), 20.0);
    // A Bézier that returns to its start still has length: it is kept.
    EXPECT_EQ(parse_svg_path("M0 0 C 0 10 10 10 0 0").parts().size(), 1u);
    // A segment shorter than 2⁻⁵² of the whole would get a cue span no u can land in (here a
    // denormal one, whose inverse overflows): it is left out as well.
    const ComplexPath sliver = parse_svg_path("M0 0 L1e-300 0 L1e10 0");
    ASSERT_EQ(sliver.parts().size(), 1u);
    EXPECT_EQ(sliver.parts()[0].point(0.0), (Vec2{1e-300, 0.0}));
}

TEST(Svg, ExtremeMagnitudesGiveNoNaN) {
    // Data the fuzzer produced (tiny segments beside ones 1e200 times longer) and its kin: the
    // path's points stay finite and its derivatives are never NaN (they may be huge).
    for (const char* data : {"m10,10 h80 v10 h0 -.5e220 h80 v10 h80 v80 h-80 z",
                             "m10,10 h 0,-10 Z M0 100\tM 1e2,1e262.55 162.45 L 172.55 152.45 A 30 50 -45 0 1 215.1 1",
                             "M0 0 L1e-300 0 L1e10 0", "M0 0 C1e-320 0 0 1e-320 1e-320 1e-320",
                             "M-1e307 0 A 1e-300 1e300 45 1 1 1e307 1 L0 0"}) {
        SCOPED_TRACE(data);
        const ComplexPath path = parse_svg_path(data);
        for (int k = 0; k <= 64; ++k) {
            const double u = k / 64.0;
            EXPECT_TRUE(grape::is_finite(path.point(u)));
            EXPECT_FALSE(std::isnan(path.d1(u).x) || std::isnan(path.d1(u).y));
            EXPECT_FALSE(std::isnan(path.d2(u).x) || std::isnan(path.d2(u).y));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Errors: each names the offset and what was expected

TEST(Svg, ErrorsNameTheOffsetAndTheReason) {
    EXPECT_EQ(error_of("L1 1"), "SVG path data: expected a moveto (M or m) at offset 0, found 'L'");
    EXPECT_EQ(error_of("  10 10"), "SVG path data: expected a moveto (M or m) at offset 2, found '1'");
    EXPECT_EQ(error_of("M0 0 L3 @"), "SVG path data: expected a number at offset 8, found '@'");
    EXPECT_EQ(error_of("M0 0 L3"), "SVG path data: expected a number at offset 7, found the end of the data");
    EXPECT_EQ(error_of("M,0 0 L1 1"), "SVG path data: expected a number at offset 1, found ','");
    EXPECT_EQ(error_of("M0 0 L1 1, L2 2"), "SVG path data: expected a number at offset 11, found 'L'");
    EXPECT_EQ(error_of("M0 0 L1 1,"), "SVG path data: expected a number at offset 10, found the end of the data");
    EXPECT_EQ(error_of("M0 0 L1 .e1"), "SVG path data: expected a number at offset 8, found '.'");
    EXPECT_EQ(error_of("M0 0 L1 --1"), "SVG path data: expected a number at offset 8, found '-'");
    EXPECT_EQ(error_of("M0 0 L1 1e"), "SVG path data: expected the digits of an exponent at offset 10, found the end of the data");
    EXPECT_EQ(error_of("M0 0 L1 1e+x"), "SVG path data: expected the digits of an exponent at offset 11, found 'x'");
    EXPECT_EQ(error_of("M0 0 X1 1"), "SVG path data: expected a command letter (M, L, H, V, C, S, Q, T, A or Z) at offset 5, found 'X'");
    EXPECT_EQ(error_of("M0 0 L1 1 Z 5"), "SVG path data: expected a command letter (M, L, H, V, C, S, Q, T, A or Z) at offset 12, found '5'");
    EXPECT_EQ(error_of(std::string("M0 0\x01", 5)), "SVG path data: expected a command letter (M, L, H, V, C, S, Q, T, A or Z) at offset 4, found byte 0x01");
    EXPECT_EQ(error_of("M0 0 A 1 1 0 2 1 5 5"), "SVG path data: expected an arc flag (0 or 1) at offset 13, found '2'");
    EXPECT_EQ(error_of("M0 0 A 1 1 0 1 -1 5 5"), "SVG path data: expected an arc flag (0 or 1) at offset 15, found '-'");
    EXPECT_EQ(error_of("M0 0 C 1 1 2 2"), "SVG path data: expected a number at offset 14, found the end of the data");
    EXPECT_EQ(error_of("M1e309 0 L1 1"), "SVG path data: a number is too large at offset 1 (beyond the range of a double)");
    EXPECT_EQ(error_of("M1.5e308 0 l1.5e308 0"), "SVG path data: a coordinate is too large at offset 12 (beyond the range of a double)");
    // Each segment's length fits, their sum does not.
    EXPECT_EQ(error_of("M-1e308 0 L0 0 L1e308 0 L0 0"),
              "SVG path data: the path's length overflows a double (segment at offset 16)");
    // One segment longer than a double holds: the path kind refuses it, the parser says where.
    EXPECT_EQ(error_of("M-1e308 0 L1e308 0").rfind("SVG path data: the segment at offset 11 ", 0), 0u);
}

TEST(Svg, ErrorsAreThrownForEveryTruncation) {
    // Cutting valid data anywhere either still parses or throws grape::Error: never anything
    // else, and every message names an offset inside the data.
    const std::string data = "M10,20 c5 5 10-5 15 0s10 10 15 0q5-5 10 0t10 0a5 3 20 1 0 10 0h5v5l-3 3z";
    for (std::size_t n = 0; n <= data.size(); ++n) {
        const std::string cut = data.substr(0, n);
        const std::string message = error_of(cut);
        if (message.empty()) continue;
        EXPECT_EQ(message.rfind("SVG path data: ", 0), 0u) << cut;
        const auto at = message.find(" at offset ");
        if (at != std::string::npos) {
            EXPECT_LE(std::stoul(message.substr(at + 11)), cut.size()) << cut;
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Random valid data

// Writes random valid path data, tracking where each part must start and end and which parts
// share a subpath, so that the parse can be checked against it.
class RandomPathData {
public:
    explicit RandomPathData(unsigned seed) : rng_(seed) {}

    struct Expected {
        std::string data;
        std::vector<Vec2> starts;    // of each drawn part
        std::vector<Vec2> ends;
        std::vector<int> subpaths;
    };

    Expected make() {
        Expected e;
        current_ = start_ = {};
        int subpath = -1;
        const int commands = pick(1, 12);
        bool moved = false;
        for (int i = 0; i < commands || !moved || e.starts.empty(); ++i) {
            const char kind = moved ? "MLHVCSQTAZ"[pick(0, 9)] : 'M';
            const bool relative = pick(0, 1) == 1;
            std::string text(1, relative ? static_cast<char>(kind - 'A' + 'a') : kind);
            if (kind == 'M') {
                moved = true;
                ++subpath;
                const Vec2 p = point();
                text += pair(p, relative);
                current_ = start_ = p;
            } else if (kind == 'Z') {
                if (current_ != start_) draw(e, subpath, start_);
                current_ = start_;
            } else {
                const Vec2 end = fresh_end();
                switch (kind) {
                case 'L': case 'T': text += pair(end, relative); break;
                case 'H': text += number(relative ? end.x - current_.x : end.x); break;
                case 'V': text += number(relative ? end.y - current_.y : end.y); break;
                case 'C': text += pair(point(), relative) + separator() + pair(point(), relative) + separator() + pair(end, relative); break;
                case 'S': case 'Q': text += pair(point(), relative) + separator() + pair(end, relative); break;
                case 'A':
                    text += number(std::abs(coordinate()) + 1) + separator() + number(std::abs(coordinate()) + 1) +
                            separator() + number(coordinate()) + separator() + (pick(0, 1) ? "1" : "0") +
                            (pick(0, 1) ? "," : "") + (pick(0, 1) ? "1" : "0") + separator() + pair(end, relative);
                    break;
                default: break;
                }
                draw(e, subpath, kind == 'H' ? Vec2{end.x, current_.y} : kind == 'V' ? Vec2{current_.x, end.y} : end);
            }
            e.data += text + (pick(0, 1) ? " " : "");
        }
        return e;
    }

private:
    int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    // Quarters in [−200, 200]: exact in binary, so relative and absolute forms of a point agree.
    double coordinate() { return pick(-800, 800) / 4.0; }
    Vec2 point() { return {coordinate(), coordinate()}; }
    // An endpoint away from the current point on both axes, so H and V draw too.
    Vec2 fresh_end() {
        Vec2 p = point();
        while (p.x == current_.x || p.y == current_.y) p = point();
        return p;
    }
    std::string separator() { return std::array<const char*, 4>{" ", ",", " , ", "\n"}[pick(0, 3)]; }
    std::string number(double v) {
        char buffer[64];
        switch (pick(0, 2)) {
        case 0: std::snprintf(buffer, sizeof buffer, "%.2f", v); break;
        case 1: std::snprintf(buffer, sizeof buffer, "%.4e", v); break;
        default: std::snprintf(buffer, sizeof buffer, "%g", v); break;
        }
        return buffer;
    }
    std::string pair(Vec2 p, bool relative) {
        const Vec2 q = relative ? p - current_ : p;
        return number(q.x) + separator() + number(q.y);
    }
    void draw(Expected& e, int subpath, Vec2 end) {
        e.starts.push_back(current_);
        e.ends.push_back(end);
        e.subpaths.push_back(subpath);
        current_ = end;
    }

    std::mt19937 rng_;
    Vec2 current_{};
    Vec2 start_{};
};

TEST(Svg, RandomValidDataParsesIntoContinuousSubpaths) {
    RandomPathData generator(20261122);
    for (int trial = 0; trial < 2000; ++trial) {
        const auto expected = generator.make();
        SCOPED_TRACE(expected.data);
        std::optional<ComplexPath> parsed;
        ASSERT_NO_THROW(parsed.emplace(parse_svg_path(expected.data)));
        const ComplexPath& path = *parsed;
        ASSERT_EQ(path.parts().size(), expected.starts.size());
        ASSERT_TRUE(std::isfinite(path.length()));
        // Coordinates ≤ 200 and arcs scaled up to at most their chord: a few hundred ulp of
        // 1000 bounds the rounding of the arcs' centers and angles.
        const double tolerance = 256 * eps * 1000.0;
        for (std::size_t i = 0; i < path.parts().size(); ++i) {
            const Path& part = path.parts()[i];
            expect_near(part.point(0.0), expected.starts[i], tolerance);
            expect_near(part.point(1.0), expected.ends[i], tolerance);
            if (i + 1 < path.parts().size() && expected.subpaths[i] == expected.subpaths[i + 1]) {
                expect_near(part.point(1.0), path.parts()[i + 1].point(0.0), tolerance);
            }
        }
        for (int k = 0; k <= 64; ++k) {
            ASSERT_TRUE(grape::is_finite(path.point(k / 64.0)));
            ASSERT_TRUE(grape::is_finite(path.d1(k / 64.0)));
        }
    }
}

// A flat arc of a huge ellipse (rx 25625, ry 1e8, chord 22): its speed's rounding noise is
// above the quadrature target, which once made the length computation run forever. Reference:
// the arc is x = rx·sin t, y = ry·(1 − cos t)-like around the top, t in [−t0, t0] with
// sin t0 = 11/rx; composite Simpson over 4000 intervals of this smooth speed is good to ~1e-15
// relative. The speed itself is only known to ~5e-13 relative (cancellation in the arc's
// center, 1e8 away), hence 1e-12.
TEST(Svg, HugeFlatEllipseArcParsesQuickly) {
    const ComplexPath p = parse_svg_path("M0 0 A 25625 100000000 0 0 1 22 0");
    const double rx = 25625.0;
    const double ry = 1e8;
    const double t0 = std::asin(11.0 / rx);
    auto speed = [&](double t) { return std::hypot(rx * std::cos(t), ry * std::sin(t)); };
    const int n = 4000;
    const double h = 2.0 * t0 / n;
    double sum = speed(-t0) + speed(t0);
    for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * speed(-t0 + k * h);
    const double reference = sum * h / 3.0;
    EXPECT_NEAR(p.length(), reference, 1e-12 * reference);
}

// Fuzz findings: smooth cubics with coordinates near 1e307, whose power-basis coefficients
// overflow (points came out infinite, derivatives NaN), are refused; the offset is that of the
// segment's first number.
TEST(Svg, CubicsTooLargeToEvaluateAreRefused) {
    const std::string reason =
        " is not a valid path (CubicBezierPath: control points are too large to evaluate in double precision "
        "(coefficients overflow))";
    EXPECT_EQ(error_of("M1 8S140e305,0 01+1E220 S400,0 ,0 80"), "SVG path data: the segment at offset 5" + reason);
    EXPECT_EQ(error_of("M0 0 C 0 0 1.4e307 0 0 0"), "SVG path data: the segment at offset 7" + reason);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Data that draws nothing is valid (SVG 2 §9.3.9: an empty path is no error; a moveto-only
// path stands at its point)

namespace {

void expect_stands_at(const Path& path, Vec2 at) {
    EXPECT_EQ(path.length(), 0.0);
    for (double u : {0.0, 0.25, 0.5, 1.0}) {
        EXPECT_EQ(path.point(u), at) << "u = " << u;
        EXPECT_EQ(path.d1(u), (Vec2{})) << "u = " << u;
    }
    EXPECT_EQ(path.bounds().min, at);
    EXPECT_EQ(path.bounds().max, at);
}

}  // namespace

TEST(SvgNothingDrawn, EmptyAndMovetoOnlyDataStandAtTheirPoint) {
    expect_stands_at(parse_svg_path(""), {0.0, 0.0});
    expect_stands_at(parse_svg_path(" \n\t"), {0.0, 0.0});
    expect_stands_at(parse_svg_path("M0 0"), {0.0, 0.0});
    expect_stands_at(parse_svg_path("M5 7"), {5.0, 7.0});
    expect_stands_at(parse_svg_path("m5 7 m1 1"), {5.0, 7.0});  // the first moveto
    // Zero-length segments (real data from an icon theme): length 0 at the point.
    expect_stands_at(parse_svg_path("M 180.66031,30.859082 L 180.66031,30.859082"), {180.66031, 30.859082});
    expect_stands_at(parse_svg_path("M1 1 L1 1 Z m0 0 z"), {1.0, 1.0});
    expect_stands_at(parse_svg_path("M2 3 C2 3 2 3 2 3 Q2 3 2 3 A5 5 0 0 1 2 3 h0 v0"), {2.0, 3.0});
}

TEST(SvgNothingDrawn, ReparametrizedStandsStillAndFlattensToThePoint) {
    // Reparametrizing a path of length 0 gives the same point at every u and speed 0 (there
    // is no length to spread u over); nothing divides by the length.
    const Path still = parse_svg_path("M5 7").reparametrized();
    for (double u : {0.0, 0.5, 1.0}) {
        EXPECT_EQ(still.point(u), (Vec2{5.0, 7.0}));
        EXPECT_EQ(still.d1(u), (Vec2{}));
    }
    EXPECT_EQ(still.u_at_length(1.0), 0.0);
    const std::vector<Vec2> flat = parse_svg_path("M5 7").flatten(0.1);
    ASSERT_EQ(flat.size(), 2u);
    EXPECT_EQ(flat[0], (Vec2{5.0, 7.0}));
    EXPECT_EQ(flat[1], (Vec2{5.0, 7.0}));
}

// ---------------------------------------------------------------------------------------------
// SVG's error rule: draw up to the command holding the first error

TEST(SvgErrorRule, PrefixUpToTheErrorWithItsOffset) {
    // M 13,9 3,19 (√200) h 11 v -3 l 1,-1 (√2) v -8, then an `l` without arguments:
    // 10√2 + 11 + 3 + √2 + 8 = 22 + 11√2 = 37.556349186104043 (exact to the last digit:
    // 11·√2 = 15.556349186104045…).
    const std::string data = "M 13,9 3,19 h 11 v -3 l 1,-1 v -8 l";
    const grape::SvgPathParse parsed = grape::parse_svg_path_prefix(data);
    EXPECT_NEAR(parsed.path.length(), 22.0 + 11.0 * std::sqrt(2.0), 4 * eps * 38.0);  // a few ulps of 37.6
    EXPECT_EQ(parsed.path.point(1.0), (Vec2{15.0, 7.0}));  // (13, 9) → (3, 19) → (14, 19) → (14, 16) → (15, 15) → (15, 7)
    ASSERT_TRUE(parsed.error.has_value());
    EXPECT_EQ(parsed.error->offset, data.size());
    EXPECT_EQ(parsed.error->message, "SVG path data: expected a number at offset 35, found the end of the data");
    // Strict parsing throws the same message.
    EXPECT_EQ(error_of(data), parsed.error->message);
}

TEST(SvgErrorRule, ValidDataHasNoErrorAndTheSamePath) {
    const std::string data = "M10,20 c5 5 10-5 15 0s10 10 15 0q5-5 10 0t10 0a5 3 20 1 0 10 0h5v5l-3 3z";
    const grape::SvgPathParse parsed = grape::parse_svg_path_prefix(data);
    EXPECT_FALSE(parsed.error.has_value());
    expect_same_points(parsed.path, parse_svg_path(data));
}

TEST(SvgErrorRule, EveryTruncationGivesTheLongestValidPrefix) {
    // Cut anywhere, the error-rule path equals the strict parse of the data up to the last
    // complete command: found independently by cutting further until the strict parse passes.
    const std::string data = "M10,20 c5 5 10-5 15 0s10 10 15 0q5-5 10 0t10 0a5 3 20 1 0 10 0h5v5l-3 3z";
    for (std::size_t n = 0; n <= data.size(); ++n) {
        const std::string cut = data.substr(0, n);
        SCOPED_TRACE(cut);
        const grape::SvgPathParse parsed = grape::parse_svg_path_prefix(cut);
        EXPECT_EQ(parsed.error.has_value(), !error_of(cut).empty());
        std::size_t k = n;
        while (!error_of(cut.substr(0, k)).empty()) --k;
        // The valid prefix can only be shorter when the cut ends inside a number that is
        // itself valid ("M10,2" reads (10, 2)); compare the lengths and the end point.
        const ComplexPath reference = parse_svg_path(cut.substr(0, k));
        if (!parsed.error) continue;
        EXPECT_NEAR(parsed.path.length(), reference.length(), 1e-12 * (1.0 + reference.length()));
        EXPECT_EQ(parsed.path.point(1.0), reference.point(1.0));
    }
}

TEST(SvgErrorRule, ErrorsBeforeAnyDrawingGiveThePathAtTheOrigin) {
    for (const char* data : {"L1 1", "M @", "M1e309 0 L1 1", "X"}) {
        SCOPED_TRACE(data);
        const grape::SvgPathParse parsed = grape::parse_svg_path_prefix(data);
        ASSERT_TRUE(parsed.error.has_value());
        EXPECT_EQ(parsed.error->message, error_of(data));
        expect_stands_at(parsed.path, {0.0, 0.0});
    }
    // After a moveto the path stands there.
    const grape::SvgPathParse moved = grape::parse_svg_path_prefix("M3 4 L");
    ASSERT_TRUE(moved.error.has_value());
    EXPECT_EQ(moved.error->offset, 6u);
    expect_stands_at(moved.path, {3.0, 4.0});
}

TEST(SvgErrorRule, ASegmentThatCannotBeAPathEndsThePrefix) {
    // Each segment's length fits, the third makes the sum overflow: the first two remain.
    const grape::SvgPathParse parsed = grape::parse_svg_path_prefix("M-1e308 0 L0 0 L1e308 0 L0 0");
    ASSERT_TRUE(parsed.error.has_value());
    EXPECT_EQ(parsed.error->offset, 16u);
    EXPECT_EQ(parsed.path.length(), 1e308);
}

// ---------------------------------------------------------------------------------------------
// Arcs whose radii just reach their endpoints

TEST(SvgJustReachingArcs, HalfCircleFromItsDiameterIsExact) {
    // Radius 49 over a chord of 98: a half circle about (49, 0). Length 49π, the midpoint
    // at the bottom, y = 49 (computed with Λ through 1/rx this came out as 153.93804148621365
    // and y = 49.00000073: the center offset √(1/Λ − 1) turned 1 − 2⁻⁵³ into 1.5e-8).
    const ComplexPath path = parse_svg_path("M 98 0 A 49 49 0 1 1 0 0");
    EXPECT_NEAR(path.length(), 49.0 * pi, 4 * eps * 154.0);  // a few ulps of 154
    EXPECT_NEAR(path.point(0.5).x, 49.0, 4 * eps * 98.0);
    EXPECT_NEAR(path.point(0.5).y, 49.0, 4 * eps * 98.0);
    EXPECT_NEAR(path.point(1.0).x, 0.0, 4 * eps * 98.0);  // cos π, sin π: rounding of the radius 49
    EXPECT_NEAR(path.point(1.0).y, 0.0, 4 * eps * 98.0);
}

TEST(SvgJustReachingArcs, DecimalDataThatOnlyRoundsToReachingIsSnapped) {
    // Icons draw circles as two half-arcs with decimal data: from (20.32, 2.91) to
    // (7.12, 25.31) is a chord of exactly 26 (13.2² + 22.4² = 676), radius 13, but the halved
    // decimal coordinates give Λ = 1 − 2⁻⁵²; likewise the vertical chord 28.33 − 13.41 = 14.92
    // with radius 7.46. Each circle has length 2πr.
    struct Case { const char* data; double radius; };
    for (const Case c : {Case{"M 20.32 2.91 A 13 13 0 0 1 7.12 25.31 A 13 13 0 0 1 20.32 2.91", 13.0},
                         Case{"M 0.53 28.33 A 7.46 7.46 0 1 0 0.53 13.41 A 7.46 7.46 0 1 0 0.53 28.33", 7.46}}) {
        SCOPED_TRACE(c.data);
        const ComplexPath path = parse_svg_path(c.data);
        // Snapped, the center is the chord's midpoint: the error is the rounding of the data
        // (a few ulps of the coordinates), not the 1e-8 of an unsnapped square root.
        EXPECT_NEAR(path.length(), 2.0 * pi * c.radius, 1e-13 * c.radius);
        EXPECT_NEAR(grape::distance(path.point(0.25), path.point(0.75)), 2.0 * c.radius, 1e-13 * c.radius);
    }
}

// Exact arithmetic on doubles, for references independent of the code under test: a value is
// an unevaluated sum of doubles, so sums are exact by concatenation and products by Dekker's
// exact two-product of every pair of terms; only the final read-out rounds.
struct ExactSum {
    std::vector<double> terms;
};

void split_halves(double a, double& hi, double& lo) {
    const double c = 134217729.0 * a;  // 2²⁷ + 1: hi keeps the upper 26 bits of the significand
    hi = c - (c - a);
    lo = a - hi;
}

// The same value as few nonoverlapping doubles, smallest first (Shewchuk's grow-expansion
// with Knuth's two-sum, exact; zeros dropped), so products and sums stay small.
ExactSum compressed(const ExactSum& a) {
    std::vector<double> expansion;
    for (double t : a.terms) {
        std::vector<double> grown;
        for (const double e : expansion) {
            const double s = t + e;
            const double bv = s - t;
            const double err = (t - (s - bv)) + (e - bv);
            if (err != 0.0) grown.push_back(err);
            t = s;
        }
        if (t != 0.0) grown.push_back(t);
        expansion = std::move(grown);
    }
    return ExactSum{std::move(expansion)};
}

ExactSum operator*(const ExactSum& a_in, const ExactSum& b_in) {
    const ExactSum a = compressed(a_in);
    const ExactSum b = compressed(b_in);
    ExactSum product;
    for (const double x : a.terms) {
        for (const double y : b.terms) {
            double xh = 0.0, xl = 0.0, yh = 0.0, yl = 0.0;
            split_halves(x, xh, xl);
            split_halves(y, yh, yl);
            const double p = x * y;
            product.terms.push_back(p);
            product.terms.push_back(((xh * yh - p) + xh * yl + xl * yh) + xl * yl);
        }
    }
    return product;
}

ExactSum operator+(ExactSum a, const ExactSum& b) {
    a.terms.insert(a.terms.end(), b.terms.begin(), b.terms.end());
    return a;
}

ExactSum operator-(ExactSum a, ExactSum b) {
    for (double& t : b.terms) t = -t;
    return std::move(a) + b;
}

// The sum rounded to a few ulps: its nonoverlapping expansion summed from the smallest part
// up rounds only at the top.
double value_of(const ExactSum& a) {
    double sum = 0.0;
    for (const double e : compressed(a).terms) sum += e;
    return sum;
}

ExactSum exact(double a) { return ExactSum{{a}}; }

TEST(SvgJustReachingArcs, TheExactReferenceIsExact) {
    // (1 + 2⁻³⁰)² − (1 + 2⁻²⁹) is 2⁻⁶⁰, the term a double product drops.
    const double a = 1.0 + std::ldexp(1.0, -30);
    EXPECT_EQ(value_of(exact(a) * exact(a) - exact(1.0 + std::ldexp(1.0, -29))), std::ldexp(1.0, -60));
    EXPECT_EQ(value_of(exact(3.0) * exact(7.0) - exact(21.0)), 0.0);
    // 0.1 and 0.01 are 3602879701896397/2⁵⁵ and 5764607523034235/2⁵⁹: 0.1² − 0.01 is
    // 12980742146337070512478121581609/2¹¹⁰ − 5764607523034235/2⁵⁹ = 9.020562075079397e-19
    // (Python's fractions.Fraction), where the double product says 0.010000000000000002.
    EXPECT_DOUBLE_EQ(value_of(exact(0.1) * exact(0.1) - exact(0.01)), 9.020562075079397e-19);
}

// One arc as the parser reads it, with its exact radicand 1 − Λ (the SVG notes' Λ, F.6.6):
// how far the radii are from just reaching, from the very doubles of the data.
struct NearReachingArc {
    Vec2 from, to;
    double rx = 0.0, ry = 0.0, rotation = 0.0;  // rotation in degrees: any for a circle, else a multiple of 30° or 45°
    bool large_arc = false, sweep = false;

    std::string data() const {
        char text[256];
        std::snprintf(text, sizeof text, "M %.17g %.17g A %.17g %.17g %.17g %d %d %.17g %.17g", from.x, from.y, rx, ry,
                      rotation, large_arc ? 1 : 0, sweep ? 1 : 0, to.x, to.y);
        return text;
    }

    // 1 − Λ = 1 − (x1/rx)² − (y1/ry)² with (x1, y1) = (c·hx + s·hy, −s·hx + c·hy), h half the
    // chord, c and s the rotation's cosine and sine. Times rx²·ry² that is
    //   rx²ry² − ry²(c²hx² + s²hy²) − rx²(s²hx² + c²hy²) − 2cs·hx·hy·(ry² − rx²),
    // exact for rotations whose c², s² are rational and 2cs is rational or a rational times √3
    // (multiples of 30° and 45°); a circle's Λ is |h|²/r² whatever its rotation.
    double radicand() const {
        double c2 = 1.0, s2 = 0.0, cs_rational = 0.0, cs_root3 = 0.0;  // 2cs = cs_rational + cs_root3·√3
        if (rx != ry) {
            const double degrees = std::fmod(rotation, 360.0) + (rotation < 0.0 ? 360.0 : 0.0);
            const int k30 = static_cast<int>(std::lround(degrees / 30.0));
            const int k45 = static_cast<int>(std::lround(degrees / 45.0));
            if (degrees == 45.0 * k45 && k45 % 2 == 1) {
                c2 = s2 = 0.5;
                cs_rational = (k45 % 4 == 1) ? 1.0 : -1.0;  // 45°, 225°: 2cs = 1; 135°, 315°: −1
            } else if (degrees == 30.0 * k30) {
                // cos² and sin 2θ at θ = 30°·k: (1, 0), (¾, √3/2), (¼, √3/2), (0, 0), (¼, −√3/2), (¾, −√3/2), …
                constexpr double cos2[] = {1, 0.75, 0.25, 0, 0.25, 0.75};
                constexpr double sin2[] = {0, 0.5, 0.5, 0, -0.5, -0.5};
                c2 = cos2[k30 % 6];
                s2 = 1.0 - c2;
                cs_root3 = sin2[k30 % 6];
            } else {
                ADD_FAILURE() << "no exact reference for a rotation of " << rotation;
            }
        }
        const ExactSum hx = exact(from.x * 0.5) - exact(to.x * 0.5);  // halving is exact
        const ExactSum hy = exact(from.y * 0.5) - exact(to.y * 0.5);
        const ExactSum rx2 = exact(rx) * exact(rx);
        const ExactSum ry2 = exact(ry) * exact(ry);
        const ExactSum hx2 = hx * hx;
        const ExactSum hy2 = hy * hy;
        const ExactSum cross = hx * hy * (ry2 - rx2);
        const ExactSum scale = rx2 * ry2;
        const ExactSum p = scale - ry2 * (exact(c2) * hx2 + exact(s2) * hy2) - rx2 * (exact(s2) * hx2 + exact(c2) * hy2) -
                           exact(cs_rational) * cross;
        const ExactSum q = exact(-cs_root3) * cross;
        // p + √3·q without cancellation: where they nearly cancel, (p² − 3q²)/(p − √3·q).
        const double pv = value_of(p);
        const double qv = value_of(q);
        const double root3 = std::sqrt(3.0);
        double n = pv;
        if (qv != 0.0) {
            n = (pv > 0.0) == (qv > 0.0) ? pv + root3 * qv : value_of(p * p - exact(3.0) * q * q) / (pv - root3 * qv);
        }
        return n / value_of(scale);
    }

    // The arc's sweep on the unit circle the ellipse maps to: half a turn, plus or minus twice
    // the angle the center's offset √(1 − Λ) (in radii, along the chord's bisector) subtends.
    double exact_sweep() const {
        const double half_turn_change = 2.0 * std::asin(std::sqrt(radicand()));
        return (sweep ? 1.0 : -1.0) * (pi + (large_arc ? half_turn_change : -half_turn_change));
    }
};

double parametric_sweep(const Path& part) {
    const grape::PathSpec spec = grape::describe(part);
    if (const auto* circle = std::get_if<grape::CircleSpec>(&spec)) return circle->end_angle - circle->start_angle;
    const auto& ellipse = std::get<grape::EllipticalArcSpec>(spec);
    return ellipse.end_angle - ellipse.start_angle;
}

// Ordinary rounding after the radicand: two atan2 (an ulp of π each, on arguments a few ulps
// off), the turn added to their difference, and for a circle the rotation added to each angle:
// fewer than 32 ulps of 1 on a sweep near π. A circle's length r·|sweep| adds an ulp.
constexpr double sweep_tolerance = 32 * eps;

struct ArcErrors {
    double sweep = 0.0;   // largest |sweep − exact| / π
    double length = 0.0;  // largest relative length error, circles only
};

ArcErrors check_near_reaching(const NearReachingArc& arc) {
    SCOPED_TRACE(arc.data());
    const ComplexPath path = parse_svg_path(arc.data());
    EXPECT_EQ(path.parts().size(), 1u);
    if (path.parts().size() != 1u) return {};
    const double exact_sweep = arc.exact_sweep();
    const double sweep = parametric_sweep(path.parts()[0]);
    EXPECT_NEAR(sweep, exact_sweep, sweep_tolerance) << "radicand " << arc.radicand();
    ArcErrors errors{std::abs(sweep - exact_sweep) / pi, 0.0};
    if (arc.rx == arc.ry) {
        const double exact_length = arc.rx * std::abs(exact_sweep);
        EXPECT_NEAR(path.length(), exact_length, (sweep_tolerance / pi + eps) * exact_length);
        errors.length = std::abs(path.length() - exact_length) / exact_length;
    }
    return errors;
}

void record(const char* name, double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2e", value);
    ::testing::Test::RecordProperty(name, text);
}

TEST(SvgJustReachingArcs, DecimalRadiiJustPastReachingAreExact) {
    // Radii a hair longer than half the chord (the radicand 1 − Λ between 1e-14 and 1e-8):
    // the center sits √(1 − Λ) radii off the chord, and Λ rounded to a double near 1 costs up
    // to 1e-9 of the sweep. Circles, an ellipse reaching along its y axis, one turned a quarter.
    std::vector<NearReachingArc> arcs{
        {{98, 0}, {0, 0}, 49.0000001, 49.0000001, 0, true, true},
        {{10, 10}, {20, 10}, 5.000000000001, 5.000000000001, 0, false, true},
        {{10, 10}, {20, 10}, 5.00000000000005, 5.00000000000005, 30, true, false},
        {{20.32, 2.91}, {7.12, 25.31}, 13.0000000001, 13.0000000001, 0, true, true},
        {{0.53, 28.33}, {0.53, 13.41}, 7.4600000001, 7.4600000001, 0, false, false},
        {{0, 0}, {0, 40}, 30, 20.0000000001, 0, true, false},
        {{0, 0}, {0, 60}, 30.00000000001, 20, 90, false, true},
        {{-3.5, 7.25}, {96.5, 7.25}, 50.000000000002, 80, 0, true, true},
        {{0, 0}, {-28.2842712474619, 28.2842712474619}, 30, 20.0000000001, 45, true, true},
        {{5, 5}, {5 + 75 * 0.8660254037844386, 5 + 75 * 0.5}, 37.5000000001, 12, 30, false, true},
        {{5, 5}, {5 - 24 * 0.8660254037844386, 5 - 24 * 0.5}, 37.5, 12.00000000001, 120, true, false},
    };
    ArcErrors worst;
    for (const NearReachingArc& arc : arcs) {
        const double radicand = arc.radicand();
        EXPECT_GT(radicand, 16 * eps) << arc.data();  // past the few ulps that snap (below)
        EXPECT_LT(radicand, 1e-7) << arc.data();
        const ArcErrors e = check_near_reaching(arc);
        worst.sweep = std::max(worst.sweep, e.sweep);
        worst.length = std::max(worst.length, e.length);
    }
    record("largest_sweep_error", worst.sweep);
    record("largest_length_error", worst.length);
}

TEST(SvgJustReachingArcs, RandomArcsWithRadicandsNearZeroAreExact) {
    // Random circles (any rotation) and ellipses (turned by multiples of 30° and 45°, where the
    // reference is exact) whose exact radicand lies between 16 ulps and 1e-12, drawn at every
    // flag combination.
    std::mt19937_64 rng(grape::testing::test_seed(20261207));
    std::uniform_real_distribution<double> coordinate(-200.0, 200.0);
    std::uniform_real_distribution<double> radius(0.5, 150.0);
    std::uniform_real_distribution<double> turn(0.0, 2.0 * pi);
    std::uniform_real_distribution<double> decades(-14.3, -12.0);
    std::uniform_int_distribution<int> bit(0, 1);
    ArcErrors worst;
    int circles = 0;
    int ellipses = 0;
    for (int attempt = 0; attempt < 1000000 && circles + ellipses < 4000; ++attempt) {
        NearReachingArc arc;
        const bool circle = bit(rng) == 1;
        arc.from = {coordinate(rng), coordinate(rng)};
        arc.rx = radius(rng);
        arc.ry = circle ? arc.rx : radius(rng);
        constexpr double turns[] = {0, 30, 45, 60, 90, 120, 135, 150, 180, 210, 225, 240, 270, 300, 315, 330};
        arc.rotation = circle ? 360.0 * bit(rng) * turn(rng) / (2.0 * pi) : turns[std::uniform_int_distribution<int>(0, 15)(rng)];
        arc.large_arc = bit(rng) == 1;
        arc.sweep = bit(rng) == 1;
        // Half the chord at Λ = 1 − 10^decades on the unit circle, mapped to the ellipse's axes
        // and turned into the data's: from − to = 2·half.
        const double reach = std::sqrt(1.0 - std::pow(10.0, decades(rng)));
        const double psi = turn(rng);
        const double x1 = arc.rx * reach * std::cos(psi);
        const double y1 = arc.ry * reach * std::sin(psi);
        const double phi = arc.rotation * (pi / 180.0);
        const Vec2 half{std::cos(phi) * x1 - std::sin(phi) * y1, std::sin(phi) * x1 + std::cos(phi) * y1};
        arc.to = arc.from - 2.0 * half;
        const double radicand = arc.radicand();
        if (!(radicand > 16 * eps && radicand < 1e-12)) continue;  // the rounded data moved it
        (circle ? circles : ellipses) += 1;
        const ArcErrors e = check_near_reaching(arc);
        worst.sweep = std::max(worst.sweep, e.sweep);
        worst.length = std::max(worst.length, e.length);
        if (::testing::Test::HasFailure()) break;
    }
    EXPECT_GT(circles, 1000);
    EXPECT_GT(ellipses, 1000);
    record("largest_sweep_error", worst.sweep);
    record("largest_length_error", worst.length);
}
