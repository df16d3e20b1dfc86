// grape — points at equal arc-length spacing along a 3-D path (fence posts, coins on a track).
#pragma once

#include <grape/export_path.hpp>
#include <grape/frames3.hpp>
#include <grape/path3.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace grape {

/// The most points a sampling returns (2²⁴), bounding its work and memory.
inline constexpr std::size_t max_samples3 = std::size_t{1} << 24;

/// The u of `count` points at equal arc-length spacing, both ends included: length_at(u[i]) =
/// length·i/(count − 1) within ~1e-15·length. count 1 gives {0}, count 0 nothing. Throws
/// grape::Error if count exceeds max_samples3.
GRAPE_PATH_API std::vector<double> equal_length_u(const Path3& path, std::size_t count);

/// The u of the points at arc length 0, spacing, 2·spacing, … up to the length (the end is
/// included only where a multiple of spacing reaches it). Throws grape::Error if spacing is not
/// finite and > 0, or if that gives more than max_samples3 points.
GRAPE_PATH_API std::vector<double> spaced_u(const Path3& path, double spacing);

/// The frames at each u, in order (for posts or coins that face along the path).
GRAPE_PATH_API std::vector<Frame3> frames_at(const Frames3& frames, std::span<const double> u);

}  // namespace grape
