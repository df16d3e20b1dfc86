// `grape render`: the sprites of a scene, drawn from their sheets' pictures, and the scene's
// warnings.
#pragma once

#include <grape/math.hpp>
#include <grape/render.hpp>
#include <grape/scene.hpp>

#include <string>

namespace grape::tool {

/// Reads every sprite's sheet picture (once per picture file); throws grape::Error naming the
/// sprite's JSON pointer when one cannot be read or a frame falls outside it.
void load_sprite_pictures(const Scene& scene);

/// Draws every sprite of the scene at time t (world units: the canvas holds the view's
/// transform): the frame its clip shows then, its pivot at its place (a point, or its
/// animation's position). load_sprite_pictures must have run.
void draw_scene_sprites(Canvas& canvas, const Scene& scene, const SceneTiming& timing, double t);

/// Prints each of the scene's warnings on stderr ("grape render: warning: FILE: ..."); with
/// `strict`, throws grape::Error with the first instead (and how many there are).
void report_scene_warnings(const Scene& scene, const std::string& file, bool strict);

/// Where the sprite's pivot is at time t.
Vec2 sprite_position(const Scene& scene, const SceneTiming& timing, const SceneSprite& sprite, double t);

}  // namespace grape::tool
