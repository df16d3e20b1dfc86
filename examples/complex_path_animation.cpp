// The seed's complex path: a spiral and three segments as one path. Cues say where in the
// animation each part begins: the spiral and the first segment take 25 % each, the second
// 10 % and the third 40 %. One curve (quad-in-out) eases the whole journey.
#include <grape/anim.hpp>

#include <cstdio>

struct View {
    double x = 0, y = 0;
};

int main() {
    grape::SpiralPath spiral({100, 100}, 200, 0);
    grape::LinearPath linear1({100, 100}, {200, 200});
    grape::LinearPath linear2({200, 200}, {200, 100});
    grape::LinearPath linear3({200, 100}, {100, 100});
    grape::ComplexPath complex({spiral, linear1, linear2, linear3}, {0, 0.25, 0.5, 0.6});

    grape::Engine engine;
    View view;
    engine.create_2d_animation(view, complex, 4.0, {.curve = grape::Curve::quad_in_out()});
    for (int frame = 1; frame <= 4 * 60; ++frame) {
        engine.tick(1.0 / 60.0);
        if (frame % 60 == 0) std::printf("t = %d s: (%.2f, %.2f)\n", frame / 60, view.x, view.y);
    }
    return engine.size() == 0 ? 0 : 1;  // completed and removed
}
