// The public Engine and Animation: thin forwarding to EngineImpl.
#include "engine_impl.hpp"
#include "timeline_impl.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace grape {

Engine::Engine() : impl_(std::make_unique<detail::EngineImpl>(this)) {}
Engine::~Engine() = default;

void Engine::tick(double dt) { impl_->tick(dt); }
void Engine::set_parallel(const ParallelDef& def) { impl_->set_parallel(def.threads, def.min_animations, def.awake); }
void Engine::set_serial() { impl_->set_serial(); }
int Engine::tick_threads() const noexcept { return impl_->threads(); }

Animation Engine::create_bound_2d(void* target, std::size_t x_offset, std::size_t y_offset, bool is_float,
                                  std::ptrdiff_t rotation_offset, const Path& path, double duration,
                                  const AnimationDef& def, bool rotation_float,
                                  std::unique_ptr<detail::TargetRef> ref) {
    return impl_->create(target, x_offset, y_offset, is_float, rotation_offset, path, duration, def, {},
                         detail::Bind{std::move(ref), rotation_float});
}

Animation Engine::create_bound_value(void* object, std::unique_ptr<detail::TargetRef> ref,
                                     std::unique_ptr<detail::ValueTrack> track, double duration,
                                     const AnimationDef& def) {
    return impl_->create_value(object, std::move(ref), std::move(track), duration, def);
}

std::size_t Engine::kill_in(const void* object, std::size_t bytes) {
    const auto lo = reinterpret_cast<std::uintptr_t>(object);
    return impl_->kill_in(lo, lo + bytes);
}

std::vector<Animation> Engine::find_in(const void* object, std::size_t bytes) {
    const auto lo = reinterpret_cast<std::uintptr_t>(object);
    return impl_->find_in(lo, lo + bytes);
}

Animation Engine::create_bound_nd(void* target, std::vector<detail::MemberRef> members, PathND path,
                                  double duration, const AnimationDef& def) {
    return impl_->create_nd(target, std::move(members), std::move(path), duration, def, {});
}

Animation Engine::create_animation(const Path& path, double duration, const AnimationDef& def,
                                   std::function<void(Vec2, double)> on_update) {
    return impl_->create(nullptr, 0, 0, false, -1, path, duration, def, std::move(on_update));
}

Animation Engine::create_animation(PathND path, double duration, const AnimationDef& def,
                                   std::function<void(std::span<const double>)> on_update) {
    return impl_->create_nd(nullptr, {}, std::move(path), duration, def, std::move(on_update));
}

std::size_t Engine::on_tick(std::function<void(double)> listener) { return impl_->on_tick(std::move(listener)); }
void Engine::remove_tick_listener(std::size_t id) noexcept { impl_->remove_tick_listener(id); }
void Engine::kill_all() noexcept { impl_->kill_all(); }
std::size_t Engine::size() const noexcept { return impl_->size(); }
std::size_t Engine::storage_bytes() const noexcept { return impl_->storage_bytes(); }
std::size_t Engine::bytes_per_animation() noexcept {
    return sizeof(detail::Hot) + sizeof(detail::Cold) + sizeof(detail::Slot);
}

detail::LiveRecord Animation::record() const noexcept {
    if (!engine_) return {};
    detail::EngineImpl& impl = *engine_->impl_;
    if (!impl.find(slot_, generation_)) return {};
    impl.touch_driven(slot_, false);
    return {&impl, impl.dense_of(slot_)};
}

bool Animation::alive() const noexcept { return bool(record()); }

bool Animation::waiting() const noexcept {
    const auto r = record();
    return r && r.hot().phase < 0.0;
}

bool Animation::paused() const noexcept {
    const auto r = record();
    return r && (r.hot().flags & detail::flag_paused) != 0;
}

Vec2 Animation::value() const noexcept {
    const auto r = record();
    if (!r) return {};
    if (const detail::Extra* e = r.impl->extra(slot_); e && (e->nd || e->value || e->p3)) return {};
    return r.impl->value_of(r.dense);
}

std::span<const double> Animation::values() const noexcept {
    const auto r = record();
    const detail::Extra* e = r ? r.impl->extra(slot_) : nullptr;
    return e && e->nd ? std::span<const double>(e->values) : std::span<const double>();
}

double Animation::heading() const noexcept {
    const auto r = record();
    return r ? r.impl->heading_of(r.dense) : 0.0;
}

double Animation::progress() const noexcept {
    const auto r = record();
    return r ? r.impl->progress_of(r.dense) : 0.0;
}

double Animation::time() const noexcept {
    const auto r = record();
    if (!r) return 0.0;
    const double cycle = 1.0 + r.impl->gap_of(r.dense);  // a play and the repeat delay after it
    return (static_cast<double>(r.cold().play()) * cycle + r.hot().phase) * r.cold().duration;
}

int Animation::repetition() const noexcept {
    const auto r = record();
    return r ? static_cast<int>(std::min<std::uint64_t>(r.cold().play(), INT32_MAX)) : 0;
}

double Animation::duration() const noexcept {
    const auto r = record();
    return r ? r.cold().duration : 0.0;
}

double Animation::time_scale() const noexcept {
    const auto r = record();
    return r ? r.impl->time_scale_of(r.dense) : 0.0;
}

void Animation::pause() const noexcept {
    if (const auto r = record()) r.hot().flags |= detail::flag_paused;
}

// Commands a timeline's child ignores: its timeline drives it.
void Animation::resume() const noexcept {
    if (const auto r = record(); r && !r.impl->driven(slot_)) r.hot().flags &= static_cast<std::uint8_t>(~detail::flag_paused);
}

void Animation::seek(double seconds) const noexcept {
    if (const auto r = record(); r && !r.impl->driven(slot_)) r.impl->seek(r.dense, seconds);
}

void Animation::set_time_scale(double scale) const noexcept {
    if (const auto r = record(); r && !r.impl->driven(slot_)) r.impl->set_time_scale(r.dense, scale);
}

void Animation::kill() const noexcept {
    if (const auto r = record()) r.impl->kill(r.dense);
}

void Animation::reverse() const noexcept {
    if (const auto r = record(); r && !r.impl->driven(slot_)) r.hot().rate = -std::fabs(r.hot().rate);
}

void Animation::play() const noexcept {
    const auto r = record();
    if (!r || r.impl->driven(slot_)) return;
    detail::Hot& h = r.hot();
    h.rate = std::fabs(h.rate);
    h.flags &= static_cast<std::uint8_t>(~detail::flag_paused);
}

bool Animation::reversed() const noexcept {
    const auto r = record();
    return r && r.hot().rate < 0.0;
}

namespace {

// Sets one handler of a live record's Extra (null clears it) and the flag that makes the tick
// look at it.
template <class Handler>
void set_handler(const detail::LiveRecord& r, std::uint32_t slot, std::shared_ptr<const Handler> detail::Extra::*member,
                 Handler handler, std::uint8_t flag) {
    if (!r) return;
    r.impl->touch_driven(slot, true);  // a timeline's fast tick reads no flags
    r.impl->extra_for(slot).*member = handler ? std::make_shared<const Handler>(std::move(handler)) : nullptr;
    r.hot().flags |= flag;
}

}  // namespace

void Animation::on_complete(std::function<void()> handler) const {
    set_handler(record(), slot_, &detail::Extra::on_complete, std::move(handler), detail::flag_listens);
}

void Animation::on_update(std::function<void()> handler) const {
    set_handler(record(), slot_, &detail::Extra::on_update, std::move(handler), detail::flag_custom);
}

void Animation::on_start(std::function<void()> handler) const {
    set_handler(record(), slot_, &detail::Extra::on_start, std::move(handler), detail::flag_listens);
}

void Animation::on_reverse_complete(std::function<void()> handler) const {
    set_handler(record(), slot_, &detail::Extra::on_reverse_complete, std::move(handler), detail::flag_listens);
}

void Animation::on_loop(std::function<void(int)> handler) const {
    if (!handler) {
        on_loop(std::function<void(int, std::uint64_t)>());
        return;
    }
    on_loop(std::function<void(int, std::uint64_t)>([h = std::move(handler)](int play, std::uint64_t) { h(play); }));
}

void Animation::on_loop(std::function<void(int play, std::uint64_t skipped)> handler) const {
    set_handler(record(), slot_, &detail::Extra::on_loop, std::move(handler), detail::flag_listens);
}

}  // namespace grape
