// Draws grape's own test and demo sprite sheet with cairo and writes it as Aseprite would
// export it with trimming on: grape_sheet.png, grape_sheet.json (hash layout) and
// grape_sheet_array.json (array layout). No third-party art.
//
//   make_sprite_sheet OUT_DIR            writes the three files
//   make_sprite_sheet --check DIR        exits 1 unless DIR's files equal what it would write
//
// Eight 48×48 frames of a bouncing, turning grape, each trimmed to its drawn pixels and packed
// in a row; uneven durations; tags of every direction, with and without repeat counts; a slice
// with a pivot at the grape's feet and a hit box without one.
#include <grape/error.hpp>
#include <grape/render.hpp>
#include <grape/sprite_sheet_json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr int frame_count = 8;
constexpr int source_size = 48;
constexpr int spacing = 1;
constexpr double durations_ms[frame_count] = {100, 150, 50, 200, 80, 120, 60, 240};

// Frame k upright in its untrimmed 48×48 image: the body rises and falls over frames 0–3 and
// 4–7, a spoke turns once over the eight, and k + 1 dots along the top count the frame.
grape::Image draw_frame(int k) {
    grape::Canvas canvas(source_size, source_size, grape::colors::transparent);
    const double pi = 3.14159265358979323846;
    const double phase = (k % 4) / 4.0;
    const double lift = 14.0 * std::sin(pi * phase);
    const grape::Vec2 centre{24.0, 34.0 - lift};
    canvas.fill_circle(centre, 9.0, {.color = {0.45, 0.20, 0.55}});
    const double a = 2.0 * pi * k / frame_count;
    canvas.stroke_line(centre, centre + grape::Vec2{8.0 * std::cos(a), 8.0 * std::sin(a)},
                       {.color = {1.0, 0.85, 0.2}, .width = 2.0});
    canvas.fill_circle(centre + grape::Vec2{5.0, -10.0}, 3.0, {.color = {0.2, 0.6, 0.25}});  // leaf
    for (int d = 0; d <= k; ++d) canvas.fill_rect({4.0 + 4.0 * d, 2.0, 2.0, 2.0}, {.color = {0.1, 0.1, 0.1}});
    return canvas.to_image();
}

struct Drawn {
    grape::Image sheet;
    grape::SpriteSheet data;
};

Drawn draw_sheet() {
    std::vector<grape::Image> frames;
    std::vector<grape::FrameRect> trims;  // drawn pixels in each frame's own image
    int width = 0, height = 0;
    for (int k = 0; k < frame_count; ++k) {
        frames.push_back(draw_frame(k));
        const grape::Image& f = frames.back();
        int x0 = source_size, y0 = source_size, x1 = -1, y1 = -1;
        for (int y = 0; y < source_size; ++y) {
            for (int x = 0; x < source_size; ++x) {
                if (f.argb()[std::size_t(y) * source_size + std::size_t(x)] >> 24 == 0) continue;
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
    grape::Image sheet(width, height);
    grape::SpriteSheetDef def{.image = "grape_sheet.png", .width = width, .height = height};
    int x = 0;
    for (int k = 0; k < frame_count; ++k) {
        const grape::FrameRect& t = trims[std::size_t(k)];
        for (int y = 0; y < t.height; ++y) {
            for (int i = 0; i < t.width; ++i) {  // premultiplied words copied as they are: exact
                sheet.argb()[std::size_t(y) * std::size_t(width) + std::size_t(x + i)] =
                    frames[std::size_t(k)].argb()[std::size_t(t.y + y) * source_size + std::size_t(t.x + i)];
            }
        }
        def.frames.push_back({.name = "grape " + std::to_string(k) + ".aseprite",
                              .rect = {x, 0, t.width, t.height},
                              .offset_x = t.x,
                              .offset_y = t.y,
                              .source_width = source_size,
                              .source_height = source_size,
                              .duration_ms = durations_ms[k]});
        x += t.width + spacing;
    }
    using grape::ClipDirection;
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
    const grape::SpriteSheet built(std::move(def));
    return {std::move(sheet), grape::load_sprite_sheet(grape::save_sprite_sheet(built, grape::SheetJsonLayout::hash))};
}

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const bool check = argc == 3 && std::string(argv[1]) == "--check";
        if (argc != 2 && !check) {
            std::fprintf(stderr, "usage: make_sprite_sheet OUT_DIR | make_sprite_sheet --check DIR\n");
            return 2;
        }
        const std::filesystem::path dir = argv[argc - 1];
        const Drawn drawn = draw_sheet();
        const std::string hash = grape::save_sprite_sheet(drawn.data, grape::SheetJsonLayout::hash);
        const std::string array = grape::save_sprite_sheet(drawn.data, grape::SheetJsonLayout::array);
        if (!check) {
            drawn.sheet.write_png(dir / "grape_sheet.png");
            std::ofstream(dir / "grape_sheet.json", std::ios::binary) << hash;
            std::ofstream(dir / "grape_sheet_array.json", std::ios::binary) << array;
            std::printf("wrote %s/grape_sheet.png, grape_sheet.json, grape_sheet_array.json\n", dir.string().c_str());
            return 0;
        }
        const grape::Image png = grape::Image::load_png(dir / "grape_sheet.png");
        const bool same_png = png.width() == drawn.sheet.width() && png.height() == drawn.sheet.height() &&
                              std::equal(png.argb().begin(), png.argb().end(), drawn.sheet.argb().begin());
        const bool same_hash = read_text(dir / "grape_sheet.json") == hash;
        const bool same_array = read_text(dir / "grape_sheet_array.json") == array;
        std::printf("png %s, hash json %s, array json %s\n", same_png ? "same" : "DIFFERS", same_hash ? "same" : "DIFFERS",
                    same_array ? "same" : "DIFFERS");
        return same_png && same_hash && same_array ? 0 : 1;
    } catch (const grape::Error& e) {
        std::fprintf(stderr, "make_sprite_sheet: %s\n", e.what());
        return 2;
    }
}
