// grape — what modules that evaluate paths in bulk (anim's tick) may know of a path beyond
// path.hpp: a kind to switch on, copied coefficients of lines and cubics, and the arc-length
// table of a reparametrized line or cubic. Owned by the path module, built by make_kernel,
// reached through the build-only target grape::path_internal (not installed).
#pragma once

#include "svg_segment.hpp"

#include <grape/detail/line_allocator.hpp>
#include <grape/path.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <new>
#include <optional>
#include <span>
#include <vector>

namespace grape::detail {

/// v(u) of a reparametrized path (u: fraction of arc length, v: the source's parameter) as
/// K even pieces (K a power of two), each a degree-11 polynomial in the piece's own x in
/// [−1, 1] held in one 64-byte cache line: the four leading coefficients as doubles, the
/// eight others as floats (each below ~1e-6 there, so float's 6e-8 relative rounding adds
/// under 1e-12 to v, against the 1e-10 budget; checked by the build and the tests). A lookup costs a floor and a dozen
/// multiply-adds in a shallow tree, where the path's own solve costs a bucket search and a
/// quintic; a typical cubic needs 8 pieces (512 bytes), so a thousand tables stay in L2.
class ArcLengthTable {
public:
    static constexpr int degree = 11;                 ///< of each piece's polynomial
    static constexpr std::size_t stride = 8;          ///< storage words (64 bytes) per piece
    static constexpr int max_steps = 4096;            ///< 256 KB of table at most

    /// The fewest pieces (K = 1, 2, 4, ... 4096) whose points, at 23 places inside every
    /// piece, land within 1e-10·length of the path's own solve (so within 2e-10·length
    /// anywhere: tested); nullopt when the path is not reparametrized, has no length or
    /// needs more than 4096 pieces (a source that stops somewhere: dv/du unbounded).
    static std::optional<ArcLengthTable> build(const Path& reparametrized);

    /// The source parameter at u: 0 at or below 0 (and for NaN), 1 at or above 1.
    double source_u(double u) const noexcept {
        if (!(u > 0.0)) return 0.0;
        return evaluate(values_.data(), steps_, u);
    }
    /// K, the number of pieces.
    double steps() const noexcept { return steps_; }
    /// The pieces' storage, piece after piece (8·K words, 64-byte aligned: a piece is one
    /// cache line): words 0–3 the coefficients of x⁰, x², x¹, x³, words 4–7 the floats of
    /// x⁴, x⁶, x⁵, x⁷, x⁸, x¹⁰, x⁹, x¹¹ (the pairs evaluate reads two at a time).
    std::span<const double> values() const noexcept { return {values_.data(), values_.size()}; }

    /// source_u on a table's raw storage (for callers that keep a pointer in a hot record),
    /// u in [0, 1]. The ends are exact (0 and 1), so that animations start and land on the
    /// end points; K is a power of two, so u·K is exact and u < 1 never reads past the
    /// last piece.
    static double evaluate(const double* values, double steps, double u) noexcept {
        if (u >= 1.0) return 1.0;
        if (u <= 0.0) return 0.0;
        const double s = u * steps;
        const auto k = static_cast<std::int64_t>(s);  // s > 0: truncation is the floor, one instruction
        const double x = 2.0 * (s - static_cast<double>(k)) - 1.0;
        const double* c = values + stride * static_cast<std::size_t>(k);
        // Estrin's scheme on the pairs (q0, q1) = (c0, c2) + (c1, c3)·x, (q2, q3), (q4, q5):
        // v = (q0 + q2·x⁴ + q4·x⁸) + (q1 + q3·x⁴ + q5·x⁸)·x², a third of Horner's chain, two
        // lanes at a time where SSE2 has them.
        const double x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
#if defined(__SSE2__)
        const __m128d vx = _mm_set1_pd(x);
        const __m128d q01 = _mm_add_pd(_mm_load_pd(c), _mm_mul_pd(_mm_load_pd(c + 2), vx));
        const __m128 f = _mm_castpd_ps(_mm_load_pd(c + 4)), g = _mm_castpd_ps(_mm_load_pd(c + 6));
        const __m128d q23 = _mm_add_pd(_mm_cvtps_pd(f), _mm_mul_pd(_mm_cvtps_pd(_mm_movehl_ps(f, f)), vx));
        const __m128d q45 = _mm_add_pd(_mm_cvtps_pd(g), _mm_mul_pd(_mm_cvtps_pd(_mm_movehl_ps(g, g)), vx));
        const __m128d sum = _mm_add_pd(_mm_add_pd(q01, _mm_mul_pd(q23, _mm_set1_pd(x4))), _mm_mul_pd(q45, _mm_set1_pd(x8)));
        return _mm_cvtsd_f64(sum) + _mm_cvtsd_f64(_mm_unpackhi_pd(sum, sum)) * x2;
#else
        float f[8];
        std::memcpy(f, c + 4, sizeof f);
        const double q0 = c[0] + c[2] * x, q1 = c[1] + c[3] * x;
        const double q2 = double(f[0]) + double(f[2]) * x, q3 = double(f[1]) + double(f[3]) * x;
        const double q4 = double(f[4]) + double(f[6]) * x, q5 = double(f[5]) + double(f[7]) * x;
        return (q0 + q2 * x4 + q4 * x8) + (q1 + q3 * x4 + q5 * x8) * x2;
#endif
    }

private:
    // Cache-line aligned storage, so that no piece straddles two lines.
    std::vector<double, LineAllocator<double>> values_;
    double steps_ = 0.0;
};

/// How a kernel evaluates inside [0, 1].
enum class KernelKind : std::uint8_t {
    generic,         ///< Path::point
    linear,          ///< c[0] + c[1]·u
    cubic,           ///< ((c[3]·u + c[2])·u + c[1])·u + c[0]
    reparam_linear,  ///< linear at v = table.source_u(u)
    reparam_cubic,   ///< cubic at v = table.source_u(u)
};

/// A path as a bulk evaluator sees it. Inside [0, 1] the formulas above give Path::point
/// bit for bit (linear, cubic) or within 2e-10·length (reparametrized, by the table).
struct PathKernel {
    KernelKind kind = KernelKind::generic;
    Vec2 c[4] = {};  ///< linear: start, end − start; cubic: power-basis coefficients (of the source)
    std::optional<ArcLengthTable> table;  ///< reparam_*: v(u) (its buffer survives moving the kernel)
};

/// The kernel of a path (builds the arc-length table of a reparametrized line or cubic).
PathKernel make_kernel(const Path& path);
/// The shape's identity: equal for copies of one Path (a key for tables of shared paths).
const void* shape_id(const Path& path) noexcept;
/// The parameters 0 = b0 < b1 < ... < bk = 1 between which the path is smooth (spline
/// joins, cues, cusps, quarter turns).
std::span<const double> smooth_breaks(const Path& path) noexcept;
/// The source parameter a reparametrized path evaluates at u in [0, 1] (its own solve);
/// u itself for other kinds.
double source_parameter(const Path& path, double u) noexcept;

/// The commands of a path made from SVG data (moves, segments, closes, zero-length dots), so
/// that it can be drawn as SVG draws it; nullptr for any other path.
const std::vector<SvgSegment>* svg_commands(const Path& path) noexcept;

}  // namespace grape::detail
