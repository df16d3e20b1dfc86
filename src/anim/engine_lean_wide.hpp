// Lean runs on lines and cubics four records at a time (AVX2, chosen at run time): the
// clocks, the run's tests, the direction and the polynomial easings in four lanes; the
// path's point and the write per record. A lean record costs some sixty instructions one
// at a time, most of them the same few operations on different records; in lanes they are
// shared by four.
//
// Every lane does lean_step's operations on the same values (no fused multiply-adds), so
// the bits are the general update's (tests/test_engine_lean.cpp). A group of four in which
// any record would leave the run goes through lean_step one record at a time.
#pragma once

#include "engine_lean.hpp"

#include <cstddef>
#include <cstdint>

namespace grape::detail {

#if GRAPE_WIDE

// Four doubles, with the operators the easing formulas use.
struct Lanes {
    __m256d v;
};
GRAPE_AVX2 inline Lanes operator+(Lanes a, Lanes b) noexcept { return {_mm256_add_pd(a.v, b.v)}; }
GRAPE_AVX2 inline Lanes operator-(Lanes a, Lanes b) noexcept { return {_mm256_sub_pd(a.v, b.v)}; }
GRAPE_AVX2 inline Lanes operator*(Lanes a, Lanes b) noexcept { return {_mm256_mul_pd(a.v, b.v)}; }
GRAPE_AVX2 inline Lanes lanes(double a) noexcept { return {_mm256_set1_pd(a)}; }
GRAPE_AVX2 inline Lanes operator+(double a, Lanes b) noexcept { return lanes(a) + b; }
GRAPE_AVX2 inline Lanes operator-(double a, Lanes b) noexcept { return lanes(a) - b; }
GRAPE_AVX2 inline Lanes operator-(Lanes a, double b) noexcept { return a - lanes(b); }
GRAPE_AVX2 inline Lanes operator*(double a, Lanes b) noexcept { return lanes(a) * b; }
// x < edge ? a : b in each lane (pick_below).
GRAPE_AVX2 inline Lanes pick_below(Lanes x, double edge, Lanes a, Lanes b) noexcept {
    return {_mm256_blendv_pd(b.v, a.v, _mm256_cmp_pd(x.v, _mm256_set1_pd(edge), _CMP_LT_OQ))};
}

// The polynomial easings (stays_on_path) as include/grape/curve.hpp writes them, operation
// for operation.
template <CurveKind K>
GRAPE_AVX2 inline Lanes lanes_in(Lanes x) noexcept {  // the in-formula of K's family
    if constexpr (K == CurveKind::quad_in) return x * x;
    else if constexpr (K == CurveKind::cubic_in) return x * x * x;
    else if constexpr (K == CurveKind::quart_in) {
        const Lanes x2 = x * x;
        return x2 * x2;
    } else {
        static_assert(K == CurveKind::quint_in);
        const Lanes x2 = x * x;
        return x2 * x2 * x;
    }
}
template <CurveKind K>
GRAPE_AVX2 inline Lanes lanes_out(Lanes x) noexcept {  // the out-formula of K's family
    if constexpr (K == CurveKind::quad_out) {
        const Lanes y = 1.0 - x;
        return 1.0 - y * y;
    } else if constexpr (K == CurveKind::cubic_out) {
        const Lanes y = 1.0 - x;
        return 1.0 - y * y * y;
    } else if constexpr (K == CurveKind::quart_out) {
        const Lanes y = (1.0 - x) * (1.0 - x);
        return 1.0 - y * y;
    } else {
        static_assert(K == CurveKind::quint_out);
        const Lanes y = 1.0 - x;
        const Lanes y2 = y * y;
        return 1.0 - y2 * y2 * y;
    }
}
// The kinds of one family sit in CurveKind as in, out, in-out, out-in.
template <CurveKind K, int step>
inline constexpr CurveKind kind_plus = static_cast<CurveKind>(static_cast<int>(K) + step);

template <CurveKind K>
GRAPE_AVX2 inline Lanes lanes_ease(Lanes x) noexcept {
    static_assert(stays_on_path(K));
    if constexpr (K == CurveKind::linear) return x;
    else {
        constexpr int place = (static_cast<int>(K) - static_cast<int>(CurveKind::quad_in)) % 4;
        constexpr CurveKind in = kind_plus<K, -place>, out = kind_plus<in, 1>;
        if constexpr (place == 0) return lanes_in<in>(x);
        else if constexpr (place == 1) return lanes_out<out>(x);
        else if constexpr (place == 3)
            return pick_below(x, 0.5, 0.5 * lanes_out<out>(2.0 * x), 0.5 + 0.5 * lanes_in<in>(2.0 * x - 1.0));
        else if constexpr (in == CurveKind::quad_in) {
            const Lanes y = 2.0 - 2.0 * x;
            return pick_below(x, 0.5, 2.0 * x * x, 1.0 - 0.5 * y * y);
        } else if constexpr (in == CurveKind::cubic_in) {
            const Lanes y = 2.0 - 2.0 * x;
            return pick_below(x, 0.5, 4.0 * x * x * x, 1.0 - 0.5 * y * y * y);
        } else if constexpr (in == CurveKind::quart_in) {
            const Lanes x2 = x * x;
            const Lanes y = (2.0 - 2.0 * x) * (2.0 - 2.0 * x);
            return pick_below(x, 0.5, 8.0 * x2 * x2, 1.0 - 0.5 * y * y);
        } else {
            const Lanes x2 = x * x;
            const Lanes y = 2.0 - 2.0 * x;
            const Lanes y2 = y * y;
            return pick_below(x, 0.5, 16.0 * x2 * x2 * x, 1.0 - 0.5 * y2 * y2 * y);
        }
    }
}

static_assert(sizeof(Hot) == 32 && offsetof(Hot, phase) == 0 && offsetof(Hot, rate) == 8 && offsetof(Hot, target) == 16 &&
              offsetof(Hot, path) == 24 && offsetof(Hot, y_offset) == 28 && offsetof(Hot, kind) == 30 &&
              offsetof(Hot, flags) == 31);

// Records i … i + 3 as four lanes of each of their 8-byte words: the phases, the rates, the
// targets and the last word (path, y offset, kind, flags; kind and flags its top 16 bits).
struct Quad {
    __m256d phase, rate;
    __m256i target, rest;
};
GRAPE_AVX2 inline __m256d pair(const double* lo, const double* hi) noexcept {  // lo's two words | hi's
    return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(lo)), _mm_loadu_pd(hi), 1);
}
GRAPE_AVX2 inline Quad load_quad(const Hot* hot) noexcept {
    const auto* w = reinterpret_cast<const double*>(hot);  // 4 words a record
    const __m256d a = pair(w, w + 8), b = pair(w + 4, w + 12);        // phase, rate of 0 | 2; of 1 | 3
    const __m256d c = pair(w + 2, w + 10), d = pair(w + 6, w + 14);  // target, rest
    return {_mm256_unpacklo_pd(a, b), _mm256_unpackhi_pd(a, b), _mm256_castpd_si256(_mm256_unpacklo_pd(c, d)),
            _mm256_castpd_si256(_mm256_unpackhi_pd(c, d))};
}

// What every group of four compares with: the tick's dt, the play's bounds and the run's
// kind and flags (as the top 16 bits of a record's last word).
struct LaneConsts {
    __m256d step, zero, end;
    __m256i flags_mask, flags_want;
};
template <CurveKind K, LaneKernel L, bool F>
GRAPE_AVX2 inline LaneConsts lane_consts(double dt) noexcept {
    constexpr std::uint16_t want = run_want<K, L, F>;
    return {_mm256_set1_pd(dt), _mm256_setzero_pd(), _mm256_set1_pd(play_end),
            _mm256_set1_epi64x(static_cast<long long>(std::uint64_t{lean_mask} << 48)),
            _mm256_set1_epi64x(static_cast<long long>(std::uint64_t{want} << 48))};
}

// Asks for the hot records `hot_ahead` on (records i + hot_ahead + 3 exist).
GRAPE_AVX2 inline void ask_hot_quad(const Hot* hot, std::size_t i) noexcept {
    ask_hot(hot, i + hot_ahead);
    ask_hot(hot, i + hot_ahead + 2);
}

// Records h[0 … 3] in lanes: their new phases and eased progress, false (nothing computed
// that matters) when any fails lean_step's tests of kind and flags, started and inside the
// play (the kind byte holds the path kernel and whether there is a target). `rest`: the
// records' last words (path, y offset, kind, flags) in lanes.
template <CurveKind K>
GRAPE_AVX2 inline bool lanes_step(const Hot* h, const LaneConsts& c, __m256d& phase, Lanes& u,
                                  __m256i* rest = nullptr) noexcept {
    constexpr int backward_bit = 56 + 2;  // flag_backward's place in the last word
    static_assert(flag_backward == 1 << (backward_bit - 56));
    const Quad q = load_quad(h);
    if (rest) *rest = q.rest;
    phase = _mm256_add_pd(q.phase, _mm256_mul_pd(c.step, q.rate));
    const __m256i kind_ok = _mm256_cmpeq_epi64(_mm256_and_si256(q.rest, c.flags_mask), c.flags_want);
    // min(phase before, after) ≥ 0 as lean_step has it: both ≥ 0 (a NaN fails either way)
    const __m256d started = _mm256_and_pd(_mm256_cmp_pd(q.phase, c.zero, _CMP_GE_OQ), _mm256_cmp_pd(phase, c.zero, _CMP_GE_OQ));
    // and not landing back on 0 (phase > 0 or rate ≥ 0): reaching the start is the general path's
    const __m256d not_home = _mm256_or_pd(_mm256_cmp_pd(phase, c.zero, _CMP_GT_OQ), _mm256_cmp_pd(q.rate, c.zero, _CMP_GE_OQ));
    const __m256d inside = _mm256_and_pd(_mm256_and_pd(started, not_home), _mm256_cmp_pd(phase, c.end, _CMP_LT_OQ));
    const __m256d ok = _mm256_and_pd(inside, _mm256_castsi256_pd(kind_ok));
    if (_mm256_movemask_pd(ok) != 0xF) return false;
    // 1 − phase where the play runs backward: the flag's bit moved to the sign, which blendv reads
    const __m256d back = _mm256_castsi256_pd(_mm256_slli_epi64(q.rest, 63 - backward_bit));
    u = lanes_ease<K>(Lanes{_mm256_blendv_pd(phase, _mm256_sub_pd(_mm256_set1_pd(1.0), phase), back)});
    return true;
}

GRAPE_AVX2 inline void store_phases(Hot* h, __m256d phase) noexcept {
    const __m128d lo = _mm256_castpd256_pd128(phase), hi = _mm256_extractf128_pd(phase, 1);
    _mm_storel_pd(&h[0].phase, lo);
    _mm_storeh_pd(&h[1].phase, lo);
    _mm_storel_pd(&h[2].phase, hi);
    _mm_storeh_pd(&h[3].phase, hi);
}

// Whether all four records' y member lies right after x (y_offset, bits 32–47 of the last
// word, is sizeof(T)): the common layout, written as one pair.
template <class T>
GRAPE_AVX2 inline bool adjacent(__m256i rest) noexcept {
    const __m256i y = _mm256_and_si256(rest, _mm256_set1_epi64x(0xFFFFll << 32));
    const __m256i want = _mm256_set1_epi64x(static_cast<long long>(sizeof(T)) << 32);
    return _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpeq_epi64(y, want))) == 0xF;
}
// lean_point's operations on (x, y) as one pair of lanes: the same bits.
template <KernelKind P>
GRAPE_AVX2 inline __m128d pair_point(const LineFast* lines, const PathFast* fast, std::uint32_t path, double u) noexcept {
    const __m128d v = _mm_set1_pd(u);
    if constexpr (P == KernelKind::linear) {
        const auto* c = reinterpret_cast<const double*>(lines[path].c);
        return _mm_add_pd(_mm_loadu_pd(c), _mm_mul_pd(_mm_loadu_pd(c + 2), v));
    } else {
        const auto* c = reinterpret_cast<const double*>(fast[path].c);
        const __m128d a = _mm_add_pd(_mm_mul_pd(_mm_loadu_pd(c + 6), v), _mm_loadu_pd(c + 4));
        const __m128d b = _mm_add_pd(_mm_mul_pd(a, v), _mm_loadu_pd(c + 2));
        return _mm_add_pd(_mm_mul_pd(b, v), _mm_loadu_pd(c));
    }
}
// write_pair for y right after x (unaligned stores: a float pair may sit at any 4 bytes).
template <class T>
GRAPE_AVX2 inline void store_pair(char* x, __m128d p) noexcept {
    if constexpr (std::is_same_v<T, double>) _mm_storeu_pd(reinterpret_cast<double*>(x), p);
    else _mm_storel_epi64(reinterpret_cast<__m128i*>(x), _mm_castps_si128(_mm_cvtpd_ps(p)));  // 8 bytes, any alignment
}

// lean_run for the polynomial easings on lines or cubics, four records at a time while at
// least `hot_ahead` records remain (lean_run takes the rest, and any group of four that holds
// a record leaving the run, one record at a time).
template <CurveKind K, KernelKind P, bool F>
GRAPE_AVX2 GRAPE_FLATTEN std::size_t lean_run_wide(Hot* hot, const LeanTables& t, std::size_t i, std::size_t n,
                                                   double dt) noexcept {
    static_assert(stays_on_path(K) && (P == KernelKind::linear || P == KernelKind::cubic));
    const LineFast* const lines = t.line;  // locals: the target writes cannot alias them
    const PathFast* const fast = t.fast;
    NewPlays plays(hot, t.cold);
    const LaneConsts c = lane_consts<K, lane_kernel(P), F>(dt);
    using T = std::conditional_t<F, float, double>;
    const std::size_t far = n > hot_ahead ? n - hot_ahead : 0;
    for (; i + 4 <= far; i += 4) {
        ask_hot_quad(hot, i);
        Hot* const h = hot + i;
        __m256d phase;
        Lanes u;
        __m256i rest;
        if (!lanes_step<K>(h, c, phase, u, &rest)) {
            for (std::size_t j = 0; j < 4; ++j)
                if (!lean_step<K, P, F>(h[j], lines, fast, dt) &&
                    !lean_loop<K, P, F>(h[j], lines, fast, dt, i + j, plays))
                    return i + j;
            continue;
        }
        store_phases(h, phase);
        alignas(32) double us[4];
        _mm256_store_pd(us, u.v);
        if (adjacent<T>(rest)) {  // y right after x in all four: (x, y) as one pair
            for (std::size_t j = 0; j < 4; ++j) store_pair<T>(h[j].target, pair_point<P>(lines, fast, h[j].path, us[j]));
        } else {
            for (std::size_t j = 0; j < 4; ++j)  // lean_step's point and write
                write_pair<T>(h[j].target, h[j].y_offset, lean_point<P>(lines, fast, h[j].path, us[j]));
        }
    }
    return lean_run<K, P, F>(hot, t, i, n, dt);
}

#else

template <CurveKind K, KernelKind P, bool F>
std::size_t lean_run_wide(Hot* hot, const LeanTables& t, std::size_t i, std::size_t n, double dt) noexcept {
    return lean_run<K, P, F>(hot, t, i, n, dt);
}

#endif

}  // namespace grape::detail
