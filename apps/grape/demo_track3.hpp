// The demo's 3-D picture (demo_track3.cpp): a track drawn in an oblique projection with its
// rotation-minimizing and Frenet ribbons.
#pragma once

#include <grape/render.hpp>

#include <string>

namespace grape::tool {

/// The picture, and its figures for the demo's list (length, frame knots, where Frenet flips).
Canvas track3_picture(std::string& figures);

}  // namespace grape::tool
