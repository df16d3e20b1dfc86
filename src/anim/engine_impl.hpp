// The engine's storage: hot records walked linearly every tick, cold records read on loops,
// completion and queries, handle slots, shared path and curve tables, and the optional
// per-animation extras (handlers, N-D targets, heading) kept apart in a map.
#pragma once

#include <grape/anim.hpp>

#include "path/kernel.hpp"

#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <map>
#include <memory>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace grape::detail {

class TimelineStore;
struct TimelineStoreDelete {
    void operator()(TimelineStore* store) const noexcept;  // timeline.cpp, where the type is complete
};
class TickPool;
struct Track3;  // engine_3d.hpp
struct TickPoolDelete {
    void operator()(TickPool* pool) const noexcept;  // engine_parallel.cpp
};

enum HotFlag : std::uint8_t {
    flag_paused = 1,
    flag_float = 2,     // the target's members are float (else double)
    flag_backward = 4,  // the current play runs from the path's end to its start
    flag_yoyo = 8,
    flag_more = 16,     // a play follows the current one (see with_more), known without the Cold record
    flag_custom = 32,   // written through its Extra (N-D, callback, heading)
    flag_dead = 64,     // killed or completed during a dispatch; removed afterwards
    flag_listens = 128, // has loop or complete handlers in its Extra
};

/// What every tick touches: 32 bytes.
struct Hot {
    double phase;           // time within the current play, in plays: [0, 1]; < 0 while waiting
    double rate;            // plays per engine second: time_scale / duration
    char* target;           // 2-D: the target's x member; N-D: the target (null: nothing to write)
    std::uint32_t path;     // index into the path table
    std::int16_t y_offset;  // 2-D: address of y minus address of x
    std::uint8_t kind;      // CurveKind in the low 6 bits, the path's LaneKernel in the top 2 (see lane_kind)
    std::uint8_t flags;
};

// A record's kind byte: its curve kind, and which lean loop its path's kernel suits (other
// when it has no target), so the lean runs test the path and the target with the compare of
// kind and flags they make anyway, instead of a load of the path's kernel kind and a test of
// the target per record. The path of a live record never changes, nor does the target of a
// record that is not custom.
enum class LaneKernel : std::uint8_t { other, linear, cubic, arc };
inline constexpr unsigned lane_shift = 6;
static_assert(static_cast<unsigned>(CurveKind::function) < (1u << lane_shift),
              "CurveKind must fit the kind byte's low 6 bits");
constexpr LaneKernel lane_kernel(KernelKind k) noexcept {
    switch (k) {
        case KernelKind::linear: return LaneKernel::linear;
        case KernelKind::cubic: return LaneKernel::cubic;
        case KernelKind::reparam_linear:
        case KernelKind::reparam_cubic: return LaneKernel::arc;
        default: return LaneKernel::other;
    }
}
constexpr std::uint8_t kind_byte(CurveKind c, LaneKernel p) noexcept {
    return static_cast<std::uint8_t>(static_cast<unsigned>(c) | static_cast<unsigned>(p) << lane_shift);
}
inline CurveKind curve_kind(const Hot& h) noexcept { return static_cast<CurveKind>(h.kind & ((1u << lane_shift) - 1)); }
inline LaneKernel lane_kind(const Hot& h) noexcept { return static_cast<LaneKernel>(h.kind >> lane_shift); }

/// Read on loops, completion, curves with parameters and queries: 24 bytes.
struct Cold {
    double duration;       // seconds per play
    // The play running (from 0) and the number of plays in one word, so that 64-bit play
    // counts fit the 24 bytes: a record playing forever has the top bit set and its play in
    // the other 63 bits; a finite one has plays − 1 (= repeat, < 2³¹) in bits 32–62 and its
    // play (< plays) in the low 32. Either way the next play is ++count.
    std::uint64_t count;
    std::uint32_t slot;    // the handle slot that refers to this record
    std::uint16_t curve;   // index into the curve table (curves with parameters)
    // time_scale() = rate·duration moved by this many ulps (rate·duration is up to ~2 ulps
    // off the scale set); scale_in_extra: too far, the scale is in Extra::time_scale
    std::int8_t scale_ulps = 0;
    bool reversed = false;  // AnimationDef::reversed: every play starts backward unless yoyo turns it

    static constexpr std::uint64_t forever = std::uint64_t{1} << 63;
    // A play count past this (2⁶², reached only by seeking ~10¹⁸ plays ahead) holds there,
    // keeping its parity (which yoyo reads).
    static constexpr std::uint64_t most_plays = std::uint64_t{1} << 62;
    /// The word for `plays` (repeat + 1; 0 plays forever) at play 0.
    static constexpr std::uint64_t count_of(std::uint32_t plays) noexcept {
        return plays == 0 ? forever : std::uint64_t{plays - 1} << 32;
    }
    /// repeat + 1; 0 plays forever.
    constexpr std::uint32_t plays() const noexcept {
        return (count & forever) ? 0u : static_cast<std::uint32_t>(count >> 32) + 1u;
    }
    /// Which play is running, from 0.
    constexpr std::uint64_t play() const noexcept { return (count & forever) ? count & ~forever : count & 0xffffffffu; }
    /// Sets the play running (< plays() for a finite record).
    constexpr void set_play(std::uint64_t play) noexcept {
        if (count & forever) count = forever | (play < most_plays ? play : most_plays | (play & 1u));
        else count = (count & ~std::uint64_t{0xffffffffu}) | play;
    }
};
static_assert(sizeof(Cold) == 24, "Cold must stay 24 bytes (EngineScale.SixtyFourBytesPerAnimation)");

// flag_more for a record whose Cold play count is `c`: set when the record plays forever or
// its current play is not its last. Every change of Cold::play sets it again, so that it is
// never set on a last play (the lean runs begin the next play on its word alone).
inline std::uint8_t with_more(std::uint8_t flags, const Cold& c) noexcept {
    return static_cast<std::uint8_t>((c.plays() == 0 || c.play() + 1 < c.plays()) ? flags | flag_more : flags & ~flag_more);
}
// The flags after Cold::play or the direction changed: flag_backward as `backward`, flag_more anew.
inline std::uint8_t play_flags(std::uint8_t flags, bool backward, const Cold& c) noexcept {
    return with_more(static_cast<std::uint8_t>(backward ? flags | flag_backward : flags & ~flag_backward), c);
}

/// A handle slot: 8 bytes. `dense` is the record index while alive; free slots chain
/// through it with the high bit set. `generation` counts the slot's lives and never wraps: a
/// slot whose generation reaches last_generation is retired (never reused), so a handle's
/// generation names one life of its slot for good and a stale handle stays inert. That costs
/// 8 bytes per 2³² − 1 lives of one slot, against 64-bit generations in every handle, slot and
/// timeline child.
struct Slot {
    std::uint32_t dense;
    std::uint32_t generation;
};
inline constexpr std::uint32_t last_generation = UINT32_MAX;

/// The handlers and targets only some animations have.
struct Extra {
    // Shared so that a running handler survives being replaced from inside itself: the
    // caller holds a copy of the pointer for the duration of the call (no allocation).
    std::shared_ptr<const std::function<void()>> on_complete;
    std::shared_ptr<const std::function<void(int, std::uint64_t)>> on_loop;  // (play, skipped)
    std::shared_ptr<const std::function<void(Vec2, double)>> on_update_2d;
    std::shared_ptr<const std::function<void(std::span<const double>)>> on_update_nd;
    std::shared_ptr<const std::function<void()>> on_start;             // the first play begins
    std::shared_ptr<const std::function<void()>> on_reverse_complete;  // back at the start
    std::shared_ptr<const std::function<void()>> on_update;            // after every change (flag_custom)
    bool write_rotation = false;          // 2-D targets: the heading goes to x + rotation_offset
    std::ptrdiff_t rotation_offset = 0;
    bool track_heading = false;
    double heading = 0.0;
    std::optional<PathND> nd;             // N-D animations
    std::vector<MemberRef> members;       // N-D targets
    std::vector<double> values;           // N-D current values
    // typed values, linked targets, the first play's start (values.cpp, targets.cpp)
    std::unique_ptr<ValueTrack> value;    // typed animations: writes lerp(from, to, u) at h.target
    std::unique_ptr<TargetRef> ref;       // linked targets (null: raw)
    std::ptrdiff_t target_offset = 0;     // linked: h.target = where the object is + this
    std::uintptr_t indexed_at = 0;        // its key in the target index (0: not indexed)
    bool started = false;                 // the first play has begun: captures and overwrite done
    bool overwrite = false;
    bool rotation_float = false;          // the rotation member is a float
    bool heading_continuous = false;
    bool have_heading = false;            // `heading` holds a written heading
    double heading_offset = 0.0;
    double still = 0.0;                   // |d1| at or below this: a cusp; the heading stays
    double time_scale = 0.0;              // Cold::scale_ulps == scale_in_extra: the exact scale
    double range_start = 0.0;             // AnimationDef::range_start, range_end, offset: the
    double range_end = 1.0;               // path's u = range_start + u·(range_end − range_start),
    double offset = 0.0;                  // drawn `offset` beside the path
    std::shared_ptr<Track3> p3;           // 3-D animations (engine_3d.cpp)
    double repeat_gap = 0.0;              // repeat delay in plays (its record has flag_listens,
                                          // so play ends take the slow path that reads it)
};

/// The path's u for eased progress u under the record's range (u itself for the default
/// [0, 1]: 0 + u·1 is u exactly).
inline double along_range(const Extra& e, double u) noexcept { return e.range_start + u * (e.range_end - e.range_start); }

/// Cold::scale_ulps when the exact scale is kept in Extra::time_scale.
inline constexpr std::int8_t scale_in_extra = INT8_MIN;

/// How a new 2-D record follows its target (create's extras).
struct Bind {
    std::unique_ptr<TargetRef> ref;  // linked target (null: raw)
    std::optional<bool> rotation_float;  // the rotation member's type (default: x's)
};

struct PathEntry {
    Path path;           // keeps the shape alive
    const void* shape = nullptr;  // its key in path_index_
    PathKernel kernel;   // coefficients and, for reparametrized lines and cubics, v(u)
    std::uint32_t refs = 0;
};

/// What the hot loop reads of a shared path, the linear and cubic coefficients copied in so
/// that most updates never leave the engine's storage. Line-aligned with the kind first: a
/// cubic reads two cache lines, a reparametrized path one and the three of its table's
/// piece. Lines read LineFast instead, 32 bytes, so that a thousand shared lines take half
/// the cache they would here.
struct alignas(64) PathFast {
    KernelKind fast = KernelKind::generic;
    const double* table = nullptr;   // reparametrized: the kernel's ArcLengthTable values
    double steps = 0.0;
    Vec2 c[4];                       // PathKernel::c (reparametrized: the end points)
};

/// A line's coefficients alone (c[0], c[1]), two to a cache line.
struct LineFast {
    Vec2 c[2];
};
/// An arc-length path's table alone, four to a cache line.
struct ArcFast {
    const double* table = nullptr;
    double steps = 0.0;
};

struct CurveEntry {
    Curve curve;
    std::uint32_t refs = 0;
    std::string key;  // its name in curve_index_
};

class EngineImpl {
public:
    explicit EngineImpl(Engine* owner) : owner_(owner) {
        curves_.push_back({Curve(), 1, {}});  // index 0: the formula kinds (never released)
    }

    void tick(double dt);
    Animation create(void* target, std::size_t x_offset, std::size_t y_offset, bool is_float,
                     std::ptrdiff_t rotation_offset, const Path& path, double duration, const AnimationDef& def,
                     std::function<void(Vec2, double)> on_update, Bind bind = {});
    Animation create_nd(void* target, std::vector<MemberRef> members, PathND path, double duration,
                        const AnimationDef& def, std::function<void(std::span<const double>)> on_update);

    // handle operations (inert on stale handles)
    const Hot* find(std::uint32_t slot, std::uint32_t generation) const noexcept;
    std::uint32_t dense_of(std::uint32_t slot) const noexcept { return slots_[slot].dense; }
    const Cold& cold(std::uint32_t dense) const noexcept { return cold_[dense]; }
    Hot& hot(std::uint32_t dense) noexcept { return hot_[dense]; }
    const Extra* extra(std::uint32_t slot) const noexcept;
    Extra* extra_mut(std::uint32_t slot) noexcept;  // null when it has none
    Extra& extra_for(std::uint32_t slot);
    Vec2 value_of(std::uint32_t dense) const noexcept;
    double heading_of(std::uint32_t dense) const noexcept;
    double progress_of(std::uint32_t dense) const noexcept;
    /// The repeat delay in plays (0 unless one was given).
    double gap_of(std::uint32_t dense) const noexcept {
        if (!(hot_[dense].flags & flag_listens)) return 0.0;
        const Extra* e = extra(cold_[dense].slot);
        return e ? e->repeat_gap : 0.0;
    }
    void seek(std::uint32_t dense, double seconds) noexcept;
    void set_time_scale(std::uint32_t dense, double scale) noexcept;
    void kill(std::uint32_t dense) noexcept;
    void kill_all() noexcept;

    std::size_t on_tick(std::function<void(double)> listener);
    void remove_tick_listener(std::size_t id) noexcept;

    std::size_t size() const noexcept { return live_; }
    std::size_t storage_bytes() const noexcept;

    /// The timelines (timeline_impl.hpp), made on first use.
    TimelineStore& timelines();
    /// Driven by a timeline (its own pause, resume, seek and time scale are ignored).
    bool driven(std::uint32_t slot) const noexcept;
    /// Before a handle reads or changes a driven record: its timeline writes out the state its
    /// fast tick keeps aside (`leave`: and takes the general path next tick).
    void touch_driven(std::uint32_t slot, bool leave) noexcept;

    /// Test only (tests/test_anim.cpp): sets a live animation's slot generation, so that a
    /// test reaches the last generations without 2³² reuses; returns the handle that now names
    /// it (a default handle if `a` is stale). And a handle's slot.
    GRAPE_ANIM_API static Animation with_generation_for_test(const Animation& a, std::uint32_t generation) noexcept;
    GRAPE_ANIM_API static std::uint32_t slot_for_test(const Animation& a) noexcept;

private:
    friend class TimelineStore;
    struct Dispatch;  // RAII: counts nested handler calls, compacts when the last one ends

    std::uint32_t acquire_path(const Path& path);
    void release_path(std::uint32_t index) noexcept;
    std::uint16_t acquire_curve(const Curve& curve);
    // The curve slot for a new animation whose path slot `path` is already held; releases that
    // path slot if acquiring the curve throws.
    std::uint16_t acquire_curve_for(std::uint32_t path, const Curve& curve);
    void release_curve(std::uint16_t index) noexcept;
    Animation add(Hot hot, std::uint16_t curve, double duration, const AnimationDef& def, std::optional<Extra> extra);

    double ease(CurveKind kind, std::uint16_t curve, double x) const noexcept;
    Vec2 point(std::uint32_t path, double u) const noexcept;
    void write_2d(const Hot& h, Vec2 p) const noexcept;
    void write_state(std::uint32_t dense);
    void advance_slow(std::uint32_t dense, double phase);
    void advance_back(std::uint32_t dense, double phase);
    bool fire_simple(std::uint32_t dense, std::shared_ptr<const std::function<void()>> Extra::*member);
    void fire_events(std::uint32_t dense, std::uint64_t first_play, double loops, bool completes);
    void mark_dead(std::uint32_t dense) noexcept;
    void remove_now(std::uint32_t dense) noexcept;
    void move_record(std::uint32_t from, std::uint32_t to) noexcept;
    /// Moves a record into the driven region (outside a dispatch only).
    void make_driven(std::uint32_t dense) noexcept;
    void compact() noexcept;
    void finish_dispatch() noexcept;

    Engine* owner_;
    std::vector<Hot> hot_;
    std::vector<Cold> cold_;
    std::vector<Slot> slots_;
    std::uint32_t free_slot_ = UINT32_MAX;
    std::unordered_map<std::uint32_t, Extra> extras_;  // by slot

    std::vector<PathEntry> paths_;
    std::vector<PathFast> path_fast_;  // same index as paths_
    std::vector<KernelKind> path_kind_;  // path_fast_[i].fast, dense (kernel_point's test; a record's kind byte)
    std::vector<LineFast> line_fast_;    // path_fast_[i].c[0], c[1] (lines: the lean lane's read)
    std::vector<ArcFast> arc_fast_;      // path_fast_[i].table, steps (arc length: the lean lane's read)
    std::vector<std::uint32_t> free_paths_;
    std::unordered_map<const void*, std::uint32_t> path_index_;
    std::vector<CurveEntry> curves_;
    std::vector<std::uint16_t> free_curves_;
    std::unordered_map<std::string, std::uint16_t> curve_index_;

    struct Listener {
        std::size_t id;
        std::function<void(double)> f;
        bool removed = false;  // erased after the dispatch, so a running listener stays intact
    };
    std::vector<Listener> listeners_;
    std::vector<Listener> new_listeners_;  // added during a dispatch; joined afterwards
    std::size_t next_listener_ = 1;
    bool listeners_removed_ = false;

    std::size_t live_ = 0;
    std::size_t dead_ = 0;  // records flagged dead and not yet compacted
    int depth_ = 0;         // handler calls in progress
    bool ticking_ = false;
    std::unique_ptr<TimelineStore, TimelineStoreDelete> timelines_;  // null until the first timeline
    // Records [0, driven_begin_) are ticked by the engine; [driven_begin_, size) are driven by
    // timelines and never walked by the tick.
    std::uint32_t driven_begin_ = 0;

    // --- typed values, safe targets, exact time scales (values.cpp, targets.cpp) ---
public:
    Animation create_value(void* object, std::unique_ptr<TargetRef> ref, std::unique_ptr<ValueTrack> track,
                           double duration, const AnimationDef& def);
    // --- 3-D animations (engine_3d.cpp) ---
    Animation create_3d(void* object, const Layout3& layout, std::unique_ptr<TargetRef> ref, const Path3& path,
                        double duration, const Speed* speed, const AnimationDef& def, const Motion3Def& motion);
    // Writes the state at eased progress u (after begin_write).
    void write_3d(const Hot& h, Extra& e, double u) const noexcept;
    Vec3 value3_of(std::uint32_t dense) const noexcept;
    std::size_t kill_in(std::uintptr_t lo, std::uintptr_t hi);
    std::vector<Animation> find_in(std::uintptr_t lo, std::uintptr_t hi);
    // The scale time_scale() returns for the record in `slot` (set at creation and by
    // set_time_scale).
    void remember_scale(std::uint32_t slot, double scale) noexcept;
    double time_scale_of(std::uint32_t dense) const noexcept;
    // Custom writes begin here: follows a linked target (false: gone, killed), runs the first
    // play's start once, writes typed values (false: done). True: the caller writes as before.
    // A timeline that moves a child into its plays without write_state must call start_play.
    bool begin_write(std::uint32_t dense, Extra& e, double u);
    void start_play(std::uint32_t dense);
    double next_heading(const Path& path, double u, bool backward, Extra& e) const noexcept;
    // Pauses from on_loop: the record holds at the start of play `play` (plays since the first).
    void hold_at_play(std::uint32_t dense, double play);
    void index_insert(std::uint32_t dense);
    void index_erase(std::uint32_t dense) noexcept;

private:
    struct Span {  // bytes [lo, hi) as addresses; hi == 0: writes nothing
        std::uintptr_t lo = 0;
        std::uintptr_t hi = 0;
    };
    template <class F>
    void members_of(std::uint32_t dense, F&& f) const noexcept;  // f(address, bytes) per written member
    Span span_of(std::uint32_t dense) const noexcept;
    bool writes_in(std::uint32_t dense, std::uintptr_t lo, std::uintptr_t hi) const noexcept;
    template <class F>
    void for_each_in(std::uintptr_t lo, std::uintptr_t hi, F&& f);
    void enable_index();
    void refresh_linked();
    void overwrite_others(std::uint32_t dense);

    bool index_on_ = false;
    std::multimap<std::uintptr_t, std::uint32_t> by_address_;  // lowest written byte -> slot
    std::size_t widest_ = 0;                                 // widest written span indexed (bytes)
    std::unordered_set<std::uint32_t> linked_;               // slots of linked records

    // --- two-phase and parallel ticks (engine_parallel.cpp) ---
public:
    void set_parallel(int threads, std::size_t min_records, double awake);
    void set_serial();
    int threads() const noexcept { return two_phase_ ? threads_ : 0; }

private:
    // The common update of record i (see tick); false, with nothing changed, when the record
    // needs the general path. phase1: also leaves function curves (user code) to the general path.
    template <bool phase1>
    bool plain_step(Hot* hot, Cold* cold, const PathFast* fast, std::size_t i, double dt) const noexcept;
    template <bool phase1>
    bool plain_advance(Hot* hot, Cold* cold, std::size_t i, double dt, double& u) const noexcept;
    void plain_write(const Hot& h, const PathFast* fast, double u) const noexcept;
    std::size_t plain_run(std::size_t i, std::size_t n, double dt) noexcept;
    void advance_general(std::uint32_t dense, double dt);
    void plain_phase(double dt);
    void general_phase(double dt);
    std::size_t advance_plain(std::size_t begin, std::size_t end, double dt, std::uint32_t* slow) noexcept;
    static void plain_job(void* self) noexcept;

    bool two_phase_ = false;
    int threads_ = 1;
    std::size_t parallel_min_ = 0;           // fewer records: phase 1 on the calling thread alone
    std::vector<std::uint32_t> slow_;        // phase 1's records for phase 2, from each block's start
    std::vector<std::uint32_t> slow_count_;  // per block
    std::size_t block_ = 0;                  // this tick's records per block, blocks and records
    std::size_t blocks_ = 0;
    int slices_ = 1;  // this tick's: threads_ when shared, else 1
    std::size_t slice_begin(int s) const noexcept { return blocks_ * static_cast<std::size_t>(s) / static_cast<std::size_t>(slices_); }
    std::size_t plain_n_ = 0;
    double plain_dt_ = 0.0;
    // Phase 1's blocks fall into one slice per thread, each slice's taken in order through
    // its own counter (a cache line each): a thread takes its own slice's blocks, contiguous
    // records that its prefetchers stream, then helps with the others'.
    struct alignas(64) SliceCounter {
        std::atomic<std::size_t> next{0};
    };
    std::unique_ptr<SliceCounter[]> slice_next_;  // threads_ of them
    std::atomic<int> arrivals_{0};                // threads that joined this tick's phase 1
    std::unique_ptr<TickPool, TickPoolDelete> pool_;  // last: its workers stop before the rest goes
};

/// The high bit of Slot::dense marks a free slot (its low bits chain to the next free one).
inline constexpr std::uint32_t free_bit = 0x80000000u;

/// A play counts as finished within play_snap of its end (in plays).
inline constexpr double play_end = 1.0 - play_snap;

/// A whole number of plays as the engine's 32-bit play counter advances by it: modulo 2³²,
/// which keeps the parity yoyo needs (every double from 2⁵³ on, and +inf, counts as even).
inline std::uint64_t wrap_plays(double whole) noexcept {
    if (!(whole < 4611686018427387904.0)) return Cold::most_plays;  // ≥ 2⁶² (even) and +inf: held there
    return static_cast<std::uint64_t>(whole);
}

/// Throws grape::Error naming `where` for a bad duration or def.
void validate(std::string_view where, double duration, const AnimationDef& def);
/// Throws grape::Error naming `where` for a bad delay, repeat, repeat delay or time scale: the
/// play settings animations and timelines share.
void validate_plays(const std::string& where, double delay, int repeat, double repeat_delay, double time_scale);
/// A custom (general-path) hot record of `def` for `target`: rate, curve kind and flags.
Hot custom_hot(void* target, double duration, const AnimationDef& def) noexcept;

// Counts nested handler calls; removals wait until the outermost one has returned, so a
// handler can kill anything (itself included) without pulling storage from under a caller.
struct EngineImpl::Dispatch {
    EngineImpl& engine;
    explicit Dispatch(EngineImpl& e) noexcept : engine(e) { ++engine.depth_; }
    ~Dispatch() {
        if (--engine.depth_ == 0 && !engine.ticking_) engine.finish_dispatch();
    }
    Dispatch(const Dispatch&) = delete;
    Dispatch& operator=(const Dispatch&) = delete;
};

/// What a live Animation handle refers to; false when the handle is stale.
struct LiveRecord {
    EngineImpl* impl = nullptr;
    std::uint32_t dense = 0;
    explicit operator bool() const noexcept { return impl != nullptr; }
    Hot& hot() const noexcept { return impl->hot(dense); }
    const Cold& cold() const noexcept { return impl->cold(dense); }
};

}  // namespace grape::detail
