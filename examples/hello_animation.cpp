// The seed's first example: a view tweens along a spiral (radius 200 → 0) for 2 seconds,
// with complete and loop listeners and the engine's tick.
#include <grape/anim.hpp>

#include <cstdio>

struct View {
    double x = 0, y = 0;
};

int main() {
    grape::Engine engine;
    View view;
    grape::SpiralPath spiral({100, 100}, 200, 0);

    grape::Animation anim = engine.create_2d_animation(view, spiral, 2.0, {.repeat = 1});
    anim.on_complete([] { std::puts("animation done!"); });
    anim.on_loop([](int play) { std::printf("loop: play %d begins\n", play); });
    engine.on_tick([&](double) { /* draw view at (view.x, view.y) */ });

    for (int frame = 0; frame < 4 * 60; ++frame) engine.tick(1.0 / 60.0);
    std::printf("view at (%.3f, %.3f)\n", view.x, view.y);  // the spiral's center
    return anim.alive() ? 1 : 0;
}
