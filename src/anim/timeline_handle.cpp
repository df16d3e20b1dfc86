// Timelines: the public Engine and Timeline handles, their queries and commands.
#include "timeline_impl.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace grape {

// --- the public Engine and Timeline ------------------------------------------------------------

Timeline Engine::create_timeline() { return create_timeline(TimelineDef{}); }
Timeline Engine::create_timeline(const TimelineDef& def) { return impl_->timelines().create(this, def); }

// The record brought up to date from the tick's fast entry (`leave`: commands, which put the
// timeline on the general path; queries keep the fast entry).
#define GRAPE_TIMELINE_RECORD(fallback, leave)                                     \
    if (!engine_) return fallback;                                                 \
    detail::EngineImpl& impl = *engine_->impl_;                                    \
    detail::TimelineStore& store = impl.timelines();                               \
    detail::TimelineRec* found = store.current(slot_, generation_, leave);         \
    if (!found) return fallback;                                                   \
    detail::TimelineRec& r = *found;                                               \
    (void)r
#define GRAPE_TIMELINE(fallback) GRAPE_TIMELINE_RECORD(fallback, true)
#define GRAPE_TIMELINE_QUERY(fallback) GRAPE_TIMELINE_RECORD(fallback, false)

namespace {
void require(const detail::TimelineRec* r, const char* what) {
    if (!r) throw Error(std::string("Timeline::") + what + ": the timeline is not alive");
}
}  // namespace

bool Timeline::alive() const noexcept {
    GRAPE_TIMELINE_QUERY(false);
    return true;
}

Timeline& Timeline::add(const Animation& animation, At at) {
    detail::TimelineRec* r = engine_ ? engine_->impl_->timelines().find(slot_, generation_) : nullptr;
    require(r, "add");
    engine_->impl_->timelines().add_animation(slot_, animation, at.position);
    engine_->impl_->timelines().sync(slot_);
    return *this;
}

Timeline& Timeline::add(const Timeline& child, At at) {
    detail::TimelineRec* r = engine_ ? engine_->impl_->timelines().find(slot_, generation_) : nullptr;
    require(r, "add");
    if (child.engine_ != engine_ || !child.alive()) throw Error("Timeline::add: the timeline is not alive in this engine");
    engine_->impl_->timelines().add_timeline(slot_, child.slot_, at.position);
    engine_->impl_->timelines().sync(slot_);
    return *this;
}

Timeline& Timeline::call(std::function<void()> handler, At at) {
    detail::TimelineRec* r = engine_ ? engine_->impl_->timelines().find(slot_, generation_) : nullptr;
    require(r, "call");
    if (!handler) throw Error("Timeline::call: the handler is empty");
    engine_->impl_->timelines().add_callback(slot_, std::move(handler), at.position);
    engine_->impl_->timelines().sync(slot_);
    return *this;
}

Timeline& Timeline::label(std::string_view name, At at) {
    detail::TimelineRec* r = engine_ ? engine_->impl_->timelines().find(slot_, generation_) : nullptr;
    require(r, "label");
    engine_->impl_->timelines().add_label(slot_, name, at.position);
    engine_->impl_->timelines().sync(slot_);
    return *this;
}

Timeline& Timeline::gap(double seconds, At at) {
    detail::TimelineRec* r = engine_ ? engine_->impl_->timelines().find(slot_, generation_) : nullptr;
    require(r, "gap");
    engine_->impl_->timelines().add_gap(slot_, seconds, at.position);
    engine_->impl_->timelines().sync(slot_);
    return *this;
}

double Timeline::duration() const noexcept {
    GRAPE_TIMELINE_QUERY(0.0);
    return r.duration;
}

double Timeline::total_duration() const noexcept {
    GRAPE_TIMELINE_QUERY(0.0);
    return store.total(r) - r.delay;
}

double Timeline::time() const noexcept {
    GRAPE_TIMELINE_QUERY(0.0);
    return r.tau - r.delay;
}

double Timeline::local_time() const noexcept {
    GRAPE_TIMELINE_QUERY(0.0);
    return store.local_of(r, r.tau, nullptr);
}

double Timeline::progress() const noexcept {
    GRAPE_TIMELINE_QUERY(0.0);
    return r.duration > 0.0 ? store.local_of(r, r.tau, nullptr) / r.duration : 0.0;
}

int Timeline::repetition() const noexcept {
    GRAPE_TIMELINE_QUERY(0);
    double play = 0.0;
    store.local_of(r, r.tau, &play);
    return static_cast<int>(std::min(play, static_cast<double>(INT32_MAX)));
}

double Timeline::label_time(std::string_view name) const noexcept {
    GRAPE_TIMELINE_QUERY(NAN);
    for (const auto& l : r.labels)
        if (l.first == name) return l.second;
    return NAN;
}

bool Timeline::paused() const noexcept {
    GRAPE_TIMELINE_QUERY(false);
    return r.paused;
}

void Timeline::pause() const noexcept {
    GRAPE_TIMELINE();
    if (r.parent != UINT32_MAX || r.paused) return;
    r.paused = true;
    store.rebase(r);
}

void Timeline::resume() const noexcept {
    GRAPE_TIMELINE();
    if (r.parent != UINT32_MAX || !r.paused) return;
    r.paused = false;
    store.rebase(r);
}

void Timeline::reverse() const noexcept {
    GRAPE_TIMELINE();
    if (r.parent != UINT32_MAX || r.direction < 0.0) return;
    r.direction = -1.0;
    store.rebase(r);
}

void Timeline::play() const noexcept {
    GRAPE_TIMELINE();
    if (r.parent != UINT32_MAX) return;
    r.direction = 1.0;
    r.paused = false;
    store.rebase(r);
}

bool Timeline::reversed() const noexcept {
    GRAPE_TIMELINE_QUERY(false);
    return r.direction < 0.0;
}

void Timeline::set_time_scale(double scale) const noexcept {
    GRAPE_TIMELINE();
    if (r.parent != UINT32_MAX || !(std::isfinite(scale) && scale >= 0.0)) return;
    r.time_scale = scale;
    store.rebase(r);
}

double Timeline::time_scale() const noexcept {
    GRAPE_TIMELINE_QUERY(0.0);
    return r.time_scale;
}

void Timeline::seek(double seconds, bool fire_events) const {
    GRAPE_TIMELINE();
    if (r.parent != UINT32_MAX || !std::isfinite(seconds)) return;
    const double tau = std::clamp(seconds + r.delay, 0.0, store.total(r));
    store.seek(slot_, tau, fire_events);
}

void Timeline::seek(std::string_view label, bool fire_events) const {
    GRAPE_TIMELINE();
    const double t = label_time(label);
    if (std::isnan(t)) throw Error("Timeline::seek: unknown label '" + std::string(label) + "'");
    seek(t, fire_events);
}

void Timeline::kill() const noexcept {
    GRAPE_TIMELINE();
    store.kill(slot_);
}

namespace {
detail::Handler wrap(std::function<void()> f) {
    return f ? std::make_shared<const std::function<void()>>(std::move(f)) : nullptr;
}
}  // namespace

void detail::TimelineStore::set_handler(const Timeline& t, Handler TimelineRec::*member, std::function<void()> handler) {
    if (!t.engine_) return;
    TimelineRec* r = t.engine_->impl_->timelines().current(t.slot_, t.generation_, true);
    if (r) (*r).*member = wrap(std::move(handler));
}

void Timeline::on_start(std::function<void()> handler) const {
    detail::TimelineStore::set_handler(*this, &detail::TimelineRec::on_start, std::move(handler));
}
void Timeline::on_update(std::function<void()> handler) const {
    detail::TimelineStore::set_handler(*this, &detail::TimelineRec::on_update, std::move(handler));
}
void Timeline::on_complete(std::function<void()> handler) const {
    detail::TimelineStore::set_handler(*this, &detail::TimelineRec::on_complete, std::move(handler));
}
void Timeline::on_reverse_complete(std::function<void()> handler) const {
    detail::TimelineStore::set_handler(*this, &detail::TimelineRec::on_reverse_complete, std::move(handler));
}
void Timeline::on_loop(std::function<void(int)> handler) const {
    GRAPE_TIMELINE();
    r.on_loop = handler ? std::make_shared<const std::function<void(int)>>(std::move(handler)) : nullptr;
}

#undef GRAPE_TIMELINE
#undef GRAPE_TIMELINE_QUERY
#undef GRAPE_TIMELINE_RECORD

}  // namespace grape
