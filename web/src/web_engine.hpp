// The engine as JavaScript sees it, shared by bind_anim.cpp (the class and its 2-D slots) and
// bind_3d.cpp (its 3-D slots). 2-D animations made with `add` write x, y into slots of one
// array, 3-D ones made with `add3` write x, y, z and an orientation (w, x, y, z) into slots of
// another: JavaScript reads each as a single Float64Array view after a tick.
#pragma once

#include "web_util.hpp"

#include <grape/anim.hpp>
#include <grape/anim3.hpp>
#include <grape/quat.hpp>

#include <memory>
#include <string>
#include <vector>

namespace grape::web {

/// An AnimationDef from JavaScript options (bind_anim.cpp).
AnimationDef animation_def(const val& options);

struct Slot {
    double x = 0.0;
    double y = 0.0;
};
static_assert(sizeof(Slot) == 2 * sizeof(double), "slots are viewed as 2n doubles");

/// A 3-D slot: position, then the orientation (the identity until an aligned animation writes it).
struct Slot3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
    Quat orientation{};
};
static_assert(sizeof(Slot3) == 7 * sizeof(double), "3-D slots are viewed as 7n doubles");

class WebEngine {
public:
    WebEngine(unsigned capacity, unsigned capacity3)
        : capacity_(capacity), capacity3_(capacity3), slots_(new Slot[capacity]), slots3_(new Slot3[capacity3]) {}
    explicit WebEngine(unsigned capacity) : WebEngine(capacity, 0) {}

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
    // A 3-D animation writing into the next free 3-D slot (bind_3d.cpp); `timing` is a duration
    // in seconds or {speed: units per second}.
    unsigned add3(const Path3& path, val timing, val options, val motion);
    Animation animation3(unsigned slot) const {
        if (slot >= used3_)
            throw Error("Engine.animation3: no 3-D slot " + std::to_string(slot) + " (" + std::to_string(used3_) + " in use)");
        return handles3_[slot];
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
    val positions3() const {
        if (capacity3_ == 0) return val::global("Float64Array").new_(0);
        return val(emscripten::typed_memory_view(7 * std::size_t(used3_), &slots3_[0].x));
    }
    unsigned used() const noexcept { return used_; }
    unsigned capacity() const noexcept { return capacity_; }
    unsigned used3() const noexcept { return used3_; }
    unsigned capacity3() const noexcept { return capacity3_; }
    double size() const noexcept { return double(engine_.size()); }
    double storage_bytes() const noexcept { return double(engine_.storage_bytes()); }
    // Kills every animation and frees every slot, 2-D and 3-D.
    void clear() noexcept {
        engine_.kill_all();
        handles_.clear();
        handles3_.clear();
        used_ = 0;
        used3_ = 0;
        for (unsigned i = 0; i < capacity3_; ++i) slots3_[i] = Slot3{};
    }
    double on_tick(val fn) { return double(engine_.on_tick([fn](double dt) { fn(dt); })); }
    void remove_tick_listener(double id) noexcept { engine_.remove_tick_listener(std::size_t(id)); }

private:
    unsigned capacity_;
    unsigned capacity3_;
    unsigned used_ = 0;
    unsigned used3_ = 0;
    std::unique_ptr<Slot[]> slots_;    // fixed: the engine holds pointers into them
    std::unique_ptr<Slot3[]> slots3_;
    std::vector<Animation> handles_;
    std::vector<Animation> handles3_;
    Engine engine_;  // declared last: destroyed first, while its targets still exist
};

}  // namespace grape::web
