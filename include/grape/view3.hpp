// grape — View3: how a 3-D scene is seen on a 2-D canvas. An oblique (parallel) projection for
// pictures that keep lengths readable, or a perspective camera placed by eye and target or by
// orbiting a point (the studio's drag-to-orbit, the browser's coaster).
#pragma once

#include <grape/export_math.hpp>
#include <grape/math.hpp>
#include <grape/vec3.hpp>

namespace grape {

/// \addtogroup math
/// @{

/// Where a world point lands on the picture plane.
struct Projected {
    Vec2 point;           ///< picture-plane coordinates, y pointing down (a Canvas's convention)
    double depth = 0.0;   ///< distance along the view direction: larger is farther (sort far to near)
    bool visible = true;  ///< false behind a perspective camera's near plane (point is then meaningless)
};

/// A projection of 3-D points to a picture plane, with z up. Picture coordinates are unscaled:
/// fit them to a viewport with grape::fit over the projected bounds. A value type; project()
/// is noexcept and allocation-free.
class GRAPE_MATH_API View3 {
public:
    /// The default: oblique(40°, 0.8).
    View3() noexcept;

    /// Oblique parallel projection, z up: x to the right, y receding at `angle` radians above
    /// the horizontal, scaled by `recede` (cabinet is π/4 and 0.5). Throws grape::Error naming
    /// the argument when angle is not finite or recede is not finite and in (0, 1].
    static View3 oblique(double angle = 0.6981317007977318, double recede = 0.8);

    /// Perspective camera at `eye` looking at `target`, `up` giving the picture's up side,
    /// `fov_y` the full vertical field of view in radians. Throws grape::Error naming the
    /// argument when a value is not finite, eye equals target, up is zero or parallel to the
    /// view, or fov_y is not in (0, π).
    static View3 perspective(Vec3 eye, Vec3 target, Vec3 up = {0, 0, 1}, double fov_y = 0.8);

    /// Perspective camera orbiting `target` at `distance`: `azimuth` radians about z from +x,
    /// `elevation` radians above the xy plane (clamped to ±(π/2 − 1e-3), where the view would
    /// be parallel to up). Throws grape::Error like perspective, and when distance is not
    /// finite and positive.
    static View3 orbit(Vec3 target, double distance, double azimuth, double elevation, double fov_y = 0.8);

    /// True for a perspective camera.
    bool is_perspective() const noexcept { return perspective_; }

    /// Where p lands (see Projected). Perspective divides by the depth: a point at depth d
    /// and lateral offset h lands at h / (d tan(fov_y / 2)), so the picture's half height is 1.
    Projected project(Vec3 p) const noexcept;

    /// The unit direction from the viewer toward p: a face whose normal n has dot(n, it) < 0
    /// is seen from its front. Constant for an oblique view.
    Vec3 view_direction(Vec3 p) const noexcept;

    /// The camera's position (perspective), or a point far back along the view (oblique).
    Vec3 eye() const noexcept { return eye_; }

private:
    bool perspective_ = false;
    Vec3 eye_{};
    Vec3 right_{1, 0, 0};    // picture +x in the world
    Vec3 up_{0, 0, 1};       // picture −y in the world
    Vec3 forward_{0, 1, 0};  // into the picture
    double recede_x_ = 0.0;  // oblique: picture offset per unit y
    double recede_y_ = 0.0;
    double focal_ = 1.0;     // perspective: 1 / tan(fov_y / 2)
};

/// @}

}  // namespace grape
