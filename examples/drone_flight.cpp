// A drone flies a 3-D track in the engine: constant speed along the reparametrized path, its
// model (facing −z, up +y, the OpenGL convention) turned by the track's rotation-minimizing
// frame, half a metre above the rail along the frame's normal, back and forth forever.
#include <grape/anim.hpp>

#include <cmath>
#include <cstdio>

struct Drone {
    double x = 0, y = 0, z = 0;
    grape::Basis orientation;  // where the model's axes point
};

int main() {
    const grape::Path3 track = grape::Path3::cubic_bezier({0, 0, 1}, {10, 0, 1}, {10, 10, 6}, {20, 10, 6});
    grape::Engine engine;
    Drone drone;
    engine.create_3d_animation(drone, track, grape::Speed{4.0}, {.repeat = -1, .yoyo = true},
                               {.align = grape::Align3::frame,
                                .frames = {.up = {0, 0, 1}},
                                .forward = grape::Axis3::neg_z,
                                .up = grape::Axis3::pos_y,
                                .normal_offset = 0.5});
    for (int frame = 0; frame < 60 * 4; ++frame) engine.tick(1.0 / 60);  // 4 s at 4 m/s: 16 m
    const grape::Vec3 nose = -drone.orientation.z;  // the model faces −z
    std::printf("at (%.2f, %.2f, %.2f), nose (%.3f, %.3f, %.3f)\n", drone.x, drone.y, drone.z, nose.x, nose.y,
                nose.z);

    // The answers check themselves: 16 m along the track (to the reparametrization's 1e-9 and
    // the summed frame times), half a metre from it, and the nose along the tangent there.
    const grape::Vec3 at{drone.x, drone.y, drone.z};
    const grape::Vec3 on = at - drone.orientation.y * 0.5;  // back down the normal onto the track
    const grape::Closest3 c = grape::closest_point(track, on);
    const bool ok = c.distance < 1e-9 && std::abs(track.length_at(c.u) - 16.0) < 1e-6 &&
                    grape::approx_equal(nose, track.tangent(c.u), 1e-9);
    return ok ? 0 : 1;
}
