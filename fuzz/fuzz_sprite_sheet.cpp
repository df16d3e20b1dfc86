// libFuzzer target for grape::load_sprite_sheet (Aseprite and TexturePacker JSON): any byte
// string either loads or throws grape::Error. A loaded sheet must save in Aseprite's array
// layout and load again to the same frames (places, offsets, durations), scale and clips (and
// in the hash layout, unless its frame names are not unique), and every clip must play at
// normal, reversed and absurd rates without showing a frame outside the clip. Anything else (a crash, a sanitizer report, another
// exception, a broken round trip) is a finding.
#include <grape/error.hpp>
#include <grape/sprite.hpp>
#include <grape/sprite_sheet_json.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

namespace {

void require(bool condition) {
    if (!condition) std::abort();
}

bool same_rect(const grape::FrameRect& a, const grape::FrameRect& b) {
    return a.x == b.x && a.y == b.y && a.width == b.width && a.height == b.height;
}

void require_same(const grape::SpriteSheet& a, const grape::SpriteSheet& b) {
    require(a.frame_count() == b.frame_count() && a.clips().size() == b.clips().size());
    require(a.scale() == b.scale());
    for (std::size_t k = 0; k < a.frame_count(); ++k) {
        require(same_rect(a.frame(k).rect, b.frame(k).rect));
        require(a.frame(k).offset_x == b.frame(k).offset_x && a.frame(k).offset_y == b.frame(k).offset_y);
        require(a.frame(k).rotated == b.frame(k).rotated);
        require(a.frame(k).duration_ms == b.frame(k).duration_ms);
    }
    for (std::size_t c = 0; c < a.clips().size(); ++c) {
        require(a.clips()[c].from == b.clips()[c].from && a.clips()[c].to == b.clips()[c].to);
        require(a.clips()[c].direction == b.clips()[c].direction && a.clips()[c].repeat == b.clips()[c].repeat);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto sheet = [&]() -> std::optional<grape::SpriteSheet> {
        try {
            return grape::load_sprite_sheet(text);
        } catch (const grape::Error& e) {
            require(std::string_view(e.what()).size() > 0);
            return std::nullopt;
        }
    }();
    if (!sheet) return 0;
    require_same(*sheet, grape::load_sprite_sheet(grape::save_sprite_sheet(*sheet, grape::SheetJsonLayout::array)));
    try {
        const std::string hash = grape::save_sprite_sheet(*sheet, grape::SheetJsonLayout::hash);
        require_same(*sheet, grape::load_sprite_sheet(hash));
    } catch (const grape::Error&) {
        // frame names that the hash layout cannot key (empty or repeated): refused, fine
    }
    // Every clip (at most 16) plays; the work per advance is bounded by the player.
    for (std::size_t c = 0; c < std::min<std::size_t>(sheet->clips().size(), 16); ++c) {
        const grape::SpriteClip& clip = sheet->clips()[c];
        for (double rate : {1.0, -2.5, 1e6}) {
            grape::ClipPlayer player(*sheet, c, {.rate = rate});
            for (int step = 0; step < 8; ++step) {
                player.advance(step == 7 ? 1e12 : 1.0 / 60.0);
                require(player.frame() >= clip.from && player.frame() <= clip.to);
            }
        }
    }
    return 0;
}
