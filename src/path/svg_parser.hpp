// SVG path data → a flat list of drawn segments (private to the path module; in svg.cpp).
//
// The parser knows nothing about Path objects: it turns the text into absolute geometry
// (lines, quadratic and cubic Béziers, centre-parametrized elliptical arcs), so that
// parse_svg_path only has to wrap each segment in its path kind, and the grammar can be read
// on its own.
#pragma once

#include <grape/math.hpp>

#include <array>
#include <string_view>
#include <vector>

namespace grape::detail {

/// One drawn piece of SVG path data, in absolute coordinates (y down).
struct SvgSegment {
    enum class Kind { line, quadratic, cubic, arc };
    Kind kind = Kind::line;
    /// Line: p[0..1]; quadratic: p[0..2]; cubic: p[0..3]; arc: p[0] start, p[1] end (as written).
    std::array<Vec2, 4> p{};
    /// Arc only: point = centre + R(rotation)·(rx·cos θ, ry·sin θ), θ from start_angle to
    /// end_angle (radians; increasing θ turns clockwise on screen, as SVG's sweep flag 1).
    Vec2 centre{};
    double rx = 0.0;
    double ry = 0.0;
    double rotation = 0.0;  ///< radians, in [0, 2π)
    double start_angle = 0.0;
    double end_angle = 0.0;
    /// Which subpath (0, 1, ...) the segment belongs to; a new one starts at every moveto.
    int subpath = 0;
    /// Character offset of the command that drew it (for error messages).
    std::size_t offset = 0;
};

/// Every drawn segment of `data`, in order. Zero-length segments are left out; moves between
/// subpaths are not segments. Throws grape::Error ("SVG path data: ... at offset N") on a
/// syntax error or a number that does not fit in a double. An empty result is NOT an error
/// here (the caller decides).
std::vector<SvgSegment> parse_svg_segments(std::string_view data);

/// The SVG implementation notes' endpoint → centre conversion (F.6.5, F.6.6) for an arc from
/// `from` to `to`. Returns false when the arc is a straight line (a zero radius, or endpoints
/// too close for the radii to matter) and true after filling the arc fields of `out`.
/// Callers have already dropped arcs whose endpoints coincide.
bool svg_arc_to_centre(Vec2 from, Vec2 to, double rx, double ry, double rotation_degrees,
                       bool large_arc, bool sweep, SvgSegment& out) noexcept;

}  // namespace grape::detail
