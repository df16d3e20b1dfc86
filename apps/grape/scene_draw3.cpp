#include "scene_draw3.hpp"

#include "scene_draw.hpp"

#include <grape/error.hpp>
#include <grape/frames3.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

namespace grape::tool {

namespace {

// Path frames every 1/12 of each path's length: enough to show the frame turning along a
// loop, few enough (13 a path) to stay small next to it.
constexpr int path_frame_steps = 12;
// Axis lengths as shares of the content box's diagonal.
constexpr double path_axis_share = 0.035;
constexpr double follower_axis_share = 0.07;
// Flattening tolerance on the picture, output units: under a pixel, so no corner shows.
constexpr double picture_tolerance = 0.25;

const Color tangent_colour = colors::red;
const Color normal_colour = colors::green;
const Color binormal_colour{0.1, 0.3, 0.95};

Bounds3 content_bounds3(const Scene& scene) {
    Bounds3 box;
    const auto add = [&box](const Bounds3& b, double grow) {
        box.add(b.min - Vec3{grow, grow, grow});
        box.add(b.max + Vec3{grow, grow, grow});
    };
    for (const NamedPath3& p : scene.paths3) add(p.path.bounds(), 0.0);
    // A follower offset along its frame stays within |normal| + |binormal| offset of its path.
    for (const SceneAnimation3& a : scene.animations3)
        add(a.path.bounds(), std::fabs(a.normal_offset) + std::fabs(a.binormal_offset));
    if (!is_finite(box.min) || !is_finite(box.max)) {
        box.add(Vec3{0, 0, 0});
        box.add(Vec3{1, 1, 1});
    }
    return box;
}

View3 make_view(const ViewSpec& spec, const Bounds3& box) {
    const double degree = pi / 180.0;
    if (!spec.perspective) return View3::oblique(spec.angle * degree, spec.recede);
    const Vec3 centre = (box.min + box.max) * 0.5;
    const double radius = std::max(0.5 * length(box.max - box.min), 1e-9);
    // The whole bounding sphere inside the vertical field of view.
    const double distance = radius / std::sin(0.5 * spec.fov * degree);
    return View3::orbit(centre, distance, spec.azimuth * degree, spec.elevation * degree, spec.fov * degree);
}

void draw_axes(Canvas& canvas, const View3& view, const Frame3& f, double size, double width, double alpha) {
    const Projected o = view.project(f.point);
    const std::pair<Vec3, Color> axes[] = {{f.tangent, tangent_colour}, {f.normal, normal_colour}, {f.binormal, binormal_colour}};
    for (const auto& [axis, colour] : axes) {
        const Projected e = view.project(f.point + axis * size);
        if (o.visible && e.visible)
            canvas.stroke_line(o.point, e.point, {.color = {colour.r, colour.g, colour.b, alpha}, .width = width});
    }
}

}  // namespace

// From orange on, apart from the paths' first colours.
Color follower_colour(std::size_t i) { return palette_color(i + 4); }

bool has_3d_content(const Scene& scene) { return !scene.paths3.empty() || !scene.animations3.empty(); }

Scene3Picture::Scene3Picture(const Scene& scene, const ViewSpec& spec, double width, double height) : scene_(scene) {
    Bounds3 box = content_bounds3(scene);
    const double diagonal = length(box.max - box.min);
    path_axis_ = path_axis_share * diagonal;
    follower_axis_ = follower_axis_share * diagonal;
    box.add(box.min - Vec3{follower_axis_, follower_axis_, follower_axis_});
    box.add(box.max + Vec3{follower_axis_, follower_axis_, follower_axis_});
    view_ = make_view(spec, box);
    // The box's corners fix the picture: the projection of the box is their convex hull (a
    // parallel projection is linear; a perspective one keeps segments in front of the eye
    // straight), so every frame shares one fit whatever moves inside it.
    Bounds picture;
    double reach = 0.0;  // the largest picture distance from the centre of view (perspective)
    for (int k = 0; k < 8; ++k) {
        const Vec3 c{(k & 1) ? box.max.x : box.min.x, (k & 2) ? box.max.y : box.min.y, (k & 4) ? box.max.z : box.min.z};
        const Vec2 q = view_.project(c).point;
        picture.add(q);
        reach = std::max(reach, length(q));
    }
    fit_ = fit(picture, {0, 0, width, height}, 30);
    if (!view_.is_perspective()) {
        // Columns of the linear map (1, 0), (rx, −ry), (0, −1): its norm is at most the
        // Frobenius norm √(2 + recede²).
        stretch_ = std::sqrt(2.0 + spec.recede * spec.recede);
    } else {
        // q = f·h/d for lateral h and depth d: dq = (f/d)(dh − (q/f)·dd), so |dq| ≤ (f/d)(1 + |q|/f)|dp|
        // with d at least the distance to the sphere around the box.
        const double degree = pi / 180.0;
        const double radius = std::max(0.5 * length(box.max - box.min), 1e-9);
        const double focal = 1.0 / std::tan(0.5 * spec.fov * degree);
        const double nearest = radius / std::sin(0.5 * spec.fov * degree) - radius;
        stretch_ = focal / nearest * (1.0 + reach / focal);
    }
    stretch_ *= fit_.max_stretch();
    for (const NamedPath3& p : scene.paths3) paths_.push_back({p.path, "3-D path '" + p.name + "'"});
    for (std::size_t i = 0; i < scene.animations3.size(); ++i)
        if (scene.animations3[i].path_name.empty())
            paths_.push_back({scene.animations3[i].path, "the path of 3-D animation " + std::to_string(i)});
}

double Scene3Picture::drawn_length_bound(double& longest, std::string& longest_name) const {
    double total = 0.0;
    for (const Drawn3& p : paths_) {
        const double l = p.path.length() * stretch_;
        total += l;
        if (l > longest) longest = l, longest_name = p.name;
    }
    return total;
}

void Scene3Picture::prepare() {
    const double tolerance = picture_tolerance / stretch_;
    for (const Drawn3& p : paths_) {
        std::vector<Vec2>& line = lines_.emplace_back();
        for (Vec3 q : p.path.flatten(tolerance)) line.push_back(view_.project(q).point);
        std::vector<Frame3>& frames = frames_.emplace_back();
        const double l = p.path.length();
        if (!(l > 0.0)) continue;
        // Rotation-minimizing from the world's up, or from y where the path starts vertical.
        std::unique_ptr<Frames3> table;
        for (Vec3 up : {Vec3{0, 0, 1}, Vec3{0, 1, 0}}) {
            try {
                table = std::make_unique<Frames3>(p.path, FramesDef{.up = up});
                break;
            } catch (const Error&) {
            }
        }
        if (!table) continue;
        for (int k = 0; k <= path_frame_steps; ++k) frames.push_back(table->frame(p.path.u_at_length(l * k / path_frame_steps)));
    }
    for (const SceneAnimation3& a : scene_.animations3) motions_.emplace_back(a);
}

Vec2 Scene3Picture::follower(const SceneTiming& timing, std::size_t i, double t) const noexcept {
    return to_picture(motions_[i].position_at(timing.animation3_progress(i, t)));
}

void Scene3Picture::draw(Canvas& canvas, const SceneTiming& timing, double t) const {
    canvas.push();
    canvas.set_transform(fit_);
    // The paths' colours follow the 2-D paths' in the palette.
    std::size_t colour = scene_.paths.size();
    for (const SceneAnimation& a : scene_.animations) colour += a.path_name.empty() ? 1 : 0;
    for (std::size_t k = 0; k < lines_.size(); ++k) {
        const Color c = palette_color(colour + k);
        canvas.stroke_polyline(lines_[k], {.color = {c.r, c.g, c.b, 0.6}, .width = 1.5});
        for (const Frame3& f : frames_[k]) draw_axes(canvas, view_, f, path_axis_, 1.0, 0.55);
    }
    std::vector<Vec2> at;
    for (std::size_t i = 0; i < motions_.size(); ++i) {
        const double p = timing.animation3_progress(i, t);
        if (motions_[i].align() == Align3::frame) draw_axes(canvas, view_, motions_[i].frame_at(p), follower_axis_, 2.0, 1.0);
        at.push_back(view_.project(motions_[i].position_at(p)).point);
    }
    // The dots over every axis, so each follower's centre shows in its own colour.
    for (std::size_t i = 0; i < at.size(); ++i) {
        canvas.dot(at[i], 7.0, colors::black);
        canvas.dot(at[i], 5.0, follower_colour(i));
    }
    for (std::size_t i = 0; i < at.size(); ++i)
        if (!scene_.animations3[i].name.empty()) canvas.text(at[i], "   " + scene_.animations3[i].name, {.size = 11});
    canvas.pop();
}

}  // namespace grape::tool
