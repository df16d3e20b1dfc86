// Canvas over a cairo recording surface: drawing is recorded once and replayed onto a
// PNG, SVG or PDF surface (or an image in memory) on demand.
#include <grape/render.hpp>

#include <grape/error.hpp>

#include "atomic_file.hpp"
#include "cairo_util.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <new>
#include <string>
#include <system_error>

#include "internal/compiler.hpp"

#if GRAPE_ADDRESS_SANITIZER
// Text goes through fontconfig and cairo's font caches, which live until the process ends
// and are freed by no one (cairo_debug_reset_static_data asserts if any face is still
// referenced). The leak checker would report them for every program that draws a label.
// Their stacks end inside these libraries (built without frame pointers), so nothing of
// grape's own is hidden by naming them. Visible: the runtime finds it by name.
extern "C" GRAPE_DEFAULT_VISIBILITY const char* __lsan_default_suppressions() {
    return "leak:libfontconfig.so\nleak:libcairo.so\nleak:libpixman-1.so\n";
}
#endif

namespace grape {

namespace detail {
struct CanvasState {
    double width = 0.0;
    double height = 0.0;
    cairo_surface_t* surface = nullptr;  // recording surface
    cairo_t* cr = nullptr;
    int depth = 0;  // push() nesting

    ~CanvasState() {
        if (cr) cairo_destroy(cr);
        if (surface) cairo_surface_destroy(surface);
    }
};
}  // namespace detail

namespace {

using detail::number_text;

void check_size(const char* what, double width, double height) {
    const auto ok = [](double v) { return std::isfinite(v) && v >= 1.0 && v <= 32768.0; };
    if (!ok(width)) throw Error(std::string(what) + ": width must be in [1, 32768] (got " + number_text(width) + ")");
    if (!ok(height))
        throw Error(std::string(what) + ": height must be in [1, 32768] (got " + number_text(height) + ")");
}

std::uint32_t pack(Color c) noexcept {
    const auto channel = [](double v) {
        v = std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0;
        return static_cast<std::uint32_t>(std::lround(v * 255.0));
    };
    const std::uint32_t a = channel(c.a);
    // Premultiply in 8 bits, as cairo stores it.
    const auto pre = [&](double v) { return (channel(v) * a + 127) / 255; };
    return (a << 24) | (pre(c.r) << 16) | (pre(c.g) << 8) | pre(c.b);
}

Color unpack(std::uint32_t w) noexcept {
    const double a = static_cast<double>(w >> 24);
    if (a == 0.0) return colors::transparent;
    const auto straight = [&](std::uint32_t v) { return std::min(1.0, static_cast<double>(v & 0xffu) / a); };
    return {straight(w >> 16), straight(w >> 8), straight(w), a / 255.0};
}

// Copies a cairo image surface (any format) into ARGB32 words.
void copy_from_surface(cairo_surface_t* image, std::span<std::uint32_t> out, int width, int height) {
    cairo_surface_flush(image);
    const unsigned char* data = cairo_image_surface_get_data(image);
    const int stride = cairo_image_surface_get_stride(image);
    for (int y = 0; y < height; ++y) {
        std::memcpy(out.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width),
                    data + static_cast<std::ptrdiff_t>(y) * stride, static_cast<std::size_t>(width) * 4);
    }
}

// A cairo-owned copy of the image: the recording surface may replay long after the Image
// it came from is gone.
cairo_surface_t* surface_from_image(const Image& image) {
    cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, image.width(), image.height());
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) return s;  // the caller sees the status
    cairo_surface_flush(s);
    unsigned char* data = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    const auto words = image.argb();
    for (int y = 0; y < image.height(); ++y) {
        std::memcpy(data + static_cast<std::ptrdiff_t>(y) * stride,
                    words.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width()),
                    static_cast<std::size_t>(image.width()) * 4);
    }
    cairo_surface_mark_dirty(s);
    return s;
}

std::string lower_extension(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

// cairo's stream callback: the bytes go to the file's temporary, errors are kept for the message.
cairo_status_t write_to_file(void* closure, const unsigned char* data, unsigned int length) {
    auto* out = static_cast<detail::AtomicFile*>(closure);
    return out->append({reinterpret_cast<const char*>(data), length}) ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

// cairo's stream callback for reading: the next LENGTH bytes of a std::ifstream.
cairo_status_t read_from_file(void* closure, unsigned char* data, unsigned int length) {
    auto* in = static_cast<std::ifstream*>(closure);
    in->read(reinterpret_cast<char*>(data), static_cast<std::streamsize>(length));
    return in->gcount() == static_cast<std::streamsize>(length) ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_READ_ERROR;
}

// After cairo is done with the file: a failed write is reported by its errno's reason,
// any other cairo failure (e.g. out of memory) by cairo's own words.
void finish_file(detail::AtomicFile& out, cairo_status_t status) {
    if (status == CAIRO_STATUS_WRITE_ERROR) out.fail();
    if (status != CAIRO_STATUS_SUCCESS) out.fail(cairo_status_to_string(status));
    out.commit();
}

}  // namespace

// ---------------------------------------------------------------------------------- Affine

Affine Affine::rotation(double radians) noexcept {
    const double c = std::cos(radians);
    const double s = std::sin(radians);
    return {c, s, -s, c, 0.0, 0.0};
}

double Affine::max_stretch() const noexcept {
    // Largest singular value of [[xx, xy], [yx, yy]] from the eigenvalues of MᵀM.
    const double a = xx * xx + yx * yx;
    const double b = xx * xy + yx * yy;
    const double d = xy * xy + yy * yy;
    const double mean = 0.5 * (a + d);
    const double spread = std::hypot(0.5 * (a - d), b);
    return std::sqrt(mean + spread);
}

Affine fit(const Bounds& world, const Rect& viewport, double margin) noexcept {
    const double w = std::max(0.0, viewport.width - 2.0 * margin);
    const double h = std::max(0.0, viewport.height - 2.0 * margin);
    const Vec2 center{viewport.x + 0.5 * viewport.width, viewport.y + 0.5 * viewport.height};
    if (!is_finite(world.min) || !is_finite(world.max)) return Affine::translation(center);
    const Vec2 size = world.size();
    double scale = 1.0;
    if (size.x > 0.0 && size.y > 0.0) scale = std::min(w / size.x, h / size.y);
    else if (size.x > 0.0) scale = w / size.x;
    else if (size.y > 0.0) scale = h / size.y;
    const Vec2 mid = (world.min + world.max) * 0.5;
    return Affine::translation(center) * Affine::scaling(scale, scale) * Affine::translation(-mid);
}

// ----------------------------------------------------------------------------------- Image

Image::Image(int width, int height, Color fill) : width_(width), height_(height) {
    check_size("Image", width, height);
    argb_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), pack(fill));
}

Image Image::load_png(const std::filesystem::path& file) {
    // Read through a stream: cairo's file functions take a narrow name, which on Windows
    // cannot hold every path.
    std::ifstream in(file, std::ios::binary);
    cairo_surface_t* s = cairo_image_surface_create_from_png_stream(read_from_file, &in);
    const cairo_status_t status = cairo_surface_status(s);
    if (status != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(s);
        std::error_code ec;
        if (!std::filesystem::exists(file, ec)) throw Error("cannot read " + file.string() + ": no such file");
        // cairo reports a corrupt file as "out of memory"; the signature tells the real story.
        char signature[8] = {};
        std::ifstream(file, std::ios::binary).read(signature, 8);
        const bool png = std::memcmp(signature, "\x89PNG\r\n\x1a\n", 8) == 0;
        throw Error("cannot read " + file.string() + ": not a readable PNG file (" +
                    (png ? std::string(cairo_status_to_string(status)) : std::string("no PNG signature")) + ")");
    }
    const int w = cairo_image_surface_get_width(s);
    const int h = cairo_image_surface_get_height(s);
    Image image(std::max(w, 1), std::max(h, 1));
    // Convert any PNG format (grey, RGB, palette) to ARGB32 by painting it.
    cairo_surface_t* argb = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    cairo_t* cr = cairo_create(argb);
    cairo_set_source_surface(cr, s, 0, 0);
    cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
    cairo_paint(cr);
    cairo_destroy(cr);
    copy_from_surface(argb, image.argb(), w, h);
    cairo_surface_destroy(argb);
    cairo_surface_destroy(s);
    return image;
}

Color Image::pixel(int x, int y) const noexcept {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return colors::transparent;
    return unpack(argb_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)]);
}

void Image::set_pixel(int x, int y, Color color) noexcept {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
    argb_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)] = pack(color);
}

void Image::write_png(const std::filesystem::path& file) const {
    detail::AtomicFile out(file);
    cairo_surface_t* s = surface_from_image(*this);
    cairo_status_t status = cairo_surface_status(s);
    if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_write_to_png_stream(s, write_to_file, &out);
    cairo_surface_destroy(s);
    finish_file(out, status);
}

// ---------------------------------------------------------------------------------- Canvas

Canvas::Canvas(double width, double height, Color background) : state_(std::make_unique<detail::CanvasState>()) {
    check_size("Canvas", width, height);
    state_->width = width;
    state_->height = height;
    const cairo_rectangle_t extents{0.0, 0.0, width, height};
    state_->surface = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, &extents);
    state_->cr = cairo_create(state_->surface);
    if (background.a > 0.0) {
        cairo_set_source_rgba(state_->cr, background.r, background.g, background.b, background.a);
        cairo_paint(state_->cr);
    }
}

Canvas::~Canvas() = default;
Canvas::Canvas(Canvas&&) noexcept = default;
Canvas& Canvas::operator=(Canvas&&) noexcept = default;

double Canvas::width() const noexcept { return state_->width; }
double Canvas::height() const noexcept { return state_->height; }

void Canvas::push() {
    cairo_save(state_->cr);
    ++state_->depth;
}

void Canvas::pop() {
    if (state_->depth == 0) {
        cairo_identity_matrix(state_->cr);
        return;
    }
    cairo_restore(state_->cr);
    --state_->depth;
}

void Canvas::set_transform(const Affine& t) noexcept {
    const cairo_matrix_t m{t.xx, t.yx, t.xy, t.yy, t.x0, t.y0};
    // A singular or non-finite matrix would put cairo into an error state for good: refuse it.
    const double det = t.xx * t.yy - t.xy * t.yx;
    const bool finite = std::isfinite(t.xx) && std::isfinite(t.yx) && std::isfinite(t.xy) && std::isfinite(t.yy) &&
                        std::isfinite(t.x0) && std::isfinite(t.y0);
    if (finite && std::isfinite(det) && det != 0.0) cairo_set_matrix(state_->cr, &m);
}

Affine Canvas::transform() const noexcept {
    cairo_matrix_t m;
    cairo_get_matrix(state_->cr, &m);
    return {m.xx, m.yx, m.xy, m.yy, m.x0, m.y0};
}

void Canvas::concat(const Affine& t) noexcept { set_transform(transform() * t); }

namespace {
bool finite_rect(const Rect& r) noexcept {
    return std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.width) && std::isfinite(r.height);
}
}  // namespace

void Canvas::clip(const Rect& area) noexcept {
    if (!finite_rect(area)) return;
    cairo_rectangle(state_->cr, area.x, area.y, area.width, area.height);
    cairo_clip(state_->cr);
}

void Canvas::stroke_line(Vec2 a, Vec2 b, const StrokeStyle& style) {
    const Vec2 points[2] = {a, b};
    stroke_polyline(points, style);
}

void Canvas::stroke_polyline(std::span<const Vec2> points, const StrokeStyle& style, bool closed) {
    if (points.empty()) return;
    cairo_t* cr = state_->cr;
    cairo_new_path(cr);
    for (const Vec2 p : points) detail::line_to(cr, p);
    if (closed) cairo_close_path(cr);
    detail::stroke(cr, style);
}

void Canvas::fill_polygon(std::span<const Vec2> points, const FillStyle& style) {
    if (points.size() < 3) return;
    cairo_t* cr = state_->cr;
    cairo_new_path(cr);
    for (const Vec2 p : points) detail::line_to(cr, p);
    cairo_close_path(cr);
    detail::fill(cr, style);
}

namespace {

// A circle as cairo's current path; false (and no path) when it has no finite area to draw.
bool circle_path(cairo_t* cr, Vec2 center, double radius) {
    if (!is_finite(center) || !std::isfinite(radius) || radius <= 0.0) return false;
    cairo_new_path(cr);
    cairo_arc(cr, center.x, center.y, radius, 0.0, 2.0 * pi);
    cairo_close_path(cr);
    return true;
}

}  // namespace

void Canvas::stroke_circle(Vec2 center, double radius, const StrokeStyle& style) {
    if (circle_path(state_->cr, center, radius)) detail::stroke(state_->cr, style);
}

void Canvas::fill_circle(Vec2 center, double radius, const FillStyle& style) {
    if (circle_path(state_->cr, center, radius)) detail::fill(state_->cr, style);
}

void Canvas::dot(Vec2 center, double radius, Color color) {
    if (!is_finite(center) || !std::isfinite(radius) || radius <= 0.0) return;
    const Vec2 d = transform().apply(center);
    cairo_t* cr = state_->cr;
    cairo_save(cr);
    cairo_identity_matrix(cr);
    cairo_new_path(cr);
    cairo_arc(cr, d.x, d.y, radius, 0.0, 2.0 * pi);
    cairo_set_source_rgba(cr, color.r, color.g, color.b, color.a);
    cairo_fill(cr);
    cairo_restore(cr);
}

void Canvas::stroke_rect(const Rect& r, const StrokeStyle& style) {
    if (!finite_rect(r)) return;
    cairo_new_path(state_->cr);
    cairo_rectangle(state_->cr, r.x, r.y, r.width, r.height);
    detail::stroke(state_->cr, style);
}

void Canvas::fill_rect(const Rect& r, const FillStyle& style) {
    if (!finite_rect(r)) return;
    cairo_new_path(state_->cr);
    cairo_rectangle(state_->cr, r.x, r.y, r.width, r.height);
    detail::fill(state_->cr, style);
}

void Canvas::stroke_path(const Path& path, const StrokeStyle& style) {
    cairo_t* cr = state_->cr;
    cairo_new_path(cr);
    detail::add_path(cr, path, 0.25 / transform().max_stretch());
    detail::stroke(cr, style);
}

std::size_t Canvas::path_pieces(const Path& path) {
    cairo_t* cr = state_->cr;
    cairo_new_path(cr);
    detail::add_path(cr, path, 0.25 / transform().max_stretch());
    cairo_path_t* copy = cairo_copy_path(cr);
    std::size_t pieces = 0;
    if (copy->status == CAIRO_STATUS_SUCCESS)
        for (int i = 0; i < copy->num_data; i += copy->data[i].header.length) {
            const auto type = copy->data[i].header.type;
            if (type == CAIRO_PATH_LINE_TO || type == CAIRO_PATH_CURVE_TO) ++pieces;
        }
    cairo_path_destroy(copy);
    cairo_new_path(cr);
    return pieces;
}

void Canvas::fill_path(const Path& path, const FillStyle& style) {
    cairo_t* cr = state_->cr;
    cairo_new_path(cr);
    detail::add_path(cr, path, 0.25 / transform().max_stretch());
    cairo_close_path(cr);
    detail::fill(cr, style);
}

void Canvas::text(Vec2 at, std::string_view utf8, const TextStyle& style) {
    if (!is_finite(at) || utf8.empty()) return;
    const std::string s(utf8);  // cairo wants a terminated string
    const Vec2 d = transform().apply(at);
    cairo_t* cr = state_->cr;
    cairo_save(cr);
    cairo_identity_matrix(cr);
    cairo_select_font_face(cr, style.family.c_str(), CAIRO_FONT_SLANT_NORMAL,
                           style.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, std::isfinite(style.size) && style.size > 0.0 ? style.size : 12.0);
    cairo_text_extents_t e;
    cairo_text_extents(cr, s.c_str(), &e);
    const double shift = style.align == TextAlign::left     ? 0.0
                         : style.align == TextAlign::center ? 0.5 * e.x_advance
                                                            : e.x_advance;
    cairo_move_to(cr, d.x - shift, d.y);
    cairo_set_source_rgba(cr, style.color.r, style.color.g, style.color.b, style.color.a);
    cairo_show_text(cr, s.c_str());
    cairo_new_path(cr);
    cairo_restore(cr);
}

void Canvas::draw_image(const Image& image, const Rect& source, const Rect& target, bool smooth) {
    if (!finite_rect(source) || !finite_rect(target)) return;
    if (!(source.width > 0.0 && source.height > 0.0 && target.width != 0.0 && target.height != 0.0)) return;
    cairo_t* cr = state_->cr;
    cairo_surface_t* s = surface_from_image(image);
    cairo_save(cr);
    cairo_translate(cr, target.x, target.y);
    cairo_scale(cr, target.width / source.width, target.height / source.height);
    cairo_set_source_surface(cr, s, -source.x, -source.y);
    cairo_pattern_set_filter(cairo_get_source(cr), smooth ? CAIRO_FILTER_GOOD : CAIRO_FILTER_NEAREST);
    cairo_new_path(cr);
    cairo_rectangle(cr, 0.0, 0.0, source.width, source.height);
    cairo_fill(cr);
    cairo_restore(cr);
    cairo_surface_destroy(s);
}

void Canvas::draw_image(const Image& image, Vec2 at) {
    const double w = image.width();
    const double h = image.height();
    draw_image(image, {0.0, 0.0, w, h}, {at.x, at.y, w, h});
}

void Canvas::write(const std::filesystem::path& file) const {
    const std::string ext = lower_extension(file);
    if (ext != ".png" && ext != ".svg" && ext != ".pdf")
        throw Error("cannot write " + file.string() + ": unknown format \"" + ext +
                    "\" (the file name must end in .png, .svg or .pdf)");
    if (ext == ".png") {
        to_image().write_png(file);
        return;
    }
    detail::AtomicFile out(file);
    cairo_surface_t* target =
        ext == ".svg" ? cairo_svg_surface_create_for_stream(write_to_file, &out, state_->width, state_->height)
                      : cairo_pdf_surface_create_for_stream(write_to_file, &out, state_->width, state_->height);
    cairo_status_t status = cairo_surface_status(target);
    if (status == CAIRO_STATUS_SUCCESS) {
        cairo_t* cr = cairo_create(target);
        cairo_set_source_surface(cr, state_->surface, 0.0, 0.0);
        cairo_paint(cr);
        status = cairo_status(cr);
        cairo_destroy(cr);
        // PDF and SVG surfaces write most of their bytes here: its status is the write's.
        cairo_surface_finish(target);
        if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(target);
    }
    cairo_surface_destroy(target);
    finish_file(out, status);
}

Image Canvas::to_image() const {
    const int w = static_cast<int>(std::ceil(state_->width));
    const int h = static_cast<int>(std::ceil(state_->height));
    Image image(w, h);
    cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {  // no memory for the raster
        cairo_surface_destroy(s);
        throw std::bad_alloc();
    }
    cairo_t* cr = cairo_create(s);
    cairo_set_source_surface(cr, state_->surface, 0.0, 0.0);
    cairo_paint(cr);
    cairo_destroy(cr);
    copy_from_surface(s, image.argb(), w, h);
    cairo_surface_destroy(s);
    return image;
}

}  // namespace grape
