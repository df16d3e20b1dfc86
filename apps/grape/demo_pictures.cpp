// The demo's pictures (`grape demo`, render module): every path kind, the seed's splines,
// the arc-length comparison, the complex paths, a tile-sheet sprite, the parabola and a 3-D
// track with its frames, a banked coaster and a camera rail. The scenes come from the catalogue by name (scenes/catalogue.hpp),
// as the tests take them.
#include "commands.hpp"

#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/render.hpp>
#include <grape/sprite.hpp>

#include "catalogue.hpp"
#include "demo_rides3.hpp"
#include "demo_track3.hpp"
#include "scene_draw.hpp"
#include "seed_paths.hpp"
#include "sprite_sheets.hpp"

#ifdef GRAPE_TOOL_DYNAMICS
#include <grape/dynamics.hpp>

#include "seed_dynamics.hpp"
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace grape::tool {

namespace {

struct Written {
    std::string file;        // where it ends up, as printed
    std::uintmax_t bytes;    // its size, read where it was written (the staging folder)
    std::string what;
    std::string figures;
};

// The catalogue's builder of `name` in `category`; a missing entry is a defect of the build.
const scenes::Entry& entry(const char* name) {
    const scenes::Entry* e = scenes::find_entry(name);
    if (!e) throw Error(std::string("demo: the catalogue has no entry ") + name);
    return *e;
}

Path path_named(const char* name) { return entry(name).path(); }

}  // namespace

void demo_pictures(const DemoContext& context) {
    std::vector<Written> written;
    // A file written into context.dir, listed under the folder it ends up in.
    const auto note = [&](const std::string& name, std::string what, std::string figures) {
        std::error_code ec;
        const std::uintmax_t bytes = std::filesystem::file_size(context.dir / name, ec);
        written.push_back({(context.shown / name).string(), ec ? 0 : bytes, std::move(what), std::move(figures)});
    };
    const auto save = [&](const Canvas& canvas, const std::string& name, std::string what, std::string figures = {}) {
        canvas.write(context.dir / name);
        note(name, std::move(what), std::move(figures));
    };
    const TextStyle title{.size = 15, .bold = true};
    const TextStyle label{.color = {0.25, 0.25, 0.25}, .size = 10};

    // 1. Every path kind in one gallery, with u-ticks every 0.05 and the start/end marks.
    {
        Canvas canvas(700, 700);
        canvas.set_transform(Affine::translation({50, 60}));
        const std::string prefix = "gallery_";  // one path of every kind
        std::vector<std::pair<std::string, Path>> gallery;
        for (const scenes::Entry* e : scenes::entries_of(scenes::Category::path))
            if (e->name.rfind(prefix, 0) == 0) gallery.emplace_back(e->name.substr(prefix.size()), e->path());
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
        note("gallery.svg", "the same, as SVG", "");
        note("gallery.pdf", "the same, as PDF", "");
    }

    // 2. The seed's spline image: top to bottom linear, cosine, Catmull-Rom through p1, p2, p3.
    {
        Canvas canvas(560, 560);
        canvas.set_transform(Affine::translation({10, 40}));
        const std::pair<const char*, Path> splines[] = {{"linear", path_named("seed_linear_spline_p1")},
                                                        {"cosine", path_named("seed_cosine_spline_p2")},
                                                        {"Catmull-Rom", path_named("seed_catmull_rom_spline_p3")}};
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
        const Path plain = path_named("seed_bezier");
        const Path even = path_named("seed_bezier_reparametrized");
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
            {"complex.png", path_named("seed_complex")}, {"nested_complex.png", path_named("seed_nested_complex")}};
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
        const scenes::DrawnSheet drawn = entry("grape_tile_sheet").sheet();  // 8 frames on a 4 × 2 grid
        const Image& sheet_image = drawn.image;
        const TileSheet sheet({.width = sheet_image.width(), .height = sheet_image.height(), .columns = 4, .rows = 2});
        TileSheetSprite sprite(sheet);
        SpritePlayer player(sprite, {.rate = 0.5});
        Canvas canvas(620, 200);
        canvas.text({20, 22}, "TileSheetSprite at rate 0.5: its sheet, and the frame at each step", title);
        for (int step = 0; step < 8; ++step) {
            draw_sprite(canvas, sheet_image, sprite, {300.0 + 38.0 * (step % 8), 60.0}, 1.0, false);
            canvas.text({316.0 + 38.0 * (step % 8), 108.0}, std::to_string(sprite.current_frame()),
                        {.size = 10, .align = TextAlign::center});
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

    // 7. A 3-D track in an oblique projection: the rotation-minimizing ribbon keeps its up side
    //    up, the Frenet ribbon turns over at an inflection.
    {
        std::string figures;
        const Canvas canvas = track3_picture(figures);
        save(canvas, "track3d.png", "3-D track: RMF and Frenet ribbons", figures);
    }

    // 8. A coaster with a loop, banked for its speed by bank_track: the rolled ribbon.
    {
        std::string figures;
        const Canvas canvas = coaster_picture(figures);
        save(canvas, "coaster3d.png", "3-D coaster: banked for 12 units/s", figures);
    }

    // 9. A camera on a rail: its frames along the rail, and what it sees from one of them.
    {
        std::string figures;
        const Canvas canvas = camera_rail_picture(figures);
        save(canvas, "camera_rail3d.png", "3-D camera rail and its view", figures);
    }

    std::ostream& out = context.out;
    out << "\nPictures (render module)\n";
    for (const Written& w : written) {
        char line[512];
        std::snprintf(line, sizeof line, "  %-34s %8.1f KB  %-32s %s\n", w.file.c_str(), static_cast<double>(w.bytes) / 1024.0,
                      w.what.c_str(), w.figures.c_str());
        out << line;
    }
}

}  // namespace grape::tool
