// The program of the consumer projects: every module this grape build announces in
// grape/config.hpp is included, linked and used, and the result is checked against a
// closed form, so a missing header, library or wrong macro fails the build or the run.
// -DCONSUMER_CORE_ONLY uses the core alone (what `pkg-config --libs grape` links).
#include <grape/anim.hpp>
#include <grape/config.hpp>
#include <grape/curve.hpp>
#include <grape/path.hpp>

#ifdef CONSUMER_CORE_ONLY
#define USE_DYNAMICS 0
#define USE_RENDER 0
#define USE_SCENE 0
#else
#define USE_DYNAMICS GRAPE_HAS_DYNAMICS
#define USE_RENDER GRAPE_HAS_RENDER
#define USE_SCENE GRAPE_HAS_SCENE
#endif

#if USE_DYNAMICS
#include <grape/dynamics.hpp>
#endif
#if USE_RENDER
#include <grape/render.hpp>
#endif
#if USE_SCENE
#include <grape/scene.hpp>
#endif

#include <cmath>
#include <cstdio>

// The consumer's CMakeLists.txt says which targets it found; the header must agree.
#if defined(EXPECT_DYNAMICS) && EXPECT_DYNAMICS != GRAPE_HAS_DYNAMICS
#error "grape::dynamics and GRAPE_HAS_DYNAMICS disagree"
#endif
#if defined(EXPECT_RENDER) && EXPECT_RENDER != GRAPE_HAS_RENDER
#error "grape::render and GRAPE_HAS_RENDER disagree"
#endif
#if defined(EXPECT_SCENE) && EXPECT_SCENE != GRAPE_HAS_SCENE
#error "grape::scene and GRAPE_HAS_SCENE disagree"
#endif

namespace {
struct Dot {
    double x = 0, y = 0;
};

int failures = 0;
void check(bool ok, const char* what) {
    if (!ok) {
        std::printf("FAIL: %s\n", what);
        ++failures;
    }
}
}  // namespace

int main() {
    // Core: the 3-4-5 segment, driven for 1 s by quad-in-out; half-way in time is half-way
    // along (quad-in-out(0.5) = 0.5 exactly), the point (1.5, 2).
    const grape::LinearPath line({0, 0}, {3, 4});
    check(line.length() == 5, "length of the 3-4-5 segment");
    grape::Engine engine;
    Dot dot;
    engine.create_2d_animation(dot, line, 1.0, {.curve = grape::Curve::quad_in_out()});
    engine.tick(0.5);
    check(dot.x == 1.5 && dot.y == 2, "animated point at t = 0.5");
#if USE_DYNAMICS
    // A free particle under gravity g for t: y = g·t²/2. RK4 (the default) integrates a
    // quadratic exactly, so only round-off remains: 1e-9 is thousands of ulps of 5.
    grape::ParticleSystem system;
    const auto p = system.create_particle({.position = {0, 0}});
    system.add_gravity({0, 10});
    for (int i = 0; i < 100; ++i) system.step(0.01);
    check(std::abs(system.position(p).y - 5) < 1e-9, "particle fallen g·t²/2 in 1 s");
#endif
#if USE_RENDER
    grape::Canvas canvas(16, 16);
    check(canvas.to_image().width() == 16, "canvas width");
#endif
#if USE_SCENE
    check(grape::parse_path_json(grape::path_to_json(line)).length() == 5, "path through scene JSON");
#endif
    std::printf("grape %s (dynamics %d, render %d, scene %d; used %d %d %d): %s\n", GRAPE_VERSION_STRING,
                GRAPE_HAS_DYNAMICS, GRAPE_HAS_RENDER, GRAPE_HAS_SCENE, USE_DYNAMICS, USE_RENDER, USE_SCENE,
                failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
