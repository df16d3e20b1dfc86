// A ship's orientation: keyed poses joined by a C² quaternion spline (no jerk in its turning at
// the keys), a tween of a Quat member through the engine, and the orientation of a path's frame.
#include <grape/anim.hpp>
#include <grape/frames3.hpp>
#include <grape/path3.hpp>
#include <grape/quat.hpp>
#include <grape/quat_spline.hpp>

#include <cmath>
#include <cstdio>

struct Ship {
    grape::Quat orientation{};
};

int main() {
    using grape::EulerOrder;
    // Poses as yaw, pitch, roll (intrinsic z-y-x), keyed in seconds.
    const grape::QuatSpline turn({0.0, 1.0, 2.5, 4.0},
                                 {grape::from_euler({0.0, 0.0, 0.0}, EulerOrder::zyx),
                                  grape::from_euler({0.8, -0.2, 0.5}, EulerOrder::zyx),
                                  grape::from_euler({1.6, 0.1, -0.3}, EulerOrder::zyx),
                                  grape::from_euler({2.0, 0.0, 0.0}, EulerOrder::zyx)});
    for (double t = 0.0; t <= 4.0; t += 0.5) {
        const grape::EulerAngles a = grape::to_euler(turn.orientation(t), EulerOrder::zyx);
        const grape::Vec3 w = turn.angular_velocity(t);  // rad/s, world axes
        std::printf("t = %.1f s: yaw %6.3f pitch %6.3f roll %6.3f  |w| %.3f rad/s\n", t, a.first, a.second, a.third,
                    grape::length(w));
    }

    // A tween: from the current orientation, a quarter turn about the ship's own x (by composes).
    grape::Engine engine;
    Ship ship{turn.orientation(4.0)};
    engine.animate(ship, &Ship::orientation, grape::by(grape::from_axis_angle({1, 0, 0}, grape::pi / 2)), 1.0);
    engine.tick(1.0);

    // Facing along a path: the frame's tangent becomes the ship's +x, its normal the ship's +y.
    const grape::Path3 rail = grape::Path3::line({0, 0, 0}, {0, 10, 0});
    const grape::Frames3 frames(rail, {.up = {0, 0, 1}});
    const grape::Quat along = grape::from_frame(frames.frame(0.5));

    // The answers check themselves: the keys are hit, the roll came out at π/2, +x runs along +y.
    const double roll = grape::to_euler(ship.orientation, EulerOrder::zyx).third;
    const grape::Vec3 nose = grape::rotate(along, {1, 0, 0});
    const bool ok = std::abs(grape::to_euler(turn.orientation(1.0), EulerOrder::zyx).third - 0.5) < 1e-12 &&
                    std::abs(roll - grape::pi / 2) < 1e-12 && grape::distance(nose, {0, 1, 0}) < 1e-12;
    return ok ? 0 : 1;
}
