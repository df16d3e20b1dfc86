// A sprite sheet as Aseprite exports it (`aseprite -b hero.aseprite --sheet hero.png --data
// hero.json --format json-array --list-tags`): its "walk" tag played at half speed with the
// frames' own durations, then "jump" once the current pass of the walk ends.
#include <grape/sprite.hpp>
#include <grape/sprite_sheet_json.hpp>

#include <cstdio>

// Four 32×32 frames with uneven durations (ms) and two tags, as Aseprite writes them; a file
// reads the same way with grape::load_sprite_sheet_file("hero.json").
const char* hero_json = R"({
 "frames": [
  {"filename": "hero 0", "frame": {"x": 0, "y": 0, "w": 32, "h": 32}, "duration": 100},
  {"filename": "hero 1", "frame": {"x": 32, "y": 0, "w": 32, "h": 32}, "duration": 150},
  {"filename": "hero 2", "frame": {"x": 64, "y": 0, "w": 32, "h": 32}, "duration": 100},
  {"filename": "hero 3", "frame": {"x": 96, "y": 0, "w": 32, "h": 32}, "duration": 200}],
 "meta": {"image": "hero.png", "size": {"w": 128, "h": 32},
  "frameTags": [{"name": "walk", "from": 0, "to": 2, "direction": "pingpong"},
                {"name": "jump", "from": 3, "to": 3, "direction": "forward", "repeat": "1"}]}})";

int main() {
    const grape::SpriteSheet sheet = grape::load_sprite_sheet(hero_json);
    grape::ClipPlayer player(sheet, "walk", {.rate = 0.5});   // half speed
    player.on_event([](const grape::ClipEvent& e) {
        if (e.kind == grape::ClipEventKind::complete) std::puts("jump done");
    });
    for (int frame = 0; frame < 120; ++frame) {
        player.advance(1.0 / 60);                              // seconds of game time
        const grape::SpriteFrame& f = sheet.frame(player.frame());
        (void)f;  // draw f.rect of hero.png, or grape::draw_sprite_frame(canvas, png, f, position)
    }
    player.play("jump", grape::ClipSwitch::at_loop_end);       // when this pass of the walk ends
    for (int frame = 0; frame < 60; ++frame) player.advance(1.0 / 60);
    // A pass of the walk lasts at most 250 ms of clip time and the jump 200: within the
    // 500 ms of the last second (at half speed) the jump has played and completed.
    std::printf("clip '%s', frame %zu\n", sheet.clips()[player.clip()].name.c_str(), player.frame());
    return player.clip() == 1 && player.frame() == 3 && player.finished() ? 0 : 1;
}
