// The Paths tab's list: paths with the points a drag edits (Bézier control points, spline
// points), built from any Path through its public description and rebuilt from moved points.
#pragma once

#include <grape/math.hpp>
#include <grape/path.hpp>

#include <string>
#include <vector>

namespace grape::studio {

struct PathEntry {
    std::string name;
    Path path;
    std::vector<Vec2> controls;  // the points a drag moves: Bézier control points or spline points
    bool bezier = false;         // draw the control polygon
};

/// The entry of a path: its movable points read from describe(path).
PathEntry entry_from_path(std::string name, const Path& path);

/// Every path of the scene catalogue, in its order (the original's, then one of every kind).
std::vector<PathEntry> path_catalogue();

/// The entry's path with its points moved to `controls`, reparametrized again if it was
/// (throws grape::Error for a degenerate set).
Path rebuild(const PathEntry& e);

}  // namespace grape::studio
