// scene: JSON load/save. Loaded objects are checked against the numbers in the file,
// save → load is checked to give bit-identical paths, and every kind of bad input is checked
// to name its JSON pointer and the reason.
#include <grape/anim.hpp>
#include <grape/error.hpp>
#include <grape/path_query.hpp>
#include <grape/scene.hpp>

#include "seed_paths.hpp"
#if GRAPE_HAS_DYNAMICS
#include <grape/dynamics.hpp>

#include "seed_dynamics.hpp"
#include "seeds.hpp"
#endif

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>

namespace {

using grape::Path;
using grape::Scene;
using grape::Vec2;

// A scene using every path kind, a named curve, references and a simulation.
const char* const complete_scene = R"json({
  "grape_scene": 1,
  "name": "everything",
  "view": {"width": 800, "height": 600, "ticks": 0.05},
  "paths": [
    {"name": "line", "path": {"kind": "linear", "start": [0, 0], "end": [3, 4]}},
    {"name": "circle", "path": {"kind": "circle", "center": [150, 200], "radius": 50, "start_angle": 6.283185307179586, "end_angle": 0}},
    {"name": "ellipse", "path": {"kind": "elliptical_arc", "center": [0, 0], "rx": 80, "ry": 30, "rotation": 0.5, "start_angle": 0, "end_angle": 3}},
    {"name": "spiral", "path": {"kind": "spiral", "center": [100, 100], "start_radius": 200, "end_radius": 0}},
    {"name": "sine", "path": {"kind": "sine_wave", "start": [350, 200], "end": [200, 200], "frequency": 3, "amplitude": 50}},
    {"name": "quad", "path": {"kind": "quadratic_bezier", "points": [[0, 0], [50, 100], [100, 0]]}},
    {"name": "bez", "path": {"kind": "cubic_bezier", "points": [[20, 20], [400, 200], [400, 600], [600, 600]], "reparametrize": true}},
    {"name": "p1", "path": {"kind": "linear_spline", "points": [[20, 20], [100, 100], [120, 50], [300, 300]]}},
    {"name": "p2", "path": {"kind": "cosine_spline", "points": [[20, 120], [100, 200], [120, 150]]}},
    {"name": "herm", "path": {"kind": "hermite_spline", "points": [[0, 0], [100, 50]], "tangents": [[100, 200], [0, -300]]}},
    {"name": "p3", "path": {"kind": "catmull_rom_spline", "points": [[20, 220], [100, 300], [120, 250], [300, 500]], "type": "centripetal"}},
    {"name": "shot", "path": {"kind": "physics", "position": [0, 0], "velocity": [100, -200], "acceleration": [0, 400], "seconds": 1}},
    {"name": "drawn", "path": {"kind": "svg", "data": "M10 10 C 20 80 90 80 100 10 A 40 20 30 1 0 150 60 Z"}},
    {"name": "nested", "path": {"kind": "complex", "parts": ["circle", {"kind": "complex", "parts": ["line", "quad"]}, "sine"], "cues": [0, 0.5, 0.75]}}
  ],
  "curves": [{"name": "bouncy", "curve": "back-out(2.5)"}],
  "animations": [
    {"name": "a", "path": "spiral", "curve": "quad-in-out", "duration": 2, "delay": 0.5, "repeat": 2, "yoyo": true},
    {"path": {"kind": "linear", "start": [0, 0], "end": [10, 0]}, "curve": "bouncy", "duration": 1, "reversed": true, "repeat": -1}
  ],
  "simulations": [
    {"name": "parabola", "integrator": "rk4", "drift": "none", "dt": 0.01, "duration": 5,
     "particles": [{"position": [100, -100], "velocity": [0, 0], "mass": 1}, {"position": [0, 0], "mass": "pinned"}],
     "forces": [{"kind": "gravity", "acceleration": [0, 500]}, {"kind": "drag", "k": 0.1},
                {"kind": "spring", "a": 0, "b": 1, "rest_length": 10, "stiffness": 5, "damping": 0.5}],
     "constraints": [{"kind": "conic", "a": 0, "coefficients": [1, 0, 0, 0, 100, 0]},
                     {"kind": "distance", "a": 0, "b": 1}, {"kind": "anchor", "a": 0, "point": [0, 0], "length": 50},
                     {"kind": "fixed_point", "a": 1, "point": [0, 0]}]}
  ]
})json";

// Bit-identical evaluation at many parameters (including the ends and outside [0, 1]).
void expect_same_path(const Path& a, const Path& b, const std::string& label) {
    ASSERT_EQ(a.kind(), b.kind()) << label;
    for (int i = -5; i <= 105; ++i) {
        const double u = i / 100.0;
        ASSERT_EQ(a.point(u), b.point(u)) << label << " at u = " << u;
        ASSERT_EQ(a.d1(u), b.d1(u)) << label << " at u = " << u;
        ASSERT_EQ(a.d2(u), b.d2(u)) << label << " at u = " << u;
    }
    EXPECT_EQ(a.length(), b.length()) << label;
}

void expect_same_scene(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.view.width, b.view.width);
    EXPECT_EQ(a.view.height, b.view.height);
    EXPECT_EQ(a.view.ticks, b.view.ticks);
    ASSERT_EQ(a.paths.size(), b.paths.size());
    for (std::size_t i = 0; i < a.paths.size(); ++i) {
        EXPECT_EQ(a.paths[i].name, b.paths[i].name);
        expect_same_path(a.paths[i].path, b.paths[i].path, a.paths[i].name);
    }
    ASSERT_EQ(a.curves.size(), b.curves.size());
    for (std::size_t i = 0; i < a.curves.size(); ++i) {
        EXPECT_EQ(a.curves[i].name, b.curves[i].name);
        EXPECT_TRUE(a.curves[i].curve == b.curves[i].curve);
    }
    ASSERT_EQ(a.animations.size(), b.animations.size());
    for (std::size_t i = 0; i < a.animations.size(); ++i) {
        const auto& x = a.animations[i];
        const auto& y = b.animations[i];
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.path_name, y.path_name);
        expect_same_path(x.path, y.path, "animation " + std::to_string(i));
        EXPECT_TRUE(x.curve == y.curve);
        EXPECT_EQ(x.curve_name, y.curve_name);
        EXPECT_EQ(x.duration, y.duration);
        EXPECT_EQ(x.delay, y.delay);
        EXPECT_EQ(x.repeat, y.repeat);
        EXPECT_EQ(x.yoyo, y.yoyo);
        EXPECT_EQ(x.reversed, y.reversed);
        EXPECT_EQ(x.range_start, y.range_start);
        EXPECT_EQ(x.range_end, y.range_end);
        EXPECT_EQ(x.offset, y.offset);
    }
    ASSERT_EQ(a.sprites.size(), b.sprites.size());
    for (std::size_t i = 0; i < a.sprites.size(); ++i) {
        const auto& x = a.sprites[i];
        const auto& y = b.sprites[i];
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.sheet_file, y.sheet_file);
        EXPECT_EQ(x.clip, y.clip);
        EXPECT_EQ(x.first_frame, y.first_frame);
        EXPECT_EQ(x.last_frame, y.last_frame);
        EXPECT_EQ(x.rate, y.rate);
        EXPECT_EQ(x.scale, y.scale);
        EXPECT_EQ(x.animation, y.animation);
        EXPECT_EQ(x.at, y.at);
    }
    ASSERT_EQ(a.simulations.size(), b.simulations.size());
    for (std::size_t i = 0; i < a.simulations.size(); ++i) {
        const auto& x = a.simulations[i];
        const auto& y = b.simulations[i];
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.integrator, y.integrator);
        EXPECT_EQ(x.drift, y.drift);
        EXPECT_EQ(x.dt, y.dt);
        EXPECT_EQ(x.duration, y.duration);
        ASSERT_EQ(x.particles.size(), y.particles.size());
        for (std::size_t k = 0; k < x.particles.size(); ++k) {
            EXPECT_EQ(x.particles[k].position, y.particles[k].position);
            EXPECT_EQ(x.particles[k].velocity, y.particles[k].velocity);
            EXPECT_EQ(x.particles[k].mass, y.particles[k].mass);
        }
        ASSERT_EQ(x.forces.size(), y.forces.size());
        for (std::size_t k = 0; k < x.forces.size(); ++k) {
            EXPECT_EQ(x.forces[k].kind, y.forces[k].kind);
            EXPECT_EQ(x.forces[k].gravity, y.forces[k].gravity);
            EXPECT_EQ(x.forces[k].drag, y.forces[k].drag);
            EXPECT_EQ(x.forces[k].stiffness, y.forces[k].stiffness);
        }
        ASSERT_EQ(x.constraints.size(), y.constraints.size());
        for (std::size_t k = 0; k < x.constraints.size(); ++k) {
            EXPECT_EQ(x.constraints[k].kind, y.constraints[k].kind);
            EXPECT_EQ(x.constraints[k].a, y.constraints[k].a);
            EXPECT_EQ(x.constraints[k].point, y.constraints[k].point);
            EXPECT_EQ(x.constraints[k].length, y.constraints[k].length);
            for (int m = 0; m < 6; ++m) EXPECT_EQ(x.constraints[k].conic[m], y.constraints[k].conic[m]);
        }
    }
}

void expect_error(const std::string& json, const std::string& pointer, const std::string& reason) {
    try {
        (void)grape::load_scene(json);
        ADD_FAILURE() << "accepted: " << json;
    } catch (const grape::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("scene: " + pointer + ": "), std::string::npos) << "message: " << what << "\nwanted pointer " << pointer;
        EXPECT_NE(what.find(reason), std::string::npos) << "message: " << what << "\nwanted reason " << reason;
    }
}

// ---------------------------------------------------------------------------------- load

TEST(SceneLoad, ReadsEveryPart) {
    const Scene s = grape::load_scene(complete_scene);
    EXPECT_EQ(s.name, "everything");
    EXPECT_EQ(s.view.width, 800);
    EXPECT_EQ(s.view.ticks, 0.05);
    ASSERT_EQ(s.paths.size(), 14u);
    // Closed forms of the simplest kinds, straight from the numbers in the file.
    EXPECT_EQ(s.find_path("line")->path.length(), 5.0);
    EXPECT_NEAR(s.find_path("circle")->path.length(), 2 * grape::pi * 50, 1e-10);  // exact arc, ~1e-13 relative
    EXPECT_EQ(s.find_path("circle")->path.point(0.25), grape::CirclePath({150, 200}, 50, 2 * grape::pi, 0).point(0.25));
    EXPECT_EQ(s.find_path("bez")->path.kind(), grape::PathKind::reparametrized);
    EXPECT_EQ(s.find_path("drawn")->path.kind(), grape::PathKind::complex);
    // References share the named path (same shape object, not a copy).
    const auto* nested = s.find_path("nested");
    ASSERT_NE(nested, nullptr);
    EXPECT_EQ(nested->path.point(0.0), s.find_path("circle")->path.point(0.0));
    EXPECT_TRUE(s.animations[0].path == s.find_path("spiral")->path);
    EXPECT_EQ(s.animations[0].path_name, "spiral");
    EXPECT_TRUE(s.animations[0].curve == grape::Curve::quad_in_out());
    EXPECT_EQ(s.animations[0].repeat, 2);
    EXPECT_TRUE(s.animations[0].yoyo);
    EXPECT_EQ(s.animations[1].curve_name, "bouncy");
    EXPECT_TRUE(s.animations[1].curve == grape::Curve::back(grape::EaseDirection::out, 2.5));
    EXPECT_TRUE(s.animations[1].reversed);
    EXPECT_EQ(s.animations[1].repeat, -1);
    ASSERT_EQ(s.simulations.size(), 1u);
    const auto& sim = s.simulations[0];
    EXPECT_EQ(sim.integrator, "rk4");
    EXPECT_EQ(sim.drift, "none");
    EXPECT_TRUE(std::isinf(sim.particles[1].mass));
    EXPECT_EQ(sim.forces[2].kind, grape::SceneForceKind::spring);
    EXPECT_EQ(sim.constraints[0].conic[4], 100.0);
    EXPECT_EQ(sim.constraints[1].length, 0.0);  // 0: keep the starting distance
}

TEST(SceneLoad, DefaultsAreDocumented) {
    const Scene s = grape::load_scene(R"({"animations": [{"path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 3}]})");
    ASSERT_EQ(s.animations.size(), 1u);
    const auto& a = s.animations[0];
    EXPECT_TRUE(a.curve == grape::Curve::linear());
    EXPECT_EQ(a.delay, 0.0);
    EXPECT_EQ(a.repeat, 0);
    EXPECT_FALSE(a.yoyo);
    EXPECT_FALSE(a.reversed);
    EXPECT_EQ(s.view.width, 640);
    EXPECT_EQ(s.view.height, 480);
}

TEST(SceneLoad, SeedScenesMatchTheCatalogue) {
    // The seed's nested example written as JSON gives the catalogue's path exactly.
    const Scene s = grape::load_scene(R"({"paths": [{"name": "nested", "path": {"kind": "complex", "cues": [0, 0.5, 0.75], "parts": [
        {"kind": "complex", "cues": [0, 0.25, 0.5], "parts": [
            {"kind": "circle", "center": [150, 200], "radius": 50, "start_angle": 6.283185307179586, "end_angle": 0},
            {"kind": "circle", "center": [250, 200], "radius": 50, "start_angle": 3.141592653589793, "end_angle": 9.42477796076938},
            {"kind": "circle", "center": [300, 200], "radius": 100, "start_angle": 3.141592653589793, "end_angle": 9.42477796076938}]},
        {"kind": "cubic_bezier", "points": [[200, 200], [350, 0], [350, 500], [350, 200]]},
        {"kind": "sine_wave", "start": [350, 200], "end": [200, 200], "frequency": 3, "amplitude": 50}]}}]})");
    expect_same_path(s.paths[0].path, grape::scenes::seed_nested_complex(), "seed nested complex");
}

// ------------------------------------------------------------------------------ round trip

TEST(SceneLoad, TheOlderSpellingCentreReadsAsCenter) {
    const auto path_of = [](const char* key) {
        const std::string text = std::string(R"({"paths": [{"name": "s", "path": {"kind": "spiral", ")") + key +
                                 R"(": [3, 4], "start_radius": 10, "end_radius": 2, "end_angle": 7}}]})";
        return grape::load_scene(text).find_path("s")->path;
    };
    const grape::Path older = path_of("centre"), newer = path_of("center");
    for (int k = 0; k <= 16; ++k) EXPECT_EQ(older.point(k / 16.0), newer.point(k / 16.0)) << k;
    expect_error(R"({"paths": [{"name": "c", "path": {"kind": "circle", "center": [0, 0], "centre": [0, 0], "radius": 1}}]})",
                 "/paths/0/path/centre", "give \"center\" only");
}

TEST(SceneRoundTrip, SaveThenLoadGivesTheSameObjects) {
    const Scene first = grape::load_scene(complete_scene);
    const std::string text = grape::save_scene(first);
    const Scene second = grape::load_scene(text);
    expect_same_scene(first, second);
    // Saving is a fixed point: the second save is the same text.
    EXPECT_EQ(grape::save_scene(second), text);
    // References stay references.
    EXPECT_NE(text.find("\"path\": \"spiral\""), std::string::npos);
    EXPECT_NE(text.find("\"curve\": \"bouncy\""), std::string::npos);
}

TEST(SceneRoundTrip, PathsBuiltInCodeSaveToo) {
    for (const auto& [name, path] : grape::scenes::path_gallery()) {
        const Path back = grape::parse_path_json(grape::path_to_json(path));
        expect_same_path(path, back, name);
    }
    for (const auto& [name, path] : grape::scenes::seed_paths()) {
        const Path back = grape::parse_path_json(grape::path_to_json(path));
        expect_same_path(path, back, name);
    }
}

// Random scenes (fixed seed): random path trees of every kind, curves and timings.
TEST(SceneRoundTrip, RandomScenes) {
    std::mt19937_64 rng(grape::testing::test_seed(20261122));
    std::uniform_real_distribution<double> coord(-500, 500);
    std::uniform_real_distribution<double> unit(0, 1);
    const auto pt = [&] { return Vec2{coord(rng), coord(rng)}; };
    const auto points = [&](int n) {
        std::vector<Vec2> p;
        for (int i = 0; i < n; ++i) p.push_back(pt());
        return p;
    };
    std::function<Path(int)> random_path = [&](int depth) -> Path {
        const int kind = static_cast<int>(rng() % (depth < 2 ? 13 : 12));
        switch (kind) {
            case 0: return grape::LinearPath(pt(), pt());
            case 1: return grape::CirclePath(pt(), 1 + 100 * unit(rng), coord(rng) / 50, coord(rng) / 50);
            case 2: return grape::EllipticalArcPath(pt(), 1 + 100 * unit(rng), 1 + 50 * unit(rng), unit(rng) * 3, 0, 1 + unit(rng) * 5);
            case 3: return grape::SpiralPath(pt(), 100 * unit(rng), 100 * unit(rng), 0, 1 + 10 * unit(rng));
            case 4: return grape::SineWavePath(pt(), pt(), 1 + 5 * unit(rng), 50 * unit(rng));
            case 5: return grape::QuadraticBezierPath(pt(), pt(), pt(), rng() % 2 == 0);
            case 6: return grape::CubicBezierPath(pt(), pt(), pt(), pt(), rng() % 2 == 0);
            case 7: { const auto p = points(2 + static_cast<int>(rng() % 5)); return grape::LinearSplinePath(std::span<const Vec2>(p)); }
            case 8: { const auto p = points(2 + static_cast<int>(rng() % 5)); return grape::CosineSplinePath(std::span<const Vec2>(p)); }
            case 9: {
                const auto p = points(2 + static_cast<int>(rng() % 5));
                const auto t = points(static_cast<int>(p.size()));
                return grape::HermiteSplinePath(std::span<const Vec2>(p), std::span<const Vec2>(t));
            }
            case 10: {
                const auto p = points(2 + static_cast<int>(rng() % 5));
                return grape::CatmullRomSplinePath(std::span<const Vec2>(p), static_cast<grape::CatmullRom>(rng() % 3));
            }
            case 11: return grape::PhysicsPath(pt(), pt(), pt(), 0.1 + unit(rng) * 3);
            default: {
                std::vector<Path> parts;
                const int n = 1 + static_cast<int>(rng() % 4);
                for (int i = 0; i < n; ++i) parts.push_back(random_path(depth + 1));
                if (rng() % 2 == 0) return grape::ComplexPath::by_length(parts);
                std::vector<double> cues{0.0};
                for (int i = 1; i < n; ++i) cues.push_back(std::min(1.0, cues.back() + unit(rng) / n));
                return grape::ComplexPath(parts, cues);
            }
        }
    };
    const auto names = grape::curve_names();
    for (int round = 0; round < 30; ++round) {
        Scene s;
        s.name = std::string("random ").append(std::to_string(round));
        for (int i = 0; i < 4; ++i) s.paths.push_back({std::string("p").append(std::to_string(i)), random_path(0)});
        for (int i = 0; i < 3; ++i) {
            grape::SceneAnimation a;
            a.path = i == 0 ? s.paths[1].path : random_path(0);
            a.path_name = i == 0 ? "p1" : "";
            a.curve = grape::parse_curve(names[rng() % names.size()]);
            a.duration = 0.1 + unit(rng) * 5;
            a.delay = unit(rng);
            a.repeat = static_cast<int>(rng() % 4) - 1;
            a.yoyo = rng() % 2 == 0;
            a.reversed = rng() % 2 == 0;
            if (rng() % 2 == 0) a.range_start = unit(rng), a.range_end = unit(rng);
            if (rng() % 2 == 0) a.offset = coord(rng) / 10;
            s.animations.push_back(a);
        }
        const std::string text = grape::save_scene(s);
        const Scene back = grape::load_scene(text);
        expect_same_scene(s, back);
        EXPECT_EQ(grape::save_scene(back), text);
    }
}

TEST(SceneRoundTrip, Files) {
    const auto dir = std::filesystem::temp_directory_path() / "grape_test_scene";
    std::filesystem::create_directories(dir);
    const Scene s = grape::load_scene(complete_scene);
    grape::save_scene_file(s, dir / "copy.json");
    expect_same_scene(s, grape::load_scene_file(dir / "copy.json"));
    for (const auto& entry : std::filesystem::directory_iterator(dir))  // no temporary left
        EXPECT_NE(entry.path().filename().string().rfind("copy.json.partial", 0), 0u) << entry.path();
    try {
        grape::save_scene_file(s, "/nonexistent/dir/x.json");
        ADD_FAILURE();
    } catch (const grape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/x.json"), std::string::npos) << e.what();
    }
    try {
        (void)grape::load_scene_file(dir / "missing.json");
        ADD_FAILURE();
    } catch (const grape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.json: no such file"), std::string::npos) << e.what();
    }
    // Errors inside a file name the file and the pointer.
    std::ofstream(dir / "bad.json") << R"({"animations": [{"path": "nowhere", "duration": 1}]})";
    try {
        (void)grape::load_scene_file(dir / "bad.json");
        ADD_FAILURE();
    } catch (const grape::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("bad.json: scene: /animations/0/path: unknown path \"nowhere\""), std::string::npos) << what;
    }
}

// ------------------------------------------------------------------------------ timing

TEST(SceneAnimation, ProgressFollowsDelayRepeatYoyoAndReverse) {
    grape::SceneAnimation a;
    a.path = grape::LinearPath({0, 0}, {100, 0});
    a.duration = 2.0;
    a.delay = 1.0;
    // Linear curve: progress is the fraction of the play, exactly (binary fractions).
    EXPECT_EQ(a.progress(0.0), 0.0);
    EXPECT_EQ(a.progress(1.0), 0.0);
    EXPECT_EQ(a.progress(2.0), 0.5);
    EXPECT_EQ(a.progress(3.0), 1.0);
    EXPECT_EQ(a.progress(50.0), 1.0);  // plays once, then rests at the end
    EXPECT_EQ(a.position(2.5), (Vec2{75, 0}));
    EXPECT_EQ(a.end_time(), 3.0);
    a.repeat = 2;
    a.yoyo = true;
    EXPECT_EQ(a.progress(3.5), 0.75);  // second play runs backwards: 1 − 0.25
    EXPECT_EQ(a.progress(5.0), 0.0);   // end of the backward play
    EXPECT_EQ(a.progress(5.5), 0.25);  // third play forwards again
    EXPECT_EQ(a.progress(7.0), 1.0);
    EXPECT_EQ(a.progress(99.0), 1.0);
    EXPECT_EQ(a.end_time(), 7.0);
    a.reversed = true;
    EXPECT_EQ(a.progress(0.0), 1.0);
    EXPECT_EQ(a.progress(1.5), 0.75);
    EXPECT_EQ(a.progress(3.5), 0.25);
    a.repeat = -1;
    EXPECT_TRUE(std::isinf(a.end_time()));
    EXPECT_EQ(a.progress(1001.5), 0.75);  // 500 plays later: even play, reversed
    // The curve applies within each play; a backward play is the forward one run back in time.
    a = {};
    a.duration = 1.0;
    a.curve = grape::Curve::quad_in();
    EXPECT_EQ(a.progress(0.5), 0.25);
    EXPECT_EQ(a.progress(0.25), 0.0625);
    a.reversed = true;
    EXPECT_EQ(a.progress(0.25), 0.5625);  // curve(0.75), not 1 − curve(0.25)
}

// ------------------------------------------------------------------------------ errors

TEST(SceneErrors, NameThePointerAndTheReason) {
    // A typical slip: cues out of order in the fourth animation's path.
    expect_error(R"({"animations": [
        {"path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 1},
        {"path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 1},
        {"path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 1},
        {"path": {"kind": "complex", "parts": [{"kind": "linear", "start": [0, 0], "end": [1, 0]},
                                              {"kind": "linear", "start": [1, 0], "end": [2, 0]},
                                              {"kind": "linear", "start": [2, 0], "end": [3, 0]}],
                  "cues": [0, 0.6, 0.5]}, "duration": 1}]})",
                 "/animations/3/path/cues/2", "cues must not decrease (0.5 after 0.6)");
    const std::string line = R"({"kind": "linear", "start": [0, 0], "end": [1, 0]})";
    const auto anim = [&](const std::string& fields) { return R"({"animations": [{"path": )" + line + ", " + fields + "}]}"; };
    expect_error(anim(R"("duration": -1)"), "/animations/0/duration", "must be positive (got -1)");
    expect_error(anim(R"("duration": "long")"), "/animations/0/duration", "expected a number, got a string");
    // Past the range of a double: named at its place, not by the JSON library's exception.
    expect_error(anim(R"("duration": 1e999)"), "/animations/0/duration", "number out of range (got 1e999)");
    expect_error(R"({"paths": [{"name": "p", "path": {"kind": "linear", "start": [0, 0], "end": [1, -1e400]}}]})",
                 "/paths/0/path/end/1", "number out of range (got -1e400)");
    expect_error(anim(R"("delay": 1)"), "/animations/0", "missing field \"duration\"");
    expect_error(anim(R"("duration": 1, "delay": -2)"), "/animations/0/delay", "must not be negative");
    expect_error(anim(R"("duration": 1, "repeat": 1.5)"), "/animations/0/repeat", "expected a whole number");
    expect_error(anim(R"("duration": 1, "repeat": -3)"), "/animations/0/repeat", "must be −1 (forever)");
    expect_error(anim(R"("duration": 1, "yoyo": 1)"), "/animations/0/yoyo", "expected true or false, got a number");
    expect_error(anim(R"("duration": 1, "duraton": 1)"), "/animations/0/duraton", "unknown field \"duraton\"");
    expect_error(anim(R"("duration": 1, "curve": "quad-sideways")"), "/animations/0/curve", "quad-sideways");
    expect_error(R"({"animations": [{"path": "nowhere", "duration": 1}]})", "/animations/0/path", "unknown path \"nowhere\"");
    expect_error(R"({"animations": [{"path": {"kind": "teleport"}, "duration": 1}]})", "/animations/0/path/kind",
                 "unknown path kind \"teleport\"");
    expect_error(R"({"paths": [{"name": "c", "path": {"kind": "circle", "center": [0, 0]}}]})", "/paths/0/path",
                 "missing field \"radius\"");
    expect_error(R"({"paths": [{"name": "c", "path": {"kind": "circle", "center": [0], "radius": 1}}]})",
                 "/paths/0/path/center", "expected a point [x, y]");
    expect_error(R"({"paths": [{"name": "c", "path": {"kind": "circle", "center": [0, "x"], "radius": 1}}]})",
                 "/paths/0/path/center/1", "expected a number, got a string");
    // A path constructor's own message, placed at its object.
    expect_error(R"({"paths": [{"name": "c", "path": {"kind": "circle", "center": [0, 0], "radius": -1}}]})",
                 "/paths/0/path", "radius");
    expect_error(R"({"paths": [{"name": "s", "path": {"kind": "linear_spline", "points": [[0, 0]]}}]})",
                 "/paths/0/path/points", "too few points: 1 (at least 2)");
    expect_error(R"({"paths": [{"name": "b", "path": {"kind": "cubic_bezier", "points": [[0, 0], [1, 1], [2, 2], [3, 3], [4, 4]]}}]})",
                 "/paths/0/path/points", "exactly 4 points (got 5)");
    expect_error(R"({"paths": [{"name": "h", "path": {"kind": "hermite_spline", "points": [[0, 0], [1, 1]], "tangents": [[1, 0]]}}]})",
                 "/paths/0/path/tangents", "one tangent per point");
    expect_error(R"({"paths": [{"name": "c", "path": {"kind": "catmull_rom_spline", "points": [[0, 0], [1, 1]], "type": "tight"}}]})",
                 "/paths/0/path/type", "unknown Catmull-Rom type \"tight\"");
    expect_error(R"({"paths": [{"name": "x", "path": {"kind": "complex", "parts": [], "cues": []}}]})",
                 "/paths/0/path/parts", "at least one part");
    expect_error(R"({"paths": [{"name": "x", "path": {"kind": "complex", "parts": [)" + line + R"(], "cues": [0.5]}}]})",
                 "/paths/0/path/cues/0", "the first cue must be 0");
    expect_error(R"({"paths": [{"name": "x", "path": {"kind": "complex", "parts": [)" + line + "," + line + R"(], "cues": [0, 1.5]}}]})",
                 "/paths/0/path/cues/1", "cues must lie in [0, 1]");
    expect_error(R"({"paths": [{"name": "x", "path": {"kind": "complex", "parts": [)" + line + R"(], "cues": [0, 0.5]}}]})",
                 "/paths/0/path/cues", "one cue per part");
    // A syntax error in SVG data is a warning of the scene (SVG's error rule, SceneSvg below);
    // a single path read by parse_path_json stays strict.
    try {
        (void)grape::parse_path_json(R"({"kind": "svg", "data": "M 0 0 L 1 @"})");
        ADD_FAILURE() << "accepted SVG data with a syntax error";
    } catch (const grape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("SVG path data: expected a number at offset 10"), std::string::npos) << e.what();
    }
    expect_error(R"({"paths": [{"name": "a", "path": )" + line + R"(}, {"name": "a", "path": )" + line + "}]}",
                 "/paths/1/name", "duplicate name \"a\"");
    expect_error(R"({"curves": [{"name": "c", "curve": "nope"}]})", "/curves/0/curve", "nope");
    expect_error(R"({"view": {"width": 0}})", "/view/width", "must be in [1, 32768]");
    expect_error(R"({"grape_scene": 2})", "/grape_scene", "unsupported format version");
    expect_error(R"({"pathz": []})", "/pathz", "unknown field \"pathz\"");
    expect_error(R"([1, 2])", "/", "expected an object, got an array");
    // JSON pointer escaping of odd keys: "~" → "~0", "/" → "~1".
    expect_error(R"({"view": {"a/b~c": 1}})", "/view/a~1b~0c", "unknown field");
}

TEST(SceneErrors, AParticleInTooManyConstraints) {
    // 16 rods to one particle load; a 17th is refused where it is (each couples with the others
    // in the solve: 20000 of them stalled it).
    std::string rods;
    for (int i = 0; i < 17; ++i) rods += std::string(i ? ", " : "") + R"({"kind": "anchor", "a": 0, "point": [0, 0], "length": 5})";
    const std::string sim = R"({"simulations": [{"particles": [{"position": [3, 4]}], "constraints": [)";
    const std::string sixteen = rods.substr(0, rods.rfind(", {"));
    EXPECT_EQ(grape::load_scene(sim + sixteen + "]}]}").simulations[0].constraints.size(), 16u);
    expect_error(sim + rods + "]}]}", "/simulations/0/constraints/16", "particle 0 is in more than 16 constraints");
}

TEST(SceneErrors, Simulations) {
    const auto sim = [](const std::string& fields) {
        return R"({"simulations": [{"particles": [{"position": [0, 0]}, {"position": [1, 0]}])" +
               (fields.empty() ? "" : ", " + fields) + "}]}";
    };
    EXPECT_NO_THROW((void)grape::load_scene(sim("")));
    expect_error(sim(R"("integrator": "leapfrog")"), "/simulations/0/integrator", "unknown value \"leapfrog\"");
    expect_error(sim(R"("drift": "lots")"), "/simulations/0/drift", "unknown value \"lots\"");
    expect_error(sim(R"("dt": 0)"), "/simulations/0/dt", "must be positive");
    expect_error(sim(R"("dt": 1e-9, "duration": 100)"), "/simulations/0/duration", "more than 1e7 steps");
    expect_error(R"({"simulations": [{"particles": []}]})", "/simulations/0/particles", "at least one particle");
    expect_error(R"({"simulations": [{"particles": [{"position": [0, 0], "mass": 0}]}]})",
                 "/simulations/0/particles/0/mass", "must be positive");
    expect_error(R"({"simulations": [{"particles": [{"position": [0, 0], "mass": "heavy"}]}]})",
                 "/simulations/0/particles/0/mass", "\"pinned\"");
    expect_error(sim(R"("forces": [{"kind": "wind"}])"), "/simulations/0/forces/0/kind", "unknown force kind \"wind\"");
    expect_error(sim(R"("forces": [{"kind": "gravity"}])"), "/simulations/0/forces/0", "missing field \"acceleration\"");
    expect_error(sim(R"("forces": [{"kind": "drag", "k": -1}])"), "/simulations/0/forces/0/k", "must not be negative");
    expect_error(sim(R"("forces": [{"kind": "spring", "a": 0, "b": 2, "stiffness": 1}])"), "/simulations/0/forces/0/b",
                 "no particle 2 (the simulation has 2)");
    expect_error(sim(R"("forces": [{"kind": "spring", "a": 1, "b": 1, "stiffness": 1}])"), "/simulations/0/forces/0/b",
                 "two different particles");
    expect_error(sim(R"("constraints": [{"kind": "rope", "a": 0}])"), "/simulations/0/constraints/0/kind",
                 "unknown constraint kind \"rope\"");
    expect_error(sim(R"("constraints": [{"kind": "anchor", "a": 0, "point": [0, 0], "length": 0}])"),
                 "/simulations/0/constraints/0/length", "must be positive");
    expect_error(sim(R"("constraints": [{"kind": "conic", "a": 0, "coefficients": [1, 2, 3]}])"),
                 "/simulations/0/constraints/0/coefficients", "expected 6 coefficients");
    expect_error(sim(R"("constraints": [{"kind": "conic", "a": 0, "coefficients": [0, 0, 0, 0, 0, 1]}])"),
                 "/simulations/0/constraints/0/coefficients", "not a curve");
    expect_error(sim(R"("constraints": [{"kind": "distance", "a": -1, "b": 0}])"), "/simulations/0/constraints/0/a",
                 "no particle -1");
}

TEST(SceneErrors, SyntaxAndNesting) {
    try {
        (void)grape::load_scene("{\"paths\": [1, 2,]}");
        ADD_FAILURE();
    } catch (const grape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("JSON syntax error at byte 17"), std::string::npos) << e.what();
    }
    // Deeply nested complex paths are refused, not recursed into without bound.
    std::string deep = R"({"kind": "linear", "start": [0, 0], "end": [1, 0]})";
    for (int i = 0; i < 40; ++i) deep = R"({"kind": "complex", "parts": [)" + deep + "]}";
    std::string where = "/paths/0/path";
    for (int i = 0; i < 33; ++i) where += "/parts/0";  // the first level past the limit
    expect_error(R"({"paths": [{"name": "deep", "path": )" + deep + "}]}", where, "nested more than 32 deep");
}

// Every scene that loads saves to one that loads: the depth bound also holds for a path as
// written out, where a named path is spelled out in full and a closed chordal Catmull–Rom
// spline becomes a complex path of its Béziers (one level deeper than the object read).
TEST(SceneErrors, NestingCountsThePathAsWrittenOut) {
    const std::string loop = R"({"name": "loop", "path": {"kind": "catmull_rom_spline", "closed": true, "type": "chordal",
                                 "points": [[0, 0], [100, 0], [100, 100], [0, 80]]}})";
    const std::string pair = R"({"name": "pair", "path": {"kind": "complex", "parts": [{"kind": "complex", "parts": [
                                 {"kind": "linear", "start": [0, 0], "end": [1, 0]}]}]}})";  // two levels
    auto nest = [](std::string inner, int levels) {
        for (int i = 0; i < levels; ++i) inner = R"({"kind": "complex", "parts": [)" + inner + "]}";
        return inner;
    };
    auto scene = [&](const std::string& named, const std::string& path) {
        return R"({"paths": [)" + named + R"(, {"name": "all", "path": )" + path + "}]}";
    };
    // At the bound as written (31 levels, then the loop's own): loads, and its saved form loads
    // and saves to the same text.
    for (const std::string& text : {scene(loop, nest("\"loop\"", 31)), scene(pair, nest("\"pair\"", 30))}) {
        const std::string saved = grape::save_scene(grape::load_scene(text));
        EXPECT_EQ(grape::save_scene(grape::load_scene(saved)), saved);
    }
    // One level past it: refused where the whole path is named, as the saved form would be.
    expect_error(scene(loop, nest("\"loop\"", 32)), "/paths/1/path", "nested more than 32 deep as written out");
    expect_error(scene(pair, nest("\"pair\"", 31)), "/paths/1/path", "nested more than 32 deep as written out");
    const std::string inline_loop =
        R"({"kind": "catmull_rom_spline", "closed": true, "type": "chordal", "points": [[0, 0], [1, 0], [1, 1], [0, 2]]})";
    expect_error(scene(loop, nest(inline_loop, 32)), "/paths/1/path", "nested more than 32 deep as written out");
    EXPECT_NO_THROW((void)grape::load_scene(scene(loop, nest(inline_loop, 31))));
}

// The named scene files in scenes/ load, round-trip, and hold the catalogue's seed paths.
TEST(SceneFiles, CatalogueScenesLoadAndMatch) {
    const auto dir = std::filesystem::path(__FILE__).parent_path().parent_path() / "scenes";
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".json") continue;
        ++count;
        const Scene s = grape::load_scene_file(entry.path());
        expect_same_scene(s, grape::load_scene(grape::save_scene(s)));
    }
    EXPECT_GE(count, 6);
    const auto path_in = [&](const char* file, const char* name) {
        const Scene s = grape::load_scene_file(dir / file);
        const auto* p = s.find_path(name);
        EXPECT_NE(p, nullptr) << file << ": " << name;
        return p ? p->path : Path();
    };
    namespace sc = grape::scenes;
    expect_same_path(path_in("seed_spiral.json", "spiral"), sc::seed_spiral(), "spiral");
    expect_same_path(path_in("seed_complex.json", "complex"), sc::seed_complex(), "complex");
    expect_same_path(path_in("seed_nested_complex.json", "nested_complex"), sc::seed_nested_complex(), "nested");
    expect_same_path(path_in("seed_splines.json", "linear_spline_p1"), sc::seed_linear_spline(), "p1");
    expect_same_path(path_in("seed_splines.json", "cosine_spline_p2"), sc::seed_cosine_spline(), "p2");
    expect_same_path(path_in("seed_splines.json", "catmull_rom_spline_p3"), sc::seed_catmull_rom_spline(), "p3");
    expect_same_path(path_in("seed_bezier.json", "bezier"), sc::seed_bezier(false), "bezier");
    expect_same_path(path_in("seed_bezier.json", "bezier_reparametrized"), sc::seed_bezier(true), "bezier by length");
}

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The documentation's complete example is a valid scene, and the schema names every path
// kind the loader reads (and nothing it would refuse as unknown).
TEST(SceneFiles, DocumentationExampleAndSchemaAgreeWithTheLoader) {
    const auto root = std::filesystem::path(__FILE__).parent_path().parent_path();
    const std::string doc = read_text(root / "docs" / "scene-format.md");
    // The complete example (the 3-D path section before it has blocks of single paths).
    const auto section = doc.find("## A complete example");
    ASSERT_NE(section, std::string::npos);
    const auto begin = doc.find("```json\n", section);
    ASSERT_NE(begin, std::string::npos);
    const auto end = doc.find("```", begin + 8);
    const Scene example = grape::load_scene(doc.substr(begin + 8, end - begin - 8));
    EXPECT_EQ(example.paths.size(), 5u);
    EXPECT_EQ(example.animations.size(), 3u);
    EXPECT_EQ(example.simulations.size(), 1u);
    const std::string schema = read_text(root / "docs" / "scene.schema.json");
    for (const char* kind : {"linear", "circle", "elliptical_arc", "spiral", "sine_wave", "quadratic_bezier", "cubic_bezier",
                             "linear_spline", "cosine_spline", "hermite_spline", "catmull_rom_spline", "physics", "svg", "complex"}) {
        EXPECT_NE(schema.find(std::string("\"const\": \"") + kind + "\""), std::string::npos) << kind;
        // The loader knows the kind: with no other fields it complains about a field, not the kind.
        try {
            (void)grape::parse_path_json(std::string(R"({"kind": ")") + kind + "\"}");
            ADD_FAILURE() << kind;
        } catch (const grape::Error& e) {
            EXPECT_EQ(std::string(e.what()).find("unknown path kind"), std::string::npos) << e.what();
        }
    }
}

// SceneAnimation's closed-form timing agrees with the anim engine playing the same
// animation (random timings, curves, repeat, repeat delay, yoyo and reverse; fixed seed).
void expect_agreement_with_engine(const std::vector<std::string>& curves) {
    std::mt19937_64 rng(grape::testing::test_seed(6));
    std::uniform_real_distribution<double> unit(0, 1);
    for (int round = 0; round < 40; ++round) {
        grape::SceneAnimation a;
        a.path = grape::CubicBezierPath({20, 20}, {400, 200}, {400, 600}, {600, 600});
        a.curve = grape::parse_curve(curves[rng() % curves.size()]);
        a.duration = 0.3 + 2.0 * unit(rng);
        a.delay = unit(rng);
        a.repeat = static_cast<int>(rng() % 4) - 1;
        a.yoyo = rng() % 2 == 0;
        a.reversed = rng() % 2 == 0;
        a.repeat_delay = rng() % 2 == 0 ? 0.0 : 0.5 * unit(rng);
        grape::Engine engine;
        Vec2 last{};
        grape::AnimationDef def{.curve = a.curve, .delay = a.delay, .repeat = a.repeat, .reversed = a.reversed, .yoyo = a.yoyo};
        def.repeat_delay = a.repeat_delay;
        engine.create_animation(a.path, a.duration, def, [&](Vec2 p, double) { last = p; });
        const double dt = 1.0 / 64.0;  // exact in binary: engine time is k/64 with no drift
        for (int k = 1; k <= 64 * 8; ++k) {
            engine.tick(dt);
            if (k * dt <= a.delay) continue;  // nothing written while waiting
            const Vec2 expected = a.position(k * dt);
            // Both evaluate the same curve and path at a play fraction computed in different
            // orders: a few ulps of τ, times |path′| ≤ ~1200 and the curve slope (≤ ~10 for
            // elastic and back), stays under 1e-9.
            ASSERT_NEAR(last.x, expected.x, 1e-9) << "round " << round << " t = " << k * dt << " curve " << to_string(a.curve);
            ASSERT_NEAR(last.y, expected.y, 1e-9) << "round " << round << " t = " << k * dt << " curve " << to_string(a.curve);
        }
    }
}

TEST(SceneAnimation, AgreesWithTheEngine) {
    expect_agreement_with_engine({"linear", "quad-in", "quad-out", "quad-in-out", "cubic-in", "cubic-out", "cubic-in-out",
                                  "sine-in-out", "back-out(2.5)", "elastic-in(1.2,0.4)", "cubic-bezier(0.25,0.1,0.25,1)",
                                  "steps(4,jump-end)"});
}

// Every named curve, played by a scene and by the engine, gives the same positions.
TEST(SceneAnimation, AgreesWithTheEngineForEveryNamedCurve) {
    const auto names = grape::curve_names();
    expect_agreement_with_engine({names.begin(), names.end()});
}

#if GRAPE_HAS_DYNAMICS
// The seed's parabola as a scene runs exactly like the catalogue's implicit parabola run.
TEST(SceneSimulation, ParabolaMatchesTheCatalogue) {
    const Scene s = grape::load_scene(R"({"simulations": [{"integrator": "rk4", "drift": "none", "dt": 0.01,
        "particles": [{"position": [100, -100]}],
        "forces": [{"kind": "gravity", "acceleration": [0, 500]}],
        "constraints": [{"kind": "conic", "a": 0, "coefficients": [1, 0, 0, 0, 100, 0]}]}]})");
    grape::ParticleSystem system = grape::make_particle_system(s.simulations[0]);
    grape::scenes::ParabolaRun run({.method = grape::scenes::ParabolaMethod::implicit, .integrator = grape::Integrator::rk4,
                                    .x0 = 100, .g = 500});
    for (int i = 0; i < 100; ++i) {
        system.step(0.01);
        run.step(0.01);
    }
    const Vec2 a = system.positions()[0];
    const Vec2 b = run.state().x;
    // Same equations, same integrator: only summation order may differ (a few ulps of 100).
    EXPECT_NEAR(a.x, b.x, 1e-10);
    EXPECT_NEAR(a.y, b.y, 1e-10);
    // The scene's drift setting reaches the solver: with Baumgarte feedback the particle ends
    // closer to the parabola than without it.
    grape::SceneSimulation controlled = s.simulations[0];
    controlled.drift = "baumgarte";
    grape::ParticleSystem fed_back = grape::make_particle_system(controlled);
    for (int i = 0; i < 100; ++i) fed_back.step(0.01);
    const auto& conic = s.simulations[0].constraints[0];
    EXPECT_GT(std::abs(grape::conic_value(conic, a)), 0.0);
    EXPECT_LT(std::abs(grape::conic_value(conic, fed_back.positions()[0])), std::abs(grape::conic_value(conic, a)));
}

// A pendulum by RATTLE from a scene: the rod's length holds to round-off (RATTLE projects
// positions onto the constraint every step: a few ulps of 100 per step over 600 steps stays
// far below 1e-9), and the name survives a save.
TEST(SceneSimulation, RattleHoldsAPendulumsRod) {
    const Scene s = grape::load_scene(R"({"simulations": [{"integrator": "rattle", "drift": "none", "dt": 0.01,
        "particles": [{"position": [100, 0]}],
        "forces": [{"kind": "gravity", "acceleration": [0, 500]}],
        "constraints": [{"kind": "anchor", "a": 0, "point": [0, 0], "length": 100}]}]})");
    EXPECT_EQ(grape::load_scene(grape::save_scene(s)).simulations[0].integrator, "rattle");
    grape::ParticleSystem system = grape::make_particle_system(s.simulations[0]);
    double worst = 0.0;
    for (int i = 0; i < 600; ++i) {
        system.step(0.01);
        worst = std::max(worst, std::abs(grape::length(system.positions()[0]) - 100.0));
    }
    EXPECT_LT(worst, 1e-9);
    EXPECT_GT(system.positions()[0].y, 1.0);  // it swung: the test is not of a particle at rest
}
#endif

TEST(SceneSvg, DataWithASyntaxErrorIsReadBySvgsErrorRuleWithAWarning) {
    // Truncated data from a real file: the path before the `l` that lacks its arguments,
    // 22 + 11·√2 long, and one warning naming the value and the offset.
    const grape::Scene scene = grape::load_scene(
        R"({"paths": [{"name": "cut", "path": {"kind": "svg", "data": "M 13,9 3,19 h 11 v -3 l 1,-1 v -8 l"}}]})");
    ASSERT_EQ(scene.paths.size(), 1u);
    EXPECT_NEAR(scene.paths[0].path.length(), 22.0 + 11.0 * std::sqrt(2.0), 1e-13);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0],
              "scene: /paths/0/path/data: SVG path data: expected a number at offset 35, found the end of the data; "
              "the path stops before it, as SVG draws it");
    // Valid data, empty data and a moveto alone give no warning (length 0 is valid).
    const grape::Scene clean = grape::load_scene(
        R"({"paths": [{"name": "a", "path": {"kind": "svg", "data": "M0 0 L3 4"}},
                      {"name": "b", "path": {"kind": "svg", "data": ""}},
                      {"name": "c", "path": {"kind": "svg", "data": "M5 7"}}]})");
    EXPECT_TRUE(clean.warnings.empty());
    EXPECT_EQ(clean.paths[2].path.point(0.5), (grape::Vec2{5, 7}));
}

// ------------------------------------------------ closed splines, slices, ranges, offsets

const Path& only_path(const Scene& scene) { return scene.paths.at(0).path; }

Scene one_path(const std::string& path) { return grape::load_scene(R"({"paths": [{"name": "p", "path": )" + path + "}]}"); }

TEST(SceneLoops, ClosedSplinesAreTheLibrarysLoopsAndSaveBack) {
    const std::vector<Vec2> pts{{0, 0}, {100, 20}, {120, 90}, {30, 110}};
    const std::vector<Vec2> tan{{50, -10}, {20, 60}, {-40, 30}, {-30, -50}};
    const std::string points = "[[0, 0], [100, 20], [120, 90], [30, 110]]";
    struct Case {
        std::string json;
        Path expected;
        bool saved_closed;  // written back as "closed": true (cosine and Hermite loops)
    };
    const std::vector<Case> cases{
        {R"({"kind": "cosine_spline", "closed": true, "points": )" + points + "}", grape::closed_cosine_spline(pts), true},
        {R"({"kind": "hermite_spline", "closed": true, "points": )" + points +
             R"(, "tangents": [[50, -10], [20, 60], [-40, 30], [-30, -50]]})",
         grape::closed_hermite_spline(pts, tan), true},
        {R"({"kind": "catmull_rom_spline", "closed": true, "points": )" + points + "}",
         grape::closed_catmull_rom_spline(pts, grape::CatmullRom::uniform), true},
        {R"({"kind": "catmull_rom_spline", "closed": true, "type": "centripetal", "points": )" + points + "}",
         grape::closed_catmull_rom_spline(pts, grape::CatmullRom::centripetal), false},
        {R"({"kind": "catmull_rom_spline", "closed": true, "type": "chordal", "points": )" + points + "}",
         grape::closed_catmull_rom_spline(pts, grape::CatmullRom::chordal), false},
    };
    for (const Case& c : cases) {
        const Scene scene = one_path(c.json);
        expect_same_path(only_path(scene), c.expected, c.json);
        EXPECT_TRUE(grape::closed(only_path(scene))) << c.json;
        // The seam is C1 for the cosine and Hermite forms: the derivative leaving u = 0 is the
        // one arriving at u = 1 (the cosine's is 0 up to sin(π) ≈ 1.2e-16 times n·π/2·chord ≈
        // 800 per u: 1e-12 is far above that rounding and far below any real mismatch).
        if (c.saved_closed) {
            EXPECT_LT(distance(only_path(scene).d1(0.0), only_path(scene).d1(1.0)), 1e-12) << c.json;
        }
        const std::string text = grape::save_scene(scene);
        EXPECT_EQ(text.find("\"closed\": true") != std::string::npos, c.saved_closed) << text;
        const Scene back = grape::load_scene(text);
        expect_same_path(only_path(back), c.expected, "saved " + c.json);
        EXPECT_EQ(grape::save_scene(back), text);
    }
    // The same points without "closed" stay open: the path ends at the last point.
    EXPECT_EQ(only_path(one_path(R"({"kind": "cosine_spline", "points": )" + points + "}")).point(1.0), (Vec2{30, 110}));
    // An open spline that happens to repeat its first point is written as the loop it is.
    const Scene repeated = one_path(R"({"kind": "cosine_spline", "points": [[0, 0], [100, 20], [120, 90], [0, 0]]})");
    EXPECT_NE(grape::save_scene(repeated).find("\"closed\": true"), std::string::npos);
    expect_same_path(only_path(grape::load_scene(grape::save_scene(repeated))), only_path(repeated), "repeated first point");
}

TEST(SceneLoops, Errors) {
    const auto path = [](const std::string& p) { return R"({"paths": [{"name": "p", "path": )" + p + "}]}"; };
    expect_error(path(R"({"kind": "cosine_spline", "closed": true, "points": [[0, 0], [1, 1]]})"), "/paths/0/path/points",
                 "too few points: 2 (at least 3)");
    expect_error(path(R"({"kind": "cosine_spline", "closed": 1, "points": [[0, 0], [1, 1], [2, 0]]})"),
                 "/paths/0/path/closed", "expected true or false");
    expect_error(path(R"({"kind": "linear_spline", "closed": true, "points": [[0, 0], [1, 1], [2, 0]]})"),
                 "/paths/0/path/closed", "unknown field \"closed\"");
    expect_error(path(R"({"kind": "hermite_spline", "closed": true, "points": [[0, 0], [1, 1], [2, 0]], "tangents": [[1, 0]]})"),
                 "/paths/0/path/tangents", "one tangent per point");
}

TEST(SceneSlices, AreTheLibrarysExactSlices) {
    const std::string bez = R"("kind": "cubic_bezier", "points": [[20, 20], [400, 200], [400, 600], [600, 600]])";
    const Path whole = grape::CubicBezierPath({20, 20}, {400, 200}, {400, 600}, {600, 600});
    const Scene scene = one_path("{" + bez + R"(, "slice": [0.25, 0.75]})");
    const Path& part = only_path(scene);
    expect_same_path(part, grape::slice(whole, 0.25, 0.75), "sliced Bézier");
    EXPECT_EQ(part.kind(), grape::PathKind::cubic_bezier);
    for (int i = 0; i <= 100; ++i) {
        const double v = i / 100.0;
        // De Casteljau's control points against the original's evaluation at 0.25 + v/2:
        // a few ulps of coordinates up to 600 (1e-12 is ~10 ulps of 600).
        EXPECT_NEAR(distance(part.point(v), whole.point(0.25 + 0.5 * v)), 0.0, 1e-12) << v;
    }
    // Saved as what it is: a cubic Bézier, read back bit for bit.
    const std::string text = grape::save_scene(scene);
    EXPECT_EQ(text.find("slice"), std::string::npos);
    expect_same_path(only_path(grape::load_scene(text)), part, "saved slice");
    // After reparametrize: the reparametrized slice of the source, as grape::slice gives it.
    const Scene even = one_path("{" + bez + R"(, "reparametrize": true, "slice": [0.5, 1]})");
    expect_same_path(only_path(even), grape::slice(whole.reparametrized(), 0.5, 1.0), "sliced reparametrized Bézier");
    // A complex path slices part by part; a named path can be sliced through a complex wrapper.
    const Scene circle = one_path(R"({"kind": "circle", "center": [0, 0], "radius": 50, "slice": [0, 0.5]})");
    EXPECT_NEAR(only_path(circle).length(), grape::pi * 50, 1e-12 * 50);  // half the circle, closed form
    EXPECT_NEAR(only_path(circle).point(1.0).x, -50.0, 1e-12 * 50);
}

TEST(SceneSlices, Errors) {
    const auto path = [](const std::string& p) { return R"({"paths": [{"name": "p", "path": )" + p + "}]}"; };
    const std::string line = R"("kind": "linear", "start": [0, 0], "end": [1, 0])";
    expect_error(path("{" + line + R"(, "slice": [0.5, 0.5]})"), "/paths/0/path/slice", "expected 0 ≤ u0 < u1 ≤ 1 (got [0.5, 0.5])");
    expect_error(path("{" + line + R"(, "slice": [-0.1, 0.5]})"), "/paths/0/path/slice", "expected 0 ≤ u0 < u1 ≤ 1");
    expect_error(path("{" + line + R"(, "slice": [0.5]})"), "/paths/0/path/slice", "expected [u0, u1]");
    expect_error(path("{" + line + R"(, "slice": [0.1, "x"]})"), "/paths/0/path/slice/1", "expected a number, got a string");
    expect_error(path(R"({"kind": "sine_wave", "start": [0, 0], "end": [100, 0], "frequency": 2, "amplitude": 10, "slice": [0, 0.5]})"),
                 "/paths/0/path/slice", "slice");
    // A bad field of the sliced path is still named as the path's own.
    expect_error(path(R"({"kind": "linear", "start": [0, 0], "slice": [0, 0.5]})"), "/paths/0/path", "missing field \"end\"");
}

TEST(SceneAnimation, RangeAndOffset) {
    const Scene scene = grape::load_scene(R"({"animations": [
        {"path": {"kind": "linear", "start": [0, 0], "end": [100, 0]}, "duration": 2, "range": [0.8, 0.2], "offset": 5},
        {"path": {"kind": "circle", "center": [0, 0], "radius": 50}, "duration": 1, "repeat": -1, "offset": 10}]})");
    const grape::SceneAnimation& lane = scene.animations[0];
    // Linear curve on a straight line: u = 0.8 − 0.6·t/2, the normal of +x is +y (y down).
    EXPECT_EQ(lane.position(0.0), (Vec2{80, 5}));
    EXPECT_EQ(lane.position(1.0), (Vec2{50, 5}));
    EXPECT_NEAR(lane.u(1.5), 0.35, 1e-15);
    EXPECT_NEAR(lane.position(2.0).x, 20.0, 1e-13);  // 0.8 − 0.6 in doubles: a few ulps of 100
    EXPECT_EQ(lane.position(2.0).y, 5.0);
    // A circle whose angle increases turns towards its normal (curvature 1/r > 0): an offset of
    // 10 rides 10 inside, at radius 40 all the way round.
    const grape::SceneAnimation& ring = scene.animations[1];
    for (int i = 0; i <= 40; ++i) {
        const double t = i / 16.0;
        EXPECT_NEAR(grape::length(ring.position(t)), 40.0, 1e-12 * 50) << t;
        EXPECT_NEAR(distance(ring.position(t), ring.path.point(ring.u(t))), 10.0, 1e-12 * 50) << t;
    }
    // Saved and read back; defaults are not written.
    const std::string text = grape::save_scene(scene);
    EXPECT_NE(text.find("\"range\""), std::string::npos);
    const Scene back = grape::load_scene(text);
    expect_same_scene(scene, back);
    EXPECT_EQ(back.animations[1].range_start, 0.0);
    EXPECT_EQ(back.animations[1].range_end, 1.0);
    EXPECT_EQ(grape::save_scene(back), text);
}

TEST(SceneAnimation, RangeAndOffsetErrors) {
    const std::string line = R"({"kind": "linear", "start": [0, 0], "end": [1, 0]})";
    const auto anim = [&](const std::string& fields) { return R"({"animations": [{"path": )" + line + ", \"duration\": 1, " + fields + "}]}"; };
    expect_error(anim(R"("range": [0.2, 1.5])"), "/animations/0/range/1", "must be in [0, 1] (got 1.5)");
    expect_error(anim(R"("range": 0.5)"), "/animations/0/range", "expected [u0, u1]");
    expect_error(anim(R"("range": [0, 0.5, 1])"), "/animations/0/range", "expected [u0, u1]");
    expect_error(anim(R"("offset": "left")"), "/animations/0/offset", "expected a number, got a string");
}

// ------------------------------------------------------------------------------ sprites

const std::filesystem::path sprite_data = std::filesystem::absolute(std::filesystem::path(__FILE__).parent_path() / "data" / "sprites");

// A folder of this test's own (ctest runs tests in parallel).
std::filesystem::path own_folder() {
    const auto dir = std::filesystem::temp_directory_path() /
                     (std::string("grape_test_scene_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir);
    return dir;
}

// A scene file in the test's folder with the sprites given (they name sheets by absolute path
// or relative to that folder).
Scene sprite_scene(const std::string& sprites, const std::string& extra = "") {
    const auto file = own_folder() / "scene.json";
    std::ofstream(file) << R"({"animations": [{"name": "walk", "path": {"kind": "linear", "start": [0, 0], "end": [100, 0]},
        "duration": 2}])" << extra << R"(, "sprites": )" << sprites << "}";
    return grape::load_scene_file(file);
}

// With '/' between folders: a Windows path's backslashes would be escapes inside the JSON.
std::string sheet_json() { return (sprite_data / "grape_sheet.json").generic_string(); }

TEST(SceneSprites, LoadPlayAndSaveBack) {
    const Scene scene = sprite_scene(R"([
        {"name": "hero", "sheet": ")" + sheet_json() + R"(", "clip": "bounce", "animation": "walk"},
        {"sheet": ")" + sheet_json() + R"(", "frames": [4, 7], "rate": 0.5, "scale": 1.5, "at": [30, 40]},
        {"sheet": ")" + sheet_json() + R"(", "clip": "rewind", "rate": -1, "at": [0, 0]}])");
    ASSERT_EQ(scene.sprites.size(), 3u);
    const grape::SceneSprite& hero = scene.sprites[0];
    ASSERT_NE(hero.sheet, nullptr);
    EXPECT_EQ(hero.sheet->frame_count(), 8u);
    EXPECT_EQ(hero.clip_index, 0u);
    // "bounce" is frames 0–3 forward, 100, 150, 50 and 200 ms (period 500 ms): the frame shown
    // is the one the elapsed time falls in, looping. Times in the middle of frames, so no
    // rounding can move a boundary.
    for (const auto& [t, frame] : std::vector<std::pair<double, std::size_t>>{
             {0.0, 0}, {0.05, 0}, {0.2, 1}, {0.275, 2}, {0.4, 3}, {0.55, 0}, {0.7, 1}, {10.375, 3}})
        EXPECT_EQ(hero.frame_at(t), frame) << t;
    // Frames 4–7 forward (80, 120, 60, 240 ms, period 500) at half speed: 2t seconds of game
    // time are t of the sheet's.
    const grape::SceneSprite& flag = scene.sprites[1];
    EXPECT_TRUE(flag.clip.empty());
    for (const auto& [t, frame] : std::vector<std::pair<double, std::size_t>>{
             {0.0, 4}, {0.1, 4}, {0.3, 5}, {0.45, 6}, {0.8, 7}, {1.05, 4}, {1.3, 5}})
        EXPECT_EQ(flag.frame_at(t), frame) << t;
    // "rewind" plays 7, 6, 5, 4 (reverse tag); at rate −1 the player starts at the clip's end
    // and walks back: 4, then 5 after 80 ms, ...
    const grape::SceneSprite& back = scene.sprites[2];
    EXPECT_EQ(back.frame_at(0.0), 4u);
    EXPECT_EQ(back.frame_at(0.1), 5u);
    EXPECT_THROW((void)back.frame_at(-1.0), grape::Error);
    // The sheet's own clips are left as they were; the range is one clip more.
    EXPECT_EQ(flag.sheet->clips().size(), hero.sheet->clips().size() + 1);
    // Saved and read back (as text: no sheet is read).
    const std::string text = grape::save_scene(scene);
    const Scene back_text = grape::load_scene(text);
    expect_same_scene(scene, back_text);
    EXPECT_EQ(back_text.sprites[0].sheet, nullptr);
    EXPECT_THROW((void)back_text.sprites[0].frame_at(0.0), grape::Error);
    EXPECT_EQ(grape::save_scene(back_text), text);
    // The sheet is found relative to the scene's folder.
    Scene relative = grape::load_scene(R"({"sprites": [{"sheet": "grape_sheet.json", "clip": "hop", "at": [0, 0]}]})");
    grape::load_scene_sprite_sheets(relative, sprite_data);
    EXPECT_EQ(relative.sprites[0].clip_index, 2u);
    EXPECT_EQ(relative.sprites[0].sheet_path, sprite_data / "grape_sheet.json");
}

// File names are UTF-8 on every system (the scene's own, its sheets', the messages naming
// them), and a sheet's folders may be separated by '/' or, as written on Windows, a backslash.
TEST(SceneSprites, NonAsciiNamesAndEitherSeparator) {
    const auto dir = own_folder();
    std::filesystem::create_directories(dir / u8"réglages");
    std::filesystem::copy_file(sprite_data / "grape_sheet.json", dir / u8"réglages" / u8"feuille_ü.json",
                               std::filesystem::copy_options::overwrite_existing);
    for (const std::string sheet : {"réglages/feuille_ü.json", "réglages\\\\feuille_ü.json"}) {
        const Scene scene = grape::load_scene(R"({"sprites": [{"sheet": ")" + sheet + R"(", "clip": "hop", "at": [0, 0]}]})");
        const auto file = dir / u8"dé_ü.json";
        grape::save_scene_file(scene, file);
        const Scene back = grape::load_scene_file(file);
        ASSERT_EQ(back.sprites.size(), 1u);
        EXPECT_EQ(back.sprites[0].sheet_file, scene.sprites[0].sheet_file);
        EXPECT_EQ(back.sprites[0].clip_index, 2u);
        EXPECT_EQ(back.sprites[0].sheet_path, dir / u8"réglages" / u8"feuille_ü.json");
    }
    try {
        (void)grape::load_scene_file(dir / u8"absent_é.json");
        ADD_FAILURE();
    } catch (const grape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("absent_é.json: no such file"), std::string::npos) << e.what();
    }
}

TEST(SceneSprites, ErrorsNameThePointer) {
    const std::string sheet = R"("sheet": ")" + sheet_json() + "\"";
    const auto sprites = [](const std::string& s) {
        return R"({"animations": [{"name": "walk", "path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 1},
                                  {"name": "twin", "path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 1},
                                  {"name": "twin", "path": {"kind": "linear", "start": [0, 0], "end": [1, 0]}, "duration": 1}],
                  "sprites": [)" + s + "]}";
    };
    expect_error(sprites(R"({"clip": "bounce", "at": [0, 0]})"), "/sprites/0", "missing field \"sheet\"");
    expect_error(sprites(R"({"sheet": "", "clip": "bounce", "at": [0, 0]})"), "/sprites/0/sheet", "must name a sprite-sheet JSON file");
    expect_error(sprites("{" + sheet + R"(, "at": [0, 0]})"), "/sprites/0", "give either \"clip\"");
    expect_error(sprites("{" + sheet + R"(, "clip": "", "at": [0, 0]})"), "/sprites/0/clip", "must name a clip of the sheet");
    expect_error(sprites("{" + sheet + R"(, "clip": "bounce", "frames": [0, 1], "at": [0, 0]})"), "/sprites/0", "give either \"clip\"");
    expect_error(sprites("{" + sheet + R"(, "frames": [3, 1], "at": [0, 0]})"), "/sprites/0/frames/1", "the last frame comes before the first (1 < 3)");
    expect_error(sprites("{" + sheet + R"(, "frames": [-1, 1], "at": [0, 0]})"), "/sprites/0/frames/0", "not negative");
    expect_error(sprites("{" + sheet + R"(, "frames": 2, "at": [0, 0]})"), "/sprites/0/frames", "expected [first, last]");
    expect_error(sprites("{" + sheet + R"(, "clip": "bounce"})"), "/sprites/0", "give either \"animation\"");
    expect_error(sprites("{" + sheet + R"(, "clip": "bounce", "animation": "run"})"), "/sprites/0/animation", "no animation is named \"run\"");
    expect_error(sprites("{" + sheet + R"(, "clip": "bounce", "animation": "twin"})"), "/sprites/0/animation", "2 animations are named \"twin\"");
    expect_error(sprites("{" + sheet + R"(, "clip": "bounce", "at": [0, 0], "scale": 0})"), "/sprites/0/scale", "must be positive (got 0)");
    expect_error(sprites("{" + sheet + R"(, "clip": "bounce", "at": [0, 0], "rate": "fast"})"), "/sprites/0/rate", "expected a number");
    expect_error(sprites("{" + sheet + R"(, "clip": "bounce", "at": [0, 0], "speed": 2})"), "/sprites/0/speed", "unknown field \"speed\"");
    expect_error(R"({"sprites": {}})", "/sprites", "expected an array, got an object");
    // What only the sheet can tell: load_scene_file (and load_scene_sprite_sheets) read it.
    const auto file_error = [&](const std::string& s, const std::string& pointer, const std::string& reason) {
        try {
            (void)sprite_scene("[" + s + "]");
            ADD_FAILURE() << "accepted: " << s;
        } catch (const grape::Error& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("scene: " + pointer + ": "), std::string::npos) << what;
            EXPECT_NE(what.find(reason), std::string::npos) << what;
        }
    };
    file_error("{" + sheet + R"(, "clip": "moonwalk", "at": [0, 0]})", "/sprites/0/clip", "moonwalk");
    file_error("{" + sheet + R"(, "frames": [2, 8], "at": [0, 0]})", "/sprites/0/frames/1", "the sheet has 8 frames (0 to 7)");
    file_error("{" + sheet + R"(, "frames": [8, 9], "at": [0, 0]})", "/sprites/0/frames/0", "the sheet has 8 frames");
    file_error(R"({"sheet": "nowhere.json", "clip": "bounce", "at": [0, 0]})", "/sprites/0/sheet", "nowhere.json");
    // A sheet whose own JSON is bad: its error (with its pointer) inside the sprite's.
    const auto bad = own_folder() / "bad_sheet.json";
    std::ofstream(bad) << R"({"frames": [], "meta": {}})";
    file_error(R"({"sheet": "bad_sheet.json", "frames": [0, 0], "at": [0, 0]})", "/sprites/0/sheet", "sprite sheet");
}

}  // namespace
