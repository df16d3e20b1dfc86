// 3-D animations: the engine's updates against direct evaluation of the path and its frames, speed
// mode against arc length, offsets, axis remaps, plays, timelines, allocation-free ticks, errors.
#include <grape/anim.hpp>
#ifdef GRAPE_TEST_SCRIPTS
#include <grape/script.hpp>
#endif
#include <grape/stagger.hpp>
#include <grape/timeline.hpp>

#include <gtest/gtest.h>

#include "count_allocations.hpp"
#include "error_text.hpp"

#include <cmath>
#include <memory>
#include <vector>

namespace {

using grape::Align3;
using grape::Animation;
using grape::AnimationDef;
using grape::Axis3;
using grape::Engine;
using grape::Frame3;
using grape::Frames3;
using grape::FramesDef;
using grape::Motion3Def;
using grape::Path3;
using grape::Vec3;

struct Body {
    double x = 0, y = 0, z = 0;
    grape::Basis orientation;
};
struct FloatBody {
    float x = 0, y = 0, z = 0;
    grape::Frame3 orientation;
};
struct QuatBody {
    double x = 0, y = 0, z = 0;
    grape::Quat orientation;
};
struct Plain {
    double x = 0, y = 0, z = 0;
};

Path3 track() { return Path3::cubic_bezier({0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, 2}); }

void expect_same(Vec3 a, Vec3 b, int k) {
    EXPECT_EQ(a.x, b.x) << "tick " << k;
    EXPECT_EQ(a.y, b.y) << "tick " << k;
    EXPECT_EQ(a.z, b.z) << "tick " << k;
}

// 1/64 s ticks over 20 yoyo plays of 2 s: each tick adds 1/128 of a play, exact in binary, so
// the play and its phase are known exactly and the engine must write point(u) and frame(u) of
// u = curve(τ) (curve(1 − τ) backwards) bit for bit, the frame's table built separately here.
TEST(Anim3, UpdatesEqualDirectEvaluationBitForBit) {
    const Path3 path = track();
    const FramesDef frames{.mode = grape::FrameMode::rotation_minimizing, .up = {0, 0, 1}};
    const Frames3 reference(path, frames);
    const grape::Curve curve = grape::Curve::quad_in_out();
    Engine engine;
    Body body;
    const Animation a = engine.create_3d_animation(body, path, 2.0, {.curve = curve, .repeat = -1, .yoyo = true},
                                                   {.align = Align3::frame, .frames = frames});
    for (int k = 1; k <= 64 * 40; ++k) {
        engine.tick(1.0 / 64);
        const int play = (k / 128);  // 128 ticks a play
        const double tau = (k % 128) / 128.0;
        // At a play's end the next play starts at phase 0 (on a yoyo: the other way, at the same u).
        const bool backward = play % 2 == 1;
        const double u = backward ? curve(1.0 - tau) : curve(tau);
        ASSERT_EQ(a.progress(), u) << "tick " << k;
        expect_same({body.x, body.y, body.z}, path.point(u), k);
        expect_same(a.value3(), path.point(u), k);
        const Frame3 f = reference.frame(u);
        // forward +z takes the tangent, up +y the normal, so +x = y × z takes normal × tangent =
        // −binormal; travelling backwards the model turns by π about the normal.
        const double s = backward ? -1.0 : 1.0;
        expect_same(body.orientation.z, f.tangent * s, k);
        expect_same(body.orientation.y, f.normal, k);
        expect_same(body.orientation.x, f.binormal * -s, k);
    }
}

// Constant speed: the distance travelled along the original path (arc length to the nearest
// point) is v·t. Tolerance: the reparametrization is within 1e-9·L of arc length u·L; the
// nearest point's u is found to ~1e-13·L and length_at to ~1e-14 relative; the phase sums
// k ≤ 64·L/v exact-ish steps (≤ 200 ulps of 1): 1e-9·L + 1e-11·L covers them all.
TEST(Anim3, SpeedModeTravelsSpeedTimesTime) {
    const Path3 path = track();
    const double length = path.length();
    const double v = 3.0;
    Engine engine;
    Plain p;
    const Animation a = engine.create_3d_animation(p, path, grape::Speed{v});
    EXPECT_EQ(a.duration(), length / v);
    int k = 0;
    for (; a.alive(); ++k) {
        engine.tick(1.0 / 64);
        const double t = std::min((k + 1) / 64.0, length / v);
        const grape::Closest3 c = grape::closest_point(path, {p.x, p.y, p.z});
        ASSERT_LT(c.distance, 1e-9 * length) << "tick " << k;
        EXPECT_NEAR(path.length_at(c.u), v * t, 1e-9 * length + 1e-11 * length) << "tick " << k;
    }
    EXPECT_EQ(k, static_cast<int>(std::ceil(64 * length / v)));
}

// Offsets: point + a·N + b·B of the frame at the engine's u, exactly (the same operations).
TEST(Anim3, OffsetsAlongNormalAndBinormal) {
    const Path3 path = track();
    const FramesDef frames{.mode = grape::FrameMode::reference_up, .up = {0, 0, 1}};
    const Frames3 reference(path, frames);
    Engine engine;
    Plain p;
    const double a_off = 0.25, b_off = -0.5;
    const Animation a = engine.create_3d_animation(p, path, 1.0, {.curve = grape::Curve::sine_in_out()},
                                                   {.frames = frames, .normal_offset = a_off, .binormal_offset = b_off});
    // While waiting nothing was written, but value3 tells where it starts: offset from point(0).
    for (int k = 0; k <= 64; ++k) {
        a.seek(k / 64.0);
        const double u = a.progress();
        const Frame3 f = reference.frame(u);
        const Vec3 want = path.point(u) + f.normal * a_off + f.binormal * b_off;
        expect_same({p.x, p.y, p.z}, want, k);
        // and it really is a_off, b_off away along orthonormal N, B
        const Vec3 d = Vec3{p.x, p.y, p.z} - path.point(u);
        EXPECT_NEAR(dot(d, f.normal), a_off, 1e-12);
        EXPECT_NEAR(dot(d, f.binormal), b_off, 1e-12);
        EXPECT_NEAR(dot(d, f.tangent), 0.0, 1e-12);
    }
}

// Axis remaps: the model's forward axis is the path's tangent (Path3::tangent, computed apart
// from the frame's table: within 1e-12 as both are unit vectors from the same d1), its up axis
// the normal, and the basis stays right-handed and orthonormal.
TEST(Anim3, ForwardAxisFollowsTheTangent) {
    const Path3 path = track();
    struct Case {
        Axis3 forward, up;
    };
    for (const Case c : {Case{Axis3::pos_z, Axis3::pos_y}, Case{Axis3::neg_z, Axis3::pos_y}, Case{Axis3::pos_x, Axis3::pos_z},
                         Case{Axis3::neg_y, Axis3::neg_x}}) {
        Engine engine;
        Body body;
        engine.create_3d_animation(body, path, 1.0, {}, {.align = Align3::frame, .forward = c.forward, .up = c.up});
        const auto model = [&](Axis3 axis) {
            const Vec3 e = grape::axis_vector(axis);
            return body.orientation.x * e.x + body.orientation.y * e.y + body.orientation.z * e.z;
        };
        for (int k = 1; k <= 64; ++k) {
            engine.tick(1.0 / 64);
            const double u = k / 64.0;  // linear, 1 s: exact (progress() reads 0 once completed)
            EXPECT_TRUE(grape::approx_equal(model(c.forward), path.tangent(u), 1e-12)) << k;
            EXPECT_NEAR(dot(model(c.up), path.tangent(u)), 0.0, 1e-12) << k;
            EXPECT_TRUE(grape::approx_equal(cross(body.orientation.x, body.orientation.y), body.orientation.z, 1e-12)) << k;
        }
    }
    // Upright in the world: up is world up exactly, forward is the level tangent.
    Engine engine;
    Body body;
    engine.create_3d_animation(body, path, 1.0, {}, {.align = Align3::world, .up = Axis3::pos_y});
    for (int k = 1; k <= 64; ++k) {
        engine.tick(1.0 / 64);
        const Vec3 t = path.tangent(k / 64.0);
        const Vec3 level = grape::normalized(Vec3{t.x, t.y, 0.0});
        EXPECT_EQ(body.orientation.y, (Vec3{0, 0, 1})) << k;
        EXPECT_TRUE(grape::approx_equal(body.orientation.z, level, 1e-12)) << k;
    }
}

// A Quat member: the quaternion of the basis a Basis member gets (from_basis_unchecked of the
// same columns, bit for bit); it turns the model's forward axis onto the tangent (a rotation
// of a unit vector by a unit quaternion: a few ulp, 1e-12 is far above).
TEST(Anim3, QuaternionOrientation) {
    const Path3 path = track();
    for (const Align3 align : {Align3::frame, Align3::world}) {
        Engine engine;
        QuatBody q;
        Body b;
        const Motion3Def motion{.align = align, .frames = {.mode = grape::FrameMode::frenet}, .forward = Axis3::neg_z};
        const AnimationDef def{.curve = grape::Curve::cubic_in_out(), .repeat = 3, .yoyo = true};
        engine.create_3d_animation(q, path, 1.0, def, motion);
        engine.create_3d_animation(b, path, 1.0, def, motion);
        for (int k = 1; k < 64 * 4; ++k) {
            engine.tick(1.0 / 64);
            const grape::Quat want = grape::from_basis_unchecked(b.orientation.x, b.orientation.y, b.orientation.z);
            EXPECT_EQ(q.orientation.w, want.w) << k;
            EXPECT_EQ(q.orientation.x, want.x) << k;
            EXPECT_EQ(q.orientation.y, want.y) << k;
            EXPECT_EQ(q.orientation.z, want.z) << k;
            EXPECT_TRUE(grape::approx_equal(grape::rotate(q.orientation, {0, 0, -1}), -b.orientation.z, 1e-12)) << k;
            if (align == Align3::frame) {
                const double tau = (k % 64) / 64.0;
                const bool backward = (k / 64) % 2 == 1;
                const double u = grape::Curve::cubic_in_out()(backward ? 1.0 - tau : tau);
                const Vec3 travel = path.tangent(u) * (backward ? -1.0 : 1.0);
                EXPECT_TRUE(grape::approx_equal(grape::rotate(q.orientation, {0, 0, -1}), travel, 1e-12)) << k;
            }
        }
    }
}

// Plays: reversed + yoyo + 2 repeats runs backward, forward, backward, completes once at the
// start; reverse() runs back to the start and fires on_reverse_complete; a float target with a
// Frame3 member gets the rounded point and the frame.
TEST(Anim3, RepeatYoyoReverseAndFloatTargets) {
    const Path3 path = track();
    Engine engine;
    FloatBody body;
    int completes = 0, loops = 0;
    const Animation a = engine.create_3d_animation(body, path, 1.0, {.repeat = 2, .reversed = true, .yoyo = true},
                                                   {.align = Align3::frame, .face_travel = false});
    a.on_complete([&] { ++completes; });
    a.on_loop([&](int) { ++loops; });
    const Frames3 reference(path, FramesDef{});
    for (int k = 1; k <= 64 * 3; ++k) {
        engine.tick(1.0 / 64);
        const int play = std::min(k / 64, 2);
        const double tau = k == 64 * 3 ? 1.0 : (k % 64) / 64.0;
        const double u = play % 2 == 0 ? 1.0 - tau : tau;  // backward, forward, backward
        const Vec3 want = path.point(u);
        EXPECT_EQ(body.x, static_cast<float>(want.x)) << k;
        EXPECT_EQ(body.y, static_cast<float>(want.y)) << k;
        EXPECT_EQ(body.z, static_cast<float>(want.z)) << k;
        expect_same(body.orientation.tangent, reference.frame(u).tangent, k);
        expect_same(body.orientation.point, want, k);
    }
    engine.tick(1.0 / 64);
    EXPECT_FALSE(a.alive());
    EXPECT_EQ(completes, 1);
    EXPECT_EQ(loops, 2);

    Plain p;
    int back = 0;
    const Animation b = engine.create_3d_animation(p, path, 1.0);
    b.on_reverse_complete([&] { ++back; });
    for (int k = 0; k < 30; ++k) engine.tick(1.0 / 64);
    b.reverse();
    for (int k = 0; k < 3; ++k) engine.tick(0.3);  // 30/64 s back: crosses the start inside the second tick
    EXPECT_EQ(back, 1);
    expect_same({p.x, p.y, p.z}, path.point(0.0), 0);
    EXPECT_TRUE(b.alive());
}

// In a timeline at 0.5 s, a 1 s linear play is at u = t − 0.5; a stagger's delays hold back.
TEST(Anim3, TimelinePlacementAndStagger) {
    const Path3 path = Path3::line({0, 0, 0}, {8, 4, 2});
    Engine engine;
    Plain p;
    grape::Timeline tl = engine.create_timeline();
    tl.add(engine.create_3d_animation(p, path, 1.0), 0.5);
    for (int k = 1; k <= 96; ++k) {
        engine.tick(1.0 / 64);
        const double t = k / 64.0;
        if (t >= 0.5) expect_same({p.x, p.y, p.z}, path.point(t - 0.5), k);
    }
    std::vector<Plain> dots(3);
    const auto made = grape::stagger(3, {.each = 0.25}, [&](std::size_t i, double delay) {
        return engine.create_3d_animation(dots[i], path, 1.0, {.delay = delay});
    });
    for (int k = 0; k < 32; ++k) engine.tick(1.0 / 64);  // 0.5 s
    for (std::size_t i = 0; i < 3; ++i) expect_same({dots[i].x, dots[i].y, dots[i].z}, path.point(0.5 - 0.25 * i), int(i));
}

// A range that runs back (0.75 → 0.25) at time scale 2: u = 0.75 − 0.5·τ with τ = 2t/duration,
// exact at 1/64 s ticks; the model faces its travel (the range runs backwards): −tangent.
TEST(Anim3, RangeAndTimeScale) {
    const Path3 path = track();
    Engine engine;
    Body body;
    const Frames3 reference(path, FramesDef{});
    const Animation a = engine.create_3d_animation(body, path, 2.0, {.time_scale = 2.0, .range_start = 0.75, .range_end = 0.25},
                                                   {.align = Align3::frame});
    for (int k = 1; k < 64; ++k) {
        engine.tick(1.0 / 64);
        const double u = 0.75 + (k / 64.0) * (0.25 - 0.75);
        expect_same({body.x, body.y, body.z}, path.point(u), k);
        expect_same(body.orientation.z, -reference.frame(u).tangent, k);
    }
    engine.tick(1.0 / 64);
    expect_same({body.x, body.y, body.z}, path.point(0.25), 64);
    EXPECT_FALSE(a.alive());
}

#ifdef GRAPE_TEST_SCRIPTS
// A script awaits a 3-D animation until it completes, then starts the next leg.
grape::Script legs(Engine& engine, Plain& p, const Path3& path, int& done) {
    co_await engine.create_3d_animation(p, path, 0.5);
    ++done;
    co_await engine.create_3d_animation(p, path, 0.5, {.reversed = true});
    ++done;
}

TEST(Anim3, ScriptsAwaitThem) {
    const Path3 path = track();
    Engine engine;
    Plain p;
    int done = 0;
    grape::Script s = legs(engine, p, path, done);
    s.start(engine);
    for (int k = 0; k < 32; ++k) engine.tick(1.0 / 64);
    EXPECT_EQ(done, 1);
    expect_same({p.x, p.y, p.z}, path.point(1.0), 32);
    for (int k = 0; k < 40; ++k) engine.tick(1.0 / 64);
    EXPECT_EQ(done, 2);
    expect_same({p.x, p.y, p.z}, path.point(0.0), 72);
    EXPECT_TRUE(s.done());
}
#endif

// Linked targets stop once gone; kill_animations_of finds 3-D animations.
TEST(Anim3, LinkedTargetsAndKill) {
    const Path3 path = track();
    Engine engine;
    auto owned = std::make_shared<Plain>();
    const Animation a = engine.create_3d_animation(owned, path, 1.0);
    engine.tick(0.25);
    expect_same({owned->x, owned->y, owned->z}, path.point(0.25), 0);
    owned.reset();
    engine.tick(0.25);
    EXPECT_FALSE(a.alive());
    Body body;
    const Animation b = engine.create_3d_animation(body, path, 1.0, {}, {.align = Align3::frame});
    EXPECT_EQ(engine.animations_of(body).size(), 1u);
    EXPECT_EQ(engine.kill_animations_of(body), 1u);
    EXPECT_FALSE(b.alive());
}

// Ticks allocate nothing, with orientation, offsets and a shared table.
TEST(Anim3, TicksAllocateNothing) {
    const Path3 path = track();
    const auto table = std::make_shared<const Frames3>(path, FramesDef{.mode = grape::FrameMode::frenet});
    Engine engine;
    std::vector<Body> bodies(1000);
    for (std::size_t i = 0; i < bodies.size(); ++i)
        engine.create_3d_animation(bodies[i], path, 0.5 + 0.001 * static_cast<double>(i),
                                   {.curve = grape::Curve::back_out(), .repeat = -1, .yoyo = true},
                                   {.align = Align3::frame, .shared_frames = table, .normal_offset = 0.1});
    engine.tick(1.0 / 60);
    const long before = g_allocations.load();
    for (int k = 0; k < 200; ++k) engine.tick(1.0 / 60);
    EXPECT_EQ(g_allocations.load() - before, 0);
}

TEST(Anim3, InvalidDefinitionsNameTheField) {
    using grape::testing::error_text;
    const Path3 path = track();
    Engine engine;
    Plain p;
    Body body;
    const auto has = [](const std::string& text, const char* what) {
        EXPECT_NE(text.find(what), std::string::npos) << text;
    };
    has(error_text([&] { engine.create_3d_animation(p, path, 0.0); }), "duration");
    has(error_text([&] { engine.create_3d_animation(p, path, grape::Speed{0.0}); }), "speed");
    has(error_text([&] { engine.create_3d_animation(p, path, grape::Speed{NAN}); }), "speed");
    has(error_text([&] { engine.create_3d_animation(p, Path3(), grape::Speed{1.0}); }), "length");
    has(error_text([&] { engine.create_3d_animation(p, path, 1.0, {.repeat = -2}); }), "repeat");
    has(error_text([&] { engine.create_3d_animation(p, path, 1.0, {.range_start = 2}); }), "range_start");
    has(error_text([&] { engine.create_3d_animation(p, path, 1.0, {.heading = true}); }), "heading");
    has(error_text([&] { engine.create_3d_animation(p, path, 1.0, {.offset = 1}); }), "offset");
    has(error_text([&] { engine.create_3d_animation(p, path, 1.0, {}, {.align = Align3::frame}); }), "align");
    has(error_text([&] { engine.create_3d_animation(body, path, 1.0, {}, {.forward = Axis3::pos_z, .up = Axis3::neg_z}); }),
        "forward and up");
    has(error_text([&] { engine.create_3d_animation(body, path, 1.0, {}, {.up = static_cast<Axis3>(9)}); }), "up");
    has(error_text([&] { engine.create_3d_animation(body, path, 1.0, {}, {.world_up = {0, 0, 0}}); }), "world_up");
    has(error_text([&] { engine.create_3d_animation(p, path, 1.0, {}, {.normal_offset = NAN}); }), "normal_offset");
    has(error_text([&] { engine.create_3d_animation(p, path, 1.0, {}, {.binormal_offset = INFINITY}); }), "binormal_offset");
    has(error_text([&] {
            engine.create_3d_animation(body, path, 1.0, {}, {.align = Align3::frame, .frames = {.up = {1, 2, 0}}});
        }),
        "frames");
    const auto other = std::make_shared<const Frames3>(Path3::line({0, 0, 0}, {1, 0, 0}));
    has(error_text([&] {
            engine.create_3d_animation(body, path, 1.0, {}, {.align = Align3::frame, .shared_frames = other});
        }),
        "shared_frames");
    std::shared_ptr<Plain> gone;
    has(error_text([&] { engine.create_3d_animation(gone, path, 1.0); }), "gone");
    EXPECT_EQ(engine.size(), 0u);
}

}  // namespace
