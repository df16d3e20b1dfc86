// A 16-frame walk cycle cut from a sheet, played at half speed, then reversed.
#include <grape/sprite.hpp>

#include <cstdio>

int main() {
    const grape::TileSheet sheet({.width = 512, .height = 64, .columns = 16, .rows = 1});
    grape::TileSheetSprite walker(sheet);
    grape::SpritePlayer player(walker, {.rate = 0.5});
    for (int frame = 0; frame < 4; ++frame) player.advance();  // once per game frame
    std::printf("frame %zu at x=%d\n", walker.current_frame(), walker.rect().x);
    player.set_rate(-2);  // reverse at double speed, wrapping past frame 0
    player.advance(1.0 / 60, 60);  // or by time: dt seconds at the sheet's 60 fps
    std::printf("frame %zu at x=%d\n", walker.current_frame(), walker.rect().x);
    return walker.current_frame() == 0 ? 0 : 1;
}
