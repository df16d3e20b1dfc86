// The grape sprite sheets of the catalogue (scenes/sprite_sheets.hpp): one drawing cut two ways.
// The packed sheet holds each frame's drawn pixels word for word at its rect, the tile sheet
// holds each frame's opaque pixels in its tile, and every frame lies on its picture.
#include "catalogue.hpp"
#include "sprite_sheets.hpp"

#include <grape/error.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

namespace {

using namespace grape;

std::uint32_t word(const Image& image, int x, int y) {
    return image.argb()[static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width()) + static_cast<std::size_t>(x)];
}

TEST(SpriteSheets, EveryFrameLiesOnItsPictureAndShowsSomething) {
    for (const scenes::Entry* e : scenes::entries_of(scenes::Category::sprite_sheet)) {
        const scenes::DrawnSheet drawn = e->sheet();
        EXPECT_EQ(drawn.sheet.width(), drawn.image.width()) << e->name;
        EXPECT_EQ(drawn.sheet.height(), drawn.image.height()) << e->name;
        for (const SpriteFrame& f : drawn.sheet.frames()) {
            ASSERT_TRUE(f.rect.x >= 0 && f.rect.y >= 0 && f.rect.x + f.rect.width <= drawn.image.width() &&
                        f.rect.y + f.rect.height <= drawn.image.height())
                << e->name << " " << f.name;
            int opaque = 0;
            for (int y = f.rect.y; y < f.rect.y + f.rect.height; ++y)
                for (int x = f.rect.x; x < f.rect.x + f.rect.width; ++x) opaque += word(drawn.image, x, y) >> 24 == 255;
            EXPECT_GT(opaque, 50) << e->name << " " << f.name;  // the body alone is ~250 pixels at 48 px
        }
    }
}

TEST(SpriteSheets, FramesDifferFromEachOther) {
    for (int k = 1; k < 8; ++k) {
        const Image a = scenes::grape_sprite_frame(k - 1), b = scenes::grape_sprite_frame(k);
        EXPECT_FALSE(std::equal(a.argb().begin(), a.argb().end(), b.argb().begin())) << k;
    }
}

TEST(SpriteSheets, TheTileSheetHoldsEachFramesOpaquePixelsInItsTile) {
    const int frames = 6, columns = 4, size = 40;
    const scenes::DrawnSheet tiles = scenes::grape_tile_sheet(frames, columns, size);
    EXPECT_EQ(tiles.image.width(), columns * size);
    EXPECT_EQ(tiles.image.height(), 2 * size);
    ASSERT_EQ(tiles.sheet.frame_count(), std::size_t(frames));
    for (int k = 0; k < frames; ++k) {
        const Image frame = scenes::grape_sprite_frame(k, frames, size);
        const FrameRect& r = tiles.sheet.frame(std::size_t(k)).rect;
        EXPECT_EQ(r.x, (k % columns) * size);
        EXPECT_EQ(r.y, (k / columns) * size);
        int compared = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                if (word(frame, x, y) >> 24 != 255) continue;  // an opaque pixel covers the tile's background
                EXPECT_EQ(word(tiles.image, r.x + x, r.y + y), word(frame, x, y)) << k << " " << x << "," << y;
                ++compared;
            }
        EXPECT_GT(compared, 50) << k;
    }
}

#ifdef GRAPE_SCENES_SHEET_JSON
TEST(SpriteSheets, ThePackedSheetHoldsEachFramesDrawnPixelsWordForWord) {
    const scenes::DrawnSheet packed = scenes::grape_packed_sheet();
    ASSERT_EQ(packed.sheet.frame_count(), 8u);
    for (int k = 0; k < 8; ++k) {
        const Image frame = scenes::grape_sprite_frame(k);
        const SpriteFrame& f = packed.sheet.frame(std::size_t(k));
        EXPECT_EQ(f.source_width, 48);
        int drawn = 0;
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 48; ++x) {
                const bool inside = x >= f.offset_x && x < f.offset_x + f.rect.width && y >= f.offset_y &&
                                    y < f.offset_y + f.rect.height;
                if (!inside) {
                    EXPECT_EQ(word(frame, x, y) >> 24, 0u) << k << ": the trim cut a drawn pixel at " << x << "," << y;
                    continue;
                }
                EXPECT_EQ(word(packed.image, f.rect.x + x - f.offset_x, f.rect.y + y - f.offset_y), word(frame, x, y));
                drawn += word(frame, x, y) >> 24 != 0;
            }
        EXPECT_GT(drawn, 0) << k;
    }
    EXPECT_EQ(packed.sheet.clips().size(), 7u);
}
#endif

TEST(SpriteSheets, BadArgumentsAreRefusedByName) {
    EXPECT_THROW((void)scenes::grape_sprite_frame(8, 8, 48), Error);
    EXPECT_THROW((void)scenes::grape_sprite_frame(0, 0, 48), Error);
    EXPECT_THROW((void)scenes::grape_sprite_frame(0, 8, 4), Error);
    EXPECT_THROW((void)scenes::grape_tile_sheet(8, 9, 32), Error);
    try {
        (void)scenes::grape_tile_sheet(8, 0, 32);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("columns"), std::string::npos) << e.what();
    }
}

}  // namespace
