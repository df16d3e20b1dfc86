// A race track that banks itself: a straight, a half circle of radius 25 m and a straight back.
// At 20 m/s the cars lean into the turn by atan(v²/(g·R)) = 1.02 rad, eased in and out over 10 m
// of track; a barrel roll keyed by arc length spins them once on the last straight; the
// track's width, data along the path, narrows in the turn.
#include <grape/frames3.hpp>
#include <grape/path3.hpp>
#include <grape/path_data.hpp>
#include <grape/roll3.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

int main() {
    const double r = 25.0, v = 20.0;
    const grape::Path3 track = grape::Path3::complex_by_length({
        grape::Path3::line({-50, -r, 0}, {0, -r, 0}),
        grape::Path3::arc({.center = {0, 0, 0}, .start = {0, -1, 0}, .radius = r, .start_angle = 0, .end_angle = grape::pi}),
        grape::Path3::line({0, r, 0}, {-50, r, 0}),
    });
    const grape::RollTrack bank = grape::bank_track(track, {.speed = v, .max_angle = 1.2, .smoothing = 10.0});
    const grape::RolledFrames3 car(grape::Frames3(track, {.mode = grape::FrameMode::reference_up}), bank);
    const double turn_end = 50.0 + grape::pi * r;
    const std::vector<grape::RollKey> spin{{0.0, 0.0}, {turn_end + 15.0, 0.0}, {turn_end + 35.0, 2.0 * grape::pi}};
    const grape::RolledFrames3 stunt(track, grape::RollTrack(spin, {.curves = {grape::Curve(), grape::Curve::quad_in_out()}}));
    const grape::PathData<double> width(grape::PathDataKey::arc_length, {{0.0, 12.0}, {50.0, 12.0}, {60.0, 9.0}});
    for (double s : {25.0, 50.0, 50.0 + grape::pi * r / 2, turn_end + 25.0}) {
        const double u = track.u_at_length(s);
        const grape::Frame3 f = car.frame(u);
        std::printf("%6.1f m: bank %.3f rad, up (%6.3f, %6.3f, %5.3f), width %4.1f m, stunt roll %.3f rad\n", s,
                    car.roll(u), f.normal.x, f.normal.y, f.normal.z, width.at_u(track, u), stunt.roll(u));
    }
    const double mid = car.roll(track.u_at_length(50.0 + grape::pi * r / 2));
    return std::abs(std::abs(mid) - std::atan(v * v / (9.81 * r))) < 1e-12 ? 0 : 1;
}
