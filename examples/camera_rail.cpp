// A camera on a rail: a centripetal Catmull–Rom spline through waypoints, travelled at a
// constant speed, looking along the rail with the horizon level (up is world z without its
// part along the view). A rail that never runs vertical needs no more; a track that loops
// needs rotation-minimizing frames (examples/roller_coaster.cpp).
#include <grape/path3.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

int main() {
    const std::vector<grape::Vec3> waypoints{{0, 0, 2}, {10, 4, 3}, {20, 0, 6}, {30, -6, 4}, {40, 0, 2}};
    const grape::Path3 rail = grape::Path3::catmull_rom(waypoints, grape::CatmullRom::centripetal);
    const double seconds = 8.0;
    for (double t = 0.0; t <= seconds; t += 2.0) {
        const double u = rail.u_at_length(rail.length() * t / seconds);  // constant speed
        const grape::Vec3 eye = rail.point(u);
        const grape::Vec3 look = rail.tangent(u);
        const grape::Vec3 up = grape::normalized(grape::Vec3{0, 0, 1} - look * look.z);
        std::printf("t = %.0f s: eye (%6.2f, %6.2f, %5.2f)  look (%6.3f, %6.3f, %6.3f)  up (%6.3f, %6.3f, %6.3f)\n", t, eye.x,
                    eye.y, eye.z, look.x, look.y, look.z, up.x, up.y, up.z);
    }

    // The answers check themselves: the rail passes through every waypoint (segment i starts
    // at u = i/4), and it never runs within 60° of vertical, where the level horizon holds.
    bool ok = true;
    for (std::size_t i = 0; i < waypoints.size(); ++i)
        ok = ok && grape::distance(rail.point(static_cast<double>(i) / 4.0), waypoints[i]) < 1e-12;
    for (int k = 0; k <= 1000; ++k) ok = ok && std::abs(rail.tangent(k / 1000.0).z) < 0.5;
    return ok ? 0 : 1;
}
