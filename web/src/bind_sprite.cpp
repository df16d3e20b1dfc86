// Sprites for JavaScript: a SpritePlayer over a frame count (the page draws the frame it
// reports) and TileSheet rectangles.
#include "web_util.hpp"

#include <grape/sprite.hpp>

#include <emscripten/bind.h>

#include <cmath>
#include <string>

namespace grape::web {
namespace {

PlayMode parse_play_mode(const std::string& name) {
    if (name == "loop") return PlayMode::loop;
    if (name == "once") return PlayMode::once;
    if (name == "ping_pong" || name == "ping-pong") return PlayMode::ping_pong;
    throw Error("SpritePlayer: mode must be loop, once or ping_pong (got '" + name + "')");
}
std::string mode_name(PlayMode mode) {
    switch (mode) {
        case PlayMode::loop: return "loop";
        case PlayMode::once: return "once";
        case PlayMode::ping_pong: return "ping_pong";
    }
    return "loop";
}

SpritePlayer* make_player(unsigned frames, val o) {
    std::string message;
    try {
        SpritePlayerDef def;
        def.rate = number_or(o, "rate", def.rate, "SpritePlayer");
        if (has(o, "mode")) def.mode = parse_play_mode(string_or(o, "mode", "", "SpritePlayer"));
        const double start = number_or(o, "startFrame", 0.0, "SpritePlayer");
        if (!(start >= 0.0 && start <= 4294967295.0) || start != std::floor(start))
            throw Error("SpritePlayer: startFrame must be a whole number ≥ 0 (got " + detail::number_text(start) + ")");
        def.start_frame = unsigned(start);
        return new SpritePlayer(frames, def);
    } catch (const std::exception& e) {
        message = e.what();
    }
    throw_js(message);
}
SpritePlayer* make_default_player(unsigned frames) { return make_player(frames, val::undefined()); }
void advance(SpritePlayer& p) { p.advance(); }
void advance_by(SpritePlayer& p, double dt, double fps) { p.advance(dt, fps); }
unsigned frame(const SpritePlayer& p) { return unsigned(p.frame()); }
void set_rate(SpritePlayer& p, double rate) { p.set_rate(rate); }
std::string mode(const SpritePlayer& p) { return mode_name(p.mode()); }
void set_mode(SpritePlayer& p, std::string name) { p.set_mode(parse_play_mode(name)); }
unsigned frame_count(const SpritePlayer& p) { return unsigned(p.frame_count()); }
void set_frame(SpritePlayer& p, unsigned k) { p.set_frame(k); }
void on_frame(SpritePlayer& p, val fn) { p.on_frame([fn](std::size_t k) { fn(unsigned(k)); }); }
void on_complete(SpritePlayer& p, val fn) { p.on_complete([fn] { fn(); }); }
void on_loop(SpritePlayer& p, val fn) { p.on_loop([fn](std::size_t cycle) { fn(unsigned(cycle)); }); }

TileSheet* make_sheet(val o) {
    std::string message;
    try {
        auto whole = [&](const char* name, int fallback) {
            const double v = number_or(o, name, fallback, "TileSheet");
            if (!(v >= -2147483648.0 && v <= 2147483647.0) || v != std::floor(v)) throw Error(std::string("TileSheet: '") + name + "' must be a whole number");
            return int(v);
        };
        return new TileSheet(TileSheetDef{.width = whole("width", 0),
                                          .height = whole("height", 0),
                                          .columns = whole("columns", 1),
                                          .rows = whole("rows", 1),
                                          .margin = whole("margin", 0),
                                          .spacing = whole("spacing", 0),
                                          .frame_width = whole("frameWidth", 0),
                                          .frame_height = whole("frameHeight", 0),
                                          .frame_count = whole("frameCount", 0)});
    } catch (const std::exception& e) {
        message = e.what();
    }
    throw_js(message);
}
FrameRect rect(const TileSheet& s, unsigned k) { return s.at(k); }
unsigned sheet_frames(const TileSheet& s) { return unsigned(s.frame_count()); }

}  // namespace

EMSCRIPTEN_BINDINGS(grape_sprite) {
    using namespace emscripten;
    value_object<FrameRect>("FrameRect")
        .field("x", &FrameRect::x)
        .field("y", &FrameRect::y)
        .field("width", &FrameRect::width)
        .field("height", &FrameRect::height);
    class_<SpritePlayer>("SpritePlayer")
        .constructor(&make_player, allow_raw_pointers())
        .constructor(&make_default_player, allow_raw_pointers())
        .function("advance", &advance)
        .function("advanceBy", guarded<&advance_by>)
        .function("frame", &frame)
        .function("remainder", method<&SpritePlayer::remainder>)
        .function("rate", method<&SpritePlayer::rate>)
        .function("setRate", guarded<&set_rate>)
        .function("mode", &mode)
        .function("setMode", guarded<&set_mode>)
        .function("frameCount", &frame_count)
        .function("setFrame", guarded<&set_frame>)
        .function("playing", method<&SpritePlayer::playing>)
        .function("pause", method<&SpritePlayer::pause>)
        .function("play", method<&SpritePlayer::play>)
        .function("onFrame", guarded<&on_frame>)
        .function("onComplete", guarded<&on_complete>)
        .function("onLoop", guarded<&on_loop>);
    class_<TileSheet>("TileSheet")
        .constructor(&make_sheet, allow_raw_pointers())
        .function("width", method<&TileSheet::width>)
        .function("height", method<&TileSheet::height>)
        .function("frameCount", &sheet_frames)
        .function("frame", guarded<&rect>);
}

}  // namespace grape::web
