// grape — the catalogue: every named scene (the original's paths, animations and physics, one
// path of every kind, the benchmark set-ups, the scene files, the sprite sheets) with its category and how to
// build it. The tests build and step every entry, `grape list` prints them, the studio lists
// them, `grape demo` draws them, and the benchmarks take theirs by name; scenes/*.json are the file form of the
// original's scenes, checked against the entries they share.
#pragma once

#include "seed_animations.hpp"

#include <grape/anim.hpp>
#include <grape/path.hpp>

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grape {
class ParticleSystem;
namespace scenes {
struct DrawnSheet;
}
}

namespace grape::scenes {

/// What an entry builds.
enum class Category {
    path,        ///< a Path (the original's paths, the gallery of kinds, the benchmark paths)
    animation,   ///< an animation of a Sprite in an Engine
    dynamics,    ///< a ParticleSystem (with grape::dynamics)
    scene_file,  ///< a scene file in scenes/ (with grape::scene)
    sprite_sheet,  ///< a drawn sprite sheet (with grape::render; see sprite_sheets.hpp)
};

/// "path", "animation", "dynamics", "scene_file", "sprite_sheet".
std::string_view to_string(Category category) noexcept;

/// One entry. The builder of its category is set; the others are empty.
struct Entry {
    std::string name{};    ///< unique, snake_case ("seed_bezier", "gallery_circle", "chain_100")
    Category category = Category::path;
    std::string summary{}; ///< one line, for lists
    std::function<Path()> path{};                          ///< Category::path
    std::function<Animation(Engine&, Sprite&)> animation{};  ///< Category::animation
    std::function<ParticleSystem()> system{};              ///< Category::dynamics
    std::string file{};    ///< Category::scene_file: its name in scenes/ ("seed_bezier.json")
    std::function<DrawnSheet()> sheet{};                   ///< Category::sprite_sheet
};

/// Every entry, grouped by category, in a fixed order (built once, on first use).
std::span<const Entry> catalogue();

/// The entry named `name`, or null.
const Entry* find_entry(std::string_view name);

/// The entries of one category, in catalogue order.
std::vector<const Entry*> entries_of(Category category);

}  // namespace grape::scenes
