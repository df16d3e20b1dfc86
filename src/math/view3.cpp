// View3: oblique and perspective projections (grape/view3.hpp).
#include <grape/error.hpp>
#include <grape/view3.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace grape {
namespace {

[[noreturn]] void view_error(const char* function, const char* argument, const char* reason) {
    throw Error(std::string(function) + ": " + argument + " " + reason);
}

void check_finite(const char* function, const char* argument, double v) {
    if (!std::isfinite(v)) view_error(function, argument, "is not finite");
}

void check_finite(const char* function, const char* argument, Vec3 v) {
    if (!is_finite(v)) view_error(function, argument, "is not finite");
}

}  // namespace

View3::View3() noexcept {
    recede_x_ = 0.8 * std::cos(0.6981317007977318);
    recede_y_ = 0.8 * std::sin(0.6981317007977318);
    forward_ = normalized(Vec3{-recede_x_, 1.0, -recede_y_});
    eye_ = forward_ * -1e6;
}

View3 View3::oblique(double angle, double recede) {
    check_finite("View3::oblique", "angle", angle);
    check_finite("View3::oblique", "recede", recede);
    if (!(recede > 0.0 && recede <= 1.0)) view_error("View3::oblique", "recede", "is not in (0, 1]");
    View3 v;
    v.recede_x_ = recede * std::cos(angle);
    v.recede_y_ = recede * std::sin(angle);
    // The direction that projects to a single point: (−rx, 1, −ry) moves the picture by
    // rx·1 − rx = 0 across and ry·1 − ry = 0 up.
    v.forward_ = normalized(Vec3{-v.recede_x_, 1.0, -v.recede_y_});
    v.eye_ = v.forward_ * -1e6;
    return v;
}

View3 View3::perspective(Vec3 eye, Vec3 target, Vec3 up, double fov_y) {
    const char* f = "View3::perspective";
    check_finite(f, "eye", eye);
    check_finite(f, "target", target);
    check_finite(f, "up", up);
    check_finite(f, "fov_y", fov_y);
    if (!(fov_y > 0.0 && fov_y < pi)) view_error(f, "fov_y", "is not in (0, pi)");
    const Vec3 d = target - eye;
    const double dl = length(d);
    if (!(dl > 0.0) || !std::isfinite(dl)) view_error(f, "target", "equals eye (no view direction)");
    if (!(length(up) > 0.0)) view_error(f, "up", "is zero");
    View3 v;
    v.perspective_ = true;
    v.eye_ = eye;
    v.forward_ = d / dl;
    const Vec3 r = cross(v.forward_, up);
    // 1e-9: below it the picture's up side is decided by rounding, not by `up`.
    if (!(length(r) > 1e-9 * length(up))) view_error(f, "up", "is parallel to the view direction");
    v.right_ = normalized(r);
    v.up_ = cross(v.right_, v.forward_);
    v.focal_ = 1.0 / std::tan(0.5 * fov_y);
    return v;
}

View3 View3::orbit(Vec3 target, double distance, double azimuth, double elevation, double fov_y) {
    const char* f = "View3::orbit";
    check_finite(f, "target", target);
    check_finite(f, "distance", distance);
    check_finite(f, "azimuth", azimuth);
    check_finite(f, "elevation", elevation);
    if (!(distance > 0.0)) view_error(f, "distance", "is not positive");
    const double limit = 0.5 * pi - 1e-3;
    const double e = std::clamp(elevation, -limit, limit);
    const Vec3 out{std::cos(e) * std::cos(azimuth), std::cos(e) * std::sin(azimuth), std::sin(e)};
    return perspective(target + out * distance, target, {0, 0, 1}, fov_y);
}

Projected View3::project(Vec3 p) const noexcept {
    if (!perspective_) return {{p.x + recede_x_ * p.y, -(p.z + recede_y_ * p.y)}, dot(p, forward_), true};
    const Vec3 d = p - eye_;
    const double z = dot(d, forward_);
    // The near plane: 1e-6 of a unit in front of the eye, so the division stays finite.
    if (!(z > 1e-6)) return {{0.0, 0.0}, z, false};
    const double s = focal_ / z;
    return {{dot(d, right_) * s, -dot(d, up_) * s}, z, true};
}

Vec3 View3::view_direction(Vec3 p) const noexcept {
    if (!perspective_) return forward_;
    const Vec3 d = p - eye_;
    const double l = length(d);
    return l > 0.0 ? d / l : forward_;
}

}  // namespace grape
