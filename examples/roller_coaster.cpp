// A roller coaster with a loop: a straight run in, one turn of a helix standing on end (it
// drifts 1.5 m sideways, so the track clears itself) and a run out. The rider's "up" is the
// rotation-minimizing frame's normal: it never spins about the track, so at the top of the
// loop the rider hangs upside down, and comes out of the loop banked by the loop's twist alone,
// 2π·c/√(r² + c²) radians for a rise of 2π·c per turn (0.30 rad here).
#include <grape/path3.hpp>

#include <cmath>
#include <cstdio>

int main() {
    const double r = 5.0;  // loop radius, metres
    const grape::Path3 track = grape::Path3::complex_by_length({
        grape::Path3::line({-20, 0, 0}, {0, 0, 0}),
        grape::Path3::helix({.center = {0, 0, r}, .axis = {0, -1, 0}, .start = {0, 0, -1}, .radius = r,
                             .rise = 1.5, .turns = 1}),
        grape::Path3::line({0, -1.5, 0}, {20, -1.5, 0}),
    });
    const grape::RotationMinimizingFrames rider(track, {0, 0, 1});  // upright at the start
    const double loop = std::sqrt(std::pow(2.0 * grape::pi * r, 2) + 1.5 * 1.5);  // one helix turn
    bool upside_down = false;
    for (double s : {10.0, 20.0 + loop / 4, 20.0 + loop / 2, 20.0 + 3 * loop / 4, 30.0 + loop}) {
        const double u = track.u_at_length(s);
        const grape::Frame3 f = rider.frame(u);
        std::printf("%5.1f m: at (%6.2f, %5.2f, %5.2f), rider's up (%6.3f, %6.3f, %6.3f)\n", s, f.point.x, f.point.y,
                    f.point.z, f.normal.x, f.normal.y, f.normal.z);
        if (s == 20.0 + loop / 2) upside_down = f.point.z > 2 * r - 0.01 && f.normal.z < -0.9;
    }
    // The bank coming out is the twist, within the frames' tolerance (1e-9 rad over the track).
    const grape::Frame3 out = rider.frame(1.0);
    const double c = 1.5 / (2.0 * grape::pi);
    const double bank = std::atan2(out.normal.y, out.normal.z);
    std::printf("banked %.9f rad coming out (the twist: %.9f rad)\n", bank, 2.0 * grape::pi * c / std::hypot(r, c));
    return upside_down && std::abs(bank - 2.0 * grape::pi * c / std::hypot(r, c)) < 1e-9 ? 0 : 1;
}
