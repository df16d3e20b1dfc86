// The tick: the hot loop, the slow path for loops and completion, events; state queries.
#include "engine_impl.hpp"

#include <grape/error.hpp>
#include <grape/path_query.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "engine_eval.hpp"
#include "engine_lean_table.hpp"
#include "timeline_impl.hpp"

namespace grape::detail {

double EngineImpl::progress_of(std::uint32_t dense) const noexcept {
    const Hot& h = hot_[dense];
    const double phase = std::clamp(h.phase, 0.0, 1.0);
    return ease(curve_kind(h), cold_[dense].curve, (h.flags & flag_backward) ? 1.0 - phase : phase);
}

Vec2 EngineImpl::value_of(std::uint32_t dense) const noexcept {
    const Hot& h = hot_[dense];
    const double u = progress_of(dense);
    if (const Extra* e = (h.flags & flag_custom) ? extra(cold_[dense].slot) : nullptr) {
        const double at = along_range(*e, u);
        return e->offset == 0.0 ? point(h.path, at) : offset_point(paths_[h.path].path, at, e->offset);
    }
    return point(h.path, u);
}

double EngineImpl::heading_of(std::uint32_t dense) const noexcept {
    const Hot& h = hot_[dense];
    const Extra* e = extra(cold_[dense].slot);
    if (e && e->track_heading) return e->heading;
    const double u = progress_of(dense);
    const double angle = paths_[h.path].path.heading(e ? along_range(*e, u) : u);
    const bool backward = ((h.flags & flag_backward) != 0) != (e && e->range_end < e->range_start);
    return backward ? std::remainder(angle + pi, 2.0 * pi) : angle;
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
    if (!begin_write(dense, e, u)) return;  // linked targets, the first play's start, typed values
    if (e.p3) {
        write_3d(h, e, u);
        if (e.on_update) {
            const auto handler = e.on_update;
            Dispatch d(*this);
            (*handler)();
        }
        return;
    }
    if (e.nd) {
        e.nd->point(along_range(e, u), e.values);
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
        if (e.on_update) {
            const auto handler = e.on_update;
            Dispatch d(*this);
            (*handler)();
        }
        return;
    }
    const Path& path = paths_[h.path].path;
    const double at = along_range(e, u);
    const Vec2 p = e.offset == 0.0 ? point(h.path, at) : offset_point(path, at, e.offset);
    const bool backward = ((h.flags & flag_backward) != 0) != (e.range_end < e.range_start);
    e.heading = next_heading(path, at, backward, e);
    if (h.target) {
        write_2d(h, p);
        if (e.write_rotation) {
            char* at = h.target + e.rotation_offset;
            if (e.rotation_float) *reinterpret_cast<float*>(at) = static_cast<float>(e.heading);
            else *reinterpret_cast<double*>(at) = e.heading;
        }
    }
    if (e.on_update_2d) {
        const auto handler = e.on_update_2d;
        Dispatch d(*this);
        (*handler)(p, e.heading);
    }
    if (e.on_update) {
        const auto handler = e.on_update;
        Dispatch d(*this);
        (*handler)();
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

    if (two_phase_) {
        plain_phase(dt);    // engine_parallel.cpp
        general_phase(dt);
    } else {
        // Records created by handlers during this tick land past n and start on the next tick.
        const std::size_t n = driven_begin_;  // the records timelines drive lie beyond
        std::size_t i = 0;
        while (i < n) {
            // The common case runs in a tight loop (plain_run). Anything else (paused, dead,
            // custom writes, waiting, a play ending, nothing to write to) leaves it for the
            // general path, where handlers may run and grow the storage.
            i = plain_run(i, n, dt);
            if (i == n) break;
            advance_general(static_cast<std::uint32_t>(i), dt);
            ++i;
        }
    }

    if (timelines_) timelines_->tick(dt);

    if (!listeners_.empty()) {
        Dispatch d(*this);
        const std::size_t count = listeners_.size();
        for (std::size_t k = 0; k < count; ++k) {
            if (!listeners_[k].removed) listeners_[k].f(dt);  // the vector never grows here
        }
    }
}

// Records from i on while plain_step takes them; returns the first it does not (or n), with
// plain_step's results bit for bit. Runs of records that share a formula curve, a path
// kernel and a target type go to their lean run (engine_lean.hpp), and the record that ends
// a run (a play ending, a waiting record) to plain_step alone. The records no lean run
// takes go in batches of 32: every record of a batch is advanced, and its arc-length piece
// found and asked for, before any is written, so that the misses on shared tables overlap
// instead of stalling each record in turn (nothing but the batch's own records sees the
// order). Flattened so that the easing switch and the path formulas are inlined (compilers
// otherwise call curve.hpp's ease_formula out of line, a fifth of the loop's time).
GRAPE_FLATTEN std::size_t EngineImpl::plain_run(std::size_t i, std::size_t n, double dt) noexcept {
    Hot* const hot = hot_.data();
    Cold* const cold = cold_.data();
    const PathFast* const fast = path_fast_.data();
    const LeanTables tables{line_fast_.data(), fast, arc_fast_.data(), cold, wide_lanes()};
    constexpr std::size_t batch = 32;
    double u[batch];
    ArcLengthTable::Piece piece[batch];
    while (i < n) {
        if (const LeanRun run = lean_for(hot[i], tables)) {
            i = run(hot, tables, i, n, dt);
            if (i == n) break;
            if (!plain_step<false>(hot, cold, fast, i, dt)) break;
            ++i;
            continue;
        }
        const std::size_t m = std::min(batch, n - i);
        std::size_t k = 0;
        bool general = false;  // record i + k needs the general path
        for (; k < m && !lean_for(hot[i + k], tables); ++k) {
            ask_hot_ahead(hot, i + k, n);
            if (!plain_advance<false>(hot, cold, i + k, dt, u[k])) {
                general = true;
                break;
            }
            piece[k] = plain_piece(hot[i + k], fast, u[k]);
        }
        for (std::size_t j = 0; j < k; ++j) {
            if (piece[j].c) write_2d(hot[i + j], ArcLengthTable::evaluate_piece(piece[j].c, piece[j].x));
            else plain_write(hot[i + j], fast, u[j]);
        }
        i += k;
        if (general) break;
    }
    return i;
}

// One record's update outside the common case (paused and dead records stay as they are).
void EngineImpl::advance_general(std::uint32_t dense, double dt) {
    Hot& h = hot_[dense];
    if (h.flags & (flag_paused | flag_dead)) return;
    const double phase = h.phase + dt * h.rate;
    if (h.rate < 0.0) advance_back(dense, phase);
    else if (phase < 0.0) h.phase = phase;  // still waiting: nothing to write
    else advance_slow(dense, phase);
}

// Loops, completion, waiting custom records and custom writes. The plays crossed come from
// the timing model, counted from the current play (whose direction stands for `reversed`).
void EngineImpl::advance_slow(std::uint32_t dense, double phase) {
    Hot& h = hot_[dense];
    Cold& c = cold_[dense];
    const bool starts = h.phase < 0.0 && (h.flags & flag_listens);  // the first play begins now
    double loops = 0.0;
    bool completes = false;
    const std::uint64_t first_play = c.play();
    if (phase >= play_end) {
        const double plays_left = c.plays() == 0 ? 0.0 : static_cast<double>(c.plays() - c.play());
        const PlayState s = play_at_position(phase, plays_left, (h.flags & flag_backward) != 0, (h.flags & flag_yoyo) != 0,
                                             gap_of(dense));
        loops = s.play;
        completes = s.finished;
        c.set_play(completes ? c.plays() - 1 : c.play() + wrap_plays(s.play));
        phase = s.phase + s.gap;  // inside a repeat delay the phase runs past 1 (clamped when drawn)
        h.flags = play_flags(h.flags, s.backward, c);
    }
    h.phase = phase;
    write_state(dense);
    if (starts && !fire_simple(dense, &Extra::on_start)) return;  // changed by its handler
    if (loops > 0.0 || completes) fire_events(dense, first_play, loops, completes);
}

// Running backwards (reverse() at run time): back through earlier plays to the first one's
// start, which fires on_reverse_complete and holds there. No loop events going back.
void EngineImpl::advance_back(std::uint32_t dense, double phase) {
    Hot& h = hot_[dense];
    Cold& c = cold_[dense];
    if (h.phase < 0.0) return;  // reversed inside its delay: it waits
    // Landing exactly on the first play's start is reaching it (below), not a phase of 0.
    if (phase > 0.0 || (phase == 0.0 && c.play() != 0)) {
        h.phase = phase;
        write_state(dense);
        return;
    }
    const double gap = gap_of(dense);
    const double position = static_cast<double>(c.play()) * (1.0 + gap) + phase;  // from the first play's start
    const bool was_at_start = c.play() == 0 && h.phase == 0.0;
    if (position <= 0.0) {
        c.set_play(0);
        h.phase = 0.0;
        h.flags = play_flags(h.flags, c.reversed, c);
        if (was_at_start) return;
        write_state(dense);
        if (h.flags & flag_listens) fire_simple(dense, &Extra::on_reverse_complete);
        return;
    }
    const PlayState s = play_at_position(position, static_cast<double>(c.plays()), c.reversed,
                                         (h.flags & flag_yoyo) != 0, gap);
    c.set_play(wrap_plays(s.play));
    h.phase = s.phase + s.gap;
    h.flags = play_flags(h.flags, s.backward, c);
    write_state(dense);
}

// One handler without arguments from the record's Extra; false if the handler changed the
// record's state (seek, kill, restart), as fire_events judges it.
bool EngineImpl::fire_simple(std::uint32_t dense, std::shared_ptr<const std::function<void()>> Extra::*member) {
    const std::uint32_t slot = cold_[dense].slot;
    const auto it = extras_.find(slot);
    if (it == extras_.end() || !(it->second.*member)) return true;
    const std::uint32_t generation = slots_[slot].generation;
    const std::uint64_t play = cold_[dense].play();
    const double phase = hot_[dense].phase;
    const auto handler = it->second.*member;
    {
        Dispatch d(*this);
        (*handler)();
    }
    const Hot& h = hot_[dense];
    return slots_[slot].generation == generation && cold_[dense].play() == play && h.phase == phase && !(h.flags & flag_dead);
}

void EngineImpl::fire_events(std::uint32_t dense, std::uint64_t first_play, double loops, bool completes) {
    if (hot_[dense].flags & flag_dead) return;  // a linked target that went during the write
    const std::uint32_t slot = cold_[dense].slot;
    const std::uint32_t generation = slots_[slot].generation;
    // The state every handler should find; a handler that seeks, kills or restarts this
    // animation changes it, and then the remaining events of this update are dropped.
    const std::uint64_t play = cold_[dense].play();
    const double phase = hot_[dense].phase;
    auto unchanged = [&] {
        const Hot& h = hot_[dense];
        return slots_[slot].generation == generation && cold_[dense].play() == play && h.phase == phase &&
               !(h.flags & flag_dead);
    };
    // Paused by its own loop handler: hold at the start of that play, no further events.
    auto paused_at = [&](double k) {
        if (!unchanged() || !(hot_[dense].flags & flag_paused)) return false;
        hold_at_play(dense, static_cast<double>(first_play) + k);
        return true;
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
                    if (paused_at(k) || !unchanged()) return;
                }
            } else {  // bounded work: one event for the last play, counting the skipped ones
                const double skipped = loops - 1.0;
                (*handler)(play_number(loops), skipped < 1.8446744073709552e19 ? static_cast<std::uint64_t>(skipped)
                                                                               : UINT64_MAX);
                if (paused_at(loops) || !unchanged()) return;
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

}  // namespace grape::detail
