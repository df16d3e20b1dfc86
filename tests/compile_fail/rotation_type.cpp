// Must not compile: a rotation member that cannot receive the heading (an int) beside double
// x and y. With -DROTATION_TYPE=float it compiles (the control).
#include <grape/anim.hpp>

#ifndef ROTATION_TYPE
#define ROTATION_TYPE int
#endif

struct Tile {
    double x = 0, y = 0;
    ROTATION_TYPE rotation = 0;
};

void animate_tile(grape::Engine& engine, Tile& tile, const grape::Path& path) {
    engine.create_2d_animation(tile, path, 1.0, {.heading = true});
}
