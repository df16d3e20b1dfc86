// SVG path data → a flat list of drawing commands (private to the path module; in svg.cpp).
//
// The parser knows nothing about Path objects: it turns the text into absolute geometry
// (moves, lines, quadratic and cubic Béziers, center-parametrized elliptical arcs, closes),
// so that parse_svg_path only has to wrap each drawn segment in its path kind, and the
// grammar can be read on its own. The same list, kept beside the path, lets render draw the
// data as SVG does (closed subpaths get joins, zero-length subpaths get round-cap dots).
#pragma once

#include "kinds.hpp"
#include "svg_segment.hpp"

#include <grape/math.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace grape::detail {

/// What the grammar read: every command up to the first error, and that error.
struct SvgCommands {
    std::vector<SvgSegment> commands;  ///< in order; every segment before the error
    bool ok = true;                    ///< false when the data broke the grammar
    std::size_t error_offset = 0;      ///< character offset of the error
    std::string error;                 ///< "SVG path data: expected ... at offset N, found ..."
};

/// Reads `data` by SVG's error rule: the commands up to (not including) the one holding the
/// first error, each implicit repetition of a command counting as a command of its own, as
/// browsers draw it. Arcs whose endpoints coincide are left out (SVG F.6.2). Never throws
/// grape::Error.
SvgCommands parse_svg_segments(std::string_view data);

/// The SVG implementation notes' endpoint → center conversion (F.6.5, F.6.6) for an arc from
/// `from` to `to`. Returns false when the arc is a straight line (a zero radius, or endpoints
/// too close for the radii to matter) and true after filling the arc fields of `out`.
/// Callers have already dropped arcs whose endpoints coincide.
bool svg_arc_to_center(Vec2 from, Vec2 to, double rx, double ry, double rotation_degrees,
                       bool large_arc, bool sweep, SvgSegment& out) noexcept;

/// A ComplexPath made from SVG path data: the parts and cues as any complex path, plus the
/// commands, so that render can close subpaths and draw zero-length ones as SVG does.
class SvgNode final : public ComplexNode {
public:
    SvgNode(std::vector<Path> parts, std::vector<double> cues, std::vector<SvgSegment> commands)
        : ComplexNode(std::move(parts), std::move(cues)), commands(std::move(commands)) {}
    const std::vector<SvgSegment> commands;  ///< as parsed (moves, segments, closes)
};

}  // namespace grape::detail
