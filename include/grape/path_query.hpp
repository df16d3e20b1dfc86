// grape — questions game code asks a path: the nearest point (snapping a dragged object to a
// track, "how far along is the player"), curvature and frames (a camera that banks, a car in a
// lane), the part between two parameters as a path of its own, and a path beside a path.
//
//   const grape::ClosestPoint near = grape::closest_point(track, mouse);
//   const grape::PathFrame f = grape::frame(track, near.u);   // tangent, normal, curvature
#pragma once

#include <grape/export_path.hpp>
#include <grape/path.hpp>

#include <string>

namespace grape {

/// \addtogroup path_query
/// @{

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
/// within 1e-13 of the path's size) go to the smallest u: the center of a circle gives its
/// start. Where the parts of a complex path do not meet, a part's end is reached just before
/// the cue of the next (u one double below it). A q that is not finite gives u = 0 and an
/// infinite distance. Allocation-free; work is bounded.
GRAPE_PATH_API ClosestPoint closest_point(const Path& path, Vec2 q) noexcept;

/// The nearest point with u in [u0, u1] (0 ≤ u0 ≤ u1 ≤ 1; throws grape::Error otherwise).
GRAPE_PATH_API ClosestPoint closest_point(const Path& path, Vec2 q, double u0, double u1);

/// The globally nearest point, as closest_point(path, q), starting from `last_u` (the answer
/// for a nearby q a moment ago: a dragged object): Newton from there gives the bound that
/// discards the rest of the path cheaply. Same answer, usually faster.
GRAPE_PATH_API ClosestPoint closest_point_from(const Path& path, Vec2 q, double last_u) noexcept;

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
GRAPE_PATH_API PathFrame frame(const Path& path, double u) noexcept;

/// Signed curvature at u, as in PathFrame.
GRAPE_PATH_API double curvature(const Path& path, double u) noexcept;

/// The part of `path` between u0 and u1 (0 ≤ u0 < u1 ≤ 1; throws grape::Error otherwise) as
/// a path of its own: slice.point(v) = path.point(u0 + v·(u1 − u0)) to rounding, exactly in
/// shape and parameter. A segment slices to a segment, an arc to an arc, a spiral to a spiral, a
/// Bézier to a Bézier (by blossoming: de Casteljau's points), a projectile to a projectile, a
/// linear or cubic (Hermite, Catmull–Rom) spline to a complex path of segments or cubic
/// Béziers, a complex path to the complex path of its sliced parts, a reparametrized path to
/// the reparametrized slice of its source. Sine waves and cosine splines have no exact slice
/// among the kinds (the phase, the easing inside a segment): they throw grape::Error.
GRAPE_PATH_API Path slice(const Path& path, double u0, double u1);

/// The part between arc lengths s0 < s1 in [0, length()]: slice at u_at_length(s0), u_at_length(s1).
GRAPE_PATH_API Path slice_by_length(const Path& path, double s0, double s1);

/// point(u) + distance·normal(u): where something beside the path is (a car in a lane, a
/// positive distance to the frame's normal side), evaluated pointwise.
GRAPE_PATH_API Vec2 offset_point(const Path& path, double u, double distance) noexcept;

/// SVG path data that draws `path` (y down as in SVG), numbers with 17 significant digits:
/// lines, quadratic and cubic Béziers, elliptical arcs (split below half turns), splines as
/// their segments, a complex path part by part (M where a part does not start at the pen).
/// Spirals and sine waves have no SVG form: grape::Error.
GRAPE_PATH_API std::string svg_path_data(const Path& path);

/// True when the path ends where it starts (within 1e-12 of its size): a loop, which an
/// animation can repeat without a jump.
GRAPE_PATH_API bool closed(const Path& path) noexcept;

/// Closed loops through n ≥ 3 points (the last joins the first; do not repeat it): each has
/// n segments sharing u evenly, the seam's tangents wrap around, and point(1) == point(0).
/// A cosine loop (still at every point, kind cosine_spline).
GRAPE_PATH_API Path closed_cosine_spline(std::span<const Vec2> points);
/// A Hermite loop with one tangent per point (kind hermite_spline): C1 at the seam.
GRAPE_PATH_API Path closed_hermite_spline(std::span<const Vec2> points, std::span<const Vec2> tangents);
/// A Catmull–Rom loop: tangents from each point's neighbours, the seam's from the last and
/// first points. Uniform is C1 everywhere (a hermite_spline); centripetal and chordal, whose
/// knot spacings differ per segment, are complex paths of cubic Béziers (one per segment,
/// smooth in direction at every point, the seam included, as the open splines are).
GRAPE_PATH_API Path closed_catmull_rom_spline(std::span<const Vec2> points, CatmullRom type = CatmullRom::uniform);

/// How fit_path turns points into a path.
struct FitPathDef {
    double tolerance = 1.0;        ///< largest distance of any input point from the path, world units (> 0)
    double corner_angle = pi / 3;  ///< a turn sharper than this between successive chords is kept as a corner, radians in (0, π]
};

/// A smooth path through a sequence of sampled points (a mouse drag, a recorded trajectory):
/// cubic Béziers joined with continuous tangents, few of them, every input point within
/// def.tolerance of the path, corners kept where the input turns by more than corner_angle
/// (Schneider's algorithm: least-squares handles along the end tangents, Newton
/// reparametrization, a split at the worst point). Parts have cues by length. Consecutive
/// repeated points are dropped; throws grape::Error for fewer than 2 distinct points, a point
/// that is not finite or a bad tolerance or angle.
GRAPE_PATH_API ComplexPath fit_path(std::span<const Vec2> points, const FitPathDef& def = {});

/// @}

}  // namespace grape
