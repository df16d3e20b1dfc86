// Debug drawings of particles, constraint curves and tile-sheet sprites.
#include <grape/render.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace grape {

void draw_particles(Canvas& canvas, std::span<const Vec2> positions, std::span<const Vec2> velocities,
                    std::span<const double> inverse_masses, const ParticleStyle& style) {
    const bool with_v = velocities.size() == positions.size() && style.velocity_scale > 0.0;
    const bool with_m = inverse_masses.size() == positions.size();
    for (std::size_t i = 0; i < positions.size(); ++i) {
        if (with_v) {
            canvas.stroke_line(positions[i], positions[i] + velocities[i] * style.velocity_scale,
                               {.color = style.velocity_color, .width = 1.5});
        }
        const bool pinned = with_m && inverse_masses[i] == 0.0;
        canvas.dot(positions[i], style.radius, pinned ? style.pinned_color : style.color);
    }
}

void draw_implicit_curve(Canvas& canvas, const std::function<double(Vec2)>& c, const Bounds& region,
                         const StrokeStyle& style, int cells) {
    if (!c || !is_finite(region.min) || !is_finite(region.max)) return;
    const int n = std::clamp(cells, 2, 2000);
    const Vec2 size = region.size();
    if (!(size.x > 0.0 && size.y > 0.0)) return;
    const Vec2 step{size.x / n, size.y / n};
    std::vector<double> row0(static_cast<std::size_t>(n) + 1), row1(row0.size());
    const auto sample = [&](int i, int j) { return c(region.min + Vec2{i * step.x, j * step.y}); };
    for (int i = 0; i <= n; ++i) row0[static_cast<std::size_t>(i)] = sample(i, 0);
    // Corners in order: (i, j), (i+1, j), (i+1, j+1), (i, j+1); an edge is crossed where the
    // sign changes, at the linear interpolation of C along it.
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i <= n; ++i) row1[static_cast<std::size_t>(i)] = sample(i, j + 1);
        for (int i = 0; i < n; ++i) {
            const std::array<double, 4> v{row0[static_cast<std::size_t>(i)], row0[static_cast<std::size_t>(i) + 1],
                                          row1[static_cast<std::size_t>(i) + 1], row1[static_cast<std::size_t>(i)]};
            const std::array<Vec2, 4> p{region.min + Vec2{i * step.x, j * step.y},
                                        region.min + Vec2{(i + 1) * step.x, j * step.y},
                                        region.min + Vec2{(i + 1) * step.x, (j + 1) * step.y},
                                        region.min + Vec2{i * step.x, (j + 1) * step.y}};
            std::array<Vec2, 4> hits;
            int count = 0;
            for (int e = 0; e < 4; ++e) {
                const double a = v[static_cast<std::size_t>(e)];
                const double b = v[static_cast<std::size_t>((e + 1) % 4)];
                if (!std::isfinite(a) || !std::isfinite(b)) continue;
                if ((a < 0.0) != (b < 0.0)) {
                    const double t = a / (a - b);
                    hits[static_cast<std::size_t>(count++)] =
                        lerp(p[static_cast<std::size_t>(e)], p[static_cast<std::size_t>((e + 1) % 4)], t);
                }
            }
            if (count >= 2) canvas.stroke_line(hits[0], hits[1], style);
            if (count == 4) canvas.stroke_line(hits[2], hits[3], style);
        }
        std::swap(row0, row1);
    }
}

void draw_sprite(Canvas& canvas, const Image& sheet_image, const TileSheetSprite& sprite, Vec2 at, double scale,
                 bool debug) {
    const FrameRect& r = sprite.rect();
    const Rect target{at.x, at.y, r.width * scale, r.height * scale};
    canvas.draw_image(sheet_image, {static_cast<double>(r.x), static_cast<double>(r.y), static_cast<double>(r.width),
                                    static_cast<double>(r.height)},
                      target);
    if (debug) {
        canvas.stroke_rect(target, {.color = colors::red, .width = 1.0, .dashes = {4.0, 3.0}});
        canvas.text(at + Vec2{0.0, target.height}, "frame " + std::to_string(sprite.current_frame()),
                    {.color = colors::red, .size = 10.0});
    }
}

void draw_tile_sheet(Canvas& canvas, const Image& sheet_image, const TileSheetSprite& sprite, Vec2 at, double scale) {
    const double w = sheet_image.width();
    const double h = sheet_image.height();
    canvas.draw_image(sheet_image, {0.0, 0.0, w, h}, {at.x, at.y, w * scale, h * scale});
    const TileSheet& sheet = sprite.sheet();
    for (std::size_t k = 0; k < sheet.frame_count(); ++k) {
        const FrameRect& r = sheet.frame(k);
        const Rect box{at.x + r.x * scale, at.y + r.y * scale, r.width * scale, r.height * scale};
        const bool current = k == sprite.current_frame();
        canvas.stroke_rect(box, {.color = current ? colors::red : colors::grey, .width = current ? 2.0 : 1.0});
        canvas.text({box.x + 2.0 * scale, box.y + box.height - 2.0 * scale}, std::to_string(k),
                    {.color = current ? colors::red : colors::grey, .size = 9.0});
    }
}

}  // namespace grape
