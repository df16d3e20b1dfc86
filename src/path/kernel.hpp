// grape — what modules that evaluate paths in bulk (anim's tick) may know of a path beyond
// path.hpp: a kind to switch on, copied coefficients of lines and cubics, and the arc-length
// table of a reparametrized line or cubic. Owned by the path module, built by make_kernel,
// reached through the build-only target grape::path_internal (not installed). What is compiled
// is exported (GRAPE_PATH_API): anim and render call it from other shared libraries.
#pragma once

#include "svg_segment.hpp"

#include <grape/detail/line_allocator.hpp>
#include <grape/export_path.hpp>
#include <grape/path.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include "internal/compiler.hpp"
// Four-lane (AVX2) loops chosen at run time: x86-64 compilers that take per-function targets.
#if GRAPE_X86_TARGETS && defined(__x86_64__)
#define GRAPE_WIDE 1
#define GRAPE_AVX2 GRAPE_TARGET("avx2")
#else
#define GRAPE_WIDE 0
#endif
#include <new>
#include <optional>
#include <span>
#include <vector>

namespace grape::detail {

#if defined(__SSE2__)
/// The (x, y) pair in an SSE register's two lanes as a Vec2.
inline Vec2 vec2_of(__m128d p) noexcept { return {_mm_cvtsd_f64(p), _mm_cvtsd_f64(_mm_unpackhi_pd(p, p))}; }
#endif

/// The point at u of a reparametrized path (u: fraction of arc length) as K even pieces (K a
/// power of two), each a degree-11 polynomial in the piece's own x in [−1, 1] for x(u) and
/// y(u) at once: twelve (x, y) coefficient pairs of doubles, three 64-byte cache lines. A
/// lookup costs a floor and a dozen two-lane multiply-adds in a shallow tree, with no table
/// walk and no Bézier after it (the path's own solve costs a bucket search, a quintic and
/// the cubic); a typical cubic needs 8 pieces (1.5 KB). Doubles throughout: floats for the
/// small high-order coefficients would halve the bytes, but their conversions cost more of
/// the tick than the third line's traffic does (the tick prefetches the lines).
///
/// Each line holds the pairs of x^4k, x^4k+2, x^4k+1, x^4k+3 in that order (`slot`), so that
/// a four-lane machine forms two of Estrin's first terms with one multiply and one add
/// (evaluate_piece_wide), and two pieces share the last steps (evaluate_two_pieces_wide): the
/// arithmetic, not the table's traffic, is what an arc-length update costs beyond a plain
/// cubic's (with every update reading one shared table, in L1, it costs the same).
class ArcLengthTable {
public:
    static constexpr int degree = 11;                 ///< of each piece's polynomials
    static constexpr std::size_t stride = 24;         ///< storage words (192 bytes) per piece
    static constexpr int max_steps = 4096;            ///< 768 KB of table at most

    /// The fewest pieces (K = 1, 2, 4, ... 4096) whose points, at 23 places inside every
    /// piece, land within 1e-10·length of the path's own point (so within 2e-10·length
    /// anywhere: tested); nullopt when the path is not reparametrized, has no length or
    /// needs more than 4096 pieces (a source that stops somewhere: dv/du unbounded).
    GRAPE_PATH_API static std::optional<ArcLengthTable> build(const Path& reparametrized);

    /// The point at u: the path's own end points at or below 0 (and for NaN) and at or above 1.
    Vec2 point(double u) const noexcept {
        if (u >= 1.0) return end_;
        if (!(u > 0.0)) return start_;
        return evaluate(values_.data(), steps_, u);
    }
    /// K, the number of pieces.
    double steps() const noexcept { return steps_; }
    /// Path::point at 0 and 1 (the ends, exact: animations start and land on them).
    Vec2 start() const noexcept { return start_; }
    Vec2 end() const noexcept { return end_; }
    /// The pieces' storage, piece after piece (24·K words, 64-byte aligned: a piece is three
    /// cache lines): the (x, y) coefficients of x⁰, x¹, … x¹¹, those of x^i at slot(i).
    std::span<const double> values() const noexcept { return {values_.data(), values_.size()}; }
    /// Where the (x, y) pair of x^i's coefficients starts within a piece (see the class).
    static constexpr std::size_t slot(int i) noexcept {
        constexpr std::size_t within[4] = {0, 4, 2, 6};
        return 8 * static_cast<std::size_t>(i / 4) + within[i % 4];
    }

    /// point on a table's raw storage (for callers that keep a pointer in a hot record), u
    /// strictly inside (0, 1). K is a power of two, so u·K is exact and u < 1 never reads
    /// past the last piece.
    static Vec2 evaluate(const double* values, double steps, double u) noexcept {
        const Piece p = piece_at(values, steps, u);
        return evaluate_piece(p.c, p.x);
    }
    /// Where u falls: the piece's storage and u's place x in [−1, 1] within it (u strictly
    /// inside (0, 1)), so that bulk callers can ask for the piece's lines before evaluating.
    struct Piece {
        const double* c;
        double x;
    };
    static Piece piece_at(const double* values, double steps, double u) noexcept {
        const double s = u * steps;
        const auto k = static_cast<std::int64_t>(s);  // s > 0: truncation is the floor, one instruction
        return {values + stride * static_cast<std::size_t>(k), 2.0 * (s - static_cast<double>(k)) - 1.0};
    }
    /// Asks for a piece's three cache lines (a hint: no effect on results).
    static void prefetch_piece(const double* c) noexcept {
        for (std::size_t line = 0; line < stride; line += 8) prefetch_read(c + line);
    }
    /// One piece's point at its own x in [−1, 1]. Estrin's scheme on the coefficient pairs:
    /// q_i = a_2i + a_2i+1·x, r_j = q_2j + q_2j+1·x², p = r0 + (r1 + r2·x⁴)·x⁴; both
    /// coordinates in the two lanes where SSE2 has them.
    static Vec2 evaluate_piece(const double* c, double x) noexcept {
        const double x2 = x * x, x4 = x2 * x2;
#if defined(__SSE2__)
        const __m128d vx = _mm_set1_pd(x), vx2 = _mm_set1_pd(x2), vx4 = _mm_set1_pd(x4);
        auto q = [c, vx](int i) {
            return _mm_add_pd(_mm_load_pd(c + slot(2 * i)), _mm_mul_pd(_mm_load_pd(c + slot(2 * i + 1)), vx));
        };
        const __m128d r0 = _mm_add_pd(q(0), _mm_mul_pd(q(1), vx2));
        const __m128d r1 = _mm_add_pd(q(2), _mm_mul_pd(q(3), vx2));
        const __m128d r2 = _mm_add_pd(q(4), _mm_mul_pd(q(5), vx2));
        const __m128d p = _mm_add_pd(r0, _mm_mul_pd(_mm_add_pd(r1, _mm_mul_pd(r2, vx4)), vx4));
        return vec2_of(p);
#else
        double out[2];
        for (int d = 0; d < 2; ++d) {
            auto q = [c, d, x](int i) { return c[slot(2 * i) + d] + c[slot(2 * i + 1) + d] * x; };
            const double r0 = q(0) + q(1) * x2, r1 = q(2) + q(3) * x2, r2 = q(4) + q(5) * x2;
            out[d] = r0 + (r1 + r2 * x4) * x4;
        }
        return {out[0], out[1]};
#endif
    }
#if GRAPE_WIDE
    /// evaluate_piece in four lanes (AVX2, without fused multiply-adds): the same operations on
    /// the same values, so the same bits, in 7 multiplies and 7 adds instead of 11 and 11.
    /// Only where wide_lanes() says so.
    GRAPE_AVX2 static Vec2 evaluate_piece_wide(const double* c, double x) noexcept {
        const __m256d vx = _mm256_set1_pd(x), vx2 = _mm256_mul_pd(vx, vx);  // x² in every lane: x * x
        const __m128d vx4 = _mm_mul_pd(_mm256_castpd256_pd128(vx2), _mm256_castpd256_pd128(vx2));
        const __m256d q01 = q_line(c, 0, vx), q23 = q_line(c, 1, vx), q45 = q_line(c, 2, vx);
        const __m256d even = _mm256_permute2f128_pd(q01, q23, 0x20);  // q0, q2
        const __m256d odd = _mm256_permute2f128_pd(q01, q23, 0x31);   // q1, q3
        const __m256d r01 = _mm256_add_pd(even, _mm256_mul_pd(odd, vx2));
        const __m128d r2 = _mm_add_pd(_mm256_castpd256_pd128(q45),
                                      _mm_mul_pd(_mm256_extractf128_pd(q45, 1), _mm256_castpd256_pd128(vx2)));
        const __m128d r0 = _mm256_castpd256_pd128(r01), r1 = _mm256_extractf128_pd(r01, 1);
        const __m128d p = _mm_add_pd(r0, _mm_mul_pd(_mm_add_pd(r1, _mm_mul_pd(r2, vx4)), vx4));
        return vec2_of(p);
    }
    /// piece_at for four u in lanes (tables[j] with steps[j] for u[j]), the same bits: the
    /// same product, truncation (u·K < 4096 fits an int32) and x.
    GRAPE_AVX2 static void four_pieces_at(const double* const tables[4], __m256d steps, __m256d u,
                                          Piece out[4]) noexcept {
        const __m256d s = _mm256_mul_pd(u, steps);
        const __m128i k = _mm256_cvttpd_epi32(s);  // s > 0: truncation is the floor
        const __m256d x = _mm256_sub_pd(_mm256_mul_pd(_mm256_set1_pd(2.0), _mm256_sub_pd(s, _mm256_cvtepi32_pd(k))),
                                        _mm256_set1_pd(1.0));
        alignas(32) double xs[4];
        alignas(16) std::int32_t ks[4];
        _mm256_store_pd(xs, x);
        _mm_store_si128(reinterpret_cast<__m128i*>(ks), k);
        for (int j = 0; j < 4; ++j) out[j] = {tables[j] + stride * static_cast<std::size_t>(ks[j]), xs[j]};
    }
    /// The q terms of line `line` of a piece: the pairs there plus x times the pairs after them.
    GRAPE_AVX2 static __m256d q_line(const double* c, int line, __m256d vx) noexcept {
        return _mm256_add_pd(_mm256_load_pd(c + 8 * line), _mm256_mul_pd(_mm256_load_pd(c + 8 * line + 4), vx));
    }
    /// evaluate_piece_wide on two pieces at once, the last steps of each sharing four lanes:
    /// the same operations on the same values (the same bits), in 11 multiplies and 11 adds
    /// beside the powers of x, instead of 14 and 14.
    GRAPE_AVX2 static void evaluate_two_pieces_wide(const double* a, double xa, const double* b, double xb,
                                                    Vec2& pa, Vec2& pb) noexcept {
        const __m256d p = two_pieces_wide(a, xa, b, xb);
        const __m128d lo = _mm256_castpd256_pd128(p), hi = _mm256_extractf128_pd(p, 1);
        pa = vec2_of(lo);
        pb = vec2_of(hi);
    }
    /// The same, as (pa.x, pa.y, pb.x, pb.y) in four lanes.
    GRAPE_AVX2 static __m256d two_pieces_wide(const double* a, double xa, const double* b, double xb) noexcept {
        const __m256d va = _mm256_set1_pd(xa), vb = _mm256_set1_pd(xb);
        const __m256d va2 = _mm256_mul_pd(va, va), vb2 = _mm256_mul_pd(vb, vb);
        // x² of a in the low half, of b in the high half; x⁴ the same
        const __m256d vab2 = _mm256_permute2f128_pd(va2, vb2, 0x20);
        const __m256d vab4 = _mm256_mul_pd(vab2, vab2);
        const __m256d qa01 = q_line(a, 0, va), qa23 = q_line(a, 1, va), qa45 = q_line(a, 2, va);
        const __m256d qb01 = q_line(b, 0, vb), qb23 = q_line(b, 1, vb), qb45 = q_line(b, 2, vb);
        const __m256d ra01 = _mm256_add_pd(_mm256_permute2f128_pd(qa01, qa23, 0x20),
                                           _mm256_mul_pd(_mm256_permute2f128_pd(qa01, qa23, 0x31), va2));
        const __m256d rb01 = _mm256_add_pd(_mm256_permute2f128_pd(qb01, qb23, 0x20),
                                           _mm256_mul_pd(_mm256_permute2f128_pd(qb01, qb23, 0x31), vb2));
        const __m256d r2 = _mm256_add_pd(_mm256_permute2f128_pd(qa45, qb45, 0x20),
                                         _mm256_mul_pd(_mm256_permute2f128_pd(qa45, qb45, 0x31), vab2));
        const __m256d r0 = _mm256_permute2f128_pd(ra01, rb01, 0x20), r1 = _mm256_permute2f128_pd(ra01, rb01, 0x31);
        return _mm256_add_pd(r0, _mm256_mul_pd(_mm256_add_pd(r1, _mm256_mul_pd(r2, vab4)), vab4));
    }
#endif
private:
    // Cache-line aligned storage, so that no piece straddles two lines.
    std::vector<double, LineAllocator<double>> values_;
    double steps_ = 0.0;
    Vec2 start_, end_;
};

/// Whether this processor runs the four-lane (AVX2) loops: evaluate_piece_wide and the
/// tick's (checked once; the environment variable GRAPE_WIDE_LANES=0 turns them off).
GRAPE_PATH_API bool wide_lanes() noexcept;

/// How a kernel evaluates inside [0, 1].
enum class KernelKind : std::uint8_t {
    generic,         ///< Path::point
    linear,          ///< c[0] + c[1]·u
    cubic,           ///< ((c[3]·u + c[2])·u + c[1])·u + c[0]
    reparam_linear,  ///< table.point(u) (a reparametrized line)
    reparam_cubic,   ///< table.point(u) (a reparametrized cubic)
};

/// A path as a bulk evaluator sees it. Inside [0, 1] the formulas above give Path::point
/// bit for bit (cubic), to rounding (linear: a + (b − a)·u where the path has lerp) or within
/// 2e-10·length (reparametrized, by the table).
struct PathKernel {
    KernelKind kind = KernelKind::generic;
    Vec2 c[4] = {};  ///< linear: start, end − start; cubic: power-basis coefficients; reparam_*: start, end
    std::optional<ArcLengthTable> table;  ///< reparam_*: the points (its buffer survives moving the kernel)
};

/// The kernel of a path (builds the arc-length table of a reparametrized line or cubic).
GRAPE_PATH_API PathKernel make_kernel(const Path& path);
/// The shape's identity: equal for copies of one Path (a key for tables of shared paths).
GRAPE_PATH_API const void* shape_id(const Path& path) noexcept;
/// The parameters 0 = b0 < b1 < ... < bk = 1 between which the path is smooth (spline
/// joins, cues, cusps, quarter turns).
GRAPE_PATH_API std::span<const double> smooth_breaks(const Path& path) noexcept;
/// The source parameter a reparametrized path evaluates at u in [0, 1] (its own solve);
/// u itself for other kinds.
GRAPE_PATH_API double source_parameter(const Path& path, double u) noexcept;

/// The commands of a path made from SVG data (moves, segments, closes, zero-length dots), so
/// that it can be drawn as SVG draws it; nullptr for any other path.
GRAPE_PATH_API const std::vector<SvgSegment>* svg_commands(const Path& path) noexcept;

}  // namespace grape::detail
