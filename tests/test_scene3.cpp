// 3-D paths and 3-D animations in scene files: the example scenes against the library used
// directly (paths built in code, Frames3, bank_track, the engine), save → load → save bit for
// bit, timelines placing 3-D animations, and errors by JSON pointer.
#include <grape/anim.hpp>
#include <grape/error.hpp>
#include <grape/scene.hpp>
#include <grape/scene_values.hpp>

#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace {

using grape::Align3;
using grape::Path3;
using grape::Quat;
using grape::Scene;
using grape::SceneMotion3;
using grape::Vec3;

const std::filesystem::path scenes_dir = GRAPE_SCENES_DIR;

struct QuatTarget {
    double x = 0, y = 0, z = 0;
    Quat orientation;
};

// The rail of scenes/camera_rail3d.json, built in code (examples/camera_rail.cpp's).
Path3 rail_in_code() {
    const std::vector<Vec3> waypoints{{0, 0, 2}, {10, 4, 3}, {20, 0, 6}, {30, -6, 4}, {40, 0, 2}};
    return Path3::catmull_rom(waypoints, grape::CatmullRom::centripetal);
}

// The track of scenes/coaster_banked.json, built in code (examples/banked_track.cpp's).
Path3 track_in_code() {
    const double r = 25.0;
    return Path3::complex_by_length({
        Path3::line({-50, -r, 0}, {0, -r, 0}),
        Path3::arc({.center = {0, 0, 0}, .start = {0, -1, 0}, .radius = r, .start_angle = 0, .end_angle = grape::pi}),
        Path3::line({0, r, 0}, {-50, r, 0}),
    });
}

void expect_same_vec3(Vec3 a, Vec3 b, const std::string& what) {
    EXPECT_EQ(a.x, b.x) << what;
    EXPECT_EQ(a.y, b.y) << what;
    EXPECT_EQ(a.z, b.z) << what;
}

void expect_same_quat(const Quat& a, const Quat& b, const std::string& what) {
    EXPECT_EQ(a.w, b.w) << what;
    EXPECT_EQ(a.x, b.x) << what;
    EXPECT_EQ(a.y, b.y) << what;
    EXPECT_EQ(a.z, b.z) << what;
}

std::size_t index_of(const Scene& s, const std::string& name) {
    for (std::size_t i = 0; i < s.animations3.size(); ++i)
        if (s.animations3[i].name == name) return i;
    ADD_FAILURE() << "no 3-D animation " << name;
    return 0;
}

// The camera: paths read from the file evaluate as the rail built in code, and the scene's
// pose is what the engine writes playing the same animation (same path value, speed, curve,
// frame and axes), bit for bit, at times that are sums of powers of two (one tick each, so the
// engine's clock holds them exactly).
TEST(Scene3Files, CameraRailAgreesWithTheEngine) {
    const Scene scene = grape::load_scene_file(scenes_dir / "camera_rail3d.json");
    ASSERT_EQ(scene.paths3.size(), 1u);
    const Path3 rail = rail_in_code();
    for (int k = 0; k <= 256; ++k)
        expect_same_vec3(scene.paths3[0].path.point(k / 256.0), rail.point(k / 256.0), "rail u " + std::to_string(k));
    const std::size_t camera = index_of(scene, "camera");
    const grape::SceneAnimation3& a = scene.animations3[camera];
    EXPECT_EQ(a.speed, 5.0);
    EXPECT_EQ(a.align, Align3::frame);
    EXPECT_EQ(a.forward, grape::Axis3::neg_z);
    const grape::SceneTiming timing(scene);
    EXPECT_EQ(timing.animation3_driver(camera), -1);
    const SceneMotion3 motion(a);
    for (const double t : {0.0, 0.5, 1.25, 2.0, 3.75, 6.0, 8.5, 100.0}) {
        grape::Engine engine;
        QuatTarget target;
        (void)engine.create_3d_animation(target, a.path, grape::Speed{a.speed}, a.def(), a.motion());
        engine.tick(t);
        const double p = timing.animation3_progress(camera, t);
        const std::string at = "t " + std::to_string(t);
        expect_same_vec3(motion.position_at(p), {target.x, target.y, target.z}, at);
        expect_same_quat(motion.orientation_at(p, timing.animation3_backward(camera, t)), target.orientation, at);
        // Independently of the engine: the view looks along the rail (the model's −z on the
        // tangent) with the horizon level (its +y on world z less its part along the view).
        // Both within 1e-12: a unit quaternion from an orthonormal basis and back rotate
        // within a few ulp (1e-15), and the frame's normal is the normalized level up to rounding.
        const Quat q = motion.orientation_at(p, false);
        const grape::Frame3 f = motion.frame_at(p);
        EXPECT_LT(grape::distance(grape::rotate(q, {0, 0, -1}), f.tangent), 1e-12) << at;
        const Vec3 level = grape::normalized(Vec3{0, 0, 1} - f.tangent * f.tangent.z);
        EXPECT_LT(grape::distance(grape::rotate(q, {0, 1, 0}), level), 1e-12) << at;
    }
}

// Timelines drive 3-D animations as they drive 2-D ones: "shot" waits 1 s, plays the marker
// (2 s over u in [0.25, 0.75]) and the boom 0.5 s after the marker's start (two 4 s plays,
// the second backwards). Times chosen so that every u is a sum of powers of two.
TEST(Scene3Files, TimelinesPlaceThreeDAnimations) {
    const Scene scene = grape::load_scene_file(scenes_dir / "camera_rail3d.json");
    const grape::SceneTiming timing(scene);
    const std::size_t marker = index_of(scene, "marker"), boom = index_of(scene, "boom");
    EXPECT_EQ(timing.animation3_driver(marker), 0);
    EXPECT_EQ(timing.animation3_driver(boom), 0);
    EXPECT_EQ(timing.layout(0).start[1], 0.5);
    EXPECT_EQ(timing.layout(0).duration, 8.5);  // the boom's two plays end at 0.5 + 8
    const SceneMotion3 m(scene.animations3[marker]);
    const Path3 rail = rail_in_code();
    // t = 2: the marker is 1 s in, half its play: u = 0.25 + 0.5·0.5.
    expect_same_vec3(m.position_at(timing.animation3_progress(marker, 2.0)), rail.point(0.5), "marker at 2");
    EXPECT_EQ(timing.animation3_progress(marker, 0.5), 0.0);  // waiting: at its start
    EXPECT_EQ(timing.animation3_progress(marker, 50.0), 1.0);  // ended: at its end
    // The boom: 1 + 0.5 + 4 + 1 s: 1 s into its second, backward play.
    EXPECT_EQ(timing.animation3_time(boom, 6.5), 5.0);
    EXPECT_EQ(timing.animation3_progress(boom, 6.5), 0.75);
    EXPECT_TRUE(timing.animation3_backward(boom, 6.5));
    EXPECT_FALSE(timing.animation3_backward(boom, 2.5));
    // Upright (align world) and facing the way it goes: on the backward play its +z points
    // against the rail's horizontal direction, its +y is world up.
    const SceneMotion3 b(scene.animations3[boom]);
    const Quat q = b.orientation_at(0.75, true);
    const Vec3 d = rail.tangent(0.75);
    const Vec3 level = grape::normalized(Vec3{d.x, d.y, 0});
    EXPECT_LT(grape::distance(grape::rotate(q, {0, 0, 1}), -level), 1e-12);
    EXPECT_LT(grape::distance(grape::rotate(q, {0, 1, 0}), {0, 0, 1}), 1e-12);
    // Offset 1.5 along the frame's normal (world up less its part along the tangent).
    const Vec3 t = grape::normalized(d);
    const Vec3 n = grape::normalized(Vec3{0, 0, 1} - t * t.z);
    EXPECT_LT(grape::distance(b.position_at(0.75), rail.point(0.75) + n * 1.5), 1e-12);
    EXPECT_EQ(timing.end_time(), 9.5);
}

// The banked car: against bank_track and RolledFrames3 built directly on the track built in
// code; mid-turn it leans by atan(v²/(g·R)) (the example's closed form); the stunt's roll is the
// keys' linear interpolation in arc length about the RMF's tangent.
TEST(Scene3Files, CoasterBanksAndRolls) {
    const Scene scene = grape::load_scene_file(scenes_dir / "coaster_banked.json");
    const grape::SceneTiming timing(scene);
    const std::size_t car = index_of(scene, "car"), stunt = index_of(scene, "stunt");
    EXPECT_TRUE(std::isinf(timing.end_time()));  // the car laps forever
    const Path3 track = track_in_code();
    const Path3 played = track.reparametrized();
    const grape::RolledFrames3 direct(grape::Frames3(played, {.mode = grape::FrameMode::reference_up}),
                                      grape::bank_track(played, {.speed = 20, .max_angle = 1.2, .smoothing = 10}));
    const SceneMotion3 m(scene.animations3[car]);
    const double length = track.length();
    const double r = 25.0, v = 20.0, turn_end = 50.0 + grape::pi * r;
    for (const double s : {10.0, 50.0, 50.0 + grape::pi * r / 2, turn_end + 5.0}) {
        const double t = s / v;  // linear curve at constant speed: s = v·t
        const double p = timing.animation3_progress(car, t);
        EXPECT_NEAR(p, s / length, 1e-15);  // t·v/length in one division or two: an ulp or so
        const grape::Frame3 f = direct.frame(p);
        const Quat q = m.orientation_at(p, timing.animation3_backward(car, t));
        // axes forward +x, up +z: the quaternion takes x to the tangent, z to the rolled normal,
        // from an orthonormal basis: a few ulp.
        EXPECT_LT(grape::distance(grape::rotate(q, {1, 0, 0}), f.tangent), 1e-14) << s;
        EXPECT_LT(grape::distance(grape::rotate(q, {0, 0, 1}), f.normal), 1e-14) << s;
        expect_same_vec3(m.position_at(p), played.point(p), "car at s " + std::to_string(s));
    }
    // Mid-turn, more than the 10 m window from the arc's ends, the bank is the closed form:
    // the angle between the car's up and world up (atan2 of |×| and ·: accurate to ~1e-16 rad),
    // within 1e-12 (the example's bound on bank_track there).
    const double mid = (50.0 + grape::pi * r / 2) / length;
    const Vec3 up = grape::rotate(m.orientation_at(mid, false), {0, 0, 1});
    const double lean = std::atan2(grape::length(grape::cross(up, {0, 0, 1})), up.z);
    EXPECT_NEAR(lean, std::atan(v * v / (9.81 * r)), 1e-12);
    EXPECT_LT(up.x, -0.5);  // leaning toward the turn's centre: the origin lies at −x of the arc's midpoint (25, 0, 0)

    // The stunt: roll 0 until s = turn_end + 15, then linear to 2π over 20 m.
    const SceneMotion3 st(scene.animations3[stunt]);
    const grape::Frames3 rmf(played, {.mode = grape::FrameMode::rotation_minimizing, .up = {0, 0, 1}});
    for (const double s : {20.0, turn_end + 15.0, turn_end + 20.0, turn_end + 25.0, turn_end + 30.0}) {
        const double u = played.u_at_length(s);
        const double phi = s <= turn_end + 15.0 ? 0.0 : 2.0 * grape::pi * (s - turn_end - 15.0) / 20.0;
        const grape::Frame3 f = rmf.frame(u);
        const Vec3 expected = f.normal * std::cos(phi) + f.binormal * std::sin(phi);
        // u_at_length and the panel table's arc length agree within ~1e-9·length (the
        // reparametrization's bound): the roll then within 2π/20·1e-9·L ≈ 1e-7 rad.
        const Vec3 got = grape::rotate(st.orientation_at(u, false), {0, 0, 1});
        EXPECT_LT(grape::distance(got, expected), 1e-6) << s;
    }
    EXPECT_EQ(timing.animation3_driver(stunt), -1);
}

// Orientation keys (scenes/glider_keys.json): the orientation is the keyed pose where the arc
// length reaches a key, a C² spline between (against QuatSpline built here from the file's
// numbers), constant outside the keys, and the position is the reparametrized path's point.
TEST(Scene3Motion, OrientationKeysAreHitAtTheirArcLengths) {
    const Scene scene = grape::load_scene_file(scenes_dir / "glider_keys.json");
    const grape::SceneAnimation3& glider = scene.animations3.at(0);
    ASSERT_TRUE(glider.keyed());
    EXPECT_EQ(glider.align, Align3::none);
    const SceneMotion3 m(glider);
    EXPECT_TRUE(m.writes_orientation());
    const double L = glider.path.length();
    // The keys as the file writes them (docs: quaternions evaluated normalized).
    const std::vector<double> s{0, 30, 60, 90, 120};
    const std::vector<Quat> q{{0.98753537156, 0.007468793718, -0.049417957074, 0.149251373721},
                              {0.963212416459, -0.238228008618, -0.096867373561, 0.078012618394},
                              {0.934533169993, 0.294283380407, -0.035287559622, -0.196976735519},
                              {0.764652135105, 0.309161527024, -0.154623960445, -0.543891251395},
                              {0.529797130725, 0.116524770756, -0.043488325902, -0.838955149925}};
    ASSERT_GT(L, 120.0);  // every key lies on the path
    // The angle between two orientations from the chord between unit quaternions (q and −q
    // alike): 4·asin(|a ∓ b|/2), accurate near 0 (acos of the dot product is not: one ulp of it
    // is 3e-8 rad there).
    const auto angle = [](Quat a, Quat b) {
        const auto chord = [](Quat u, Quat v) {
            return std::sqrt((u.w - v.w) * (u.w - v.w) + (u.x - v.x) * (u.x - v.x) + (u.y - v.y) * (u.y - v.y) +
                             (u.z - v.z) * (u.z - v.z));
        };
        const double c = std::min(chord(a, b), chord(a, Quat{-b.w, -b.x, -b.y, -b.z}));
        return 4.0 * std::asin(std::min(1.0, 0.5 * c));
    };
    for (std::size_t k = 0; k < s.size(); ++k) {
        // In speed mode the path played is reparametrized: arc length s at u = s / L, within
        // the reparametrization's 1e-9·L; the spline turns below 0.1 rad per unit, so 1e-7 rad.
        EXPECT_LT(angle(m.orientation_at(s[k] / L, false), grape::normalized(q[k])), 1e-7) << k;
    }
    const grape::QuatSpline spline(s, q);
    const Path3 played = glider.path.reparametrized();
    for (int i = 0; i <= 50; ++i) {
        const double p = i / 50.0;
        EXPECT_LT(angle(m.orientation_at(p, i % 2 == 0), spline.orientation(played.length_at(p))), 1e-12) << p;
        EXPECT_LT(grape::distance(m.position_at(p), played.point(p)), 1e-12) << p;
    }
    // Past the last key (s = 120 < L) the pose holds.
    EXPECT_LT(angle(m.orientation_at(1.0, false), grape::normalized(q.back())), 1e-12);
    // The chase camera is an ordinary frame-aligned animation beside it.
    EXPECT_FALSE(scene.animations3.at(1).keyed());
}

// save → load → save gives the same text, for the example scenes and a scene with every 3-D
// path kind the format has and every field of a 3-D animation.
TEST(Scene3Files, SaveLoadSaveIsBitForBit) {
    for (const char* file : {"camera_rail3d.json", "coaster_banked.json", "glider_keys.json"}) {
        const std::string once = grape::save_scene(grape::load_scene_file(scenes_dir / file));
        EXPECT_EQ(grape::save_scene(grape::load_scene(once)), once) << file;
    }
    const std::string every = R"({"paths3": [
      {"name": "l", "path": {"kind": "line", "points": [[0, 0, 0], [1, 2, 3]]}},
      {"name": "q", "path": {"kind": "quadratic", "points": [[0, 0, 0], [1, 2, 3], [0.1, 0.2, 0.3]]}},
      {"name": "c", "path": {"kind": "cubic", "points": [[0, 0, 0], [1, 2, 3], [4, 5, 6], [7, 8, 10]]}},
      {"name": "h", "path": {"kind": "helix", "center": [1, 0, 0], "axis": [0, 1, 1], "start": [1, 0, 0], "radius": 2.5,
                             "rise_per_turn": 0.7, "turns": 2.25}},
      {"name": "cr", "path": {"kind": "catmull-rom", "alpha": 1, "closed": true, "points": [[0, 0, 0], [3, 0, 1], [3, 3, 0.3]]}},
      {"name": "he", "path": {"kind": "hermite", "points": [[0, 0, 0], [1, 1, 1]], "tangents": [[1, 0, 0], [0, 1, 0]]}},
      {"name": "ls", "path": {"kind": "linear", "points": [[0, 0, 0], [1, 0, 0], [1, 1, 0.1]]}},
      {"name": "ar", "path": {"kind": "arc", "center": [0, 0, 0], "axis": [0, 0, -1], "start": [0, 1, 0], "radius": 3,
                              "start_angle": 0.1, "end_angle": -2}},
      {"name": "pr", "path": {"kind": "projectile", "position": [0, 0, 0], "velocity": [1, 2, 9], "acceleration": [0, 0, -9.81],
                              "seconds": 1.7}},
      {"name": "op", "path": {"kind": "on_plane", "path": {"kind": "circle", "center": [0, 0], "radius": 1},
                              "origin": [0, 0, 1], "x_axis": [1, 0, 0], "y_axis": [0, 0.6, 0.8]}},
      {"name": "cx", "path": {"kind": "complex", "parts": [{"kind": "line", "points": [[0, 0, 0], [1, 0, 0]]},
                                                       {"kind": "line", "points": [[1, 0, 0], [1, 1, 0.3]]}]}}
    ],
    "curves": [{"name": "soft", "curve": "quad-in-out"}],
    "animations3": [
      {"name": "a", "path": "h", "curve": "soft", "duration": 1.3, "delay": 0.1, "repeat": 2, "yoyo": true, "reversed": true,
       "repeat_delay": 0.2, "range": [0.9, 0.1], "align": "frame", "frame": {"mode": "up", "up": [0, 1, 1], "cone": 0.7},
       "axes": {"forward": "-y", "up": "+x"}, "face_travel": false, "offset": [0.3, -0.1],
       "bank": {"speed": 3, "gravity": 1.62, "max_angle": 0.5, "smoothing": 0.25, "samples": 65}},
      {"name": "b", "path": {"kind": "line", "points": [[0, 0, 0], [0, 0, 5]]}, "speed": 0.3, "align": "world"},
      {"name": "c", "path": "cx", "duration": 2, "align": "frame", "frame": {"mode": "frenet"}},
      {"name": "d", "path": "c", "duration": 2, "align": "frame", "roll": [[0, 0.1], [3.3, -1]]},
      {"name": "e", "path": "l", "duration": 2, "align": "keys", "offset": [0.5, 0],
       "orientation": [[0, [2, 0, 0, 0]], [1.5, [0.5, 0.5, -0.5, 0.5]], [3, [0, 0, 1e-3, 1]]]}
    ],
    "timelines": [{"name": "t", "children": [{"animation3": "c"}, {"animation3": "d", "at": "<"}]}]
    })";
    const Scene scene = grape::load_scene(every);
    EXPECT_EQ(scene.paths3.size(), 11u);
    EXPECT_EQ(scene.animations3.size(), 5u);
    const std::string once = grape::save_scene(scene);
    const Scene back = grape::load_scene(once);
    EXPECT_EQ(grape::save_scene(back), once);
    // And the paths read back evaluate as the ones read first, bit for bit.
    for (std::size_t i = 0; i < scene.paths3.size(); ++i)
        for (int k = 0; k <= 32; ++k)
            expect_same_vec3(back.paths3[i].path.point(k / 32.0), scene.paths3[i].path.point(k / 32.0),
                             scene.paths3[i].name + " u " + std::to_string(k));
    EXPECT_EQ(back.animations3[0].path_name, "h");  // references kept
    EXPECT_EQ(back.animations3[0].curve_name, "soft");
    EXPECT_EQ(back.timelines[0].children[1].kind, grape::SceneTimelineChildKind::animation3);
    // A path built in code that has no JSON form names where it is.
    Scene coded;
    coded.animations3.push_back({.name = "x", .path = grape::slice(Path3::line({0, 0, 0}, {1, 0, 0}), 0.2, 0.4)});
    grape::testing::expect_error([&] { (void)grape::save_scene(coded); }, {"scene: /animations3/0/path: ", "slice"});
}

// Random 3-D animations (frame modes, alignments, axes, ranges, yoyo) evaluated by the scene
// agree with the engine bit for bit, and every orientation is a unit quaternion.
TEST(Scene3Motion, RandomAnimationsAgreeWithTheEngine) {
    std::mt19937_64 rng(grape::testing::test_seed(33));
    std::uniform_real_distribution<double> unit(0, 1);
    const grape::Axis3 axes[][2] = {{grape::Axis3::pos_z, grape::Axis3::pos_y}, {grape::Axis3::neg_z, grape::Axis3::pos_y},
                                    {grape::Axis3::pos_x, grape::Axis3::pos_z}, {grape::Axis3::neg_y, grape::Axis3::neg_x}};
    for (int round = 0; round < 60; ++round) {
        grape::SceneAnimation3 a;
        a.path = Path3::cubic_bezier({0, 0, 0}, {4 * unit(rng), 2, 0}, {3, 2 + unit(rng), 1}, {4, 0, 2});
        a.duration = 0.5 + unit(rng);
        if (rng() % 2) a.speed = 1.0 + unit(rng);
        a.repeat = static_cast<int>(rng() % 3);
        a.yoyo = rng() % 2 == 0;
        a.reversed = rng() % 2 == 0;
        a.range_start = rng() % 2 ? 0.0 : unit(rng);
        a.range_end = rng() % 2 ? 1.0 : unit(rng);
        a.align = static_cast<Align3>(rng() % 3);
        a.frame = static_cast<grape::SceneFrameMode>(rng() % 3);
        a.up = {0.1, 0.2, 1.0};
        const auto& ax = axes[rng() % 4];
        a.forward = ax[0];
        a.model_up = ax[1];
        a.face_travel = rng() % 2 == 0;
        if (rng() % 2) a.normal_offset = unit(rng) - 0.5;
        const SceneMotion3 m(a);
        Scene scene;
        scene.animations3.push_back(a);
        const grape::SceneTiming timing(scene);
        const double t = std::ldexp(static_cast<double>(rng() % 1024), -8);  // k/256 s in [0, 4): exact
        grape::Engine engine;
        QuatTarget target;
        if (a.speed > 0.0) (void)engine.create_3d_animation(target, a.path, grape::Speed{a.speed}, a.def(), a.motion());
        else (void)engine.create_3d_animation(target, a.path, a.duration, a.def(), a.motion());
        engine.tick(t);
        const double p = timing.animation3_progress(0, t);
        const std::string at = "round " + std::to_string(round);
        expect_same_vec3(m.position_at(p), {target.x, target.y, target.z}, at);
        const Quat q = m.orientation_at(p, timing.animation3_backward(0, t));
        if (a.align != Align3::none) expect_same_quat(q, target.orientation, at);
        // |q| = 1 within a few ulp (from_basis_unchecked normalizes).
        EXPECT_NEAR(grape::length(q), 1.0, 4e-16) << at;
    }
}

// Errors name the JSON pointer of the bad value and the reason.
TEST(Scene3Errors, NameThePointer) {
    const std::string line = R"({"kind": "line", "points": [[0, 0, 0], [1, 0, 0]]})";
    const std::string up_line = R"({"kind": "line", "points": [[0, 0, 0], [0, 0, 1]]})";
    const auto anim = [&](const std::string& fields) { return R"({"animations3": [{"path": )" + line + ", " + fields + "}]}"; };
    struct Case {
        std::string json, pointer, why;
    };
    const std::vector<Case> cases{
        {anim(R"("duration": 1, "speed": 2)"), "/animations3/0", "exactly one of \"duration\""},
        {anim(R"("delay": 1)"), "/animations3/0", "exactly one of \"duration\""},
        {anim(R"("duration": 0)"), "/animations3/0/duration", ""},
        {anim(R"("duration": 1, "duraton": 1)"), "/animations3/0/duraton", "unknown field"},
        {anim(R"("duration": 1, "align": "sideways")"), "/animations3/0/align", "unknown value \"sideways\""},
        {anim(R"("duration": 1, "frame": {"mode": "twisty"})"), "/animations3/0/frame/mode", "unknown value"},
        {anim(R"("duration": 1, "frame": {"up": [0, 0]})"), "/animations3/0/frame/up", "[x, y, z]"},
        {anim(R"("duration": 1, "frame": {"up": [0, 0, 0]})"), "/animations3/0/frame/up", "zero"},
        {anim(R"("duration": 1, "frame": {"mode": "rmf", "cone": 1})"), "/animations3/0/frame/cone", "\"up\" only"},
        {anim(R"("duration": 1, "frame": {"mode": "up", "cone": 2})"), "/animations3/0/frame/cone", "[0.05, 1.5]"},
        {anim(R"("duration": 1, "axes": {"forward": "+z", "up": "-z"})"), "/animations3/0/axes/up", "perpendicular"},
        {anim(R"("duration": 1, "axes": {"forward": "z"})"), "/animations3/0/axes/forward", "unknown value"},
        {anim(R"("duration": 1, "offset": [1])"), "/animations3/0/offset", "[along the normal"},
        {anim(R"("duration": 1, "range": [0, 2])"), "/animations3/0/range/1", "[0, 1]"},
        {anim(R"("duration": 1, "align": "frame", "roll": [[0, 0], [0, 1]])"), "/animations3/0/roll/1/0", "increasing"},
        {anim(R"("duration": 1, "align": "frame", "roll": [[-1, 0]])"), "/animations3/0/roll/0/0", "≥ 0"},
        {anim(R"("duration": 1, "align": "frame", "roll": [0, 1])"), "/animations3/0/roll/0", "[s, radians]"},
        {anim(R"("duration": 1, "roll": [[0, 1]])"), "/animations3/0/roll", "\"align\": \"frame\""},
        {anim(R"("duration": 1, "align": "frame", "bank": {"speed": 1})"), "/animations3/0/bank", "\"mode\": \"up\""},
        {anim(R"("duration": 1, "align": "frame", "frame": {"mode": "up"}, "bank": {"speed": -1})"), "/animations3/0/bank/speed", "≥ 0"},
        {anim(R"("duration": 1, "align": "frame", "frame": {"mode": "up"}, "bank": {"speed": 1, "samples": 1})"),
         "/animations3/0/bank/samples", "[2, 1048576]"},
        {anim(R"("duration": 1, "align": "frame", "frame": {"mode": "up"}, "bank": {"speed": 1, "max_angle": 2})"),
         "/animations3/0/bank/max_angle", "π/2"},
        {anim(R"("duration": 1, "align": "frame", "roll": [[0, 1]], "bank": {"speed": 1})"), "/animations3/0/bank", "not both"},
        {anim(R"("duration": 1, "align": "keys")"), "/animations3/0/align", "needs \"orientation\""},
        {anim(R"("duration": 1, "orientation": [[0, [1, 0, 0, 0]]])"), "/animations3/0/orientation", "\"align\": \"keys\""},
        {anim(R"("duration": 1, "align": "keys", "orientation": [])"), "/animations3/0/orientation", "1 to 65536"},
        {anim(R"("duration": 1, "align": "keys", "orientation": [[0, [0, 0, 0, 0]]])"), "/animations3/0/orientation/0/1", "zero"},
        {anim(R"("duration": 1, "align": "keys", "orientation": [[0, [1, 0, 0]]])"), "/animations3/0/orientation/0/1", "[w, x, y, z]"},
        {anim(R"("duration": 1, "align": "keys", "orientation": [[1, [1, 0, 0, 0]], [1, [0, 1, 0, 0]]])"),
         "/animations3/0/orientation/1/0", "increasing"},
        {anim(R"("duration": 1, "align": "keys", "orientation": [[-1, [1, 0, 0, 0]]])"), "/animations3/0/orientation/0/0", "≥ 0"},
        {anim(R"("duration": 1, "align": "keys", "orientation": [[0, [1, 0, 0, 0]]], "roll": [[0, 1]])"), "/animations3/0/roll", ""},
        {R"({"animations3": [{"path": )" + up_line + R"(, "duration": 1, "align": "frame", "frame": {"up": [0, 0, 2]}}]})",
         "/animations3/0/frame", ""},
        {R"({"animations3": [{"path": {"kind": "line", "points": [[1, 1, 1], [1, 1, 1]]}, "speed": 1}]})",
         "/animations3/0/speed", "positive length"},
        {R"({"animations3": [{"path": "nowhere", "duration": 1}]})", "/animations3/0/path", "unknown 3-D path \"nowhere\""},
        {R"({"animations3": [{"path": {"kind": "line", "points": [[0, 0], [1, 0, 0]]}, "duration": 1}]})",
         "/animations3/0/path/points/0", "[x, y, z]"},
        {R"({"paths3": [{"name": "a", "path": )" + line + R"(}, {"name": "a", "path": )" + line + "}]}", "/paths3/1/name",
         "duplicate"},
        {R"({"paths3": [{"path": )" + line + "}]}", "/paths3/0/name", "must not be empty"},
        {R"({"paths3": {}})", "/paths3", "expected an array"},
        {R"({"animations3": [{"name": "a", "path": )" + line + R"(, "duration": 1}],
             "timelines": [{"name": "t", "children": [{"animation3": "b"}]}]})",
         "/timelines/0/children/0/animation3", "no animation3 named \"b\" in /animations3"},
        {R"({"animations3": [{"name": "a", "path": )" + line + R"(, "duration": 1, "repeat": -1}],
             "timelines": [{"name": "t", "children": [{"animation3": "a"}]}]})",
         "/timelines/0/children/0/animation3", "repeats forever"},
        {R"({"animations3": [{"name": "a", "path": )" + line + R"(, "duration": 1}],
             "timelines": [{"name": "t", "children": [{"animation3": "a"}, {"animation3": "a"}]}]})",
         "/timelines/0/children/1/animation3", "already placed"},
    };
    for (const Case& c : cases) {
        const std::string what = grape::testing::error_text([&] { (void)grape::load_scene(c.json); });
        EXPECT_EQ(what.rfind("scene: " + c.pointer + ": ", 0), 0u) << c.json << "\n" << what;
        EXPECT_NE(what.find(c.why), std::string::npos) << c.json << "\n" << what;
    }
}

}  // namespace

namespace {

// vec3 and quat properties: lerp and slerp against closed forms, the quaternion kept as written
// (save → load → save) and evaluated normalized, errors by pointer.
TEST(Scene3Properties, Vec3AndQuatTween) {
    const std::string text = R"({"properties": [
        {"name": "v", "type": "vec3", "value": [0, 0, 0]},
        {"name": "q", "type": "quat", "value": [2, 0, 0, 0]}],
      "tweens": [
        {"property": "v", "to": [4, 8, -2], "duration": 2},
        {"property": "v", "by": [1, 1, 1], "duration": 1, "delay": 2},
        {"property": "q", "to": [1, 0, 0, 1], "duration": 1}]})";
    const Scene scene = grape::load_scene(text);
    const std::string once = grape::save_scene(scene);
    EXPECT_EQ(grape::save_scene(grape::load_scene(once)), once);
    expect_same_quat(std::get<Quat>(grape::load_scene(once).properties[1].value), Quat{2, 0, 0, 0}, "saved as written");
    const grape::SceneTiming timing(scene);
    const grape::SceneProperties values(scene, timing);
    // Linear: at 0.5 s a quarter of the way (exact in binary); the relative tween starts at its
    // entry from where the first ended, [4, 8, −2], and moves by [1, 1, 1]: at 2.5 s half of it.
    expect_same_vec3(std::get<Vec3>(values.value(0, 0.5)), {1, 2, -0.5}, "v at 0.5");
    expect_same_vec3(std::get<Vec3>(values.value(0, 2.5)), {4.5, 8.5, -1.5}, "v at 2.5");
    // The identity to a quarter turn about z: at 0.5 s an eighth of a turn, (cos π/8, 0, 0,
    // sin π/8). Within 4e-16: slerp's sinc weights and the normalization round to an ulp or
    // two of components below 1.
    const Quat q = std::get<Quat>(values.value(1, 0.5));
    EXPECT_NEAR(q.w, std::cos(grape::pi / 8), 4e-16);
    EXPECT_NEAR(q.z, std::sin(grape::pi / 8), 4e-16);
    EXPECT_EQ(q.x, 0.0);
    EXPECT_EQ(q.y, 0.0);
    // Before the tween: the property's value normalized, exactly the identity.
    expect_same_quat(std::get<Quat>(values.value(1, -1.0)), Quat{}, "q before");
    // The other sign of the same end turns the same way (the shortest arc): the same rotation.
    const Scene flipped = grape::load_scene(R"({"properties": [{"name": "q", "type": "quat", "value": [1, 0, 0, 0]}],
        "tweens": [{"property": "q", "to": [-1, 0, 0, -1], "duration": 1}]})");
    const grape::SceneTiming flipped_timing(flipped);
    const Quat r = std::get<Quat>(grape::SceneProperties(flipped, flipped_timing).value(0, 0.5));
    EXPECT_LT(grape::distance(grape::rotate(r, {1, 0, 0}), grape::rotate(q, {1, 0, 0})), 1e-15);

    struct Case {
        std::string json, pointer, why;
    };
    const std::vector<Case> cases{
        {R"({"properties": [{"name": "q", "type": "quat", "value": [0, 0, 0, 0]}]})", "/properties/0/value", "must not be zero"},
        {R"({"properties": [{"name": "q", "type": "quat", "value": [1, 0, 0]}]})", "/properties/0/value", "[w, x, y, z]"},
        {R"({"properties": [{"name": "v", "type": "vec3", "value": [1, 0]}]})", "/properties/0/value", "[x, y, z]"},
        {R"({"properties": [{"name": "q", "type": "quat", "value": [1, 0, 0, 0]}],
             "tweens": [{"property": "q", "by": [1, 0, 0, 0], "duration": 1}]})", "/tweens/0/by", "cannot move by an amount"},
        {R"({"properties": [{"name": "v", "type": "vec3", "value": [1, 0, 0]}],
             "tweens": [{"property": "v", "to": [1, 0], "duration": 1}]})", "/tweens/0/to", "[x, y, z]"},
    };
    for (const Case& c : cases) {
        const std::string what = grape::testing::error_text([&] { (void)grape::load_scene(c.json); });
        EXPECT_EQ(what.rfind("scene: " + c.pointer + ": ", 0), 0u) << c.json << "\n" << what;
        EXPECT_NE(what.find(c.why), std::string::npos) << c.json << "\n" << what;
    }
}

}  // namespace
