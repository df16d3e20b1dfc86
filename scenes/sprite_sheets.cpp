// The grape sprite: one drawing, cut into the tile sheet and the packed (trimmed) sheet.
#include "sprite_sheets.hpp"

#include <grape/error.hpp>

#ifdef GRAPE_SCENES_SHEET_JSON
#include <grape/sprite_sheet_json.hpp>
#endif

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace grape::scenes {

namespace {

constexpr int unit = 48;  // the drawing's own square, pixels

void check(int k, int frames, int size, const char* who) {
    if (frames < 1 || frames > 64)
        throw Error(std::string(who) + ": frames must be in [1, 64] (got " + std::to_string(frames) + ")");
    if (k < 0 || k >= frames)
        throw Error(std::string(who) + ": frame " + std::to_string(k) + " is not in [0, " + std::to_string(frames) + ")");
    if (size < 8 || size > 1024)
        throw Error(std::string(who) + ": size must be in [8, 1024] pixels (got " + std::to_string(size) + ")");
}

// Frame k of `frames` in the 48-unit square under the canvas's current transform.
void draw_grape(Canvas& canvas, int k, int frames) {
    const int half = std::max(1, frames / 2);  // the body bounces twice per cycle
    const double phase = (k % half) / static_cast<double>(half);
    const double lift = 14.0 * std::sin(pi * phase);
    const Vec2 body{24.0, 34.0 - lift};
    canvas.fill_circle(body, 9.0, {.color = {0.45, 0.20, 0.55}});
    const double a = 2.0 * pi * k / frames;
    canvas.stroke_line(body, body + Vec2{8.0 * std::cos(a), 8.0 * std::sin(a)}, {.color = {1.0, 0.85, 0.2}, .width = 2.0});
    canvas.fill_circle(body + Vec2{5.0, -10.0}, 3.0, {.color = {0.2, 0.6, 0.25}});  // leaf
    const double step = std::min(4.0, 44.0 / frames);                               // k + 1 dots fit the width
    for (int d = 0; d <= k; ++d) canvas.fill_rect({4.0 + step * d, 2.0, 2.0, 2.0}, {.color = {0.1, 0.1, 0.1}});
}

}  // namespace

Image grape_sprite_frame(int k, int frames, int size) {
    check(k, frames, size, "grape_sprite_frame");
    Canvas canvas(size, size, colors::transparent);
    if (size != unit) canvas.set_transform(Affine::scaling(size / double(unit), size / double(unit)));
    draw_grape(canvas, k, frames);
    return canvas.to_image();
}

DrawnSheet grape_tile_sheet(int frames, int columns, int size) {
    check(0, frames, size, "grape_tile_sheet");
    if (columns < 1 || columns > frames)
        throw Error("grape_tile_sheet: columns must be in [1, frames] (got " + std::to_string(columns) + ")");
    const int rows = (frames + columns - 1) / columns;
    Canvas canvas(columns * size, rows * size, colors::transparent);
    SpriteSheetDef def{.image = "grape_tile_sheet", .width = columns * size, .height = rows * size};
    const double s = size / double(unit);
    for (int k = 0; k < frames; ++k) {
        const int x = (k % columns) * size, y = (k / columns) * size;
        canvas.set_transform(Affine::translation({double(x), double(y)}) * Affine::scaling(s, s));
        canvas.fill_rect({1, 1, unit - 2.0, unit - 2.0}, {.color = {0.93, 0.95, 0.98}});
        draw_grape(canvas, k, frames);
        def.frames.push_back({.name = "grape " + std::to_string(k), .rect = {x, y, size, size}});
    }
    return {canvas.to_image(), SpriteSheet(std::move(def))};
}

#ifdef GRAPE_SCENES_SHEET_JSON
DrawnSheet grape_packed_sheet() {
    constexpr int frame_count = 8;
    constexpr int spacing = 1;
    constexpr double durations_ms[frame_count] = {100, 150, 50, 200, 80, 120, 60, 240};
    std::vector<Image> frames;
    std::vector<FrameRect> trims;  // drawn pixels in each frame's own image
    int width = 0, height = 0;
    for (int k = 0; k < frame_count; ++k) {
        frames.push_back(grape_sprite_frame(k, frame_count, unit));
        const Image& f = frames.back();
        int x0 = unit, y0 = unit, x1 = -1, y1 = -1;
        for (int y = 0; y < unit; ++y) {
            for (int x = 0; x < unit; ++x) {
                if (f.argb()[std::size_t(y) * unit + std::size_t(x)] >> 24 == 0) continue;
                x0 = std::min(x0, x);
                y0 = std::min(y0, y);
                x1 = std::max(x1, x);
                y1 = std::max(y1, y);
            }
        }
        trims.push_back({x0, y0, x1 - x0 + 1, y1 - y0 + 1});
        width += trims.back().width + (k > 0 ? spacing : 0);
        height = std::max(height, trims.back().height);
    }
    Image sheet(width, height);
    SpriteSheetDef def{.image = "grape_sheet.png", .width = width, .height = height};
    int x = 0;
    for (int k = 0; k < frame_count; ++k) {
        const FrameRect& t = trims[std::size_t(k)];
        for (int y = 0; y < t.height; ++y) {
            for (int i = 0; i < t.width; ++i) {  // premultiplied words copied as they are: exact
                sheet.argb()[std::size_t(y) * std::size_t(width) + std::size_t(x + i)] =
                    frames[std::size_t(k)].argb()[std::size_t(t.y + y) * unit + std::size_t(t.x + i)];
            }
        }
        def.frames.push_back({.name = "grape " + std::to_string(k) + ".aseprite",
                              .rect = {x, 0, t.width, t.height},
                              .offset_x = t.x,
                              .offset_y = t.y,
                              .source_width = unit,
                              .source_height = unit,
                              .duration_ms = durations_ms[k]});
        x += t.width + spacing;
    }
    def.clips = {{.name = "bounce", .from = 0, .to = 3, .direction = ClipDirection::forward},
                 {.name = "rewind", .from = 4, .to = 7, .direction = ClipDirection::reverse},
                 {.name = "hop", .from = 0, .to = 3, .direction = ClipDirection::ping_pong, .repeat = 3},
                 {.name = "sway", .from = 4, .to = 7, .direction = ClipDirection::ping_pong_reverse},
                 {.name = "turn", .from = 0, .to = 7, .direction = ClipDirection::forward, .repeat = 2},
                 {.name = "flip", .from = 2, .to = 5, .direction = ClipDirection::ping_pong_reverse, .repeat = 4},
                 {.name = "still", .from = 6, .to = 6}};
    def.slices = {{.name = "feet", .keys = {{.frame = 0, .bounds = {16, 40, 16, 8}, .has_pivot = true, .pivot = {8, 4}},
                                             {.frame = 4, .bounds = {14, 40, 20, 8}, .has_pivot = true, .pivot = {10, 4}}}},
                  {.name = "hit", .keys = {{.frame = 0, .bounds = {14, 10, 20, 34}}}}};
    // Through the JSON and back, so the frames carry the pivots the loader derives from slices.
    const SpriteSheet built(std::move(def));
    return {std::move(sheet), load_sprite_sheet(save_sprite_sheet(built, SheetJsonLayout::hash))};
}
#endif

}  // namespace grape::scenes
