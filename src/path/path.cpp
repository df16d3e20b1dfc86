// grape — the Path handle, the kinds' constructors (validation) and accessors, Path1D, PathND.
#include <grape/error.hpp>
#include <grape/path.hpp>

#include "kinds.hpp"
#include "path_node.hpp"

#include <cstdio>
#include <string>

namespace grape {

namespace {

using detail::make_node;

std::string text(double v) { return detail::number_text(v); }

std::string text(Vec2 v) {
    std::string s = "(";
    s += text(v.x);
    s += ", ";
    s += text(v.y);
    s += ')';
    return s;
}

[[noreturn]] void fail(const char* who, const std::string& what) { throw Error(std::string(who) + ": " + what); }

void require_finite(const char* who, const char* name, double v) {
    if (!std::isfinite(v)) fail(who, std::string(name) + " must be finite (got " + text(v) + ")");
}

void require_finite(const char* who, const char* name, Vec2 v) {
    if (!is_finite(v)) fail(who, std::string(name) + " must be finite (got " + text(v) + ")");
}

// Polynomial kinds evaluate power-basis coefficients by Horner's rule. Every partial sum, and
// the derivatives (factors up to 6), stay finite for u in [0, 1] when 6·Σ|c| does: beyond
// that a point of the curve could come out infinite although the curve itself is finite.
void require_evaluable(const char* who, const char* what, std::initializer_list<Vec2> coefficients) {
    double x = 0.0;
    double y = 0.0;
    for (const Vec2 c : coefficients) {
        x += std::abs(c.x);
        y += std::abs(c.y);
    }
    if (!(std::isfinite(6.0 * x) && std::isfinite(6.0 * y)))
        fail(who, std::string(what) + " are too large to evaluate in double precision (coefficients overflow)");
}

// Work for length, bounds and flattening grows with the turns: a million is far beyond any
// drawing and keeps every construction bounded.
constexpr double max_turns = 1e6;

void require_turns(const char* who, double a0, double a1) {
    if (std::abs(a1 - a0) > 2.0 * pi * max_turns) {
        fail(who, "end_angle − start_angle must be at most a million turns (got " + text(a1 - a0) + " radians)");
    }
}

std::vector<Vec2> checked_points(const char* who, const char* name, std::span<const Vec2> points, std::size_t at_least) {
    if (points.size() < at_least) {
        fail(who, std::string(name) + " needs at least " + std::to_string(at_least) + " points (got " +
                      std::to_string(points.size()) + ")");
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!is_finite(points[i])) {
            fail(who, std::string(name) + "[" + std::to_string(i) + "] must be finite (got " + text(points[i]) + ")");
        }
    }
    return {points.begin(), points.end()};
}

// Flat x, y pairs as points (the seed's Number vectors).
std::vector<Vec2> pairs(const char* who, const char* name, std::span<const double> xy) {
    if (xy.size() % 2 != 0) {
        fail(who, std::string(name) + " must hold x, y pairs: an even number of coordinates (got " +
                      std::to_string(xy.size()) + ")");
    }
    std::vector<Vec2> points(xy.size() / 2);
    for (std::size_t i = 0; i < points.size(); ++i) points[i] = {xy[2 * i], xy[2 * i + 1]};
    return points;
}

template <class T>
const T& underlying(const detail::PathNode& node) noexcept {
    if (node.kind() == PathKind::reparametrized) {
        return static_cast<const T&>(detail::NodeAccess::node(static_cast<const detail::ReparametrizedNode&>(node).source()));
    }
    return static_cast<const T&>(node);
}

const std::shared_ptr<const detail::PathNode>& origin_node() {
    static const std::shared_ptr<const detail::PathNode> node = make_node<detail::LinearNode>(Vec2{}, Vec2{});
    return node;
}

}  // namespace

std::string_view to_string(PathKind kind) noexcept {
    switch (kind) {
        case PathKind::linear: return "linear";
        case PathKind::circle: return "circle";
        case PathKind::elliptical_arc: return "elliptical_arc";
        case PathKind::spiral: return "spiral";
        case PathKind::sine_wave: return "sine_wave";
        case PathKind::quadratic_bezier: return "quadratic_bezier";
        case PathKind::cubic_bezier: return "cubic_bezier";
        case PathKind::linear_spline: return "linear_spline";
        case PathKind::cosine_spline: return "cosine_spline";
        case PathKind::hermite_spline: return "hermite_spline";
        case PathKind::catmull_rom_spline: return "catmull_rom_spline";
        case PathKind::physics: return "physics";
        case PathKind::complex: return "complex";
        case PathKind::reparametrized: return "reparametrized";
    }
    return "unknown";
}

// --- Path ---------------------------------------------------------------------------------

Path::Path() : node_(origin_node()) {}

Path::Path(std::shared_ptr<const detail::PathNode> node) noexcept : node_(std::move(node)) {}

Vec2 Path::point(double u) const noexcept {
    if (u < 0.0) return node_->point(0.0) + node_->d1(0.0) * u;
    if (u > 1.0) return node_->point(1.0) + node_->d1(1.0) * (u - 1.0);
    return node_->point(u);
}

Vec2 Path::d1(double u) const noexcept {
    if (u < 0.0) return node_->d1(0.0);
    if (u > 1.0) return node_->d1(1.0);
    return node_->d1(u);
}

Vec2 Path::d2(double u) const noexcept {
    if (u < 0.0 || u > 1.0) return {};
    return node_->d2(u);
}

double Path::heading(double u) const noexcept {
    const Vec2 d = d1(u);
    if (d.x == 0.0 && d.y == 0.0) return 0.0;
    return std::atan2(d.y, d.x);
}

double Path::length() const noexcept { return node_->length(); }

double Path::length_at(double u) const noexcept {
    if (!(u > 0.0)) return 0.0;
    if (u >= 1.0) return node_->length();
    return node_->length_at(u);
}

double Path::u_at_length(double s) const noexcept {
    const double total = node_->length();
    if (!(s > 0.0) || !(total > 0.0)) return 0.0;
    if (s >= total) return 1.0;
    if (node_->kind() == PathKind::reparametrized || node_->kind() == PathKind::linear) return s / total;
    // Newton on length_at(u) − s (derivative: the speed), kept in its bracket by bisection.
    const detail::PathNode& n = *node_;
    auto fd = [&n, s](double u) noexcept {
        return std::pair<double, double>{n.length_at(u) - s, grape::length(n.d1(u))};
    };
    return find_root(fd, 0.0, 1.0, s / total, 1e-15).x;
}

Bounds Path::bounds() const noexcept { return node_->bounds(); }

std::vector<Vec2> Path::flatten(double tolerance) const {
    if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
        fail("Path::flatten", "tolerance must be positive and finite (got " + text(tolerance) + ")");
    }
    // Below ~1e-12 of the path's size the rounding of the points themselves dominates.
    const Vec2 size = node_->bounds().size();
    tolerance = std::max(tolerance, 1e-12 * std::max({std::abs(size.x), std::abs(size.y), 1e-300}));
    std::vector<Vec2> out{node_->point(0.0)};
    node_->append_flattened(tolerance, out);
    if (out.size() == 1) out.push_back(out.front());
    return out;
}

Path Path::reparametrized() const {
    if (node_->kind() == PathKind::reparametrized) return *this;
    return Path(make_node<detail::ReparametrizedNode>(*this));
}

PathKind Path::kind() const noexcept { return node_->kind(); }

// --- the kinds ----------------------------------------------------------------------------

LinearPath::LinearPath(Vec2 start, Vec2 end)
    : Path([&] {
          require_finite("LinearPath", "start", start);
          require_finite("LinearPath", "end", end);
          return make_node<detail::LinearNode>(start, end);
      }()) {}
Vec2 LinearPath::start() const noexcept { return static_cast<const detail::LinearNode&>(*node_).a; }
Vec2 LinearPath::end() const noexcept { return static_cast<const detail::LinearNode&>(*node_).b; }

namespace {

std::shared_ptr<const detail::ArcNode> arc(const char* who, PathKind kind, Vec2 center, double rx, double ry,
                                           double rotation, double a0, double a1) {
    require_finite(who, "center", center);
    if (kind == PathKind::circle) {
        if (!(rx > 0.0) || !std::isfinite(rx)) fail(who, "radius must be positive and finite (got " + text(rx) + ")");
    } else {
        if (!(rx > 0.0) || !std::isfinite(rx)) fail(who, "rx must be positive and finite (got " + text(rx) + ")");
        if (!(ry > 0.0) || !std::isfinite(ry)) fail(who, "ry must be positive and finite (got " + text(ry) + ")");
        require_finite(who, "rotation", rotation);
    }
    require_finite(who, "start_angle", a0);
    require_finite(who, "end_angle", a1);
    require_turns(who, a0, a1);
    return make_node<detail::ArcNode>(kind, center, rx, ry, rotation, a0, a1);
}

}  // namespace

CirclePath::CirclePath(Vec2 center, double radius, double start_angle, double end_angle)
    : Path(arc("CirclePath", PathKind::circle, center, radius, radius, 0.0, start_angle, end_angle)) {}
Vec2 CirclePath::center() const noexcept { return static_cast<const detail::ArcNode&>(*node_).center; }
double CirclePath::radius() const noexcept { return static_cast<const detail::ArcNode&>(*node_).rx; }
double CirclePath::start_angle() const noexcept { return static_cast<const detail::ArcNode&>(*node_).a0; }
double CirclePath::end_angle() const noexcept { return static_cast<const detail::ArcNode&>(*node_).a1; }

EllipticalArcPath::EllipticalArcPath(Vec2 center, double rx, double ry, double rotation, double start_angle,
                                     double end_angle)
    : Path(arc("EllipticalArcPath", PathKind::elliptical_arc, center, rx, ry, rotation, start_angle, end_angle)) {}
Vec2 EllipticalArcPath::center() const noexcept { return static_cast<const detail::ArcNode&>(*node_).center; }
double EllipticalArcPath::rx() const noexcept { return static_cast<const detail::ArcNode&>(*node_).rx; }
double EllipticalArcPath::ry() const noexcept { return static_cast<const detail::ArcNode&>(*node_).ry; }
double EllipticalArcPath::rotation() const noexcept { return static_cast<const detail::ArcNode&>(*node_).rotation; }
double EllipticalArcPath::start_angle() const noexcept { return static_cast<const detail::ArcNode&>(*node_).a0; }
double EllipticalArcPath::end_angle() const noexcept { return static_cast<const detail::ArcNode&>(*node_).a1; }

SpiralPath::SpiralPath(Vec2 center, double start_radius, double end_radius, double start_angle, double end_angle)
    : Path([&] {
          const char* who = "SpiralPath";
          require_finite(who, "center", center);
          if (!(start_radius >= 0.0) || !std::isfinite(start_radius)) {
              fail(who, "start_radius must be non-negative and finite (got " + text(start_radius) + ")");
          }
          if (!(end_radius >= 0.0) || !std::isfinite(end_radius)) {
              fail(who, "end_radius must be non-negative and finite (got " + text(end_radius) + ")");
          }
          require_finite(who, "start_angle", start_angle);
          require_finite(who, "end_angle", end_angle);
          require_turns(who, start_angle, end_angle);
          return make_node<detail::SpiralNode>(center, start_radius, end_radius, start_angle, end_angle);
      }()) {}
Vec2 SpiralPath::center() const noexcept { return static_cast<const detail::SpiralNode&>(*node_).center; }
double SpiralPath::start_radius() const noexcept { return static_cast<const detail::SpiralNode&>(*node_).r0; }
double SpiralPath::end_radius() const noexcept { return static_cast<const detail::SpiralNode&>(*node_).r1; }
double SpiralPath::start_angle() const noexcept { return static_cast<const detail::SpiralNode&>(*node_).a0; }
double SpiralPath::end_angle() const noexcept { return static_cast<const detail::SpiralNode&>(*node_).a1; }

SineWavePath::SineWavePath(Vec2 start, Vec2 end, double frequency, double amplitude)
    : Path([&] {
          const char* who = "SineWavePath";
          require_finite(who, "start", start);
          require_finite(who, "end", end);
          if (start == end) fail(who, "start and end must differ (both " + text(start) + "): the wave needs a direction");
          require_finite(who, "frequency", frequency);
          if (std::abs(frequency) > max_turns) {
              fail(who, "frequency must be at most a million waves (got " + text(frequency) + ")");
          }
          require_finite(who, "amplitude", amplitude);
          return make_node<detail::SineWaveNode>(start, end, frequency, amplitude);
      }()) {}
Vec2 SineWavePath::start() const noexcept { return static_cast<const detail::SineWaveNode&>(*node_).a; }
Vec2 SineWavePath::end() const noexcept { return static_cast<const detail::SineWaveNode&>(*node_).b; }
double SineWavePath::frequency() const noexcept { return static_cast<const detail::SineWaveNode&>(*node_).frequency; }
double SineWavePath::amplitude() const noexcept { return static_cast<const detail::SineWaveNode&>(*node_).amplitude; }


QuadraticBezierPath::QuadraticBezierPath(Vec2 p0, Vec2 p1, Vec2 p2, bool reparametrize)
    : Path([&] {
          const char* who = "QuadraticBezierPath";
          require_finite(who, "p0", p0);
          require_finite(who, "p1", p1);
          require_finite(who, "p2", p2);
          const Vec2 c1 = 2.0 * (p1 - p0);
          const Vec2 c2 = p2 - 2.0 * p1 + p0;
          require_evaluable(who, "control points", {p0, c1, c2});
          return make_node<detail::QuadraticNode>(PathKind::quadratic_bezier, p0, c1, c2,
                                                  std::array<Vec2, 3>{p0, p1, p2}, 1.0);
      }()) {
    if (reparametrize) node_ = make_node<detail::ReparametrizedNode>(detail::NodeAccess::wrap(node_));
}
Vec2 QuadraticBezierPath::control(std::size_t i) const noexcept {
    return underlying<detail::QuadraticNode>(*node_).inputs[std::min<std::size_t>(i, 2)];
}

CubicBezierPath::CubicBezierPath(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, bool reparametrize)
    : Path([&] {
          const char* who = "CubicBezierPath";
          require_finite(who, "p0", p0);
          require_finite(who, "p1", p1);
          require_finite(who, "p2", p2);
          require_finite(who, "p3", p3);
          require_evaluable(who, "control points",
                            {p0, 3.0 * (p1 - p0), 3.0 * (p2 - 2.0 * p1 + p0), p3 - p0 + 3.0 * (p1 - p2)});
          return make_node<detail::CubicBezierNode>(p0, p1, p2, p3);
      }()) {
    if (reparametrize) node_ = make_node<detail::ReparametrizedNode>(detail::NodeAccess::wrap(node_));
}
Vec2 CubicBezierPath::control(std::size_t i) const noexcept {
    return underlying<detail::CubicBezierNode>(*node_).p[std::min<std::size_t>(i, 3)];
}

// Splines ---------------------------------------------------------------------------------

LinearSplinePath::LinearSplinePath(std::span<const Vec2> points)
    : Path(make_node<detail::PolylineNode>(PathKind::linear_spline,
                                           checked_points("LinearSplinePath", "points", points, 2))) {}
LinearSplinePath::LinearSplinePath(std::span<const double> xy)
    : LinearSplinePath(std::span<const Vec2>(pairs("LinearSplinePath", "xy", xy))) {}
std::span<const Vec2> LinearSplinePath::points() const noexcept {
    return static_cast<const detail::PolylineNode&>(*node_).points;
}

CosineSplinePath::CosineSplinePath(std::span<const Vec2> points)
    : Path(make_node<detail::PolylineNode>(PathKind::cosine_spline,
                                           checked_points("CosineSplinePath", "points", points, 2))) {}
CosineSplinePath::CosineSplinePath(std::span<const double> xy)
    : CosineSplinePath(std::span<const Vec2>(pairs("CosineSplinePath", "xy", xy))) {}
std::span<const Vec2> CosineSplinePath::points() const noexcept {
    return static_cast<const detail::PolylineNode&>(*node_).points;
}

namespace {

std::shared_ptr<const detail::PathNode> hermite_node(std::span<const Vec2> points, std::span<const Vec2> tangents) {
    const char* who = "HermiteSplinePath";
    auto p = checked_points(who, "points", points, 2);
    if (tangents.size() != points.size()) {
        fail(who, "tangents needs one tangent per point (got " + std::to_string(tangents.size()) + " tangents for " +
                      std::to_string(points.size()) + " points)");
    }
    auto t = checked_points(who, "tangents", tangents, 0);
    return make_node<detail::CubicSplineNode>(PathKind::hermite_spline, std::move(p), std::move(t),
                                              CatmullRom::uniform);
}

}  // namespace

HermiteSplinePath::HermiteSplinePath(std::span<const Vec2> points, std::span<const Vec2> tangents)
    : Path(hermite_node(points, tangents)) {}
HermiteSplinePath::HermiteSplinePath(std::span<const double> xy, std::span<const double> tangent_xy)
    : Path(hermite_node(pairs("HermiteSplinePath", "xy", xy), pairs("HermiteSplinePath", "tangent_xy", tangent_xy))) {}
std::span<const Vec2> HermiteSplinePath::points() const noexcept {
    return static_cast<const detail::CubicSplineNode&>(*node_).points;
}
std::span<const Vec2> HermiteSplinePath::tangents() const noexcept {
    return static_cast<const detail::CubicSplineNode&>(*node_).tangents;
}

CatmullRomSplinePath::CatmullRomSplinePath(std::span<const Vec2> points, CatmullRom type)
    : Path([&] {
          const char* who = "CatmullRomSplinePath";
          if (type != CatmullRom::uniform && type != CatmullRom::centripetal && type != CatmullRom::chordal) {
              fail(who, "type must be uniform, centripetal or chordal (got " +
                            std::to_string(static_cast<int>(type)) + ")");
          }
          return make_node<detail::CubicSplineNode>(PathKind::catmull_rom_spline,
                                                    checked_points(who, "points", points, 2), std::vector<Vec2>{},
                                                    type);
      }()) {}
CatmullRomSplinePath::CatmullRomSplinePath(std::span<const double> xy, CatmullRom type)
    : CatmullRomSplinePath(std::span<const Vec2>(pairs("CatmullRomSplinePath", "xy", xy)), type) {}
std::span<const Vec2> CatmullRomSplinePath::points() const noexcept {
    return static_cast<const detail::CubicSplineNode&>(*node_).points;
}
CatmullRom CatmullRomSplinePath::type() const noexcept { return static_cast<const detail::CubicSplineNode&>(*node_).type; }

// Physics ---------------------------------------------------------------------------------

PhysicsPath::PhysicsPath(Vec2 position, Vec2 velocity, Vec2 acceleration, double seconds)
    : Path([&] {
          const char* who = "PhysicsPath";
          require_finite(who, "position", position);
          require_finite(who, "velocity", velocity);
          require_finite(who, "acceleration", acceleration);
          if (!(seconds > 0.0) || !std::isfinite(seconds)) {
              fail(who, "seconds must be positive and finite (got " + text(seconds) + ")");
          }
          // In u = t/seconds: x = p + (v·T)·u + (½·a·T²)·u².
          const Vec2 c1 = velocity * seconds;
          const Vec2 c2 = acceleration * (0.5 * seconds * seconds);
          require_evaluable(who, "position, velocity·seconds and acceleration·seconds²", {position, c1, c2});
          return make_node<detail::QuadraticNode>(PathKind::physics, position, c1, c2,
                                                  std::array<Vec2, 3>{position, velocity, acceleration}, seconds);
      }()) {}
Vec2 PhysicsPath::position() const noexcept { return static_cast<const detail::QuadraticNode&>(*node_).inputs[0]; }
Vec2 PhysicsPath::velocity() const noexcept { return static_cast<const detail::QuadraticNode&>(*node_).inputs[1]; }
Vec2 PhysicsPath::acceleration() const noexcept { return static_cast<const detail::QuadraticNode&>(*node_).inputs[2]; }
double PhysicsPath::seconds() const noexcept { return static_cast<const detail::QuadraticNode&>(*node_).seconds; }

// Complex ---------------------------------------------------------------------------------

namespace {

std::shared_ptr<const detail::PathNode> complex_node(std::vector<Path> parts, std::vector<double> cues) {
    const char* who = "ComplexPath";
    if (parts.empty()) fail(who, "parts must not be empty");
    if (cues.size() != parts.size()) {
        fail(who, "cues needs one cue per part (got " + std::to_string(cues.size()) + " cues for " +
                      std::to_string(parts.size()) + " parts)");
    }
    for (std::size_t i = 0; i < cues.size(); ++i) {
        const std::string name = "cues[" + std::to_string(i) + "]";
        if (!std::isfinite(cues[i])) fail(who, name + " must be finite (got " + text(cues[i]) + ")");
        if (cues[i] < 0.0 || cues[i] > 1.0) fail(who, name + " must lie in [0, 1] (got " + text(cues[i]) + ")");
        if (i == 0 && cues[0] != 0.0) fail(who, "cues[0] must be 0: the first part starts the path (got " + text(cues[0]) + ")");
        if (i > 0 && cues[i] < cues[i - 1]) {
            fail(who, "cues must not decrease (" + name + " = " + text(cues[i]) + " < cues[" + std::to_string(i - 1) +
                          "] = " + text(cues[i - 1]) + ")");
        }
    }
    return make_node<detail::ComplexNode>(std::move(parts), std::move(cues));
}

}  // namespace

ComplexPath::ComplexPath(std::vector<Path> parts, std::vector<double> cues)
    : Path(complex_node(std::move(parts), std::move(cues))) {}

ComplexPath ComplexPath::by_length(std::vector<Path> parts) {
    if (parts.empty()) fail("ComplexPath::by_length", "parts must not be empty");
    double total = 0.0;
    for (const Path& p : parts) total += p.length();
    std::vector<double> cues(parts.size());
    double s = 0.0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        // All parts of zero length: share u evenly instead of dividing by zero.
        cues[i] = total > 0.0 ? std::min(s / total, 1.0) : static_cast<double>(i) / static_cast<double>(parts.size());
        s += parts[i].length();
    }
    return ComplexPath(std::move(parts), std::move(cues));
}

std::span<const Path> ComplexPath::parts() const noexcept { return static_cast<const detail::ComplexNode&>(*node_).parts; }
std::span<const double> ComplexPath::cues() const noexcept { return static_cast<const detail::ComplexNode&>(*node_).cues; }

// --- Path1D, PathND -----------------------------------------------------------------------

Path1D::Path1D(double from, double to) : from_(from), to_(to) {
    require_finite("Path1D", "from", from);
    require_finite("Path1D", "to", to);
}

namespace {

std::vector<double> checked_keys(std::size_t dimension, std::span<const double> keys) {
    const char* who = "PathND";
    if (dimension == 0) fail(who, "dimension must be at least 1 (got 0)");
    if (keys.size() % dimension != 0) {
        fail(who, "keyframes must hold a multiple of dimension " + std::to_string(dimension) + " values (got " +
                      std::to_string(keys.size()) + ")");
    }
    if (keys.size() / dimension < 2) {
        fail(who, "keyframes needs at least 2 keyframes (got " + std::to_string(keys.size() / dimension) + ")");
    }
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (!std::isfinite(keys[i])) {
            fail(who, "keyframes[" + std::to_string(i) + "] must be finite (got " + text(keys[i]) + ")");
        }
    }
    return {keys.begin(), keys.end()};
}

std::vector<double> joined(std::span<const double> from, std::span<const double> to) {
    if (from.size() != to.size()) {
        fail("PathND", "from and to must have the same size (got " + std::to_string(from.size()) + " and " +
                           std::to_string(to.size()) + ")");
    }
    std::vector<double> keys(from.begin(), from.end());
    keys.insert(keys.end(), to.begin(), to.end());
    return keys;
}

}  // namespace

PathND::PathND(std::span<const double> from, std::span<const double> to)
    : PathND(from.size(), std::span<const double>(joined(from, to))) {}

PathND::PathND(std::size_t dimension, std::span<const double> keyframes)
    : dimension_(dimension), keys_(checked_keys(dimension, keyframes)) {}

void PathND::point(double u, std::span<double> out) const noexcept {
    const std::size_t segments = keyframe_count() - 1;
    double t;
    // Outside [0, 1] the end segments extend linearly (t leaves [0, 1]).
    std::size_t i = detail::segment_of(u * static_cast<double>(segments), segments, t);
    if (u < 0.0) t = u * static_cast<double>(segments);
    if (u > 1.0) t = 1.0 + (u - 1.0) * static_cast<double>(segments);
    const double* a = keys_.data() + i * dimension_;
    const double* b = a + dimension_;
    const std::size_t n = std::min(out.size(), dimension_);
    for (std::size_t k = 0; k < n; ++k) out[k] = a[k] + (b[k] - a[k]) * t;
}

void PathND::d1(double u, std::span<double> out) const noexcept {
    const std::size_t segments = keyframe_count() - 1;
    double t;
    const std::size_t i = detail::segment_of(u * static_cast<double>(segments), segments, t);
    const double* a = keys_.data() + i * dimension_;
    const double* b = a + dimension_;
    const std::size_t n = std::min(out.size(), dimension_);
    for (std::size_t k = 0; k < n; ++k) out[k] = (b[k] - a[k]) * static_cast<double>(segments);
}

}  // namespace grape
