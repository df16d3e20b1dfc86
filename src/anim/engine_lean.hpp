// The lean lane of the tick: runs of records in the middle of a play, sharing one formula
// curve kind on lines, cubics or arc-length paths, each run in a loop compiled for its
// (curve, path, target type).
#pragma once

#include "engine_eval.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace grape::detail {

// The shared path tables the lean lane reads.
struct LeanTables {
    const LineFast* line;    // per path
    const PathFast* fast;
    const ArcFast* arc;
    Cold* cold;              // per record
    bool wide;               // wide_lanes()
};

// A play ends for about one record in a hundred per tick. The plays that another follows,
// with nobody listening, begin the next inside the run (lean_loop, arc_advance); the rest
// (last plays, listeners) leave it for the general update, which reads their Cold record, a
// cache miss. The runs on lines and cubics do not ask for that record ahead: the test of a
// play ending ahead read hot records asked for only shortly before, and that wait cost more
// than the misses it saved (a sixth of the linear run at 10⁶); the arc-length runs, whose
// records take longer, do (engine_lean_arc.hpp). The hot records are read in order, but each
// costs tens of instructions, so the reorder window holds fewer of their misses than a plain
// copy loop's: asked for `hot_ahead` records (8 KB) early, beyond what the demand loads
// reach. (Measured at 10⁶, 6 alternating rounds, with Cold records asked for 160 ahead:
// 160/256 against 64/128, lines 2.24 → 2.13 ns and cubics 2.73 → 2.61 ns, faster in every
// round; 256/384 no better than 160/256.)
inline constexpr std::size_t hot_ahead = 256;
// Asks for the cache line at p, to be written: a hint, no effect on results.
inline void ask_line(const void* p) noexcept { prefetch_write(p); }
// Record j's hot or Cold record (j < n: the caller's bound).
inline void ask_hot(const Hot* hot, std::size_t j) noexcept { ask_line(hot + j); }
inline void ask_cold(const Cold* cold, std::size_t j) noexcept { ask_line(cold + j); }
inline void ask_hot_ahead(const Hot* hot, std::size_t i, std::size_t n) noexcept {
    if (i + hot_ahead < n) ask_hot(hot, i + hot_ahead);
}

// A record's kind byte (curve kind and lane kernel) and flags as one 16-bit word (the kind
// byte low), so that one compare checks the curve, the path, the target and every flag a run
// depends on.
// (kind and flags are adjacent: compilers read them as one word)
inline std::uint16_t kind_and_flags(const Hot& h) noexcept {
    return static_cast<std::uint16_t>(static_cast<unsigned>(h.kind) | (static_cast<unsigned>(h.flags) << 8));
}
// The flags a run needs as it started: not paused, dead or custom, and the target's type.
inline constexpr std::uint16_t lean_mask = 0xFF | (flag_paused | flag_dead | flag_custom | flag_float) << 8;

// The formula kinds whose value stays in [0, 1] for x in [0, 1], so that the run needs no
// test for Path::point's tangents outside the ends: linear and the polynomials (products,
// sums and differences of values in [0, 1] whose exact bounds 0, ½ and 1 are doubles, and
// rounding is monotone, so every intermediate keeps its bound).
constexpr bool stays_on_path(CurveKind k) noexcept { return k <= CurveKind::quint_out_in; }

// What a run of kind K on paths of lane kernel L and target type F compares
// kind_and_flags(h) & lean_mask with.
template <CurveKind K, LaneKernel L, bool F>
inline constexpr std::uint16_t run_want = static_cast<std::uint16_t>(kind_byte(K, L) | (F ? flag_float << 8 : 0));

// The point at u of a line or cubic kernel, from the engine's dense tables.
template <KernelKind P>
inline Vec2 lean_point(const LineFast* lines, const PathFast* fast, std::uint32_t path, double u) noexcept {
    static_assert(P == KernelKind::linear || P == KernelKind::cubic);
    if constexpr (P == KernelKind::linear) {
        const LineFast& f = lines[path];
        return f.c[0] + f.c[1] * u;
    } else {
        const PathFast& f = fast[path];
        return ((f.c[3] * u + f.c[2]) * u + f.c[1]) * u + f.c[0];
    }
}

// One record of a lean run: false (nothing written) when it does not belong to the run.
template <CurveKind K, KernelKind P, bool F>
inline bool lean_step(Hot& h, const LineFast* lines, const PathFast* fast, double dt) noexcept {
    constexpr std::uint16_t want = run_want<K, lane_kernel(P), F>;
    const double phase = h.phase + dt * h.rate;
    // started before this tick and still inside the play (either way: the rate is < 0
    // when reversed at run time); landing back on 0 is reaching the start (on_reverse_complete)
    if ((kind_and_flags(h) & lean_mask) != want || !(std::min(h.phase, phase) >= 0.0) || (phase == 0.0 && h.rate < 0.0) ||
        !(phase < play_end))
        return false;
    const double u = detail::ease_formula(K, (h.flags & flag_backward) ? 1.0 - phase : phase);
    if constexpr (!stays_on_path(K))
        if (!(u >= 0.0 && u <= 1.0)) return false;  // outside the path's ends: Path::point's tangents
    h.phase = phase;
    write_pair<std::conditional_t<F, float, double>>(h.target, h.y_offset, lean_point<P>(lines, fast, h.path, u));
    return true;
}

// The records that began a new play inside a lean run, whose Cold play counts are added
// in one pass when the run returns (or the log is full), each with its flag_more for the
// play after: an ending play is the only update of a lean record that writes its Cold
// record, a cache and TLB miss (the Cold records of 10⁶ animations spread over 24 MB), and
// taken where it comes, asked for or not, that wait cost a sixth of the linear run at 10⁶;
// in one pass the misses overlap. Nothing reads a record's play count while the run goes on,
// and a record begins at most one play a run.
class NewPlays {
public:
    NewPlays(Hot* hot, Cold* cold) noexcept : hot_(hot), cold_(cold) {}
    NewPlays(const NewPlays&) = delete;
    NewPlays& operator=(const NewPlays&) = delete;
    ~NewPlays() { flush(); }
    void add(std::size_t i) noexcept {
        index_[count_++] = static_cast<std::uint32_t>(i);
        if (count_ == capacity) flush();
    }
    void flush() noexcept {
        for (std::size_t k = 0; k < count_; ++k) {
            Cold& c = cold_[index_[k]];
            ++c.count;  // the next play (see Cold::count)
            hot_[index_[k]].flags = with_more(hot_[index_[k]].flags, c);
        }
        count_ = 0;
    }

private:
    static constexpr std::size_t capacity = 64;  // ~8,000 records of a run at one ending in ~120
    Hot* hot_;
    Cold* cold_;
    std::size_t count_ = 0;
    std::uint32_t index_[capacity];
};

// Whether a record's next play, when its play ends, is lean_loop's (no look at its Cold
// record): another play follows (forever, or not the last of its repeats) and nobody listens.
inline bool loops_lean(std::uint8_t flags) noexcept { return (flags & (flag_more | flag_listens)) == flag_more; }

// Record i of a lean run when its play ends on this tick, another play follows and nobody
// listens: its next play, as plain_advance makes it, without reading its Cold record (the
// count goes to `plays`); false, nothing changed, for any other record.
template <CurveKind K, KernelKind P, bool F>
inline bool lean_loop(Hot& h, const LineFast* lines, const PathFast* fast, double dt, std::size_t i,
                      NewPlays& plays) noexcept {
    constexpr std::uint16_t want = run_want<K, lane_kernel(P), F>;
    const double phase = h.phase + dt * h.rate;
    if ((kind_and_flags(h) & lean_mask) != want || !loops_lean(h.flags) || !(phase >= play_end && phase < next_play_end))
        return false;
    const NextPlay next = next_play(h, phase);
    const double u = detail::ease_formula(K, (next.flags & flag_backward) ? 1.0 - next.phase : next.phase);
    if constexpr (!stays_on_path(K))
        if (!(u >= 0.0 && u <= 1.0)) return false;  // outside the path's ends: Path::point's tangents
    h.phase = next.phase;
    h.flags = next.flags;
    write_pair<std::conditional_t<F, float, double>>(h.target, h.y_offset, lean_point<P>(lines, fast, h.path, u));
    plays.add(i);
    return true;
}

// Records from i on while they share curve kind K (no parameters), path kernel P (lines or
// cubics) and target type F (float or double), stay inside the current play, are not
// paused, dead or custom, have a target and started before this tick; returns the first
// record that does not (or n), unchanged; a record whose new play lean_loop takes stays in
// the run. What it writes is plain_step's, bit for bit: the same formulas on the same values.
// The easing and path formula are inline and nothing else is tested, so a record costs a few
// instructions more than a hand-written loop; the records up to `hot_ahead` before the end ask
// for those ahead without bound tests, the last ones ask for nothing.
template <CurveKind K, KernelKind P, bool F>
GRAPE_FLATTEN std::size_t lean_run(Hot* hot, const LeanTables& t, std::size_t i, std::size_t n, double dt) noexcept {
    static_assert(!has_parameters(K) && (P == KernelKind::linear || P == KernelKind::cubic));
    const LineFast* const lines = t.line;  // locals: the target writes cannot alias them
    const PathFast* const fast = t.fast;
    NewPlays plays(hot, t.cold);
    const std::size_t far = n > hot_ahead ? n - hot_ahead : 0;
    for (; i < far; ++i) {
        ask_hot(hot, i + hot_ahead);
        if (!lean_step<K, P, F>(hot[i], lines, fast, dt) && !lean_loop<K, P, F>(hot[i], lines, fast, dt, i, plays))
            return i;
    }
    for (; i < n; ++i)
        if (!lean_step<K, P, F>(hot[i], lines, fast, dt) && !lean_loop<K, P, F>(hot[i], lines, fast, dt, i, plays))
            return i;
    return i;
}

}  // namespace grape::detail
