// One command of SVG path data as plain geometry: what the parser produces and what render
// draws from (closed subpaths get joins, zero-length subpaths round-cap dots). Its own
// header so that the path kernel can hand the commands out without the node headers.
#pragma once

#include <grape/math.hpp>

#include <array>
#include <cstddef>

namespace grape::detail {

/// One command of SVG path data, in absolute coordinates (y down).
struct SvgSegment {
    /// move: p[0] starts a subpath; close: Z (p[0] the subpath's start); the rest are drawn.
    enum class Kind { line, quadratic, cubic, arc, move, close };
    Kind kind = Kind::line;
    /// Line: p[0..1]; quadratic: p[0..2]; cubic: p[0..3]; arc: p[0] start, p[1] end (as written).
    std::array<Vec2, 4> p{};
    /// Arc only: point = center + R(rotation)·(rx·cos θ, ry·sin θ), θ from start_angle to
    /// end_angle (radians; increasing θ turns clockwise on screen, as SVG's sweep flag 1).
    Vec2 center{};
    double rx = 0.0;
    double ry = 0.0;
    double rotation = 0.0;  ///< radians, in [0, 2π)
    double start_angle = 0.0;
    double end_angle = 0.0;
    /// Which subpath (0, 1, ...) the command belongs to; a new one starts at every moveto.
    int subpath = 0;
    /// Character offset of the command that drew it (for error messages).
    std::size_t offset = 0;
    /// A line, quadratic or cubic whose points all coincide: nothing to travel, but drawn as
    /// a dot with round caps.
    bool zero_length = false;
    /// The line Z draws back to the subpath's start (followed by a close command).
    bool closing = false;

    /// True for line, quadratic, cubic and arc.
    bool drawn() const noexcept { return kind != Kind::move && kind != Kind::close; }
};

}  // namespace grape::detail
