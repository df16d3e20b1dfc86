// A frame of a SpriteSheet drawn from its sheet picture: trimmed pixels at their offset in the
// untrimmed image, rotated frames turned upright, the pivot at the sprite's position.
#include <grape/render.hpp>

namespace grape {

void draw_sprite_frame(Canvas& canvas, const Image& sheet_image, const SpriteFrame& frame, Vec2 at, double scale) {
    const FrameRect& r = frame.rect;
    // Upright pixel (x, y) of the frame ↦ world at + scale·(offset + (x, y) − pivot).
    const Affine place = Affine::translation(at) * Affine::scaling(scale, scale) *
                         Affine::translation({frame.offset_x - frame.pivot.x, frame.offset_y - frame.pivot.y});
    // A rotated frame is stored turned 90° clockwise: the region's (u, v) is upright
    // (v, h − u), h the upright height (the region's width).
    const Affine upright = frame.rotated ? Affine{0.0, -1.0, 1.0, 0.0, 0.0, static_cast<double>(r.width)} : Affine{};
    canvas.push();
    canvas.concat(place * upright);
    canvas.draw_image(sheet_image, {static_cast<double>(r.x), static_cast<double>(r.y), static_cast<double>(r.width),
                                    static_cast<double>(r.height)},
                      {0.0, 0.0, static_cast<double>(r.width), static_cast<double>(r.height)});
    canvas.pop();
}

}  // namespace grape
