// Internals shared by the render sources: cairo path building and styled stroke/fill.
#pragma once

#include <grape/render.hpp>

#include <cairo.h>

namespace grape::detail {

/// Line to p, or move to p when there is no current point. Non-finite points are skipped.
void line_to(cairo_t* cr, Vec2 p) noexcept;
/// Strokes and clears the current path; width and dashes in output units.
void stroke(cairo_t* cr, const StrokeStyle& style) noexcept;
/// Fills and clears the current path.
void fill(cairo_t* cr, const FillStyle& style) noexcept;
/// Appends the path over u in [0, 1] to cairo's current path (world units). Exact curves
/// where the kind allows, otherwise flattened within `tolerance` world units.
void add_path(cairo_t* cr, const Path& path, double tolerance);

}  // namespace grape::detail
