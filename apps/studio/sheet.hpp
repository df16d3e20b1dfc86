// A sprite sheet drawn at start-up with cairo (no image files to ship): a ball that bounces,
// squashes and spins, with the frame number written on each frame so the player's frame
// choice is visible.
#pragma once

#include <cstdint>
#include <vector>

namespace grape::studio {

/// Pixels in native-endian 0xAARRGGBB words (cairo ARGB32, premultiplied; SDL ARGB8888).
struct SheetImage {
    int width = 0;            ///< pixels
    int height = 0;           ///< pixels
    int stride = 0;           ///< bytes per row
    std::vector<std::uint8_t> pixels;
};

/// Draws `frames` frames of `frame_size`×`frame_size` pixels, `columns` per row, row after row.
SheetImage draw_sprite_sheet(int frames, int columns, int frame_size);

}  // namespace grape::studio
