// grape — questions game code asks a path: the nearest point (snapping a dragged object to a
// track, "how far along is the player"), curvature and frames (a camera that banks, a car in a
// lane), the part between two parameters as a path of its own, and a path beside a path.
//
//   const grape::ClosestPoint near = grape::closest_point(track, mouse);
//   const grape::PathFrame f = grape::frame(track, near.u);   // tangent, normal, curvature
#pragma once

#include <grape/path.hpp>

namespace grape {

/// The nearest point of a path to a query point.
struct ClosestPoint {
    double u = 0.0;         ///< the path's parameter there, in [0, 1]
    Vec2 point;             ///< path.point(u)
    double distance = 0.0;  ///< |query − point|, world units
};

/// The globally nearest point of `path` over u in [0, 1] to `q` (not a local minimum), its
/// distance within 1e-12 of the path's size of the true minimum, for every kind. The search is
/// branch and bound over the smooth pieces with proven bounds on |x″| and |x‴| per span, so no
/// nearer point can hide between the spans it discards; Newton on the analytic derivatives
/// finishes where the squared distance is provably convex. Ties (points whose distances agree
/// within 1e-13 of the path's size) go to the smallest u: the centre of a circle gives its
/// start. Where the parts of a complex path do not meet, a part's end is reached just before
/// the cue of the next (u one double below it). A q that is not finite gives u = 0 and an
/// infinite distance. Allocation-free; work is bounded.
ClosestPoint closest_point(const Path& path, Vec2 q) noexcept;

/// The nearest point with u in [u0, u1] (0 ≤ u0 ≤ u1 ≤ 1; throws grape::Error otherwise).
ClosestPoint closest_point(const Path& path, Vec2 q, double u0, double u1);

/// The globally nearest point, as closest_point(path, q), starting from `last_u` (the answer
/// for a nearby q a moment ago: a dragged object): Newton from there gives the bound that
/// discards the rest of the path cheaply. Same answer, usually faster.
ClosestPoint closest_point_from(const Path& path, Vec2 q, double last_u) noexcept;

/// The moving frame at u: unit tangent, unit normal (the tangent turned a quarter turn,
/// perpendicular() of it: to the left in y-up axes, to the right on a y-down screen) and the
/// signed curvature κ = cross(x′, x″)/|x′|³ (positive where the path turns towards the
/// normal; 1/r on a circle whose angle increases). Where the path stands still (x′ = 0) the
/// tangent is the direction it leaves in (x″, or the chord onward) and κ is 0.
struct PathFrame {
    Vec2 point;              ///< path.point(u)
    Vec2 tangent;            ///< unit vector along x′(u)
    Vec2 normal;             ///< perpendicular(tangent)
    double curvature = 0.0;  ///< κ, 1 / world units
};

/// The frame at u (outside [0, 1], that of the end-tangent extension: curvature 0).
PathFrame frame(const Path& path, double u) noexcept;

/// Signed curvature at u, as in PathFrame.
double curvature(const Path& path, double u) noexcept;

}  // namespace grape
