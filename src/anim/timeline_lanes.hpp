// Lean timeline entries four at a time (AVX2, chosen at run time): the clocks, the fast
// case's tests, the child's position and the polynomial easings in four lanes; the path's
// point and the write per entry, as the engine's four-lane runs do for free animations.
//
// Every lane does fast_run's operations on the same values (no fused multiply-adds), so the
// bits are the general update's (tests/test_timeline_fast.cpp). A group of four in which any
// entry would leave the run goes back to fast_run, which takes it one entry at a time.
#pragma once

#include "engine_lean_wide.hpp"
#include "timeline_impl.hpp"

#include <cstddef>
#include <cstdint>

namespace grape::detail {

// The entries' run from i: returns the first entry of the first group of four that does not
// belong to it (or of the last, incomplete group), its entries unchanged.
using TimelineLanes = std::size_t (*)(RootLine*, const LineFast*, const PathFast*, std::size_t, std::size_t,
                                      double) noexcept;

#if GRAPE_WIDE

static_assert(offsetof(RootLine, elapsed) == 0 && offsetof(RootLine, base) == 8 && offsetof(RootLine, duration) == 16 &&
              offsetof(RootLine, start) == 24 && offsetof(RootLine, rate) == 32 && offsetof(RootLine, until) == 40 &&
              offsetof(RootLine, kc) == 44 && offsetof(RootLine, target) == 48 && offsetof(RootLine, path) == 56 &&
              offsetof(RootLine, y_offset) == 60 && offsetof(RootLine, kind) == 62 && offsetof(RootLine, bits) == 63);

// Four lines' 4-word halves (a: words 0–3, b: 4–7 of each) turned into lanes of one word each.
struct LineQuad {
    __m256d elapsed, base, duration, start, rate, until, kc;
    __m256i target, rest;  // rest: path, y offset, kind, bits (kind and bits the top 16 bits)
};
GRAPE_AVX2 inline void transpose(__m256d r0, __m256d r1, __m256d r2, __m256d r3, __m256d& c0, __m256d& c1,
                                 __m256d& c2, __m256d& c3) noexcept {
    const __m256d t0 = _mm256_unpacklo_pd(r0, r1), t1 = _mm256_unpackhi_pd(r0, r1);  // 00 10 02 12 | 01 11 03 13
    const __m256d t2 = _mm256_unpacklo_pd(r2, r3), t3 = _mm256_unpackhi_pd(r2, r3);
    c0 = _mm256_permute2f128_pd(t0, t2, 0x20);
    c1 = _mm256_permute2f128_pd(t1, t3, 0x20);
    c2 = _mm256_permute2f128_pd(t0, t2, 0x31);
    c3 = _mm256_permute2f128_pd(t1, t3, 0x31);
}
GRAPE_AVX2 inline __m256d half_line(const RootLine* l, std::size_t k, int word) noexcept {  // four words of line k
    return _mm256_load_pd(reinterpret_cast<const double*>(l + k) + word);
}
GRAPE_AVX2 inline LineQuad load_lines(const RootLine* l) noexcept {
    LineQuad q;
    transpose(half_line(l, 0, 0), half_line(l, 1, 0), half_line(l, 2, 0), half_line(l, 3, 0), q.elapsed, q.base,
              q.duration, q.start);
    __m256d until_kc, target, rest;
    transpose(half_line(l, 0, 4), half_line(l, 1, 4), half_line(l, 2, 4), half_line(l, 3, 4), q.rate, until_kc, target,
              rest);
    // until (low 4 bytes) and kc (high 4 bytes) of each word, as doubles
    const __m256i order = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);
    const __m256 split = _mm256_castsi256_ps(_mm256_permutevar8x32_epi32(_mm256_castpd_si256(until_kc), order));
    q.until = _mm256_cvtps_pd(_mm256_castps256_ps128(split));
    q.kc = _mm256_cvtps_pd(_mm256_extractf128_ps(split, 1));
    q.target = _mm256_castpd_si256(target);
    q.rest = _mm256_castpd_si256(rest);
    return q;
}

// What the bits and kind of an entry of the run are: fast with one lean animation, the
// target type, the path kernel (none without a target) and the curve kind; backward free.
template <CurveKind K, KernelKind P, bool F>
inline constexpr std::uint64_t lanes_want =
    (std::uint64_t{unsigned{root_one} | root_lean | (F ? unsigned{root_float} : 0u) |
                   (static_cast<unsigned>(lane_kernel(P)) << root_kernel_shift)}
     << 56) |
    (std::uint64_t{static_cast<std::uint8_t>(K)} << 48);
inline constexpr std::uint64_t lanes_mask =
    (std::uint64_t{unsigned{root_mode} | root_lean | root_float | root_kernel} << 56) | (std::uint64_t{0xFF} << 48);

template <CurveKind K, KernelKind P, bool F>
GRAPE_AVX2 GRAPE_FLATTEN std::size_t timeline_lanes(RootLine* lines, const LineFast* line_fast, const PathFast* path_fast,
                                                    std::size_t i, std::size_t n, double dt) noexcept {
    static_assert(stays_on_path(K) && (P == KernelKind::linear || P == KernelKind::cubic));
    using T = std::conditional_t<F, float, double>;
    constexpr int backward_bit = 56 + 4;  // root_backward's place in the last word
    static_assert(root_backward == 1 << (backward_bit - 56));
    const __m256d step = _mm256_set1_pd(dt);
    const __m256i mask = _mm256_set1_epi64x(static_cast<long long>(lanes_mask));
    const __m256i want = _mm256_set1_epi64x(static_cast<long long>(lanes_want<K, P, F>));
    for (; i + 4 <= n; i += 4) {
        RootLine* const l = lines + i;
        if (i + timeline_ahead + 4 <= n)
            for (std::size_t k = 0; k < 4; ++k) ask_line(l[timeline_ahead + k].target);
        const LineQuad q = load_lines(l);
        const __m256d elapsed = _mm256_add_pd(q.elapsed, step);
        const __m256i kind_ok = _mm256_cmpeq_epi64(_mm256_and_si256(q.rest, mask), want);
        const __m256d ok = _mm256_and_pd(_mm256_cmp_pd(elapsed, q.until, _CMP_LE_OQ), _mm256_castsi256_pd(kind_ok));
        if (_mm256_movemask_pd(ok) != 0xF) return i;
        // fast_run's lean point: lp = (base + elapsed) / duration − kc, x = (lp · duration − start) · rate
        const __m256d lp = _mm256_sub_pd(_mm256_div_pd(_mm256_add_pd(q.base, elapsed), q.duration), q.kc);
        const __m256d x = _mm256_mul_pd(_mm256_sub_pd(_mm256_mul_pd(lp, q.duration), q.start), q.rate);
        const __m256d back = _mm256_castsi256_pd(_mm256_slli_epi64(q.rest, 63 - backward_bit));
        const Lanes u = lanes_ease<K>(Lanes{_mm256_blendv_pd(x, _mm256_sub_pd(_mm256_set1_pd(1.0), x), back)});
        alignas(32) double el[4], us[4];
        _mm256_store_pd(el, elapsed);
        _mm256_store_pd(us, u.v);
        for (std::size_t k = 0; k < 4; ++k) l[k].elapsed = el[k];
        if (adjacent<T>(q.rest)) {  // y right after x in all four: (x, y) as one pair
            for (std::size_t k = 0; k < 4; ++k)
                store_pair<T>(l[k].target, pair_point<P>(line_fast, path_fast, l[k].path, us[k]));
        } else {
            for (std::size_t k = 0; k < 4; ++k)
                write_pair<T>(l[k].target, l[k].y_offset, lean_point<P>(line_fast, path_fast, l[k].path, us[k]));
        }
    }
    return i;
}

#endif

// The four-lane run an entry would start ([kind][line, cubic][double, float]); null where
// there is none (not AVX2, not a polynomial easing, another path kernel).
TimelineLanes timeline_lanes_for(const RootLine& l) noexcept;

}  // namespace grape::detail
