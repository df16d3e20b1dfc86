// `grape render`: a scene's sprites. Each sheet picture is read once per run; a sprite shows
// the frame its ClipPlayer reaches at the scene time (SceneSprite::frame_at), drawn by
// draw_sprite_frame with its pivot at the sprite's place.
#include "render_sprites.hpp"

#include <grape/error.hpp>
#include <grape/sprite_sheet_json.hpp>

#include <iostream>
#include <map>
#include <string>

namespace grape::tool {

namespace {

// The pictures read so far, by file (one tool run renders one scene).
std::map<std::filesystem::path, Image>& pictures() {
    static std::map<std::filesystem::path, Image> read;
    return read;
}

std::filesystem::path picture_file(const SceneSprite& s) { return sprite_sheet_image_path(*s.sheet, s.sheet_path); }

}  // namespace

void load_sprite_pictures(const Scene& scene) {
    for (std::size_t i = 0; i < scene.sprites.size(); ++i) {
        const SceneSprite& s = scene.sprites[i];
        const std::string where = "scene: /sprites/" + std::to_string(i) + "/sheet: ";
        if (!s.sheet) throw Error(where + "the sheet " + s.sheet_file + " is not loaded");
        const std::filesystem::path file = picture_file(s);
        auto it = pictures().find(file);
        if (it == pictures().end()) {
            try {
                it = pictures().emplace(file, Image::load_png(file)).first;
            } catch (const Error& e) {
                throw Error(where + "the sheet's picture: " + e.what());
            }
        }
        if (it->second.width() < s.sheet->width() || it->second.height() < s.sheet->height())
            throw Error(where + "the picture " + file.string() + " is " + std::to_string(it->second.width()) + "×" +
                        std::to_string(it->second.height()) + " pixels, smaller than the sheet's " +
                        std::to_string(s.sheet->width()) + "×" + std::to_string(s.sheet->height()));
    }
}

void report_scene_warnings(const Scene& scene, const std::string& file, bool strict) {
    if (scene.warnings.empty()) return;
    if (strict) {
        const std::size_t more = scene.warnings.size() - 1;
        throw Error("render: " + file + ": " + scene.warnings.front() +
                    (more ? " (and " + std::to_string(more) + " more warning" + (more > 1 ? "s" : "") + ")" : std::string()) +
                    " (--strict)");
    }
    for (const std::string& w : scene.warnings) std::cerr << "grape render: warning: " << file << ": " << w << '\n';
}

Vec2 sprite_position(const Scene& scene, const SceneTiming& timing, const SceneSprite& sprite, double t) {
    if (sprite.animation.empty()) return sprite.at;
    for (std::size_t i = 0; i < scene.animations.size(); ++i)
        if (scene.animations[i].name == sprite.animation) return scene.animations[i].position_at(timing.progress(i, t));
    return sprite.at;  // a scene built in code may name none; the loader refuses that
}

void draw_scene_sprites(Canvas& canvas, const Scene& scene, const SceneTiming& timing, double t) {
    for (const SceneSprite& s : scene.sprites) {
        const auto it = pictures().find(picture_file(s));
        if (it == pictures().end()) throw Error("render: the picture of sprite sheet " + s.sheet_file + " was not read");
        draw_sprite_frame(canvas, it->second, s.sheet->frame(s.frame_at(t)), sprite_position(scene, timing, s, t), s.scale);
    }
}

}  // namespace grape::tool
