// grape — path kernels for bulk evaluation and the arc-length table they carry.
#include "kernel.hpp"

#include "path_node.hpp"
#include "svg_parser.hpp"

namespace grape::detail {

// Doubles K until the Hermite table of v(u) lands within 1e-10·length of the node's own
// solve at three points inside every step; gives up where the source stops (dv/du
// unbounded) or K would pass 16384.
std::optional<ArcLengthTable> ArcLengthTable::build(const Path& reparametrized) {
    const PathNode& node = NodeAccess::node(reparametrized);
    if (node.kind() != PathKind::reparametrized) return std::nullopt;
    const auto& r = static_cast<const ReparametrizedNode&>(node);
    const PathNode& source = NodeAccess::node(r.source());
    const double length = r.length();
    if (!(length > 0.0)) return std::nullopt;
    for (int steps = 64; steps <= 16384; steps *= 2) {
        const double k_steps = steps;
        std::vector<double> table(2 * static_cast<std::size_t>(steps + 1));
        bool finite = true;
        for (int k = 0; k <= steps && finite; ++k) {
            const double v = r.source_u(k / k_steps);
            const double speed = grape::length(source.d1(v));
            finite = speed > 1e-12 * length;
            table[2 * k] = v;
            table[2 * k + 1] = finite ? length / speed / k_steps : 0.0;
        }
        if (!finite) return std::nullopt;
        bool good = true;
        for (int k = 0; k < steps && good; ++k) {
            for (double t : {0.25, 0.5, 0.75}) {
                const double u = (k + t) / k_steps;
                const Vec2 exact = source.point(r.source_u(u));
                const Vec2 fast = source.point(evaluate(table.data(), k_steps, u));
                if (distance(exact, fast) > 1e-10 * length) {
                    good = false;
                    break;
                }
            }
        }
        if (good) {
            ArcLengthTable out;
            out.values_ = std::move(table);
            out.steps_ = k_steps;
            return out;
        }
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
            copy_coefficients(source, kernel.c);
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
