// Built against grape's shared libraries: something compiled in every module this build has,
// and grape::Error thrown inside each library and caught here. A declaration without its
// module's export mark fails the link; an Error whose type_info the libraries and this
// program do not share escapes its catch and fails the run.
#include <grape/anim.hpp>
#include <grape/bits.hpp>
#include <grape/config.hpp>
#include <grape/curve.hpp>
#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/sprite.hpp>
#if GRAPE_HAS_DYNAMICS
#include <grape/dynamics.hpp>
#endif
#if GRAPE_HAS_RENDER
#include <grape/render.hpp>
#endif
#if GRAPE_HAS_SCENE
#include <grape/scene.hpp>
#endif

#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <typeinfo>

namespace {
int failures = 0;
void check(bool ok, const char* what) {
    if (!ok) {
        std::printf("FAIL: %s\n", what);
        ++failures;
    }
}

// f must throw grape::Error from inside a library, caught as itself.
template <class F>
void expect_error(const char* what, F&& f) {
    try {
        f();
    } catch (const grape::Error& e) {
        check(typeid(e) == typeid(grape::Error) && *e.what() != '\0', what);
        return;
    } catch (...) {
        std::printf("FAIL: %s: escaped catch (const grape::Error&)\n", what);
        ++failures;
        return;
    }
    std::printf("FAIL: %s: nothing thrown\n", what);
    ++failures;
}
}  // namespace

int main() {
    check(grape::detail::number_text(0.1) == "0.1", "math: number_text");

    const grape::ComplexPath path = grape::parse_svg_path("M0 0 L3 4");
    check(path.length() == 5, "path: parse_svg_path");
    expect_error("path: bad SVG data", [] { grape::parse_svg_path("M0 0 L3 @"); });
    try {  // by its base class too
        grape::parse_svg_path("M0 0 L3 @");
        check(false, "path: bad SVG data, caught as std::runtime_error");
    } catch (const std::runtime_error&) {
    }

    check(grape::parse_curve("quad-in-out")(0.5) == 0.5, "curve: parse_curve");
    expect_error("curve: unknown name", [] { grape::parse_curve("wobble"); });

    grape::Engine engine;
    grape::Vec2 at;
    engine.create_animation(grape::LinearPath({0, 0}, {3, 4}), 1.0, {}, [&](grape::Vec2 p, double) { at = p; });
    engine.tick(0.5);
    check(at == grape::Vec2{1.5, 2}, "anim: Engine");
    expect_error("anim: negative duration", [&] { engine.create_animation(path, -1.0); });

    grape::BitVector bits(100);
    bits.set(3);
    std::ostringstream text;
    text << bits;
    check(bits.count() == 1 && !text.str().empty(), "bits: BitVector");
    expect_error("bits: bad text", [] { grape::BitVector::from_string("01x"); });

    grape::SpritePlayer player(4);
    player.advance();
    check(player.frame() == 1, "sprite: SpritePlayer");
    expect_error("sprite: no frames", [] { grape::SpritePlayer none(0); });
#if GRAPE_HAS_DYNAMICS
    check(grape::order(grape::parse_integrator("rk4")) == 4, "dynamics: parse_integrator");
    expect_error("dynamics: unknown integrator", [] { grape::parse_integrator("leapfrog"); });
#endif
#if GRAPE_HAS_RENDER
    check(grape::Canvas(16, 16).to_image().width() == 16, "render: Canvas");
    expect_error("render: empty canvas", [] { grape::Canvas(0, 16); });
#endif
#if GRAPE_HAS_SCENE
    check(grape::parse_path_json(grape::path_to_json(path)).length() == 5, "scene: path JSON");
    expect_error("scene: bad JSON", [] { grape::load_scene("{"); });
#endif
    std::printf("shared libraries: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
