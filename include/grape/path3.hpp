// grape — 3-D paths: lines, Béziers, Hermite, linear and Catmull–Rom splines, exact circular
// arcs and helices, projectiles, 2-D paths lifted onto a plane, complex paths, arc-length
// reparametrizations and slices; with exact arc length, tight bounds, flattening, Frenet data,
// rotation-minimizing frames and a plain-value description of every path (describe, from_spec).
#pragma once

#include <grape/export_path.hpp>
#include <grape/path.hpp>
#include <grape/path_query.hpp>
#include <grape/vec3.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string_view>
#include <variant>
#include <vector>

namespace grape {

namespace detail {
class Path3Node;
struct Path3Access;
}

/// Every kind of 3-D path, in the order of Path3Spec's alternatives.
enum class Path3Kind {
    line,
    quadratic_bezier,
    cubic_bezier,
    catmull_rom,
    helix,
    complex,
    hermite,
    linear_spline,
    arc,
    projectile,
    on_plane,
    reparametrized,
    slice,
};

/// The kind's name in snake_case ("cubic_bezier").
GRAPE_PATH_API std::string_view to_string(Path3Kind kind) noexcept;

/// An exact circular helix: it starts at center + radius·start and turns counter-clockwise
/// about `axis` (seen from its tip), rising `rise` along the axis per turn.
struct HelixSpec {
    Vec3 center{};             ///< a point on the axis, level with the start
    Vec3 axis{0.0, 0.0, 1.0};  ///< axis direction (any length > 0)
    Vec3 start{1.0, 0.0, 0.0}; ///< direction from the axis to the start; its part along the axis is dropped
    double radius = 1.0;       ///< world units, > 0
    double rise = 0.0;         ///< advance along the axis per turn (negative: left-handed; 0: a circle)
    double turns = 1.0;        ///< number of turns, > 0
};

/// An exact arc of a circle: point = center + radius·(e1·cos θ + e2·sin θ), θ going linearly
/// from `start_angle` (u = 0) to `end_angle` (u = 1), where e1 is `start` without its part
/// along `axis`, normalized, and e2 = axis × e1 (counter-clockwise seen from the axis' tip).
/// Either direction, several turns when the angles are more than 2π apart; equal angles give
/// a point standing still.
struct Arc3Spec {
    Vec3 center{};             ///< the circle's centre
    Vec3 axis{0.0, 0.0, 1.0};  ///< normal of the circle's plane (any length > 0)
    Vec3 start{1.0, 0.0, 0.0}; ///< direction of angle 0 from the centre; its part along the axis is dropped
    double radius = 1.0;       ///< world units, > 0
    double start_angle = 0.0;  ///< radians, at u = 0
    double end_angle = 6.283185307179586;  ///< radians, at u = 1 (default: one full turn)
};

/// An axis-aligned box in 3-D; `min` ≤ `max` componentwise once anything has been added.
struct Bounds3 {
    /// The smallest x, y and z (+∞ while empty).
    Vec3 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity()};
    /// The largest x, y and z (−∞ while empty).
    Vec3 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
             -std::numeric_limits<double>::infinity()};
    /// Grows the box to hold p.
    void add(Vec3 p) noexcept {
        min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
        max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
    }
    /// Grows the box to hold b.
    void add(const Bounds3& b) noexcept { add(b.min); add(b.max); }
    /// p inside or on the box, within tolerance.
    bool contains(Vec3 p, double tolerance = 0.0) const noexcept {
        return p.x >= min.x - tolerance && p.x <= max.x + tolerance && p.y >= min.y - tolerance &&
               p.y <= max.y + tolerance && p.z >= min.z - tolerance && p.z <= max.z + tolerance;
    }
    Vec3 size() const noexcept { return max - min; }  ///< max − min
};

/// Frenet data at a point. Where the curvature is zero (a straight stretch, an inflection) or
/// the speed is zero, the normal is undefined: `normal_defined` is false, `normal` is
/// any_perpendicular(tangent), `binormal` = tangent × normal, curvature and torsion are 0.
struct Frenet3 {
    Vec3 point;                  ///< position
    Vec3 tangent;                ///< unit tangent (at zero speed: the direction of d2, else d3)
    Vec3 normal;                 ///< unit principal normal
    Vec3 binormal;               ///< tangent × normal
    double curvature = 0.0;      ///< κ = |r′ × r″| / |r′|³, per world unit
    double torsion = 0.0;        ///< τ = (r′ × r″)·r‴ / |r′ × r″|², per world unit
    bool normal_defined = false; ///< false where κ = 0 (within rounding) or the speed is 0
};

/// A 3-D path over u in [0, 1]: an immutable value, cheap to copy (a shared handle).
/// Outside [0, 1] it extends along its end tangents, as a 2-D Path does. Evaluation is
/// noexcept and allocation-free; constructors validate and throw grape::Error naming the
/// argument. A default-constructed Path3 stays at the origin (a line of length 0).
class GRAPE_PATH_API Path3 {
public:
    Path3();  ///< a line of length 0 at the origin

    /// Straight line from a (u = 0) to b (u = 1), at constant speed.
    static Path3 line(Vec3 a, Vec3 b);
    /// Quadratic Bézier with control points p0, p1, p2.
    static Path3 quadratic_bezier(Vec3 p0, Vec3 p1, Vec3 p2);
    /// Cubic Bézier with control points p0, p1, p2, p3.
    static Path3 cubic_bezier(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3);
    /// Catmull–Rom spline through ≥ 2 points, in the Barry–Goldman form with knot spacing
    /// |Δp|^α (uniform α = 0, centripetal ½, chordal 1), exactly as the 2-D spline: an open
    /// spline's end segments use mirrored phantom points; a closed one (≥ 3 points) also joins
    /// the last point to the first, with neighbours taken cyclically. Each segment takes an
    /// equal share of u. Coincident neighbours (spacing 0) fall back to spacing 1 there.
    static Path3 catmull_rom(std::span<const Vec3> points, CatmullRom type = CatmullRom::uniform,
                             bool closed = false);
    /// An exact helix (see HelixSpec); u is proportional to arc length.
    static Path3 helix(const HelixSpec& spec);
    /// Several paths as one, as a 2-D ComplexPath: part i spans u in [cues[i], cues[i+1]) of
    /// the whole, the last part ends at 1. Cues start at 0, never decrease and stay in [0, 1];
    /// a part whose span is empty is skipped. Derivatives follow the chain rule.
    static Path3 complex(std::vector<Path3> parts, std::vector<double> cues);
    /// A complex path whose cues come from the parts' lengths (zero-length parts get empty
    /// spans; if all are zero, u is shared evenly).
    static Path3 complex_by_length(std::vector<Path3> parts);
    /// Cubic Hermite spline through ≥ 2 points with one tangent per point (d/dt of each
    /// segment's local t in [0, 1], as the 2-D HermiteSplinePath); each segment takes an equal
    /// share of u. `closed` (≥ 3 points) adds the segment from the last point to the first.
    static Path3 hermite(std::span<const Vec3> points, std::span<const Vec3> tangents, bool closed = false);
    /// Straight segments through ≥ 2 points (`closed`: ≥ 3, and back to the first), each
    /// segment an equal share of u, at constant speed within a segment.
    static Path3 linear_spline(std::span<const Vec3> points, bool closed = false);
    /// An exact circular arc (see Arc3Spec): length radius·|end_angle − start_angle|, d1–d3
    /// in closed form.
    static Path3 arc(const Arc3Spec& spec);
    /// A projectile: position + velocity·t + ½·acceleration·t², t = u·seconds (seconds > 0):
    /// an exact parabola (evaluated as the quadratic Bézier it is).
    static Path3 projectile(Vec3 position, Vec3 velocity, Vec3 acceleration, double seconds);
    /// Any 2-D path (every kind, SVG paths included) on the plane through `origin` spanned by
    /// `x_axis` and `y_axis`: point(u) = origin + x_axis·p.x + y_axis·p.y with p = path.point(u),
    /// and d1, d2 the same image of the 2-D path's. The axes must be orthogonal and of equal
    /// length s > 0 (both within 1e-12 relative; unit axes keep the 2-D sizes), so distances
    /// scale by s = |x_axis|: length() is s·path.length(), length_at and u_at_length are the
    /// 2-D path's scaled. The 2-D paths give no third derivative: d3 is the image of a central
    /// difference of d2 inside the piece (one-sided at its ends), to ~1e-7 relative; it lies in
    /// the plane, so the torsion stays 0 to rounding.
    static Path3 on_plane(Path path, Vec3 origin, Vec3 x_axis, Vec3 y_axis);

    Path3Kind kind() const noexcept;  ///< what the path was built as
    Vec3 point(double u) const noexcept;  ///< position at u
    Vec3 d1(double u) const noexcept;  ///< dpoint/du
    Vec3 d2(double u) const noexcept;  ///< d²point/du²
    Vec3 d3(double u) const noexcept;  ///< d³point/du³
    /// Unit tangent at u (at zero speed: the direction of d2, else of d3; never NaN).
    Vec3 tangent(double u) const noexcept;
    /// Tangent, normal, binormal, curvature and torsion at u (u clamped to [0, 1]).
    Frenet3 frenet(double u) const noexcept;

    /// Arc length over [0, 1]: adaptive Gauss–Legendre to ~1e-14 relative, or the closed form.
    double length() const noexcept;
    /// Arc length over [0, u] (u clamped to [0, 1]).
    double length_at(double u) const noexcept;
    /// The u at which length_at(u) = s (s clamped to [0, length()]); u within ~1e-15.
    double u_at_length(double s) const noexcept;
    /// The point at arc length s from the start (point(u_at_length(s))).
    Vec3 point_at_length(double s) const noexcept;

    /// The u values, 0 and 1 included, where a piece starts or ends (spline segments, parts
    /// of a complex path): derivatives may jump there, and nowhere else.
    std::span<const double> breaks() const noexcept;

    /// Tight axis-aligned box of the path over [0, 1], computed once: the exact extremes of
    /// each piece (derivative roots in closed form for Béziers, splines, arcs and helices;
    /// for lifted 2-D paths, slices and the rest, d1's roots bracketed by 64 samples per piece
    /// and bisected to adjacent doubles).
    const Bounds3& bounds() const noexcept;

    /// A polyline from point(0) to point(1) with every point of the path within `tolerance`
    /// of it: intervals are halved until the chord error bound sup|d2|·h²/8 is within the
    /// tolerance (lifted 2-D paths use the 2-D flattening; a complex path's parts are
    /// flattened one by one, joined by a straight segment where they do not meet). Tolerances
    /// below 1e-12 of the path's size are raised to it. Throws grape::Error if the tolerance
    /// is not positive and finite.
    std::vector<Vec3> flatten(double tolerance) const;

    /// The same shape at constant speed: point(u) of the result lies at arc length u·length()
    /// along this path (to 1e-9·length()), |d1| = length() and d2, d3 by the chain rule. Built
    /// once: a table of spans with the quintic Hermite model of the inverse of the arc length,
    /// each checked against quadrature; spans where the path stops (zero speed), or whose
    /// model misses, solve u_at_length instead (at most 256 spans per piece bound the work).
    /// Building costs ~0.4 ms for a cubic and ~4 s for a 10⁴-segment spline; evaluation is
    /// a binary search and one polynomial (~0.1 µs). Reparametrizing a reparametrized path
    /// returns it unchanged.
    Path3 reparametrized() const;

private:
    explicit Path3(std::shared_ptr<const detail::Path3Node> node) noexcept;
    std::shared_ptr<const detail::Path3Node> node_;
    friend struct detail::Path3Access;
};

/// The point of a path nearest to a query point (closest_point).
struct Closest3 {
    double u = 0.0;         ///< parameter of the nearest point found
    Vec3 point;             ///< path.point(u)
    double distance = 0.0;  ///< |point − query|
    /// Proven: no point of the path is nearer the query than distance − gap.
    double gap = 0.0;
};

/// The globally nearest point of `path` (u in [0, 1]) to `query`: each piece is subdivided,
/// every interval bounded below by its midpoint tangent segment less sup|d2|·h²/8, intervals
/// that cannot beat the best point found pruned, and the survivors polished by Newton steps
/// on (point − query)·d1 = 0. The gap returned is within ~1e-13·(length + distance), except
/// where a long stretch is equidistant from the query (a circle about it), where the work is
/// capped (2¹⁵ intervals) and the gap is what was proven; and except on a lifted 2-D path
/// reparametrized by arc length, whose d2 has no bound: nothing is pruned there, the work is
/// capped likewise and the gap may be infinite. Of exact ties the smaller u wins.
/// Noexcept and allocation-free.
GRAPE_PATH_API Closest3 closest_point(const Path3& path, Vec3 query) noexcept;

/// A rotation-minimizing (parallel-transport) frame along a path: the moving frame whose
/// normal turns only as much as the tangent forces it to (no spin about the tangent).
struct Frame3 {
    Vec3 point;     ///< position
    Vec3 tangent;   ///< unit tangent
    Vec3 normal;    ///< unit, ⟂ tangent: the transported up vector
    Vec3 binormal;  ///< tangent × normal
};

/// Rotation-minimizing frames of one path, built once: a table of frames at knots placed by
/// the error of the double-reflection method (Wang, Jüttler, Zheng, Liu, ACM TOG 27(1), 2008),
/// refined until each step's estimated roll error, against two half steps, is within its
/// share of `tolerance` radians for the whole path (half by chord length, half by u, so that
/// a near-stop, where chords shrink and the tangent still turns, does not starve the steps);
/// every break of the path is a knot. The table holds at most `max_knots` knots: a path that
/// needs more (a cusp, where the frame is not defined) is refused with grape::Error. At a break where the tangent jumps the frame turns by the least rotation that
/// takes the tangent before to the tangent after, so the frame stays continuous wherever the
/// path is C¹. A closed path's frame need not close up (its end differs by the holonomy).
class GRAPE_PATH_API RotationMinimizingFrames {
public:
    /// `up`: the normal at u = 0 is up without its part along the tangent there; it must be
    /// finite and not parallel to that tangent. `tolerance`: radians over the whole path, in
    /// [1e-13, 0.1]. Throws grape::Error for bad arguments and for a path that needs more than
    /// `max_knots` knots at that tolerance.
    RotationMinimizingFrames(Path3 path, Vec3 up, double tolerance = 1e-9);

    /// The most knots a table holds (2²⁰: 84 MiB with its index), bounding the work of a build.
    static constexpr std::size_t max_knots = std::size_t{1} << 20;

    /// The frame at u (clamped to [0, 1]): one double-reflection step from the knot at or
    /// before u, found through an index of equal steps in u (O(1) where knots are even).
    /// Orthonormal within a few ulp.
    Frame3 frame(double u) const noexcept;
    const Path3& path() const noexcept;  ///< the path framed
    std::size_t knot_count() const noexcept;  ///< size of the table
    double knot_u(std::size_t i) const noexcept;  ///< u of knot i (increasing; i < knot_count())

    /// One double-reflection step: the normal at (x1, t1) transported from the frame (x0, t0,
    /// r0), with unit tangents t0, t1 and r0 ⟂ t0. Fourth-order accurate in the step.
    static Vec3 double_reflection(Vec3 x0, Vec3 t0, Vec3 r0, Vec3 x1, Vec3 t1) noexcept;

private:
    // A knot keeps the path's point and tangent there, so a lookup evaluates the path at u only.
    struct Knot {
        double u;
        Vec3 normal;
        Vec3 point;
        Vec3 tangent;
    };
    Path3 path_;
    std::vector<Knot> knots_;
    // bucket_[i]: the last knot with u ≤ i / (bucket_.size() − 1).
    std::vector<std::uint32_t> bucket_;
    double buckets_ = 0.0;  // bucket_.size() − 1
};

/// The part of `path` between u0 and u1 (0 ≤ u0 < u1 ≤ 1, finite; throws grape::Error
/// otherwise) as a path of its own (kind slice): point(v) = path.point(u0 + v·(u1 − u0)),
/// exactly path.point(u1) at v = 1, derivatives by the chain rule, length and bounds those of
/// the sub-range.
GRAPE_PATH_API Path3 slice(const Path3& path, double u0, double u1);

/// A smooth 3-D path through sampled points (a recorded flight, a tracked hand), as the 2-D
/// fit_path makes one: cubic Béziers with continuous tangents, every input point within
/// def.tolerance of the path, corners kept where successive chords turn by more than
/// def.corner_angle (Schneider's algorithm), joined as a complex path with cues by length.
/// Consecutive repeated points are dropped; throws grape::Error for fewer than 2 distinct
/// points, a point that is not finite or a bad tolerance or angle.
GRAPE_PATH_API Path3 fit_path(std::span<const Vec3> points, const FitPathDef& def = {});

// --- what a path is: plain values -------------------------------------------------------

/// Path3::line's end points.
struct Line3Spec {
    Vec3 a;  ///< point at u = 0
    Vec3 b;  ///< point at u = 1
};
/// Path3::quadratic_bezier's control points.
struct QuadraticBezier3Spec {
    std::array<Vec3, 3> control;  ///< p0, p1, p2
};
/// Path3::cubic_bezier's control points.
struct CubicBezier3Spec {
    std::array<Vec3, 4> control;  ///< p0, p1, p2, p3
};
/// Path3::catmull_rom's arguments.
struct CatmullRom3Spec {
    std::vector<Vec3> points;               ///< the points passed through
    CatmullRom type = CatmullRom::uniform;  ///< knot spacing
    bool closed = false;                    ///< joined back to the first point
};
/// Path3::complex's parts and cues (complex_by_length gives the cues it computed).
struct Complex3Spec {
    std::vector<Path3> parts;  ///< played one after another
    std::vector<double> cues;  ///< one per part
};
/// Path3::hermite's arguments.
struct Hermite3Spec {
    std::vector<Vec3> points;    ///< the points passed through
    std::vector<Vec3> tangents;  ///< one per point
    bool closed = false;         ///< joined back to the first point
};
/// Path3::linear_spline's arguments.
struct LinearSpline3Spec {
    std::vector<Vec3> points;  ///< the corners
    bool closed = false;       ///< joined back to the first point
};
/// Path3::projectile's arguments.
struct Projectile3Spec {
    Vec3 position;         ///< at t = 0, world units
    Vec3 velocity;         ///< at t = 0, units per second
    Vec3 acceleration;     ///< constant (gravity), units per second²
    double seconds = 1.0;  ///< time at u = 1 (> 0)
};
/// Path3::on_plane's arguments.
struct OnPlane3Spec {
    Path path;                    ///< the 2-D path (describe it in turn)
    Vec3 origin;                  ///< image of the 2-D origin
    Vec3 x_axis{1.0, 0.0, 0.0};   ///< image of the 2-D unit x
    Vec3 y_axis{0.0, 1.0, 0.0};   ///< image of the 2-D unit y
};
/// Path3::reparametrized's source.
struct Reparametrized3Spec {
    Path3 source;  ///< the path reparametrized
};
/// slice's arguments.
struct Slice3Spec {
    Path3 source;     ///< the path sliced
    double u0 = 0.0;  ///< start of the sub-range
    double u1 = 1.0;  ///< end of the sub-range
};

/// Every 3-D kind with its parameters, in Path3Kind's order (`spec.index()` is the kind).
using Path3Spec = std::variant<Line3Spec, QuadraticBezier3Spec, CubicBezier3Spec, CatmullRom3Spec, HelixSpec,
                               Complex3Spec, Hermite3Spec, LinearSpline3Spec, Arc3Spec, Projectile3Spec,
                               OnPlane3Spec, Reparametrized3Spec, Slice3Spec>;

/// The kind and the arguments a path was built from (copies point lists; a query, not for
/// per-frame loops).
GRAPE_PATH_API Path3Spec describe(const Path3& path);
/// The path a spec describes: from_spec(describe(p)) evaluates bit for bit like p. Throws
/// grape::Error as the kind's factory does for invalid parameters.
GRAPE_PATH_API Path3 from_spec(const Path3Spec& spec);
/// The kind a spec describes.
inline Path3Kind kind_of(const Path3Spec& spec) noexcept { return static_cast<Path3Kind>(spec.index()); }

}  // namespace grape
