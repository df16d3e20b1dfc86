// grape — the sprite sheets grape draws for itself (no third-party art): a bouncing, turning
// grape. One drawing serves the tests' Aseprite-style sheet (tests/data/sprites, checked by
// make_sprite_sheet --check), the tile sheet of `grape demo` and the studio's Sprites tab.
#pragma once

#include <grape/render.hpp>
#include <grape/sprite.hpp>

namespace grape::scenes {

/// A sheet picture and the frames on it.
struct DrawnSheet {
    Image image;        ///< premultiplied ARGB words, row after row
    SpriteSheet sheet;  ///< where each frame lies on `image`
};

/// Frame k of a `frames`-frame cycle of the grape, `size` × `size` pixels on transparency:
/// the body rises and falls twice per cycle, a spoke turns once, and k + 1 dots along the top
/// count the frame. Drawn in a 48-pixel square and scaled, so 48 gives the sheet's own pixels.
/// Throws grape::Error unless 1 ≤ frames ≤ 64, 0 ≤ k < frames and 8 ≤ size ≤ 1024.
Image grape_sprite_frame(int k, int frames = 8, int size = 48);

/// `frames` untrimmed frames of `size` pixels, `columns` per row, row after row, each on a
/// light tile (so the grid reads in a sheet view): the picture a TileSheet with those columns
/// and rows cuts. Frames show 100 ms each. Throws grape::Error as grape_sprite_frame does, or
/// unless 1 ≤ columns ≤ frames.
DrawnSheet grape_tile_sheet(int frames, int columns, int size);

#ifdef GRAPE_SCENES_SHEET_JSON
/// The sheet as Aseprite exports it with trimming on: eight 48-pixel frames, each trimmed to
/// its drawn pixels and packed in a row 1 pixel apart, uneven durations, clips of every
/// direction (with and without repeat counts), a slice with a pivot at the grape's feet and a
/// hit box without one. The frames carry the pivots the loader derives from the slices.
DrawnSheet grape_packed_sheet();
#endif

}  // namespace grape::scenes
