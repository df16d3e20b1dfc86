// Tests for grape::draw_sprite_frame: grape's own sheet drawn frame by frame lands each trimmed
// pixel at pivot-relative offset + position exactly (nearest-neighbour at one pixel per unit
// copies the premultiplied words unchanged), and a rotated frame draws the same picture as its
// upright original.
#include <grape/render.hpp>
#include <grape/sprite_sheet_json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

const std::string data = GRAPE_SPRITE_DATA;

std::uint32_t at(const grape::Image& image, int x, int y) {
    return image.argb()[std::size_t(y) * std::size_t(image.width()) + std::size_t(x)];
}

int opaque(const grape::Image& image) {
    int n = 0;
    for (std::uint32_t w : image.argb()) n += (w >> 24) != 0;
    return n;
}

TEST(DrawSpriteFrame, TrimmedPixelsLandAtTheirOffsetAroundThePivot) {
    const std::string json = data + "/grape_sheet.json";
    const grape::SpriteSheet sheet = grape::load_sprite_sheet_file(json);
    const grape::Image picture = grape::Image::load_png(grape::sprite_sheet_image_path(sheet, json));
    const grape::Vec2 where{50, 60};
    for (std::size_t k = 0; k < sheet.frame_count(); ++k) {
        const grape::SpriteFrame& f = sheet.frame(k);
        grape::Canvas canvas(120, 120, grape::colors::transparent);
        grape::draw_sprite_frame(canvas, picture, f, where);
        const grape::Image out = canvas.to_image();
        int expected = 0;
        for (int y = 0; y < f.rect.height; ++y) {
            for (int x = 0; x < f.rect.width; ++x) {
                const std::uint32_t source = at(picture, f.rect.x + x, f.rect.y + y);
                expected += (source >> 24) != 0;
                const int ox = static_cast<int>(where.x - f.pivot.x) + f.offset_x + x;
                const int oy = static_cast<int>(where.y - f.pivot.y) + f.offset_y + y;
                ASSERT_EQ(at(out, ox, oy), source) << "frame " << k << " pixel " << x << ", " << y;
            }
        }
        EXPECT_EQ(opaque(out), expected) << "frame " << k << ": nothing drawn outside its rectangle";
        EXPECT_GT(expected, 100);
    }
}

TEST(DrawSpriteFrame, RotatedFramesDrawUpright) {
    const std::string json = data + "/grape_sheet.json";
    const grape::SpriteSheet sheet = grape::load_sprite_sheet_file(json);
    const grape::Image picture = grape::Image::load_png(grape::sprite_sheet_image_path(sheet, json));
    const grape::SpriteFrame& f = sheet.frame(3);
    // The same pixels stored turned 90° clockwise (upright (x, y) at (h − 1 − y, x)), as
    // TexturePacker packs a rotated sprite.
    const int w = f.rect.width, h = f.rect.height;
    grape::Image turned(h, w);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) turned.argb()[std::size_t(x) * std::size_t(h) + std::size_t(h - 1 - y)] = at(picture, f.rect.x + x, f.rect.y + y);
    }
    grape::SpriteFrame rotated = f;
    rotated.rect = {0, 0, h, w};
    rotated.rotated = true;
    EXPECT_EQ(rotated.width(), f.width());
    grape::Canvas a(100, 100, grape::colors::transparent), b(100, 100, grape::colors::transparent);
    grape::draw_sprite_frame(a, picture, f, {40, 50});
    grape::draw_sprite_frame(b, turned, rotated, {40, 50});
    const grape::Image ia = a.to_image(), ib = b.to_image();
    ASSERT_GT(opaque(ia), 100);
    for (std::size_t i = 0; i < ia.argb().size(); ++i) ASSERT_EQ(ia.argb()[i], ib.argb()[i]) << "pixel " << i;
    // Scale 2: the frame covers four times the pixels.
    grape::Canvas c(200, 200, grape::colors::transparent);
    grape::draw_sprite_frame(c, turned, rotated, {100, 100}, 2.0);
    EXPECT_EQ(opaque(c.to_image()), 4 * opaque(ia));
}

}  // namespace
