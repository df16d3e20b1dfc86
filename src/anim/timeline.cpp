// Timelines: creation, placing children, the handle's queries and commands.
#include "timeline_impl.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace grape {

namespace detail {

void TimelineStoreDelete::operator()(TimelineStore* store) const noexcept { delete store; }

TimelineStore& EngineImpl::timelines() {
    if (!timelines_) timelines_.reset(new TimelineStore(*this));
    return *timelines_;
}

bool EngineImpl::driven(std::uint32_t slot) const noexcept { return timelines_ && timelines_->drives(slot); }

void EngineImpl::touch_driven(std::uint32_t slot, bool leave) noexcept {
    if (timelines_) timelines_->touch(slot, leave);
}

namespace {
std::string where_of(const char* what) { return std::string("Timeline::") + what; }

// A record made new for its next timeline; the window's vectors keep their storage when small
// (creating and killing timelines of a few children allocates nothing for them).
void recycle(TimelineRec& r) noexcept {
    const std::uint32_t generation = r.generation;
    std::vector<TimelineChild> children = std::move(r.children);
    std::vector<std::uint32_t> by_end = std::move(r.by_end);
    std::vector<std::uint32_t> active = std::move(r.active);
    r = TimelineRec();  // frees its callbacks, labels and handlers
    r.generation = generation;
    if (children.capacity() <= 64) {
        children.clear();
        by_end.clear();
        active.clear();
        r.children = std::move(children);
        r.by_end = std::move(by_end);
        r.active = std::move(active);
    }
}
}  // namespace

Timeline TimelineStore::create(Engine* owner, const TimelineDef& def) {
    validate_plays("create_timeline", def.delay, def.repeat, def.repeat_delay, def.time_scale);
    std::uint32_t slot;
    if (!free_.empty()) {
        slot = free_.back();
        free_.pop_back();
    } else {
        if (recs_.size() >= UINT32_MAX - 1) throw Error("create_timeline: too many timelines");
        slot = static_cast<std::uint32_t>(recs_.size());
        recs_.push_back(std::make_unique<TimelineRec>());
        free_.reserve(recs_.size());  // so killing never allocates
        dead_slots_.reserve(recs_.size());
    }
    roots_.push_back(RootEntry{.rec = recs_[slot].get(), .slot = slot});
    lines_.emplace_back();
    due_.push_back(-HUGE_VAL);
    if (soon_.capacity() < lines_.capacity()) soon_.reserve(lines_.capacity());  // the tick never allocates
    TimelineRec& r = *recs_[slot];
    const std::uint32_t generation = r.generation;
    recycle(r);
    r.alive = true;
    r.root = static_cast<std::uint32_t>(roots_.size() - 1);
    r.delay = def.delay;
    r.plays = def.repeat < 0 ? 0.0 : def.repeat + 1.0;
    r.repeat_delay = def.repeat_delay;
    r.yoyo = def.yoyo;
    r.time_scale = def.time_scale;
    r.paused = def.paused;
    return Timeline(owner, slot, generation);
}

double TimelineStore::total(const TimelineRec& r) const noexcept {
    if (r.plays == 0.0) return HUGE_VAL;
    return r.delay + r.duration * r.plays + r.repeat_delay * (r.plays - 1.0);
}

// Resolves a position as layout_timeline does, for one more entry at the end.
double TimelineStore::place(TimelineRec& r, const TimelinePosition& at, double duration, bool point,
                            const char* what) {
    const std::string w = where_of(what);
    if (!std::isfinite(at.offset)) throw Error(w + ": position offset must be finite (got " + number_text(at.offset) + ")");
    double start = 0.0;
    using Anchor = TimelinePosition::Anchor;
    switch (at.anchor) {
        case Anchor::start: start = at.offset; break;
        case Anchor::end: start = r.duration + at.offset; break;
        case Anchor::previous_end: start = r.previous_end + at.offset; break;
        case Anchor::previous_start: start = r.previous_start + at.offset; break;
        case Anchor::label: {
            const auto it = std::find_if(r.labels.begin(), r.labels.end(), [&](const auto& l) { return l.first == at.label; });
            if (it == r.labels.end()) throw Error(w + ": unknown label '" + at.label + "'");
            start = it->second + at.offset;
            break;
        }
    }
    if (!(start >= 0.0))
        throw Error(w + ": position '" + to_string(at) + "' gives a negative start (" + number_text(start) + " s)");
    if (!std::isfinite(start + duration)) throw Error(w + ": start + length overflows");
    if (!point) {
        r.previous_start = start;
        r.previous_end = start + duration;
    }
    return start;
}

void TimelineStore::insert_child(std::uint32_t slot, TimelineChild c) {
    TimelineRec& r = *recs_[slot];
    // Geometric growth (placing n children costs O(n) copies); the active window gets the
    // same capacity, so it never allocates while playing.
    const std::size_t need = r.children.size() + 1;
    const std::size_t capacity = need > r.children.capacity() ? std::max(need, 2 * r.children.capacity()) : r.children.capacity();
    r.children.reserve(capacity);
    r.by_end.reserve(capacity);
    r.active.reserve(capacity);
    const auto pos = std::upper_bound(r.children.begin(), r.children.end(), c.start,
                                      [](double s, const TimelineChild& x) { return s < x.start; });
    const auto index = static_cast<std::uint32_t>(pos - r.children.begin());
    const bool at_back = pos == r.children.end();
    const bool end_last = r.by_end.empty() || r.children[r.by_end.back()].end <= c.end;
    const bool ahead = c.start > r.cursor;  // the window has not reached it
    r.children.insert(pos, c);
    if (!at_back) {
        for (std::uint32_t& e : r.by_end) e += e >= index ? 1u : 0u;
        for (std::uint32_t& e : r.active) e += e >= index ? 1u : 0u;
    }
    const auto epos = std::upper_bound(r.by_end.begin(), r.by_end.end(), c.end,
                                       [&](double e, std::uint32_t x) { return e < r.children[x].end; });
    r.by_end.insert(epos, index);
    if (!(at_back && end_last && ahead)) r.dirty = true;  // the window is rebuilt at the next update
    if (c.end > r.duration) {
        r.duration = c.end;
        grew(slot);
    }
}

// Logarithmic in the parent's children: its entry is found among those starting where it
// starts, its place in by_end among those ending where it ended, and it moves there alone
// (the order a stable sort by end would give; no allocation).
void TimelineStore::grew(std::uint32_t slot) {
    TimelineRec& r = *recs_[slot];
    if (r.parent == UINT32_MAX) return;
    TimelineRec& p = *recs_[r.parent];
    auto i = static_cast<std::size_t>(
        std::lower_bound(p.children.begin(), p.children.end(), r.placed,
                         [](const TimelineChild& x, double s) { return x.start < s; }) -
        p.children.begin());
    while (i < p.children.size() && p.children[i].start == r.placed &&
           !(p.children[i].is_timeline && p.children[i].slot == slot && p.children[i].generation == r.generation))
        ++i;
    if (i == p.children.size() || p.children[i].start != r.placed) return;
    TimelineChild& c = p.children[i];
    const double old_end = c.end;
    const double length = length_in_parent(r);
    const double end = c.start + length;
    if (end != old_end) {
        auto it = std::lower_bound(p.by_end.begin(), p.by_end.end(), old_end,
                                   [&](std::uint32_t x, double e) { return p.children[x].end < e; });
        while (it != p.by_end.end() && *it != i) ++it;  // among those ending there, in order
        if (it != p.by_end.end()) {
            p.by_end.erase(it);
            // A later end goes before the entries ending there (they came after it), an earlier one after.
            const auto to = end > old_end ? std::lower_bound(p.by_end.begin(), p.by_end.end(), end,
                                                             [&](std::uint32_t x, double e) { return p.children[x].end < e; })
                                          : std::upper_bound(p.by_end.begin(), p.by_end.end(), end,
                                                             [&](double e, std::uint32_t x) { return e < p.children[x].end; });
            p.by_end.insert(to, static_cast<std::uint32_t>(i));  // in the capacity just freed
        }
    }
    c.length = length;
    c.end = end;
    p.dirty = true;
    if (c.end > p.duration) {
        p.duration = c.end;
        grew(r.parent);
    }
}

void TimelineStore::add_animation(std::uint32_t slot, const Animation& a, const TimelinePosition& at) {
    const std::string w = where_of("add");
    if (a.engine_ == nullptr || &*a.engine_->impl_ != &engine_ || !engine_.find(a.slot_, a.generation_))
        throw Error(w + ": the animation is not alive in this engine");
    if (drives(a.slot_)) throw Error(w + ": the animation is already in a timeline");
    const std::uint32_t dense = engine_.dense_of(a.slot_);
    Hot& h = engine_.hot_[dense];
    Cold& cold = engine_.cold_[dense];
    TimelineChild c;
    c.slot = a.slot_;
    c.generation = a.generation_;
    c.p0 = cold.play() == 0 && h.phase < 0.0 ? h.phase : 0.0;  // its delay, if it has not begun
    c.rate = std::fabs(h.rate);  // a run-time reverse does not carry into the timeline
    c.plays = cold.plays();
    c.gap = engine_.gap_of(dense);
    c.reversed = cold.reversed;
    c.yoyo = (h.flags & flag_yoyo) != 0;
    if (c.plays == 0.0 || !(c.rate > 0.0))
        throw Error(w + ": an endless animation (repeat -1 or time_scale 0) has no end to place");
    c.length = (-c.p0 + c.plays + (c.plays - 1.0) * c.gap) / c.rate;
    if (!std::isfinite(c.length)) throw Error(w + ": the animation's length overflows");
    c.start = place(*recs_[slot], at, c.length, false, "add");
    c.end = c.start + c.length;
    if (driven_.size() <= a.slot_) driven_.resize(engine_.slots_.size(), UINT32_MAX);  // as many as the engine's slots
    insert_child(slot, c);
    driven_[a.slot_] = slot;
    // Driven from now on: the engine's own loop passes over it; it rests at its start.
    Hot& hot = engine_.hot_[dense];
    hot.flags |= flag_paused;  // skipped by the engine's loop until it moves out of it
    pending_driven_.push_back(a.slot_);
    cold.set_play(0);
    hot.phase = 0.0;
    hot.flags = play_flags(hot.flags, c.reversed, cold);
    {
        EngineImpl::Dispatch d(engine_);
        engine_.write_state(dense);
    }
    engine_.hot_[engine_.dense_of(a.slot_)].phase = c.p0;
    // Its first play begins when the timeline reaches it, not at creation or placement: a
    // from-current or relative start is read then (where the previous child left the member),
    // and overwrite applies then.
    if (Extra* e = engine_.extra_mut(a.slot_)) e->started = false;
}

void TimelineStore::add_timeline(std::uint32_t slot, std::uint32_t child, const TimelinePosition& at) {
    const std::string w = where_of("add");
    TimelineRec& c = *recs_[child];
    if (c.parent != UINT32_MAX) throw Error(w + ": the timeline is already in a timeline");
    for (std::uint32_t s = slot; s != UINT32_MAX; s = recs_[s]->parent)
        if (s == child) throw Error(w + ": a timeline cannot contain itself (the placement would make a cycle)");
    if (c.plays == 0.0 || !(c.time_scale > 0.0))
        throw Error(w + ": an endless timeline (repeat -1 or time_scale 0) has no end to place");
    TimelineChild e;
    e.is_timeline = true;
    e.slot = child;
    e.generation = c.generation;
    e.length = length_in_parent(c);
    if (!std::isfinite(e.length)) throw Error(w + ": the timeline's length overflows");
    e.start = place(*recs_[slot], at, e.length, false, "add");
    e.end = e.start + e.length;
    c.placed = e.start;
    insert_child(slot, e);
    ++recs_[slot]->nested;
    if (c.root != UINT32_MAX) {
        flush(c, true);
        set_mode(c.root, root_idle);  // driven by its parent from now on
    }
    c.parent = slot;
    ++stale_roots_;
    c.paused = false;
    c.direction = 1.0;
}

void TimelineStore::add_callback(std::uint32_t slot, std::function<void()> f, const TimelinePosition& at) {
    TimelineRec& r = *recs_[slot];
    const double t = place(r, at, 0.0, true, "call");
    auto handler = std::make_shared<const std::function<void()>>(std::move(f));
    const auto pos = std::upper_bound(r.callbacks.begin(), r.callbacks.end(), t,
                                      [](double s, const TimelineCallback& x) { return s < x.time; });
    if (!(pos == r.callbacks.end() && t > r.cursor)) r.dirty = true;
    r.callbacks.insert(pos, {t, std::move(handler)});
    if (t > r.duration) {
        r.duration = t;
        grew(slot);
    }
}

void TimelineStore::add_label(std::uint32_t slot, std::string_view name, const TimelinePosition& at) {
    TimelineRec& r = *recs_[slot];
    if (name.empty()) throw Error("Timeline::label: a label needs a name");
    if (std::any_of(r.labels.begin(), r.labels.end(), [&](const auto& l) { return l.first == name; }))
        throw Error("Timeline::label: duplicate label '" + std::string(name) + "'");
    const double t = place(r, at, 0.0, true, "label");
    r.labels.emplace_back(std::string(name), t);
    if (t > r.duration) {
        r.duration = t;
        grew(slot);
    }
}

void TimelineStore::add_gap(std::uint32_t slot, double seconds, const TimelinePosition& at) {
    if (!(std::isfinite(seconds) && seconds >= 0.0))
        throw Error("Timeline::gap: seconds must be >= 0 and finite (got " + number_text(seconds) + ")");
    TimelineRec& r = *recs_[slot];
    const double t = place(r, at, seconds, false, "gap");
    if (t + seconds > r.duration) {
        r.duration = t + seconds;
        grew(slot);
    }
}

void TimelineStore::rebase(TimelineRec& r) noexcept {
    r.base = r.tau;
    r.elapsed = 0.0;
    ++r.epoch;
}

void TimelineStore::kill_rec(std::uint32_t slot) noexcept {
    TimelineRec& r = *recs_[slot];
    if (!r.alive) return;
    r.alive = false;
    r.dead = true;
    ++r.generation;
    ++r.epoch;
    ++dead_;
    dead_slots_.push_back(slot);  // capacity reserved at creation
    if (r.parent == UINT32_MAX) ++stale_roots_;
    if (r.root != UINT32_MAX) set_mode(r.root, root_idle);
    for (const TimelineChild& c : r.children) {
        if (c.is_timeline) {
            if (recs_[c.slot]->generation == c.generation) kill_rec(c.slot);
        } else if (const Hot* h = engine_.find(c.slot, c.generation)) {
            (void)h;
            driven_[c.slot] = UINT32_MAX;
            engine_.mark_dead(engine_.dense_of(c.slot));
        }
    }
}

Timeline TimelineStore::with_generation_for_test(const Timeline& t, std::uint32_t generation) noexcept {
    if (!t.engine_) return {};
    TimelineRec* r = t.engine_->impl_->timelines().find(t.slot_, t.generation_);
    if (!r) return {};
    r->generation = generation;
    return Timeline(t.engine_, t.slot_, generation);
}

void TimelineStore::kill(std::uint32_t slot) noexcept {
    kill_rec(slot);
    if (!engine_.ticking_ && engine_.depth_ == 0) engine_.finish_dispatch();
}

void TimelineStore::kill_all() noexcept {
    for (std::uint32_t s = 0; s < recs_.size(); ++s) kill_rec(s);
}

void TimelineStore::finish() noexcept {
    if (depth_ > 0) return;
    for (const std::uint32_t s : dead_slots_) {
        recycle(*recs_[s]);
        // At the last generation the slot is retired (engine_impl.hpp, Slot): never reused.
        if (recs_[s]->generation != last_generation) free_.push_back(s);  // capacity reserved at creation
    }
    dead_slots_.clear();
    dead_ = 0;
    // Animations placed since: out of the engine's loop (their records move past it).
    for (const std::uint32_t slot : pending_driven_) {
        const Slot& s = engine_.slots_[slot];
        if (!(s.dense & free_bit) && drives(slot)) engine_.make_driven(s.dense);
    }
    pending_driven_.clear();
    // Top-level entries that were killed or placed into a timeline leave the list.
    if (stale_roots_ > 0) {
        std::size_t kept = 0;
        for (std::size_t i = 0; i < roots_.size(); ++i) {
            TimelineRec& r = *recs_[roots_[i].slot];
            if (!r.alive || r.parent != UINT32_MAX) {
                r.root = UINT32_MAX;
                continue;
            }
            roots_[kept] = roots_[i];
            lines_[kept] = lines_[i];
            due_[kept] = due_[i];
            r.root = static_cast<std::uint32_t>(kept++);
        }
        roots_.resize(kept);
        lines_.resize(kept);
        due_.resize(kept);
        stale_roots_ = 0;
    }
}

}  // namespace detail

}  // namespace grape
