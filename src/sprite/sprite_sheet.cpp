// SpriteSheet: checks a sheet's frames, clips and slices once, so players and renderers can
// index them without checks.
#include <grape/error.hpp>
#include <grape/sprite.hpp>

#include <cassert>
#include <cmath>
#include <string>

namespace grape {
namespace {

std::string at(const char* list, std::size_t k, const char* field) {
    return std::string("SpriteSheet: ") + list + "[" + std::to_string(k) + "]." + field + " ";
}

}  // namespace

SpriteSheet::SpriteSheet(SpriteSheetDef def) : def_(std::move(def)) {
    if (def_.width <= 0 || def_.height <= 0) {
        throw Error("SpriteSheet: width and height must be positive (got " + std::to_string(def_.width) + "x" +
                    std::to_string(def_.height) + ")");
    }
    if (def_.frames.empty()) throw Error("SpriteSheet: frames is empty; a sheet needs at least one frame");
    if (!(std::isfinite(def_.scale) && def_.scale > 0.0)) {
        throw Error("SpriteSheet: scale must be positive and finite (got " + detail::number_text(def_.scale) + ")");
    }
    for (std::size_t k = 0; k < def_.frames.size(); ++k) {
        SpriteFrame& f = def_.frames[k];
        const FrameRect& r = f.rect;
        if (r.width <= 0 || r.height <= 0) {
            throw Error(at("frames", k, "rect") + "has size " + std::to_string(r.width) + "x" +
                        std::to_string(r.height) + "; width and height must be positive");
        }
        if (r.x < 0 || r.y < 0 || std::int64_t{r.x} + r.width > def_.width ||
            std::int64_t{r.y} + r.height > def_.height) {
            throw Error(at("frames", k, "rect") + "at (" + std::to_string(r.x) + ", " + std::to_string(r.y) +
                        ") size " + std::to_string(r.width) + "x" + std::to_string(r.height) + " leaves the " +
                        std::to_string(def_.width) + "x" + std::to_string(def_.height) + " sheet");
        }
        if (f.source_width == 0) f.source_width = f.width();
        if (f.source_height == 0) f.source_height = f.height();
        // Pixels that are the whole untrimmed image can be placed anywhere ("crop, keep
        // position": the crop drawn where it was in the art); trimmed pixels lie inside it.
        if (f.trimmed() && (f.offset_x < 0 || f.offset_y < 0 || std::int64_t{f.offset_x} + f.width() > f.source_width ||
                            std::int64_t{f.offset_y} + f.height() > f.source_height)) {
            throw Error(at("frames", k, "offset") + "(" + std::to_string(f.offset_x) + ", " +
                        std::to_string(f.offset_y) + ") puts its " + std::to_string(f.width()) + "x" +
                        std::to_string(f.height()) + " pixels outside the " + std::to_string(f.source_width) +
                        "x" + std::to_string(f.source_height) + " untrimmed image");
        }
        if (!(std::isfinite(f.duration_ms) && f.duration_ms > 0.0)) {
            throw Error(at("frames", k, "duration_ms") + "must be positive and finite (got " +
                        detail::number_text(f.duration_ms) + ")");
        }
        if (!(std::isfinite(f.pivot.x) && std::isfinite(f.pivot.y))) {
            throw Error(at("frames", k, "pivot") + "must be finite");
        }
    }
    const std::size_t n = def_.frames.size();
    for (std::size_t k = 0; k < def_.clips.size(); ++k) {
        const SpriteClip& c = def_.clips[k];
        if (c.from > c.to || c.to >= n) {
            throw Error(at("clips", k, "to") + std::to_string(c.to) + " (from " + std::to_string(c.from) +
                        ") must satisfy from <= to < frame count " + std::to_string(n));
        }
        if (c.repeat < 0) {
            throw Error(at("clips", k, "repeat") + "must be >= 0 (got " + std::to_string(c.repeat) + ")");
        }
    }
    for (std::size_t k = 0; k < def_.slices.size(); ++k) {
        for (const SliceKey& key : def_.slices[k].keys) {
            if (key.frame >= n) {
                throw Error(at("slices", k, "keys") + "names frame " + std::to_string(key.frame) +
                            ", past the last frame (frame count " + std::to_string(n) + ")");
            }
        }
    }
}

const SpriteFrame& SpriteSheet::frame(std::size_t k) const noexcept {
    assert(k < def_.frames.size() && "SpriteSheet: frame index out of range");
    return def_.frames[k];
}

std::size_t SpriteSheet::clip_index(std::string_view name) const {
    for (std::size_t k = 0; k < def_.clips.size(); ++k) {
        if (def_.clips[k].name == name) return k;
    }
    std::string names;
    for (const SpriteClip& c : def_.clips) names += (names.empty() ? "" : ", ") + ("'" + c.name + "'");
    throw Error("SpriteSheet: no clip named '" + std::string(name) + "' (clips: " +
                (names.empty() ? std::string("none") : names) + ")");
}

const SliceKey* SpriteSheet::slice_key(std::string_view name, std::size_t k) const noexcept {
    for (const SpriteSlice& s : def_.slices) {
        if (s.name != name) continue;
        const SliceKey* found = nullptr;
        for (const SliceKey& key : s.keys) {
            if (key.frame <= k && (!found || key.frame >= found->frame)) found = &key;
        }
        return found;
    }
    return nullptr;
}

TileSheet SpriteSheet::tile_sheet() const {
    std::vector<FrameRect> rects;
    rects.reserve(def_.frames.size());
    for (const SpriteFrame& f : def_.frames) rects.push_back(f.rect);
    return TileSheet(def_.width, def_.height, std::move(rects));
}

}  // namespace grape
