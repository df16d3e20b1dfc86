// grape — sprite: play anything with frames at any real-valued rate, and cut tile sheets
// (sprite sheets and clips in sprite_sheet.hpp, included here).
//
//   grape::TileSheet sheet({.width = 256, .height = 64, .columns = 8, .rows = 2});
//   grape::TileSheetSprite hero(sheet);
//   grape::SpritePlayer player(hero, {.rate = 0.5});   // half speed
//   player.advance();                                   // once per game frame
//   draw(texture, hero.rect());                         // the render module's job
//
// SpritePlayer uses the seed's remainder algorithm: each step takes the integer part of the
// rate and accumulates the fraction in a remainder in (−1, 1) that carries ±1 frame when it
// reaches ±1, so no multiplication or modulo is needed and the frame after n steps is
// start + trunc(rate·n), wrapped: reverse play is the mirror image of forward play. It is
// exact for rates whose fractions add exactly in binary (0.5, 0.25, 1.375, …). For other rates
// each addition to the remainder rounds, so where rate·n lies within that accumulated rounding
// (about n·2⁻⁵³) of a whole number the frame can be one off trunc(rate·n), either way: 0.1
// trails by one at step 10 (ten additions give 0.999…9), 1/3 leads by one at step 3 (three
// additions of the stored 0.333…31 round up to 1).
#pragma once

#include <grape/export_sprite.hpp>
#include <grape/math.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grape {

/// \addtogroup sprite
/// @{

/// Anything with frames: a tile sheet, a list of images, a 3-D model's key poses.
class Playable {
public:
    virtual ~Playable() = default;
    /// Number of frames (at least 1; read by SpritePlayer when it is attached).
    virtual std::size_t frame_count() const noexcept = 0;
    /// Makes frame k (0-based, < frame_count()) the one shown.
    virtual void show_frame(std::size_t k) noexcept = 0;
};

/// What happens at the ends of the frame range.
enum class PlayMode : std::uint8_t {
    loop,       ///< wrap around at both ends (the seed's behaviour)
    once,       ///< stop at the last frame (first, when the rate is negative; start there) and report completion
    ping_pong,  ///< bounce between the ends: 0 1 2 3 2 1 0 1 …
};

/// How a SpritePlayer starts; fill with designated initializers.
struct SpritePlayerDef {
    /// Frames per step: 1 normal, 0.5 half speed, −2 reverse at double speed. Must be finite;
    /// |rate| is capped just below the frame count (see SpritePlayer::set_rate).
    double rate = 1.0;
    /// Behaviour at the ends.
    PlayMode mode = PlayMode::loop;
    /// First frame shown (< frame count).
    std::size_t start_frame = 0;
};

/// Advances a Playable (or a bare frame counter) by a real-valued rate per step.
/// Stepping is noexcept and allocation-free; callbacks are stored apart from the hot state.
class GRAPE_SPRITE_API SpritePlayer {
public:
    /// Called with each frame the playback enters, in order of travel, frames skipped over
    /// by a fast rate included (at most one full cycle per advance call).
    using FrameCallback = std::function<void(std::size_t frame)>;
    /// Called when a PlayMode::once playback reaches its end and stops.
    using CompleteCallback = std::function<void()>;
    /// Called after an advance that completed loop or ping-pong cycles, as Animation::on_loop
    /// is called when plays begin: `cycle` counts the cycles completed since the callback was
    /// set (1, 2, …; saturating), `skipped` how many this advance completed before `cycle`
    /// without a call of their own (0 unless a time-based advance spans several cycles).
    using LoopCallback = std::function<void(std::size_t cycle, std::size_t skipped)>;
    // Callbacks run after the player's state is final for the step; they may change the
    // player (rate, frame, mode, callbacks) but must not destroy it, and must not throw.

    /// Plays `playable`, which must outlive the player (or be replaced by set_playable).
    /// Shows the start frame. Throws grape::Error for a playable with no frames, a
    /// non-finite rate or a start frame past the end.
    explicit SpritePlayer(Playable& playable, const SpritePlayerDef& def = {});
    /// A player with no Playable, only a frame counter of `frame_count` frames (read frame()).
    /// Throws grape::Error as above and when frame_count is 0.
    explicit SpritePlayer(std::size_t frame_count, const SpritePlayerDef& def = {});
    SpritePlayer(const SpritePlayer& other);  ///< the same state, playable and callbacks (copied)
    SpritePlayer& operator=(const SpritePlayer& other);  ///< as the copy constructor
    SpritePlayer(SpritePlayer&&) noexcept;  ///< takes the state and callbacks; the source keeps its state and playable, without callbacks
    SpritePlayer& operator=(SpritePlayer&&) noexcept;  ///< as the move constructor, after dropping this player's callbacks
    ~SpritePlayer();

    /// One step at the rate: the seed's algorithm (additions and comparisons only). Inline:
    /// a looping player without callbacks steps without a call.
    void advance() noexcept;
    /// Time-based play: moves rate·fps·dt frames (dt in seconds ≥ 0, fps > 0 the sheet's
    /// frame rate at rate 1) with the same remainder bookkeeping. Throws grape::Error for a
    /// negative or non-finite dt or a non-positive or non-finite fps.
    void advance(double dt, double fps);

    /// The frame shown now (0-based).
    std::size_t frame() const noexcept;
    /// The accumulated fraction of a frame, in (−1, 1).
    double remainder() const noexcept { return remainder_; }
    /// Frames per step (after the cap).
    double rate() const noexcept { return static_cast<double>(whole_) + fraction_; }  // exact
    /// Sets the rate. A rate at or beyond ±frame_count is clamped to the largest magnitude
    /// below it (a slider or a time scale pushed too far keeps playing at the fastest rate
    /// the algorithm supports instead of stopping the game); a NaN or infinite rate throws
    /// grape::Error. The remainder is kept so a rate change does not jump.
    void set_rate(double rate);
    /// The behaviour at the ends.
    PlayMode mode() const noexcept { return mode_; }
    /// Changes the behaviour at the ends (keeps the frame shown).
    void set_mode(PlayMode mode) noexcept;
    /// Number of frames of the playable (at most 2^30).
    std::size_t frame_count() const noexcept { return static_cast<std::size_t>(frame_count_); }

    /// Jumps to frame k and clears the remainder (ping-pong resumes on its forward leg);
    /// throws grape::Error when k >= frame_count().
    void set_frame(std::size_t k);
    /// False once a PlayMode::once playback has finished or after pause().
    bool playing() const noexcept { return playing_; }
    /// Stops advancing (advance() does nothing) until play().
    void pause() noexcept {
        playing_ = false;
        plain_ = false;
    }
    /// Resumes; a finished once playback restarts from its beginning (frame 0, or the last
    /// frame when the rate is negative).
    void play() noexcept;

    /// Attaches another playable (frame count re-read; frame clamped into range and shown).
    /// Throws grape::Error when it has no frames.
    void set_playable(Playable& playable);
    /// The playable, or nullptr for a bare frame counter.
    Playable* playable() const noexcept;

    /// Sets the frame callback (empty to remove).
    void on_frame(FrameCallback callback);
    /// Sets the completion callback of PlayMode::once (empty to remove).
    void on_complete(CompleteCallback callback);
    /// Sets the callback for completed loop or ping-pong cycles (empty to remove); its cycle
    /// count starts again from 0.
    void on_loop(LoopCallback callback);
    /// The same without `skipped`.
    void on_loop(std::function<void(std::size_t cycle)> callback);

private:
    struct Callbacks;
    void advance_general() noexcept;
    void refresh() noexcept { plain_ = mode_ == PlayMode::loop && playing_ && !has_callbacks(); }
    bool has_callbacks() const noexcept { return (link_ & 1u) != 0; }
    Callbacks* callbacks_block() const noexcept { return reinterpret_cast<Callbacks*>(link_ & ~std::uintptr_t{1}); }
    Playable* playable_ptr() const noexcept;   // the playable, wherever link_ keeps it
    void set_shown(Playable* playable) noexcept;
    void release_callbacks() noexcept;
    void init(std::size_t frame_count, const SpritePlayerDef& def);
    void move_by(std::int64_t delta, std::size_t extra_cycles, std::int64_t direction) noexcept;
    void set_rate_parts(double rate) noexcept;
    void report(std::int64_t target, std::int64_t steps, std::int64_t direction, std::size_t cycles,
                bool completed) noexcept;
    std::int64_t period() const noexcept;
    std::size_t frame_at(std::int64_t position) const noexcept;
    Callbacks& callbacks();

    // Hot state first and small (40 bytes), so a million players stream through the cache:
    // 32-bit frame numbers (frame counts are capped at 2^30), the rate kept as its exact
    // integer and fractional parts, and one word for the playable and the callbacks.
    std::int32_t position_ = 0;     // frame (loop, once) or place on the 0 … 2n−3 ping-pong cycle
    std::int32_t frame_count_ = 1;
    std::int32_t whole_ = 0;        // trunc(rate)
    PlayMode mode_ = PlayMode::loop;
    bool playing_ = true;
    bool finished_ = false;         // a once playback reached its end
    bool plain_ = true;             // looping, playing, no callbacks: the inline step applies
    double fraction_ = 0.0;         // rate − trunc(rate), exact
    double remainder_ = 0.0;        // in (−1, 1)
    // The Playable (or 0) while no callback is set; then the Callbacks block, which holds the
    // playable, with bit 0 set (both are at least 8-byte aligned). The inline step runs only
    // without callbacks (plain_), so it reads the playable straight from here.
    std::uintptr_t link_ = 0;
};

// The common case inline: looping, playing, no callbacks. The carry and the wrap are selects,
// not branches: with many players at different rates they are unpredictable.
inline void SpritePlayer::advance() noexcept {
    if (!plain_) {
        advance_general();
        return;
    }
    const double r = remainder_ + fraction_;  // in (−2, 2)
    const int carry = static_cast<int>(r >= 1.0) - static_cast<int>(r <= -1.0);
    remainder_ = r - static_cast<double>(carry);  // exact (Sterbenz)
    // |whole_ + carry| ≤ frame count (the rate is capped below it), so one wrap each way
    // suffices; the wraps are masks (compilers turn `next < 0 ? n : 0` into a branch).
    std::int32_t next = position_ + whole_ + carry;
    next += (next >> 31) & frame_count_;
    next -= frame_count_ & -static_cast<std::int32_t>(next >= frame_count_);
    // One branch, never taken without a playable, so a bare counter predicts it.
    Playable* const playable = reinterpret_cast<Playable*>(link_);  // plain_: no callbacks, no tag
    if ((playable != nullptr) & (next != position_)) playable->show_frame(static_cast<std::size_t>(next));
    position_ = next;
}

/// A frame's rectangle on the sheet, in pixels (integers: texture texels), y down.
struct FrameRect {
    int x = 0;       ///< left edge, pixels
    int y = 0;       ///< top edge, pixels
    int width = 0;   ///< pixels
    int height = 0;  ///< pixels
    friend bool operator==(const FrameRect&, const FrameRect&) = default;  ///< all four fields equal
};

/// A frame's rectangle in normalized texture coordinates [0, 1] (for GPU renderers).
struct UvRect {
    double u0 = 0.0;  ///< left
    double v0 = 0.0;  ///< top
    double u1 = 0.0;  ///< right
    double v1 = 0.0;  ///< bottom
};

/// A regular grid of frames on a sheet; fill with designated initializers.
struct TileSheetDef {
    int width = 0;         ///< sheet width, pixels
    int height = 0;        ///< sheet height, pixels
    int columns = 1;       ///< frames across
    int rows = 1;          ///< frames down
    int margin = 0;        ///< pixels between the sheet's edge and the outer frames
    int spacing = 0;       ///< pixels between neighbouring frames
    int frame_width = 0;   ///< pixels; 0: derived, (width − 2·margin − (columns−1)·spacing) / columns exactly
    int frame_height = 0;  ///< pixels; 0: derived like frame_width
    int frame_count = 0;   ///< frames used, row by row; 0: columns·rows (a last row may be partial)
};

/// A sheet image cut into frame rectangles, row by row (left to right, top to bottom), or
/// from a list of rectangles (a packed atlas). Immutable once built.
class GRAPE_SPRITE_API TileSheet {
public:
    /// Cuts a regular grid; throws grape::Error naming the field and the reason when a size
    /// is not positive, the frames do not fit the sheet, or a derived frame size is not whole.
    explicit TileSheet(const TileSheetDef& def);
    /// Uses the given rectangles on a width × height sheet; throws grape::Error when the list
    /// is empty or a rectangle is empty or leaves the sheet (naming its index).
    TileSheet(int width, int height, std::vector<FrameRect> frames);

    /// Sheet width, pixels.
    int width() const noexcept { return width_; }
    /// Sheet height, pixels.
    int height() const noexcept { return height_; }
    /// Number of frames.
    std::size_t frame_count() const noexcept { return frames_.size(); }
    /// Frame k's rectangle (k < frame_count(); asserted in debug builds).
    const FrameRect& frame(std::size_t k) const noexcept;
    /// Frame k's rectangle, checked: throws grape::Error when k >= frame_count().
    const FrameRect& at(std::size_t k) const;
    /// Frame k's rectangle in texture coordinates (k < frame_count()).
    UvRect uv(std::size_t k) const noexcept;
    /// Every frame.
    std::span<const FrameRect> frames() const noexcept { return frames_; }

private:
    int width_ = 0;
    int height_ = 0;
    std::vector<FrameRect> frames_;
};

/// A Playable over a TileSheet: its current frame is a rectangle of the sheet. The sheet
/// must outlive the sprite (many sprites share one sheet).
class GRAPE_SPRITE_API TileSheetSprite : public Playable {
public:
    /// Shows frame 0 of `sheet`.
    explicit TileSheetSprite(const TileSheet& sheet) noexcept : sheet_(&sheet) {}

    std::size_t frame_count() const noexcept override { return sheet_->frame_count(); }
    /// Shows frame k (clamped to the last frame, so a stale index never reads past the sheet).
    void show_frame(std::size_t k) noexcept override;
    /// The frame shown.
    std::size_t current_frame() const noexcept { return frame_; }
    /// The rectangle of the frame shown, pixels.
    const FrameRect& rect() const noexcept { return sheet_->frame(frame_); }
    /// The rectangle of the frame shown, texture coordinates.
    UvRect uv() const noexcept { return sheet_->uv(frame_); }
    /// The sheet.
    const TileSheet& sheet() const noexcept { return *sheet_; }

private:
    const TileSheet* sheet_;
    std::size_t frame_ = 0;
};

/// @}

}  // namespace grape

// Sprite sheets and their clip player are built on these frames; this header keeps offering them.
#include <grape/sprite_sheet.hpp>
