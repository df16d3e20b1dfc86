// Paths as cairo geometry, and the debug decorations of draw_path.
//
// Exact where cairo has the primitive: Bézier control points come back from the path's own
// derivatives (p1 = p0 + d1(0)/3 for a cubic), circle and ellipse arcs from point, d1 and d2,
// and piecewise-cubic splines segment by segment from four points per segment (a cubic is
// fixed by four of its points). Everything else is flattened by Path::flatten.
#include "cairo_util.hpp"
#include "path/kernel.hpp"  // svg_commands: how SVG data draws (subpaths, Z, dots)

#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace grape::detail {

void line_to(cairo_t* cr, Vec2 p) noexcept {
    if (!is_finite(p)) return;
    if (cairo_has_current_point(cr)) cairo_line_to(cr, p.x, p.y);
    else cairo_move_to(cr, p.x, p.y);
}

void stroke(cairo_t* cr, const StrokeStyle& style) noexcept {
    cairo_save(cr);
    // The path is already in device space; stroking under identity keeps widths in output units.
    cairo_identity_matrix(cr);
    cairo_set_source_rgba(cr, style.color.r, style.color.g, style.color.b, style.color.a);
    cairo_set_line_width(cr, std::isfinite(style.width) && style.width > 0.0 ? style.width : 1.0);
    cairo_set_line_cap(cr, style.cap == LineCap::butt    ? CAIRO_LINE_CAP_BUTT
                           : style.cap == LineCap::round ? CAIRO_LINE_CAP_ROUND
                                                         : CAIRO_LINE_CAP_SQUARE);
    cairo_set_line_join(cr, style.join == LineJoin::miter   ? CAIRO_LINE_JOIN_MITER
                            : style.join == LineJoin::round ? CAIRO_LINE_JOIN_ROUND
                                                            : CAIRO_LINE_JOIN_BEVEL);
    cairo_set_miter_limit(cr, std::isfinite(style.miter_limit) && style.miter_limit >= 1.0 ? style.miter_limit : 4.0);
    bool dashes_ok = !style.dashes.empty();
    double total = 0.0;
    for (double d : style.dashes) {
        dashes_ok = dashes_ok && std::isfinite(d) && d >= 0.0;
        total += d;
    }
    if (dashes_ok && total > 0.0) cairo_set_dash(cr, style.dashes.data(), static_cast<int>(style.dashes.size()), 0.0);
    cairo_stroke(cr);
    cairo_restore(cr);
}

void fill(cairo_t* cr, const FillStyle& style) noexcept {
    cairo_set_source_rgba(cr, style.color.r, style.color.g, style.color.b, style.color.a);
    cairo_set_fill_rule(cr, style.rule == FillRule::even_odd ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
    cairo_fill(cr);
}

namespace {

// Starts a piece at p: continues the current subpath when it ends there, else moves.
void begin_at(cairo_t* cr, Vec2 p, double tolerance) {
    if (cairo_has_current_point(cr)) {
        double x = 0.0, y = 0.0;
        cairo_get_current_point(cr, &x, &y);
        if (distance({x, y}, p) <= tolerance) {
            cairo_line_to(cr, p.x, p.y);
            return;
        }
    }
    cairo_move_to(cr, p.x, p.y);
}

void curve_to(cairo_t* cr, Vec2 b1, Vec2 b2, Vec2 b3) { cairo_curve_to(cr, b1.x, b1.y, b2.x, b2.y, b3.x, b3.y); }

void add_flattened(cairo_t* cr, const Path& path, double tolerance) {
    const std::vector<Vec2> points = path.flatten(tolerance);
    if (points.empty()) return;
    begin_at(cr, points.front(), tolerance);
    for (std::size_t i = 1; i < points.size(); ++i) line_to(cr, points[i]);
}

// The cubic through path points at local s = 0, ⅓, ⅔, 1 of [u0, u1], as a Bézier:
// with A = 27·P(⅓) − 8·B0 − B3 = 12·B1 + 6·B2 and C = 27·P(⅔) − B0 − 8·B3 = 6·B1 + 12·B2.
void add_cubic_piece(cairo_t* cr, const Path& path, double u0, double u1) {
    const Vec2 b0 = path.point(u0);
    const Vec2 b3 = path.point(u1);
    const Vec2 p1 = path.point(u0 + (u1 - u0) / 3.0);
    const Vec2 p2 = path.point(u0 + 2.0 * (u1 - u0) / 3.0);
    const Vec2 a = 27.0 * p1 - 8.0 * b0 - b3;
    const Vec2 c = 27.0 * p2 - b0 - 8.0 * b3;
    curve_to(cr, (2.0 * a - c) / 18.0, (2.0 * c - a) / 18.0, b3);
}

// An arc of device radius beyond huge_arc_radius: cairo splits arcs into Béziers by angle,
// more the larger the radius (150 at 1e12 px, 3220 at 1e20, and tens of seconds at 1e50),
// though almost all of such an arc lies far outside the picture. Here it is divided by
// angle only where it comes near the picture: a piece is a straight chord once it bulges
// from it by at most the tolerance, or once its box (the chord's, grown by that bulge)
// misses the picture, so the work grows with the depth of the division (≤ 64), not with
// the radius. The points are device coordinates: x = c + A·cos θ + B·sin θ.
constexpr double huge_arc_radius = 1e6;

struct HugeArc {
    cairo_t* cr;
    Vec2 c, a, b;
    double radius, tolerance;
    Rect view;  // device units, grown by a margin for strokes
    Vec2 at(double theta) const noexcept { return c + a * std::cos(theta) + b * std::sin(theta); }
    void piece(double t0, Vec2 p0, double t1, Vec2 p1, int depth) const noexcept {
        const double half = 0.5 * (t1 - t0);
        // How far the arc strays from its chord: R·(1 − cos(Δθ/2)), or its whole size past a half turn.
        const double s = std::sin(0.5 * half);  // 1 − cos(Δθ/2) = 2 sin²(Δθ/4), without cancellation
        const double bulge = half >= 0.5 * pi ? 2.0 * radius : 2.0 * radius * s * s;
        const bool away = std::max(p0.x, p1.x) + bulge < view.x || std::min(p0.x, p1.x) - bulge > view.x + view.width ||
                          std::max(p0.y, p1.y) + bulge < view.y || std::min(p0.y, p1.y) - bulge > view.y + view.height;
        if (bulge <= tolerance || away || depth >= 64) {
            cairo_line_to(cr, p1.x, p1.y);
            return;
        }
        const double tm = t0 + half;
        const Vec2 pm = at(tm);
        piece(t0, p0, tm, pm, depth + 1);
        piece(tm, pm, t1, p1, depth + 1);
    }
};

// Draws the arc c + N·(cos θ, sin θ), θ in [0, ω] (world units) as HugeArc when its device
// radius is beyond huge_arc_radius; false otherwise.
bool add_huge_arc(cairo_t* cr, Vec2 center, Vec2 col0, Vec2 col1, double omega, double tolerance) {
    cairo_matrix_t m;
    cairo_get_matrix(cr, &m);
    const auto linear = [&](Vec2 v) { return Vec2{m.xx * v.x + m.xy * v.y, m.yx * v.x + m.yy * v.y}; };
    const Vec2 a = linear(col0), b = linear(col1);
    // A bound on the semi-major axis on the picture (the largest singular value of [a b]):
    // the Frobenius norm, by hypot so that no square overflows.
    const double radius = std::hypot(std::hypot(a.x, a.y), std::hypot(b.x, b.y));
    if (!(radius > huge_arc_radius) || !std::isfinite(radius)) return false;
    const double stretch = std::sqrt(0.5 * (m.xx * m.xx + m.xy * m.xy + m.yx * m.yx + m.yy * m.yy) +
                                     std::hypot(0.5 * (m.xx * m.xx + m.yx * m.yx - m.xy * m.xy - m.yy * m.yy),
                                                m.xx * m.xy + m.yx * m.yy));
    double x1 = 0.0, y1 = 0.0, x2 = 0.0, y2 = 0.0;
    cairo_save(cr);
    cairo_identity_matrix(cr);
    cairo_clip_extents(cr, &x1, &y1, &x2, &y2);
    constexpr double margin = 64.0;  // device units: wide strokes and their caps stay outside
    const HugeArc arc{cr, Vec2{m.xx * center.x + m.xy * center.y + m.x0, m.yx * center.x + m.yy * center.y + m.y0}, a, b,
                      radius, tolerance * stretch, {x1 - margin, y1 - margin, x2 - x1 + 2 * margin, y2 - y1 + 2 * margin}};
    arc.piece(0.0, arc.at(0.0), omega, arc.at(omega), 0);  // the caller began the subpath at x(0)
    cairo_restore(cr);
    return true;
}

// Circle and ellipse arcs: x = c + N·(cos ωu, sin ωu) for a 2×2 matrix N and ω > 0 (a
// clockwise sweep folds into N). Then d2 = −ω²·(x − c), so x(u) − x(0) = −(d2(u) − d2(0))/ω²
// gives ω, c = x(0) + d2(0)/ω², and N = [x(0) − c | d1(0)/ω]; cairo draws the unit arc
// through N exactly.
void add_arc(cairo_t* cr, const Path& path, double tolerance) {
    const Vec2 p0 = path.point(0.0);
    const Vec2 a0 = path.d2(0.0);
    double best = 0.0;
    double omega2 = 0.0;
    for (double u : {0.5, 0.3, 0.7, 0.1}) {  // one of these avoids a whole number of turns
        const Vec2 dx = path.point(u) - p0;
        if (length(dx) > best) {
            best = length(dx);
            omega2 = length(path.d2(u) - a0) / best;
        }
    }
    if (!(best > 0.0) || !(omega2 > 0.0) || !std::isfinite(omega2)) {
        add_flattened(cr, path, tolerance);
        return;
    }
    const double omega = std::sqrt(omega2);
    const Vec2 center = p0 + a0 / omega2;
    const Vec2 col0 = p0 - center;
    const Vec2 col1 = path.d1(0.0) / omega;
    if (!(std::abs(cross(col0, col1)) > 0.0)) {
        add_flattened(cr, path, tolerance);
        return;
    }
    begin_at(cr, p0, tolerance);
    if (add_huge_arc(cr, center, col0, col1, omega, tolerance)) return;
    cairo_matrix_t saved;
    cairo_get_matrix(cr, &saved);
    const cairo_matrix_t n{col0.x, col0.y, col1.x, col1.y, center.x, center.y};
    cairo_transform(cr, &n);
    cairo_arc(cr, 0.0, 0.0, 1.0, 0.0, omega);
    cairo_set_matrix(cr, &saved);
}

// SVG data command by command, as SVG draws it: each moveto starts a subpath, Z closes it
// (cairo then joins the last segment to the first instead of capping both ends), and a
// zero-length segment stays in, so cairo draws it as a dot under round caps.
void add_svg(cairo_t* cr, const std::vector<SvgSegment>& commands, double tolerance) {
    using Kind = SvgSegment::Kind;
    for (const SvgSegment& c : commands) {
        switch (c.kind) {
            case Kind::move: cairo_move_to(cr, c.p[0].x, c.p[0].y); break;
            case Kind::line:
                if (!c.closing) line_to(cr, c.p[1]);  // the close below draws the closing line
                break;
            case Kind::quadratic:  // degree elevation, as for QuadraticBezierPath
                if (!cairo_has_current_point(cr)) cairo_move_to(cr, c.p[0].x, c.p[0].y);
                curve_to(cr, c.p[0] + (2.0 / 3.0) * (c.p[1] - c.p[0]), c.p[2] + (2.0 / 3.0) * (c.p[1] - c.p[2]), c.p[2]);
                break;
            case Kind::cubic:
                if (!cairo_has_current_point(cr)) cairo_move_to(cr, c.p[0].x, c.p[0].y);
                curve_to(cr, c.p[1], c.p[2], c.p[3]);
                break;
            case Kind::arc: {
                // The same path the parser made of it, drawn exactly by add_arc (which falls
                // back to flattening for arcs too thin for cairo's matrices).
                std::optional<Path> arc;
                try {
                    if (c.rx == c.ry) arc = CirclePath(c.center, c.rx, c.start_angle + c.rotation, c.end_angle + c.rotation);
                    else arc = EllipticalArcPath(c.center, c.rx, c.ry, c.rotation, c.start_angle, c.end_angle);
                } catch (const Error&) {
                }
                if (arc) add_arc(cr, *arc, tolerance);
                else line_to(cr, c.p[1]);
                break;
            }
            case Kind::close: cairo_close_path(cr); break;
        }
    }
}

// A sine wave within `tolerance` (world units) of the drawn polyline, with work proportional
// to its length on the picture rather than to its number of waves: an amplitude within the
// tolerance is its axis; waves shorter than the tolerance (a band on the picture) are a
// zigzag between ±amplitude every `tolerance` along the axis, which every point of the wave
// is within a tolerance of (each step holds a whole wave) and which is within a wavelength
// of the wave. Returns false for the waves Path::flatten draws as they are.
bool add_dense_sine(cairo_t* cr, const Path& path, double tolerance) {
    const auto spec = path_cast<SineWaveSpec>(path);
    if (!spec) return false;
    const Vec2 axis = spec->end - spec->start;
    const double along = length(axis);
    const double amplitude = std::abs(spec->amplitude);
    const double wavelength = along / std::abs(spec->frequency);
    if (!(along > 0.0) || !std::isfinite(along)) return false;
    if (amplitude <= tolerance) {
        begin_at(cr, spec->start, tolerance);
        line_to(cr, spec->end);
        return true;
    }
    if (!(wavelength < tolerance)) return false;
    // Bounded in any case: 2²⁴ steps are 4e6 output units of axis at a quarter unit each.
    const double steps = std::min(std::ceil(along / tolerance), 16777216.0);
    const auto n = static_cast<long>(steps);
    const Vec2 normal = perpendicular(axis / along) * amplitude;
    begin_at(cr, path.point(0.0), tolerance);
    for (long i = 1; i < n; ++i) line_to(cr, spec->start + axis * (static_cast<double>(i) / steps) + (i % 2 ? normal : -normal));
    line_to(cr, path.point(1.0));
    return true;
}

// The segment count (points − 1) of a spline; 0 for other kinds.
std::size_t spline_segments(const PathSpec& spec) {
    return std::visit([](const auto& s) -> std::size_t {
        if constexpr (requires { s.points; }) return s.points.empty() ? 0 : s.points.size() - 1;
        else return 0;
    }, spec);
}

void add_path_range(cairo_t* cr, const Path& path, double tolerance) {
    if (const std::vector<SvgSegment>* commands = svg_commands(path)) {
        add_svg(cr, *commands, tolerance);
        return;
    }
    switch (path.kind()) {
        case PathKind::linear: {
            begin_at(cr, path.point(0.0), tolerance);
            line_to(cr, path.point(1.0));
            return;
        }
        case PathKind::circle:
        case PathKind::elliptical_arc: add_arc(cr, path, tolerance); return;
        case PathKind::sine_wave:
            if (add_dense_sine(cr, path, tolerance)) return;
            break;
        case PathKind::quadratic_bezier:
        case PathKind::physics:
        case PathKind::cubic_bezier: {
            // A cubic's inner controls are p0 + d1(0)/3 and p3 − d1(1)/3. A quadratic is the
            // same by degree elevation: controls p0 + ⅔(p1 − p0) and p2 + ⅔(p1 − p2), where
            // p1 − p0 = d1(0)/2 and p1 − p2 = −d1(1)/2.
            const Vec2 start = path.point(0.0);
            const Vec2 end = path.point(1.0);
            begin_at(cr, start, tolerance);
            curve_to(cr, start + path.d1(0.0) / 3.0, end - path.d1(1.0) / 3.0, end);
            return;
        }
        case PathKind::linear_spline:
        case PathKind::hermite_spline:
        case PathKind::catmull_rom_spline: {
            const std::size_t segments = spline_segments(describe(path));
            if (segments == 0) break;
            begin_at(cr, path.point(0.0), tolerance);
            for (std::size_t i = 0; i < segments; ++i) {
                const double u0 = static_cast<double>(i) / static_cast<double>(segments);
                const double u1 = static_cast<double>(i + 1) / static_cast<double>(segments);
                if (path.kind() == PathKind::linear_spline) line_to(cr, path.point(u1));
                else add_cubic_piece(cr, path, u0, u1);
            }
            return;
        }
        case PathKind::complex: {
            const auto view = path_cast<ComplexSpec>(path);
            if (!view) break;
            for (std::size_t i = 0; i < view->parts.size(); ++i) {
                const double end = i + 1 < view->cues.size() ? view->cues[i + 1] : 1.0;
                if (end <= view->cues[i]) continue;  // an empty span is skipped, as in evaluation
                add_path_range(cr, view->parts[i], tolerance);
            }
            return;
        }
        case PathKind::reparametrized: {
            // The same shape as its source, so the source's exact curves draw it.
            if (const auto reparametrized = path_cast<ReparametrizedSpec>(path)) {
                add_path_range(cr, reparametrized->source, tolerance);
                return;
            }
            break;
        }
        default: break;
    }
    add_flattened(cr, path, tolerance);
}

}  // namespace

void add_path(cairo_t* cr, const Path& path, double tolerance) {
    if (!std::isfinite(tolerance) || tolerance <= 0.0) tolerance = 0.25;
    add_path_range(cr, path, tolerance);
}

}  // namespace grape::detail

namespace grape {

namespace {

// Cue positions (in u of the whole) of a complex path and of complex paths nested in it.
void collect_cues(const Path& path, double u0, double u1, std::vector<double>& out) {
    if (path.kind() != PathKind::complex) return;
    const auto view = path_cast<ComplexSpec>(path);
    if (!view) return;
    for (std::size_t i = 0; i < view->parts.size(); ++i) {
        const double a = view->cues[i];
        const double b = i + 1 < view->cues.size() ? view->cues[i + 1] : 1.0;
        if (b <= a) continue;
        out.push_back(u0 + (u1 - u0) * a);
        collect_cues(view->parts[i], u0 + (u1 - u0) * a, u0 + (u1 - u0) * b, out);
    }
}

// Draws a segment given in output units, whatever the transform.
void device_line(Canvas& canvas, Vec2 a, Vec2 b, const StrokeStyle& style) {
    canvas.push();
    canvas.set_transform({});
    canvas.stroke_line(a, b, style);
    canvas.pop();
}

}  // namespace

void draw_path(Canvas& canvas, const Path& path, const PathStyle& style) {
    canvas.stroke_path(path, style.stroke);
    const Affine t = canvas.transform();
    const auto device_normal = [&](double u) {
        // The normal in output space, so ticks stay perpendicular under any transform.
        return normalized(perpendicular(t.apply_vector(path.d1(u))));
    };
    if (std::isfinite(style.ticks) && style.ticks > 0.0) {
        const StrokeStyle tick{.color = style.tick_color, .width = 1.0, .cap = LineCap::butt};
        const auto count = static_cast<long>(std::min(10000.0, std::floor(1.0 / style.ticks + 1e-9)));
        for (long i = 0; i <= count; ++i) {
            const double u = std::min(1.0, static_cast<double>(i) * style.ticks);
            const Vec2 p = t.apply(path.point(u));
            const Vec2 n = device_normal(u) * (0.5 * style.tick_length);
            device_line(canvas, p - n, p + n, tick);
        }
    }
    if (style.tangents > 0) {
        const StrokeStyle arrow{.color = style.tangent_color, .width = 1.5};
        const int n = std::min(style.tangents, 10000);
        for (int i = 0; i < n; ++i) {
            const double u = n == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(n - 1);
            const Vec2 p = t.apply(path.point(u));
            const Vec2 dir = normalized(t.apply_vector(path.d1(u)));
            if (dir == Vec2{}) continue;
            const Vec2 tip = p + dir * style.tangent_length;
            const Vec2 side = perpendicular(dir) * 4.0;
            device_line(canvas, p, tip, arrow);
            device_line(canvas, tip, tip - dir * 7.0 + side, arrow);
            device_line(canvas, tip, tip - dir * 7.0 - side, arrow);
        }
    }
    if (style.ends) {
        canvas.dot(path.point(1.0), 3.5, style.stroke.color);
        canvas.dot(path.point(0.0), 3.5, style.stroke.color);
        canvas.dot(path.point(0.0), 2.0, colors::white);
    }
    if (style.cues) {
        std::vector<double> cues;
        collect_cues(path, 0.0, 1.0, cues);
        // Cues that land on the same spot (nested parts often start together) share one label.
        std::vector<bool> done(cues.size(), false);
        for (std::size_t i = 0; i < cues.size(); ++i) {
            if (done[i]) continue;
            const Vec2 at = t.apply(path.point(cues[i]));
            std::string label;
            for (std::size_t k = i; k < cues.size(); ++k) {
                if (done[k] || distance(t.apply(path.point(cues[k])), at) > 3.0) continue;
                done[k] = true;
                char buffer[24];
                std::snprintf(buffer, sizeof buffer, "%s%.3g", label.empty() ? "" : ", ", cues[k]);
                label += buffer;
            }
            canvas.dot(path.point(cues[i]), 4.0, style.cue_color);
            canvas.text(path.point(cues[i]), "  " + label, {.color = style.cue_color, .size = 10.0});
        }
    }
}

void draw_plot(Canvas& canvas, const Rect& area, std::span<const PlotSeries> series, std::string_view title) {
    canvas.push();
    canvas.set_transform({});
    const double left = area.x + 58.0;
    const double right = area.x + area.width - 10.0;
    const double top = area.y + (title.empty() ? 10.0 : 26.0);
    const double bottom = area.y + area.height - 24.0;
    Bounds box;
    for (const PlotSeries& s : series) {
        const std::size_t n = std::min(s.x.size(), s.y.size());
        for (std::size_t i = 0; i < n; ++i)
            if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) box.add(Vec2{s.x[i], s.y[i]});
    }
    if (!title.empty()) canvas.text({area.x + 0.5 * area.width, area.y + 16.0}, title, {.size = 13.0, .align = TextAlign::center, .bold = true});
    const StrokeStyle axis{.color = colors::grey, .width = 1.0, .cap = LineCap::butt};
    canvas.stroke_line({left, top}, {left, bottom}, axis);
    canvas.stroke_line({left, bottom}, {right, bottom}, axis);
    if (!is_finite(box.min) || right <= left || bottom <= top) {
        canvas.pop();
        return;
    }
    // A flat series still gets a visible band instead of a division by zero.
    if (!(box.max.y - box.min.y > 1e-300)) {
        const double pad = std::max(1e-12, std::abs(box.min.y) * 1e-6);
        box.min.y -= pad;
        box.max.y += pad;
    }
    if (!(box.max.x - box.min.x > 0.0)) box.max.x = box.min.x + 1.0;
    const auto map = [&](double x, double y) {
        return Vec2{left + (x - box.min.x) / (box.max.x - box.min.x) * (right - left),
                    bottom - (y - box.min.y) / (box.max.y - box.min.y) * (bottom - top)};
    };
    const auto label = [](double v) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.4g", v);
        return std::string(buffer);
    };
    const TextStyle small{.color = colors::grey, .size = 10.0, .align = TextAlign::right};
    canvas.text({left - 4.0, top + 8.0}, label(box.max.y), small);
    canvas.text({left - 4.0, bottom}, label(box.min.y), small);
    canvas.text({left, bottom + 14.0}, label(box.min.x), {.color = colors::grey, .size = 10.0});
    canvas.text({right, bottom + 14.0}, label(box.max.x), small);
    double legend_y = top + 12.0;
    for (const PlotSeries& s : series) {
        std::vector<Vec2> points;
        const std::size_t n = std::min(s.x.size(), s.y.size());
        points.reserve(n);
        for (std::size_t i = 0; i < n; ++i)
            if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) points.push_back(map(s.x[i], s.y[i]));
        canvas.stroke_polyline(points, s.stroke);
        if (!s.label.empty()) {
            canvas.stroke_line({right - 190.0, legend_y - 4.0}, {right - 170.0, legend_y - 4.0}, s.stroke);
            canvas.text({right - 164.0, legend_y}, s.label, {.color = s.stroke.color, .size = 11.0});
            legend_y += 15.0;
        }
    }
    canvas.pop();
}

}  // namespace grape
