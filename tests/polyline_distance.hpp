// Test helper shared by the path and render tests: how far a point lies from a polyline.
#pragma once

#include <grape/math.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace grape::testing {

/// Shortest distance from p to the polyline through `line` (infinity for fewer than 2 points).
inline double distance_to_polyline(Vec2 p, const std::vector<Vec2>& line) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const Vec2 d = line[i + 1] - line[i];
        const double l2 = length_squared(d);
        const double t = l2 > 0.0 ? std::clamp(dot(p - line[i], d) / l2, 0.0, 1.0) : 0.0;
        best = std::min(best, distance(p, line[i] + d * t));
    }
    return best;
}

}  // namespace grape::testing
