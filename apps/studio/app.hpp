// The window: SDL2 + Dear ImGui over SDL_Renderer, the fixed-step frame loop, scripted
// input and screenshots.
#pragma once

#include "studio.hpp"

namespace grape::studio {

/// Opens the window and runs the frame loop until it is closed or `options.frames` have run.
/// Returns the process exit status; throws grape::Error for bad options or files.
int run(const Options& options);

/// The names `--tab` accepts, in tab-bar order.
std::vector<std::string> tab_names();

}  // namespace grape::studio
