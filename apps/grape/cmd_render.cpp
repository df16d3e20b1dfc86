// `grape render`: a scene file to a picture, a run of frames or one animated SVG, within
// budgets of memory, disk and drawing work (--force lifts them).
#include "commands.hpp"

#include <grape/error.hpp>
#include <grape/render.hpp>
#include <grape/scene.hpp>

#include "atomic_file.hpp"
#include "progress.hpp"
#include "scene_draw.hpp"
#include "scene_draw3.hpp"
#include "scene_player.hpp"
#include "render_sprites.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

namespace grape::tool {

namespace {

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

// The work `grape render` takes on without --force (stated in --help and docs/guide/limits-and-errors.md).
constexpr double memory_budget = 1024.0 * 1024.0 * 1024.0;  // bytes of raster per picture
constexpr int max_frames = 100000;
constexpr double max_drawn_length = 1e6;  // output units of path drawn per picture (~1000 view perimeters)
// Force evaluations × (particles + constraints) of the scene's simulations, counted at their
// most (simulation_work): about 10 s here at ~0.2 µs each.
constexpr double max_simulation_work = 5e7;

struct RenderOptions {
    std::string scene;
    std::string out;
    double time = 0.0;
    int frames = 0;  // 0: one picture (--frames not given)
    bool frames_given = false;
    double fps = 30.0;
    bool force = false;
    bool strict = false;  // the scene's warnings are errors
    double simulation_budget = max_simulation_work;
    std::string view;  // --view SPEC ("": oblique, for a scene with 3-D content)
    bool view_given = false;
};


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

// Refuses (unless forced) a scene whose simulations would take more than the work budget or
// whose recorded trails would take more than the memory budget, naming the heaviest.
void check_simulation_work(const Scene& scene, double t_end, bool force, double budget) {
    if (force) return;
    double total = 0.0, trails = 0.0;
    std::size_t heaviest = 0;
    SimulationWork worst;
    for (std::size_t i = 0; i < scene.simulations.size(); ++i) {
        const SimulationWork w = simulation_work(scene, i, t_end);
        total += w.work;
        trails += w.trail_bytes;
        if (w.work > worst.work) worst = w, heaviest = i;
    }
    if (total <= budget && trails <= memory_budget) return;
    const SceneSimulation& s = scene.simulations[heaviest];
    const std::string name = (s.name.empty() ? std::string("simulation") : "simulation '" + s.name + "'") +
                             " (/simulations/" + std::to_string(heaviest) + ")";
    if (total > budget)
        throw Error("render: the scene's simulations need up to " + format("%.3g", total) +
                    " force evaluations × particles and constraints, more than the budget of " +
                    format("%.3g", budget) + "; the heaviest, " + name + ", takes " + format("%.3g", worst.steps) +
                    " steps of " + s.integrator + " with up to " + format("%.0f", worst.evaluations_per_step) +
                    " evaluations each for " + format("%.0f", worst.size) +
                    " particles and constraints (use a larger dt, a shorter duration, or --force to render it anyway)");
    throw Error("render: recording the scene's simulations for the picture's bounds needs about " + mebibytes(trails) +
                ", more than the budget of " + mebibytes(memory_budget) + "; the heaviest is " + name +
                " (use a larger dt, a shorter duration, or --force to render it anyway)");
}

void run_render(const RenderOptions& o) {
    const std::filesystem::path out = o.out;
    const std::string ext = lower_extension(out);
    if (ext != ".png" && ext != ".svg" && ext != ".pdf")
        throw Error("render: -o " + o.out + ": the output must end in .png, .svg or .pdf");
    if (!std::isfinite(o.time) || o.time < 0.0) throw Error("render: --time must be finite and ≥ 0 (got " + format("%g", o.time) + ")");
    if (o.frames_given && (o.frames < 1 || o.frames > max_frames))
        throw Error("render: --frames must be in [1, 100000] (got " + std::to_string(o.frames) + ")");
    if (!(o.simulation_budget > 0.0) || !std::isfinite(o.simulation_budget))
        throw Error("render: --simulation-budget must be finite and > 0 (got " + format("%g", o.simulation_budget) + ")");
    if (!std::isfinite(o.fps) || o.fps <= 0.0 || o.fps > 10000.0) throw Error("render: --fps must be in (0, 10000] (got " + format("%g", o.fps) + ")");
    const auto parent = out.parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent))
        throw Error("cannot write " + o.out + ": folder " + parent.string() + " does not exist");
    std::error_code ec;
    if (std::filesystem::is_directory(out, ec)) throw Error("cannot write " + o.out + ": it is a folder");
    current_activity() = "reading " + o.scene;
    const ViewSpec view_spec = o.view_given ? parse_view_spec(o.view) : ViewSpec{};
    const Scene scene = load_scene_file(o.scene);
    if (o.view_given && !has_3d_content(scene))
        throw Error("render: --view: " + o.scene + " has no 3-D paths or animations (paths3, animations3) to project");
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
    check_simulation_work(scene, t_end, o.force, o.simulation_budget);
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
    // The 3-D paths count at the most their projection can stretch them on the picture.
    std::unique_ptr<Scene3Picture> picture3;
    if (has_3d_content(scene)) {
        picture3 = std::make_unique<Scene3Picture>(scene, view_spec, scene.view.width, scene.view.height);
        drawn += picture3->drawn_length_bound(longest, longest_name);
    }
    if (drawn > max_drawn_length && !o.force)
        throw Error("render: the scene's paths are " + format("%.3g", drawn) + " units long on the picture (" + longest_name +
                    ": " + format("%.3g", longest) + "), more than the budget of " + format("%.0g", max_drawn_length) +
                    " units a picture (use --force to render them anyway)");

    if (picture3) {
        current_activity() = "projecting the 3-D paths of " + o.scene;
        picture3->prepare();
    }

    if (o.frames_given && ext == ".svg") {
        current_activity() = "building the animated SVG " + o.out;
        detail::write_file_atomically(out, scene_animated_svg(scene, world, o.time, frames, o.fps, picture3.get()));
        std::cout << "wrote " << out.string() << " (" << frames << " frames at " << o.fps << " fps, animated SVG)\n";
        return;
    }
    ScenePlayer player(scene);
    // All frames or none: a half-written sequence is worse than a clear error, so a failure
    // or an interruption (SIGINT, SIGTERM) removes every frame this run wrote.
    detail::RunFiles written;
    Progress progress("render: frame", frames, 1);
    for (int f = 0; f < frames; ++f) {
        const double t = o.time + f / o.fps;
        player.advance_to(t);
        const auto file = o.frames_given ? frame_file(out, f + 1) : out;
        current_activity() = "drawing " + file.string() + " (" + format("%.0f", scene.view.width) + "×" +
                             format("%.0f", scene.view.height) + ")";
        Canvas canvas(scene.view.width, scene.view.height);
        draw_scene(canvas, scene, world, player);
        if (picture3) picture3->draw(canvas, player.timing(), t);
        // A single picture replaces its file only when complete (an old one survives a failure).
        // A frame is registered once written: one that fails leaves what was at its name (an
        // interruption while it is written removes its temporary, never the file it would replace).
        {
            // Committed and registered with no interruption between the two (see there).
            const detail::InterruptsDeferred uncut;
            canvas.write(file);
            if (o.frames_given) written.add(file);
        }
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
                  "longer than 1e6 output units on the picture or the simulations need more than 5e7 force "
                  "evaluations × particles and constraints (rk45 counted at its cap of 100 sub-steps a step)");
    cmd->add_option("--simulation-budget", options->simulation_budget,
                    "Force evaluations × (particles + constraints) the scene's simulations may take, counted before "
                    "they run (default 5e7, about 10 s; --force lifts the budget)");
    cmd->add_option_function<std::string>(
        "--view", [options](const std::string& v) { options->view = v, options->view_given = true; },
        "How the scene's 3-D paths and animations are projected: oblique[:ANGLE_DEG,RECEDE] (the y axis receding "
        "at ANGLE_DEG above the horizontal, scaled by RECEDE in (0, 1]; default oblique:40,0.8, also used without "
        "--view) or perspective[:AZIMUTH_DEG,ELEVATION_DEG[,FOV_DEG]] (a camera orbiting the 3-D content's centre "
        "at a distance that fits it; default perspective:-60,30,45; elevation in [-89, 89], field of view in "
        "[5, 120]). 2-D content is drawn as without it");
    cmd->add_flag("--strict", options->strict,
                  "Refuse a scene that loads with warnings (SVG path data with a syntax error, read by SVG's error "
                  "rule) instead of printing them on stderr and rendering");
    cmd->callback([options] { run_render(*options); });
}


}  // namespace grape::tool
