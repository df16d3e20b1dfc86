// The engine for JavaScript. Animations made with `add` write x, y into slots of one array
// that JavaScript reads as a single Float64Array view (slot k at [2k, 2k + 1]) after each
// tick: one call per tick, none per animation; `add3` does the same for 3-D animations
// (web_engine.hpp, bind_3d.cpp). `animate` writes into a JavaScript object instead (one call
// into JavaScript per update: for a few objects, not for thousands).
#include "web_engine.hpp"

#include <grape/anim.hpp>

#include <emscripten/bind.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

namespace grape::web {

AnimationDef animation_def(const val& o) {
    const char* where = "animation options";
    AnimationDef def;
    if (has(o, "curve")) {
        const val c = o["curve"];
        def.curve = c.isString() ? parse_curve(c.as<std::string>()) : c.as<Curve>();
    }
    def.delay = number_or(o, "delay", def.delay, where);
    const double repeat = number_or(o, "repeat", def.repeat, where);
    if (!(repeat >= -1 && repeat <= 2147483647.0) || repeat != std::floor(repeat))
        throw Error("animation options: 'repeat' must be an integer ≥ −1 (got " + detail::number_text(repeat) + ")");
    def.repeat = static_cast<int>(repeat);
    def.reversed = bool_or(o, "reversed", def.reversed);
    def.yoyo = bool_or(o, "yoyo", def.yoyo);
    def.time_scale = number_or(o, "timeScale", def.time_scale, where);
    def.paused = bool_or(o, "paused", def.paused);
    def.heading = bool_or(o, "heading", def.heading);
    def.range_start = number_or(o, "rangeStart", def.range_start, where);
    def.range_end = number_or(o, "rangeEnd", def.range_end, where);
    def.offset = number_or(o, "offset", def.offset, where);
    return def;
}

namespace {

// Guarded members (C++ errors as JavaScript Errors).
unsigned add(WebEngine& e, const Path& p, double d, val o) { return e.add(p, d, o); }
unsigned add_default(WebEngine& e, const Path& p, double d) { return e.add(p, d, val::undefined()); }
Animation animate_default(WebEngine& e, val t, const Path& p, double d) { return e.animate(t, p, d, val::undefined()); }
Animation animation(const WebEngine& e, unsigned slot) { return e.animation(slot); }
Animation animate(WebEngine& e, val t, const Path& p, double d, val o) { return e.animate(t, p, d, o); }
Animation on_update(WebEngine& e, const Path& p, double d, val o, val fn) { return e.on_update(p, d, o, fn); }
void tick(WebEngine& e, double dt) { e.tick(dt); }
unsigned add3(WebEngine& e, const Path3& p, val timing, val o, val m) { return e.add3(p, timing, o, m); }
unsigned add3_timing(WebEngine& e, const Path3& p, val timing) { return e.add3(p, timing, val::undefined(), val::undefined()); }
unsigned add3_options(WebEngine& e, const Path3& p, val timing, val o) { return e.add3(p, timing, o, val::undefined()); }
Animation animation3(const WebEngine& e, unsigned slot) { return e.animation3(slot); }
double bytes_per_animation() { return double(Engine::bytes_per_animation()); }

void on_complete(const Animation& a, val fn) { a.on_complete([fn] { fn(); }); }
void on_loop(const Animation& a, val fn) { a.on_loop([fn](int play) { fn(play); }); }

}  // namespace

EMSCRIPTEN_BINDINGS(grape_anim) {
    using namespace emscripten;
    class_<WebEngine>("Engine")
        .constructor<unsigned>()
        .constructor<unsigned, unsigned>()
        .function("add", guarded<&add>)
        .function("add", guarded<&add_default>)
        .function("animation", guarded<&animation>)
        .function("animate", guarded<&animate>)
        .function("animate", guarded<&animate_default>)
        .function("onUpdate", guarded<&on_update>)
        .function("add3", guarded<&add3>)
        .function("add3", guarded<&add3_timing>)
        .function("add3", guarded<&add3_options>)
        .function("animation3", guarded<&animation3>)
        .function("positions3", method<&WebEngine::positions3>)
        .function("used3", method<&WebEngine::used3>)
        .function("capacity3", method<&WebEngine::capacity3>)
        .function("tick", guarded<&tick>)
        .function("positions", method<&WebEngine::positions>)
        .function("used", method<&WebEngine::used>)
        .function("capacity", method<&WebEngine::capacity>)
        .function("size", method<&WebEngine::size>)
        .function("storageBytes", method<&WebEngine::storage_bytes>)
        .function("clear", method<&WebEngine::clear>)
        .function("onTick", method<&WebEngine::on_tick>)
        .function("removeTickListener", method<&WebEngine::remove_tick_listener>)
        .class_function("bytesPerAnimation", &bytes_per_animation);
    class_<Animation>("Animation")
        .function("alive", method<&Animation::alive>)
        .function("waiting", method<&Animation::waiting>)
        .function("paused", method<&Animation::paused>)
        .function("value", method<&Animation::value>)
        .function("value3", method<&Animation::value3>)
        .function("heading", method<&Animation::heading>)
        .function("progress", method<&Animation::progress>)
        .function("time", method<&Animation::time>)
        .function("repetition", method<&Animation::repetition>)
        .function("duration", method<&Animation::duration>)
        .function("timeScale", method<&Animation::time_scale>)
        .function("pause", method<&Animation::pause>)
        .function("resume", method<&Animation::resume>)
        .function("seek", method<&Animation::seek>)
        .function("setTimeScale", method<&Animation::set_time_scale>)
        .function("kill", method<&Animation::kill>)
        .function("onComplete", &on_complete)
        .function("onLoop", &on_loop);
}

}  // namespace grape::web
