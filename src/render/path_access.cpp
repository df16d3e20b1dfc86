// Reads the path module's node types (src/path/kinds.hpp): the only render source that does.
#include "path_access.hpp"

#include "kinds.hpp"
#include "path_node.hpp"
#include "svg_parser.hpp"

namespace grape::detail {

std::optional<ComplexView> complex_view(const Path& path) noexcept {
    const auto* node = dynamic_cast<const ComplexNode*>(&path.node());
    if (!node || node->parts.empty() || node->cues.size() != node->parts.size()) return std::nullopt;
    return ComplexView{node->parts, node->cues};
}

std::size_t spline_segments(const Path& path) noexcept {
    if (const auto* cubic = dynamic_cast<const CubicSplineNode*>(&path.node())) return cubic->segments.size();
    if (const auto* poly = dynamic_cast<const PolylineNode*>(&path.node()))
        return poly->points.empty() ? 0 : poly->points.size() - 1;
    return 0;
}

const Path* reparametrized_source(const Path& path) noexcept {
    const auto* node = dynamic_cast<const ReparametrizedNode*>(&path.node());
    return node ? &node->source() : nullptr;
}

const std::vector<SvgSegment>* svg_commands(const Path& path) noexcept {
    const auto* node = dynamic_cast<const SvgNode*>(&path.node());
    return node ? &node->commands : nullptr;
}

}  // namespace grape::detail
