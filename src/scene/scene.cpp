// Scene files: JSON ↔ grape objects. Every read goes through a helper that knows the JSON
// pointer of the value, so each error names where it is and why.
#include <grape/scene.hpp>

#include <grape/error.hpp>
#include <grape/path_query.hpp>
#include <grape/scene_values.hpp>

#include "atomic_file.hpp"

#include "file_text.hpp"
#include "json_pointer.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <system_error>

#include "scene_json.hpp"

namespace grape {

namespace {

using namespace scene_io;

// An animation's "range": [u0, u1] (the part of the path a play covers) and "offset".
void read_range_and_offset(const json& o, const std::string& p, SceneAnimation& a) {
    if (const auto r = o.find("range"); r != o.end()) {
        const std::string rp = child(p, "range");
        if (!r->is_array() || r->size() != 2) fail(rp, "expected [u0, u1] with both in [0, 1], got " + type_of(*r));
        for (std::size_t k = 0; k < 2; ++k) {
            const double u = number((*r)[k], child(rp, k));
            if (!(u >= 0.0 && u <= 1.0)) fail(child(rp, k), "must be in [0, 1] (got " + number_text(u) + ")");
            (k == 0 ? a.range_start : a.range_end) = u;
        }
    }
    a.offset = number_field(o, p, "offset", 0.0);
}

Scene read_scene(const json& root) {
    object(root, "", {"grape_scene", "name", "view", "paths", "curves", "animations", "simulations", "timelines", "sprites",
                  "properties", "tweens", "paths3", "animations3"});
    if (const auto v = root.find("grape_scene"); v != root.end()) {
        if (integer(*v, "/grape_scene") != 1) fail("/grape_scene", "unsupported format version (this reader knows 1)");
    }
    Scene scene;
    scene.name = string_field(root, "", "name", "");
    if (const auto v = root.find("view"); v != root.end()) {
        object(*v, "/view", {"width", "height", "ticks"});
        const auto size = [&](std::string_view key, double fallback) {
            const double s = number_field(*v, "/view", key, fallback);
            if (!(s >= 1.0 && s <= 32768.0)) fail(child("/view", key), "must be in [1, 32768] (got " + number_text(s) + ")");
            return s;
        };
        scene.view.width = size("width", scene.view.width);
        scene.view.height = size("height", scene.view.height);
        scene.view.ticks = non_negative_field(*v, "/view", "ticks", 0.0);
        if (scene.view.ticks > 0.0 && scene.view.ticks < 1e-4)
            fail("/view/ticks", "ticks closer than 1e-4 would be a solid smear (got " + number_text(scene.view.ticks) + ")");
    }
    std::set<std::string> names;
    if (const auto v = root.find("paths"); v != root.end()) {
        if (!v->is_array()) fail("/paths", "expected an array, got " + type_of(*v));
        PathReader reader{&scene.paths, &scene.warnings};  // a path may use those listed before it
        for (std::size_t i = 0; i < v->size(); ++i) {
            const std::string p = child("/paths", i);
            const json& o = (*v)[i];
            if (!o.is_object()) fail(p, "expected an object with \"name\" and \"path\", got " + type_of(o));
            object(o, p, {"name", "path"});
            NamedPath named;
            named.name = name_field(o, p, &names);
            named.path = reader.read(required(o, p, "path"), child(p, "path"), 0);
            scene.paths.push_back(std::move(named));
        }
    }
    std::set<std::string> curve_names;
    if (const auto v = root.find("curves"); v != root.end()) {
        if (!v->is_array()) fail("/curves", "expected an array, got " + type_of(*v));
        for (std::size_t i = 0; i < v->size(); ++i) {
            const std::string p = child("/curves", i);
            const json& o = object((*v)[i], p, {"name", "curve"});
            NamedCurve named;
            named.name = name_field(o, p, &curve_names);
            const std::string text = string_value(required(o, p, "curve"), child(p, "curve"));
            try {
                named.curve = parse_curve(text);
            } catch (const Error& e) {
                fail(child(p, "curve"), e.what());
            }
            scene.curves.push_back(std::move(named));
        }
    }
    if (const auto v = root.find("animations"); v != root.end()) {
        if (!v->is_array()) fail("/animations", "expected an array, got " + type_of(*v));
        PathReader reader{&scene.paths, &scene.warnings};
        for (std::size_t i = 0; i < v->size(); ++i) {
            const std::string p = child("/animations", i);
            const json& o = object((*v)[i], p, {"name", "path", "curve", "duration", "delay", "repeat", "yoyo", "reversed",
                                                       "repeat_delay", "range", "offset"});
            SceneAnimation a;
            a.name = name_field(o, p, nullptr);
            const json& path = required(o, p, "path");
            if (path.is_string()) a.path_name = path.get<std::string>();
            a.path = reader.read(path, child(p, "path"), 0);
            curve_field(o, p, scene, a.curve, a.curve_name);
            a.duration = positive_field(o, p, "duration");
            a.delay = non_negative_field(o, p, "delay", 0.0);
            a.repeat = repeat_field(o, p, a.repeat);
            a.yoyo = bool_field(o, p, "yoyo", false);
            a.reversed = bool_field(o, p, "reversed", false);
            a.repeat_delay = non_negative_field(o, p, "repeat_delay", 0.0);
            read_range_and_offset(o, p, a);
            scene.animations.push_back(std::move(a));
        }
    }
    if (const auto v = root.find("paths3"); v != root.end()) read_paths3(*v, scene);
    if (const auto v = root.find("animations3"); v != root.end()) read_animations3(*v, scene);
    if (const auto v = root.find("properties"); v != root.end()) read_properties(*v, scene);
    if (const auto v = root.find("tweens"); v != root.end()) read_tweens(*v, scene);
    if (const auto v = root.find("simulations"); v != root.end()) {
        if (!v->is_array()) fail("/simulations", "expected an array, got " + type_of(*v));
        for (std::size_t i = 0; i < v->size(); ++i) scene.simulations.push_back(read_simulation((*v)[i], child("/simulations", i)));
    }
    if (const auto v = root.find("timelines"); v != root.end()) {
        scene.timelines = read_timelines(*v, "/timelines");
        (void)SceneTiming(scene);  // names, cycles and positions resolve, or the error names where
    }
    if (!scene.tweens.empty()) (void)SceneProperties(scene, SceneTiming(scene));  // starts resolve
    if (const auto v = root.find("sprites"); v != root.end()) read_sprites(*v, scene);
    return scene;
}

ordered scene_json(const Scene& scene) {
    ordered j;
    j["grape_scene"] = 1;
    if (!scene.name.empty()) j["name"] = scene.name;
    j["view"] = {{"width", scene.view.width}, {"height", scene.view.height}, {"ticks", scene.view.ticks}};
    if (!scene.paths.empty()) {
        ordered a = ordered::array();
        for (const NamedPath& p : scene.paths) a.push_back({{"name", p.name}, {"path", path_json(p.path)}});
        j["paths"] = std::move(a);
    }
    if (!scene.curves.empty()) {
        ordered a = ordered::array();
        for (std::size_t i = 0; i < scene.curves.size(); ++i)
            a.push_back({{"name", scene.curves[i].name},
                         {"curve", saved_curve(scene.curves[i].curve, child(child("/curves", i), "curve"))}});
        j["curves"] = std::move(a);
    }
    if (!scene.animations.empty()) {
        ordered a = ordered::array();
        for (std::size_t i = 0; i < scene.animations.size(); ++i) {
            const SceneAnimation& anim = scene.animations[i];
            ordered o;
            if (!anim.name.empty()) o["name"] = anim.name;
            // A reference is kept only while it still names this very path.
            const NamedPath* named = anim.path_name.empty() ? nullptr : scene.find_path(anim.path_name);
            if (named && named->path == anim.path) o["path"] = anim.path_name;
            else o["path"] = path_json(anim.path);
            const NamedCurve* curve = anim.curve_name.empty() ? nullptr : scene.find_curve(anim.curve_name);
            o["curve"] = curve && curve->curve == anim.curve ? anim.curve_name
                                                                  : saved_curve(anim.curve, child(child("/animations", i), "curve"));
            o["duration"] = anim.duration;
            o["delay"] = anim.delay;
            o["repeat"] = anim.repeat;
            o["yoyo"] = anim.yoyo;
            o["reversed"] = anim.reversed;
            if (anim.repeat_delay != 0.0) o["repeat_delay"] = anim.repeat_delay;
            if (anim.range_start != 0.0 || anim.range_end != 1.0) o["range"] = {anim.range_start, anim.range_end};
            if (anim.offset != 0.0) o["offset"] = anim.offset;
            a.push_back(std::move(o));
        }
        j["animations"] = std::move(a);
    }
    if (!scene.paths3.empty()) j["paths3"] = paths3_json(scene);
    if (!scene.animations3.empty()) j["animations3"] = animations3_json(scene);
    if (!scene.properties.empty()) j["properties"] = properties_json(scene);
    if (!scene.tweens.empty()) j["tweens"] = tweens_json(scene);
    if (!scene.simulations.empty()) {
        ordered a = ordered::array();
        for (const SceneSimulation& s : scene.simulations) a.push_back(simulation_json(s));
        j["simulations"] = std::move(a);
    }
    if (!scene.timelines.empty()) j["timelines"] = timelines_json(scene.timelines);
    if (!scene.sprites.empty()) j["sprites"] = sprites_json(scene);
    return j;
}

}  // namespace

// --------------------------------------------------------------------------------- public

AnimationDef SceneAnimation::def() const noexcept {
    AnimationDef d{.curve = curve, .delay = delay, .repeat = repeat, .reversed = reversed, .yoyo = yoyo};
    d.repeat_delay = repeat_delay;
    d.range_start = range_start;
    d.range_end = range_end;
    d.offset = offset;
    return d;
}

double SceneAnimation::progress(double t) const noexcept {
    if (!(duration > 0.0)) return curve(reversed ? 1.0 : 0.0);  // not playable: its start
    return progress_at(def(), duration, t);
}

double SceneAnimation::u(double t) const noexcept { return range_start + progress(t) * (range_end - range_start); }

Vec2 SceneAnimation::position(double t) const noexcept { return position_at(progress(t)); }

Vec2 SceneAnimation::position_at(double p) const noexcept {
    const double at = range_start + p * (range_end - range_start);
    return offset == 0.0 ? path.point(at) : offset_point(path, at, offset);
}

double SceneAnimation::end_time() const noexcept { return grape::end_time(def(), duration); }

const NamedPath* Scene::find_path(std::string_view name) const noexcept {
    for (const NamedPath& p : paths)
        if (p.name == name) return &p;
    return nullptr;
}

const NamedPath3* Scene::find_path3(std::string_view name) const noexcept {
    for (const NamedPath3& p : paths3)
        if (p.name == name) return &p;
    return nullptr;
}

const NamedCurve* Scene::find_curve(std::string_view name) const noexcept {
    for (const NamedCurve& c : curves)
        if (c.name == name) return &c;
    return nullptr;
}

Scene load_scene(std::string_view text) { return read_scene(parse_text(text, "scene: ")); }

Scene load_scene_file(const std::filesystem::path& file) {
    const std::string text = detail::read_file_text(file, "a scene file");
    try {
        Scene scene = load_scene(text);
        load_scene_sprite_sheets(scene, file.parent_path());
        return scene;
    } catch (const Error& e) {
        throw Error(detail::utf8_string(file) + ": " + e.what());
    }
}

std::string save_scene(const Scene& scene) { return scene_json(scene).dump(2) + "\n"; }

void save_scene_file(const Scene& scene, const std::filesystem::path& file) {
    detail::write_file_atomically(file, save_scene(scene));
}

double conic_value(const SceneConstraint& c, Vec2 p) noexcept {
    return c.conic[0] * p.x * p.x + c.conic[1] * p.x * p.y + c.conic[2] * p.y * p.y + c.conic[3] * p.x +
           c.conic[4] * p.y + c.conic[5];
}


}  // namespace grape
