// grape — more nearest-point queries on 3-D paths: to a ray (picking with the mouse) and a
// cheap local one from a hint (a point being dragged).
#pragma once

#include <grape/export_path.hpp>
#include <grape/path3.hpp>
#include <grape/vec3.hpp>

namespace grape {

/// The point of a path nearest to a ray (closest_point_to_ray).
struct RayClosest3 {
    double u = 0.0;         ///< parameter of the nearest point found
    Vec3 point;             ///< path.point(u)
    double distance = 0.0;  ///< distance from point to the ray
    double t = 0.0;         ///< where along the ray, ≥ 0: the ray's nearest point is origin + t·unit(direction)
    /// Proven: no point of the path is nearer the ray than distance − gap.
    double gap = 0.0;
};

/// The globally nearest point of `path` (u in [0, 1]) to the ray origin + t·direction, t ≥ 0:
/// the same branch and bound as closest_point, each interval bounded below by the distance
/// from its midpoint tangent segment to the ray less sup|d2|·h²/8, the survivors polished by
/// Newton steps on the distance to the ray. t is measured in units of |direction| = 1 (the
/// direction is normalized); a zero direction makes it closest_point to the origin. The gap
/// is within ~1e-13·(length + distance) except where a long stretch is equidistant from the
/// ray (a circle about it), where the work is capped (2¹⁵ intervals) and the gap is what was
/// proven. Of exact ties the smaller u wins. Noexcept and allocation-free.
GRAPE_PATH_API RayClosest3 closest_point_to_ray(const Path3& path, Vec3 origin, Vec3 direction) noexcept;

/// A local nearest point for a query that moves a little between calls (a dragged point):
/// damped Newton steps on (point − query)·d1 = 0 from u_hint (clamped to [0, 1]), at most 32,
/// each moving the point by at most half its distance from the query and accepted only if it
/// is not farther. It finds the nearest point of the valley the hint lies in, not the global
/// one (use closest_point for that, or to re-seed after a jump): nothing is proven, so gap =
/// distance. A few evaluations instead of closest_point's thousands. Noexcept and
/// allocation-free.
GRAPE_PATH_API Closest3 closest_point_near(const Path3& path, Vec3 query, double u_hint) noexcept;

}  // namespace grape
