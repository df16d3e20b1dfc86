// grape — 3-D paths as JSON: the one object that `grape path3` reads and that a scene file's
// 3-D path holds (part of grape::scene; the fields: docs/scene-format.md, "3-D paths").
//
//   grape::Path3 rail = grape::parse_path3_json(
//       R"({"kind": "helix", "center": [0, 0, 0], "axis": [0, 0, 1], "start": [1, 0, 0],
//           "radius": 5, "rise_per_turn": 2, "turns": 3})");
//
// Errors name the JSON pointer of the bad value and the reason, as scene files do
// ("path3: /parts/1/points/2: expected a point [x, y, z], got an array of 2").
#pragma once

#include <grape/export_scene.hpp>
#include <grape/path3.hpp>

#include <string_view>

namespace grape {

/// \addtogroup scene
/// @{

/// A 3-D path from JSON text holding one path object: `line`, `quadratic`, `cubic`, `helix`,
/// `catmull-rom`, `hermite`, `linear` (a linear spline), `arc`, `projectile`, `on_plane` (a 2-D
/// scene path on a plane) or `complex` (parts nest up to 32 deep). Unknown fields, wrong array
/// sizes, numbers that are not finite and degenerate shapes (a zero axis, a start along the
/// axis) are refused: grape::Error "path3: POINTER: WHY", or "path3: JSON syntax error at byte
/// N: ...".
GRAPE_SCENE_API Path3 parse_path3_json(std::string_view json);

/// @}

}  // namespace grape
