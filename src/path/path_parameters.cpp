// grape — what each path kind was built from, read back from its node.
#include "path_checks.hpp"

#include <algorithm>

namespace grape {

using namespace path_checks;

Vec2 LinearPath::start() const noexcept { return static_cast<const detail::LinearNode&>(*node_).a; }
Vec2 LinearPath::end() const noexcept { return static_cast<const detail::LinearNode&>(*node_).b; }

Vec2 CirclePath::center() const noexcept { return static_cast<const detail::ArcNode&>(*node_).center; }
double CirclePath::radius() const noexcept { return static_cast<const detail::ArcNode&>(*node_).rx; }
double CirclePath::start_angle() const noexcept { return static_cast<const detail::ArcNode&>(*node_).a0; }
double CirclePath::end_angle() const noexcept { return static_cast<const detail::ArcNode&>(*node_).a1; }

Vec2 EllipticalArcPath::center() const noexcept { return static_cast<const detail::ArcNode&>(*node_).center; }
double EllipticalArcPath::rx() const noexcept { return static_cast<const detail::ArcNode&>(*node_).rx; }
double EllipticalArcPath::ry() const noexcept { return static_cast<const detail::ArcNode&>(*node_).ry; }
double EllipticalArcPath::rotation() const noexcept { return static_cast<const detail::ArcNode&>(*node_).rotation; }
double EllipticalArcPath::start_angle() const noexcept { return static_cast<const detail::ArcNode&>(*node_).a0; }
double EllipticalArcPath::end_angle() const noexcept { return static_cast<const detail::ArcNode&>(*node_).a1; }

Vec2 SpiralPath::center() const noexcept { return static_cast<const detail::SpiralNode&>(*node_).center; }
double SpiralPath::start_radius() const noexcept { return static_cast<const detail::SpiralNode&>(*node_).r0; }
double SpiralPath::end_radius() const noexcept { return static_cast<const detail::SpiralNode&>(*node_).r1; }
double SpiralPath::start_angle() const noexcept { return static_cast<const detail::SpiralNode&>(*node_).a0; }
double SpiralPath::end_angle() const noexcept { return static_cast<const detail::SpiralNode&>(*node_).a1; }

Vec2 SineWavePath::start() const noexcept { return static_cast<const detail::SineWaveNode&>(*node_).a; }
Vec2 SineWavePath::end() const noexcept { return static_cast<const detail::SineWaveNode&>(*node_).b; }
double SineWavePath::frequency() const noexcept { return static_cast<const detail::SineWaveNode&>(*node_).frequency; }
double SineWavePath::amplitude() const noexcept { return static_cast<const detail::SineWaveNode&>(*node_).amplitude; }

Vec2 QuadraticBezierPath::control(std::size_t i) const noexcept {
    return underlying<detail::QuadraticNode>(*node_).inputs[std::min<std::size_t>(i, 2)];
}

Vec2 CubicBezierPath::control(std::size_t i) const noexcept {
    return underlying<detail::CubicBezierNode>(*node_).p[std::min<std::size_t>(i, 3)];
}

std::span<const Vec2> LinearSplinePath::points() const noexcept {
    return static_cast<const detail::PolylineNode&>(*node_).points;
}

std::span<const Vec2> CosineSplinePath::points() const noexcept {
    return static_cast<const detail::PolylineNode&>(*node_).points;
}

std::span<const Vec2> HermiteSplinePath::points() const noexcept {
    return static_cast<const detail::CubicSplineNode&>(*node_).points;
}
std::span<const Vec2> HermiteSplinePath::tangents() const noexcept {
    return static_cast<const detail::CubicSplineNode&>(*node_).tangents;
}

std::span<const Vec2> CatmullRomSplinePath::points() const noexcept {
    return static_cast<const detail::CubicSplineNode&>(*node_).points;
}
CatmullRom CatmullRomSplinePath::type() const noexcept { return static_cast<const detail::CubicSplineNode&>(*node_).type; }

Vec2 PhysicsPath::position() const noexcept { return static_cast<const detail::QuadraticNode&>(*node_).inputs[0]; }
Vec2 PhysicsPath::velocity() const noexcept { return static_cast<const detail::QuadraticNode&>(*node_).inputs[1]; }
Vec2 PhysicsPath::acceleration() const noexcept { return static_cast<const detail::QuadraticNode&>(*node_).inputs[2]; }
double PhysicsPath::seconds() const noexcept { return static_cast<const detail::QuadraticNode&>(*node_).seconds; }

std::span<const Path> ComplexPath::parts() const noexcept { return static_cast<const detail::ComplexNode&>(*node_).parts; }
std::span<const double> ComplexPath::cues() const noexcept { return static_cast<const detail::ComplexNode&>(*node_).cues; }

}  // namespace grape
