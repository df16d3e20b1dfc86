// grape — 3-D paths: lines, Béziers, Catmull–Rom splines, an exact helix and complex paths,
// with exact arc length, Frenet data and rotation-minimizing frames.
#pragma once

#include <grape/export_path.hpp>
#include <grape/path.hpp>
#include <grape/vec3.hpp>

#include <memory>
#include <span>
#include <string_view>
#include <vector>

namespace grape {

namespace detail {
class Path3Node;
struct Path3Access;
}

/// Every kind of 3-D path.
enum class Path3Kind { line, quadratic_bezier, cubic_bezier, catmull_rom, helix, complex };

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
/// capped (2¹⁵ intervals) and the gap is what was proven. Of exact ties the smaller u wins.
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

    /// The most knots a table holds (2²⁰: 32 MiB), bounding the work of a build.
    static constexpr std::size_t max_knots = std::size_t{1} << 20;

    /// The frame at u (clamped to [0, 1]): one double-reflection step from the knot at or
    /// before u. Orthonormal within a few ulp.
    Frame3 frame(double u) const noexcept;
    const Path3& path() const noexcept;  ///< the path framed
    std::size_t knot_count() const noexcept;  ///< size of the table
    double knot_u(std::size_t i) const noexcept;  ///< u of knot i (increasing; i < knot_count())

    /// One double-reflection step: the normal at (x1, t1) transported from the frame (x0, t0,
    /// r0), with unit tangents t0, t1 and r0 ⟂ t0. Fourth-order accurate in the step.
    static Vec3 double_reflection(Vec3 x0, Vec3 t0, Vec3 r0, Vec3 x1, Vec3 t1) noexcept;

private:
    struct Knot {
        double u;
        Vec3 normal;
    };
    Path3 path_;
    std::vector<Knot> knots_;
};

}  // namespace grape
