// grape — describe(): a path's kind and parameters as a plain value; from_spec(): back again.
// The round trip is exact because every node keeps what its constructor was given and the
// kinds' constructors are deterministic.
#include <grape/path.hpp>

#include "kinds.hpp"
#include "path_node.hpp"

namespace grape {

static_assert(std::variant_size_v<PathSpec> == static_cast<std::size_t>(PathKind::reparametrized) + 1,
              "PathSpec has one alternative per PathKind");
static_assert(spec_kind<LinearSpec> == PathKind::linear && spec_kind<CircleSpec> == PathKind::circle &&
              spec_kind<EllipticalArcSpec> == PathKind::elliptical_arc && spec_kind<SpiralSpec> == PathKind::spiral &&
              spec_kind<SineWaveSpec> == PathKind::sine_wave &&
              spec_kind<QuadraticBezierSpec> == PathKind::quadratic_bezier &&
              spec_kind<CubicBezierSpec> == PathKind::cubic_bezier &&
              spec_kind<LinearSplineSpec> == PathKind::linear_spline &&
              spec_kind<CosineSplineSpec> == PathKind::cosine_spline &&
              spec_kind<HermiteSplineSpec> == PathKind::hermite_spline &&
              spec_kind<CatmullRomSplineSpec> == PathKind::catmull_rom_spline &&
              spec_kind<PhysicsSpec> == PathKind::physics && spec_kind<ComplexSpec> == PathKind::complex &&
              spec_kind<ReparametrizedSpec> == PathKind::reparametrized,
              "PathSpec's alternatives come in PathKind's order");

PathSpec describe(const Path& path) {
    using namespace detail;
    const PathNode& node = NodeAccess::node(path);
    switch (node.kind()) {
        case PathKind::linear: {
            const auto& n = static_cast<const LinearNode&>(node);
            return LinearSpec{n.a, n.b};
        }
        case PathKind::circle: {
            const auto& n = static_cast<const ArcNode&>(node);
            return CircleSpec{n.center, n.rx, n.a0, n.a1};
        }
        case PathKind::elliptical_arc: {
            const auto& n = static_cast<const ArcNode&>(node);
            return EllipticalArcSpec{n.center, n.rx, n.ry, n.rotation, n.a0, n.a1};
        }
        case PathKind::spiral: {
            const auto& n = static_cast<const SpiralNode&>(node);
            return SpiralSpec{n.center, n.r0, n.r1, n.a0, n.a1};
        }
        case PathKind::sine_wave: {
            const auto& n = static_cast<const SineWaveNode&>(node);
            return SineWaveSpec{n.a, n.b, n.frequency, n.amplitude};
        }
        case PathKind::quadratic_bezier:
            return QuadraticBezierSpec{static_cast<const QuadraticNode&>(node).inputs};
        case PathKind::cubic_bezier: {
            const auto& n = static_cast<const CubicBezierNode&>(node);
            return CubicBezierSpec{{n.p[0], n.p[1], n.p[2], n.p[3]}};
        }
        case PathKind::linear_spline: return LinearSplineSpec{static_cast<const PolylineNode&>(node).points};
        case PathKind::cosine_spline: return CosineSplineSpec{static_cast<const PolylineNode&>(node).points};
        case PathKind::hermite_spline: {
            const auto& n = static_cast<const CubicSplineNode&>(node);
            return HermiteSplineSpec{n.points, n.tangents};
        }
        case PathKind::catmull_rom_spline: {
            const auto& n = static_cast<const CubicSplineNode&>(node);
            return CatmullRomSplineSpec{n.points, n.type};
        }
        case PathKind::physics: {
            const auto& n = static_cast<const QuadraticNode&>(node);
            return PhysicsSpec{n.inputs[0], n.inputs[1], n.inputs[2], n.seconds};
        }
        case PathKind::complex: {
            const auto& n = static_cast<const ComplexNode&>(node);
            return ComplexSpec{n.parts, n.cues};
        }
        case PathKind::reparametrized: return ReparametrizedSpec{static_cast<const ReparametrizedNode&>(node).source()};
    }
    return LinearSpec{};  // not reached: every kind is handled above
}

Path from_spec(const PathSpec& spec) {
    struct Build {
        Path operator()(const LinearSpec& s) const { return LinearPath(s.start, s.end); }
        Path operator()(const CircleSpec& s) const { return CirclePath(s.center, s.radius, s.start_angle, s.end_angle); }
        Path operator()(const EllipticalArcSpec& s) const {
            return EllipticalArcPath(s.center, s.rx, s.ry, s.rotation, s.start_angle, s.end_angle);
        }
        Path operator()(const SpiralSpec& s) const {
            return SpiralPath(s.center, s.start_radius, s.end_radius, s.start_angle, s.end_angle);
        }
        Path operator()(const SineWaveSpec& s) const { return SineWavePath(s.start, s.end, s.frequency, s.amplitude); }
        Path operator()(const QuadraticBezierSpec& s) const {
            return QuadraticBezierPath(s.control[0], s.control[1], s.control[2]);
        }
        Path operator()(const CubicBezierSpec& s) const {
            return CubicBezierPath(s.control[0], s.control[1], s.control[2], s.control[3]);
        }
        Path operator()(const LinearSplineSpec& s) const { return LinearSplinePath(std::span<const Vec2>(s.points)); }
        Path operator()(const CosineSplineSpec& s) const { return CosineSplinePath(std::span<const Vec2>(s.points)); }
        Path operator()(const HermiteSplineSpec& s) const {
            return HermiteSplinePath(std::span<const Vec2>(s.points), std::span<const Vec2>(s.tangents));
        }
        Path operator()(const CatmullRomSplineSpec& s) const {
            return CatmullRomSplinePath(std::span<const Vec2>(s.points), s.type);
        }
        Path operator()(const PhysicsSpec& s) const {
            return PhysicsPath(s.position, s.velocity, s.acceleration, s.seconds);
        }
        Path operator()(const ComplexSpec& s) const { return ComplexPath(s.parts, s.cues); }
        Path operator()(const ReparametrizedSpec& s) const { return s.source.reparametrized(); }
    };
    return std::visit(Build{}, spec);
}

}  // namespace grape
