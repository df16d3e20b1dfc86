// The demo's 3-D picture: a track (a climbing helix, then an S-bend) in an oblique projection,
// with its rotation-minimizing ribbon beside its Frenet ribbon, which turns over at the bend's
// inflection, where the curvature passes through zero.
#include "demo_track3.hpp"

#include <grape/path3.hpp>
#include <grape/view3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace grape::tool {
namespace {

// Oblique projection, z up: x to the right, y receding at 40° above the horizontal at 0.8 scale
// (steeper than cabinet, so that the helix's turns stand apart).
const View3 view = View3::oblique(40.0 * pi / 180.0, 0.8);

Vec2 project3(Vec3 p) { return view.project(p).point; }

Path3 demo_track() {
    // One and a quarter turns up a helix about z, then an S-bend in the plane of its end
    // tangent and the y axis: it first turns on towards the axis, as the helix does, then the
    // other way; planar, so its curvature passes through exactly zero halfway.
    const HelixSpec climb{.center = {0, 0, 0}, .axis = {0, 0, 1}, .start = {1, 0, 0}, .radius = 4, .rise = 3, .turns = 1.25};
    const Path3 helix = Path3::helix(climb);
    const Vec3 p0 = helix.point(1.0);
    const Vec3 t = helix.tangent(1.0);
    const Vec3 side{0, -1, 0};
    const Path3 bend = Path3::cubic_bezier(p0, p0 + t * 5.0, p0 + t * 10.0 + side * 7.0, p0 + t * 15.0 + side * 7.0);
    return Path3::complex_by_length({helix, bend});
}

struct Quad3 {
    std::array<Vec2, 4> corners;
    double depth;
    bool front;
};

}  // namespace

Canvas track3_picture(std::string& figures) {
    const Path3 track = demo_track();
    const RotationMinimizingFrames rmf(track, {0, 0, 1});
    constexpr int samples = 480;
    constexpr double half_width = 0.7;

    // Each ribbon's quads (side = binormal, face normal = the frame's normal), both projected.
    std::vector<Quad3> ribbons[2];
    Bounds world;
    double flip_u = -1.0;
    Vec3 previous_binormal{};
    for (int m = 0; m < 2; ++m) {
        Vec3 last_point{}, last_side{};
        for (int i = 0; i <= samples; ++i) {
            const double u = static_cast<double>(i) / samples;
            Vec3 point, normal, side;
            if (m == 0) {
                const Frame3 f = rmf.frame(u);
                point = f.point;
                normal = f.normal;
                side = f.binormal;
            } else {
                const Frenet3 f = track.frenet(u);
                point = f.point;
                normal = f.normal;
                side = f.binormal;
                if (i > 0 && flip_u < 0.0 && dot(side, previous_binormal) < 0.0) flip_u = u;
                previous_binormal = side;
            }
            world.add(project3(point + side * half_width));
            world.add(project3(point - side * half_width));
            if (i > 0) {
                const Vec3 middle = (point + last_point) * 0.5;
                ribbons[m].push_back({{project3(last_point + last_side * half_width), project3(point + side * half_width),
                                       project3(point - side * half_width), project3(last_point - last_side * half_width)},
                                      view.project(middle).depth,
                                      dot(normal, view.view_direction(middle)) < 0.0});
            }
            last_point = point;
            last_side = side;
        }
    }

    Canvas canvas(1000, 560);
    const TextStyle title{.size = 15, .bold = true};
    const TextStyle label{.color = {0.25, 0.25, 0.25}, .size = 11};
    canvas.text({20, 26}, "A 3-D track: its rotation-minimizing ribbon (left) and its Frenet ribbon (right)", title);
    const Color top{0.95, 0.55, 0.15}, under{0.2, 0.4, 0.85};
    const char* names[] = {"rotation-minimizing: the up side stays up", "Frenet: turns over at the S-bend's inflection"};
    for (int m = 0; m < 2; ++m) {
        const Rect panel{10.0 + 495.0 * m, 40, 485, 480};
        canvas.push();
        canvas.set_transform(fit(world, panel, 20));
        std::vector<Quad3>& quads = ribbons[m];
        // Painter's order: the farthest first.
        std::stable_sort(quads.begin(), quads.end(), [](const Quad3& a, const Quad3& b) { return a.depth > b.depth; });
        for (const Quad3& q : quads) canvas.fill_polygon(q.corners, {.color = q.front ? top : under});
        if (m == 1 && flip_u >= 0.0) canvas.dot(project3(track.point(flip_u)), 5, colors::red);
        canvas.pop();
        canvas.stroke_rect(panel, {.color = colors::light_grey});
        canvas.text({panel.x + 10, panel.y + 20}, names[m], {.size = 12});
    }
    canvas.text({20, 545}, "orange: the frame's normal side, blue: the other; red dot: where the Frenet binormal reverses", label);
    char text[160];
    std::snprintf(text, sizeof text, "length %.2f, %zu frame knots; Frenet flips at u = %.3f", track.length(),
                  rmf.knot_count(), flip_u);
    figures = text;
    return canvas;
}

}  // namespace grape::tool
