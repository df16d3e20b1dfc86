// Draws the seed's spiral with its debug decorations (u-ticks, tangents, start and end) and
// writes it as PNG and SVG.
#include <grape/render.hpp>

int main() {
    const grape::SpiralPath spiral({100, 100}, 200, 0);
    grape::Canvas canvas(480, 480);
    canvas.set_transform(grape::fit(spiral.bounds(), {0, 0, 480, 480}, 20));
    grape::draw_path(canvas, spiral, {.stroke = {.color = grape::colors::blue, .width = 2}, .ticks = 0.05, .tangents = 8});
    canvas.write("render_gallery.png");
    canvas.write("render_gallery.svg");
}
