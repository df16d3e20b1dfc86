// grape — sprite sheets from the JSON that Aseprite and TexturePacker export (part of
// grape::scene; supported fields: docs/sprite-sheets.md).
//
//   grape::SpriteSheet sheet = grape::load_sprite_sheet_file("hero.json");
//   grape::Image picture = grape::Image::load_png(grape::sprite_sheet_image_path(sheet, "hero.json"));
//   grape::ClipPlayer player(sheet, "walk");
//
// Errors name the JSON pointer of the bad value and the reason, as scene files do
// ("sprite sheet: /meta/frameTags/2/to: 12 is past the last frame (frame count 8)").
#pragma once

#include <grape/export_scene.hpp>
#include <grape/sprite.hpp>

#include <filesystem>
#include <string>
#include <string_view>

namespace grape {

/// \addtogroup scene
/// @{

/// How a sheet's JSON lists its frames: Aseprite's `--format json-hash` / `json-array`,
/// TexturePacker's "JSON (Hash)" / "JSON (Array)".
enum class SheetJsonLayout { hash, array };

/// Parses sprite-sheet JSON as Aseprite or TexturePacker write it (either layout, frames in
/// the file's order). Throws grape::Error naming the JSON pointer and the reason, or the byte
/// offset of a syntax error.
GRAPE_SCENE_API SpriteSheet load_sprite_sheet(std::string_view json);
/// Reads and parses a sprite-sheet JSON file; errors also name the file.
GRAPE_SCENE_API SpriteSheet load_sprite_sheet_file(const std::filesystem::path& file);
/// The sheet picture of a sheet read from `json_file`: its image() taken relative to the
/// file's folder, as both tools write it.
GRAPE_SCENE_API std::filesystem::path sprite_sheet_image_path(const SpriteSheet& sheet,
                                                              const std::filesystem::path& json_file);
/// The sheet as Aseprite JSON in either layout: frames with durations, tags, slices with
/// pivots (a frame's own pivot is kept only through slices), the scale. The hash layout keys
/// frames by name, so names must then be unique and not empty (grape::Error otherwise). On a
/// sheet of several sprites (docs/sprite-sheets.md) a clip whose name starts with a sprite's
/// title is written counting that sprite's frames, and must lie within them (grape::Error).
GRAPE_SCENE_API std::string save_sprite_sheet(const SpriteSheet& sheet, SheetJsonLayout layout);

/// @}

}  // namespace grape
