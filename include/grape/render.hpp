// grape — render: a Canvas that writes PNG, SVG and PDF, and debug drawings of paths.
//
// A Canvas records what is drawn and writes it in the format its file name asks for, as
// many times as wanted; `to_image()` rasterizes it for reading pixels back. Sizes and line
// widths are in output units (pixels for PNG, points for SVG and PDF) whatever the current
// transform, so a debug line stays one pixel wide however far the world is zoomed.
//
//   grape::Canvas canvas(640, 480);
//   canvas.set_transform(grape::fit(path.bounds(), {0, 0, 640, 480}, 20));
//   grape::draw_path(canvas, path, {.ticks = 0.1});
//   canvas.write("path.png");
#pragma once

#include <grape/color.hpp>
#include <grape/export_render.hpp>
#include <grape/math.hpp>
#include <grape/path.hpp>
#include <grape/sprite.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grape {

/// \addtogroup render
/// @{

// Colours are grape::Color (grape/color.hpp): straight (not premultiplied) sRGB-encoded
// components in [0, 1] and opacity a, the one definition the anim engine's tweens use too.

/// A few named colours for debug drawings.
namespace colors {
inline constexpr Color black{0.0, 0.0, 0.0};  ///< (0, 0, 0)
inline constexpr Color white{1.0, 1.0, 1.0};  ///< (1, 1, 1)
inline constexpr Color transparent{0.0, 0.0, 0.0, 0.0};  ///< black with alpha 0
inline constexpr Color red{0.85, 0.1, 0.1};  ///< a strong red
inline constexpr Color green{0.1, 0.6, 0.2};  ///< a mid green
inline constexpr Color blue{0.15, 0.35, 0.85};  ///< a mid blue
inline constexpr Color orange{0.95, 0.55, 0.1};  ///< a bright orange
inline constexpr Color purple{0.55, 0.2, 0.7};  ///< a mid purple
inline constexpr Color grey{0.55, 0.55, 0.55};  ///< a mid grey
inline constexpr Color light_grey{0.85, 0.85, 0.85};  ///< a light grey
}  // namespace colors

/// An axis-aligned rectangle: top-left corner and size, in the units of its context.
struct Rect {
    double x = 0.0;  ///< left edge
    double y = 0.0;  ///< top edge
    double width = 0.0;  ///< extent to the right
    double height = 0.0;  ///< extent downwards
};

/// A 2-D affine map p ↦ (xx·x + xy·y + x0, yx·x + yy·y + y0), the layout cairo uses.
struct GRAPE_RENDER_API Affine {
    /// x per unit of x; the coefficients are named as in the map above, the default is the identity.
    double xx = 1.0, yx = 0.0, xy = 0.0, yy = 1.0, x0 = 0.0, y0 = 0.0;
    /** \var grape::Affine::yx
        y per unit of x. */
    /** \var grape::Affine::xy
        x per unit of y. */
    /** \var grape::Affine::yy
        y per unit of y. */
    /** \var grape::Affine::x0
        x of the image of the origin. */
    /** \var grape::Affine::y0
        y of the image of the origin. */

    /// The image of point p.
    constexpr Vec2 apply(Vec2 p) const noexcept { return {xx * p.x + xy * p.y + x0, yx * p.x + yy * p.y + y0}; }
    /// The image of direction v (no translation).
    constexpr Vec2 apply_vector(Vec2 v) const noexcept { return {xx * v.x + xy * v.y, yx * v.x + yy * v.y}; }
    /// A move by t.
    static constexpr Affine translation(Vec2 t) noexcept { return {1.0, 0.0, 0.0, 1.0, t.x, t.y}; }
    /// A scaling by sx along x and sy along y about the origin.
    static constexpr Affine scaling(double sx, double sy) noexcept { return {sx, 0.0, 0.0, sy, 0.0, 0.0}; }
    /// A turn by `radians` about the origin (clockwise on screen, where y points down).
    static Affine rotation(double radians) noexcept;
    /// First `second`, then `first`: (first * second).apply(p) == first.apply(second.apply(p)).
    friend constexpr Affine operator*(const Affine& first, const Affine& second) noexcept {
        return {first.xx * second.xx + first.xy * second.yx, first.yx * second.xx + first.yy * second.yx,
                first.xx * second.xy + first.xy * second.yy, first.yx * second.xy + first.yy * second.yy,
                first.xx * second.x0 + first.xy * second.y0 + first.x0,
                first.yx * second.x0 + first.yy * second.y0 + first.y0};
    }
    /// The largest factor by which the map stretches a length (largest singular value).
    double max_stretch() const noexcept;
};

/// The map that fits `world` into `viewport` (output units) with `margin` on every side,
/// keeping the aspect ratio and centring. A degenerate box (a point or a line) still maps
/// to the viewport's center without dividing by zero.
GRAPE_RENDER_API Affine fit(const Bounds& world, const Rect& viewport, double margin = 0.0) noexcept;

/// How line ends look.
enum class LineCap { butt, round, square };
/// How polyline corners look.
enum class LineJoin { miter, round, bevel };

/// How lines are drawn. Width and dashes are in output units, unaffected by the transform.
struct StrokeStyle {
    Color color = colors::black;       ///< line colour
    double width = 1.0;                ///< line width (output units, > 0)
    LineCap cap = LineCap::round;      ///< line ends
    LineJoin join = LineJoin::round;   ///< corners
    std::vector<double> dashes = {};   ///< on/off lengths (output units); empty: solid
    /// Miter joins longer than this many line widths are drawn beveled (≥ 1; SVG's default 4,
    /// where cairo's own 10 shows spikes at sharp corners).
    double miter_limit = 4.0;
};

/// Which points a self-overlapping shape covers.
enum class FillRule { nonzero, even_odd };

/// How areas are filled.
struct FillStyle {
    Color color = colors::black;       ///< fill colour
    FillRule rule = FillRule::nonzero; ///< which overlaps count as inside
};

/// Horizontal placement of a text label relative to its anchor point.
enum class TextAlign { left, center, right };

/// How text labels look. The anchor is the left/center/right end of the baseline.
struct TextStyle {
    Color color = colors::black;       ///< text colour
    double size = 12.0;                ///< font size (output units)
    TextAlign align = TextAlign::left; ///< anchor position along the text
    bool bold = false;                 ///< bold face
    std::string family = "sans-serif"; ///< font family (fontconfig name)
};

/// An RGBA raster image in memory: a tile sheet to blit, or a Canvas read back.
class GRAPE_RENDER_API Image {
public:
    /// A `width` × `height` image filled with `fill`. Throws grape::Error unless both sizes
    /// are in [1, 32768].
    Image(int width, int height, Color fill = colors::transparent);
    /// Reads a PNG file. Throws grape::Error naming the file and the reason.
    static Image load_png(const std::filesystem::path& file);

    /// Width in pixels.
    int width() const noexcept { return width_; }
    /// Height in pixels.
    int height() const noexcept { return height_; }
    /// Pixel (x, y) with straight alpha; transparent outside the image.
    Color pixel(int x, int y) const noexcept;
    /// Sets pixel (x, y); ignored outside the image.
    void set_pixel(int x, int y, Color color) noexcept;
    /// Writes a PNG file (through a temporary, so a failure leaves no partial file).
    /// Throws grape::Error naming the file and the reason.
    void write_png(const std::filesystem::path& file) const;
    /// Premultiplied 32-bit ARGB words in native byte order, row after row (cairo's layout).
    std::span<const std::uint32_t> argb() const noexcept { return argb_; }
    /// The same, writable.
    std::span<std::uint32_t> argb() noexcept { return argb_; }

private:
    int width_;
    int height_;
    std::vector<std::uint32_t> argb_;
};

namespace detail {
struct CanvasState;  // cairo recording surface and context (src/render/canvas.cpp)
}

/// A drawing surface. Everything drawn is recorded, then written by file extension
/// (.png, .svg, .pdf) or rasterized with to_image(). Move-only.
class GRAPE_RENDER_API Canvas {
public:
    /// A `width` × `height` canvas (output units) cleared to `background`.
    /// Throws grape::Error unless both sizes are finite and in [1, 32768].
    Canvas(double width, double height, Color background = colors::white);
    ~Canvas();
    Canvas(Canvas&&) noexcept;  ///< takes the drawing over; the moved-from canvas may only be destroyed or assigned to
    Canvas& operator=(Canvas&&) noexcept;  ///< as the move constructor

    /// Width (output units).
    double width() const noexcept;
    /// Height (output units).
    double height() const noexcept;

    /// Saves the transform and clip; pop() restores them. Pushes and pops must pair.
    void push();
    /// Restores what the matching push() saved; without one, resets the transform.
    void pop();
    /// Replaces the world-to-output transform. A singular or non-finite one is ignored (the
    /// current transform stays): it would map the world onto a line and poison cairo's state.
    void set_transform(const Affine& transform) noexcept;
    /// The current world-to-output transform.
    Affine transform() const noexcept;
    /// Applies `t` before the current transform (world points are mapped by t first).
    void concat(const Affine& t) noexcept;
    /// Limits drawing to `area` (world units, current transform) until pop().
    void clip(const Rect& area) noexcept;

    /// A line segment from a to b (world units).
    void stroke_line(Vec2 a, Vec2 b, const StrokeStyle& style);
    /// A polyline through the points, closed back to the first when `closed`.
    void stroke_polyline(std::span<const Vec2> points, const StrokeStyle& style, bool closed = false);
    /// The polygon through the points, filled.
    void fill_polygon(std::span<const Vec2> points, const FillStyle& style);
    /// A circle's outline (center and radius in world units).
    void stroke_circle(Vec2 center, double radius, const StrokeStyle& style);
    /// A filled circle (center and radius in world units).
    void fill_circle(Vec2 center, double radius, const FillStyle& style);
    /// A filled disc of `radius` output units at world point `center`: a marker that keeps
    /// its size however the world is scaled.
    void dot(Vec2 center, double radius, Color color);
    /// A rectangle's outline (world units).
    void stroke_rect(const Rect& rect, const StrokeStyle& style);
    /// A filled rectangle (world units).
    void fill_rect(const Rect& rect, const FillStyle& style);

    /// The path over u in [0, 1]: Béziers, circle arcs, lines and cubic splines as exact
    /// curves, other kinds flattened within a quarter of an output unit. A path from SVG data
    /// is drawn as SVG draws it: `Z` closes its subpath (a join, not two caps) and a
    /// zero-length subpath is a dot with round caps. The work is bounded by the length on
    /// the picture: a sine wave of waves shorter than the tolerance is drawn as the band it
    /// fills (a zigzag every quarter unit), one of amplitude within it as its axis.
    void stroke_path(const Path& path, const StrokeStyle& style);
    /// The pieces (lines and cubic curves) stroke_path hands to cairo for `path` under the
    /// current transform: the work of drawing it. Leaves no path behind.
    std::size_t path_pieces(const Path& path);
    /// The path closed by a straight line from its end back to its start, filled.
    void fill_path(const Path& path, const FillStyle& style);

    /// A text label (UTF-8) anchored at world point `at`, upright whatever the transform.
    void text(Vec2 at, std::string_view utf8, const TextStyle& style = {});

    /// Blits the `source` rectangle of `image` (pixels) onto the `target` rectangle (world
    /// units), scaled to fit; nearest-neighbour when not scaled smoothly, so pixel art stays sharp.
    void draw_image(const Image& image, const Rect& source, const Rect& target, bool smooth = false);
    /// Blits the whole image with its top-left corner at world point `at`, one pixel per unit.
    void draw_image(const Image& image, Vec2 at);

    /// Writes the picture; the format follows the extension (.png, .svg, .pdf, any case).
    /// Throws grape::Error naming the file and the reason (unknown extension, unwritable);
    /// a failed write leaves no partial file behind.
    void write(const std::filesystem::path& file) const;
    /// The picture as pixels, one per output unit (rounded up).
    Image to_image() const;

private:
    std::unique_ptr<detail::CanvasState> state_;
};

/// What draw_path adds to the stroked path ("debug rendering" in the seed).
struct PathStyle {
    StrokeStyle stroke = {};            ///< the path itself
    double ticks = 0.0;                 ///< a tick across the path every Δu (0: none); shows the parametrization
    double tick_length = 8.0;           ///< tick length (output units)
    Color tick_color = colors::grey;    ///< tick colour
    bool cues = true;                   ///< mark where each part of a complex path begins (nested too)
    Color cue_color = colors::orange;   ///< cue marker colour
    int tangents = 0;                   ///< tangent arrows at this many evenly spaced u (0: none)
    double tangent_length = 24.0;       ///< arrow length (output units)
    Color tangent_color = colors::blue; ///< arrow colour
    bool ends = true;                   ///< mark the start (hollow) and end (filled) points
};

/// Draws a path with the decorations of `style`. Ticks and arrows keep their output size.
GRAPE_RENDER_API void draw_path(Canvas& canvas, const Path& path, const PathStyle& style = {});

/// How draw_particles shows particles. Sizes in output units; arrows in world units per unit.
struct ParticleStyle {
    Color color = colors::blue;          ///< moving particles
    Color pinned_color = colors::black;  ///< particles of infinite mass
    double radius = 5.0;                 ///< disc radius (output units)
    double velocity_scale = 0.0;         ///< velocity arrows of v·scale world units (0: none)
    Color velocity_color = colors::green;///< velocity arrow colour
};

/// Particles as discs (pinned ones in their own colour), with optional velocity arrows.
/// `velocities` and `inverse_masses` may be empty; otherwise one per position.
GRAPE_RENDER_API void draw_particles(Canvas& canvas, std::span<const Vec2> positions,
                                     std::span<const Vec2> velocities, std::span<const double> inverse_masses,
                                     const ParticleStyle& style = {});

/// The zero set of an implicit curve C(x, y) = 0 (a constraint curve) inside `region`
/// (world units), traced by marching squares on a `cells` × `cells` grid with linear
/// interpolation: within (cell size)²·|C''|/|∇C| of the curve. `cells` is clamped to [2, 2000].
GRAPE_RENDER_API void draw_implicit_curve(Canvas& canvas, const std::function<double(Vec2)>& c, const Bounds& region,
                                          const StrokeStyle& style, int cells = 256);

/// A TileSheetSprite's current frame from `sheet_image` blitted at world point `at`,
/// `scale` world units per sheet pixel; with `debug`, its outline and frame number too.
GRAPE_RENDER_API void draw_sprite(Canvas& canvas, const Image& sheet_image, const TileSheetSprite& sprite, Vec2 at,
                                  double scale = 1.0, bool debug = false);

/// Frame `frame` of a SpriteSheet (Aseprite, TexturePacker) from its sheet picture, drawn
/// upright with its pivot at world point `at`, `scale` world units per pixel: trimmed pixels
/// sit at their offset in the untrimmed image, rotated frames are turned back.
GRAPE_RENDER_API void draw_sprite_frame(Canvas& canvas, const Image& sheet_image, const SpriteFrame& frame,
                                        Vec2 at, double scale = 1.0);

/// The whole sheet at `at` (world units, one unit per pixel × scale) with every frame
/// outlined and numbered and the sprite's current frame highlighted.
GRAPE_RENDER_API void draw_tile_sheet(Canvas& canvas, const Image& sheet_image, const TileSheetSprite& sprite,
                                      Vec2 at, double scale = 1.0);

/// A marker that moves in an animated SVG: where it is at each frame.
struct SvgMover {
    std::vector<Vec2> positions = {};  ///< one per frame, world units
    Color color = colors::blue;    ///< fill colour
    std::string label = {};        ///< shown as the marker's tooltip ("" for none)
    double radius = 5.0;           ///< output units
};

/// A looping SMIL-animated SVG document `width` × `height` (output units): the paths drawn
/// once (flattened within a quarter of an output unit, colours cycling through
/// `path_colors`), and each mover a circle stepping through its positions, all frames in
/// `seconds`. `transform` maps world units to output units. Non-finite positions are drawn
/// at the origin rather than written as NaN.
GRAPE_RENDER_API std::string animated_svg(double width, double height, const Affine& transform,
                                          std::span<const Path> paths, std::span<const Color> path_colors,
                                          std::span<const SvgMover> movers, double seconds,
                                          std::string_view title = {});

/// A line chart of y over x (one series), for diagnostics such as energy over time.
struct PlotSeries {
    std::span<const double> x;          ///< abscissae (same size as y)
    std::span<const double> y;          ///< ordinates
    StrokeStyle stroke = {};            ///< line style
    std::string label = {};             ///< legend entry ("" for none)
};

/// Draws axes, the series, their legend and min/max labels into `area` (output units,
/// ignoring the transform). Non-finite points are skipped; a flat series gets a small range.
GRAPE_RENDER_API void draw_plot(Canvas& canvas, const Rect& area, std::span<const PlotSeries> series,
                                std::string_view title = {});

/// @}

}  // namespace grape
