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
void Engine::set_parallel(const ParallelDef& def) { impl_->set_parallel(def.threads, def.min_animations); }
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

#define GRAPE_FIND(fallback)                                                        \
    if (!engine_) return fallback;                                                  \
    detail::EngineImpl& impl = *engine_->impl_;                                     \
    const detail::Hot* found = impl.find(slot_, generation_);                       \
    if (!found) return fallback;                                                    \
    const std::uint32_t dense = impl.dense_of(slot_);                               \
    (void)dense

bool Animation::alive() const noexcept {
    GRAPE_FIND(false);
    return true;
}

bool Animation::waiting() const noexcept {
    GRAPE_FIND(false);
    return found->phase < 0.0;
}

bool Animation::paused() const noexcept {
    GRAPE_FIND(false);
    return (found->flags & detail::flag_paused) != 0;
}

Vec2 Animation::value() const noexcept {
    GRAPE_FIND(Vec2{});
    if (const detail::Extra* e = impl.extra(slot_); e && (e->nd || e->value)) return {};
    return impl.value_of(dense);
}

std::span<const double> Animation::values() const noexcept {
    GRAPE_FIND(std::span<const double>());
    const detail::Extra* e = impl.extra(slot_);
    return e && e->nd ? std::span<const double>(e->values) : std::span<const double>();
}

double Animation::heading() const noexcept {
    GRAPE_FIND(0.0);
    return impl.heading_of(dense);
}

double Animation::progress() const noexcept {
    GRAPE_FIND(0.0);
    return impl.progress_of(dense);
}

double Animation::time() const noexcept {
    GRAPE_FIND(0.0);
    const double cycle = 1.0 + impl.gap_of(dense);  // a play and the repeat delay after it
    return (static_cast<double>(impl.cold(dense).play) * cycle + found->phase) * impl.cold(dense).duration;
}

int Animation::repetition() const noexcept {
    GRAPE_FIND(0);
    return static_cast<int>(std::min<std::uint32_t>(impl.cold(dense).play, INT32_MAX));
}

double Animation::duration() const noexcept {
    GRAPE_FIND(0.0);
    return impl.cold(dense).duration;
}

double Animation::time_scale() const noexcept {
    GRAPE_FIND(0.0);
    return impl.time_scale_of(dense);
}

void Animation::pause() const noexcept {
    GRAPE_FIND();
    impl.hot(dense).flags |= detail::flag_paused;
}

void Animation::resume() const noexcept {
    GRAPE_FIND();
    if (impl.driven(slot_)) return;  // its timeline drives it
    impl.hot(dense).flags &= static_cast<std::uint8_t>(~detail::flag_paused);
}

void Animation::seek(double seconds) const noexcept {
    GRAPE_FIND();
    if (impl.driven(slot_)) return;
    impl.seek(dense, seconds);
}

void Animation::set_time_scale(double scale) const noexcept {
    GRAPE_FIND();
    if (impl.driven(slot_)) return;
    impl.set_time_scale(dense, scale);
}

void Animation::kill() const noexcept {
    GRAPE_FIND();
    impl.kill(dense);
}

void Animation::on_complete(std::function<void()> handler) const {
    GRAPE_FIND();
    impl.extra_for(slot_).on_complete = handler ? std::make_shared<const std::function<void()>>(std::move(handler)) : nullptr;
    impl.hot(dense).flags |= detail::flag_listens;
}

void Animation::reverse() const noexcept {
    GRAPE_FIND();
    if (impl.driven(slot_)) return;
    detail::Hot& h = impl.hot(dense);
    h.rate = -std::fabs(h.rate);
}

void Animation::play() const noexcept {
    GRAPE_FIND();
    if (impl.driven(slot_)) return;
    detail::Hot& h = impl.hot(dense);
    h.rate = std::fabs(h.rate);
    h.flags &= static_cast<std::uint8_t>(~detail::flag_paused);
}

bool Animation::reversed() const noexcept {
    GRAPE_FIND(false);
    return found->rate < 0.0;
}

void Animation::on_update(std::function<void()> handler) const {
    GRAPE_FIND();
    impl.extra_for(slot_).on_update = handler ? std::make_shared<const std::function<void()>>(std::move(handler)) : nullptr;
    impl.hot(dense).flags |= detail::flag_custom;
}

void Animation::on_start(std::function<void()> handler) const {
    GRAPE_FIND();
    impl.extra_for(slot_).on_start = handler ? std::make_shared<const std::function<void()>>(std::move(handler)) : nullptr;
    impl.hot(dense).flags |= detail::flag_listens;
}

void Animation::on_reverse_complete(std::function<void()> handler) const {
    GRAPE_FIND();
    impl.extra_for(slot_).on_reverse_complete =
        handler ? std::make_shared<const std::function<void()>>(std::move(handler)) : nullptr;
    impl.hot(dense).flags |= detail::flag_listens;
}

void Animation::on_loop(std::function<void(int)> handler) const {
    if (!handler) {
        on_loop(std::function<void(int, std::uint64_t)>());
        return;
    }
    on_loop(std::function<void(int, std::uint64_t)>([h = std::move(handler)](int play, std::uint64_t) { h(play); }));
}

void Animation::on_loop(std::function<void(int play, std::uint64_t skipped)> handler) const {
    GRAPE_FIND();
    impl.extra_for(slot_).on_loop =
        handler ? std::make_shared<const std::function<void(int, std::uint64_t)>>(std::move(handler)) : nullptr;
    impl.hot(dense).flags |= detail::flag_listens;
}

#undef GRAPE_FIND

}  // namespace grape
