// The lean runs on arc-length paths: batches whose records are all advanced, their table
// pieces found and asked for, before any point is written.
#pragma once

#include "engine_lean.hpp"
#include "engine_lean_wide.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace grape::detail {

// A play that ends and that the run does not continue (a last play, listeners) leaves the run
// for the general update, which reads the record's Cold record, a cache and TLB miss: asked
// for `cold_ahead` records before (~800 ns of arc-length updates, so the hot record tested
// there arrived long ago). The plays the run continues are not asked for: their play counts
// are added in one pass (NewPlays), where the misses overlap.
inline constexpr std::size_t cold_ahead = 160;
static_assert(cold_ahead < hot_ahead);
inline void ask_cold_if_leaving(const Hot* hot, const Cold* cold, std::size_t j, double dt) noexcept {
    const Hot& h = hot[j];
    if (h.phase + dt * h.rate >= play_end && !loops_lean(h.flags)) ask_cold(cold, j);
}

#if GRAPE_WIDE
// ask_cold_if_leaving for the records `cold_ahead` on, four at a time (records i + hot_ahead
// + 3 exist): one compare for the four, the flags read only where a play ends.
GRAPE_AVX2 inline void ask_leaving_quad(const Hot* hot, const Cold* cold, std::size_t i, const LaneConsts& c) noexcept {
    const Quad ahead = load_quad(hot + i + cold_ahead);
    const __m256d next = _mm256_add_pd(ahead.phase, _mm256_mul_pd(c.step, ahead.rate));
    if (int ending = _mm256_movemask_pd(_mm256_cmp_pd(next, c.end, _CMP_GE_OQ))) {
        for (std::size_t j = i + cold_ahead; ending; ++j, ending >>= 1)
            if ((ending & 1) && !loops_lean(hot[j].flags)) ask_cold(cold, j);
    }
}
#endif

// One record of an arc-length run's batch: advanced, its table piece found and asked for;
// false (nothing changed) when it does not belong to the run. A play that ends, with another
// to follow and nobody listening, leads into the next here, as lean_loop has it (its count
// goes to `plays`). Far: the records `hot_ahead` on exist, so the look-ahead needs no bound
// test.
template <CurveKind K, bool F, bool Far>
inline bool arc_advance(Hot* hot, const ArcFast* arcs, const Cold* cold, std::size_t i, std::size_t n, double dt,
                        ArcLengthTable::Piece& piece, NewPlays& plays) noexcept {
    constexpr std::uint16_t want = run_want<K, LaneKernel::arc, F>;
    if constexpr (Far) {
        ask_hot(hot, i + hot_ahead);
        ask_cold_if_leaving(hot, cold, i + cold_ahead, dt);
    } else {
        ask_hot_ahead(hot, i, n);
        if (i + cold_ahead < n) ask_cold_if_leaving(hot, cold, i + cold_ahead, dt);
    }
    Hot& h = hot[i];
    double phase = h.phase + dt * h.rate;
    // the arc lane kernel in `want`: the path has a table (reparametrized kernels exist only with one)
    if ((kind_and_flags(h) & lean_mask) != want || !(std::min(h.phase, phase) >= 0.0) || (phase == 0.0 && h.rate < 0.0))
        return false;  // landing back on 0 is reaching the start: the general path's
    std::uint8_t flags = h.flags;
    const bool loops = !(phase < play_end);
    if (loops) {
        if (!loops_lean(flags) || !(phase < next_play_end)) return false;  // (a NaN phase fails here)
        const NextPlay next = next_play(h, phase);
        phase = next.phase;
        flags = next.flags;
    }
    const double u = detail::ease_formula(K, (flags & flag_backward) ? 1.0 - phase : phase);
    if (!(u > 0.0 && u < 1.0)) return false;
    h.phase = phase;
    if (loops) {
        h.flags = flags;
        plays.add(i);
    }
    const ArcFast& f = arcs[h.path];
    piece = ArcLengthTable::piece_at(f.table, f.steps, u);
    ArcLengthTable::prefetch_piece(piece.c);
    return true;
}

// Records k, k + 1, ... of the batch of m at i advanced one at a time (arc_advance) while they
// belong to the run; how many of the batch are advanced then.
template <CurveKind K, bool F>
inline std::size_t arc_advance_batch(Hot* hot, const ArcFast* arcs, const Cold* cold, std::size_t i, std::size_t k,
                                     std::size_t m, std::size_t n, double dt, ArcLengthTable::Piece* piece,
                                     NewPlays& plays) noexcept {
    if (i + m + hot_ahead <= n) {
        while (k < m && arc_advance<K, F, true>(hot, arcs, cold, i + k, n, dt, piece[k], plays)) ++k;
    } else {
        while (k < m && arc_advance<K, F, false>(hot, arcs, cold, i + k, n, dt, piece[k], plays)) ++k;
    }
    return k;
}

// The same on arc-length paths, strictly inside them (the ends are Path::point's exact end
// points, which plain_write gives), in batches of 32 as plain_run has them: every record of
// a batch is advanced and its table piece found and asked for before any is written, so
// that the misses on shared tables overlap. The piece comes from ArcLengthTable's piece_at
// and evaluate_piece, as in plain_piece. W: the pieces' points in four lanes
// (evaluate_piece_wide, the same bits).
template <CurveKind K, bool F, bool W>
inline std::size_t arc_run(Hot* hot, const LeanTables& t, std::size_t i, std::size_t n, double dt) noexcept {
    static_assert(!has_parameters(K));
    constexpr std::size_t batch = 32;
    const ArcFast* const arcs = t.arc;  // locals: the writes cannot alias them
    const Cold* const cold = t.cold;
    NewPlays plays(hot, t.cold);
    ArcLengthTable::Piece piece[batch];
    while (i < n) {
        const std::size_t m = std::min(batch, n - i);
        const std::size_t k = arc_advance_batch<K, F>(hot, arcs, cold, i, 0, m, n, dt, piece, plays);
        for (std::size_t j = 0; j < k; ++j) {
            const Hot& h = hot[i + j];
            Vec2 p;
#if GRAPE_WIDE
            if constexpr (W) p = ArcLengthTable::evaluate_piece_wide(piece[j].c, piece[j].x);
            else
#endif
                p = ArcLengthTable::evaluate_piece(piece[j].c, piece[j].x);
            write_pair<std::conditional_t<F, float, double>>(h.target, h.y_offset, p);
        }
        i += k;
        if (k < m) break;
    }
    return i;
}

template <CurveKind K, bool F>
GRAPE_FLATTEN std::size_t lean_arc_run(Hot* hot, const LeanTables& t, std::size_t i, std::size_t n, double dt) noexcept {
    return arc_run<K, F, false>(hot, t, i, n, dt);
}
#if GRAPE_WIDE
// The whole loop compiled for AVX2, so that the four-lane evaluation inlines into it.
template <CurveKind K, bool F>
GRAPE_AVX2 GRAPE_FLATTEN std::size_t lean_arc_run_wide(Hot* hot, const LeanTables& t, std::size_t i, std::size_t n,
                                                       double dt) noexcept {
    return arc_run<K, F, true>(hot, t, i, n, dt);
}

// lean_arc_run_wide for the polynomial easings: the batch's records advanced four at a time
// in lanes (lanes_step, then four_pieces_at) while whole groups stay in the run, the rest one
// at a time; the points two at a time (two_pieces_wide), written as one pair where y follows
// x. All of it the same bits.
// A loop of its own: the same steps folded into arc_run through a helper measured ~25 %
// slower with GCC 12 (cause not found).
template <CurveKind K, bool F>
GRAPE_AVX2 GRAPE_FLATTEN std::size_t arc_run_lanes(Hot* hot, const LeanTables& t, std::size_t i, std::size_t n,
                                                   double dt) noexcept {
    static_assert(stays_on_path(K));
    constexpr std::size_t batch = 32;
    const ArcFast* const arcs = t.arc;
    const Cold* const cold = t.cold;
    const LaneConsts c = lane_consts<K, LaneKernel::arc, F>(dt);
    NewPlays plays(hot, t.cold);
    ArcLengthTable::Piece piece[batch];
    while (i < n) {
        const std::size_t m = std::min(batch, n - i);
        std::size_t k = 0;
        if (i + m + hot_ahead <= n) {
            for (; k + 4 <= m; k += 4) {
                ask_hot_quad(hot, i + k);
                ask_leaving_quad(hot, cold, i + k, c);
                Hot* const h = hot + i + k;
                __m256d phase;
                Lanes u;
                if (!lanes_step<K>(h, c, phase, u)) break;
                const ArcFast &f0 = arcs[h[0].path], &f1 = arcs[h[1].path], &f2 = arcs[h[2].path], &f3 = arcs[h[3].path];
                const __m256d inside = _mm256_and_pd(_mm256_cmp_pd(u.v, c.zero, _CMP_GT_OQ),
                                                     _mm256_cmp_pd(u.v, _mm256_set1_pd(1.0), _CMP_LT_OQ));
                if (_mm256_movemask_pd(inside) != 0xF) break;
                store_phases(h, phase);
                const double* const tables[4] = {f0.table, f1.table, f2.table, f3.table};
                ArcLengthTable::four_pieces_at(tables, _mm256_setr_pd(f0.steps, f1.steps, f2.steps, f3.steps), u.v,
                                               piece + k);
                for (std::size_t j = 0; j < 4; ++j) ArcLengthTable::prefetch_piece(piece[k + j].c);
            }
        }
        k = arc_advance_batch<K, F>(hot, arcs, cold, i, k, m, n, dt, piece, plays);
        std::size_t j = 0;
        using T = std::conditional_t<F, float, double>;
        for (; j + 2 <= k; j += 2) {
            const __m256d p = ArcLengthTable::two_pieces_wide(piece[j].c, piece[j].x, piece[j + 1].c, piece[j + 1].x);
            const __m128d pa = _mm256_castpd256_pd128(p), pb = _mm256_extractf128_pd(p, 1);
            const Hot& ha = hot[i + j];
            const Hot& hb = hot[i + j + 1];
            if (ha.y_offset == sizeof(T) && hb.y_offset == sizeof(T)) {  // y right after x: one pair each
                store_pair<T>(ha.target, pa);
                store_pair<T>(hb.target, pb);
            } else {
                write_pair<T>(ha.target, ha.y_offset, vec2_of(pa));
                write_pair<T>(hb.target, hb.y_offset, vec2_of(pb));
            }
        }
        for (; j < k; ++j) {
            const Hot& h = hot[i + j];
            write_pair<std::conditional_t<F, float, double>>(h.target, h.y_offset,
                                                             ArcLengthTable::evaluate_piece_wide(piece[j].c, piece[j].x));
        }
        i += k;
        if (k < m) break;
    }
    return i;
}

#else
template <CurveKind K, bool F>
std::size_t lean_arc_run_wide(Hot* hot, const LeanTables& t, std::size_t i, std::size_t n, double dt) noexcept {
    return lean_arc_run<K, F>(hot, t, i, n, dt);
}
#endif

}  // namespace grape::detail
