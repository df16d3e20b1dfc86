// The engine for JavaScript. Animations made with `add` write x, y into slots of one array
// that JavaScript reads as a single Float64Array view (slot k at [2k, 2k + 1]) after each
// tick: one call per tick, none per animation. `animate` writes into a JavaScript object
// instead (one call into JavaScript per update: for a few objects, not for thousands).
#include "web_util.hpp"

#include <grape/anim.hpp>

#include <emscripten/bind.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

namespace grape::web {
namespace {

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

struct Slot {
    double x = 0.0;
    double y = 0.0;
};
static_assert(sizeof(Slot) == 2 * sizeof(double), "slots are viewed as 2n doubles");

class WebEngine {
public:
    explicit WebEngine(unsigned capacity) : capacity_(capacity), slots_(new Slot[capacity]) {}

    // A new animation writing into the next free slot; returns the slot index.
    unsigned add(const Path& path, double duration, val options) {
        if (used_ >= capacity_)
            throw Error("Engine.add: all " + std::to_string(capacity_) + " slots are used (capacity is fixed at construction)");
        Slot& slot = slots_[used_];
        handles_.push_back(engine_.create_2d_animation(slot, path, duration, animation_def(options)));
        return used_++;
    }
    Animation animation(unsigned slot) const {
        if (slot >= used_) throw Error("Engine.animation: no slot " + std::to_string(slot) + " (" + std::to_string(used_) + " in use)");
        return handles_[slot];
    }
    // An animation bound to a JavaScript object: target.x, target.y (and target.rotation with
    // the heading option) after every change.
    Animation animate(val target, const Path& path, double duration, val options) {
        const AnimationDef def = animation_def(options);
        const bool heading = def.heading;
        return engine_.create_animation(path, duration, def, [target, heading](Vec2 p, double h) mutable {
            target.set("x", p.x);
            target.set("y", p.y);
            if (heading) target.set("rotation", h);
        });
    }
    // One callback per update: fn(x, y, heading).
    Animation on_update(const Path& path, double duration, val options, val fn) {
        return engine_.create_animation(path, duration, animation_def(options),
                                        [fn](Vec2 p, double h) { fn(p.x, p.y, h); });
    }
    void tick(double dt) { engine_.tick(dt); }
    val positions() const { return val(emscripten::typed_memory_view(2 * std::size_t(used_), &slots_[0].x)); }
    unsigned used() const noexcept { return used_; }
    unsigned capacity() const noexcept { return capacity_; }
    double size() const noexcept { return double(engine_.size()); }
    double storage_bytes() const noexcept { return double(engine_.storage_bytes()); }
    // Kills every animation and frees every slot.
    void clear() noexcept {
        engine_.kill_all();
        handles_.clear();
        used_ = 0;
    }
    double on_tick(val fn) { return double(engine_.on_tick([fn](double dt) { fn(dt); })); }
    void remove_tick_listener(double id) noexcept { engine_.remove_tick_listener(std::size_t(id)); }

private:
    unsigned capacity_;
    unsigned used_ = 0;
    std::unique_ptr<Slot[]> slots_;  // fixed: the engine holds pointers into it
    std::vector<Animation> handles_;
    Engine engine_;  // declared last: destroyed first, while its targets still exist
};

// Guarded members (C++ errors as JavaScript Errors).
unsigned add(WebEngine& e, const Path& p, double d, val o) { return e.add(p, d, o); }
unsigned add_default(WebEngine& e, const Path& p, double d) { return e.add(p, d, val::undefined()); }
Animation animate_default(WebEngine& e, val t, const Path& p, double d) { return e.animate(t, p, d, val::undefined()); }
Animation animation(const WebEngine& e, unsigned slot) { return e.animation(slot); }
Animation animate(WebEngine& e, val t, const Path& p, double d, val o) { return e.animate(t, p, d, o); }
Animation on_update(WebEngine& e, const Path& p, double d, val o, val fn) { return e.on_update(p, d, o, fn); }
void tick(WebEngine& e, double dt) { e.tick(dt); }
double bytes_per_animation() { return double(Engine::bytes_per_animation()); }

void on_complete(const Animation& a, val fn) { a.on_complete([fn] { fn(); }); }
void on_loop(const Animation& a, val fn) { a.on_loop([fn](int play) { fn(play); }); }

}  // namespace

EMSCRIPTEN_BINDINGS(grape_anim) {
    using namespace emscripten;
    class_<WebEngine>("Engine")
        .constructor<unsigned>()
        .function("add", guarded<&add>)
        .function("add", guarded<&add_default>)
        .function("animation", guarded<&animation>)
        .function("animate", guarded<&animate>)
        .function("animate", guarded<&animate_default>)
        .function("onUpdate", guarded<&on_update>)
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
