// A camera on a rail: a centripetal Catmull–Rom spline through waypoints, travelled at a
// constant speed, looking along the rail with the horizon level: the reference-up frame keeps
// world z as up without its part along the view (and blends where the rail runs near
// vertical, where that is undefined; a track that loops: examples/roller_coaster.cpp).
#include <grape/frames3.hpp>
#include <grape/path3.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

int main() {
    const std::vector<grape::Vec3> waypoints{{0, 0, 2}, {10, 4, 3}, {20, 0, 6}, {30, -6, 4}, {40, 0, 2}};
    const grape::Path3 rail = grape::Path3::catmull_rom(waypoints, grape::CatmullRom::centripetal);
    const grape::Frames3 camera(rail, {.mode = grape::FrameMode::reference_up, .up = {0, 0, 1}});
    const double seconds = 8.0;
    for (double t = 0.0; t <= seconds; t += 2.0) {
        const double u = rail.u_at_length(rail.length() * t / seconds);  // constant speed
        const grape::Frame3 view = camera.frame(u);  // eye: point, look: tangent, up: normal
        std::printf("t = %.0f s: eye (%6.2f, %6.2f, %5.2f)  look (%6.3f, %6.3f, %6.3f)  up (%6.3f, %6.3f, %6.3f)\n", t,
                    view.point.x, view.point.y, view.point.z, view.tangent.x, view.tangent.y, view.tangent.z,
                    view.normal.x, view.normal.y, view.normal.z);
    }

    // The answers check themselves: the rail passes through every waypoint (segment i starts
    // at u = i/4), and away from vertical (here everywhere) up is level: world z less its part
    // along the view, to rounding.
    bool ok = true;
    for (std::size_t i = 0; i < waypoints.size(); ++i)
        ok = ok && grape::distance(rail.point(static_cast<double>(i) / 4.0), waypoints[i]) < 1e-12;
    for (int k = 0; k <= 1000; ++k) {
        const grape::Frame3 f = camera.frame(k / 1000.0);
        const grape::Vec3 level = grape::normalized(grape::Vec3{0, 0, 1} - f.tangent * f.tangent.z);
        ok = ok && std::abs(f.tangent.z) < 0.5 && grape::distance(f.normal, level) < 1e-12;
    }
    return ok ? 0 : 1;
}
