// The tick over the top-level timelines: a fast loop for the common case (one animation or
// none active, no point crossed, no handler to run) on the timelines' own entries, and the
// general update (timeline_tick.cpp) for everything else.
//
// The fast case repeats the general update's arithmetic operation for operation (the clock,
// the timing model's play and phase inside a play, the child's position and phase, the
// engine's easing, point and write), so a timeline gives the same bits whichever path ran.
// It holds only while the time stays inside the current play of the timeline and of the
// child, `margin` plays clear of their ends, where the timing model's snapping (play_snap,
// 1e-9 plays) and rounding cannot pick another play; and strictly between the nearest child
// starts, ends and callbacks, so the window is unchanged. Anything else takes the general
// path for that tick, after which the entry is filled again if the state allows it.
#include "timeline_impl.hpp"

#include "engine_eval.hpp"

#include <algorithm>
#include <cmath>

namespace grape::detail {

namespace {

constexpr double margin = 1e-7;  // plays; ≫ play_snap + the rounding of plays below 1e7
constexpr double most_plays = 1e7;  // (play + 1) · cycle below this: rounding ≤ 2e-9 plays
constexpr std::size_t ahead = 8;    // entries: ~ a memory latency of fast updates

inline void prefetch(const void* p) noexcept {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(p, 1);
#else
    (void)p;
#endif
}

struct Depth {
    int& depth;
    explicit Depth(int& d) noexcept : depth(d) { ++depth; }
    ~Depth() { --depth; }
};

// Where the timeline's local time and the child's position stand after `elapsed` seconds
// (the operations of TimelineStore::tick, point_of and drive_animation).
struct FastPoint {
    double tau, lp, local, position;
};
FastPoint fast_point(const RootEntry& e, double elapsed) noexcept {
    FastPoint p;
    p.tau = e.base + elapsed * e.scale;
    p.lp = (p.tau - e.delay) / e.duration - e.kc;
    p.local = e.backward ? (1.0 - p.lp) * e.duration : p.lp * e.duration;
    p.position = e.p0 + (p.local - e.start) * e.rate;
    return p;
}

}  // namespace

TimelineRec* TimelineStore::find(std::uint32_t slot, std::uint32_t generation) noexcept {
    return current(slot, generation, true);
}

TimelineRec* TimelineStore::peek(std::uint32_t slot, std::uint32_t generation) noexcept {
    return current(slot, generation, false);
}

TimelineRec* TimelineStore::current(std::uint32_t slot, std::uint32_t generation, bool leave) noexcept {
    if (slot >= recs_.size()) return nullptr;
    TimelineRec* r = recs_[slot].get();
    if (!r->alive || r->generation != generation) return nullptr;
    flush(*r, leave);
    return r;
}

void TimelineStore::flush(TimelineRec& r, bool leave) noexcept {
    if (r.root == UINT32_MAX) return;
    RootEntry& e = roots_[r.root];
    if (e.mode == root_empty || e.mode == root_one) {
        const FastPoint p = fast_point(e, e.elapsed);
        r.elapsed = e.elapsed;
        r.tau = p.tau;
        r.cursor = p.local;
        if (e.mode == root_one) r.children[e.child_index].last = p.position;
    }
    if (leave) e.mode = root_slow;
}

void TimelineStore::forget(std::uint32_t animation_slot) noexcept {
    if (!drives(animation_slot)) return;
    TimelineRec& r = *recs_[driven_[animation_slot]];
    if (r.root != UINT32_MAX && roots_[r.root].mode == root_one) flush(r, true);
    driven_[animation_slot] = UINT32_MAX;
}

void TimelineStore::tick(double dt) {
    const std::size_t n = roots_.size();  // timelines created by handlers start next tick
    const Slot* slots = engine_.slots_.data();
    Hot* hot = engine_.hot_.data();
    const Cold* cold = engine_.cold_.data();
    if (moved_ || engine_.hot_.size() != seen_records_) {
        for (std::size_t i = 0; i < n; ++i) {
            RootEntry& e = roots_[i];
            if (e.mode != root_one) continue;
            const Slot s = slots[e.child];
            if (s.generation == e.child_generation && !(s.dense & free_bit)) e.dense = s.dense;
            else flush(*recs_[e.slot], true);
        }
        moved_ = false;
    }
    bool stale = false;  // records moved during this tick: look the children up
    std::size_t records = engine_.hot_.size();
    for (std::size_t i = 0; i < n; ++i) {
        // The children's records and targets lie anywhere: fetched some entries ahead (a
        // stale address is only a wasted fetch).
        if (i + ahead < n && roots_[i + ahead].mode == root_one) {
            const RootEntry& f = roots_[i + ahead];
            if (f.dense < records) prefetch(hot + f.dense);
            prefetch(f.target);
        }
        RootEntry& e = roots_[i];
        if (e.mode == root_idle) continue;
        if (e.mode != root_slow) {
            const double elapsed = e.elapsed + dt;
            const double tau = e.base + elapsed * e.scale;
            const double lp = (tau - e.delay) / e.duration - e.kc;
            const double local = e.backward ? (1.0 - lp) * e.duration : lp * e.duration;
            if (lp >= margin && lp <= 1.0 - margin && local > e.lo && local < e.hi) {
                if (e.mode == root_empty) {
                    e.elapsed = elapsed;
                    continue;
                }
                bool found = true;
                if (stale) {
                    const Slot s = slots[e.child];
                    found = s.generation == e.child_generation && !(s.dense & free_bit);
                    e.dense = s.dense;
                }
                const double into = local - e.start;
                const double position = e.p0 + into * e.rate;
                const double ph = position - e.cj;
                if (found && ph >= margin && ph <= 1.0 - margin) {
                    Hot& h = hot[e.dense];
                    if (!(h.flags & (flag_dead | flag_custom))) {
                        h.phase = ph;
                        const double x = (h.flags & flag_backward) ? 1.0 - ph : ph;
                        const double u = engine_.ease(h.kind, has_parameters(h.kind) ? cold[e.dense].curve : 0, x);
                        if (h.target) engine_.write_2d(h, engine_.point(h.path, u));
                        e.elapsed = elapsed;
                        continue;
                    }
                }
            }
        }
        step_slow(i, dt);
        if (engine_.hot_.size() != records) stale = true;  // a handler created (the engine moved one)
        records = engine_.hot_.size();
        slots = engine_.slots_.data();  // handlers may have grown the storage
        hot = engine_.hot_.data();
        cold = engine_.cold_.data();
    }
    seen_records_ = engine_.hot_.size();
    if (stale) moved_ = true;
}

void TimelineStore::step_slow(std::size_t i, double dt) {
    const std::uint32_t slot = roots_[i].slot;
    TimelineRec& r = *recs_[slot];
    flush(r, true);
    if (!r.alive || r.paused || r.parent != UINT32_MAX) {
        roots_[i].mode = root_idle;  // until a command on it
        return;
    }
    r.elapsed += dt;
    const double tau = std::clamp(r.base + r.elapsed * r.time_scale * r.direction, 0.0, total(r));
    if (tau != r.tau || r.dirty) {
        Depth depth(depth_);
        Base base(*this);
        if (!advance(slot, tau, true)) settle(slot);
    }
    try_fast(i);
}

void TimelineStore::try_fast(std::size_t i) noexcept {
    RootEntry& e = roots_[i];
    e.mode = root_slow;
    const TimelineRec& r = *recs_[e.slot];
    if (!r.alive || r.parent != UINT32_MAX || r.paused || r.dirty || r.nested > 0 || r.on_update || r.active.size() > 1 ||
        !(r.duration > 0.0))
        return;
    // The timeline: inside a play, where the clock gives its time exactly.
    const double scale = r.time_scale * r.direction;
    const double tau = r.base + r.elapsed * scale;
    if (tau != r.tau) return;
    const double pos = (tau - r.delay) / r.duration;
    const double gap = r.repeat_delay / r.duration;
    const PlayState s = play_at_position(pos, r.plays, false, r.yoyo, gap);
    const double cycle = 1.0 + gap;
    if (s.finished || !(s.phase >= margin && s.phase <= 1.0 - margin) || !((s.play + 1.0) * cycle < most_plays)) return;
    const double kc = gap > 0.0 ? s.play * cycle : s.play;
    if (pos - kc != s.phase) return;
    const double local = s.backward ? (1.0 - s.phase) * r.duration : s.phase * r.duration;
    if (local != r.cursor) return;
    // The window: the nearest points either side (the next ones the sweep would cross).
    double lo = -HUGE_VAL, hi = HUGE_VAL;
    if (r.started < r.children.size()) hi = std::min(hi, r.children[r.started].start);
    if (r.finished < r.by_end.size()) hi = std::min(hi, r.children[r.by_end[r.finished]].end);
    if (r.passed < r.callbacks.size()) hi = std::min(hi, r.callbacks[r.passed].time);
    if (r.started > 0) lo = std::max(lo, r.children[r.started - 1].start);
    if (r.finished > 0) lo = std::max(lo, r.children[r.by_end[r.finished - 1]].end);
    if (r.passed > 0) lo = std::max(lo, r.callbacks[r.passed - 1].time);
    e.elapsed = r.elapsed;
    e.base = r.base;
    e.scale = scale;
    e.delay = r.delay;
    e.duration = r.duration;
    e.kc = kc;
    e.lo = lo;
    e.hi = hi;
    e.backward = s.backward;
    if (r.active.empty()) {
        e.mode = root_empty;
        return;
    }
    // The child: an animation inside one of its plays, written by the engine's plain path.
    const std::uint32_t ci = r.active[0];
    const TimelineChild& c = r.children[ci];
    if (c.is_timeline) return;
    const Hot* h = engine_.find(c.slot, c.generation);
    if (!h || (h->flags & (flag_dead | flag_custom))) return;
    const double into = local - c.start;
    if (!(into > 0.0 && into < c.length)) return;
    const double position = c.p0 + into * c.rate;
    if (position != c.last) return;
    const PlayState cs = play_at_position(position, c.plays, c.reversed, c.yoyo, c.gap);
    const double child_cycle = 1.0 + c.gap;
    if (cs.finished || !(cs.phase >= margin && cs.phase <= 1.0 - margin) || !((cs.play + 1.0) * child_cycle < most_plays))
        return;
    const double cj = c.gap > 0.0 ? cs.play * child_cycle : cs.play;
    if (position - cj != cs.phase || h->phase != cs.phase || ((h->flags & flag_backward) != 0) != cs.backward) return;
    // local < hi must keep local − start below the length (into ≥ length is the child's end).
    for (int k = 0; k < 64 && hi > local && !(hi - c.start < c.length); ++k) hi = std::nextafter(hi, -HUGE_VAL);
    if (!(hi - c.start < c.length)) return;
    if (!(hi > local)) return;
    e.hi = hi;
    e.start = c.start;
    e.p0 = c.p0;
    e.rate = c.rate;
    e.cj = cj;
    e.child = c.slot;
    e.child_generation = c.generation;
    e.child_index = ci;
    e.dense = engine_.dense_of(c.slot);
    e.target = h->target;
    e.mode = root_one;
}

}  // namespace grape::detail
