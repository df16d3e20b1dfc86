// `grape sprite info SHEET.json` (frames, clips and durations as JSON) and `grape sprite play
// SHEET.json --clip NAME --rate R --fps F --frames N` (the frame shown at each game frame), so
// any Aseprite or TexturePacker sheet can be checked from the command line. Built with the
// scene module (JSON); without it the commands are absent.
#include "commands.hpp"
#include "json_out.hpp"

#ifdef GRAPE_TOOL_SPRITE
#include <grape/error.hpp>
#include <grape/sprite.hpp>
#include <grape/sprite_sheet_json.hpp>

#include <nlohmann/json.hpp>

#include "utf8_path.hpp"

#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>
#endif

namespace grape::tool {

#ifdef GRAPE_TOOL_SPRITE
namespace {

using json = nlohmann::ordered_json;

// A number as JSON: whole values as integers, others with 17 significant digits.
json number_json(double v) {
    if (v == std::floor(v) && std::fabs(v) < 9e15) return static_cast<std::int64_t>(v);
    return v;
}

// The frames one clip shows, in order: its whole playback when it has a repeat count, one
// period when it loops forever; and how long that takes at rate 1.
struct Sequence {
    std::vector<std::size_t> frames;
    double duration_ms = 0.0;
};

// The sheet frame at `step` of the clip's playback, in the player's order (ClipPlayer walks
// the same periodic sequence: forward, reverse, or a ping-pong of period 2·length − 2).
std::size_t frame_at(const SpriteClip& c, bool bounce, std::size_t period, std::size_t step) {
    const std::size_t n = c.length(), k = step % period;
    switch (c.direction) {
        case ClipDirection::forward: return c.from + k;
        case ClipDirection::reverse: return c.from + (n - 1 - k);
        case ClipDirection::ping_pong: return c.from + (!bounce || k < n ? k : 2 * n - 2 - k);
        case ClipDirection::ping_pong_reverse: return c.from + (!bounce || k < n ? n - 1 - k : k - n + 1);
    }
    return c.from;
}

Sequence sequence(const SpriteSheet& sheet, std::size_t clip) {
    // Counted in frames, not walked in time: a frame may last any positive time (5e-324 ms
    // included), so the work is the number of frames shown, bounded below.
    const SpriteClip& c = sheet.clips()[clip];
    const bool bounce = (c.direction == ClipDirection::ping_pong || c.direction == ClipDirection::ping_pong_reverse) &&
                        c.length() > 1;
    const std::size_t period = bounce ? 2 * c.length() - 2 : c.length();
    const std::size_t steps = c.repeat == 0 ? period
                                            : (bounce ? c.length() + std::size_t(c.repeat - 1) * (c.length() - 1)
                                                      : std::size_t(c.repeat) * c.length());
    if (steps > 1'000'000) throw Error("sprite info: clip '" + c.name + "' plays more than 1,000,000 frames");
    Sequence s;
    s.frames.reserve(steps);
    for (std::size_t k = 0; k < steps; ++k) {
        s.frames.push_back(frame_at(c, bounce, period, k));
        s.duration_ms += sheet.frame(s.frames.back()).duration_ms;
    }
    return s;
}

const char* direction_name(ClipDirection d) {
    const char* names[] = {"forward", "reverse", "pingpong", "pingpong_reverse"};
    return names[static_cast<int>(d)];
}

json info(const SpriteSheet& sheet) {
    json frames = json::array();
    for (const SpriteFrame& f : sheet.frames()) {
        frames.push_back({{"name", f.name}, {"x", f.rect.x}, {"y", f.rect.y}, {"w", f.width()}, {"h", f.height()},
                          {"rotated", f.rotated}, {"offset_x", f.offset_x}, {"offset_y", f.offset_y},
                          {"source_w", f.source_width}, {"source_h", f.source_height},
                          {"duration_ms", number_json(f.duration_ms)}, {"pivot_x", number_json(f.pivot.x)},
                          {"pivot_y", number_json(f.pivot.y)}});
    }
    json clips = json::array();
    for (std::size_t k = 0; k < sheet.clips().size(); ++k) {
        const SpriteClip& c = sheet.clips()[k];
        const Sequence s = sequence(sheet, k);
        clips.push_back({{"name", c.name}, {"from", c.from}, {"to", c.to}, {"direction", direction_name(c.direction)},
                         {"repeat", c.repeat}, {"frames", s.frames}, {"duration_ms", number_json(s.duration_ms)}});
    }
    json slices = json::array();
    for (const SpriteSlice& s : sheet.slices()) {
        json keys = json::array();
        for (const SliceKey& key : s.keys) {
            json k = {{"frame", key.frame}, {"x", key.bounds.x}, {"y", key.bounds.y}, {"w", key.bounds.width}, {"h", key.bounds.height}};
            if (key.has_pivot) {
                k["pivot_x"] = number_json(key.pivot.x);
                k["pivot_y"] = number_json(key.pivot.y);
            }
            keys.push_back(std::move(k));
        }
        slices.push_back({{"name", s.name}, {"keys", std::move(keys)}});
    }
    return {{"image", sheet.image()}, {"width", sheet.width()}, {"height", sheet.height()},
            {"scale", number_json(sheet.scale())}, {"frame_count", sheet.frame_count()}, {"frames", std::move(frames)},
            {"clips", std::move(clips)}, {"slices", std::move(slices)}};
}

// A sheet without tags (a TexturePacker atlas) plays all its frames in order.
SpriteSheet with_all_frames_clip(const SpriteSheet& sheet) {
    SpriteSheetDef def{.image = sheet.image(), .width = sheet.width(), .height = sheet.height(), .scale = sheet.scale(),
                       .frames = {sheet.frames().begin(), sheet.frames().end()},
                       .clips = {{.name = "all", .from = 0, .to = sheet.frame_count() - 1}},
                       .slices = {sheet.slices().begin(), sheet.slices().end()}};
    return SpriteSheet(std::move(def));
}

}  // namespace
#endif

void register_sprite_commands([[maybe_unused]] CLI::App& app) {
#ifdef GRAPE_TOOL_SPRITE
    auto* sprite = app.add_subcommand("sprite", "Inspect and play sprite sheets (Aseprite or TexturePacker JSON)");
    sprite->require_subcommand(1);

    auto info_file = std::make_shared<std::string>();
    auto* info_cmd = sprite->add_subcommand("info", "Print a sheet's frames, clips (with the frames they show) and durations as JSON");
    info_cmd->add_option("SHEET", *info_file, "Sheet data: Aseprite or TexturePacker JSON, hash or array layout")->required();
    info_cmd->callback([info_file] { std::cout << info(load_sprite_sheet_file(detail::path_from_utf8(*info_file))).dump(1) << '\n'; });

    struct PlayArgs {
        std::string file, clip, rate = "1", fps = "60", frames = "60";
    };
    auto args = std::make_shared<PlayArgs>();
    auto* play = sprite->add_subcommand(
        "play", "Print the sheet frame shown at each of N game frames (a JSON array; the first is at time 0)");
    play->add_option("SHEET", args->file, "Sheet data: Aseprite or TexturePacker JSON")->required();
    play->add_option("--clip", args->clip, "Clip (tag) name; without it a sheet with no tags plays all its frames");
    play->add_option("--rate", args->rate, "Playback rate: 1 normal, 0.5 half, -2 backwards at double speed (default 1)");
    play->add_option("--fps", args->fps, "Game frames per second (default 60)");
    play->add_option("--frames", args->frames, "Number of game frames N (default 60)");
    play->callback([args] {
        const double rate = parse_finite("sprite play: --rate", args->rate);
        const double fps = parse_finite("sprite play: --fps", args->fps);
        if (!(fps > 0.0)) throw Error("sprite play: --fps must be positive (got " + args->fps + ")");
        const double n = parse_finite("sprite play: --frames", args->frames);
        if (n != std::floor(n) || n < 0 || n > 1e7) {
            throw Error("sprite play: --frames must be a whole number in [0, 10000000] (got " + args->frames + ")");
        }
        SpriteSheet sheet = load_sprite_sheet_file(detail::path_from_utf8(args->file));
        if (args->clip.empty()) {
            if (!sheet.clips().empty()) {
                throw Error("sprite play: --clip is required for a sheet with tags (clip names: see `grape sprite info`)");
            }
            sheet = with_all_frames_clip(sheet);
            args->clip = "all";
        }
        ClipPlayer player(sheet, args->clip, {.rate = rate});
        std::string out = "[";
        for (std::int64_t k = 0; k < static_cast<std::int64_t>(n); ++k) {
            if (k > 0) {
                out += ", ";
                player.advance(1.0 / fps);
            }
            out += std::to_string(player.frame());
        }
        std::cout << out << "]\n";
    });
#endif
}

}  // namespace grape::tool
