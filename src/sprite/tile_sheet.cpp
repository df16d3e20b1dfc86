#include <grape/error.hpp>
#include <grape/sprite.hpp>

#include <cassert>
#include <string>

namespace grape {
namespace {

void require_positive(int value, const char* name) {
    if (value <= 0) throw Error(std::string("TileSheet: ") + name + " must be positive (got " + std::to_string(value) + ")");
}

void require_non_negative(int value, const char* name) {
    if (value < 0) {
        throw Error(std::string("TileSheet: ") + name + " must be >= 0 (got " + std::to_string(value) + ")");
    }
}

// The frame size along one axis: given, or derived exactly from the sheet size. 64-bit
// arithmetic so no int product overflows.
int frame_extent(int sheet, int cells, int margin, int spacing, int given, const char* sheet_name,
                 const char* cells_name, const char* frame_name) {
    const std::int64_t used_by_gaps = 2 * std::int64_t{margin} + (std::int64_t{cells} - 1) * spacing;
    if (given == 0) {
        const std::int64_t available = sheet - used_by_gaps;
        if (available < cells || available % cells != 0) {
            throw Error(std::string("TileSheet: ") + sheet_name + " " + std::to_string(sheet) + " leaves " +
                        std::to_string(available) + " pixels for " + std::to_string(cells) + " " + cells_name +
                        " after margin and spacing, not a whole positive " + frame_name + " (set " + frame_name +
                        ")");
        }
        return static_cast<int>(available / cells);
    }
    require_non_negative(given, frame_name);
    const std::int64_t needed = used_by_gaps + std::int64_t{cells} * given;
    if (needed > sheet) {
        throw Error(std::string("TileSheet: ") + std::to_string(cells) + " " + cells_name + " of " + frame_name +
                    " " + std::to_string(given) + " with margin and spacing need " + std::to_string(needed) +
                    " pixels, more than the " + sheet_name + " " + std::to_string(sheet));
    }
    return given;
}

}  // namespace

TileSheet::TileSheet(const TileSheetDef& def) : width_(def.width), height_(def.height) {
    require_positive(def.width, "width");
    require_positive(def.height, "height");
    require_positive(def.columns, "columns");
    require_positive(def.rows, "rows");
    require_non_negative(def.margin, "margin");
    require_non_negative(def.spacing, "spacing");
    require_non_negative(def.frame_count, "frame_count");
    const int fw = frame_extent(def.width, def.columns, def.margin, def.spacing, def.frame_width, "width", "columns",
                                "frame_width");
    const int fh = frame_extent(def.height, def.rows, def.margin, def.spacing, def.frame_height, "height", "rows",
                                "frame_height");
    const std::int64_t cells = std::int64_t{def.columns} * def.rows;
    if (def.frame_count > cells) {
        throw Error("TileSheet: frame_count " + std::to_string(def.frame_count) + " is more than columns*rows (" +
                    std::to_string(cells) + ")");
    }
    const std::int64_t count = def.frame_count == 0 ? cells : def.frame_count;
    frames_.reserve(static_cast<std::size_t>(count));
    for (std::int64_t k = 0; k < count; ++k) {
        const int column = static_cast<int>(k % def.columns);
        const int row = static_cast<int>(k / def.columns);
        frames_.push_back({def.margin + column * (fw + def.spacing), def.margin + row * (fh + def.spacing), fw, fh});
    }
}

TileSheet::TileSheet(int width, int height, std::vector<FrameRect> frames)
    : width_(width), height_(height), frames_(std::move(frames)) {
    require_positive(width, "width");
    require_positive(height, "height");
    if (frames_.empty()) throw Error("TileSheet: frames is empty; a sheet needs at least one frame");
    for (std::size_t k = 0; k < frames_.size(); ++k) {
        const FrameRect& r = frames_[k];
        const std::string name = "TileSheet: frames[" + std::to_string(k) + "] ";
        if (r.width <= 0 || r.height <= 0) {
            throw Error(name + "has size " + std::to_string(r.width) + "x" + std::to_string(r.height) +
                        "; width and height must be positive");
        }
        if (r.x < 0 || r.y < 0 || std::int64_t{r.x} + r.width > width || std::int64_t{r.y} + r.height > height) {
            throw Error(name + "at (" + std::to_string(r.x) + ", " + std::to_string(r.y) + ") size " +
                        std::to_string(r.width) + "x" + std::to_string(r.height) + " leaves the " +
                        std::to_string(width) + "x" + std::to_string(height) + " sheet");
        }
    }
}

const FrameRect& TileSheet::frame(std::size_t k) const noexcept {
    assert(k < frames_.size() && "TileSheet: frame index out of range");
    return frames_[k];
}

const FrameRect& TileSheet::at(std::size_t k) const {
    if (k >= frames_.size()) {
        throw Error("TileSheet::at: k " + std::to_string(k) + " is past the last frame (frame_count " +
                    std::to_string(frames_.size()) + ")");
    }
    return frames_[k];
}

UvRect TileSheet::uv(std::size_t k) const noexcept {
    const FrameRect& r = frame(k);
    const double w = width_;
    const double h = height_;
    return {r.x / w, r.y / h, (r.x + r.width) / w, (r.y + r.height) / h};
}

void TileSheetSprite::show_frame(std::size_t k) noexcept {
    const std::size_t n = sheet_->frame_count();
    frame_ = k < n ? k : n - 1;
}

}  // namespace grape
