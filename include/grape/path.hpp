// grape — paths: where an animation goes. A path maps u in [0, 1] to a point.
//
// `Path` is a cheap-to-copy handle to an immutable, shared shape: one path can drive any
// number of animations and bead simulations at once. Each kind (LinearPath, CirclePath, ...)
// is a `Path` whose constructor validates its arguments (throwing grape::Error) and which
// adds accessors for its own parameters. Evaluation is noexcept and allocation-free.
// Any Path, whatever its static type, says what it is: `describe(path)` gives its kind and
// parameters as a plain value (a PathSpec), `from_spec` builds the same path back, and
// `path_cast<CubicBezierSpec>(path)` reads one kind's parameters if the path is of that kind.
//
//   grape::SpiralPath spiral({100, 100}, 200, 0);
//   grape::Vec2 p = spiral.point(0.5);
//   if (auto c = grape::path_cast<grape::ComplexSpec>(path)) { /* c->parts, c->cues */ }
//
// Threads: a Path (any kind, reparametrized and complex paths included) is immutable after
// construction, so one Path may be read from any number of threads at once (point, tangent,
// derivatives, length, bounds, flattening, copying the handle) with no locking; copies share
// the shape through an atomic reference count. Constructing, assigning or destroying one
// Path object is not synchronized: give each thread its own handle to write.
#pragma once

#include <grape/export_path.hpp>
#include <grape/math.hpp>

#include <array>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace grape {

/// \addtogroup path
/// @{

namespace detail {
class PathNode;  // the shape behind a Path, private to the path module
}

/// Every kind of 2-D path.
enum class PathKind {
    linear,
    circle,
    elliptical_arc,
    spiral,
    sine_wave,
    quadratic_bezier,
    cubic_bezier,
    linear_spline,
    cosine_spline,
    hermite_spline,
    catmull_rom_spline,
    physics,
    complex,
    reparametrized,
};

/// The kind's name in snake_case ("cubic_bezier").
GRAPE_PATH_API std::string_view to_string(PathKind kind) noexcept;

/// A 2-D path. Outside [0, 1] it extends along its end tangents:
/// point(u) = point(0) + u·d1(0) for u < 0 and point(1) + (u − 1)·d1(1) for u > 1,
/// so overshooting easing curves (back, elastic) carry motion past the ends (a path that
/// stops at an end, like a cosine spline, stays there). A default-constructed Path stays at
/// the origin. Where a path is not smooth (spline knots, complex-path cues) d1 and d2 are
/// those of the piece that starts there. A NaN u gives a meaningless point, never a crash.
class GRAPE_PATH_API Path {
public:
    Path();  ///< the origin, standing still

    /// Position at parameter u.
    Vec2 point(double u) const noexcept;
    /// First derivative dx/du (analytic).
    Vec2 d1(double u) const noexcept;
    /// Second derivative d²x/du² (analytic).
    Vec2 d2(double u) const noexcept;
    /// Direction of travel at u in radians, atan2(d1.y, d1.x); 0 where the path stands still.
    double heading(double u) const noexcept;

    /// Arc length over u in [0, 1] (computed once at construction, to ~1e-13 relative).
    double length() const noexcept;
    /// Arc length from 0 to u, u clamped to [0, 1] (closed form or quadrature: a query, not
    /// for per-frame loops — use reparametrized() there).
    double length_at(double u) const noexcept;
    /// The u in [0, 1] where length_at(u) == s (s clamped to [0, length()]), to ~1e-15 in u
    /// (Newton on length_at with bisection safeguard). Where the path stands still over a
    /// stretch of u, one of the u in it.
    double u_at_length(double s) const noexcept;

    /// Axis-aligned box holding the path over [0, 1] (tight: from the analytic extremes
    /// where the kind has them).
    Bounds bounds() const noexcept;

    /// A polyline from point(0) to point(1) that stays within `tolerance` of the path
    /// (distance from every path point to the polyline), with few points: straight kinds give
    /// their corners, circles even angle steps, the rest adaptive subdivision by measured
    /// deviation and curvature. A complex path whose parts do not meet (SVG subpaths) gets a
    /// straight segment across each gap. Tolerances below 1e-12 of the path's size are raised
    /// to it. Throws grape::Error if tolerance is not positive and finite.
    std::vector<Vec2> flatten(double tolerance) const;

    /// The same shape moving at constant speed: point(u) of the result lies at arc length
    /// u·length() along this path (to 1e-9·length(); a length in the denormal range as closely
    /// as its few digits allow), with consistent derivatives (|d1| is
    /// length() everywhere, d2 is the chain rule's). Works for every kind; costs a table
    /// built once (tens of µs for a Bézier, a few KB) and one polynomial per evaluation.
    /// Reparametrizing a reparametrized path returns it unchanged.
    Path reparametrized() const;

    /// Which kind of path this is.
    PathKind kind() const noexcept;

    /// Same shape object (not a geometric comparison).
    friend bool operator==(const Path& a, const Path& b) noexcept { return a.node_ == b.node_; }

protected:
    /// Wraps a built shape; for the path kinds' constructors.
    explicit Path(std::shared_ptr<const detail::PathNode> node) noexcept;
    /// The shared, immutable shape.
    std::shared_ptr<const detail::PathNode> node_;
};

/// A straight segment from `start` to `end`; u is proportional to distance.
class GRAPE_PATH_API LinearPath : public Path {
public:
    LinearPath(Vec2 start, Vec2 end);  ///< throws if a point is not finite
    Vec2 start() const noexcept;  ///< point at u = 0
    Vec2 end() const noexcept;  ///< point at u = 1
};

/// An arc of a circle: point = center + radius·(cos θ, sin θ), θ from `start_angle` to
/// `end_angle` radians. Either direction, and more than one turn when the angles are more
/// than 2π apart. With y down, increasing angles turn clockwise on screen.
class GRAPE_PATH_API CirclePath : public Path {
public:
    CirclePath(Vec2 center, double radius, double start_angle, double end_angle);  ///< radius > 0; angles in radians
    Vec2 center() const noexcept;  ///< center, world units
    double radius() const noexcept;  ///< radius, world units
    double start_angle() const noexcept;  ///< angle at u = 0, radians
    double end_angle() const noexcept;  ///< angle at u = 1, radians
};

/// An arc of an ellipse with semi-axes `rx` and `ry` turned by `rotation` radians about
/// `center`: point = center + R(rotation)·(rx·cos θ, ry·sin θ), θ from `start_angle` to
/// `end_angle` (either direction, several turns allowed). SVG's `A` command becomes one.
class GRAPE_PATH_API EllipticalArcPath : public Path {
public:
    /// rx, ry > 0; angles in radians.
    EllipticalArcPath(Vec2 center, double rx, double ry, double rotation, double start_angle,
                      double end_angle);
    Vec2 center() const noexcept;  ///< center, world units
    double rx() const noexcept;  ///< semi-axis along the rotated x, world units
    double ry() const noexcept;  ///< semi-axis along the rotated y, world units
    double rotation() const noexcept;  ///< rotation of the axes, radians
    double start_angle() const noexcept;  ///< parametric angle at u = 0, radians
    double end_angle() const noexcept;  ///< parametric angle at u = 1, radians
};

/// A circle whose radius goes linearly from `start_radius` to `end_radius` while the angle
/// goes from `start_angle` to `end_angle` (default: one full turn from 0).
class GRAPE_PATH_API SpiralPath : public Path {
public:
    /// Radii ≥ 0; angles in radians.
    SpiralPath(Vec2 center, double start_radius, double end_radius, double start_angle = 0.0,
               double end_angle = 2.0 * pi);
    Vec2 center() const noexcept;  ///< center, world units
    double start_radius() const noexcept;  ///< radius at u = 0 (≥ 0)
    double end_radius() const noexcept;  ///< radius at u = 1 (≥ 0)
    double start_angle() const noexcept;  ///< angle at u = 0, radians
    double end_angle() const noexcept;  ///< angle at u = 1, radians
};

/// A sine wave along the segment start → end: `frequency` full waves over the segment,
/// displaced by amplitude·sin(2π·frequency·u) along the segment's left-hand perpendicular.
class GRAPE_PATH_API SineWavePath : public Path {
public:
    SineWavePath(Vec2 start, Vec2 end, double frequency, double amplitude);  ///< start ≠ end
    Vec2 start() const noexcept;  ///< start of the base segment
    Vec2 end() const noexcept;  ///< end of the base segment
    double frequency() const noexcept;  ///< full waves along the segment
    double amplitude() const noexcept;  ///< peak displacement, world units
};

/// Quadratic Bézier through p0 and p2 with control point p1. With `reparametrize`, the
/// path is the arc-length reparametrization (constant speed, kind() reparametrized), as the
/// seed's flag did; control() still gives the control points.
class GRAPE_PATH_API QuadraticBezierPath : public Path {
public:
    /// Throws grape::Error if a point is not finite or the coefficients overflow a double.
    QuadraticBezierPath(Vec2 p0, Vec2 p1, Vec2 p2, bool reparametrize = false);
    /// Control point i in 0..2.
    Vec2 control(std::size_t i) const noexcept;
};

/// Cubic Bézier through p0 and p3 with control points p1 and p2; `reparametrize` as above.
class GRAPE_PATH_API CubicBezierPath : public Path {
public:
    /// Throws grape::Error if a point is not finite or the coefficients overflow a double.
    CubicBezierPath(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, bool reparametrize = false);
    /// Control point i in 0..3.
    Vec2 control(std::size_t i) const noexcept;
};

/// Splines through n ≥ 2 points; u is spread evenly over the n − 1 segments.
/// Points come as Vec2s or, as in the seed, as flat x, y pairs (an odd count is an error).
class GRAPE_PATH_API LinearSplinePath : public Path {
public:
    explicit LinearSplinePath(std::span<const Vec2> points);  ///< n ≥ 2 finite points
    explicit LinearSplinePath(std::span<const double> xy);    ///< x0, y0, x1, y1, ...
    /// x0, y0, x1, y1, ... written in place.
    LinearSplinePath(std::initializer_list<double> xy) : LinearSplinePath(std::span<const double>(xy)) {}
    std::span<const Vec2> points() const noexcept;  ///< the points passed through
};

/// Cosine interpolation between successive points (zero velocity at every point).
class GRAPE_PATH_API CosineSplinePath : public Path {
public:
    explicit CosineSplinePath(std::span<const Vec2> points);  ///< n ≥ 2 finite points
    explicit CosineSplinePath(std::span<const double> xy);    ///< x0, y0, x1, y1, ...
    /// x0, y0, x1, y1, ... written in place.
    CosineSplinePath(std::initializer_list<double> xy) : CosineSplinePath(std::span<const double>(xy)) {}
    std::span<const Vec2> points() const noexcept;  ///< the points passed through
};

/// Cubic Hermite spline through points with the given tangents (one per point, as d/du of a
/// segment's local parameter in [0, 1]).
class GRAPE_PATH_API HermiteSplinePath : public Path {
public:
    HermiteSplinePath(std::span<const Vec2> points, std::span<const Vec2> tangents);  ///< one tangent per point
    HermiteSplinePath(std::span<const double> xy, std::span<const double> tangent_xy);  ///< as flat pairs
    /// Points and tangents as flat pairs written in place.
    HermiteSplinePath(std::initializer_list<double> xy, std::initializer_list<double> tangent_xy)
        : HermiteSplinePath(std::span<const double>(xy), std::span<const double>(tangent_xy)) {}
    std::span<const Vec2> points() const noexcept;  ///< the points passed through
    std::span<const Vec2> tangents() const noexcept;  ///< d/dt of each segment's local t at each point
};

/// Catmull–Rom parametrization: knot spacing |Δp|^α with α = 0, ½, 1.
enum class CatmullRom { uniform, centripetal, chordal };

/// Catmull–Rom spline through the points (end segments use mirrored phantom points), in the
/// Barry–Goldman form with knot spacing |Δp|^α; each segment still takes an equal share of u
/// and its derivatives carry the segment's knot spacing. Centripetal never forms cusps or
/// self-intersections within a segment. Coincident neighbours (spacing 0) fall back to
/// spacing 1 there.
class GRAPE_PATH_API CatmullRomSplinePath : public Path {
public:
    /// n ≥ 2 finite points; throws grape::Error otherwise or for a `type` out of the enum.
    explicit CatmullRomSplinePath(std::span<const Vec2> points, CatmullRom type = CatmullRom::uniform);
    /// x0, y0, x1, y1, ... (an odd count is an error).
    explicit CatmullRomSplinePath(std::span<const double> xy, CatmullRom type = CatmullRom::uniform);
    /// x0, y0, x1, y1, ... written in place.
    CatmullRomSplinePath(std::initializer_list<double> xy, CatmullRom type = CatmullRom::uniform)
        : CatmullRomSplinePath(std::span<const double>(xy), type) {}
    std::span<const Vec2> points() const noexcept;  ///< the points passed through
    CatmullRom type() const noexcept;  ///< knot spacing
};

/// A projectile: position + velocity·t + ½·acceleration·t², t = u·seconds.
class GRAPE_PATH_API PhysicsPath : public Path {
public:
    PhysicsPath(Vec2 position, Vec2 velocity, Vec2 acceleration, double seconds);  ///< seconds > 0
    Vec2 position() const noexcept;  ///< position at t = 0, world units
    Vec2 velocity() const noexcept;  ///< velocity at t = 0, units per second
    Vec2 acceleration() const noexcept;  ///< constant acceleration, units per second²
    double seconds() const noexcept;  ///< time the whole path represents (u = t / seconds)
};

/// Several paths as one. Part i spans u in [cues[i], cues[i+1]) of the whole, the last part
/// ends at 1. Cues start at 0, never decrease and stay in [0, 1]; a part whose span is empty
/// is skipped (not travelled, not counted in length or bounds). Derivatives follow the chain
/// rule: d1 = part.d1(v) / span. Parts need not meet; complex paths are paths, so they nest.
class GRAPE_PATH_API ComplexPath : public Path {
public:
    ComplexPath(std::vector<Path> parts, std::vector<double> cues);  ///< one cue per part
    /// Cues from the parts' lengths, so one easing curve applies evenly over the whole
    /// (zero-length parts get empty spans; if all are zero, u is shared evenly).
    static ComplexPath by_length(std::vector<Path> parts);
    /// The parts as given (including skipped ones).
    std::span<const Path> parts() const noexcept;
    /// The cues as given.
    std::span<const double> cues() const noexcept;

protected:
    /// A handle on a node that is a complex path (parse_svg_path's).
    explicit ComplexPath(std::shared_ptr<const detail::PathNode> node) noexcept : Path(std::move(node)) {}
};

// --- what a path is: plain values -------------------------------------------------------

/// LinearPath's parameters.
struct LinearSpec {
    Vec2 start;  ///< point at u = 0
    Vec2 end;    ///< point at u = 1
};
/// CirclePath's parameters (angles in radians).
struct CircleSpec {
    Vec2 center;                  ///< world units
    double radius = 1.0;          ///< world units
    double start_angle = 0.0;     ///< angle at u = 0
    double end_angle = 2.0 * pi;  ///< angle at u = 1
};
/// EllipticalArcPath's parameters (angles in radians).
struct EllipticalArcSpec {
    Vec2 center;                  ///< world units
    double rx = 1.0;              ///< radius along the ellipse's own x axis
    double ry = 1.0;              ///< radius along the ellipse's own y axis
    double rotation = 0.0;        ///< of the ellipse's x axis from the world's
    double start_angle = 0.0;     ///< parametric angle at u = 0
    double end_angle = 2.0 * pi;  ///< parametric angle at u = 1
};
/// SpiralPath's parameters (angles in radians).
struct SpiralSpec {
    Vec2 center;                  ///< world units
    double start_radius = 0.0;    ///< radius at u = 0
    double end_radius = 1.0;      ///< radius at u = 1
    double start_angle = 0.0;     ///< angle at u = 0
    double end_angle = 2.0 * pi;  ///< angle at u = 1
};
/// SineWavePath's parameters.
struct SineWaveSpec {
    Vec2 start;              ///< point at u = 0
    Vec2 end;                ///< point at u = 1
    double frequency = 1.0;  ///< full waves along the segment
    double amplitude = 0.0;  ///< world units
};
/// QuadraticBezierPath's control points p0, p1, p2 (as a Bézier, not reparametrized).
struct QuadraticBezierSpec {
    std::array<Vec2, 3> control;  ///< p0, p1, p2
};
/// CubicBezierPath's control points p0..p3 (as a Bézier, not reparametrized).
struct CubicBezierSpec {
    std::array<Vec2, 4> control;  ///< p0, p1, p2, p3
};
/// LinearSplinePath's points.
struct LinearSplineSpec {
    std::vector<Vec2> points;  ///< n ≥ 2
};
/// CosineSplinePath's points.
struct CosineSplineSpec {
    std::vector<Vec2> points;  ///< n ≥ 2
};
/// HermiteSplinePath's points and tangents (one per point).
struct HermiteSplineSpec {
    std::vector<Vec2> points;    ///< n ≥ 2
    std::vector<Vec2> tangents;  ///< one per point
};
/// CatmullRomSplinePath's points and knot spacing.
struct CatmullRomSplineSpec {
    std::vector<Vec2> points;               ///< n ≥ 2
    CatmullRom type = CatmullRom::uniform;  ///< knot spacing
};
/// PhysicsPath's parameters.
struct PhysicsSpec {
    Vec2 position;      ///< world units
    Vec2 velocity;      ///< units per second
    Vec2 acceleration;  ///< units per second²
    double seconds = 1.0;  ///< time at u = 1 (> 0)
};
/// ComplexPath's parts and cues (the parts are paths: describe them in turn).
struct ComplexSpec {
    std::vector<Path> parts;   ///< played one after another
    std::vector<double> cues;  ///< one per part, as ComplexPath takes them
};
/// The arc-length reparametrization of `source` (Path::reparametrized()); a Bézier built
/// with `reparametrize` is one of these around the plain Bézier.
struct ReparametrizedSpec {
    Path source;  ///< the path reparametrized
};

/// Every kind with its parameters. The alternatives come in PathKind's order, so
/// `spec.index()` is the kind (kind_of).
using PathSpec = std::variant<LinearSpec, CircleSpec, EllipticalArcSpec, SpiralSpec, SineWaveSpec,
                              QuadraticBezierSpec, CubicBezierSpec, LinearSplineSpec, CosineSplineSpec,
                              HermiteSplineSpec, CatmullRomSplineSpec, PhysicsSpec, ComplexSpec,
                              ReparametrizedSpec>;

/// The kind and parameters of any path, whatever its static type (copies spline points;
/// a query, not for per-frame loops).
GRAPE_PATH_API PathSpec describe(const Path& path);
/// The path a spec describes: from_spec(describe(p)) evaluates bit for bit like p. Throws
/// grape::Error as the kind's constructor does for invalid parameters.
GRAPE_PATH_API Path from_spec(const PathSpec& spec);

/// The kind a spec describes.
inline PathKind kind_of(const PathSpec& spec) noexcept { return static_cast<PathKind>(spec.index()); }

namespace detail {
template <class S, class V>
struct spec_index;
template <class S, class... Specs>
struct spec_index<S, std::variant<Specs...>> {
    static constexpr std::size_t value = [] {
        constexpr bool same[] = {std::is_same_v<S, Specs>...};
        std::size_t i = 0;
        while (i < sizeof...(Specs) && !same[i]) ++i;
        return i;
    }();
    static_assert(value < sizeof...(Specs), "path_cast: not one of PathSpec's alternatives");
};
}  // namespace detail

/// The PathKind of a spec type: spec_kind<CircleSpec> == PathKind::circle.
template <class S>
inline constexpr PathKind spec_kind = static_cast<PathKind>(detail::spec_index<S, PathSpec>::value);

/// One kind's parameters, if `path` is of that kind (S one of PathSpec's alternatives).
template <class S>
std::optional<S> path_cast(const Path& path) {
    if (path.kind() != spec_kind<S>) return std::nullopt;
    return std::get<S>(describe(path));
}

/// SVG path data (`M L H V C S Q T A Z`, absolute and relative, implicit repeats, arcs by the
/// SVG implementation notes) as a ComplexPath with cues set by length; y points down as in
/// SVG. Data that draws nothing of positive length (empty, only movetos, zero-length
/// segments) is valid: the path stands at its first moveto (the origin for empty data), with
/// length 0. Throws grape::Error naming the character offset of a syntax error (strict).
GRAPE_PATH_API ComplexPath parse_svg_path(std::string_view data);

/// Where SVG path data breaks the grammar (or a segment cannot be a path), and why.
struct SvgPathError {
    std::size_t offset = 0;  ///< character offset in the data
    std::string message;     ///< "SVG path data: expected a number at offset 34, found the end of the data"
};

/// SVG path data read by SVG's error rule, and the error that ended it.
struct SvgPathParse {
    ComplexPath path;                   ///< everything before the command holding the error
    std::optional<SvgPathError> error;  ///< empty when the whole data was read
};

/// SVG path data as browsers read it (SVG 2 §9.5.4): the path up to, not including, the
/// command holding the first error (each implicit repetition of a command counts as one), as
/// parse_svg_path would give for that prefix, and the error. Never throws grape::Error.
GRAPE_PATH_API SvgPathParse parse_svg_path_prefix(std::string_view data);

/// A scalar from `from` to `to`: value(u) = from + (to − from)·u, extended linearly outside [0, 1].
class GRAPE_PATH_API Path1D {
public:
    Path1D(double from, double to);  ///< both finite
    double value(double u) const noexcept { return from_ + (to_ - from_) * u; }  ///< from + (to − from)·u
    double d1(double) const noexcept { return to_ - from_; }  ///< d/du: to − from, the same everywhere
    double from() const noexcept { return from_; }  ///< the value at u = 0
    double to() const noexcept { return to_; }  ///< the value at u = 1

private:
    double from_;
    double to_;
};

/// A path with a name: a scene's "paths" (referred to by animations), the scene catalogue's
/// lists, tables and file names.
struct NamedPath {
    std::string name;  ///< unique within its list, not empty
    Path path;         ///< the shape
};

/// What a PathND was built as.
enum class PathNDKind {
    linear,       ///< straight between keyframes (the constructors)
    catmull_rom,  ///< a Catmull–Rom spline through the keyframes (PathND::catmull_rom)
    hermite,      ///< a cubic Hermite spline: keyframes and a tangent at each (PathND::hermite)
};

/// N numbers moving together through keyframes (N ≥ 1, ≥ 2 keyframes, u spread evenly over
/// the segments): the path of a property animation. Linear between keyframes unless built by
/// catmull_rom or hermite. Outside [0, 1] it extends along its end tangents. Evaluation and
/// the arc-length queries are noexcept and allocation-free.
class GRAPE_PATH_API PathND {
public:
    /// From `from` to `to` (same size).
    PathND(std::span<const double> from, std::span<const double> to);
    /// Through `keyframes`, each of `dimension` numbers, stored one after another.
    PathND(std::size_t dimension, std::span<const double> keyframes);
    /// A Catmull–Rom spline through `keyframes` (as the constructor above), in the Barry–Goldman
    /// form with knot spacing |Δp|^α (uniform α = 0, centripetal ½, chordal 1; Euclidean
    /// distance in N dimensions), exactly as the 2-D spline: the end segments use mirrored
    /// phantom points (2·p0 − p1 before the first, 2·pₙ − pₙ₋₁ after the last), so the uniform
    /// spline's tangent is p1 − p0 at the start, pₙ − pₙ₋₁ at the end and (pᵢ₊₁ − pᵢ₋₁)/2
    /// between, d/dt of each segment's local t. Coincident neighbours fall back to spacing 1.
    static PathND catmull_rom(std::size_t dimension, std::span<const double> keyframes,
                              CatmullRom type = CatmullRom::uniform);
    /// A cubic Hermite spline through `keyframes` with one tangent per keyframe (`tangents`,
    /// the same layout; d/dt of each segment's local t in [0, 1], as the 2-D HermiteSplinePath).
    static PathND hermite(std::size_t dimension, std::span<const double> keyframes, std::span<const double> tangents);

    PathNDKind kind() const noexcept { return kind_; }  ///< what it was built as
    std::size_t dimension() const noexcept { return dimension_; }  ///< N, the numbers per keyframe
    std::size_t keyframe_count() const noexcept { return keys_.size() / dimension_; }  ///< the number of keyframes (≥ 2)
    /// The keyframes, dimension() values each, one after another.
    std::span<const double> keyframes() const noexcept { return keys_; }
    /// Writes the dimension() values at u into out (out.size() ≥ dimension()).
    void point(double u, std::span<double> out) const noexcept;
    /// Writes d/du of the values at u into out.
    void d1(double u, std::span<double> out) const noexcept;

    /// Euclidean arc length in N dimensions over [0, 1]. Linear: exact (the sum of the segments'
    /// lengths, O(segments·N) a call). Splines: 5-point Gauss–Legendre on panels built once:
    /// each segment is cut where its speed has a minimum or maximum (where it may reach 0 and
    /// kink, as a 1-D value turning back does), then halved at least twice and until each
    /// panel's rule agrees with its two halves within 1e-15 of the segment's length (pro rata)
    /// or the speed's rounding (at most 40 halvings and 4096 panels a segment).
    double length() const noexcept;
    /// Arc length over [0, u] (u clamped to [0, 1]).
    double length_at(double u) const noexcept;
    /// The u at which length_at(u) = s (s clamped to [0, length()]): exact for linear, Newton
    /// steps safeguarded by bisection inside a panel for splines (u within ~1e-15). Where
    /// the values stand still (a segment of length 0) the first such u is returned.
    double u_at_length(double s) const noexcept;

private:
    PathND(PathNDKind kind, std::size_t dimension, std::vector<double> keys, std::vector<double> coefficients);
    PathNDKind kind_ = PathNDKind::linear;
    std::size_t dimension_;
    std::vector<double> keys_;
    // Splines: per segment, per dimension, c0..c3 of c0 + c1·t + c2·t² + c3·t³; and the panels of
    // u (starts, and the arc length from u = 0 to each start, with one more for u = 1).
    std::vector<double> coef_;
    std::vector<double> panel_u_, panel_s_;

    double speed(double u) const noexcept;
    double gauss(double a, double b) const noexcept;
};

/// @}

}  // namespace grape
