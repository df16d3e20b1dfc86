// The endpoint-to-center conversion of an SVG arc (SVG implementation notes F.6.5, with the
// radius correction of F.6.6).
#include "svg_parser.hpp"

#include <grape/math.hpp>

#include <cmath>

namespace grape::detail {
namespace {

// cos and sin of an angle in degrees, exact at multiples of 90° so that axis-aligned arcs
// (the usual case) carry no rounding from the rotation.
void cos_sin_degrees(double degrees, double& c, double& s) noexcept {
    if (degrees == 0.0) { c = 1.0; s = 0.0; return; }
    if (degrees == 90.0) { c = 0.0; s = 1.0; return; }
    if (degrees == 180.0) { c = -1.0; s = 0.0; return; }
    if (degrees == 270.0) { c = 0.0; s = -1.0; return; }
    const double radians = degrees * (pi / 180.0);
    c = std::cos(radians);
    s = std::sin(radians);
}

}  // namespace

bool svg_arc_to_center(Vec2 from, Vec2 to, double rx, double ry, double rotation_degrees, bool large_arc,
                       bool sweep, SvgSegment& out) noexcept {
    rx = std::abs(rx);
    ry = std::abs(ry);
    if (rx == 0.0 || ry == 0.0 || !std::isfinite(rotation_degrees)) return false;
    double degrees = std::fmod(rotation_degrees, 360.0);
    if (degrees < 0.0) degrees += 360.0;
    if (degrees >= 360.0) degrees = 0.0;  // fmod of a tiny negative angle rounds up to 360
    double c = 1.0;
    double s = 0.0;
    cos_sin_degrees(degrees, c, s);

    // Half the chord in the ellipse's own axes (F.6.5.1), halved before subtracting so that
    // endpoints near ±DBL_MAX do not overflow.
    const Vec2 half = from * 0.5 - to * 0.5;
    const double x1 = c * half.x + s * half.y;
    const double y1 = -s * half.x + c * half.y;
    const double h = std::hypot(x1, y1);
    if (!(h > 0.0) || !std::isfinite(h)) return false;
    // Everything below is written with the unit chord direction (xu, yu) and the axis ratio q,
    // so radii many orders of magnitude from the chord neither overflow nor underflow.
    const double xu = x1 / h;
    const double yu = y1 / h;
    const double q = rx / ry;
    if (!(q > 0.0) || !std::isfinite(q)) return false;  // an ellipse flatter than a double holds
    // n² is the SVG notes' Λ: above 1 the radii are too small to reach and are scaled up (F.6.6).
    // Divided directly, x1/rx is exact for the common just-reaching arc (a half circle drawn
    // from its diameter); h·hypot(xu/rx, yu/ry) rounds 1 to 1 − 2⁻⁵³ there, and the square
    // root below turns that into a center offset of 1.5e-8 radii. An overflow gives n = inf:
    // scaled up; an underflow gives n ≈ 0, where the offset is √(1 − n²) ≈ 1 anyway.
    const double n = std::hypot(x1 / rx, y1 / ry);
    // Radii that reach to within a few ulps (decimal data that only rounds to just-reaching:
    // icons draw circles as two half-arcs) reach exactly: the center is the chord's midpoint.
    constexpr double reach_tolerance = 8.0 * std::numeric_limits<double>::epsilon();
    const bool just_reaching = std::abs(1.0 - n * n) <= reach_tolerance;
    double cx = 0.0;
    double cy = 0.0;
    if (just_reaching) {
        // cx = cy = 0 and the radii as given.
    } else if (!(n < 1.0)) {
        rx = h * std::hypot(xu, yu * q);
        ry = h * std::hypot(xu / q, yu);
        if (!std::isfinite(rx) || !std::isfinite(ry)) return false;
    } else {
        // F.6.5.2 divided through by rx²·ry²: the center sits sqrt(1/Λ − 1) half-chords off.
        const double k = std::sqrt((1.0 - n) * (1.0 + n)) * (large_arc == sweep ? -1.0 : 1.0);
        cx = k * rx * (yu / std::hypot(xu / q, yu));
        cy = -k * ry * (xu / std::hypot(xu, yu * q));
    }
    // F.6.5.5–6: start angle and sweep, measured on the unit circle the ellipse maps to.
    const double theta1 = std::atan2((y1 - cy) / ry, (x1 - cx) / rx);
    const double theta2 = std::atan2((-y1 - cy) / ry, (-x1 - cx) / rx);
    double delta = theta2 - theta1;
    if (sweep && delta < 0.0) delta += 2.0 * pi;
    if (!sweep && delta > 0.0) delta -= 2.0 * pi;
    if (delta == 0.0) {
        // The chord vanished against the radii: the small arc is the chord itself, the large
        // one the whole ellipse.
        if (!large_arc) return false;
        delta = sweep ? 2.0 * pi : -2.0 * pi;
    }
    const Vec2 mid = from * 0.5 + to * 0.5;
    out.kind = SvgSegment::Kind::arc;
    out.p[0] = from;
    out.p[1] = to;
    out.center = Vec2{c * cx - s * cy, s * cx + c * cy} + mid;
    out.rx = rx;
    out.ry = ry;
    out.rotation = degrees * (pi / 180.0);
    out.start_angle = theta1;
    out.end_angle = theta1 + delta;
    return is_finite(out.center);
}

}  // namespace grape::detail
