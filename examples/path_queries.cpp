// Asking a path questions: snap a dragged point to a track, the frame there, a car driving a
// lane beside the center line over part of the track, and a mouse drag turned into a path.
#include <grape/anim.hpp>
#include <grape/path.hpp>
#include <grape/path_query.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

int main() {
    const grape::ComplexPath track = grape::parse_svg_path("M100 300 C 200 100 400 100 500 300 A 100 100 0 0 1 300 300");

    // Snap: the globally nearest point of the track, and "how far along" it is.
    const grape::ClosestPoint near = grape::closest_point(track, {320, 120});
    const double along = track.length_at(near.u) / track.length();
    std::printf("nearest (%.3f, %.3f) at u = %.6f, %.1f px away, %.0f%% along\n", near.point.x, near.point.y, near.u,
                near.distance, 100 * along);

    // The frame there: where the track points and how sharply it turns.
    const grape::PathFrame f = grape::frame(track, near.u);
    std::printf("tangent (%.3f, %.3f), curvature %.5f /px\n", f.tangent.x, f.tangent.y, f.curvature);

    // A car 12 px beside the center line, over the middle 60% of the track, facing its way.
    grape::Engine engine;
    struct Car {
        double x = 0, y = 0, rotation = 0;
    } car;
    engine.create_2d_animation(car, track, 3.0, {.heading = true, .range_start = 0.2, .range_end = 0.8, .offset = 12.0});
    for (int frame = 0; frame < 90; ++frame) engine.tick(1.0 / 60.0);
    const grape::Vec2 at{car.x, car.y};
    std::printf("car at (%.3f, %.3f) heading %.3f rad, %.3f px from the track\n", car.x, car.y, car.rotation,
                grape::closest_point(track, at).distance);

    // A mouse drag: points in, a few smooth Béziers out.
    std::vector<grape::Vec2> drag;
    for (int i = 0; i <= 100; ++i) drag.push_back({4.0 * i, 50 * std::sin(i / 16.0)});
    const grape::ComplexPath drawn = grape::fit_path(drag, {.tolerance = 0.5});
    std::printf("%zu points -> %zu Beziers: %s\n", drag.size(), drawn.parts().size(), grape::svg_path_data(drawn).c_str());

    // The answers check themselves: the snap is on the track, the car beside it.
    const bool ok = grape::distance(near.point, track.point(near.u)) == 0.0 &&
                    std::abs(grape::closest_point(track, at).distance - 12.0) < 1e-9;
    return ok ? 0 : 1;
}
