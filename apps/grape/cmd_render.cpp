// `grape render` (a scene file to pictures) and the demo's pictures (the seed's images).
#include "commands.hpp"

#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/render.hpp>
#include <grape/scene.hpp>
#include <grape/sprite.hpp>

#include "seed_paths.hpp"

#include "atomic_file.hpp"
#include "progress.hpp"
#include "render_sprites.hpp"

#if GRAPE_HAS_DYNAMICS
#include <grape/dynamics.hpp>
#endif
#ifdef GRAPE_TOOL_DYNAMICS
#include "seed_dynamics.hpp"
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace grape::tool {

namespace {

// Distinct colours for the paths and animations of a scene, in order.
const Color palette[] = {colors::blue, colors::red, colors::green, colors::purple, colors::orange,
                         {0.1, 0.55, 0.6}, {0.6, 0.4, 0.2}, colors::black};

Color palette_color(std::size_t i) { return palette[i % std::size(palette)]; }

std::string format(const char* fmt, double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, fmt, v);
    return buffer;
}

// ------------------------------------------------------------------ simulations over time

// A scene's simulations stepped forward on demand, with their trajectories recorded (for
// the picture's bounds and the trails). Without the dynamics module they stay at rest.
class SimulationRunner {
public:
    /// With RECORD_TRAILS every position after every step is kept (for the picture's bounds,
    /// over at most 20000 steps); without it memory stays at the particles' current state.
    explicit SimulationRunner(const Scene& scene, bool record_trails = false) : scene_(scene), record_trails_(record_trails) {
#if GRAPE_HAS_DYNAMICS
        for (const SceneSimulation& s : scene.simulations) systems_.push_back(make_particle_system(s));
#endif
        trails_.resize(scene.simulations.size());
        for (std::size_t i = 0; i < scene.simulations.size(); ++i) record(i);
    }

    /// Advances every simulation to time t (never backwards; capped at its duration).
    void advance_to(double t) {
#if GRAPE_HAS_DYNAMICS
        for (std::size_t i = 0; i < systems_.size(); ++i) {
            const SceneSimulation& s = scene_.simulations[i];
            const double target = std::min(t, s.duration);
            // Whole steps of dt; the half-step slack keeps rounding from adding one more.
            while (systems_[i].time() + 0.5 * s.dt < target) {
                systems_[i].step(s.dt);
                record(i);
            }
        }
#else
        (void)t;
#endif
    }

    std::vector<Vec2> positions(std::size_t i) const {
#if GRAPE_HAS_DYNAMICS
        const auto p = systems_[i].positions();
        return {p.begin(), p.end()};
#else
        std::vector<Vec2> out;
        for (const SceneParticle& p : scene_.simulations[i].particles) out.push_back(p.position);
        return out;
#endif
    }

    std::vector<double> inverse_masses(std::size_t i) const {
        std::vector<double> out;
        for (const SceneParticle& p : scene_.simulations[i].particles) out.push_back(std::isinf(p.mass) ? 0.0 : 1.0 / p.mass);
        return out;
    }

    const std::vector<std::vector<Vec2>>& trails() const noexcept { return trails_; }

private:
    void record(std::size_t i) {
        if (!record_trails_) return;
        const auto p = positions(i);
        trails_[i].insert(trails_[i].end(), p.begin(), p.end());
    }

    const Scene& scene_;
    bool record_trails_;
#if GRAPE_HAS_DYNAMICS
    std::vector<ParticleSystem> systems_;
#endif
    std::vector<std::vector<Vec2>> trails_;  // every particle's position after every step
};

// The world box the picture shows: every path, and every particle over the whole run.
Bounds scene_bounds(const Scene& scene, double t_end) {
    Bounds box;
    for (const NamedPath& p : scene.paths) box.add(p.path.bounds());
    for (const SceneAnimation& a : scene.animations) box.add(a.path.bounds());
    for (const SceneSprite& s : scene.sprites) box.add(sprite_position(scene, s, 0.0));
    if (!scene.simulations.empty()) {
        // The whole run (up to 20000 steps each) sets the box, so every frame shares one view.
        double horizon = t_end;
        for (const SceneSimulation& s : scene.simulations) horizon = std::max(horizon, std::min(s.duration, 20000.0 * s.dt));
        SimulationRunner runner(scene, true);
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

// Draws the scene at time t: paths (with the view's ticks), animation markers, simulations.
void draw_scene(Canvas& canvas, const Scene& scene, const Bounds& world, double t, const SimulationRunner& sims) {
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
        const Vec2 p = a.position(t);
        canvas.dot(p, 7.0, colors::black);
        canvas.dot(p, 5.0, palette_color(i + 1));
        if (!a.name.empty()) canvas.text(p + Vec2{0, 0}, "  " + a.name, {.size = 11});
    }
    draw_scene_sprites(canvas, scene, t);
    // Constraint curves are traced over the whole visible area (fit is a uniform scale and a move).
    Bounds region;
    region.add(Vec2{(0.0 - view.x0) / view.xx, (0.0 - view.y0) / view.yy});
    region.add(Vec2{(canvas.width() - view.x0) / view.xx, (canvas.height() - view.y0) / view.yy});
    for (std::size_t i = 0; i < scene.simulations.size(); ++i) {
        const SceneSimulation& s = scene.simulations[i];
        const auto positions = sims.positions(i);
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
        draw_particles(canvas, positions, {}, sims.inverse_masses(i), {.color = palette_color(i)});
    }
    canvas.set_transform({});
    std::string title = scene.name.empty() ? std::string("grape scene") : scene.name;
    const auto room = static_cast<std::size_t>(canvas.width() / 8.0);  // ~8 units per bold 13-unit glyph
    if (title.size() > room && room > 3) title = title.substr(0, room - 3) + "...";
    canvas.text({10, 18}, title, {.size = 13, .bold = true});
    canvas.text({10, canvas.height() - 10}, format("t = %.3f s", t), {.color = colors::grey, .size = 11});
}

// OUT-0001.png for frame 1 of OUT.png.
std::filesystem::path frame_file(const std::filesystem::path& out, int index) {
    char number[16];
    std::snprintf(number, sizeof number, "-%04d", index);
    return out.parent_path() / (out.stem().string() + number + out.extension().string());
}

std::string lower_extension(const std::filesystem::path& p) {
    std::string e = p.extension().string();
    for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

// The animated SVG of a scene: its paths once, and every animation and particle as a marker
// stepping through its positions at the frame times.
std::string scene_animated_svg(const Scene& scene, const Bounds& world, double t0, int frames, double fps) {
    const Affine t = fit(world, {0, 0, scene.view.width, scene.view.height}, 30);
    std::vector<Path> paths;
    for (const NamedPath& p : scene.paths) paths.push_back(p.path);
    for (const SceneAnimation& a : scene.animations)
        if (a.path_name.empty()) paths.push_back(a.path);
    std::vector<SvgMover> movers;
    for (std::size_t i = 0; i < scene.animations.size(); ++i) {
        SvgMover m{.color = palette_color(i + 1), .label = scene.animations[i].name};
        for (int f = 0; f < frames; ++f) m.positions.push_back(scene.animations[i].position(t0 + f / fps));
        movers.push_back(std::move(m));
    }
    SimulationRunner sims(scene);
    const std::size_t first_particle = movers.size();
    for (std::size_t i = 0; i < scene.simulations.size(); ++i)
        for (std::size_t k = 0; k < scene.simulations[i].particles.size(); ++k)
            movers.push_back({.color = palette_color(i), .label = scene.simulations[i].name});
    for (int f = 0; f < frames; ++f) {
        sims.advance_to(t0 + f / fps);
        std::size_t m = first_particle;
        for (std::size_t i = 0; i < scene.simulations.size(); ++i)
            for (Vec2 p : sims.positions(i)) movers[m++].positions.push_back(p);
    }
    return animated_svg(scene.view.width, scene.view.height, t, paths, palette, movers, frames / fps, scene.name);
}

struct RenderOptions {
    std::string scene;
    std::string out;
    double time = 0.0;
    int frames = 0;  // 0: one picture (--frames not given)
    bool frames_given = false;
    double fps = 30.0;
    bool force = false;
    bool strict = false;  // the scene's warnings are errors
};

// The work `grape render` takes on without --force (stated in --help and the README).
constexpr double memory_budget = 1024.0 * 1024.0 * 1024.0;  // bytes of raster per picture
constexpr int max_frames = 100000;
constexpr double max_drawn_length = 1e6;  // output units of path drawn per picture (~1000 view perimeters)

std::string mebibytes(double bytes) {
    if (bytes < 1024.0 * 1024.0) return format("%.1f KiB", bytes / 1024.0);
    if (bytes < 1024.0 * 1024.0 * 1024.0) return format("%.1f MiB", bytes / (1024.0 * 1024.0));
    return format("%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
}

// Free bytes on the filesystem holding FOLDER (infinite when unknown).
double free_bytes(const std::filesystem::path& folder) {
    std::error_code ec;
    const auto space = std::filesystem::space(folder.empty() ? std::filesystem::path(".") : folder, ec);
    return ec ? HUGE_VAL : static_cast<double>(space.available);
}

void run_render(const RenderOptions& o) {
    const std::filesystem::path out = o.out;
    const std::string ext = lower_extension(out);
    if (ext != ".png" && ext != ".svg" && ext != ".pdf")
        throw Error("render: -o " + o.out + ": the output must end in .png, .svg or .pdf");
    if (!std::isfinite(o.time) || o.time < 0.0) throw Error("render: --time must be finite and ≥ 0 (got " + format("%g", o.time) + ")");
    if (o.frames_given && (o.frames < 1 || o.frames > max_frames))
        throw Error("render: --frames must be in [1, 100000] (got " + std::to_string(o.frames) + ")");
    if (!std::isfinite(o.fps) || o.fps <= 0.0 || o.fps > 10000.0) throw Error("render: --fps must be in (0, 10000] (got " + format("%g", o.fps) + ")");
    const auto parent = out.parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent))
        throw Error("cannot write " + o.out + ": folder " + parent.string() + " does not exist");
    std::error_code ec;
    if (std::filesystem::is_directory(out, ec)) throw Error("cannot write " + o.out + ": it is a folder");
    current_activity() = "reading " + o.scene;
    const Scene scene = load_scene_file(o.scene);
    report_scene_warnings(scene, o.scene, o.strict);
    load_sprite_pictures(scene);
    const int frames = o.frames_given ? o.frames : 1;
    // A PNG picture is rasterized twice over (cairo's surface and the image copied out of it).
    const double raster = std::ceil(scene.view.width) * std::ceil(scene.view.height) * 4.0 * 2.0;
    if (ext == ".png" && raster > memory_budget && !o.force)
        throw Error("render: a " + format("%.0f", scene.view.width) + "×" + format("%.0f", scene.view.height) +
                    " picture needs about " + mebibytes(raster) + " of memory, more than the budget of " +
                    mebibytes(memory_budget) + " (use --force to render it anyway)");
    const double t_end = o.time + (frames - 1) / o.fps;
    current_activity() = "computing the bounds of " + o.scene;
    const Bounds world = scene_bounds(scene, t_end);
    // cairo's stroking time grows with the length drawn (faster than linearly where a path
    // overlaps itself, as a circle of many turns does): bound the length on the picture.
    const double scale = fit(world, {0, 0, scene.view.width, scene.view.height}, 30).max_stretch();
    double drawn = 0.0, longest = 0.0;
    std::string longest_name;
    const auto count = [&](const Path& p, const std::string& name) {
        const double length = p.length() * scale;
        drawn += length;
        if (length > longest) longest = length, longest_name = name;
    };
    for (const NamedPath& p : scene.paths) count(p.path, "path '" + p.name + "'");
    for (std::size_t i = 0; i < scene.animations.size(); ++i)
        if (scene.animations[i].path_name.empty()) count(scene.animations[i].path, "the path of animation " + std::to_string(i));
    if (drawn > max_drawn_length && !o.force)
        throw Error("render: the scene's paths are " + format("%.3g", drawn) + " units long on the picture (" + longest_name +
                    ": " + format("%.3g", longest) + "), more than the budget of " + format("%.0g", max_drawn_length) +
                    " units a picture (use --force to render them anyway)");

    if (o.frames_given && ext == ".svg") {
        current_activity() = "building the animated SVG " + o.out;
        detail::write_file_atomically(out, scene_animated_svg(scene, world, o.time, frames, o.fps));
        std::cout << "wrote " << out.string() << " (" << frames << " frames at " << o.fps << " fps, animated SVG)\n";
        return;
    }
    SimulationRunner sims(scene);
    // All frames or none: a half-written sequence is worse than a clear error, so a failure
    // or an interruption (SIGINT, SIGTERM) removes every frame this run wrote.
    detail::RunFiles written;
    Progress progress("render: frame", frames, 1);
    for (int f = 0; f < frames; ++f) {
        const double t = o.time + f / o.fps;
        sims.advance_to(t);
        const auto file = o.frames_given ? frame_file(out, f + 1) : out;
        current_activity() = "drawing " + file.string() + " (" + format("%.0f", scene.view.width) + "×" +
                             format("%.0f", scene.view.height) + ")";
        Canvas canvas(scene.view.width, scene.view.height);
        draw_scene(canvas, scene, world, t, sims);
        // A single picture replaces its file only when complete (an old one survives a failure);
        // a frame is registered before it is written, so an interruption cannot miss it.
        if (o.frames_given) written.add(file);
        canvas.write(file);
        if (f == 0 && frames > 1 && !o.force) {
            // The first frame's size times the frame count, against the free space left.
            const double first = static_cast<double>(std::filesystem::file_size(file, ec));
            const double needed = first * (frames - 1);
            const double available = free_bytes(parent);
            if (!ec && needed > available)
                throw Error("render: " + std::to_string(frames) + " frames need about " + mebibytes(first * frames) +
                            " (the first is " + mebibytes(first) + ") but " + mebibytes(available) +
                            " are free where " + o.out + " goes (use --force to try anyway)");
        }
        progress.update(f + 1);
    }
    progress.done();
    written.keep();
    if (o.frames_given)
        std::cout << "wrote " << frames << " frames " << frame_file(out, 1).string() << " … " << frame_file(out, frames).string() << '\n';
    else
        std::cout << "wrote " << out.string() << '\n';
}

// ------------------------------------------------------------------------- demo pictures

struct Written {
    std::string file;
    std::string what;
    std::string figures;
};

// The seed's tile-sheet sprite, drawn here: 8 frames of a turning bar on a 4 × 2 sheet.
Image make_tile_sheet_image() {
    Canvas sheet(128, 64, colors::transparent);
    for (int f = 0; f < 8; ++f) {
        const Vec2 centre{32.0 * (f % 4) + 16.0, 32.0 * (f / 4) + 16.0};
        const double a = f * pi / 8.0;
        const Vec2 d{std::cos(a) * 12.0, std::sin(a) * 12.0};
        sheet.fill_rect({32.0 * (f % 4) + 1, 32.0 * (f / 4) + 1, 30, 30}, {.color = {0.93, 0.95, 1.0}});
        sheet.stroke_line(centre - d, centre + d, {.color = colors::purple, .width = 5});
        sheet.dot(centre, 3, colors::orange);
    }
    return sheet.to_image();
}

}  // namespace

void register_render_command(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    auto* cmd = app.add_subcommand("render", "Render a scene file to PNG, SVG or PDF (frames, or an animated SVG)");
    cmd->add_option("scene", options->scene, "Scene file (JSON, see docs/scene-format.md)")->required();
    cmd->add_option("-o,--out", options->out, "Output file: .png, .svg or .pdf")->required();
    cmd->add_option("--time", options->time, "Scene time in seconds of the (first) picture, ≥ 0")->capture_default_str();
    cmd->add_option_function<int>(
        "--frames", [options](int n) { options->frames = n, options->frames_given = true; },
        "Number of frames in [1, 100000]: OUT-0001.png, ...; with .svg one animated SVG (SMIL). All or none are "
        "left: a failure or Ctrl-C removes the frames written");
    cmd->add_option("--fps", options->fps, "Frames per second of scene time, in (0, 10000]")->capture_default_str();
    cmd->add_flag("--force", options->force,
                  "Render even when a PNG picture needs more than 1 GiB of raster memory (views up to 32768×32768) or "
                  "the frames look larger than the free disk space (estimated from the first frame) or the paths are "
                  "longer than 1e6 output units on the picture");
    cmd->add_flag("--strict", options->strict,
                  "Refuse a scene that loads with warnings (SVG path data with a syntax error, read by SVG's error "
                  "rule) instead of printing them on stderr and rendering");
    cmd->callback([options] { run_render(*options); });
}

void demo_pictures(const DemoContext& context) {
    std::vector<Written> written;
    const auto save = [&](const Canvas& canvas, const std::string& name, std::string what, std::string figures = {}) {
        const auto file = context.dir / name;
        canvas.write(file);
        written.push_back({file.string(), std::move(what), std::move(figures)});
    };
    const TextStyle title{.size = 15, .bold = true};
    const TextStyle label{.color = {0.25, 0.25, 0.25}, .size = 10};

    // 1. Every path kind in one gallery, with u-ticks every 0.05 and the start/end marks.
    {
        Canvas canvas(700, 700);
        canvas.set_transform(Affine::translation({50, 60}));
        const auto gallery = scenes::path_gallery();
        std::size_t i = 0;
        std::vector<Vec2> labelled;  // paths that start together get their labels stacked
        for (const auto& [name, path] : gallery) {
            draw_path(canvas, path, {.stroke = {.color = palette_color(i), .width = 2}, .ticks = 0.05, .tick_length = 6});
            const Vec2 start = path.point(0.0);
            const auto same = std::count_if(labelled.begin(), labelled.end(), [&](Vec2 p) { return distance(p, start) < 1.0; });
            labelled.push_back(start);
            canvas.text(start + Vec2{0, -9.0 - 11.0 * static_cast<double>(same)}, name,
                        {.color = palette_color(i++), .size = 10});
        }
        canvas.set_transform({});
        canvas.text({20, 28}, "Every path kind (ticks every 0.05 of u; hollow start, filled end)", title);
        save(canvas, "gallery.png", "every path kind", std::to_string(gallery.size()) + " paths");
        canvas.write(context.dir / "gallery.svg");
        canvas.write(context.dir / "gallery.pdf");
        written.push_back({(context.dir / "gallery.svg").string(), "the same, as SVG", ""});
        written.push_back({(context.dir / "gallery.pdf").string(), "the same, as PDF", ""});
    }

    // 2. The seed's spline image: top to bottom linear, cosine, Catmull-Rom through p1, p2, p3.
    {
        Canvas canvas(560, 560);
        canvas.set_transform(Affine::translation({10, 40}));
        const std::pair<const char*, Path> splines[] = {{"linear", scenes::seed_linear_spline()},
                                                        {"cosine", scenes::seed_cosine_spline()},
                                                        {"Catmull-Rom", scenes::seed_catmull_rom_spline()}};
        const std::array<double, 12>* points[] = {&scenes::seed_p1, &scenes::seed_p2, &scenes::seed_p3};
        std::string figures;
        for (int k = 0; k < 3; ++k) {
            draw_path(canvas, splines[k].second, {.stroke = {.color = colors::black, .width = 1.5}, .ends = false});
            for (std::size_t j = 0; j + 1 < points[k]->size(); j += 2)
                canvas.dot({(*points[k])[j], (*points[k])[j + 1]}, 3, colors::red);
            canvas.text({540, 30 + 100.0 * k}, splines[k].first, {.size = 11, .align = TextAlign::right});
            figures += std::string(k ? ", " : "") + splines[k].first + " " + format("%.1f px", splines[k].second.length());
        }
        canvas.set_transform({});
        canvas.text({20, 20}, "Splines through the seed's points: linear, cosine, Catmull-Rom", title);
        save(canvas, "splines.png", "the seed's spline image", figures);
    }

    // 3. Arc length: the same Bézier tweened with and without reparametrization, the tween's
    //    position marked every tenth of the duration. Black: reparametrized; red: not.
    {
        const Path plain = scenes::seed_bezier(false);
        const Path even = scenes::seed_bezier(true);
        Canvas canvas(660, 660);
        canvas.set_transform(Affine::translation({20, 40}));
        canvas.stroke_path(plain, {.color = colors::light_grey, .width = 6});
        double spread_plain = 0.0, spread_even = 0.0, min_plain = 1e300, min_even = 1e300;
        for (int k = 0; k <= 10; ++k) {
            const double u = k / 10.0;
            canvas.stroke_circle(plain.point(u), 7, {.color = colors::red, .width = 2});
            canvas.fill_circle(even.point(u), 4, {.color = colors::black});
            if (k > 0) {
                const double dp = distance(plain.point(u), plain.point(u - 0.1));
                const double de = distance(even.point(u), even.point(u - 0.1));
                spread_plain = std::max(spread_plain, dp);
                spread_even = std::max(spread_even, de);
                min_plain = std::min(min_plain, dp);
                min_even = std::min(min_even, de);
            }
        }
        canvas.set_transform({});
        canvas.text({20, 24}, "The black tween has been reparametrized, the red has not", title);
        canvas.text({20, 640}, "frames every tenth of the duration, linear curve; " +
                                   format("red steps %.0f", min_plain) + format("–%.0f px, ", spread_plain) +
                                   format("black %.1f", min_even) + format("–%.1f px", spread_even),
                    label);
        save(canvas, "arc_length.png", "the arc-length comparison",
             format("chord step max/min: plain %.2f", spread_plain / min_plain) +
                 format(", reparametrized %.6f", spread_even / min_even));
    }

    // 4. The two complex-path examples, with their (nested) cues marked and u-ticks.
    {
        const std::pair<const char*, Path> examples[] = {
            {"complex.png", scenes::seed_complex()}, {"nested_complex.png", scenes::seed_nested_complex()}};
        const char* titles[] = {"ComplexPath: spiral, then three segments (cues 0, 0.25, 0.5, 0.6)",
                                "Nested ComplexPath: three circles, a Bézier and a sine wave"};
        for (int k = 0; k < 2; ++k) {
            const Path& path = examples[k].second;
            Canvas canvas(640, 560);
            canvas.set_transform(fit(path.bounds(), {0, 30, 640, 530}, 30));
            draw_path(canvas, path, {.stroke = {.color = colors::blue, .width = 1.5}, .ticks = 0.02, .tangents = 0});
            canvas.set_transform({});
            canvas.text({20, 22}, titles[k], title);
            canvas.text({20, 548}, "orange: where each part begins (u of the whole); ticks every 0.02 of u", label);
            save(canvas, examples[k].first, k == 0 ? "the seed's complex path" : "the seed's nested complex path",
                 format("length %.1f px", path.length()));
        }
    }

    // 5. A tile-sheet sprite at half speed: the sheet with the current frame, and the frames shown.
    {
        const Image sheet_image = make_tile_sheet_image();
        const TileSheet sheet({.width = 128, .height = 64, .columns = 4, .rows = 2});
        TileSheetSprite sprite(sheet);
        SpritePlayer player(sprite, {.rate = 0.5});
        Canvas canvas(620, 200);
        canvas.text({20, 22}, "TileSheetSprite at rate 0.5: its sheet, and the frame at each step", title);
        for (int step = 0; step < 8; ++step) {
            draw_sprite(canvas, sheet_image, sprite, {300.0 + 38.0 * (step % 8), 60.0}, 1.0, false);
            canvas.text({316.0 + 38.0 * (step % 8), 108.0}, std::to_string(sprite.current_frame()),
                        {.size = 10, .align = TextAlign::centre});
            if (step == 5) draw_tile_sheet(canvas, sheet_image, sprite, {20, 50}, 2.0);
            player.advance();
        }
        canvas.text({300, 140}, "step 5 is highlighted on the sheet", label);
        save(canvas, "sprite.png", "tile-sheet sprite debug drawing", "8 frames, rate 0.5");
    }

#ifdef GRAPE_TOOL_DYNAMICS
    // 6. The parabola: implicit (Witkin) left, parametric (Lagrange) right, RK4 without drift
    //    control, with the constraint residual and the energy over time below.
    {
        const double dt = 1.0 / 60.0;
        const double seconds = 60.0;
        Canvas canvas(1000, 860);
        canvas.text({20, 24}, "The seed's parabola x² + 100y = 0, RK4 at 1/60 s for 60 s: implicit (left) and parametric (right)",
                    title);
        std::vector<double> times[2], residual[2], energy[2];
        std::string figures;
        const scenes::ParabolaMethod methods[] = {scenes::ParabolaMethod::implicit, scenes::ParabolaMethod::parametric};
        for (int m = 0; m < 2; ++m) {
            scenes::ParabolaSetup setup{.method = methods[m], .integrator = Integrator::rk4};
            std::vector<Vec2> trail;
            const auto summary = scenes::run_parabola(setup, dt, seconds, [&](const scenes::ParabolaState& s) {
                times[m].push_back(s.t);
                residual[m].push_back(s.distance);
                energy[m].push_back(s.energy);
                trail.push_back(s.x);
            });
            const Rect panel{10.0 + 495.0 * m, 40, 485, 400};
            Bounds world;
            world.add(Vec2{-130, -169});
            world.add(Vec2{130, 10});
            canvas.push();
            canvas.set_transform(fit(world, panel, 20));
            draw_implicit_curve(canvas, [](Vec2 p) { return p.x * p.x + 100.0 * p.y; }, world,
                                {.color = colors::light_grey, .width = 5}, 200);
            canvas.stroke_polyline(trail, {.color = {0.15, 0.35, 0.85, 0.35}, .width = 1});
            const Vec2 end = summary.final.x;
            draw_particles(canvas, std::span<const Vec2>(&end, 1), {}, {}, {.color = m == 0 ? colors::red : colors::blue, .radius = 6});
            canvas.pop();
            canvas.stroke_rect(panel, {.color = colors::light_grey});
            canvas.text({panel.x + 10, panel.y + 20}, m == 0 ? "implicit: Witkin constraint force" : "parametric: bead on x(q) = (q, −q²/100)",
                        {.size = 12});
            figures += std::string(m ? "; " : "") + (m == 0 ? "implicit" : "parametric") +
                       format(" max distance %.3g px", summary.max_distance) + format(", max |dE/E| %.3g", summary.max_energy_error);
        }
        const StrokeStyle implicit_line{.color = colors::red, .width = 1.5};
        const StrokeStyle parametric_line{.color = colors::blue, .width = 1.5};
        const PlotSeries res[] = {{times[0], residual[0], implicit_line, "implicit"},
                                  {times[1], residual[1], parametric_line, "parametric"}};
        draw_plot(canvas, {10, 450, 980, 200}, res, "distance from the parabola |C|/|∇C| (px) over time (s)");
        const PlotSeries en[] = {{times[0], energy[0], implicit_line, "implicit"},
                                 {times[1], energy[1], parametric_line, "parametric"}};
        draw_plot(canvas, {10, 655, 980, 200}, en, "total energy over time (s)");
        save(canvas, "parabola.png", "the parabola by both methods", figures);
    }
#endif

    std::ostream& out = context.out;
    out << "\nPictures (render module)\n";
    for (const Written& w : written) {
        std::error_code ec;
        const auto size = std::filesystem::file_size(w.file, ec);
        char line[512];
        std::snprintf(line, sizeof line, "  %-34s %8.1f KB  %-32s %s\n", w.file.c_str(), ec ? 0.0 : size / 1024.0,
                      w.what.c_str(), w.figures.c_str());
        out << line;
    }
}

}  // namespace grape::tool
