#include "scene_draw.hpp"

#include "render_properties.hpp"
#include "render_sprites.hpp"
#include "scene_draw3.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace grape::tool {

namespace {

// Distinct colours for the paths and animations of a scene, in order.
const Color palette[] = {colors::blue, colors::red, colors::green, colors::purple, colors::orange,
                         {0.1, 0.55, 0.6}, {0.6, 0.4, 0.2}, colors::black};

// The timelines that play from scene time 0 (the others are bars inside them).
std::vector<std::size_t> top_level_timelines(const SceneTiming& timing) {
    std::vector<std::size_t> out;
    for (std::size_t k = 0; k < timing.timeline_count(); ++k)
        if (timing.layout(k).parent < 0) out.push_back(k);
    return out;
}

// One row per top-level timeline above the time text: its children as bars over one play,
// labels as ticks, and the playhead at the timeline's own time (which runs back on a yoyo).
void draw_timeline_strips(Canvas& canvas, const Scene& scene, const ScenePlayer& player) {
    const SceneTiming& timing = player.timing();
    const auto rows = top_level_timelines(timing);
    constexpr double row_height = 14.0;
    constexpr std::size_t max_rows = 6;  // the picture is for the paths; more rows are summarised
    const std::size_t shown = std::min(rows.size(), max_rows);
    const double left = 10.0, right = canvas.width() - 10.0;
    const double top = canvas.height() - 26.0 - row_height * static_cast<double>(shown);
    const TextStyle small{.color = colors::grey, .size = 9};
    for (std::size_t r = 0; r < shown; ++r) {
        const std::size_t k = rows[r];
        const SceneTimeline& tl = scene.timelines[k];
        const SceneTimelineLayout& layout = timing.layout(k);
        const double y = top + row_height * static_cast<double>(r);
        const double x0 = left + 90.0;
        const double span = std::max(layout.duration, 1e-9);
        const auto x_of = [&](double s) { return x0 + (right - x0) * std::clamp(s / span, 0.0, 1.0); };
        canvas.text({left, y + 9.0}, tl.name, small);
        canvas.fill_rect({x0, y + 5.0, right - x0, 1.0}, {.color = colors::light_grey});
        for (std::size_t c = 0; c < tl.children.size(); ++c) {
            const SceneTimelineChild& child = tl.children[c];
            const double a = x_of(layout.start[c]), b = x_of(layout.start[c] + layout.length[c]);
            switch (child.kind) {
                case SceneTimelineChildKind::animation: {
                    const std::ptrdiff_t i = layout.index[c];
                    const Color col = palette_color(static_cast<std::size_t>(std::max<std::ptrdiff_t>(i, 0)) + 1);
                    canvas.fill_rect({a, y + 1.0, std::max(b - a, 1.0), 9.0}, {.color = {col.r, col.g, col.b, 0.6}});
                    break;
                }
                case SceneTimelineChildKind::timeline:
                    canvas.fill_rect({a, y + 1.0, std::max(b - a, 1.0), 9.0}, {.color = {0.5, 0.5, 0.5, 0.45}});
                    canvas.text({a + 2.0, y + 8.5}, child.name, {.color = colors::black, .size = 8});
                    break;
                case SceneTimelineChildKind::label:
                    canvas.fill_rect({a, y - 1.0, 1.0, 12.0}, {.color = colors::black});
                    break;
                case SceneTimelineChildKind::gap: break;
                case SceneTimelineChildKind::animation3:  // a 3-D animation (not drawn in the scene): a grey-blue bar with its name
                    canvas.fill_rect({a, y + 1.0, std::max(b - a, 1.0), 9.0}, {.color = {0.3, 0.45, 0.7, 0.45}});
                    canvas.text({a + 2.0, y + 8.5}, child.name, {.color = colors::black, .size = 8});
                    break;
                case SceneTimelineChildKind::tween:  // a property's tween: a pale bar with its name
                    canvas.fill_rect({a, y + 1.0, std::max(b - a, 1.0), 9.0}, {.color = {0.85, 0.6, 0.2, 0.45}});
                    canvas.text({a + 2.0, y + 8.5}, child.name, {.color = colors::black, .size = 8});
                    break;
            }
        }
        const double head = x_of(timing.timeline_time(k, player.time()));
        canvas.fill_rect({head - 0.75, y - 2.0, 1.5, 14.0}, {.color = colors::red});
    }
    if (rows.size() > shown)
        canvas.text({left, top - 4.0}, std::to_string(rows.size() - shown) + " more timelines", small);
}

}  // namespace

Color palette_color(std::size_t i) { return palette[i % std::size(palette)]; }

std::string format(const char* fmt, double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, fmt, v);
    return buffer;
}

Bounds scene_bounds(const Scene& scene, double t_end) {
    Bounds box;
    for (const NamedPath& p : scene.paths) box.add(p.path.bounds());
    for (const SceneAnimation& a : scene.animations) {
        const Bounds b = a.path.bounds();
        const double o = std::fabs(a.offset);  // a lane beside the path stays within |offset| of it
        box.add(b.min - Vec2{o, o});
        box.add(b.max + Vec2{o, o});
    }
    if (!scene.sprites.empty()) {
        const SceneTiming timing(scene);
        for (const SceneSprite& s : scene.sprites) box.add(sprite_position(scene, timing, s, 0.0));
    }
    if (!scene.simulations.empty()) {
        // The whole run (up to 20000 steps each) sets the box, so every frame shares one view.
        const double horizon = bounds_horizon(scene, t_end);
        ScenePlayer runner(scene, true);
        runner.advance_to(horizon);
        for (const auto& trail : runner.trails())
            for (Vec2 p : trail)
                if (is_finite(p)) box.add(p);
        for (const SceneSimulation& s : scene.simulations)
            for (const SceneConstraint& c : s.constraints)
                if (c.kind == SceneConstraintKind::anchor || c.kind == SceneConstraintKind::fixed_point) box.add(c.point);
    }
    if (!is_finite(box.min)) {
        box.add(Vec2{0, 0});
        box.add(Vec2{1, 1});
    }
    return box;
}

void draw_scene(Canvas& canvas, const Scene& scene, const Bounds& world, const ScenePlayer& player) {
    const Affine view = fit(world, {0, 0, canvas.width(), canvas.height()}, 30);
    canvas.set_transform(view);
    std::size_t colour = 0;
    const auto path_style = [&](Color c) {
        return PathStyle{.stroke = {.color = {c.r, c.g, c.b, 0.55}, .width = 1.5}, .ticks = scene.view.ticks};
    };
    for (const NamedPath& p : scene.paths) draw_path(canvas, p.path, path_style(palette_color(colour++)));
    for (const SceneAnimation& a : scene.animations)
        if (a.path_name.empty()) draw_path(canvas, a.path, path_style(palette_color(colour++)));
    for (std::size_t i = 0; i < scene.animations.size(); ++i) {
        const SceneAnimation& a = scene.animations[i];
        const Vec2 p = player.animation_position(i);
        canvas.dot(p, 7.0, colors::black);
        canvas.dot(p, 5.0, palette_color(i + 1));
        if (!a.name.empty()) canvas.text(p + Vec2{0, 0}, "  " + a.name, {.size = 11});
    }
    draw_scene_sprites(canvas, scene, player.timing(), player.time());
    // Constraint curves are traced over the whole visible area (fit is a uniform scale and a move).
    Bounds region;
    region.add(Vec2{(0.0 - view.x0) / view.xx, (0.0 - view.y0) / view.yy});
    region.add(Vec2{(canvas.width() - view.x0) / view.xx, (canvas.height() - view.y0) / view.yy});
    for (std::size_t i = 0; i < scene.simulations.size(); ++i) {
        const SceneSimulation& s = scene.simulations[i];
        const auto positions = player.particle_positions(i);
        for (const SceneConstraint& c : s.constraints) {
            const StrokeStyle constraint_style{.color = colors::grey, .width = 1.0};
            switch (c.kind) {
                case SceneConstraintKind::conic:
                    draw_implicit_curve(canvas, [&c](Vec2 p) { return conic_value(c, p); }, region, constraint_style, 300);
                    break;
                case SceneConstraintKind::anchor:
                    canvas.stroke_line(c.point, positions[c.a], constraint_style);
                    canvas.dot(c.point, 3.0, colors::black);
                    break;
                case SceneConstraintKind::distance: canvas.stroke_line(positions[c.a], positions[c.b], constraint_style); break;
                case SceneConstraintKind::fixed_point: canvas.dot(c.point, 3.0, colors::black); break;
            }
        }
        draw_particles(canvas, positions, {}, player.inverse_masses(i), {.color = palette_color(i)});
    }
    canvas.set_transform({});
    if (!scene.timelines.empty()) draw_timeline_strips(canvas, scene, player);
    draw_scene_properties(canvas, scene, player.timing(), player.time());
    std::string title = scene.name.empty() ? std::string("grape scene") : scene.name;
    const auto room = static_cast<std::size_t>(canvas.width() / 8.0);  // ~8 units per bold 13-unit glyph
    if (title.size() > room && room > 3) title = title.substr(0, room - 3) + "...";
    canvas.text({10, 18}, title, {.size = 13, .bold = true});
    canvas.text({10, canvas.height() - 10}, format("t = %.3f s", player.time()), {.color = colors::grey, .size = 11});
}

std::string scene_animated_svg(const Scene& scene, const Bounds& world, double t0, int frames, double fps,
                               const Scene3Picture* picture3) {
    const Affine t = fit(world, {0, 0, scene.view.width, scene.view.height}, 30);
    std::vector<Path> paths;
    for (const NamedPath& p : scene.paths) paths.push_back(p.path);
    for (const SceneAnimation& a : scene.animations)
        if (a.path_name.empty()) paths.push_back(a.path);
    // The 3-D picture is in output units: back to the 2-D world's through the fit (a uniform
    // scale and a move).
    const auto world_of = [&t](Vec2 q) { return Vec2{(q.x - t.x0) / t.xx, (q.y - t.y0) / t.yy}; };
    if (picture3)
        for (const auto& line : picture3->polylines()) {
            std::vector<Vec2> points;
            for (Vec2 q : line) points.push_back(world_of(q));
            if (points.size() >= 2) paths.push_back(LinearSplinePath(points));
        }
    std::vector<SvgMover> movers;
    for (std::size_t i = 0; i < scene.animations.size(); ++i)
        movers.push_back({.color = palette_color(i + 1), .label = scene.animations[i].name});
    for (std::size_t i = 0; i < scene.simulations.size(); ++i)
        for (std::size_t k = 0; k < scene.simulations[i].particles.size(); ++k)
            movers.push_back({.color = palette_color(i), .label = scene.simulations[i].name});
    if (picture3)
        for (std::size_t i = 0; i < scene.animations3.size(); ++i)
            movers.push_back({.color = follower_colour(i), .label = scene.animations3[i].name});
    ScenePlayer player(scene);
    for (int f = 0; f < frames; ++f) {
        player.advance_to(t0 + f / fps);
        std::size_t m = 0;
        for (std::size_t i = 0; i < scene.animations.size(); ++i) movers[m++].positions.push_back(player.animation_position(i));
        for (std::size_t i = 0; i < scene.simulations.size(); ++i)
            for (Vec2 p : player.particle_positions(i)) movers[m++].positions.push_back(p);
        if (picture3)
            for (std::size_t i = 0; i < scene.animations3.size(); ++i)
                movers[m++].positions.push_back(world_of(picture3->follower(player.timing(), i, player.time())));
    }
    return animated_svg(scene.view.width, scene.view.height, t, paths, palette, movers, frames / fps, scene.name);
}

}  // namespace grape::tool
