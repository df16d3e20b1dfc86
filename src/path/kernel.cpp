// grape — path kernels for bulk evaluation and the arc-length table they carry.
#include "kernel.hpp"

#include "path_node.hpp"
#include "svg_parser.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace grape::detail {

namespace {

// The point on one piece [u0, u0 + du] as two degree-11 polynomials in x = 2(u − u0)/du − 1:
// interpolated at the Chebyshev–Lobatto points (which include both ends, so neighbouring
// pieces meet), their Chebyshev coefficients turned into powers of x; stored as
// ArcLengthTable::evaluate reads them.
template <class F>
void fit_piece(F&& point_of_u, double u0, double du, double* out) {
    constexpr int n = ArcLengthTable::degree;
    Vec2 f[n + 1];
    for (int j = 0; j <= n; ++j) {
        const double x = j == 0 ? 1.0 : j == n ? -1.0 : std::cos(j * pi / n);
        f[j] = point_of_u(u0 + du * 0.5 * (x + 1.0));
    }
    double tm[n + 1][n + 1] = {};  // T_m(x) in powers of x, by T_{m+1} = 2x·T_m − T_{m−1}
    tm[0][0] = 1.0;
    tm[1][1] = 1.0;
    for (int m = 1; m < n; ++m) {
        for (int i = 0; i <= n; ++i) tm[m + 1][i] = (i > 0 ? 2.0 * tm[m][i - 1] : 0.0) - tm[m - 1][i];
    }
    for (int d = 0; d < 2; ++d) {
        double a[n + 1];  // Chebyshev coefficients (discrete cosine transform of the Lobatto values)
        for (int m = 0; m <= n; ++m) {
            double sum = 0.0;
            for (int j = 0; j <= n; ++j) {
                const double w = j == 0 || j == n ? 0.5 : 1.0;
                sum += w * (d == 0 ? f[j].x : f[j].y) * std::cos(m * j * pi / n);
            }
            a[m] = (m == 0 || m == n ? 1.0 : 2.0) * sum / n;
        }
        double b[n + 1] = {};  // in powers of x
        for (int m = 0; m <= n; ++m) {
            for (int i = 0; i <= n; ++i) b[i] += a[m] * tm[m][i];
        }
        for (int i = 0; i <= n; ++i) out[ArcLengthTable::slot(i) + d] = b[i];
    }
}

}  // namespace

// Doubles K until every piece's polynomials land within 1e-10·length of the path's own
// point at 23 places inside it (12 evenly spaced, and the 11 between the Lobatto points,
// where an interpolant's error peaks); gives up past 4096 pieces.
namespace {
bool is_off(const char* value) noexcept { return value && std::strcmp(value, "0") == 0; }
}  // namespace

bool wide_lanes() noexcept {
#if GRAPE_WIDE
    // GRAPE_WIDE_LANES=0 keeps the one-record loops (to compare, and to test them on AVX2 machines).
    static const bool wide = cpu_has_avx2() && !is_off(std::getenv("GRAPE_WIDE_LANES"));
    return wide;
#else
    return false;
#endif
}

std::optional<ArcLengthTable> ArcLengthTable::build(const Path& reparametrized) {
    const PathNode& node = NodeAccess::node(reparametrized);
    if (node.kind() != PathKind::reparametrized) return std::nullopt;
    const double length = node.length();
    if (!(length > 0.0)) return std::nullopt;
    auto point_of_u = [&node](double u) noexcept { return node.point(u); };
    for (int steps = 1; steps <= max_steps; steps *= 2) {
        const double k_steps = steps;
        ArcLengthTable out;
        out.values_.assign(stride * static_cast<std::size_t>(steps), 0.0);
        out.steps_ = k_steps;
        out.start_ = node.point(0.0);
        out.end_ = node.point(1.0);
        bool good = true;
        for (int k = 0; k < steps && good; ++k) {
            double* c = out.values_.data() + stride * static_cast<std::size_t>(k);
            fit_piece(point_of_u, k / k_steps, 1.0 / k_steps, c);
            for (int i = 0; i < 23 && good; ++i) {
                const double t = i < 12 ? (i + 0.5) / 12.0
                                        : 0.5 + 0.25 * (std::cos((i - 12) * pi / degree) + std::cos((i - 11) * pi / degree));
                const double u = (k + t) / k_steps;
                const Vec2 fast = evaluate(out.values_.data(), k_steps, u);
                good = std::isfinite(fast.x) && std::isfinite(fast.y) && distance(node.point(u), fast) <= 1e-10 * length;
            }
        }
        if (good) return out;
    }
    return std::nullopt;
}

namespace {

// Copies the coefficients of a line or cubic node; false for other kinds.
bool copy_coefficients(const PathNode& node, Vec2 (&c)[4]) noexcept {
    if (node.kind() == PathKind::linear) {
        const auto& n = static_cast<const LinearNode&>(node);
        c[0] = n.a;
        c[1] = n.delta;
        return true;
    }
    if (node.kind() == PathKind::cubic_bezier) {
        const auto& n = static_cast<const CubicBezierNode&>(node);
        for (int k = 0; k < 4; ++k) c[k] = n.c[k];
        return true;
    }
    return false;
}

}  // namespace

PathKernel make_kernel(const Path& path) {
    PathKernel kernel;
    const PathNode& node = NodeAccess::node(path);
    switch (node.kind()) {
        case PathKind::linear: kernel.kind = KernelKind::linear; break;
        case PathKind::cubic_bezier: kernel.kind = KernelKind::cubic; break;
        case PathKind::reparametrized: {
            const PathNode& source = NodeAccess::node(static_cast<const ReparametrizedNode&>(node).source());
            if (source.kind() != PathKind::linear && source.kind() != PathKind::cubic_bezier) return kernel;
            kernel.table = ArcLengthTable::build(path);
            if (!kernel.table) return kernel;
            kernel.c[0] = kernel.table->start();
            kernel.c[1] = kernel.table->end();
            kernel.kind = source.kind() == PathKind::linear ? KernelKind::reparam_linear : KernelKind::reparam_cubic;
            return kernel;
        }
        default: return kernel;
    }
    copy_coefficients(node, kernel.c);
    return kernel;
}

const void* shape_id(const Path& path) noexcept { return &NodeAccess::node(path); }

std::span<const double> smooth_breaks(const Path& path) noexcept { return NodeAccess::node(path).breaks(); }

double source_parameter(const Path& path, double u) noexcept {
    const PathNode& node = NodeAccess::node(path);
    if (node.kind() != PathKind::reparametrized) return u;
    return static_cast<const ReparametrizedNode&>(node).source_u(u);
}

const std::vector<SvgSegment>* svg_commands(const Path& path) noexcept {
    const auto* node = dynamic_cast<const SvgNode*>(&NodeAccess::node(path));
    return node ? &node->commands : nullptr;
}

}  // namespace grape::detail
