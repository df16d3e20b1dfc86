// Sprite-sheet JSON (Aseprite, TexturePacker) ↔ SpriteSheet. Every read knows the JSON pointer
// of its value, so each error names where it is and why. Objects are read in file order
// (ordered_json): in the hash layout the order of the keys is the order of the frames.
#include <grape/sprite_sheet_json.hpp>

#include <grape/error.hpp>

#include "file_text.hpp"
#include "json_pointer.hpp"
#include "math/number_text.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <set>
#include <span>
#include <sstream>
#include <system_error>
#include <vector>

namespace grape {
// Named, so that in a unity build beside the scene loader (whose files use scene_io at
// grape scope) its helpers are found only where asked for.
namespace sheet_io {
namespace {

using sheet_json = nlohmann::ordered_json;
using detail::child;
using detail::number_text;
using detail::type_of;

// Pixel coordinates beyond this are not a sprite sheet (cairo's limit is 32767).
constexpr double max_pixels = 1 << 24;

[[noreturn]] void fail(const std::string& pointer, const std::string& why) {
    throw Error("sprite sheet: " + (pointer.empty() ? std::string("/") : pointer) + ": " + why);
}

const sheet_json& object(const sheet_json& j, const std::string& pointer) {
    if (!j.is_object()) fail(pointer, "expected an object, got " + type_of(j));
    return j;
}

const sheet_json& required(const sheet_json& obj, const std::string& pointer, std::string_view key) {
    const auto it = obj.find(key);
    if (it == obj.end()) fail(pointer, "missing field \"" + std::string(key) + "\"");
    return *it;
}

const sheet_json* optional(const sheet_json& obj, std::string_view key) {
    const auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
}

double number(const sheet_json& j, const std::string& pointer) {
    if (!j.is_number()) fail(pointer, "expected a number, got " + type_of(j));
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(pointer, "number out of range");
    return v;
}

// A whole number of pixels in [lowest, 2^24].
int pixels(const sheet_json& obj, const std::string& pointer, std::string_view key, double lowest) {
    const std::string at = child(pointer, key);
    const double v = number(required(obj, pointer, key), at);
    if (v != std::floor(v)) fail(at, "expected a whole number of pixels (got " + number_text(v) + ")");
    if (v < lowest || v > max_pixels) {
        fail(at, "must lie in [" + number_text(lowest) + ", " + number_text(max_pixels) + "] (got " + number_text(v) + ")");
    }
    return static_cast<int>(v);
}

FrameRect rect(const sheet_json& j, const std::string& pointer, double lowest_size) {
    object(j, pointer);
    return {pixels(j, pointer, "x", -max_pixels), pixels(j, pointer, "y", -max_pixels), pixels(j, pointer, "w", lowest_size),
            pixels(j, pointer, "h", lowest_size)};
}

bool boolean(const sheet_json& obj, const std::string& pointer, std::string_view key, bool fallback) {
    return detail::bool_member(obj, pointer, key, fallback, fail);
}

std::string string(const sheet_json& j, const std::string& pointer) { return detail::string_of(j, pointer, fail); }

std::size_t frame_index(const sheet_json& obj, const std::string& pointer, std::string_view key, std::size_t count) {
    const std::string at = child(pointer, key);
    const double v = number(required(obj, pointer, key), at);
    if (v != std::floor(v) || v < 0) fail(at, "expected a frame index, a whole number >= 0 (got " + number_text(v) + ")");
    if (v >= static_cast<double>(count)) {
        fail(at, number_text(v) + " is past the last frame (frame count " + std::to_string(count) + ")");
    }
    return static_cast<std::size_t>(v);
}

std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

SpriteFrame read_frame(const sheet_json& j, const std::string& pointer, std::string name, int sheet_w, int sheet_h) {
    object(j, pointer);
    SpriteFrame f;
    f.name = std::move(name);
    f.rotated = boolean(j, pointer, "rotated", false);
    const std::string frame_at = child(pointer, "frame");
    const FrameRect upright = rect(required(j, pointer, "frame"), frame_at, 1);
    // A rotated frame's w and h are the upright sprite's; on the sheet it covers h × w.
    f.rect = f.rotated ? FrameRect{upright.x, upright.y, upright.height, upright.width} : upright;
    if (f.rect.x < 0 || f.rect.y < 0 || std::int64_t{f.rect.x} + f.rect.width > sheet_w ||
        std::int64_t{f.rect.y} + f.rect.height > sheet_h) {
        fail(frame_at, "at (" + std::to_string(f.rect.x) + ", " + std::to_string(f.rect.y) + ") size " +
                           size_text(f.rect.width, f.rect.height) + (f.rotated ? " (rotated)" : "") + " leaves the " +
                           size_text(sheet_w, sheet_h) + " sheet (meta.size)");
    }
    // The pixels' own size and place on the sheet: the frame's, or inside it past Aseprite's
    // inner padding (its exporter makes each cell the trimmed size plus the padding p on every
    // side, writes the cell as `frame` and the trimmed pixels' size in spriteSourceSize).
    int pixels_w = upright.width;
    int pixels_h = upright.height;
    if (const sheet_json* s = optional(j, "spriteSourceSize")) {
        const std::string at = child(pointer, "spriteSourceSize");
        const FrameRect r = rect(*s, at, 1);
        const int extra_w = upright.width - r.width;
        const int extra_h = upright.height - r.height;
        if (extra_w != 0 || extra_h != 0) {
            if (extra_w != extra_h || extra_w < 0 || extra_w % 2 != 0) {
                fail(at, "size " + size_text(r.width, r.height) + " differs from the frame's " +
                             size_text(upright.width, upright.height) +
                             " other than by an inner padding (the frame larger by the same even number on both axes)");
            }
            const int padding = extra_w / 2;
            pixels_w = r.width;
            pixels_h = r.height;
            f.rect = f.rotated ? FrameRect{f.rect.x + padding, f.rect.y + padding, pixels_h, pixels_w}
                               : FrameRect{f.rect.x + padding, f.rect.y + padding, pixels_w, pixels_h};
        }
        f.offset_x = r.x;
        f.offset_y = r.y;
    }
    f.source_width = pixels_w;
    f.source_height = pixels_h;
    if (const sheet_json* s = optional(j, "sourceSize")) {
        const std::string at = child(pointer, "sourceSize");
        object(*s, at);
        f.source_width = pixels(*s, at, "w", 1);
        f.source_height = pixels(*s, at, "h", 1);
    }
    // Trimmed pixels lie inside the untrimmed image. Pixels that are the whole image may sit
    // anywhere: TexturePacker's "crop, keep position" makes the crop the sprite (sourceSize)
    // and keeps where it was in the art as spriteSourceSize's x, y, of any sign.
    const bool whole_image = pixels_w == f.source_width && pixels_h == f.source_height;
    if (!whole_image && (f.offset_x < 0 || f.offset_y < 0 || std::int64_t{f.offset_x} + pixels_w > f.source_width ||
                         std::int64_t{f.offset_y} + pixels_h > f.source_height)) {
        fail(child(pointer, "spriteSourceSize"),
             "puts the trimmed " + size_text(pixels_w, pixels_h) + " pixels at (" + std::to_string(f.offset_x) + ", " +
                 std::to_string(f.offset_y) + "), outside the " + size_text(f.source_width, f.source_height) +
                 " sourceSize");
    }
    if (const sheet_json* d = optional(j, "duration")) {
        const std::string at = child(pointer, "duration");
        f.duration_ms = number(*d, at);
        if (!(f.duration_ms > 0.0)) fail(at, "must be positive, milliseconds (got " + number_text(f.duration_ms) + ")");
    }
    // TexturePacker's pivot (`anchor` in its PixiJS format): a fraction of the sprite's size,
    // from its top-left. A kept-position crop's sprite is the crop, where it sat in the art.
    const char* pivot_key = optional(j, "pivot") ? "pivot" : "anchor";
    if (const sheet_json* p = optional(j, pivot_key)) {
        const std::string at = child(pointer, pivot_key);
        object(*p, at);
        const double px = number(required(*p, at, "x"), child(at, "x"));
        const double py = number(required(*p, at, "y"), child(at, "y"));
        const Vec2 origin = whole_image ? Vec2{double(f.offset_x), double(f.offset_y)} : Vec2{};
        f.pivot = origin + Vec2{px * f.source_width, py * f.source_height};
    }
    return f;
}

// Both tools write the scale as a string of a decimal number ("1", "0.5"); a number is taken too.
double sheet_scale(const sheet_json& j, const std::string& pointer) {
    double v = 0.0;
    if (j.is_string()) {
        const std::string s = j.get<std::string>();
        if (!detail::parse_finite(s, v)) fail(pointer, "expected a number as text, like \"0.5\" (got \"" + s + "\")");
    } else {
        v = number(j, pointer);
    }
    if (!(v > 0.0)) fail(pointer, "must be positive (got " + number_text(v) + ")");
    return v;
}

ClipDirection direction(const sheet_json& j, const std::string& pointer) {
    const std::string s = string(j, pointer);
    if (s == "forward") return ClipDirection::forward;
    if (s == "reverse") return ClipDirection::reverse;
    if (s == "pingpong") return ClipDirection::ping_pong;
    if (s == "pingpong_reverse") return ClipDirection::ping_pong_reverse;
    fail(pointer, "unknown direction \"" + s + "\" (expected one of: forward, reverse, pingpong, pingpong_reverse)");
}

// Aseprite writes "repeat" as a string of digits ("3"); a number is taken too.
int repeat(const sheet_json& j, const std::string& pointer) {
    double v = 0.0;
    if (j.is_string()) {
        const std::string s = j.get<std::string>();
        if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos) {
            fail(pointer, "expected a count of passes, a whole number >= 0 (got \"" + s + "\")");
        }
        detail::parse_finite(s, v);  // nine digits at most: always a finite number
    } else {
        v = number(j, pointer);
        if (v != std::floor(v) || v < 0 || v > 1e9) {
            fail(pointer, "expected a count of passes, a whole number >= 0 (got " + number_text(v) + ")");
        }
    }
    return static_cast<int>(v);
}

// One of several sprites Aseprite packed onto a sheet: its frames are the run of `count` from
// sheet frame `first`, and its tags count from its own first frame.
struct PackedSprite {
    std::string title;
    std::size_t first = 0;
    std::size_t count = 0;
};

bool is_alphanumeric(char c) noexcept {
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

// The sprites of a sheet that says it packs several: every frame has the name Aseprite gives
// frames of several files by default, "TITLE N.EXT" (N counted from 0 in each sprite) or
// "TITLE.EXT" for a sprite of one frame, each title's frames one run, and two titles or more.
// Anything else: none.
std::vector<PackedSprite> packed_sprites(std::span<const SpriteFrame> frames) {
    std::vector<PackedSprite> sprites;
    for (std::size_t k = 0; k < frames.size(); ++k) {
        const std::string& name = frames[k].name;
        const std::size_t dot = name.rfind('.');
        if (dot == std::string::npos || dot == 0 || dot + 1 == name.size()) return {};
        for (std::size_t i = dot + 1; i < name.size(); ++i) {
            if (!is_alphanumeric(name[i])) return {};
        }
        std::string title = name.substr(0, dot);
        std::size_t number = 0;
        bool numbered = false;
        const std::size_t space = title.rfind(' ');
        const std::size_t digits = space == std::string::npos ? 0 : title.size() - space - 1;
        if (digits > 0 && digits <= 9 && space > 0 &&
            title.find_first_not_of("0123456789", space + 1) == std::string::npos) {
            number = std::stoul(title.substr(space + 1));
            numbered = true;
            title.resize(space);
        }
        if (!sprites.empty() && sprites.back().title == title) {
            if (!numbered || number != sprites.back().count) return {};
            ++sprites.back().count;
            continue;
        }
        if (numbered && number != 0) return {};
        for (const PackedSprite& s : sprites) {
            if (s.title == title) return {};
        }
        sprites.push_back({std::move(title), k, 1});
    }
    if (sprites.size() < 2) return {};
    return sprites;
}

// The sprite a tag names when Aseprite wrote it with a tag name format that starts with the
// title ("{title}/{tag}" gives "hero/walk"): the longest title followed by a separator.
const PackedSprite* sprite_of_tag(const std::string& tag, const std::vector<PackedSprite>& sprites) {
    const PackedSprite* found = nullptr;
    for (const PackedSprite& s : sprites) {
        if (tag.size() > s.title.size() + 1 && tag.compare(0, s.title.size(), s.title) == 0 &&
            !is_alphanumeric(tag[s.title.size()]) && (!found || s.title.size() > found->title.size())) {
            found = &s;
        }
    }
    return found;
}

SpriteClip read_tag(const sheet_json& j, const std::string& pointer, std::size_t count, const std::vector<PackedSprite>& sprites) {
    object(j, pointer);
    SpriteClip c;
    c.name = string(required(j, pointer, "name"), child(pointer, "name"));
    // Aseprite numbers each packed sprite's tags from that sprite's first frame.
    const PackedSprite* sprite = sprite_of_tag(c.name, sprites);
    const std::size_t first = sprite ? sprite->first : 0;
    const std::size_t frames = sprite ? sprite->count : count;
    try {
        c.from = first + frame_index(j, pointer, "from", frames);
        c.to = first + frame_index(j, pointer, "to", frames);
    } catch (const Error& e) {
        if (!sprite) throw;
        throw Error(std::string(e.what()) + " of sprite \"" + sprite->title + "\" (sheet frames " +
                    std::to_string(first) + " to " + std::to_string(first + frames - 1) + ")");
    }
    if (c.to < c.from) {
        fail(child(pointer, "to"), std::to_string(c.to - first) + " is before from (" + std::to_string(c.from - first) + ")");
    }
    if (const sheet_json* d = optional(j, "direction")) c.direction = direction(*d, child(pointer, "direction"));
    if (const sheet_json* r = optional(j, "repeat")) c.repeat = repeat(*r, child(pointer, "repeat"));
    return c;
}

SpriteSlice read_slice(const sheet_json& j, const std::string& pointer, std::size_t count) {
    object(j, pointer);
    SpriteSlice s;
    s.name = string(required(j, pointer, "name"), child(pointer, "name"));
    const std::string keys_at = child(pointer, "keys");
    const sheet_json& keys = required(j, pointer, "keys");
    if (!keys.is_array()) fail(keys_at, "expected an array, got " + type_of(keys));
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const std::string at = child(keys_at, k);
        object(keys[k], at);
        SliceKey key;
        key.frame = frame_index(keys[k], at, "frame", count);
        key.bounds = rect(required(keys[k], at, "bounds"), child(at, "bounds"), 0);
        if (const sheet_json* p = optional(keys[k], "pivot")) {
            const std::string pivot_at = child(at, "pivot");
            object(*p, pivot_at);
            key.has_pivot = true;
            key.pivot = {number(required(*p, pivot_at, "x"), child(pivot_at, "x")),
                         number(required(*p, pivot_at, "y"), child(pivot_at, "y"))};
        }
        if (!s.keys.empty() && key.frame <= s.keys.back().frame) {
            fail(child(at, "frame"), "keys must be in increasing frame order (" + std::to_string(key.frame) + " after " +
                                         std::to_string(s.keys.back().frame) + ")");
        }
        s.keys.push_back(key);
    }
    return s;
}

SpriteSheet read_sheet(const sheet_json& root) {
    object(root, "");
    const sheet_json& meta = object(required(root, "", "meta"), "/meta");
    const sheet_json& size = object(required(meta, "/meta", "size"), "/meta/size");
    SpriteSheetDef def;
    def.width = pixels(size, "/meta/size", "w", 1);
    def.height = pixels(size, "/meta/size", "h", 1);
    if (const sheet_json* image = optional(meta, "image")) def.image = string(*image, "/meta/image");
    if (const sheet_json* scale = optional(meta, "scale")) def.scale = sheet_scale(*scale, "/meta/scale");

    const sheet_json& frames = required(root, "", "frames");
    if (frames.is_object()) {
        for (const auto& [key, value] : frames.items()) {
            def.frames.push_back(read_frame(value, child("/frames", key), key, def.width, def.height));
        }
    } else if (frames.is_array()) {
        for (std::size_t k = 0; k < frames.size(); ++k) {
            const std::string at = child("/frames", k);
            std::string name;
            if (frames[k].is_object()) {
                if (const sheet_json* n = optional(frames[k], "filename")) name = string(*n, child(at, "filename"));
            }
            def.frames.push_back(read_frame(frames[k], at, std::move(name), def.width, def.height));
        }
    } else {
        fail("/frames", "expected an object (hash layout) or an array (array layout), got " + type_of(frames));
    }
    if (def.frames.empty()) fail("/frames", "a sheet needs at least one frame");

    const std::size_t count = def.frames.size();
    if (const sheet_json* tags = optional(meta, "frameTags")) {
        if (!tags->is_array()) fail("/meta/frameTags", "expected an array, got " + type_of(*tags));
        const std::vector<PackedSprite> sprites = packed_sprites(def.frames);
        for (std::size_t k = 0; k < tags->size(); ++k) {
            def.clips.push_back(read_tag((*tags)[k], child("/meta/frameTags", k), count, sprites));
        }
    }
    if (const sheet_json* slices = optional(meta, "slices")) {
        if (!slices->is_array()) fail("/meta/slices", "expected an array, got " + type_of(*slices));
        for (std::size_t k = 0; k < slices->size(); ++k) def.slices.push_back(read_slice((*slices)[k], child("/meta/slices", k), count));
    }
    // Aseprite keeps pivots in slices: a frame takes the pivot of the first slice whose key in
    // effect there has one, placed in the untrimmed image (key bounds + pivot).
    for (std::size_t k = 0; k < count; ++k) {
        for (const SpriteSlice& s : def.slices) {
            const SliceKey* key = nullptr;
            for (const SliceKey& candidate : s.keys) {
                if (candidate.frame <= k) key = &candidate;
            }
            if (key && key->has_pivot) {
                def.frames[k].pivot = {key->bounds.x + key->pivot.x, key->bounds.y + key->pivot.y};
                break;
            }
        }
    }
    return SpriteSheet(std::move(def));
}

sheet_json rect_json(const FrameRect& r) { return {{"x", r.x}, {"y", r.y}, {"w", r.width}, {"h", r.height}}; }

sheet_json duration_json(double ms) {
    if (ms == std::floor(ms) && ms < 9e15) return static_cast<std::int64_t>(ms);
    return ms;
}

}  // namespace
}  // namespace sheet_io

using sheet_io::sheet_json;

SpriteSheet load_sprite_sheet(std::string_view text) {
    sheet_json root;
    try {
        root = sheet_json::parse(text.begin(), text.end());
    } catch (const sheet_json::parse_error& e) {
        throw Error("sprite sheet: JSON syntax error at byte " + std::to_string(e.byte) + ": " +
                    std::string(e.what()).substr(std::string(e.what()).find(':') + 2));
    } catch (const sheet_json::exception& e) {
        throw Error(std::string("sprite sheet: invalid JSON: ") + e.what());
    }
    return sheet_io::read_sheet(root);
}

SpriteSheet load_sprite_sheet_file(const std::filesystem::path& file) {
    const std::string text = detail::read_file_text(file, "a sprite sheet's JSON");
    try {
        return load_sprite_sheet(text);
    } catch (const Error& e) {
        throw Error(detail::utf8_string(file) + ": " + e.what());
    }
}

std::filesystem::path sprite_sheet_image_path(const SpriteSheet& sheet, const std::filesystem::path& json_file) {
    return json_file.parent_path() / detail::path_from_utf8(sheet.image());
}

std::string save_sprite_sheet(const SpriteSheet& sheet, SheetJsonLayout layout) {
    sheet_json frames = layout == SheetJsonLayout::hash ? sheet_json::object() : sheet_json::array();
    std::set<std::string> names;
    for (std::size_t k = 0; k < sheet.frame_count(); ++k) {
        const SpriteFrame& f = sheet.frame(k);
        sheet_json j;
        if (layout == SheetJsonLayout::array) j["filename"] = f.name;
        j["frame"] = sheet_io::rect_json({f.rect.x, f.rect.y, f.width(), f.height()});
        j["rotated"] = f.rotated;
        j["trimmed"] = f.trimmed();
        j["spriteSourceSize"] = sheet_io::rect_json({f.offset_x, f.offset_y, f.width(), f.height()});
        j["sourceSize"] = {{"w", f.source_width}, {"h", f.source_height}};
        j["duration"] = sheet_io::duration_json(f.duration_ms);
        if (layout == SheetJsonLayout::hash) {
            if (f.name.empty() || !names.insert(f.name).second) {
                throw Error("save_sprite_sheet: the hash layout needs unique, non-empty frame names (frame " +
                            std::to_string(k) + " is named '" + f.name + "')");
            }
            frames[f.name] = std::move(j);
        } else {
            frames.push_back(std::move(j));
        }
    }
    const char* directions[] = {"forward", "reverse", "pingpong", "pingpong_reverse"};
    // On a sheet of several sprites a tag that names its sprite counts that sprite's frames, as
    // the reader has it.
    const std::vector<sheet_io::PackedSprite> sprites = sheet_io::packed_sprites(sheet.frames());
    sheet_json tags = sheet_json::array();
    for (const SpriteClip& c : sheet.clips()) {
        std::size_t first = 0;
        if (const sheet_io::PackedSprite* sprite = sheet_io::sprite_of_tag(c.name, sprites)) {
            if (c.from < sprite->first || c.to >= sprite->first + sprite->count) {
                throw Error("save_sprite_sheet: clip '" + c.name + "' names sprite '" + sprite->title + "' (sheet frames " +
                            std::to_string(sprite->first) + " to " + std::to_string(sprite->first + sprite->count - 1) +
                            ") but plays frames " + std::to_string(c.from) + " to " + std::to_string(c.to));
            }
            first = sprite->first;
        }
        sheet_json t = {{"name", c.name}, {"from", c.from - first}, {"to", c.to - first},
                  {"direction", directions[static_cast<int>(c.direction)]}};
        if (c.repeat > 0) t["repeat"] = std::to_string(c.repeat);  // a string, as Aseprite writes it
        tags.push_back(std::move(t));
    }
    sheet_json slices = sheet_json::array();
    for (const SpriteSlice& s : sheet.slices()) {
        sheet_json keys = sheet_json::array();
        for (const SliceKey& key : s.keys) {
            sheet_json k = {{"frame", key.frame}, {"bounds", sheet_io::rect_json(key.bounds)}};
            if (key.has_pivot) k["pivot"] = {{"x", key.pivot.x}, {"y", key.pivot.y}};
            keys.push_back(std::move(k));
        }
        slices.push_back({{"name", s.name}, {"keys", std::move(keys)}});
    }
    sheet_json meta = {{"app", "grape"},
                 {"version", "1"},
                 {"image", sheet.image()},
                 {"format", "RGBA8888"},
                 {"size", {{"w", sheet.width()}, {"h", sheet.height()}}},
                 {"scale", detail::number_text(sheet.scale())},
                 {"frameTags", std::move(tags)},
                 {"layers", sheet_json::array()},
                 {"slices", std::move(slices)}};
    const sheet_json root = {{"frames", std::move(frames)}, {"meta", std::move(meta)}};
    return root.dump(1) + "\n";
}

}  // namespace grape
