// The catalogue's entries, built once from the scene functions of this folder.
#include "catalogue.hpp"

#include "seed_paths.hpp"

#ifdef GRAPE_SCENES_DYNAMICS
#include "seed_dynamics.hpp"

#include <grape/dynamics.hpp>
#endif

#ifdef GRAPE_SCENES_SPRITES
#include "sprite_sheets.hpp"
#endif

#include <algorithm>
#include <utility>

namespace grape::scenes {

namespace {

// "linear_spline_p1" → "linear spline p1".
std::string words(std::string_view name) {
    std::string s(name);
    std::replace(s.begin(), s.end(), '_', ' ');
    return s;
}

Entry path_entry(std::string name, std::string summary, Path path) {
    Entry e{.name = std::move(name), .category = Category::path, .summary = std::move(summary)};
    e.path = [p = std::move(path)] { return p; };  // paths are immutable shared handles
    return e;
}

std::vector<Entry> build() {
    std::vector<Entry> all;
    for (auto& [name, path] : seed_paths()) all.push_back(path_entry("seed_" + name, "the original's " + words(name), path));
    for (auto& [name, path] : path_gallery())
        all.push_back(path_entry("gallery_" + name, "one path of every kind: " + words(name), path));
    all.push_back(path_entry("bench_hundred_segments", "100 SVG segments cycling C, Q, A, L (queries and benchmarks)",
                             parse_svg_path(hundred_segments_svg())));

    all.push_back({.name = "seed_spiral_animation",
                   .category = Category::animation,
                   .summary = "the original's first example: a view along the spiral in 2 s",
                   .animation = [](Engine& engine, Sprite& view) { return seed_spiral_animation(engine, view); }});
    all.push_back({.name = "seed_complex_animation",
                   .category = Category::animation,
                   .summary = "the original's complex path (spiral, three segments) in 4 s",
                   .animation = [](Engine& engine, Sprite& view) { return seed_complex_animation(engine, view); }});

#ifdef GRAPE_SCENES_DYNAMICS
    // SI units: metres, seconds, g = 9.81 m/s² along +y (y down).
    constexpr double g = 9.81;
    auto system = [&all](std::string name, std::string summary, std::function<ParticleSystem()> make) {
        all.push_back({.name = std::move(name), .category = Category::dynamics, .summary = std::move(summary), .system = std::move(make)});
    };
    system("simple_pendulum", "a 1 m pendulum released 30° from the vertical (RATTLE)",
           [] { return simple_pendulum(1.0, pi / 6, g, {.integrator = Integrator::rattle}); });
    system("double_pendulum", "two 1 m rods released horizontal (RK4, Baumgarte)",
           [] { return double_pendulum(1.0, 1.0, g, {}); });
    for (const std::size_t links : {10, 100, 1000})
        system("chain_" + std::to_string(links),
               "a chain of " + std::to_string(links) + " links of 1 m released horizontal (the benchmark's)",
               [links] { return chain(links, 1.0, g); });
    system("cloth_strip", "a 10 × 6 strip of cloth, top row pinned, released sheared",
           [] { return cloth_strip(10, 6, 0.35, g); });
#endif

    for (const char* file : {"seed_spiral.json", "seed_complex.json", "seed_bezier.json", "seed_splines.json",
                             "seed_nested_complex.json", "seed_parabola.json", "pendulum_chain.json",
                             "timeline_cutscene.json", "sprite_track.json", "typed_values.json", "camera_rail3d.json",
                             "coaster_banked.json", "glider_keys.json"})
        all.push_back({.name = file, .category = Category::scene_file, .summary = "scene file scenes/" + std::string(file),
                       .file = file});

#ifdef GRAPE_SCENES_SPRITES
    all.push_back({.name = "grape_tile_sheet",
                   .category = Category::sprite_sheet,
                   .summary = "the grape sprite: 8 frames of 32 px on a 4 × 2 tile sheet (the demo's TileSheetSprite)",
                   .sheet = [] { return grape_tile_sheet(8, 4, 32); }});
#ifdef GRAPE_SCENES_SHEET_JSON
    all.push_back({.name = "grape_packed_sheet",
                   .category = Category::sprite_sheet,
                   .summary = "the grape sprite trimmed and packed as Aseprite exports it, with clips and slices (tests/data/sprites)",
                   .sheet = [] { return grape_packed_sheet(); }});
#endif
#endif
    return all;
}

}  // namespace

std::string_view to_string(Category category) noexcept {
    switch (category) {
        case Category::path: return "path";
        case Category::animation: return "animation";
        case Category::dynamics: return "dynamics";
        case Category::scene_file: return "scene_file";
        case Category::sprite_sheet: return "sprite_sheet";
    }
    return "?";
}

std::span<const Entry> catalogue() {
    static const std::vector<Entry> all = build();
    return all;
}

const Entry* find_entry(std::string_view name) {
    for (const Entry& e : catalogue())
        if (e.name == name) return &e;
    return nullptr;
}

std::vector<const Entry*> entries_of(Category category) {
    std::vector<const Entry*> out;
    for (const Entry& e : catalogue())
        if (e.category == category) out.push_back(&e);
    return out;
}

}  // namespace grape::scenes
