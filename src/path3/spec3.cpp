// grape — what a 3-D path is, as a plain value, and the path built back from it.
#include "node3.hpp"

#include <type_traits>

namespace grape {

Path3Spec describe(const Path3& path) { return detail::Path3Access::node(path).spec(); }

Path3 from_spec(const Path3Spec& spec) {
    return std::visit(
        [](const auto& s) -> Path3 {
            using S = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<S, Line3Spec>) {
                return Path3::line(s.a, s.b);
            } else if constexpr (std::is_same_v<S, QuadraticBezier3Spec>) {
                return Path3::quadratic_bezier(s.control[0], s.control[1], s.control[2]);
            } else if constexpr (std::is_same_v<S, CubicBezier3Spec>) {
                return Path3::cubic_bezier(s.control[0], s.control[1], s.control[2], s.control[3]);
            } else if constexpr (std::is_same_v<S, CatmullRom3Spec>) {
                return Path3::catmull_rom(s.points, s.type, s.closed);
            } else if constexpr (std::is_same_v<S, HelixSpec>) {
                return Path3::helix(s);
            } else if constexpr (std::is_same_v<S, Complex3Spec>) {
                return Path3::complex(s.parts, s.cues);
            } else if constexpr (std::is_same_v<S, Hermite3Spec>) {
                return Path3::hermite(s.points, s.tangents, s.closed);
            } else if constexpr (std::is_same_v<S, LinearSpline3Spec>) {
                return Path3::linear_spline(s.points, s.closed);
            } else if constexpr (std::is_same_v<S, Arc3Spec>) {
                return Path3::arc(s);
            } else if constexpr (std::is_same_v<S, Projectile3Spec>) {
                return Path3::projectile(s.position, s.velocity, s.acceleration, s.seconds);
            } else if constexpr (std::is_same_v<S, OnPlane3Spec>) {
                return Path3::on_plane(s.path, s.origin, s.x_axis, s.y_axis);
            } else if constexpr (std::is_same_v<S, Reparametrized3Spec>) {
                return s.source.reparametrized();
            } else {
                static_assert(std::is_same_v<S, Slice3Spec>);
                return slice(s.source, s.u0, s.u1);
            }
        },
        spec);
}

}  // namespace grape
