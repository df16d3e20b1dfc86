// Sprites in scene files: a sheet (Aseprite or TexturePacker JSON, read relative to the scene
// file), the clip or frame range played, its rate and scale, and where it is (a point, or
// the position of a named animation).
#include "scene_json.hpp"

#include <grape/error.hpp>
#include <grape/sprite_sheet_json.hpp>

#include "utf8_path.hpp"

#include <algorithm>

#include <cmath>
#include <string>

namespace grape::scene_io {

namespace {

// The one animation called `name`: names are labels, so a reference must be unambiguous.
void check_animation_name(const Scene& scene, const std::string& name, const std::string& pointer) {
    std::size_t count = 0;
    for (const SceneAnimation& a : scene.animations) count += a.name == name ? 1 : 0;
    if (count == 0) fail(pointer, "no animation is named \"" + name + "\" (name one listed in /animations)");
    if (count > 1) fail(pointer, std::to_string(count) + " animations are named \"" + name + "\": the name must be unique");
}

std::size_t frame_index(const json& j, const std::string& pointer) {
    const long long i = integer(j, pointer);
    if (i < 0) fail(pointer, "a frame index is not negative (got " + std::to_string(i) + ")");
    return static_cast<std::size_t>(i);
}

}  // namespace

void read_sprites(const json& v, Scene& scene) {
    if (!v.is_array()) fail("/sprites", "expected an array, got " + type_of(v));
    for (std::size_t i = 0; i < v.size(); ++i) {
        const std::string p = child("/sprites", i);
        const json& o = object(v[i], p, {"name", "sheet", "clip", "frames", "rate", "scale", "animation", "at"});
        SceneSprite s;
        s.name = name_field(o, p, nullptr);
        s.sheet_file = string_value(required(o, p, "sheet"), child(p, "sheet"));
        if (s.sheet_file.empty()) fail(child(p, "sheet"), "must name a sprite-sheet JSON file");
        const bool has_clip = o.contains("clip"), has_frames = o.contains("frames");
        if (has_clip == has_frames) fail(p, "give either \"clip\" (a clip of the sheet) or \"frames\": [first, last]");
        if (has_clip) {
            s.clip = string_value(o["clip"], child(p, "clip"));
            if (s.clip.empty()) fail(child(p, "clip"), "must name a clip of the sheet");
        } else {
            const json& f = o["frames"];
            const std::string fp = child(p, "frames");
            if (!f.is_array() || f.size() != 2) fail(fp, "expected [first, last] frame indices, got " + type_of(f));
            s.first_frame = frame_index(f[0], child(fp, 0));
            s.last_frame = frame_index(f[1], child(fp, 1));
            if (s.last_frame < s.first_frame)
                fail(child(fp, 1), "the last frame comes before the first (" + std::to_string(s.last_frame) + " < " +
                                       std::to_string(s.first_frame) + ")");
        }
        s.rate = number_field(o, p, "rate", 1.0);
        s.scale = number_field(o, p, "scale", 1.0);
        if (!(s.scale > 0.0)) fail(child(p, "scale"), "must be positive (got " + number_text(s.scale) + ")");
        const bool has_animation = o.contains("animation"), has_at = o.contains("at");
        if (has_animation == has_at) fail(p, "give either \"animation\" (the name of one it moves along) or \"at\": [x, y]");
        if (has_animation) {
            s.animation = string_value(o["animation"], child(p, "animation"));
            check_animation_name(scene, s.animation, child(p, "animation"));
        } else {
            s.at = vec2(o["at"], child(p, "at"));
        }
        scene.sprites.push_back(std::move(s));
    }
}

ordered sprites_json(const Scene& scene) {
    ordered a = ordered::array();
    for (const SceneSprite& s : scene.sprites) {
        ordered o;
        if (!s.name.empty()) o["name"] = s.name;
        o["sheet"] = s.sheet_file;
        if (!s.clip.empty()) o["clip"] = s.clip;
        else o["frames"] = {s.first_frame, s.last_frame};
        o["rate"] = s.rate;
        o["scale"] = s.scale;
        if (!s.animation.empty()) o["animation"] = s.animation;
        else o["at"] = point_json(s.at);
        a.push_back(std::move(o));
    }
    return a;
}

}  // namespace grape::scene_io

namespace grape {

using namespace scene_io;

void load_scene_sprite_sheets(Scene& scene, const std::filesystem::path& folder) {
    for (std::size_t i = 0; i < scene.sprites.size(); ++i) {
        SceneSprite& s = scene.sprites[i];
        const std::string p = child("/sprites", i);
        // UTF-8, with "/" or (as Windows writes them) backslashes between folders, on every system.
        std::string name = s.sheet_file;
        std::replace(name.begin(), name.end(), '\\', '/');
        const std::filesystem::path sheet_file = detail::path_from_utf8(name);
        const std::filesystem::path file = sheet_file.is_absolute() ? sheet_file : folder / sheet_file;
        SpriteSheet sheet = [&] {
            try {
                return load_sprite_sheet_file(file);
            } catch (const Error& e) {
                fail(child(p, "sheet"), e.what());
            }
        }();
        if (!s.clip.empty()) {
            try {
                s.clip_index = sheet.clip_index(s.clip);
            } catch (const Error& e) {
                fail(child(p, "clip"), e.what());
            }
            s.sheet = std::make_shared<const SpriteSheet>(std::move(sheet));
        } else {
            const std::string fp = child(p, "frames");
            if (s.last_frame >= sheet.frame_count())
                fail(child(fp, s.first_frame >= sheet.frame_count() ? 0 : 1),
                     "the sheet has " + std::to_string(sheet.frame_count()) + " frames (0 to " +
                         std::to_string(sheet.frame_count() - 1) + ")");
            // The range becomes a clip of the sheet's own: the same frames, one clip more.
            SpriteSheetDef def{.image = sheet.image(), .width = sheet.width(), .height = sheet.height(), .scale = sheet.scale(),
                               .frames = {sheet.frames().begin(), sheet.frames().end()},
                               .clips = {sheet.clips().begin(), sheet.clips().end()},
                               .slices = {sheet.slices().begin(), sheet.slices().end()}};
            s.clip_index = def.clips.size();
            def.clips.push_back({.name = "", .from = s.first_frame, .to = s.last_frame});
            s.sheet = std::make_shared<const SpriteSheet>(std::move(def));
        }
        if (!std::isfinite(s.rate)) fail(child(p, "rate"), "must be finite");
        s.sheet_path = file;
    }
}

std::size_t SceneSprite::frame_at(double t) const {
    if (!sheet) throw Error("SceneSprite::frame_at: the sheet " + sheet_file + " is not loaded (load_scene_file reads it)");
    if (!(std::isfinite(t) && t >= 0.0)) throw Error("SceneSprite::frame_at: t must be finite and ≥ 0 (got " + detail::number_text(t) + ")");
    ClipPlayer player(*sheet, clip_index, {.rate = rate});
    player.advance(t);
    return player.frame();
}

}  // namespace grape
