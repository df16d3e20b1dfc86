// Scene files' JSON, read and written: the helpers that know each value's JSON pointer (so
// every error names where it is and why), paths, simulations. Internal to the scene module.
#pragma once

#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/path3.hpp>
#include <grape/scene.hpp>

#include "json_pointer.hpp"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grape::scene_io {

using json = nlohmann::json;
using ordered = nlohmann::ordered_json;

// Nested complex paths deeper than this are refused: no real scene needs it, and it bounds
// the recursion on hostile input.
inline constexpr int max_depth = 32;
// More simulation steps than this is a typo (or an attack), not a scene.
inline constexpr double max_steps = 1e7;
// Constraints on one particle (scene_simulation.cpp says why).
inline constexpr std::size_t max_constraints_per_particle = 16;

/// Throws grape::Error "scene: POINTER: WHY".
[[noreturn]] void fail(const std::string& pointer, const std::string& why);

using detail::child;
using detail::number_text;
using detail::type_of;

// An object whose keys must all be among `allowed` (a typo such as "duraton" is an error,
// not a silently ignored field).
const json& object(const json& j, const std::string& pointer, std::initializer_list<std::string_view> allowed);
const json& required(const json& obj, const std::string& pointer, std::string_view key);
double number(const json& j, const std::string& pointer);
double number_field(const json& obj, const std::string& pointer, std::string_view key);
double number_field(const json& obj, const std::string& pointer, std::string_view key, double fallback);
double positive_field(const json& obj, const std::string& pointer, std::string_view key);
double non_negative_field(const json& obj, const std::string& pointer, std::string_view key, double fallback);
bool bool_field(const json& obj, const std::string& pointer, std::string_view key, bool fallback);
std::string string_value(const json& j, const std::string& pointer);
std::string string_field(const json& obj, const std::string& pointer, std::string_view key, std::string fallback);
long long integer(const json& j, const std::string& pointer);
Vec2 vec2(const json& j, const std::string& pointer);
Vec2 vec2_field(const json& obj, const std::string& pointer, std::string_view key);
Vec2 vec2_field(const json& obj, const std::string& pointer, std::string_view key, Vec2 fallback);
const json& array_field(const json& obj, const std::string& pointer, std::string_view key);
std::vector<Vec2> points_field(const json& obj, const std::string& pointer, std::string_view key, std::size_t at_least);
std::string name_field(const json& obj, const std::string& pointer, std::set<std::string>* unique);
std::string one_of(const json& obj, const std::string& pointer, std::string_view key, std::string fallback,
                   const std::vector<std::string_view>& allowed);
/// The "repeat" count of `obj`: −1 (forever) or a count in [0, 1e9]; `fallback` when absent.
int repeat_field(const json& obj, const std::string& pointer, int fallback);
/// The "curve" of `obj` (a name in the scene's /curves or curve text) into `curve` and, when it
/// is a name, `curve_name`; both untouched when absent.
void curve_field(const json& obj, const std::string& pointer, const Scene& scene, Curve& curve, std::string& curve_name);
std::size_t particle_index(const json& obj, const std::string& pointer, std::string_view key, std::size_t count);
/// The JSON of `text`; syntax errors name the byte, prefixed by `where`.
json parse_text(std::string_view text, const std::string& where);

/// Reads a path object (or, with `named`, a path name) at `pointer`.
struct PathReader {
    const std::vector<NamedPath>* named = nullptr;  // references allowed when set
    // When set, SVG data is read by SVG's error rule (the path before the command holding
    // the first error) and the error is noted here; otherwise it is an error of the scene.
    std::vector<std::string>* warnings = nullptr;

    Path read(const json& j, const std::string& pointer, int depth) const;
    Path read_any(const json& j, const std::string& pointer, int depth) const;  // read() without the depth 0 check
    Path read_kind(const json& j, const std::string& pointer, const std::string& kind, int depth) const;
};

/// A 3-D point [x, y, z] at `pointer`, every component finite.
Vec3 vec3(const json& j, const std::string& pointer);
/// A 3-D path object at `pointer` (scene_path3.cpp; docs/scene-format.md, "3-D paths"), inside
/// `depth` complex paths.
Path3 read_path3(const json& j, const std::string& pointer, int depth);

/// The scene's "paths3" and "animations3" (after its curves and its "paths3").
void read_paths3(const json& j, Scene& scene);
void read_animations3(const json& j, Scene& scene);
ordered paths3_json(const Scene& scene);
ordered animations3_json(const Scene& scene);
/// A 3-D path as the JSON object read_path3 reads back to the same path; a reparametrized path
/// or a slice has none (grape::Error at `pointer`).
ordered path3_json(const Path3& path, const std::string& pointer);

ordered point_json(Vec2 p);
ordered points_json(std::span<const Vec2> points);
/// A path as the JSON object PathReader reads back to the same path.
ordered path_json(const Path& path);

SceneSimulation read_simulation(const json& j, const std::string& pointer);
ordered simulation_json(const SceneSimulation& s);

/// The "timelines" array (names, fields and positions; references resolve in SceneTiming).
std::vector<SceneTimeline> read_timelines(const json& j, const std::string& pointer);
ordered timelines_json(const std::vector<SceneTimeline>& timelines);
/// The scene's "sprites" (after its animations, which they may name).
void read_sprites(const json& j, Scene& scene);
ordered sprites_json(const Scene& scene);

/// The scene's "properties" (after its curves) and "tweens" (after its properties).
void read_properties(const json& j, Scene& scene);
void read_tweens(const json& j, Scene& scene);
ordered properties_json(const Scene& scene);
ordered tweens_json(const Scene& scene);
/// A value of a property of `type` at `pointer`, and its JSON.
SceneValue read_value(const json& j, const std::string& pointer, ScenePropertyType type);
ordered value_json(const SceneValue& v);
/// The text a curve is saved as; a function curve has none (grape::Error at `pointer`).
std::string saved_curve(const Curve& curve, const std::string& pointer);

}  // namespace grape::scene_io
