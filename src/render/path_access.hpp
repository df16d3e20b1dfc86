// What render needs to know about a path beyond its public evaluation: the parts and cues
// of a complex path, the segment count of a spline, the source of a reparametrized path, the
// commands of SVG data.
// Kept in one place because it reads the path module's internals.
#pragma once

#include <grape/path.hpp>

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace grape::detail {

/// The parts and cues of a complex path (views into the path, valid while it lives).
struct ComplexView {
    std::span<const Path> parts;
    std::span<const double> cues;
};

/// The parts and cues when `path` is complex; nullopt otherwise.
std::optional<ComplexView> complex_view(const Path& path) noexcept;
/// The number of segments (points − 1) of a linear, Hermite or Catmull–Rom spline; 0 otherwise.
std::size_t spline_segments(const Path& path) noexcept;
/// The path a reparametrized path was made from; nullptr otherwise.
const Path* reparametrized_source(const Path& path) noexcept;
struct SvgSegment;
/// The commands of a path made from SVG data (moves, segments, closes); nullptr otherwise.
const std::vector<SvgSegment>* svg_commands(const Path& path) noexcept;

}  // namespace grape::detail
