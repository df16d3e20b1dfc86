// The tick over the top-level timelines: a fast loop for the common case (one animation or
// none active, no point crossed, no handler to run) on one cache line per timeline, a short
// path for a sequence's hand-over from one child to the next, and the general update
// (timeline_tick.cpp) for everything else.
//
// The fast case repeats the general update's arithmetic operation for operation (the clock,
// the timing model's play and phase inside a play, the child's position and phase, the
// engine's easing, point and write), so a timeline gives the same bits whichever path ran.
// It holds only while the time stays inside the current play of the timeline and of the
// child, `margin` plays clear of their ends, where the timing model's snapping (play_snap,
// 1e-9 plays) and rounding cannot pick another play; and strictly between the nearest child
// starts, ends and callbacks, so the window is unchanged. Those conditions are solved once,
// when the entry is filled, for the last clock where they hold (`until`): every operation is
// monotone in the clock. The child's engine record is not touched: its phase is written out
// when anything looks at it (flush). Anything else takes the general path for that tick,
// after which the entry is filled again if the state allows it.
//
// Each filled entry also leaves a forecast (`due_`: its `until` on the store's clock), so a
// tick knows before it starts which entries will hand over, and asks for their records a few
// hand-overs ahead (ask_stage) instead of testing every entry's neighbours.
#include "timeline_impl.hpp"

#include "engine_eval.hpp"
#include "timeline_lanes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grape::detail {

namespace {

constexpr double margin = 1e-7;  // plays; ≫ play_snap + the rounding of plays below 1e7
constexpr double most_plays = 1e7;  // (play + 1) · cycle below this: rounding ≤ 2e-9 plays
constexpr std::size_t ahead = timeline_ahead;
// A hand-over's records are asked for in `stages` steps, `stride` hand-overs apart: neighbouring
// timelines often hand over on the same tick, one right after the other, and one hand-over's
// time is shorter than a memory latency.
constexpr std::size_t stages = 5;
constexpr std::size_t stride = 2;

struct FastDepth {
    int& depth;
    explicit FastDepth(int& d) noexcept : depth(d) { ++depth; }
    ~FastDepth() { --depth; }
};

// Where the timeline's local time and the child's position stand after `elapsed` seconds
// (the operations of TimelineStore::tick, point_of and drive_animation).
struct FastPoint {
    double tau, lp, local, position;
};
FastPoint fast_point(const RootLine& l, const RootEntry& e, double elapsed) noexcept {
    FastPoint p;
    p.tau = l.base + elapsed * e.scale;
    p.lp = (p.tau - e.delay) / l.duration - e.kc;
    p.local = e.backward ? (1.0 - p.lp) * l.duration : p.lp * l.duration;
    p.position = e.p0 + (p.local - l.start) * l.rate;
    return p;
}

// The fast case's conditions at a clock of `elapsed`: inside the play and the child's play,
// `margin` clear of their ends, and strictly between the window's nearest points lo and hi.
// Every operation is monotone in `elapsed`, so the clocks where they hold form an interval.
bool holds(const RootLine& l, const RootEntry& e, double lo, double hi, bool one, double elapsed) noexcept {
    const FastPoint p = fast_point(l, e, elapsed);
    if (!(p.lp >= margin && p.lp <= 1.0 - margin && p.local > lo && p.local < hi)) return false;
    const double ph = p.position - e.cj;
    return !one || (ph >= margin && ph <= 1.0 - margin);
}

// The clock where the interval ends, solved in real arithmetic (a little off by rounding).
double interval_end(const RootLine& l, const RootEntry& e, double lo, double hi, bool one) noexcept {
    const double d = l.duration;
    double lp_lo = margin, lp_hi = 1.0 - margin;
    auto local_bounds = [&](double a, double b) {  // local in [a, b] as bounds on lp
        lp_lo = std::max(lp_lo, e.backward ? 1.0 - b / d : a / d);
        lp_hi = std::min(lp_hi, e.backward ? 1.0 - a / d : b / d);
    };
    local_bounds(lo, hi);
    if (one && l.rate > 0.0)
        local_bounds(l.start + (e.cj + margin - e.p0) / l.rate, l.start + (e.cj + 1.0 - margin - e.p0) / l.rate);
    if (e.scale > 0.0) return (e.delay + (e.kc + lp_hi) * d - l.base) / e.scale;
    if (e.scale < 0.0) return (e.delay + (e.kc + lp_lo) * d - l.base) / e.scale;
    return HUGE_VAL;  // a stopped clock stays where it is
}

// The last clock of the interval from `elapsed` on, rounded down to a float; below `elapsed`
// when there is none.
float interval_until(const RootLine& l, const RootEntry& e, double lo, double hi, bool one, double elapsed) noexcept {
    constexpr double largest = 3.0e38;  // below FLT_MAX
    const double end = std::min(interval_end(l, e, lo, hi, one), largest);
    if (!(end > elapsed)) return -HUGE_VALF;
    // A millionth of the interval and 64 ulps of the clock back, then halved until it holds.
    double at = end - (end - elapsed) * 1e-6 - 64.0 * std::numeric_limits<double>::epsilon() * std::fabs(end);
    for (int k = 0; k < 40 && at > elapsed && !holds(l, e, lo, hi, one, at); ++k) at = elapsed + (at - elapsed) * 0.5;
    if (!(at > elapsed) || !holds(l, e, lo, hi, one, at)) return -HUGE_VALF;
    float f = static_cast<float>(at);
    if (static_cast<double>(f) > at) f = std::nextafter(f, -HUGE_VALF);
    return f;
}

inline void write_line(const RootLine& l, Vec2 p) noexcept {  // EngineImpl::write_2d
    if (l.bits & root_float) write_pair<float>(l.target, l.y_offset, p);
    else write_pair<double>(l.target, l.y_offset, p);
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
    const RootLine& l = lines_[r.root];
    const RootEntry& e = roots_[r.root];
    const RootMode m = mode(r.root);
    if (m == root_empty || m == root_one) {
        const FastPoint p = fast_point(l, e, l.elapsed);
        r.elapsed = l.elapsed;
        r.tau = p.tau;
        r.cursor = p.local;
        if (m == root_one) {
            r.children[e.child_index].last = p.position;
            const Slot s = engine_.slots_[e.child];
            if (s.generation == e.child_generation && !(s.dense & free_bit)) engine_.hot_[s.dense].phase = p.position - e.cj;
        }
    }
    if (leave) set_mode(r.root, root_slow);
}

void TimelineStore::forget(std::uint32_t animation_slot) noexcept {
    if (!drives(animation_slot)) return;
    TimelineRec& r = *recs_[driven_[animation_slot]];
    if (r.root != UINT32_MAX && mode(r.root) == root_one) flush(r, true);
    driven_[animation_slot] = UINT32_MAX;
}

void TimelineStore::touch(std::uint32_t animation_slot, bool leave) noexcept {
    if (drives(animation_slot)) flush(*recs_[driven_[animation_slot]], leave);
}

// An entry that leaves the fast case (a hand-over, a loop) reads a chain of records, each
// found through the one before: its RootEntry, its TimelineRec's first 256 bytes, the
// children at the window's edge with `by_end` and `active`, the active child's engine slot,
// hot and cold records, then the next child's. Without them a hand-over waits on about
// eight misses in turn. The tick asks for them in `stages` steps as it meets hand-overs:
// step s for the hand-over `stride · (stages − 1 − s)` ahead, so each step reads what the one
// before brought in. Every read is bounds-checked against the current vectors: a handler may
// have changed them since the forecast.
void TimelineStore::ask_stage(int stage, std::uint32_t root) const noexcept {
    if (root >= roots_.size()) return;
    const RootEntry& e = roots_[root];
    if (stage == 0) {  // nothing of the entry read yet: it is what this step asks for
        ask_line(&e);
        ask_line(reinterpret_cast<const char*>(&e) + sizeof(RootEntry) - 1);
        return;
    }
    const TimelineRec* r = e.rec;
    const auto& slots = engine_.slots_;
    auto ask_records = [&](std::uint32_t slot) {  // an animation's engine records
        if (slot >= slots.size()) return;
        const Slot s = slots[slot];
        if (!(s.dense & free_bit) && s.dense < engine_.hot_.size()) {
            ask_hot(engine_.hot_.data(), s.dense);
            ask_cold(engine_.cold_.data(), s.dense);
        }
    };
    switch (stage) {
        case 1:
            if (r) {
                const char* p = reinterpret_cast<const char*>(r);
                for (std::size_t line = 0; line < 256; line += 64) ask_line(p + line);  // the fields an update reads
            }
            if (e.child < slots.size()) ask_line(&slots[e.child]);
            return;
        case 2:
            if (r) {
                const std::size_t count = r->children.size();
                if (r->started < count) ask_line(r->children.data() + r->started);  // the next to start
                if (r->started + 1 < count) ask_line(r->children.data() + r->started + 1);  // and the one after
                if (e.child_index < count) ask_line(r->children.data() + e.child_index);
                if (r->finished < r->by_end.size()) ask_line(r->by_end.data() + r->finished);
                ask_line(r->active.data());
            }
            ask_records(e.child);
            return;
        case 3:
            if (r && r->started < r->children.size() && !r->children[r->started].is_timeline &&
                r->children[r->started].slot < slots.size())
                ask_line(&slots[r->children[r->started].slot]);
            return;
        default:
            if (r && r->started < r->children.size() && !r->children[r->started].is_timeline)
                ask_records(r->children[r->started].slot);
            return;
    }
}

// The fast entries from i on, up to the first that takes the general path (returned; n: none).
GRAPE_FLATTEN std::size_t TimelineStore::fast_run(std::size_t i, std::size_t n, double dt) noexcept {
    // Locals: no handler runs here, so the vectors stay put, and the target writes (through
    // char*) cannot make the compiler read them again for every entry.
    RootLine* const lines = lines_.data();
    const RootEntry* const roots = roots_.data();
    const KernelKind* const kinds = engine_.path_kind_.data();
    const LineFast* const line_fast = engine_.line_fast_.data();
    const PathFast* const path_fast = engine_.path_fast_.data();
    // In batches: the clocks and child positions of a batch first, then their easings, points
    // and writes. An entry is one long chain of dependent operations (a division, the easing,
    // the point), and the reorder window holds only a few entries' chains: split in two, the
    // divisions of neighbouring entries overlap, and so do their easings.
    constexpr std::size_t batch = 16;
    std::uint32_t index[batch];
    double xs[batch];
    while (i < n) {
        // Lean entries four at a time while they share a run; from the group of four that
        // stops the run (an entry that hands over, or of another kind) a batch one entry at a
        // time, and then the lanes again.
        if (wide_)
            if (const TimelineLanes run = timeline_lanes_for(lines[i])) {
                i = run(lines, line_fast, path_fast, i, n, dt);
                if (i == n) return n;
            }
        const std::size_t m = std::min(batch, n - i);
        std::size_t k = 0, count = 0;
        for (; k < m; ++k) {
            const std::size_t j = i + k;
            if (j + ahead < n && (lines[j + ahead].bits & root_mode) == root_one) ask_line(lines[j + ahead].target);
            RootLine& l = lines[j];
            const std::uint8_t mode = l.bits & root_mode;
            if (mode == root_idle) continue;
            if (mode == root_slow) break;
            const double elapsed = l.elapsed + dt;
            if (!(elapsed <= static_cast<double>(l.until))) break;
            l.elapsed = elapsed;
            if (mode == root_empty || !l.target) continue;
            double x;
            if (l.bits & root_lean) {  // fast_point with scale 1, delay 0, forward, p0 and cj 0
                const double lp = (l.base + elapsed) / l.duration - static_cast<double>(l.kc);
                x = (lp * l.duration - l.start) * l.rate;
            } else {
                const RootEntry& e = roots[j];
                x = fast_point(l, e, elapsed).position - e.cj;
            }
            if (l.bits & root_backward) x = 1.0 - x;
            index[count] = static_cast<std::uint32_t>(k);
            xs[count++] = x;
        }
        for (std::size_t c = 0; c < count; ++c) {
            const std::size_t j = i + index[c];
            const RootLine& l = lines[j];
            const double u = (l.bits & root_lean) ? detail::ease_formula(l.kind, xs[c]) : engine_.ease(l.kind, roots[j].curve, xs[c]);
            Vec2 p;  // EngineImpl::point on the locals
            if (!kernel_point(kinds, line_fast, path_fast, l.path, u, p)) p = engine_.point(l.path, u);
            write_line(l, p);
        }
        i += k;
        if (k < m) return i;
    }
    return n;
}

void TimelineStore::tick(double dt) {
    const std::size_t n = lines_.size();  // timelines created by handlers start next tick
    clock_ += dt;
    // The forecast: the entries whose fast case ends on this tick, without a branch per entry
    // (a few in a hundred are taken). Capacity reserved at creation: no allocation here.
    soon_.resize(n);
    std::size_t forecast = 0;
    const double now = clock_;
    const double* const due = due_.data();
    std::uint32_t* const soon = soon_.data();
    for (std::size_t i = 0; i < n; ++i) {
        soon[forecast] = static_cast<std::uint32_t>(i);
        forecast += !(now <= due[i]);
    }
    // The first hand-overs: the steps they would have had.
    for (std::size_t s = 0; s < stages; ++s)
        for (std::size_t j = 0; j < forecast && j < stride * (stages - s); ++j) ask_stage(static_cast<int>(s), soon_[j]);
    std::size_t next = 0;  // soon_[next]: the first forecast entry past the current one
    for (std::size_t i = 0; i < n; ++i) {
        i = fast_run(i, n, dt);
        if (i == n) break;
        while (next < forecast && soon_[next] <= i) ++next;
        for (std::size_t s = 0; s < stages; ++s)
            if (const std::size_t j = next + stride * (stages - 1 - s); j < forecast) ask_stage(static_cast<int>(s), soon_[j]);
        if (!cross(i, dt)) step_slow(i, dt);
    }
}

// A sequence's child hands over to the next: the general update's sweep across the active
// child's end and the next child's start, for plain animations that nobody listens to, in a
// play without callbacks, forward. The same reads, writes and window changes as advance()
// and sweep() in that case, without their machinery for handlers (none can run here). Also
// the step that crosses nothing, for a timeline the fast case refused or left within
// `margin` of a child's start or end: a tick that lands on a child's end (a duration in
// whole ticks) lands there, or just past it, by rounding.
bool TimelineStore::cross(std::size_t i, double dt) {
    const RootMode m = mode(static_cast<std::uint32_t>(i));
    if (m == root_idle) return false;
    TimelineRec& r = *roots_[i].rec;
    // (a slow entry's RootEntry is stale; a backward play fails the local-time test below)
    if (!r.alive || r.paused || r.parent != UINT32_MAX || !r.callbacks.empty() || r.dirty || r.on_update || r.nested > 0 ||
        (m != root_slow && roots_[i].backward) || r.active.size() > 1)
        return false;
    flush(r, false);
    const double elapsed = r.elapsed + dt;
    const double tau = std::clamp(r.base + elapsed * r.time_scale * r.direction, 0.0, total(r));  // step_slow's
    if (!(tau > r.tau) || !(r.tau > r.delay)) return false;
    const PlayPoint a = point_of(r, r.tau), b = point_of(r, tau);
    if (b.waiting || b.finished || a.finished || b.play != a.play || a.local != r.cursor || !(b.local > r.cursor)) return false;
    // The points the sweep crosses: the active child's end, then the next child's start.
    const double to = b.local;
    std::size_t started = r.started, finished = r.finished;
    std::uint32_t ended = UINT32_MAX, begun = UINT32_MAX;
    for (;;) {
        const double t_end = finished < r.by_end.size() ? r.children[r.by_end[finished]].end : HUGE_VAL;
        const double t_start = started < r.children.size() ? r.children[started].start : HUGE_VAL;
        const double t = std::min(t_end, t_start);
        if (!(t <= to)) break;
        if (t_end == t) {
            if (ended != UINT32_MAX || begun != UINT32_MAX || r.active.empty() || r.by_end[finished] != r.active[0])
                return false;
            ended = r.by_end[finished++];
        } else {
            if (begun != UINT32_MAX) return false;
            begun = static_cast<std::uint32_t>(started++);
        }
    }
    if (begun != UINT32_MAX && ended == UINT32_MAX && !r.active.empty()) return false;  // two active
    auto plain = [&](std::uint32_t k) {
        const TimelineChild& c = r.children[k];
        if (c.is_timeline) return false;
        const Hot* h = engine_.find(c.slot, c.generation);
        return h && !(h->flags & (flag_dead | flag_custom | flag_listens));
    };
    if ((ended != UINT32_MAX && !plain(ended)) || (begun != UINT32_MAX && !plain(begun)) ||
        (!r.active.empty() && !plain(r.active[0])))
        return false;
    // drive_animation without events: the child at `local`, unless it stands there already.
    auto drive_plain = [&](std::uint32_t k, double local) {
        TimelineChild& c = r.children[k];
        const double into = local - c.start;
        const double position = into <= 0.0 ? c.p0 : into >= c.length ? HUGE_VAL : c.p0 + into * c.rate;
        if (position == c.last) return;
        c.last = position;
        const std::uint32_t dense = engine_.dense_of(c.slot);
        const PlayState s = play_at_position(position, c.plays, c.reversed, c.yoyo, c.gap);
        Hot& h = engine_.hot_[dense];
        Cold& cold = engine_.cold_[dense];
        cold.set_play(s.finished ? cold.plays() - 1 : wrap_plays(s.play));
        h.phase = s.phase < 0.0 ? 0.0 : s.phase + s.gap;
        h.flags = play_flags(h.flags, s.backward, cold);
        engine_.write_state(dense);  // plain: writes the target, runs nothing
        if (s.phase < 0.0) h.phase = s.phase;
    };
    r.arrived_forward = true;
    r.elapsed = elapsed;
    if (ended != UINT32_MAX) {
        drive_plain(ended, r.children[ended].end);  // drive_active at the end, then the end itself
        r.children[ended].ended = true;
        r.active.clear();
        r.finished = finished;
    }
    if (begun != UINT32_MAX) {
        TimelineChild& c = r.children[begun];
        c.entered = true;
        r.started = started;
        if (!c.ended) r.active.push_back(begun);  // capacity reserved when placed
        drive_plain(begun, c.start);
    }
    r.cursor = to;
    if (!r.active.empty()) drive_plain(r.active[0], to);
    r.tau = tau;
    try_fast(i);
    return true;
}

void TimelineStore::step_slow(std::size_t i, double dt) {
    const std::uint32_t slot = roots_[i].slot;
    TimelineRec& r = *roots_[i].rec;  // recs_[slot]
    flush(r, true);
    if (!r.alive || r.paused || r.parent != UINT32_MAX) {
        set_mode(static_cast<std::uint32_t>(i), root_idle);  // until a command on it
        return;
    }
    r.elapsed += dt;
    const double tau = std::clamp(r.base + r.elapsed * r.time_scale * r.direction, 0.0, total(r));
    if (tau != r.tau || r.dirty) {
        FastDepth depth(depth_);
        Base base(*this);
        if (!advance(slot, tau, true)) settle(slot);
    }
    try_fast(i);
}

void TimelineStore::try_fast(std::size_t i) noexcept {
    RootLine& l = lines_[i];
    RootEntry& e = roots_[i];
    l.bits = root_slow;
    due_[i] = -HUGE_VAL;
    const TimelineRec& r = *e.rec;  // recs_[e.slot], without a miss on recs_
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
    l.elapsed = r.elapsed;
    l.base = r.base;
    l.duration = r.duration;
    l.start = 0.0;
    l.rate = 0.0;
    e.scale = scale;
    e.delay = r.delay;
    e.kc = kc;
    e.p0 = 0.0;
    e.cj = 0.0;
    e.backward = s.backward;
    const bool plain = scale == 1.0 && r.delay == 0.0 && !s.backward && kc < 16777216.0 &&
                       static_cast<double>(static_cast<float>(kc)) == kc;
    l.kc = plain ? static_cast<float>(kc) : 0.0f;
    std::uint8_t bits = 0;
    if (r.active.empty()) {
        l.until = interval_until(l, e, lo, hi, false, r.elapsed);
        l.bits = root_empty;
        due_[i] = clock_ + (static_cast<double>(l.until) - l.elapsed);
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
    const std::uint32_t dense = engine_.dense_of(c.slot);
    l.start = c.start;
    l.rate = c.rate;
    l.target = h->target;
    l.path = h->path;
    l.y_offset = h->y_offset;
    l.kind = curve_kind(*h);
    e.p0 = c.p0;
    e.cj = cj;
    e.curve = engine_.cold(dense).curve;
    e.child = c.slot;
    e.child_generation = c.generation;
    e.child_index = ci;
    l.until = interval_until(l, e, lo, hi, true, r.elapsed);
    if (h->flags & flag_float) bits |= root_float;
    if (cs.backward) bits |= root_backward;
    if (plain && c.p0 == 0.0 && cj == 0.0 && !has_parameters(curve_kind(*h)))
        bits |= root_lean | static_cast<unsigned>(lane_kind(*h)) << root_kernel_shift;  // other: no target
    l.bits = static_cast<std::uint8_t>(bits | root_one);
    due_[i] = clock_ + (static_cast<double>(l.until) - l.elapsed);
}

}  // namespace grape::detail
