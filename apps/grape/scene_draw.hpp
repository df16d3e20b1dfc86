// Pictures of a scene for `grape render`: the world box every frame shares, one frame at the
// player's time (paths, animation markers, simulations, a strip per timeline), and the
// animated SVG of a run of frames.
#pragma once

#include <grape/render.hpp>
#include <grape/scene.hpp>

#include "scene_player.hpp"

#include <cstddef>
#include <string>

namespace grape::tool {

class Scene3Picture;

/// Colour i of the palette the scene's paths and animations cycle through.
Color palette_color(std::size_t i);

/// printf-style text of one number ("%.3f").
std::string format(const char* fmt, double v);

/// The world box the picture shows: every path, and every particle over the whole run up to
/// t_end (at most 20000 steps per simulation), so every frame shares one view.
Bounds scene_bounds(const Scene& scene, double t_end);

/// Draws the scene as `player` stands now: paths (with the view's ticks), animation markers,
/// simulations, each timeline as a strip of its children with a playhead, title and time.
void draw_scene(Canvas& canvas, const Scene& scene, const Bounds& world, const ScenePlayer& player);

/// The animated SVG of `frames` frames from scene time t0 at `fps`: the paths once, every
/// animation and particle as a marker stepping through its positions; with PICTURE3 (prepared)
/// the 3-D paths as their projected polylines and the 3-D followers as markers too.
std::string scene_animated_svg(const Scene& scene, const Bounds& world, double t0, int frames, double fps,
                               const Scene3Picture* picture3 = nullptr);

}  // namespace grape::tool
