// The demo's rides: a closed coaster with a vertical loop (drifting sideways so that it clears
// itself), banked by bank_track at a stated speed, drawn as its rolled ribbon; and a camera on
// a rail through waypoints, level with the horizon, drawn from outside and from the camera.
#include "demo_rides3.hpp"

#include <grape/frames3.hpp>
#include <grape/path3.hpp>
#include <grape/roll3.hpp>
#include <grape/view3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace grape::tool {
namespace {

// Coaster: 12 units/s through the turns (about 43 km/h at a metre a unit), g = 9.81, banks
// clamped at 1.2 rad, averaged over 6 units of track.
constexpr double coaster_speed = 12.0;

Path3 coaster_track() {
    std::vector<Vec3> points{{-30, -15, 2}, {-10, -15, 2}, {4, -15, 2}};
    // The loop: radius 8 about (15, ·, 10) in the xz plane, drifting 4 units along y per turn.
    for (int k = 0; k <= 8; ++k) {
        const double phi = pi / 4.0 * k;
        points.push_back({15.0 + 8.0 * std::sin(phi), -15.0 + 4.0 * phi / (2.0 * pi), 10.0 - 8.0 * std::cos(phi)});
    }
    for (Vec3 p : {Vec3{28, -11, 2}, Vec3{40, -4, 3}, Vec3{40, 8, 5}, Vec3{28, 15, 7}, Vec3{0, 15, 8},
                   Vec3{-30, 15, 5}, Vec3{-42, 6, 3}, Vec3{-42, -8, 2}})
        points.push_back(p);
    return Path3::catmull_rom(points, CatmullRom::centripetal, true);
}

Path3 camera_rail() {  // scenes/camera_rail3d.json's rail
    const Vec3 points[] = {{0, 0, 2}, {10, 4, 3}, {20, 0, 6}, {30, -6, 4}, {40, 0, 2}};
    return Path3::catmull_rom(points, CatmullRom::centripetal);
}

struct RideQuad {
    std::array<Vec2, 4> corners;
    double depth;
    bool front;
};

}  // namespace

Canvas coaster_picture(std::string& figures) {
    const Path3 track = coaster_track();
    const BankDef bank{.speed = coaster_speed, .gravity = 9.81, .max_angle = 1.2, .smoothing = 6.0};
    const RolledFrames3 frames(Frames3(track, {.mode = FrameMode::reference_up}), bank_track(track, bank));
    const View3 camera = View3::orbit({0, 0, 6}, 95.0, -1.1, 0.45, 0.7);
    constexpr int samples = 900;
    constexpr double half_width = 1.2;
    std::vector<RideQuad> quads;
    Bounds picture;
    Frame3 last = frames.frame(0.0);
    double max_bank = 0.0, max_u = 0.0;
    for (int i = 1; i <= samples; ++i) {
        const double u = static_cast<double>(i) / samples;
        const Frame3 f = frames.frame(u);
        const double b = frames.roll(u);
        if (std::fabs(b) > std::fabs(max_bank)) max_bank = b, max_u = u;
        const auto at = [&camera](Vec3 p) { return camera.project(p).point; };
        const RideQuad q{{at(last.point + last.binormal * half_width), at(f.point + f.binormal * half_width),
                          at(f.point - f.binormal * half_width), at(last.point - last.binormal * half_width)},
                         camera.project((f.point + last.point) * 0.5).depth,
                         dot(f.normal, camera.view_direction(f.point)) < 0.0};
        for (Vec2 c : q.corners) picture.add(c);
        quads.push_back(q);
        last = f;
    }
    std::stable_sort(quads.begin(), quads.end(), [](const RideQuad& a, const RideQuad& b) { return a.depth > b.depth; });
    Canvas canvas(900, 560);
    canvas.push();
    canvas.set_transform(fit(picture, {0, 40, 900, 490}, 20));
    const Color top{0.95, 0.55, 0.15}, under{0.2, 0.4, 0.85};
    for (const RideQuad& q : quads) canvas.fill_polygon(q.corners, {.color = q.front ? top : under});
    const Vec3 peak = track.point(max_u);
    canvas.dot(camera.project(peak).point, 5, colors::red);
    canvas.pop();
    char text[200];
    std::snprintf(text, sizeof text, "largest |bank| %.1f° (into the turn) at u = %.3f (s = %.1f of %.1f), point (%.1f, %.1f, %.1f)",
                  std::fabs(max_bank) * 180.0 / pi, max_u, track.length_at(max_u), track.length(), peak.x, peak.y, peak.z);
    canvas.text({20, 26}, "A coaster with a loop, banked by bank_track for 12 units/s (g = 9.81, clamp 1.2 rad)",
                {.size = 15, .bold = true});
    canvas.text({20, 530}, text, {.size = 12});
    canvas.text({20, 548}, "orange: the rolled frame's up side, blue: its underside; red dot: the largest bank",
                {.color = {0.25, 0.25, 0.25}, .size = 11});
    std::snprintf(text, sizeof text, "at %.0f units/s: largest |bank| %.1f° at s = %.1f", coaster_speed, std::fabs(max_bank) * 180.0 / pi,
                  track.length_at(max_u));
    figures = text;
    return canvas;
}

Canvas camera_rail_picture(std::string& figures) {
    const Path3 rail = camera_rail();
    const Frames3 frames(rail, {.mode = FrameMode::reference_up});
    Canvas canvas(1000, 520);
    canvas.text({20, 26}, "A camera on a rail, level with the horizon: its frames (left) and what it sees at u = 0.4 (right)",
                {.size = 15, .bold = true});
    const TextStyle label{.color = {0.25, 0.25, 0.25}, .size = 11};
    // Left: outside, oblique; the rail, the ground's grid and the camera's frames at six places.
    const View3 side = View3::oblique(0.6981317007977318, 0.8);
    const Rect left{10, 40, 560, 440}, right{590, 40, 400, 300};
    Bounds box;
    const std::vector<Vec3> line = rail.flatten(1e-3);
    constexpr int shots = 6;
    for (Vec3 p : line) box.add(side.project(p).point), box.add(side.project({p.x, p.y, 0.0}).point);
    for (int k = 0; k < shots; ++k) {  // the frames' axes inside the panel too
        const Frame3 f = frames.frame(static_cast<double>(k) / (shots - 1));
        for (Vec3 e : {f.tangent * 4.0, f.normal * 2.5, f.binormal * 2.5}) box.add(side.project(f.point + e).point);
    }
    canvas.push();
    canvas.set_transform(fit(box, left, 30));
    std::vector<Vec2> drawn;
    for (Vec3 p : line) drawn.push_back(side.project(p).point);
    for (Vec3 p : line) canvas.stroke_line(side.project(p).point, side.project({p.x, p.y, 0.0}).point, {.color = {0.8, 0.8, 0.8}, .width = 0.5});
    canvas.stroke_polyline(drawn, {.color = colors::black, .width = 2});
    for (int k = 0; k < shots; ++k) {
        const Frame3 f = frames.frame(static_cast<double>(k) / (shots - 1));
        const Vec2 o = side.project(f.point).point;
        canvas.stroke_line(o, side.project(f.point + f.tangent * 4.0).point, {.color = colors::red, .width = 2});
        canvas.stroke_line(o, side.project(f.point + f.normal * 2.5).point, {.color = colors::green, .width = 2});
        canvas.stroke_line(o, side.project(f.point + f.binormal * 2.5).point, {.color = {0.1, 0.3, 0.95}, .width = 2});
        canvas.dot(o, 4, colors::black);
    }
    canvas.pop();
    canvas.stroke_rect(left, {.color = colors::light_grey});
    canvas.text({left.x + 10, left.y + 460}, "red: view direction (tangent), green: up (normal), blue: right (binormal)", label);
    // Right: from the camera at u = 0.4, looking along the tangent with the frame's up, 60° field.
    const double u_shot = 0.4;
    const Frame3 f = frames.frame(u_shot);
    const View3 eye = View3::perspective(f.point, f.point + f.tangent, f.normal, 1.0471975511965976);
    // The picture's half height is 1: map [−aspect, aspect] × [−1, 1] onto the panel.
    const Affine lens = Affine::translation({right.x + 0.5 * right.width, right.y + 0.5 * right.height}) *
                        Affine::scaling(0.5 * right.height, 0.5 * right.height);
    canvas.fill_rect(right, {.color = {0.93, 0.96, 1.0}});
    canvas.push();
    canvas.clip(right);
    canvas.set_transform(lens);
    // Pieces of a unit or less, each drawn when both ends lie half a unit or more in front of the
    // eye (nearer, the division by the depth blows a piece up across the picture).
    const auto segment = [&](Vec3 a, Vec3 b, const StrokeStyle& style) {
        const int pieces = std::max(1, static_cast<int>(std::ceil(length(b - a))));
        for (int k = 0; k < pieces; ++k) {
            const Projected pa = eye.project(a + (b - a) * (static_cast<double>(k) / pieces));
            const Projected pb = eye.project(a + (b - a) * (static_cast<double>(k + 1) / pieces));
            if (pa.depth > 0.5 && pb.depth > 0.5) canvas.stroke_line(pa.point, pb.point, style);
        }
    };
    for (int g = -10; g <= 50; g += 5) {  // the ground's grid, 5 units apart
        segment({static_cast<double>(g), -20, 0}, {static_cast<double>(g), 20, 0}, {.color = {0.6, 0.7, 0.6}, .width = 0.8});
        segment({-10, static_cast<double>(g) - 20.0, 0}, {50, static_cast<double>(g) - 20.0, 0}, {.color = {0.6, 0.7, 0.6}, .width = 0.8});
    }
    for (std::size_t i = 1; i < line.size(); ++i) segment(line[i - 1], line[i], {.color = colors::black, .width = 2});
    canvas.pop();
    canvas.stroke_rect(right, {.color = colors::light_grey});
    char text[200];
    std::snprintf(text, sizeof text, "from (%.1f, %.1f, %.1f) along (%.2f, %.2f, %.2f)", f.point.x, f.point.y, f.point.z,
                  f.tangent.x, f.tangent.y, f.tangent.z);
    canvas.text({right.x, right.y + right.height + 18}, text, label);
    std::snprintf(text, sizeof text, "rail %.2f long, %d frames shown, the camera's view at u = %.1f", rail.length(), shots, u_shot);
    figures = text;
    return canvas;
}

}  // namespace grape::tool
