// Timelines advancing: the play structure (loops, yoyo, repeat delays, both directions), the
// sweep of one play's window across child starts, ends and callbacks in time order, and the
// children driven from their timeline's time.
#include "timeline_impl.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <cmath>

namespace grape::detail {

namespace {

bool backward_play(const TimelineRec& r, double play) noexcept { return r.yoyo && std::fmod(play, 2.0) == 1.0; }
double start_of_play(const TimelineRec& r, double play) noexcept { return backward_play(r, play) ? r.duration : 0.0; }
double end_of_play(const TimelineRec& r, double play) noexcept { return backward_play(r, play) ? 0.0 : r.duration; }

void erase_active(TimelineRec& r, std::uint32_t i) noexcept {
    const auto it = std::lower_bound(r.active.begin(), r.active.end(), i);
    if (it != r.active.end() && *it == i) r.active.erase(it);
}
void insert_active(TimelineRec& r, std::uint32_t i) noexcept {
    const auto it = std::lower_bound(r.active.begin(), r.active.end(), i);
    if (it == r.active.end() || *it != i) r.active.insert(it, i);  // capacity reserved when placed
}

// The timeline's update on the stack of updates in progress while in scope.
struct Entered {
    std::vector<std::pair<std::uint32_t, std::uint64_t>>& stack;
    Entered(std::vector<std::pair<std::uint32_t, std::uint64_t>>& s, std::uint32_t slot, std::uint64_t epoch) : stack(s) {
        stack.push_back({slot, epoch});
    }
    ~Entered() { stack.pop_back(); }
    Entered(const Entered&) = delete;
    Entered& operator=(const Entered&) = delete;
};

struct Depth {
    int& depth;
    explicit Depth(int& d) noexcept : depth(d) { ++depth; }
    ~Depth() { --depth; }
};

}  // namespace

TimelineStore::PlayPoint TimelineStore::point_of(const TimelineRec& r, double tau) const noexcept {
    PlayPoint p;
    if (tau < r.delay) {
        p.waiting = true;
        return p;
    }
    if (!(r.duration > 0.0)) {  // nothing takes time: every play at once
        p.finished = r.plays > 0.0;
        if (p.finished) p.play = r.plays - 1.0;
        return p;
    }
    const PlayState s = play_at_position((tau - r.delay) / r.duration, r.plays, false, r.yoyo, r.repeat_delay / r.duration);
    p.play = s.play;
    p.finished = s.finished;
    const double phase = std::clamp(s.phase, 0.0, 1.0);
    p.local = s.backward ? (1.0 - phase) * r.duration : phase * r.duration;
    return p;
}

double TimelineStore::local_of(const TimelineRec& r, double tau, double* play) const noexcept {
    const PlayPoint p = point_of(r, tau);
    if (play) *play = p.play;
    return p.local;
}

void TimelineStore::set_cursor_tau(TimelineRec& r, double play, double local) noexcept {
    const double into = backward_play(r, play) ? r.duration - local : local;
    r.tau = r.delay + play * (r.duration + r.repeat_delay) + into;
}

// An update ends when a timeline it is advancing was killed or had its time changed; updates
// of other timelines begun from its handlers (a seek) do not end its own, nor it theirs.
bool TimelineStore::stack_intact() const noexcept {
    for (std::size_t k = base_; k < stack_.size(); ++k) {
        const TimelineRec& r = *recs_[stack_[k].first];
        if (!r.alive || r.epoch != stack_[k].second) return false;
    }
    return true;
}


bool TimelineStore::call(const Handler& h) {
    if (!h) return true;
    const Handler keep = h;  // survives being replaced from inside itself
    {
        EngineImpl::Dispatch d(engine_);
        (*keep)();
    }
    return stack_intact();
}

// --- the tick and seek ----------------------------------------------------------------------

void TimelineStore::seek(std::uint32_t slot, double tau, bool fire) {
    ++recs_[slot]->epoch;  // ends an update of this timeline in progress
    {
        Depth depth(depth_);
        EngineImpl::Dispatch d(engine_);
        Base base(*this);
        if (!advance(slot, tau, fire)) settle(slot);
    }
    TimelineRec& r = *recs_[slot];
    if (r.alive) {
        r.base = r.tau;
        r.elapsed = 0.0;
    }
}

// Children placed from outside an update take their state at once: the timeline and those
// containing it go, silently, to where their time now falls.
void TimelineStore::sync(std::uint32_t slot) {
    Depth depth(depth_);
    EngineImpl::Dispatch d(engine_);
    Base base(*this);
    for (std::uint32_t s = slot; s != UINT32_MAX; s = recs_[s]->parent) {
        if (!recs_[s]->alive) return;
        // One being updated now picks the change up itself (its window is rebuilt as it goes).
        for (const auto& entry : stack_)
            if (entry.first == s) return;
        if (!advance(s, recs_[s]->tau, false) || !drive_active(s, recs_[s]->cursor, false)) {
            std::uint32_t top = s;
            while (recs_[top]->parent != UINT32_MAX) top = recs_[top]->parent;
            settle(top);
            return;
        }
    }
}

// A handler ended an update part way: the timeline keeps the time its update had reached
// (set before the children running at a point are brought there), but children after the one
// whose handler ran, and the timelines containing it, were not brought there. Everything
// inside it now goes there silently, so that its state is again the pure function of its time
// that seek gives. A handler run by these silent writes may end this too: a few tries.
void TimelineStore::settle(std::uint32_t slot) {
    for (int attempt = 0; attempt < 4; ++attempt) {
        if (!recs_[slot]->alive) return;
        Base base(*this);
        if (settle_tree(slot)) return;
    }
}

bool TimelineStore::settle_tree(std::uint32_t slot) {
    if (!advance(slot, recs_[slot]->tau, false)) return false;  // the window at its time
    TimelineRec* r = recs_[slot].get();
    const Entered entered(stack_, slot, r->epoch);
    const std::uint64_t window = r->rebuilds;
    const std::size_t count = r->children.size();
    // Animations outside the window were driven to their start or end when it passed them;
    // nested timelines are walked whatever their place, as a handler may have stopped inside one.
    const std::size_t n = r->nested > 0 ? count : r->active.size();
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t i = r->nested > 0 ? j : r->active[j];
        const TimelineChild c = r->children[i];
        if (!c.is_timeline && (!c.entered || c.ended)) continue;
        if (!drive(slot, i, r->cursor, false)) return false;
        r = recs_[slot].get();
        if (c.is_timeline && recs_[c.slot]->alive && recs_[c.slot]->generation == c.generation && !settle_tree(c.slot))
            return false;
        r = recs_[slot].get();
        if (r->dirty || r->rebuilds != window || r->children.size() != count) return false;  // placed meanwhile: again
    }
    return stack_intact();
}

// --- one timeline's update ------------------------------------------------------------------

bool TimelineStore::advance(std::uint32_t slot, double tau, bool fire) {
    TimelineRec* r = recs_[slot].get();
    const Entered entered(stack_, slot, r->epoch);
    if (r->dirty) rebuild(slot);
    const double from = r->tau;
    const PlayPoint a = point_of(*r, from);
    // Children placed since the last update may have moved the play structure (a longer play):
    // the window first goes, silently, to where the current time now falls.
    if (a.local != r->cursor && !sweep(slot, a.local, a.local > r->cursor, false, a.play)) return false;
    r = recs_[slot].get();
    r->tau = from;  // the sweep's points set it from their local times, which may round
    if (tau == from) return true;
    // A handler that places children may lengthen the play, or place them behind the playhead
    // or across it after the last point this update crosses: at the end of the update the
    // window goes, silently, to where the time now falls in it, and the children active there
    // are brought to it (as sync does for children placed from outside an update).
    const double planned = r->duration;
    auto done = [&] {
        const TimelineRec& now = *recs_[slot];
        if (now.duration == planned && !now.dirty) return true;
        return advance(slot, now.tau, false) && drive_active(slot, recs_[slot]->cursor, false);
    };
    const PlayPoint b = point_of(*r, tau);
    if (tau > from) {
        if (b.waiting) {
            r->tau = tau;
            return true;
        }
        if (from <= r->delay && tau > r->delay && fire && r->on_start) {
            if (!call(r->on_start)) return false;
            r = recs_[slot].get();
        }
        double k = a.play;
        for (;;) {
            const double target = k == b.play ? b.local : end_of_play(*r, k);
            if (!sweep(slot, target, !backward_play(*r, k), fire, k)) return false;
            r = recs_[slot].get();
            if (k == b.play) break;
            // Beyond max_loop_events plays in one update, straight to the last one.
            const double next = b.play - k > max_loop_events ? b.play : k + 1.0;
            const double start = start_of_play(*r, next);
            if (r->cursor != start && !sweep(slot, start, start > r->cursor, false, next)) return false;
            r = recs_[slot].get();
            k = next;
            if (fire && r->on_loop) {
                set_cursor_tau(*r, k, start);
                const auto keep = r->on_loop;
                {
                    EngineImpl::Dispatch d(engine_);
                    (*keep)(static_cast<int>(std::min(k, static_cast<double>(INT32_MAX))));
                }
                if (!stack_intact()) return false;
                r = recs_[slot].get();
            }
        }
        r->tau = tau;
        if (fire) {
            if (!call(r->on_update)) return false;
            r = recs_[slot].get();
            if (b.finished && !a.finished && !call(r->on_complete)) return false;
        }
        return done();
    }
    // Backward (reversed at run time): down to the start of the first play at most.
    if (from <= r->delay) {
        r->tau = tau;
        return true;
    }
    const bool to_start = tau <= r->delay;
    const double k_end = to_start ? 0.0 : b.play;
    const double l_end = to_start ? 0.0 : b.local;
    double k = a.play;
    for (;;) {
        const double target = k == k_end ? l_end : start_of_play(*r, k);
        if (!sweep(slot, target, backward_play(*r, k), fire, k)) return false;
        r = recs_[slot].get();
        if (k == k_end) break;
        const double previous = k - k_end > max_loop_events ? k_end : k - 1.0;
        const double end = end_of_play(*r, previous);
        if (r->cursor != end && !sweep(slot, end, end > r->cursor, false, previous)) return false;
        r = recs_[slot].get();
        k = previous;
    }
    r->tau = tau;
    if (fire) {
        if (!call(r->on_update)) return false;
        r = recs_[slot].get();
        if (to_start && !call(r->on_reverse_complete)) return false;
    }
    return done();
}

// Moves the window from the cursor to `to` (local seconds within play `play`), crossing child
// ends, callbacks and child starts in time order, then drives the children active at `to`.
bool TimelineStore::sweep(std::uint32_t slot, double to, bool forward, bool fire, double play) {
    TimelineRec* r = recs_[slot].get();
    r->arrived_forward = forward;
    for (;;) {
        double t_end, t_call, t_start, t;
        if (forward) {
            t_end = r->finished < r->by_end.size() ? r->children[r->by_end[r->finished]].end : HUGE_VAL;
            t_call = r->passed < r->callbacks.size() ? r->callbacks[r->passed].time : HUGE_VAL;
            t_start = r->started < r->children.size() ? r->children[r->started].start : HUGE_VAL;
            t = std::min({t_end, t_call, t_start});
            if (!(t <= to)) break;
        } else {
            t_start = r->started > 0 ? r->children[r->started - 1].start : -HUGE_VAL;
            t_call = r->passed > 0 ? r->callbacks[r->passed - 1].time : -HUGE_VAL;
            t_end = r->finished > 0 ? r->children[r->by_end[r->finished - 1]].end : -HUGE_VAL;
            t = std::max({t_end, t_call, t_start});
            if (!(t >= to)) break;
        }
        r->cursor = t;
        set_cursor_tau(*r, play, t);
        // The children running now reach t first: their own events come before this point's.
        const std::uint64_t window = r->rebuilds;
        const std::size_t children = r->children.size(), calls = r->callbacks.size();
        if (!drive_active(slot, t, fire)) return false;
        r = recs_[slot].get();
        if (r->dirty) rebuild(slot);
        // Their handlers placed something: look for the next point again.
        if (r->rebuilds != window || r->children.size() != children || r->callbacks.size() != calls) continue;
        bool ok = true;
        if (forward) {  // at equal times: ends, callbacks, starts
            if (t_end == t) {
                const std::uint32_t i = r->by_end[r->finished++];
                r->children[i].ended = true;
                erase_active(*r, i);
                ok = drive(slot, i, t, fire);
            } else if (t_call == t) {
                const Handler h = r->callbacks[r->passed++].handler;
                ok = !fire || call(h);
            } else {
                const auto i = static_cast<std::uint32_t>(r->started++);
                r->children[i].entered = true;
                if (!r->children[i].ended) insert_active(*r, i);
                ok = drive(slot, i, t, fire);
            }
        } else {  // the mirror: starts, callbacks, ends
            if (t_start == t) {
                const auto i = static_cast<std::uint32_t>(--r->started);
                r->children[i].entered = false;
                erase_active(*r, i);
                ok = drive(slot, i, t, fire);
                r = recs_[slot].get();
                if (i < r->children.size() && !r->children[i].entered) r->children[i].last = -HUGE_VAL;  // resting, not begun
            } else if (t_call == t) {
                const Handler h = r->callbacks[--r->passed].handler;
                ok = !fire || call(h);
            } else {
                const std::uint32_t i = r->by_end[--r->finished];
                r->children[i].ended = false;
                if (r->children[i].entered) insert_active(*r, i);
                ok = drive(slot, i, t, fire);
            }
        }
        if (!ok) return false;
        r = recs_[slot].get();
        if (r->dirty) rebuild(slot);
    }
    r->cursor = to;
    set_cursor_tau(*r, play, to);
    return drive_active(slot, to, fire);
}

bool TimelineStore::drive_active(std::uint32_t slot, double local, bool fire) {
    TimelineRec* r = recs_[slot].get();
    for (std::size_t j = 0; j < r->active.size(); ++j) {
        const std::uint64_t window = r->rebuilds;
        if (!drive(slot, r->active[j], local, fire)) return false;
        r = recs_[slot].get();
        if (r->dirty) rebuild(slot);
        // Children added by a handler: the window again (those driven already do not change).
        if (r->rebuilds != window) j = static_cast<std::size_t>(-1);
    }
    return true;
}

bool TimelineStore::drive(std::uint32_t slot, std::size_t i, double local, bool fire) {
    const TimelineChild& c = recs_[slot]->children[i];
    if (!c.is_timeline) return drive_animation(slot, i, local, fire);
    const std::uint32_t child = c.slot;
    const TimelineRec& k = *recs_[child];
    if (!k.alive || k.generation != c.generation) return true;  // killed: nothing to drive
    const double into = local - c.start;
    const double tau = into <= 0.0 ? 0.0 : into >= c.length ? total(k) : into * k.time_scale;
    if (!advance(child, tau, fire)) return stack_intact();
    return true;
}

bool TimelineStore::drive_animation(std::uint32_t slot, std::size_t i, double local, bool fire) {
    TimelineChild& child = recs_[slot]->children[i];
    if (!engine_.find(child.slot, child.generation)) return true;  // killed
    const double into = local - child.start;
    const double position = into <= 0.0 ? child.p0 : into >= child.length ? HUGE_VAL : child.p0 + into * child.rate;
    const double old = child.last;
    if (position == old) return true;
    child.last = position;
    const TimelineChild c = child;  // handlers may move the children
    const std::uint32_t dense = engine_.dense_of(c.slot);
    const PlayState s = play_at_position(position, c.plays, c.reversed, c.yoyo, c.gap);
    Hot& h = engine_.hot_[dense];
    Cold& cold = engine_.cold_[dense];
    if (h.flags & flag_dead) return true;
    cold.set_play(s.finished ? cold.plays() - 1 : wrap_plays(s.play));
    h.phase = s.phase < 0.0 ? 0.0 : s.phase + s.gap;  // inside its own delay it shows its start
    h.flags = play_flags(h.flags, s.backward, cold);
    const std::uint32_t generation = c.generation;
    {
        EngineImpl::Dispatch d(engine_);
        engine_.write_state(dense);
    }
    if (!engine_.find(c.slot, generation)) return stack_intact();
    const std::uint32_t now = engine_.dense_of(c.slot);
    if (s.phase < 0.0) engine_.hot_[now].phase = s.phase;
    if (!stack_intact()) return false;
    if (!fire || !(engine_.hot_[now].flags & flag_listens)) return true;
    const Extra* e = engine_.extra(c.slot);
    if (!e) return true;
    const auto on_start = e->on_start;
    const auto on_loop = e->on_loop;
    const auto on_complete = e->on_complete;
    const auto on_reverse = e->on_reverse_complete;
    auto still = [&] { return engine_.find(c.slot, generation) && stack_intact(); };
    if (position > old) {
        if (old < 0.0 && position >= 0.0 && on_start) {
            call(on_start);
            if (!still()) return stack_intact();
        }
        const PlayState before = play_at_position(old, c.plays, c.reversed, c.yoyo, c.gap);
        const double loops = s.play - before.play;
        if (loops > 0.0 && on_loop) {
            EngineImpl::Dispatch d(engine_);
            auto number = [](double p) { return static_cast<int>(std::min(p, static_cast<double>(INT32_MAX))); };
            if (loops <= max_loop_events) {
                for (double k = 1.0; k <= loops; k += 1.0) {
                    (*on_loop)(number(before.play + k), 0);
                    if (!still()) return stack_intact();
                }
            } else {
                (*on_loop)(number(s.play), static_cast<std::uint64_t>(loops - 1.0));
                if (!still()) return stack_intact();
            }
        }
        if (s.finished && !before.finished && on_complete) call(on_complete);
    } else if (position <= 0.0 && old > 0.0 && on_reverse) {
        call(on_reverse);
    }
    return stack_intact();
}

// The window recomputed at the cursor after children were added behind or inside it; children
// that the window now counts as ended are driven to their end.
void TimelineStore::rebuild(std::uint32_t slot) {
    TimelineRec& r = *recs_[slot];
    r.dirty = false;
    ++r.rebuilds;
    const double x = r.cursor;
    const bool forward = r.arrived_forward;
    auto reached = [&](double t) { return forward ? t <= x : t < x; };
    r.started = 0;
    while (r.started < r.children.size() && reached(r.children[r.started].start)) ++r.started;
    r.finished = 0;
    while (r.finished < r.by_end.size() && reached(r.children[r.by_end[r.finished]].end)) ++r.finished;
    r.passed = 0;
    while (r.passed < r.callbacks.size() && reached(r.callbacks[r.passed].time)) ++r.passed;
    for (std::size_t i = 0; i < r.children.size(); ++i) r.children[i].entered = i < r.started;
    bool behind = false;  // children placed behind the playhead (rare) go to their end
    for (std::size_t j = 0; j < r.by_end.size(); ++j) {
        TimelineChild& c = r.children[r.by_end[j]];
        const bool ended = j < r.finished;
        if (ended && !c.ended) behind = c.to_end = true;
        c.ended = ended;
    }
    r.active.clear();
    for (std::uint32_t i = 0; i < r.started; ++i)
        if (!r.children[i].ended) r.active.push_back(i);
    if (!behind) return;
    // In the order of ends; handlers may place children meanwhile (the marks move with them).
    for (std::size_t j = 0; j < recs_[slot]->by_end.size(); ++j) {
        TimelineRec& q = *recs_[slot];
        const std::uint32_t i = q.by_end[j];
        if (!q.children[i].to_end) continue;
        q.children[i].to_end = false;
        drive(slot, i, x, false);
    }
}

}  // namespace grape::detail
