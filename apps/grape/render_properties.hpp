// `grape render`: a scene's properties as a legend, each with its value at the frame's time.
#pragma once

#include <grape/render.hpp>
#include <grape/scene.hpp>

namespace grape::tool {

/// Lists the scene's properties at the top right (canvas units, no transform): a colour as a
/// swatch, an angle with a dial, numbers and vec2 as text, each with its value at time t.
void draw_scene_properties(Canvas& canvas, const Scene& scene, const SceneTiming& timing, double t);

}  // namespace grape::tool
