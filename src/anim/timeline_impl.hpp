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
    // Animations: the timing, fixed when placed (position in plays = p0 + rate · seconds).
    double p0 = 0.0;       // plays at placement (−delay / duration)
    double rate = 0.0;     // plays per parent second
    double plays = 0.0;
    double gap = 0.0;      // repeat delay in plays
    bool reversed = false;
    bool yoyo = false;
    double last = -HUGE_VAL;  // the position in plays last driven to (−inf: resting, not begun)
};

struct TimelineCallback {
    double time;
    std::shared_ptr<const std::function<void()>> handler;
};

using Handler = std::shared_ptr<const std::function<void()>>;

struct TimelineRec {
    std::uint32_t generation = 0;
    bool alive = false;
    bool dead = false;  // killed during a dispatch: freed afterwards
    // play settings
    double delay = 0.0;
    double plays = 1.0;  // 0: forever
    double repeat_delay = 0.0;
    bool yoyo = false;
    double time_scale = 1.0;
    bool paused = false;
    // top-level clock: tau = base + elapsed · time_scale · direction
    double base = 0.0;
    double elapsed = 0.0;
    double direction = 1.0;
    // where it stands: seconds of own time since it was placed (delay included)
    double tau = 0.0;
    std::uint64_t epoch = 0;  // bumped by every time change from outside the current update
    std::uint32_t parent = UINT32_MAX;  // slot of the containing timeline
    // layout
    double duration = 0.0;
    double previous_start = 0.0;
    double previous_end = 0.0;
    std::vector<TimelineChild> children;      // sorted by start (stable)
    std::vector<std::uint32_t> by_end;        // child indices sorted by end (stable)
    std::vector<std::uint32_t> active;        // entered and not ended, ascending
    std::vector<TimelineCallback> callbacks;  // sorted by time (stable)
    std::vector<std::pair<std::string, double>> labels;
    std::size_t started = 0;  // children[0, started) entered
    std::size_t finished = 0; // by_end[0, finished) ended
    std::size_t passed = 0;   // callbacks[0, passed) crossed
    double cursor = 0.0;      // local time the window stands at
    bool dirty = false;       // children changed: rebuild the window at the cursor
    bool arrived_forward = false;  // the cursor came forward (points at it are behind it)
    std::uint32_t nested = 0;      // children that are timelines
    std::uint64_t rebuilds = 0;    // counts window rebuilds (a loop over the window restarts)
    // events
    Handler on_start, on_update, on_complete, on_reverse_complete;
    std::shared_ptr<const std::function<void(int)>> on_loop;
};

class TimelineStore {
public:
    explicit TimelineStore(EngineImpl& engine) : engine_(engine) { stack_.reserve(64); }

    Timeline create(Engine* owner, const TimelineDef& def);
    TimelineRec* find(std::uint32_t slot, std::uint32_t generation) noexcept;

    void add_animation(std::uint32_t slot, const Animation& a, const TimelinePosition& at);
    void add_timeline(std::uint32_t slot, std::uint32_t child, const TimelinePosition& at);
    void add_callback(std::uint32_t slot, std::function<void()> f, const TimelinePosition& at);
    void add_label(std::uint32_t slot, std::string_view name, const TimelinePosition& at);
    void add_gap(std::uint32_t slot, double seconds, const TimelinePosition& at);

    void tick(double dt);
    void sync(std::uint32_t slot);
    void seek(std::uint32_t slot, double tau, bool fire);
    void rebase(TimelineRec& r) noexcept;
    void kill(std::uint32_t slot) noexcept;
    void kill_all() noexcept;
    void finish() noexcept;  // after a dispatch: frees killed records
    bool drives(std::uint32_t animation_slot) const noexcept { return driven_.count(animation_slot) != 0; }
    void forget(std::uint32_t animation_slot) noexcept { driven_.erase(animation_slot); }

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

    // the update (timeline_tick.cpp); false: a handler changed this timeline's time, stop
    bool advance(std::uint32_t slot, double tau, bool fire);
    bool sweep(std::uint32_t slot, double to, bool forward, bool fire, double play);
    bool drive(std::uint32_t slot, std::size_t child, double local, bool fire);
    bool drive_active(std::uint32_t slot, double local, bool fire);
    bool drive_animation(std::uint32_t slot, std::size_t child, double local, bool fire);
    void rebuild(TimelineRec& r);
    bool call(const Handler& h);
    bool stack_intact() const noexcept;
    // after an update a handler ended: the tree goes silently to the state of its time
    void settle(std::uint32_t slot);
    bool settle_tree(std::uint32_t slot);
    struct Base;  // RAII: an update checks only the stack entries pushed since it began
    void set_cursor_tau(TimelineRec& r, double play, double local) noexcept;

    EngineImpl& engine_;
    std::vector<std::unique_ptr<TimelineRec>> recs_;
    std::vector<std::uint32_t> free_;
    std::vector<std::uint32_t> roots_;  // top-level timelines, in creation order
    std::unordered_map<std::uint32_t, std::uint32_t> driven_;  // animation slot → timeline slot
    std::vector<std::pair<std::uint32_t, std::uint64_t>> stack_;  // updates in progress: slot, epoch
    std::size_t base_ = 0;  // stack_[base_, size) belong to the innermost tick, seek or sync
    std::vector<std::uint32_t> dead_slots_;      // killed, freed after the dispatch
    std::vector<std::uint32_t> pending_driven_;  // animation slots to move out of the engine's loop
    std::size_t stale_roots_ = 0;                // roots_ entries killed or nested since the last clean-up
    std::size_t dead_ = 0;
    int depth_ = 0;  // updates in progress
};

}  // namespace grape::detail
