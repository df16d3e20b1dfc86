// grape — what modules that evaluate paths in bulk (anim's tick) may know of a path beyond
// path.hpp: a kind to switch on, copied coefficients of lines and cubics, and the arc-length
// table of a reparametrized line or cubic. Owned by the path module, built by make_kernel,
// reached through the build-only target grape::path_internal (not installed).
#pragma once

#include "svg_segment.hpp"

#include <grape/path.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace grape::detail {

/// v(u) of a reparametrized path (u: fraction of arc length, v: the source's parameter) as
/// cubic Hermite steps: v and dv/du·h at K + 1 even steps h = 1/K. One step costs a
/// polynomial, where the path's own solve costs a bucket search and a quintic.
class ArcLengthTable {
public:
    /// The coarsest table (K = 64, 128, ... 16384) whose points, at three places inside
    /// every step, land within 1e-10·length of the path's own solve; nullopt when the path
    /// is not reparametrized, has no length, stops somewhere (dv/du unbounded) or needs more
    /// than 16384 steps.
    static std::optional<ArcLengthTable> build(const Path& reparametrized);

    /// The source parameter at u in [0, 1].
    double source_u(double u) const noexcept { return evaluate(values_.data(), steps_, u); }
    /// K, the number of steps.
    double steps() const noexcept { return steps_; }
    /// v and dv/du·h at each step, interleaved (2·(K + 1) numbers).
    std::span<const double> values() const noexcept { return values_; }

    /// source_u on a table's raw numbers (for callers that keep a pointer in a hot record).
    static double evaluate(const double* values, double steps, double u) noexcept {
        const double s = u * steps;
        double k = std::floor(s);
        if (k >= steps) k = steps - 1.0;
        const double t = s - k;
        const double* e = values + 2 * static_cast<std::size_t>(k);
        const double t2 = t * t;
        const double t3 = t2 * t;
        return (2.0 * t3 - 3.0 * t2 + 1.0) * e[0] + (t3 - 2.0 * t2 + t) * e[1] + (3.0 * t2 - 2.0 * t3) * e[2] +
               (t3 - t2) * e[3];
    }

private:
    std::vector<double> values_;
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
/// bit for bit (linear, cubic) or within 1e-10·length (reparametrized, by the table).
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
