// grape — the path kinds' constructors: each checks its arguments and builds its node.
#include "path_checks.hpp"

#include <algorithm>
#include <string>

namespace grape {

using namespace path_checks;

LinearPath::LinearPath(Vec2 start, Vec2 end)
    : Path([&] {
          require_finite("LinearPath", "start", start, "end", end);
          return make_node<detail::LinearNode>(start, end);
      }()) {}

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
    require_finite(who, "start_angle", a0, "end_angle", a1);
    require_turns(who, a0, a1);
    return make_node<detail::ArcNode>(kind, center, rx, ry, rotation, a0, a1);
}

}  // namespace

CirclePath::CirclePath(Vec2 center, double radius, double start_angle, double end_angle)
    : Path(arc("CirclePath", PathKind::circle, center, radius, radius, 0.0, start_angle, end_angle)) {}

EllipticalArcPath::EllipticalArcPath(Vec2 center, double rx, double ry, double rotation, double start_angle,
                                     double end_angle)
    : Path(arc("EllipticalArcPath", PathKind::elliptical_arc, center, rx, ry, rotation, start_angle, end_angle)) {}

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
          require_finite(who, "start_angle", start_angle, "end_angle", end_angle);
          require_turns(who, start_angle, end_angle);
          return make_node<detail::SpiralNode>(center, start_radius, end_radius, start_angle, end_angle);
      }()) {}

SineWavePath::SineWavePath(Vec2 start, Vec2 end, double frequency, double amplitude)
    : Path([&] {
          const char* who = "SineWavePath";
          require_finite(who, "start", start, "end", end);
          if (start == end) fail(who, "start and end must differ (both " + text(start) + "): the wave needs a direction");
          require_finite(who, "frequency", frequency);
          if (std::abs(frequency) > max_turns) {
              fail(who, "frequency must be at most a million waves (got " + text(frequency) + ")");
          }
          require_finite(who, "amplitude", amplitude);
          return make_node<detail::SineWaveNode>(start, end, frequency, amplitude);
      }()) {}

QuadraticBezierPath::QuadraticBezierPath(Vec2 p0, Vec2 p1, Vec2 p2, bool reparametrize)
    : Path([&] {
          const char* who = "QuadraticBezierPath";
          require_finite(who, "p0", p0, "p1", p1, "p2", p2);
          const Vec2 c1 = 2.0 * (p1 - p0);
          const Vec2 c2 = p2 - 2.0 * p1 + p0;
          require_evaluable(who, "control points", {p0, c1, c2});
          return make_node<detail::QuadraticNode>(PathKind::quadratic_bezier, p0, c1, c2,
                                                  std::array<Vec2, 3>{p0, p1, p2}, 1.0);
      }()) {
    if (reparametrize) node_ = make_node<detail::ReparametrizedNode>(detail::NodeAccess::wrap(node_));
}

CubicBezierPath::CubicBezierPath(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, bool reparametrize)
    : Path([&] {
          const char* who = "CubicBezierPath";
          require_finite(who, "p0", p0, "p1", p1, "p2", p2, "p3", p3);
          require_evaluable(who, "control points",
                            {p0, 3.0 * (p1 - p0), 3.0 * (p2 - 2.0 * p1 + p0), p3 - p0 + 3.0 * (p1 - p2)});
          return make_node<detail::CubicBezierNode>(p0, p1, p2, p3);
      }()) {
    if (reparametrize) node_ = make_node<detail::ReparametrizedNode>(detail::NodeAccess::wrap(node_));
}

// Splines ---------------------------------------------------------------------------------

LinearSplinePath::LinearSplinePath(std::span<const Vec2> points)
    : Path(make_node<detail::PolylineNode>(PathKind::linear_spline,
                                           checked_points("LinearSplinePath", "points", points, 2))) {}
LinearSplinePath::LinearSplinePath(std::span<const double> xy)
    : LinearSplinePath(std::span<const Vec2>(pairs("LinearSplinePath", "xy", xy))) {}

CosineSplinePath::CosineSplinePath(std::span<const Vec2> points)
    : Path(make_node<detail::PolylineNode>(PathKind::cosine_spline,
                                           checked_points("CosineSplinePath", "points", points, 2))) {}
CosineSplinePath::CosineSplinePath(std::span<const double> xy)
    : CosineSplinePath(std::span<const Vec2>(pairs("CosineSplinePath", "xy", xy))) {}

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

// Physics ---------------------------------------------------------------------------------

PhysicsPath::PhysicsPath(Vec2 position, Vec2 velocity, Vec2 acceleration, double seconds)
    : Path([&] {
          const char* who = "PhysicsPath";
          require_finite(who, "position", position, "velocity", velocity, "acceleration", acceleration);
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

}  // namespace grape
