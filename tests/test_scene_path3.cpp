// 3-D paths as JSON (grape/scene_path3.hpp): each kind read from its object is the path its
// constructor builds from the same numbers (bit for bit), a helix and an arc have their
// closed-form lengths and ends, and every bad object is refused naming the JSON pointer of
// the bad value.
#include <grape/path3.hpp>
#include <grape/scene_path3.hpp>

#include "error_text.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using grape::Path3;
using grape::Vec3;
using grape::testing::error_text;

bool same_bits(Vec3 a, Vec3 b) {
    return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
           std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
           std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

// The same path: the same kind, the same points and first derivatives at 101 parameters, and the
// same length, all bit for bit (both are built from the same doubles by the same constructor).
void expect_same(const Path3& read, const Path3& built) {
    EXPECT_EQ(read.kind(), built.kind());
    for (int i = 0; i <= 100; ++i) {
        const double u = i / 100.0;
        EXPECT_TRUE(same_bits(read.point(u), built.point(u))) << "u = " << u;
        EXPECT_TRUE(same_bits(read.d1(u), built.d1(u))) << "u = " << u;
    }
    EXPECT_EQ(read.length(), built.length());
}

TEST(ScenePath3, BeziersAreTheirConstructors) {
    expect_same(grape::parse_path3_json(R"({"kind": "line", "points": [[1, 2, 3], [5, -2, 11]]})"),
                Path3::line({1, 2, 3}, {5, -2, 11}));
    expect_same(grape::parse_path3_json(R"({"kind": "quadratic", "points": [[0, 0, 0], [1, 2, 0], [2, 0, 1.5]]})"),
                Path3::quadratic_bezier({0, 0, 0}, {1, 2, 0}, {2, 0, 1.5}));
    expect_same(
        grape::parse_path3_json(R"({"kind": "cubic", "points": [[0, 0, 0], [0, 1e2, 0], [100, 100, -3.25], [100, 0, 7]]})"),
        Path3::cubic_bezier({0, 0, 0}, {0, 100, 0}, {100, 100, -3.25}, {100, 0, 7}));
    // A line's point is exact where its weights are: 0.75·a + 0.25·b.
    EXPECT_EQ(grape::parse_path3_json(R"({"kind": "line", "points": [[1, 2, 3], [5, -2, 11]]})").point(0.25),
              (Vec3{2, 1, 5}));
}

TEST(ScenePath3, CatmullRomAlphaAndClosed) {
    const std::vector<Vec3> pts{{0, 0, 0}, {1, 2, 0}, {3, 3, 1}, {4, 0, 2}};
    const char* points = R"("points": [[0, 0, 0], [1, 2, 0], [3, 3, 1], [4, 0, 2]])";
    const std::pair<const char*, grape::CatmullRom> types[] = {
        {"0", grape::CatmullRom::uniform}, {"0.5", grape::CatmullRom::centripetal}, {"1", grape::CatmullRom::chordal}};
    for (const auto& [alpha, type] : types) {
        for (bool closed : {false, true}) {
            const std::string text = std::string(R"({"kind": "catmull-rom", )") + points + R"(, "alpha": )" + alpha +
                                     R"(, "closed": )" + (closed ? "true" : "false") + "}";
            SCOPED_TRACE(text);
            expect_same(grape::parse_path3_json(text), Path3::catmull_rom(pts, type, closed));
        }
    }
    // The defaults: uniform and open.
    expect_same(grape::parse_path3_json(std::string(R"({"kind": "catmull-rom", )") + points + "}"),
                Path3::catmull_rom(pts));
}

TEST(ScenePath3, HelixMapsOntoHelixSpec) {
    const Path3 read = grape::parse_path3_json(
        R"({"kind": "helix", "center": [1, 2, 3], "axis": [0, 0, 2], "start": [1, 0, 0], "radius": 2,
            "rise_per_turn": 4, "turns": 1.25})");
    expect_same(read, Path3::helix({.center = {1, 2, 3}, .axis = {0, 0, 2}, .start = {1, 0, 0}, .radius = 2, .rise = 4,
                                    .turns = 1.25}));
    // By hand: it starts at center + radius·start; after 1¼ turns counter-clockwise about +z it
    // stands a quarter turn on, at center + radius·y, 1.25·4 = 5 higher. cos(2.5π) is 1e-16, not
    // 0, so the end is within a few ulps of 8 (2e-15): 1e-14.
    EXPECT_EQ(read.point(0.0), (Vec3{3, 2, 3}));
    EXPECT_TRUE(grape::approx_equal(read.point(1.0), {1, 4, 8}, 1e-14));
    // Length T·√((2πR)² + H²), the helix's closed form: within the 1e-14 relative that
    // Path3::length promises.
    const double exact = 1.25 * std::sqrt(std::pow(2.0 * grape::pi * 2.0, 2) + 16.0);
    EXPECT_NEAR(read.length(), exact, 1e-14 * exact);
    // rise_per_turn defaults to 0: a circle, 2πR long.
    const Path3 circle = grape::parse_path3_json(
        R"({"kind": "helix", "center": [0, 0, 0], "axis": [0, 1, 0], "start": [0, 0, 1], "radius": 3, "turns": 1})");
    EXPECT_NEAR(circle.length(), 6.0 * grape::pi, 1e-14 * 6.0 * grape::pi);
}

TEST(ScenePath3, ComplexByCuesByLengthAndNested) {
    const Path3 a = Path3::line({0, 0, 0}, {3, 0, 0});
    const Path3 b = Path3::quadratic_bezier({3, 0, 0}, {4, 1, 0}, {4, 2, 2});
    const char* parts = R"("parts": [{"kind": "line", "points": [[0, 0, 0], [3, 0, 0]]},
                                     {"kind": "quadratic", "points": [[3, 0, 0], [4, 1, 0], [4, 2, 2]]}])";
    expect_same(grape::parse_path3_json(std::string(R"({"kind": "complex", )") + parts + R"(, "cues": [0, 0.25]})"),
                Path3::complex({a, b}, {0, 0.25}));
    expect_same(grape::parse_path3_json(std::string(R"({"kind": "complex", )") + parts + "}"),
                Path3::complex_by_length({a, b}));
    expect_same(grape::parse_path3_json(std::string(R"({"kind": "complex", )") + parts + R"(, "cues": "by_length"})"),
                Path3::complex_by_length({a, b}));
    const Path3 nested = grape::parse_path3_json(std::string(R"({"kind": "complex", "parts": [{"kind": "complex", )") +
                                                 parts + R"(}, {"kind": "line", "points": [[4, 2, 2], [4, 2, 9]]}]})");
    expect_same(nested, Path3::complex_by_length({Path3::complex_by_length({a, b}), Path3::line({4, 2, 2}, {4, 2, 9})}));
}

TEST(ScenePath3, HermiteLinearArcProjectileOnPlane) {
    const std::vector<Vec3> pts{{0, 0, 0}, {2, 1, 0}, {3, 3, 2}};
    const std::vector<Vec3> tangents{{1, 0, 0}, {0, 1, 1}, {-1, 0, 2}};
    const char* points = R"("points": [[0, 0, 0], [2, 1, 0], [3, 3, 2]])";
    const char* tangent_json = R"("tangents": [[1, 0, 0], [0, 1, 1], [-1, 0, 2]])";
    for (bool closed : {false, true}) {
        const std::string loop = closed ? R"(, "closed": true})" : "}";
        expect_same(grape::parse_path3_json(std::string(R"({"kind": "hermite", )") + points + ", " + tangent_json + loop),
                    Path3::hermite(pts, tangents, closed));
        expect_same(grape::parse_path3_json(std::string(R"({"kind": "linear", )") + points + loop),
                    Path3::linear_spline(pts, closed));
    }
    const grape::Arc3Spec arc{.center = {1, 0, 0}, .axis = {0, 1, 0}, .start = {0, 0, 1}, .radius = 2, .start_angle = 0.5,
                              .end_angle = -1.25};
    expect_same(grape::parse_path3_json(R"({"kind": "arc", "center": [1, 0, 0], "axis": [0, 1, 0], "start": [0, 0, 1],
                                            "radius": 2, "start_angle": 0.5, "end_angle": -1.25})"),
                Path3::arc(arc));
    // The angles default to one full turn from 0: 2πr long (Path3::length's 1e-14 relative).
    const Path3 circle = grape::parse_path3_json(
        R"({"kind": "arc", "center": [0, 0, 0], "axis": [0, 0, 1], "start": [1, 0, 0], "radius": 3})");
    EXPECT_NEAR(circle.length(), 6.0 * grape::pi, 1e-14 * 6.0 * grape::pi);
    expect_same(grape::parse_path3_json(R"({"kind": "projectile", "position": [0, 0, 1], "velocity": [3, 0, 4],
                                            "acceleration": [0, 0, -9.8], "seconds": 0.75})"),
                Path3::projectile({0, 0, 1}, {3, 0, 4}, {0, 0, -9.8}, 0.75));
    // A 2-D scene path object on the plane x = 5 (y_axis along z): the 2-D segment (0,0)–(3,4)
    // lands at (5, 0, 0)–(5, 3, 4).
    const Path3 lifted = grape::parse_path3_json(R"({"kind": "on_plane", "path": {"kind": "linear", "start": [0, 0],
        "end": [3, 4]}, "origin": [5, 0, 0], "x_axis": [0, 1, 0], "y_axis": [0, 0, 1]})");
    expect_same(lifted, Path3::on_plane(grape::LinearPath({0, 0}, {3, 4}), {5, 0, 0}, {0, 1, 0}, {0, 0, 1}));
    EXPECT_EQ(lifted.point(1.0), (Vec3{5, 3, 4}));
}

// Every refusal: the message starts "path3: ", names the pointer and says why.
TEST(ScenePath3, ErrorsNameThePointer) {
    const std::pair<const char*, const char*> cases[] = {
        {R"({"kind": "line", )", "path3: JSON syntax error at byte "},
        {R"([1, 2])", "path3: /: expected a 3-D path object, got an array"},
        {R"({"points": []})", "path3: /: missing field \"kind\""},
        {R"({"kind": 3})", "path3: /kind: expected a string, got a number"},
        {R"({"kind": "spline", "points": []})",
         "path3: /kind: unknown 3-D path kind \"spline\" (line, quadratic, cubic, helix, catmull-rom, complex, hermite, "
         "linear, arc, projectile, on_plane)"},
        {R"({"kind": "line", "points": [[0, 0, 0], [1, 1, 1]], "closed": true})",
         "path3: /closed: unknown field \"closed\" (expected one of: kind, points)"},
        {R"({"kind": "line", "points": [[0, 0, 0], [1, 1, 1], [2, 2, 2]]})",
         "path3: /points: a line has exactly 2 points (got 3)"},
        {R"({"kind": "cubic", "points": [[0, 0, 0], [1, 1, 1], [2, 2, 2]]})",
         "path3: /points: a cubic has exactly 4 points (got 3)"},
        {R"({"kind": "quadratic", "points": [[0, 0, 0], [1, 1], [2, 2, 2]]})",
         "path3: /points/1: expected a point [x, y, z], got an array of 2"},
        {R"({"kind": "line", "points": [[0, 0, 0], [1, 1, 1e999]]})", "path3: /points/1/2: number out of range (got 1e999)"},
        {R"({"kind": "line", "points": [[0, 0, 0], [1, "1", 1]]})", "path3: /points/1/1: expected a number, got a string"},
        {R"({"kind": "line", "points": {"a": 1}})", "path3: /points: expected an array, got an object"},
        {R"({"kind": "catmull-rom", "points": [[0, 0, 0]]})", "path3: /points: too few points: 1 (at least 2)"},
        {R"({"kind": "catmull-rom", "points": [[0, 0, 0], [1, 0, 0]], "closed": true})",
         "path3: /points: too few points: 2 (at least 3)"},
        {R"({"kind": "catmull-rom", "points": [[0, 0, 0], [1, 0, 0]], "alpha": 0.25})",
         "path3: /alpha: must be 0 (uniform), 0.5 (centripetal) or 1 (chordal) (got 0.25)"},
        {R"({"kind": "catmull-rom", "points": [[0, 0, 0], [1, 0, 0]], "closed": 1})",
         "path3: /closed: expected true or false, got a number"},
        {R"({"kind": "helix", "center": [0, 0, 0], "axis": [0, 0, 0], "start": [1, 0, 0], "radius": 1, "turns": 1})",
         "path3: /axis: must not be the zero vector"},
        {R"({"kind": "helix", "center": [0, 0, 0], "axis": [0, 0, 1], "start": [0, 0, 0], "radius": 1, "turns": 1})",
         "path3: /start: must not be the zero vector"},
        {R"({"kind": "helix", "center": [0, 0, 0], "axis": [0, 0, 1], "start": [0, 0, -5], "radius": 1, "turns": 1})",
         "path3: /start: is parallel to the axis"},
        {R"({"kind": "helix", "center": [0, 0, 0], "axis": [0, 0, 1], "start": [1, 0, 0], "radius": 0, "turns": 1})",
         "path3: /radius: must be positive (got 0)"},
        {R"({"kind": "helix", "center": [0, 0, 0], "axis": [0, 0, 1], "start": [1, 0, 0], "radius": 1, "turns": -1})",
         "path3: /turns: must be positive (got -1)"},
        {R"({"kind": "helix", "axis": [0, 0, 1], "start": [1, 0, 0], "radius": 1, "turns": 1})",
         "path3: /: missing field \"center\""},
        {R"({"kind": "helix", "center": [0, 0, 0], "axis": [0, 0, 1], "start": [1, 0, 0], "radius": 1, "turns": 1, "rise": 2})",
         "path3: /rise: unknown field \"rise\""},
        {R"({"kind": "complex", "parts": []})", "path3: /parts: a complex path needs at least one part"},
        {R"({"kind": "complex", "parts": [{"kind": "line", "points": [[0, 0, 0], [1, 0, 0]]}, {"kind": "cubic", "points": [[0, 0, 0], [1, 0, 0], [1, 0, 0], [1, "x", 0]]}]})",
         "path3: /parts/1/points/3/1: expected a number, got a string"},
        {R"({"kind": "complex", "parts": [{"kind": "line", "points": [[0, 0, 0], [1, 0, 0]]}], "cues": [0, 0.5]})",
         "path3: /cues: one cue per part: 1 parts but 2 cues"},
        {R"({"kind": "complex", "parts": [{"kind": "line", "points": [[0, 0, 0], [1, 0, 0]]}, {"kind": "line", "points": [[0, 0, 0], [1, 0, 0]]}], "cues": [0.5, 0.6]})",
         "path3: /cues/0: the first cue must be 0 (got 0.5)"},
        {R"({"kind": "complex", "parts": [{"kind": "line", "points": [[0, 0, 0], [1, 0, 0]]}, {"kind": "line", "points": [[0, 0, 0], [1, 0, 0]]}, {"kind": "line", "points": [[0, 0, 0], [1, 0, 0]]}], "cues": [0, 0.6, 0.5]})",
         "path3: /cues/2: cues must not decrease (0.5 after 0.6)"},
        {R"({"kind": "complex", "parts": [{"kind": "line", "points": [[0, 0, 0], [1, 0, 0]]}], "cues": "even"})",
         "path3: /cues: expected an array of numbers or \"by_length\", got a string"},
        {R"({"kind": "hermite", "points": [[0, 0, 0], [1, 0, 0]], "tangents": [[1, 0, 0]]})",
         "path3: /tangents: one tangent per point: 2 points but 1 tangents"},
        {R"({"kind": "hermite", "points": [[0, 0, 0], [1, 0, 0]], "tangents": [[1, 0, 0], [1, 0]]})",
         "path3: /tangents/1: expected a point [x, y, z], got an array of 2"},
        {R"({"kind": "linear", "points": [[0, 0, 0], [1, 0, 0]], "closed": true})",
         "path3: /points: too few points: 2 (at least 3)"},
        {R"({"kind": "projectile", "position": [0, 0, 0], "velocity": [1, 0, 0], "acceleration": [0, 0, -9.8], "seconds": 0})",
         "path3: /seconds: must be positive (got 0)"},
        {R"({"kind": "on_plane", "path": {"kind": "linear", "start": [0, 0], "end": [1, 0, 0]}, "origin": [0, 0, 0], "x_axis": [1, 0, 0], "y_axis": [0, 1, 0]})",
         "path3: /path/end: expected a point [x, y], got an array of 3"},
        // A Path3 constructor's own refusal, at the field it names (or the object it was building).
        {R"({"kind": "arc", "center": [0, 0, 0], "axis": [0, 0, 1], "start": [0, 0, 2], "radius": 1})",
         "path3: /start: parallel to the axis"},
        {R"({"kind": "on_plane", "path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "origin": [0, 0, 0], "x_axis": [1, 0, 0], "y_axis": [1, 1, 0]})",
         "path3: /y_axis: "},
        {R"({"kind": "line", "points": [[-1e308, 0, 0], [1e308, 0, 0]]})", "path3: /: Path3 (line): the length overflows"},
    };
    for (const auto& entry : cases) {
        // Named copies: a lambda may not capture a structured binding in clang 14.
        const char* text = entry.first;
        const std::string expected = entry.second;
        const std::string message = error_text([&] { (void)grape::parse_path3_json(text); });
        EXPECT_EQ(message.rfind(expected, 0), 0u) << text << "\nmessage:  " << message << "\nexpected: " << expected;
    }
}

// Complex paths nest up to 32 deep (a bound on the recursion over hostile input): 32 levels
// read, 33 are refused at the innermost object's pointer.
TEST(ScenePath3, NestingIsBounded) {
    const auto nested = [](int levels) {
        std::string text = R"({"kind": "line", "points": [[0, 0, 0], [1, 0, 0]]})";
        for (int i = 0; i < levels; ++i) text = R"({"kind": "complex", "parts": [)" + text + "]}";
        return text;
    };
    EXPECT_DOUBLE_EQ(grape::parse_path3_json(nested(32)).length(), 1.0);
    std::string pointer;
    for (int i = 0; i < 33; ++i) pointer += "/parts/0";
    EXPECT_EQ(error_text([&] { (void)grape::parse_path3_json(nested(33)); }),
              "path3: " + pointer + ": paths nested more than 32 deep");
}

}  // namespace
