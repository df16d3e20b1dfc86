// The engine: creation and validation, the tick's hot loop, events, handles.
#include "engine_impl.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

namespace grape {

namespace detail {

namespace {

constexpr std::uint32_t free_bit = 0x80000000u;

// A play counts as finished within this much of its end (in plays): summed frame times
// such as 60 × 1/60 fall short of 1 by a few ulp, and must still complete on that frame.
constexpr double snap = 1e-9;
constexpr double play_end = 1.0 - snap;

using detail::number_text;

// A whole number of plays as the engine's 32-bit play counter advances by it: modulo 2³²,
// which keeps the parity yoyo needs (every double from 2⁵³ on, and +inf, counts as even).
std::uint32_t wrap_plays(double whole) noexcept {
    if (!(whole < 1.8446744073709552e19)) return 0;  // ≥ 2⁶⁴ (multiples of 2³²) and +inf
    return static_cast<std::uint32_t>(std::fmod(whole, 4294967296.0));
}

void validate(std::string_view where, double duration, const AnimationDef& def) {
    const std::string w(where);
    if (!(std::isfinite(duration) && duration > 0.0))
        throw Error(w + ": duration must be positive and finite (got " + number_text(duration) + ")");
    if (!std::isfinite(1.0 / duration))
        throw Error(w + ": duration is too small: 1 / duration overflows (got " + number_text(duration) + ")");
    if (!(std::isfinite(def.delay) && def.delay >= 0.0))
        throw Error(w + ": delay must be >= 0 and finite (got " + number_text(def.delay) + ")");
    if (def.repeat < -1)
        throw Error(w + ": repeat must be >= 0, or -1 for forever (got " + std::to_string(def.repeat) + ")");
    if (!(std::isfinite(def.time_scale) && def.time_scale >= 0.0))
        throw Error(w + ": time_scale must be >= 0 and finite (got " + number_text(def.time_scale) + ")");
    // The record keeps plays per second and the delay in plays; both, and the end of the last
    // play in seconds, must be numbers.
    if (!std::isfinite(def.time_scale / duration))
        throw Error(w + ": time_scale / duration overflows (time_scale " + number_text(def.time_scale) +
                    ", duration " + number_text(duration) + ")");
    if (!std::isfinite(def.delay / duration))
        throw Error(w + ": delay / duration overflows (delay " + number_text(def.delay) + ", duration " +
                    number_text(duration) + ")");
    if (def.repeat >= 0 && !std::isfinite(def.delay + duration * (static_cast<double>(def.repeat) + 1.0)))
        throw Error(w + ": delay + duration · (repeat + 1) overflows (delay " + number_text(def.delay) +
                    ", duration " + number_text(duration) + ", repeat " + std::to_string(def.repeat) + ")");
}

}  // namespace

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

// --- tables ----------------------------------------------------------------------------------

std::uint32_t EngineImpl::acquire_path(const Path& path) {
    const void* shape = shape_id(path);
    if (auto it = path_index_.find(shape); it != path_index_.end()) {
        ++paths_[it->second].refs;
        return it->second;
    }
    PathEntry entry;
    entry.path = path;
    entry.shape = shape;
    entry.kernel = make_kernel(path);
    entry.refs = 1;
    PathFast fast;
    fast.fast = entry.kernel.kind;
    for (int k = 0; k < 4; ++k) fast.c[k] = entry.kernel.c[k];
    if (entry.kernel.table) {  // the table's buffer survives moving the entry
        fast.table = entry.kernel.table->values().data();
        fast.steps = entry.kernel.table->steps();
    }
    std::uint32_t index;
    if (!free_paths_.empty()) {
        index = free_paths_.back();
        free_paths_.pop_back();
        paths_[index] = std::move(entry);
        path_fast_[index] = fast;
    } else {
        index = static_cast<std::uint32_t>(paths_.size());
        paths_.push_back(std::move(entry));
        path_fast_.push_back(fast);
        free_paths_.reserve(paths_.size());  // so releasing during a tick never allocates
    }
    path_index_.emplace(shape, index);
    return index;
}

void EngineImpl::release_path(std::uint32_t index) noexcept {
    PathEntry& e = paths_[index];
    if (--e.refs != 0) return;
    path_index_.erase(e.shape);
    e = PathEntry();                // drops the shape if nobody else holds it
    path_fast_[index] = PathFast();
    free_paths_.push_back(index);   // capacity reserved at creation
}

std::uint16_t EngineImpl::acquire_curve(const Curve& curve) {
    std::string key = to_string(curve);
    if (auto it = curve_index_.find(key); it != curve_index_.end()) {
        ++curves_[it->second].refs;
        return it->second;
    }
    std::uint16_t index;
    if (!free_curves_.empty()) {
        index = free_curves_.back();
        free_curves_.pop_back();
        curves_[index] = {curve, 1, {}};
    } else {
        if (curves_.size() > std::numeric_limits<std::uint16_t>::max())
            throw Error("Engine: more than 65535 distinct curves with parameters alive at once");
        index = static_cast<std::uint16_t>(curves_.size());
        curves_.push_back({curve, 1, {}});
        free_curves_.reserve(curves_.size());  // so releasing during a tick never allocates
    }
    curves_[index].key = key;
    curve_index_.emplace(std::move(key), index);
    return index;
}

std::uint16_t EngineImpl::acquire_curve_for(std::uint32_t path, const Curve& curve) {
    if (!has_parameters(curve.kind())) return 0;  // evaluated by kind, no slot needed
    try {
        return acquire_curve(curve);
    } catch (...) {
        release_path(path);
        throw;
    }
}

void EngineImpl::release_curve(std::uint16_t index) noexcept {
    if (index == 0) return;
    CurveEntry& e = curves_[index];
    if (--e.refs != 0) return;
    curve_index_.erase(e.key);
    free_curves_.push_back(index);  // capacity reserved at creation
    e.curve = Curve();
    e.key.clear();
}

// --- evaluation ------------------------------------------------------------------------------

// The curve of a record: parameter-free kinds by curve.hpp's inline formula, the others
// through their Curve in the table.
inline double EngineImpl::ease(CurveKind kind, std::uint16_t curve, double x) const noexcept {
    return has_parameters(kind) ? curves_[curve].curve(x) : detail::ease_formula(kind, x);
}

// The kernel's formulas on copied coefficients (Path::point bit for bit for lines and cubics).
inline Vec2 EngineImpl::point(std::uint32_t path, double u) const noexcept {
    if (u >= 0.0 && u <= 1.0) {
        const PathFast& f = path_fast_[path];
        switch (f.fast) {
            case KernelKind::linear: return f.c[0] + f.c[1] * u;
            case KernelKind::cubic: return ((f.c[3] * u + f.c[2]) * u + f.c[1]) * u + f.c[0];
            case KernelKind::reparam_cubic: {
                const double v = ArcLengthTable::evaluate(f.table, f.steps, u);
                return ((f.c[3] * v + f.c[2]) * v + f.c[1]) * v + f.c[0];
            }
            case KernelKind::reparam_linear: return f.c[0] + f.c[1] * ArcLengthTable::evaluate(f.table, f.steps, u);
            case KernelKind::generic: break;
        }
    }
    return paths_[path].path.point(u);  // other kinds, and outside [0, 1] along the end tangents
}

inline void EngineImpl::write_2d(const Hot& h, Vec2 p) const noexcept {
    char* x = h.target;
    if (h.flags & flag_float) {
        *reinterpret_cast<float*>(x) = static_cast<float>(p.x);
        *reinterpret_cast<float*>(x + h.y_offset) = static_cast<float>(p.y);
    } else {
        *reinterpret_cast<double*>(x) = p.x;
        *reinterpret_cast<double*>(x + h.y_offset) = p.y;
    }
}

double EngineImpl::progress_of(std::uint32_t dense) const noexcept {
    const Hot& h = hot_[dense];
    const double phase = std::clamp(h.phase, 0.0, 1.0);
    return ease(h.kind, cold_[dense].curve, (h.flags & flag_backward) ? 1.0 - phase : phase);
}

Vec2 EngineImpl::value_of(std::uint32_t dense) const noexcept { return point(hot_[dense].path, progress_of(dense)); }

double EngineImpl::heading_of(std::uint32_t dense) const noexcept {
    const Hot& h = hot_[dense];
    if (const Extra* e = extra(cold_[dense].slot); e && e->track_heading) return e->heading;
    const double angle = paths_[h.path].path.heading(progress_of(dense));
    return (h.flags & flag_backward) ? std::remainder(angle + pi, 2.0 * pi) : angle;
}

// The state at the record's time, written to wherever it goes. Handlers may run.
void EngineImpl::write_state(std::uint32_t dense) {
    const Hot& h = hot_[dense];
    if (h.phase < 0.0) return;  // waiting: nothing is written until the first play starts
    const double u = progress_of(dense);
    if (!(h.flags & flag_custom)) {
        if (h.target) write_2d(h, point(h.path, u));
        return;
    }
    Extra& e = extras_.find(cold_[dense].slot)->second;  // node-based: stable while handlers run
    if (e.nd) {
        e.nd->point(u, e.values);
        char* base = h.target;
        if (base) {
            for (std::size_t k = 0; k < e.members.size(); ++k) {
                if (e.members[k].is_float) *reinterpret_cast<float*>(base + e.members[k].offset) = static_cast<float>(e.values[k]);
                else *reinterpret_cast<double*>(base + e.members[k].offset) = e.values[k];
            }
        }
        if (e.on_update_nd) {
            const auto handler = e.on_update_nd;
            Dispatch d(*this);
            (*handler)(e.values);
        }
        return;
    }
    const Path& path = paths_[h.path].path;
    const Vec2 p = point(h.path, u);
    const double angle = path.heading(u);
    e.heading = (h.flags & flag_backward) ? std::remainder(angle + pi, 2.0 * pi) : angle;
    if (h.target) {
        write_2d(h, p);
        if (e.write_rotation) {
            char* at = h.target + e.rotation_offset;
            if (h.flags & flag_float) *reinterpret_cast<float*>(at) = static_cast<float>(e.heading);
            else *reinterpret_cast<double*>(at) = e.heading;
        }
    }
    if (e.on_update_2d) {
        const auto handler = e.on_update_2d;
        Dispatch d(*this);
        (*handler)(p, e.heading);
    }
}

// --- the tick --------------------------------------------------------------------------------

void EngineImpl::tick(double dt) {
    if (!(std::isfinite(dt) && dt >= 0.0))
        throw Error("Engine::tick: dt must be finite and >= 0 (got " + number_text(dt) + ")");
    if (ticking_ || depth_ > 0) throw Error("Engine::tick: called from inside one of the engine's own handlers");
    struct Ticking {
        EngineImpl& e;
        explicit Ticking(EngineImpl& engine) noexcept : e(engine) { e.ticking_ = true; }
        ~Ticking() {
            e.ticking_ = false;
            e.finish_dispatch();
        }
    } ticking(*this);

    // Records created by handlers during this tick land past n and start on the next tick.
    const std::size_t n = hot_.size();
    std::size_t i = 0;
    while (i < n) {
        // The common case runs in a tight loop over local pointers. Anything else (paused,
        // dead, custom writes, waiting, a play ending, nothing to write to) leaves the loop
        // for the general path, after which the pointers are reloaded: handlers may have
        // grown the storage.
        Hot* const hot = hot_.data();
        Cold* const cold = cold_.data();
        const PathFast* const fast = path_fast_.data();
        for (; i < n; ++i) {
            Hot& h = hot[i];
            double phase = h.phase + dt * h.rate;
            if ((h.flags & (flag_paused | flag_dead | flag_custom)) || !(phase >= 0.0) || !h.target) break;
            if (phase >= play_end) {
                // A new play that nobody listens for, reached within this tick: handled here.
                Cold& c = cold[i];
                if ((h.flags & flag_listens) || phase >= 2.0 - snap || (c.plays != 0 && c.play + 1 >= c.plays)) break;
                ++c.play;
                phase = std::max(phase - 1.0, 0.0);
                if (h.flags & flag_yoyo) h.flags ^= flag_backward;
            }
            h.phase = phase;
            const double x = (h.flags & flag_backward) ? 1.0 - phase : phase;
            const double u = has_parameters(h.kind) ? curves_[cold[i].curve].curve(x) : detail::ease_formula(h.kind, x);
            const PathFast& f = fast[h.path];
            Vec2 p;
            if (f.fast == KernelKind::linear && u >= 0.0 && u <= 1.0) p = f.c[0] + f.c[1] * u;
            else if (f.fast == KernelKind::cubic && u >= 0.0 && u <= 1.0) p = ((f.c[3] * u + f.c[2]) * u + f.c[1]) * u + f.c[0];
            else p = point(h.path, u);
            write_2d(h, p);
        }
        if (i == n) break;
        Hot& h = hot_[i];
        if (!(h.flags & (flag_paused | flag_dead))) {
            const double phase = h.phase + dt * h.rate;
            if (phase < 0.0) h.phase = phase;  // still waiting: nothing to write
            else advance_slow(static_cast<std::uint32_t>(i), phase);
        }
        ++i;
    }

    if (!listeners_.empty()) {
        Dispatch d(*this);
        const std::size_t count = listeners_.size();
        for (std::size_t k = 0; k < count; ++k) {
            if (!listeners_[k].removed) listeners_[k].f(dt);  // the vector never grows here
        }
    }
}

// Loops, completion, waiting custom records and custom writes. The plays crossed come from
// the timing model, counted from the current play (whose direction stands for `reversed`).
void EngineImpl::advance_slow(std::uint32_t dense, double phase) {
    Hot& h = hot_[dense];
    Cold& c = cold_[dense];
    double loops = 0.0;
    bool completes = false;
    const std::uint32_t first_play = c.play;
    if (phase >= play_end) {
        const double plays_left = c.plays == 0 ? 0.0 : static_cast<double>(c.plays - c.play);
        const PlayState s = play_at_position(phase, plays_left, (h.flags & flag_backward) != 0, (h.flags & flag_yoyo) != 0);
        loops = s.play;
        completes = s.finished;
        c.play = completes ? c.plays - 1 : c.play + wrap_plays(s.play);
        phase = s.phase;
        h.flags = static_cast<std::uint8_t>(s.backward ? (h.flags | flag_backward) : (h.flags & ~flag_backward));
    }
    h.phase = phase;
    write_state(dense);
    if (loops > 0.0 || completes) fire_events(dense, first_play, loops, completes);
}

void EngineImpl::fire_events(std::uint32_t dense, std::uint32_t first_play, double loops, bool completes) {
    const std::uint32_t slot = cold_[dense].slot;
    const std::uint32_t generation = slots_[slot].generation;
    // The state every handler should find; a handler that seeks, kills or restarts this
    // animation changes it, and then the remaining events of this update are dropped.
    const std::uint32_t play = cold_[dense].play;
    const double phase = hot_[dense].phase;
    auto unchanged = [&] {
        const Hot& h = hot_[dense];
        return slots_[slot].generation == generation && cold_[dense].play == play && h.phase == phase &&
               !(h.flags & flag_dead);
    };
    auto play_number = [first_play](double k) {  // play first_play + k as on_loop reports it
        return static_cast<int>(std::min(static_cast<double>(first_play) + k, static_cast<double>(INT32_MAX)));
    };
    if (hot_[dense].flags & flag_listens) {
        Extra& e = extras_.find(slot)->second;
        if (loops > 0.0 && e.on_loop) {
            const auto handler = e.on_loop;
            Dispatch d(*this);
            if (loops <= max_loop_events) {
                for (int k = 1; k <= static_cast<int>(loops); ++k) {
                    (*handler)(play_number(k), 0);
                    if (!unchanged()) return;
                }
            } else {  // bounded work: one event for the last play, counting the skipped ones
                const double skipped = loops - 1.0;
                (*handler)(play_number(loops), skipped < 1.8446744073709552e19 ? static_cast<std::uint64_t>(skipped)
                                                                               : UINT64_MAX);
                if (!unchanged()) return;
            }
        }
        if (completes && e.on_complete) {
            const auto handler = e.on_complete;
            Dispatch d(*this);
            try {
                (*handler)();
            } catch (...) {
                if (unchanged()) mark_dead(dense);  // completed all the same: no second completion
                throw;
            }
            if (!unchanged()) return;  // restarted (or killed) by its own handler
        }
    }
    if (completes) mark_dead(dense);
}

// --- creation --------------------------------------------------------------------------------

Animation EngineImpl::add(Hot hot, std::uint16_t curve, double duration, int repeat, double delay,
                          std::optional<Extra> extra) {
    std::uint32_t slot;
    if (free_slot_ != UINT32_MAX) {
        slot = free_slot_;
        free_slot_ = slots_[slot].dense & ~free_bit;
        if (free_slot_ == (UINT32_MAX & ~free_bit)) free_slot_ = UINT32_MAX;
    } else {
        if (slots_.size() >= free_bit) throw Error("Engine: too many animations (2^31)");
        slot = static_cast<std::uint32_t>(slots_.size());
        slots_.push_back({0, 0});
    }
    const auto dense = static_cast<std::uint32_t>(hot_.size());
    hot.phase = delay > 0.0 ? -delay / duration : 0.0;
    if (hot.flags & flag_reversed) hot.flags |= flag_backward;
    hot_.push_back(hot);
    cold_.push_back({duration, repeat < 0 ? 0u : static_cast<std::uint32_t>(repeat) + 1u, slot, 0, curve});
    slots_[slot].dense = dense;
    if (extra) extras_.insert_or_assign(slot, std::move(*extra));
    ++live_;
    const Animation handle(owner_, slot, slots_[slot].generation);
    {
        Dispatch d(*this);
        write_state(dense);  // the start state, unless a delay holds it back
    }
    return handle;
}

Animation EngineImpl::create(void* target, std::size_t x_offset, std::size_t y_offset, bool is_float,
                             std::ptrdiff_t rotation_offset, const Path& path, double duration,
                             const AnimationDef& def, std::function<void(Vec2, double)> on_update) {
    validate(target ? "create_2d_animation" : "create_animation", duration, def);
    const auto y_from_x = static_cast<std::ptrdiff_t>(y_offset) - static_cast<std::ptrdiff_t>(x_offset);
    if (y_from_x < -32768 || y_from_x > 32767)
        throw Error("create_2d_animation: target.x and target.y must lie within 32 KiB of each other (got " +
                    std::to_string(y_from_x) + " bytes apart)");
    Hot h{};
    h.rate = def.time_scale / duration;
    h.target = target ? static_cast<char*>(target) + x_offset : nullptr;
    h.y_offset = static_cast<std::int16_t>(y_from_x);
    h.kind = def.curve.kind();
    h.flags = static_cast<std::uint8_t>((is_float ? flag_float : 0) | (def.paused ? flag_paused : 0) |
                                        (def.yoyo ? flag_yoyo : 0) | (def.reversed ? flag_reversed : 0));
    std::optional<Extra> extra;
    if (def.heading || on_update) {
        extra.emplace();
        extra->track_heading = def.heading;
        extra->write_rotation = target && rotation_offset >= 0;
        extra->rotation_offset = rotation_offset - static_cast<std::ptrdiff_t>(x_offset);
        if (on_update) extra->on_update_2d = std::make_shared<const std::function<void(Vec2, double)>>(std::move(on_update));
        h.flags |= flag_custom;
    }
    h.path = acquire_path(path);
    const std::uint16_t curve = acquire_curve_for(h.path, def.curve);
    return add(h, curve, duration, def.repeat, def.delay, std::move(extra));
}

Animation EngineImpl::create_nd(void* target, std::vector<MemberRef> members, PathND path, double duration,
                                const AnimationDef& def, std::function<void(std::span<const double>)> on_update) {
    const char* where = target ? "create_property_animation" : "create_animation";
    validate(where, duration, def);
    if (target && members.size() != path.dimension())
        throw Error(std::string(where) + ": members and values must match (" + std::to_string(members.size()) +
                    " members, " + std::to_string(path.dimension()) + " values)");
    Hot h{};
    h.rate = def.time_scale / duration;
    h.target = static_cast<char*>(target);
    h.kind = def.curve.kind();
    h.flags = static_cast<std::uint8_t>(flag_custom | (def.paused ? flag_paused : 0) | (def.yoyo ? flag_yoyo : 0) |
                                        (def.reversed ? flag_reversed : 0));
    Extra extra;
    extra.values.assign(path.dimension(), 0.0);
    path.point(def.reversed ? 1.0 : 0.0, extra.values);  // the start values, readable while waiting
    extra.nd.emplace(std::move(path));
    extra.members = std::move(members);
    if (on_update)
        extra.on_update_nd = std::make_shared<const std::function<void(std::span<const double>)>>(std::move(on_update));
    h.path = acquire_path(Path());  // shared placeholder: N-D values come from the Extra
    const std::uint16_t curve = acquire_curve_for(h.path, def.curve);
    return add(h, curve, duration, def.repeat, def.delay, std::move(extra));
}

// --- handles ---------------------------------------------------------------------------------

const Hot* EngineImpl::find(std::uint32_t slot, std::uint32_t generation) const noexcept {
    if (slot >= slots_.size()) return nullptr;
    const Slot& s = slots_[slot];
    if (s.generation != generation || (s.dense & free_bit)) return nullptr;
    return &hot_[s.dense];
}

const Extra* EngineImpl::extra(std::uint32_t slot) const noexcept {
    const auto it = extras_.find(slot);
    return it == extras_.end() ? nullptr : &it->second;
}

Extra& EngineImpl::extra_for(std::uint32_t slot) { return extras_[slot]; }

void EngineImpl::seek(std::uint32_t dense, double seconds) noexcept {
    if (!std::isfinite(seconds)) return;
    Hot& h = hot_[dense];
    Cold& c = cold_[dense];
    const PlayState s = play_at_position(seconds / c.duration, static_cast<double>(c.plays),
                                         (h.flags & flag_reversed) != 0, (h.flags & flag_yoyo) != 0);
    c.play = s.finished ? c.plays - 1 : wrap_plays(s.play);
    h.phase = s.phase;
    h.flags = static_cast<std::uint8_t>(s.backward ? (h.flags | flag_backward) : (h.flags & ~flag_backward));
    try {
        Dispatch d(*this);
        write_state(dense);
    } catch (...) {  // a throwing on_update handler: the state is set; the error is dropped
    }
}

void EngineImpl::set_time_scale(std::uint32_t dense, double scale) noexcept {
    if (!(std::isfinite(scale) && scale >= 0.0)) return;
    const double rate = scale / cold_[dense].duration;
    if (std::isfinite(rate)) hot_[dense].rate = rate;  // an overflowing rate is ignored too
}

void EngineImpl::mark_dead(std::uint32_t dense) noexcept {
    Hot& h = hot_[dense];
    if (h.flags & flag_dead) return;
    h.flags |= flag_dead;
    ++slots_[cold_[dense].slot].generation;  // handles go inert now; storage goes later
    --live_;
    ++dead_;
}

void EngineImpl::kill(std::uint32_t dense) noexcept {
    mark_dead(dense);
    if (!ticking_ && depth_ == 0) finish_dispatch();
}

void EngineImpl::kill_all() noexcept {
    for (std::uint32_t i = 0; i < hot_.size(); ++i) mark_dead(i);
    if (!ticking_ && depth_ == 0) finish_dispatch();
}

void EngineImpl::remove_now(std::uint32_t dense) noexcept {
    const std::uint32_t slot = cold_[dense].slot;
    release_path(hot_[dense].path);
    release_curve(cold_[dense].curve);
    extras_.erase(slot);
    slots_[slot].dense = free_bit | (free_slot_ & ~free_bit);
    free_slot_ = slot;
    const auto last = static_cast<std::uint32_t>(hot_.size() - 1);
    if (dense != last) {
        hot_[dense] = hot_[last];
        cold_[dense] = cold_[last];
        slots_[cold_[dense].slot].dense = dense;
    }
    hot_.pop_back();
    cold_.pop_back();
}

void EngineImpl::compact() noexcept {
    for (std::uint32_t i = 0; i < hot_.size() && dead_ > 0;) {
        if (hot_[i].flags & flag_dead) {
            remove_now(i);  // the last record moves into i; look at i again
            --dead_;
        } else {
            ++i;
        }
    }
    dead_ = 0;
}

void EngineImpl::finish_dispatch() noexcept {
    if (dead_ > 0) compact();
    if (listeners_removed_) {
        std::erase_if(listeners_, [](const Listener& l) { return l.removed; });
        std::erase_if(new_listeners_, [](const Listener& l) { return l.removed; });
        listeners_removed_ = false;
    }
    if (!new_listeners_.empty()) {
        try {
            for (Listener& l : new_listeners_) listeners_.push_back(std::move(l));
        } catch (...) {  // out of memory: listeners not yet joined are dropped
        }
        new_listeners_.clear();
    }
}

std::size_t EngineImpl::on_tick(std::function<void(double)> listener) {
    const std::size_t id = next_listener_++;
    if (ticking_ || depth_ > 0) new_listeners_.push_back({id, std::move(listener)});
    else listeners_.push_back({id, std::move(listener)});
    return id;
}

void EngineImpl::remove_tick_listener(std::size_t id) noexcept {
    for (auto* list : {&listeners_, &new_listeners_}) {
        for (Listener& l : *list) {
            if (l.id == id && !l.removed) {
                l.removed = true;  // not called again; erased once no listener is running
                listeners_removed_ = true;
                if (!ticking_ && depth_ == 0) finish_dispatch();
                return;
            }
        }
    }
}

std::size_t EngineImpl::storage_bytes() const noexcept {
    return hot_.capacity() * sizeof(Hot) + cold_.capacity() * sizeof(Cold) + slots_.capacity() * sizeof(Slot);
}

}  // namespace detail

// --- Engine and Animation: thin forwarding ---------------------------------------------------

Engine::Engine() : impl_(std::make_unique<detail::EngineImpl>(this)) {}
Engine::~Engine() = default;

void Engine::tick(double dt) { impl_->tick(dt); }

Animation Engine::create_bound_2d(void* target, std::size_t x_offset, std::size_t y_offset, bool is_float,
                                  std::ptrdiff_t rotation_offset, const Path& path, double duration,
                                  const AnimationDef& def) {
    return impl_->create(target, x_offset, y_offset, is_float, rotation_offset, path, duration, def, {});
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
    if (const detail::Extra* e = impl.extra(slot_); e && e->nd) return {};
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
    return (static_cast<double>(impl.cold(dense).play) + found->phase) * impl.cold(dense).duration;
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
    return found->rate * impl.cold(dense).duration;
}

void Animation::pause() const noexcept {
    GRAPE_FIND();
    impl.hot(dense).flags |= detail::flag_paused;
}

void Animation::resume() const noexcept {
    GRAPE_FIND();
    impl.hot(dense).flags &= static_cast<std::uint8_t>(~detail::flag_paused);
}

void Animation::seek(double seconds) const noexcept {
    GRAPE_FIND();
    impl.seek(dense, seconds);
}

void Animation::set_time_scale(double scale) const noexcept {
    GRAPE_FIND();
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
