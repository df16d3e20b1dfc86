// Timelines inside the engine: records held by slot (stable addresses, so handlers may create
// timelines while one is advancing), children sorted by start with an index sorted by end and
// an active window, callbacks sorted by time.
#pragma once

#include <grape/timeline.hpp>

#include "engine_impl.hpp"

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace grape::detail {

/// One child of a timeline: an animation or a nested timeline.
struct TimelineChild {
    double start = 0.0;   // parent local seconds
    double end = 0.0;     // start + length
    double length = 0.0;  // parent seconds from its placement to its end
    std::uint32_t slot = 0;        // animation slot or timeline slot
    std::uint32_t generation = 0;
    bool is_timeline = false;
    bool entered = false;  // the cursor is at or past its start
    bool ended = false;    // the cursor is at or past its end
    bool to_end = false;   // ended by a rebuild of the window: to be driven to its end
    // Animations: the timing, fixed when placed (position in plays = p0 + rate · seconds).
    double p0 = 0.0;       // plays at placement (−delay / duration)
    double rate = 0.0;     // plays per parent second
    double plays = 0.0;
    double gap = 0.0;      // repeat delay in plays
    bool reversed = false;
    bool yoyo = false;
    double last = -HUGE_VAL;  // the position in plays last driven to (−inf: resting, not begun)
};

/// A top-level timeline as the tick walks it (TimelineStore::lines_ and roots_, in creation
/// order). In the fast modes the clock and the one active child's time are kept in the entry,
/// and the record's tau, cursor, the child's `last` and its engine record's phase are stale
/// until flush() (find() and the child's handle flush first): the tick computes them with the
/// slow path's own operations, so both give the same bits.
enum RootMode : std::uint8_t {
    root_slow,   // the record is current; the tick advances it the general way
    root_idle,   // paused, killed or nested: the tick passes over it (commands make it slow)
    root_empty,  // fast, no child active
    root_one,    // fast, one animation active
};

enum RootBit : std::uint8_t {
    root_mode = 3,         // RootMode
    root_lean = 4,         // scale 1, no delay, a forward play, kc whole, the child's p0 and cj 0
    root_float = 8,        // the child's target members are float
    root_backward = 16,    // the child's play runs back
    root_kernel = 96,      // lean with a target: the child's path's LaneKernel (timeline_lanes.hpp)
};
inline constexpr unsigned root_kernel_shift = 5;
static_assert(root_kernel >> root_kernel_shift == 3);

// The active children's targets lie anywhere (no stride a prefetcher could follow): asked for
// this many entries early, ~250 ns of fast updates, longer than a memory latency.
inline constexpr std::size_t timeline_ahead = 48;

/// What the tick reads of a timeline in a fast mode: one cache line. Lean entries need nothing
/// else; the others also read their RootEntry.
struct alignas(64) RootLine {
    double elapsed = 0.0;   // TimelineRec::elapsed
    double base = 0.0;      // TimelineRec::base
    double duration = 1.0;
    double start = 0.0;     // the active child: TimelineChild's start and rate
    double rate = 0.0;
    float until = -1.0f;    // a clock at or below this stays inside the interval (rounded down)
    float kc = 0.0f;        // lean: the play's start in plays (whole, below 2^24: exact)
    char* target = nullptr; // the child's target (Hot::target)
    std::uint32_t path = 0; // Hot::path
    std::int16_t y_offset = 0;
    CurveKind kind = CurveKind::linear;
    std::uint8_t bits = root_slow;
};
static_assert(sizeof(RootLine) == 64);

struct TimelineRec;

/// The rest of a fast entry: the constants lean entries do without, and what flush() needs.
struct RootEntry {
    double scale = 0.0;     // time_scale · direction
    double delay = 0.0;
    double kc = 0.0;        // the current play's start, in plays of the timeline
    double p0 = 0.0;        // the active child: TimelineChild's p0
    double cj = 0.0;        // the child's current play's start, in its plays
    TimelineRec* rec = nullptr;      // the timeline (stable: records are held by slot)
    std::uint32_t slot = 0;
    std::uint32_t child = 0;         // the child's animation slot and generation
    std::uint32_t child_generation = 0;
    std::uint32_t child_index = 0;   // in TimelineRec::children
    std::uint16_t curve = 0;         // Cold::curve (curves with parameters)
    bool backward = false;  // the play runs back (yoyo)
};

struct TimelineCallback {
    double time;
    std::shared_ptr<const std::function<void()>> handler;
};

using Handler = std::shared_ptr<const std::function<void()>>;

// The fields an update reads come first and together (a sequence's hand-over reads the first
// 240 bytes and the children at the window's edge); labels and the other handlers after them.
struct TimelineRec {
    std::uint32_t generation = 0;
    bool alive = false;
    bool dead = false;  // killed during a dispatch: freed afterwards
    bool yoyo = false;
    bool paused = false;
    bool dirty = false;            // children changed: rebuild the window at the cursor
    bool arrived_forward = false;  // the cursor came forward (points at it are behind it)
    std::uint32_t parent = UINT32_MAX;  // slot of the containing timeline
    std::uint32_t nested = 0;           // children that are timelines
    std::uint32_t root = UINT32_MAX;    // its entry in TimelineStore::lines_ and roots_ while top-level
    // play settings
    double delay = 0.0;
    double plays = 1.0;  // 0: forever
    double repeat_delay = 0.0;
    double time_scale = 1.0;
    // top-level clock: tau = base + elapsed · time_scale · direction
    double base = 0.0;
    double elapsed = 0.0;
    double direction = 1.0;
    // where it stands: seconds of own time since it was placed (delay included)
    double tau = 0.0;
    double duration = 0.0;
    double cursor = 0.0;      // local time the window stands at
    std::size_t started = 0;  // children[0, started) entered
    std::size_t finished = 0; // by_end[0, finished) ended
    std::size_t passed = 0;   // callbacks[0, passed) crossed
    std::vector<TimelineChild> children;      // sorted by start (stable)
    std::vector<std::uint32_t> by_end;        // child indices sorted by end (stable)
    std::vector<std::uint32_t> active;        // entered and not ended, ascending
    std::vector<TimelineCallback> callbacks;  // sorted by time (stable)
    Handler on_update;
    std::uint64_t epoch = 0;  // bumped by every time change from outside the current update
    std::uint64_t rebuilds = 0;    // counts window rebuilds (a loop over the window restarts)
    double placed = 0.0;                // its start there (parent seconds)
    // layout
    double previous_start = 0.0;
    double previous_end = 0.0;
    std::vector<std::pair<std::string, double>> labels;
    // events
    Handler on_start, on_complete, on_reverse_complete;
    std::shared_ptr<const std::function<void(int)>> on_loop;
};

class TimelineStore {
public:
    explicit TimelineStore(EngineImpl& engine) : engine_(engine), wide_(wide_lanes()) { stack_.reserve(64); }

    Timeline create(Engine* owner, const TimelineDef& def);
    /// Sets one of `t`'s void() handlers (empty: none); nothing for a dead handle.
    static void set_handler(const Timeline& t, Handler TimelineRec::*member, std::function<void()> handler);
    /// Test only (tests/test_timeline.cpp): as EngineImpl::with_generation_for_test, for a
    /// live timeline (a slot whose generation reaches last_generation is retired here too).
    GRAPE_ANIM_API static Timeline with_generation_for_test(const Timeline& t, std::uint32_t generation) noexcept;
    TimelineRec* find(std::uint32_t slot, std::uint32_t generation) noexcept;

    void add_animation(std::uint32_t slot, const Animation& a, const TimelinePosition& at);
    void add_timeline(std::uint32_t slot, std::uint32_t child, const TimelinePosition& at);
    void add_callback(std::uint32_t slot, std::function<void()> f, const TimelinePosition& at);
    void add_label(std::uint32_t slot, std::string_view name, const TimelinePosition& at);
    void add_gap(std::uint32_t slot, double seconds, const TimelinePosition& at);

    void tick(double dt);
    /// The record brought up to date from the tick's fast entry; `leave`: the entry goes back
    /// to the general path (the caller changes the record).
    void flush(TimelineRec& r, bool leave) noexcept;
    TimelineRec* peek(std::uint32_t slot, std::uint32_t generation) noexcept;  // find, staying fast
    // The live record, brought up to date from the fast tick's entry (`leave`: off the fast path).
    TimelineRec* current(std::uint32_t slot, std::uint32_t generation, bool leave) noexcept;
    void sync(std::uint32_t slot);
    void seek(std::uint32_t slot, double tau, bool fire);
    void rebase(TimelineRec& r) noexcept;
    void kill(std::uint32_t slot) noexcept;
    void kill_all() noexcept;
    void finish() noexcept;  // after a dispatch: frees killed records
    bool drives(std::uint32_t animation_slot) const noexcept {
        return animation_slot < driven_.size() && driven_[animation_slot] != UINT32_MAX;
    }
    void forget(std::uint32_t animation_slot) noexcept;  // killed: its timeline leaves the fast case
    /// A driven animation's handle is used: its timeline's fast state is written out (`leave`:
    /// and the timeline takes the general path next tick, as its flags may change).
    void touch(std::uint32_t animation_slot, bool leave) noexcept;

    double total(const TimelineRec& r) const noexcept;        // own seconds of all plays and delays
    double length_in_parent(const TimelineRec& r) const noexcept { return total(r) / r.time_scale; }
    double local_of(const TimelineRec& r, double tau, double* play) const noexcept;

    struct PlayPoint {
        double play = 0.0;   // which play (0 while waiting)
        double local = 0.0;  // seconds into it
        bool waiting = false;
        bool finished = false;
    };
    PlayPoint point_of(const TimelineRec& r, double tau) const noexcept;

private:
    double place(TimelineRec& r, const TimelinePosition& at, double duration, bool point, const char* where);
    void insert_child(std::uint32_t slot, TimelineChild c);
    void grew(std::uint32_t slot);  // duration changed: the parents' entries follow
    void kill_rec(std::uint32_t slot) noexcept;
    void step_slow(std::size_t i, double dt);  // one top-level timeline's tick, the general way
    void try_fast(std::size_t i) noexcept;     // enters a fast mode where the state allows it
    bool cross(std::size_t i, double dt);  // a child's end and the next one's start, fast
    std::size_t fast_run(std::size_t i, std::size_t n, double dt) noexcept;  // the fast entries from i
    void set_mode(std::uint32_t root, RootMode m) noexcept {
        lines_[root].bits = static_cast<std::uint8_t>((lines_[root].bits & ~root_mode) | m);
        due_[root] = m == root_idle ? HUGE_VAL : -HUGE_VAL;  // slow and idle: slow every tick, never
    }
    void ask_stage(int stage, std::uint32_t root) const noexcept;  // one stage of a hand-over's prefetch
    RootMode mode(std::uint32_t root) const noexcept { return static_cast<RootMode>(lines_[root].bits & root_mode); }

    // the update (timeline_tick.cpp); false: a handler changed this timeline's time, stop
    bool advance(std::uint32_t slot, double tau, bool fire);
    bool sweep(std::uint32_t slot, double to, bool forward, bool fire, double play);
    bool drive(std::uint32_t slot, std::size_t child, double local, bool fire);
    bool drive_active(std::uint32_t slot, double local, bool fire);
    bool drive_animation(std::uint32_t slot, std::size_t child, double local, bool fire);
    void rebuild(std::uint32_t slot);
    bool call(const Handler& h);
    bool stack_intact() const noexcept;
    // after an update a handler ended: the tree goes silently to the state of its time
    void settle(std::uint32_t slot);
    bool settle_tree(std::uint32_t slot);
    struct Base;  // RAII: an update checks only the stack entries pushed since it began
    void set_cursor_tau(TimelineRec& r, double play, double local) noexcept;

    EngineImpl& engine_;
    bool wide_;  // four-lane runs for lean entries (timeline_lanes.hpp)
    std::vector<std::unique_ptr<TimelineRec>> recs_;
    std::vector<std::uint32_t> free_;
    std::vector<RootLine> lines_;       // top-level timelines, in creation order
    std::vector<RootEntry> roots_;      // the same, what the tick reads only of non-lean entries
    // The same again: the store clock past which the entry leaves the fast case (its `until`
    // moved to the store clock; −inf: slow, +inf: idle). Only a forecast: it chooses what the
    // tick asks for ahead, never what it does, so rounding in it costs a prefetch at most.
    std::vector<double> due_;
    std::vector<std::uint32_t> soon_;   // this tick's entries forecast to leave the fast case
    double clock_ = 0.0;                // the sum of the ticks' dt
    std::vector<std::uint32_t> driven_;  // animation slot → timeline slot (UINT32_MAX: none)
    std::vector<std::pair<std::uint32_t, std::uint64_t>> stack_;  // updates in progress: slot, epoch
    std::size_t base_ = 0;  // stack_[base_, size) belong to the innermost tick, seek or sync
    std::vector<std::uint32_t> dead_slots_;      // killed, freed after the dispatch
    std::vector<std::uint32_t> pending_driven_;  // animation slots to move out of the engine's loop
    std::size_t stale_roots_ = 0;                // roots_ entries killed or nested since the last clean-up
    std::size_t dead_ = 0;
    int depth_ = 0;  // updates in progress
};

struct TimelineStore::Base {
    TimelineStore& store;
    std::size_t saved;
    explicit Base(TimelineStore& s) noexcept : store(s), saved(s.base_) { store.base_ = store.stack_.size(); }
    ~Base() { store.base_ = saved; }
    Base(const Base&) = delete;
    Base& operator=(const Base&) = delete;
};

}  // namespace grape::detail
