// The chain in Box2D v3 (not a Debian package), built only when -DGRAPE_BOX2D3_DIR=<Box2D v3
// source tree> is given, in its own translation unit: its <box2d/box2d.h> and Box2D 2.4's
// (libbox2d-dev) share a name and cannot meet in one file.
#pragma once

#include <cstddef>

namespace grape::bench {

/// One chain run: `frames` steps of `frame` seconds, 4 sub-steps each.
struct Box2d3Run {
    double seconds = 0.0;     ///< thread CPU time of the steps
    double link_error = 0.0;  ///< worst | |x_k − x_{k−1}| − L | over the run, m
};

/// `links` bodies of mass 1, `link` m apart, hanging from a static body at the origin and
/// released horizontally, joined by rigid distance joints (Box2D v3's soft step).
Box2d3Run box2d3_chain(std::size_t links, double link, double g, double frame, int frames, int substeps);

/// Box2D's version string ("3.1.1").
const char* box2d3_version();

}  // namespace grape::bench
