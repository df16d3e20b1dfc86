// grape — the moving frame of a path: unit tangent and normal, signed curvature.
#include <grape/path_query.hpp>

#include <cmath>

namespace grape {

PathFrame frame(const Path& path, double u) noexcept {
    const Vec2 g = path.d1(u);
    const Vec2 h = path.d2(u);
    const double speed = length(g);
    Vec2 tangent = speed > 0.0 ? g / speed : Vec2{};
    double kappa = 0.0;
    if (speed > 0.0) {
        // cross/|x′|³ in two divisions: |x′|³ alone overflows for speeds above ~1e102.
        kappa = cross(g, h) / speed / (speed * speed);
        if (!std::isfinite(kappa)) kappa = 0.0;
    } else {
        // Standing still: x′ ≈ x″·(v − u) just after u, so it leaves along x″; without x″ (a
        // path at rest over a stretch) along the chord to a little later.
        tangent = normalized(h);
        if (tangent == Vec2{}) tangent = normalized(path.point(u + 1e-7) - path.point(u));
    }
    return {path.point(u), tangent, perpendicular(tangent), kappa};
}

double curvature(const Path& path, double u) noexcept { return frame(path, u).curvature; }

}  // namespace grape
