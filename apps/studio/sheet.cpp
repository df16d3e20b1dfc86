// The generated sprite sheet.
#include "sheet.hpp"

#include <grape/math.hpp>

#include <cairo.h>

#include <cmath>
#include <string>

namespace grape::studio {

SheetImage draw_sprite_sheet(int frames, int columns, int frame_size) {
    const int rows = (frames + columns - 1) / columns;
    SheetImage image;
    image.width = columns * frame_size;
    image.height = rows * frame_size;
    image.stride = cairo_format_stride_for_width(CAIRO_FORMAT_ARGB32, image.width);
    image.pixels.assign(std::size_t(image.stride) * std::size_t(image.height), 0);
    cairo_surface_t* surface = cairo_image_surface_create_for_data(image.pixels.data(), CAIRO_FORMAT_ARGB32,
                                                                   image.width, image.height, image.stride);
    cairo_t* cr = cairo_create(surface);
    const double s = frame_size;
    for (int f = 0; f < frames; ++f) {
        const double x0 = (f % columns) * s;
        const double y0 = (f / columns) * s;
        const double phase = double(f) / frames;  // one bounce and one turn per cycle
        cairo_save(cr);
        cairo_translate(cr, x0, y0);
        // Frame background and border, so each tile reads as a frame in the sheet view.
        cairo_rectangle(cr, 1, 1, s - 2, s - 2);
        cairo_set_source_rgb(cr, 0.93, 0.95, 0.98);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0.70, 0.74, 0.80);
        cairo_set_line_width(cr, 1.0);
        cairo_stroke(cr);
        // Ground.
        cairo_move_to(cr, 0.1 * s, 0.88 * s);
        cairo_line_to(cr, 0.9 * s, 0.88 * s);
        cairo_set_source_rgb(cr, 0.35, 0.35, 0.40);
        cairo_set_line_width(cr, 2.0);
        cairo_stroke(cr);
        // Bounce height |sin|, squash near the ground.
        const double h = std::abs(std::sin(pi * phase));
        const double r = 0.16 * s;
        const double squash = 1.0 - 0.3 * std::max(0.0, 1.0 - h * 4.0);
        const double cy = 0.88 * s - r * squash - h * 0.5 * s;
        cairo_save(cr);
        cairo_translate(cr, 0.5 * s, cy);
        cairo_scale(cr, 1.0 / squash, squash);
        cairo_arc(cr, 0, 0, r, 0, 2 * pi);
        cairo_set_source_rgb(cr, 0.45, 0.20, 0.55);  // grape purple
        cairo_fill(cr);
        // A spoke that turns once per cycle shows the direction of play.
        const double a = 2 * pi * phase;
        cairo_move_to(cr, 0, 0);
        cairo_line_to(cr, r * std::cos(a), r * std::sin(a));
        cairo_set_source_rgb(cr, 1, 0.85, 0.2);
        cairo_set_line_width(cr, 3.0);
        cairo_stroke(cr);
        cairo_restore(cr);
        // Frame number.
        const std::string label = std::to_string(f);
        cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
        cairo_set_font_size(cr, 0.18 * s);
        cairo_move_to(cr, 0.08 * s, 0.22 * s);
        cairo_set_source_rgb(cr, 0.15, 0.15, 0.2);
        cairo_show_text(cr, label.c_str());
        cairo_restore(cr);
    }
    cairo_destroy(cr);
    cairo_surface_flush(surface);
    cairo_surface_destroy(surface);
    return image;
}

}  // namespace grape::studio
