// grape — sprite: play anything with frames at any real-valued rate, and cut tile sheets.
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
//
// Sheets from the tools artists use (see docs/sprite-sheets.md): a SpriteSheet holds packed or
// trimmed frames with their own durations, named clips (Aseprite's tags) with a direction and
// a repeat count, and slices with pivots; a ClipPlayer plays a clip at any real rate:
//
//   grape::SpriteSheet sheet = grape::load_sprite_sheet_file("hero.json");   // grape/sprite_sheet_json.hpp
//   grape::ClipPlayer player(sheet, "walk", {.rate = 0.5});
//   player.advance(dt);                                      // seconds of game time
//   draw(sheet.frame(player.frame()));                       // trimmed offset, pivot, rotation
#pragma once

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
class SpritePlayer {
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
    SpritePlayer(const SpritePlayer& other);
    SpritePlayer& operator=(const SpritePlayer& other);
    SpritePlayer(SpritePlayer&&) noexcept;
    SpritePlayer& operator=(SpritePlayer&&) noexcept;
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
    friend bool operator==(const FrameRect&, const FrameRect&) = default;
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
class TileSheet {
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
class TileSheetSprite : public Playable {
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

/// How a clip runs through its frames: Aseprite's tag directions.
enum class ClipDirection : std::uint8_t {
    forward,            ///< from, from+1, …, to
    reverse,            ///< to, to−1, …, from
    ping_pong,          ///< from … to, then back to from+1, …: each pass is one direction
    ping_pong_reverse,  ///< to … from, then back to to−1, …
};

/// One frame of a sprite sheet: where its pixels are, where they sit in the untrimmed image,
/// how long it shows. Fill with designated initializers.
struct SpriteFrame {
    std::string name{};          ///< the exporter's key or file name ("" allowed)
    FrameRect rect{};            ///< its pixels on the sheet; for a rotated frame the turned region (rect.width = height())
    bool rotated = false;      ///< stored turned 90° clockwise on the sheet (TexturePacker): its top-left pixel is the region's top-right
    int offset_x = 0;          ///< left of the trimmed pixels in the untrimmed image, pixels (spriteSourceSize.x)
    int offset_y = 0;          ///< top of the trimmed pixels in the untrimmed image, pixels (spriteSourceSize.y)
    int source_width = 0;      ///< untrimmed image width, pixels (sourceSize.w); 0: width()
    int source_height = 0;     ///< untrimmed image height, pixels (sourceSize.h); 0: height()
    double duration_ms = 100;  ///< how long it shows at rate 1, milliseconds (> 0)
    Vec2 pivot{};                ///< the point placed at the sprite's position, pixels of the untrimmed image from its top-left

    /// Width as drawn (upright), pixels.
    int width() const noexcept { return rotated ? rect.height : rect.width; }
    /// Height as drawn (upright), pixels.
    int height() const noexcept { return rotated ? rect.width : rect.height; }
    /// True when transparent borders were cut away (the trimmed pixels are smaller than the image).
    bool trimmed() const noexcept { return width() != source_width || height() != source_height; }
};

/// A named run of frames: an Aseprite tag, a Godot SpriteFrames animation.
struct SpriteClip {
    std::string name{};                                 ///< as the sheet names it
    std::size_t from = 0;                             ///< first frame (sheet index)
    std::size_t to = 0;                               ///< last frame, inclusive (≥ from)
    ClipDirection direction = ClipDirection::forward; ///< order of the frames
    int repeat = 0;                                   ///< passes, then stop; 0 forever (a ping-pong pass is one direction)

    /// Number of frames, to − from + 1.
    std::size_t length() const noexcept { return to - from + 1; }
};

/// A slice's rectangle from one frame on (Aseprite slice keys), with an optional pivot.
struct SliceKey {
    std::size_t frame = 0;   ///< first frame it applies to (until the next key)
    FrameRect bounds{};        ///< pixels of the untrimmed image
    bool has_pivot = false;  ///< whether `pivot` is set
    Vec2 pivot{};              ///< pixels from bounds' top-left (Aseprite's convention)
};

/// A named region of the untrimmed image over the frames: a hit box, a pivot, a 9-slice.
struct SpriteSlice {
    std::string name{};            ///< as the sheet names it
    std::vector<SliceKey> keys{};  ///< by increasing frame; the first applies from its frame on
};

/// What a SpriteSheet holds; fill with designated initializers.
struct SpriteSheetDef {
    std::string image{};                ///< the sheet picture, as the data names it ("" unknown)
    int width = 0;                    ///< sheet width, pixels (> 0)
    int height = 0;                   ///< sheet height, pixels (> 0)
    std::vector<SpriteFrame> frames{};  ///< at least one
    std::vector<SpriteClip> clips{};    ///< named clips ("" names allowed; the first of a name wins)
    std::vector<SpriteSlice> slices{};  ///< named regions
};

/// A sheet of frames with durations, clips and slices. Immutable once built.
class SpriteSheet {
public:
    /// Checks and keeps `def`: throws grape::Error naming the field (frames[3].duration_ms, …)
    /// when the sheet is empty, a frame leaves the sheet or its untrimmed image, a duration is
    /// not positive and finite, or a clip or slice key names a frame past the end. A source
    /// size of 0 becomes the frame's own size.
    explicit SpriteSheet(SpriteSheetDef def);

    /// The sheet picture's name, as the data gave it.
    const std::string& image() const noexcept { return def_.image; }
    /// Sheet width, pixels.
    int width() const noexcept { return def_.width; }
    /// Sheet height, pixels.
    int height() const noexcept { return def_.height; }
    /// Number of frames.
    std::size_t frame_count() const noexcept { return def_.frames.size(); }
    /// Frame k (k < frame_count(); asserted in debug builds).
    const SpriteFrame& frame(std::size_t k) const noexcept;
    /// Every frame.
    std::span<const SpriteFrame> frames() const noexcept { return def_.frames; }
    /// Every clip.
    std::span<const SpriteClip> clips() const noexcept { return def_.clips; }
    /// The index of the first clip called `name`; throws grape::Error listing the clip names.
    std::size_t clip_index(std::string_view name) const;
    /// Every slice.
    std::span<const SpriteSlice> slices() const noexcept { return def_.slices; }
    /// The key of slice `name` in effect at frame k; nullptr when there is no such slice or no
    /// key at or before k.
    const SliceKey* slice_key(std::string_view name, std::size_t k) const noexcept;
    /// The frames' rectangles as a TileSheet (for code that draws TileSheetSprites).
    TileSheet tile_sheet() const;

private:
    SpriteSheetDef def_;
};

/// When ClipPlayer::play switches clips.
enum class ClipSwitch : std::uint8_t {
    now,          ///< at once, from the new clip's start (its end when the rate is negative)
    at_loop_end,  ///< when the current pass ends (or the clip completes), carrying the time left over
};

/// What a ClipEvent reports.
enum class ClipEventKind : std::uint8_t {
    frame,     ///< a frame was entered
    loop,      ///< a pass ended and the next began (count of them: `count`)
    complete,  ///< a clip with a repeat count reached its end and stopped
    switched,  ///< a clip queued with ClipSwitch::at_loop_end took over
};

/// One event of a ClipPlayer, delivered in order of travel.
struct ClipEvent {
    ClipEventKind kind = ClipEventKind::frame;  ///< what happened
    std::size_t frame = 0;                      ///< the sheet frame shown after it
    std::size_t clip = 0;                       ///< the clip playing after it (sheet index)
    std::int64_t pass = 0;                      ///< the pass now playing: 0 first, counting on (down, going backwards)
    std::int64_t count = 1;                     ///< loop: passes ended at once (more than 1 only after a very long step)
};

/// How a ClipPlayer starts; fill with designated initializers.
struct ClipPlayerDef {
    /// Speed: 1 normal, 0.5 half, −2 backwards at double speed (any finite value).
    double rate = 1.0;
};

/// Plays a SpriteSheet's clips with their per-frame durations at a real-valued rate. The
/// rate scales time; the time into the current frame is carried as a remainder across frame
/// boundaries (nothing is lost or rounded away at a frame change), so with binary-exact steps
/// (1/64 s, rate 0.5, whole-millisecond durations) the frame at each step is exactly the one the
/// elapsed time falls in. Events report every frame entered, in order of travel, loops and
/// completion; one advance walks at most max(2 periods, 65,536 frames) and counts the whole
/// periods beyond that in one loop event. advance is noexcept apart from its argument check and
/// allocation-free.
class ClipPlayer {
public:
    /// Receives the player's events; may call play, set_rate, pause or on_event, must not
    /// destroy the player, must not throw.
    using EventCallback = std::function<void(const ClipEvent& event)>;

    /// Plays clip `clip` of `sheet` (which must outlive the player) from its start, or from its
    /// end when the rate is negative. Throws grape::Error for an unknown clip or a non-finite rate.
    ClipPlayer(const SpriteSheet& sheet, std::string_view clip, const ClipPlayerDef& def = {});
    /// The same, by the clip's index in sheet.clips().
    ClipPlayer(const SpriteSheet& sheet, std::size_t clip, const ClipPlayerDef& def = {});

    /// Moves rate·dt seconds along the clip (dt ≥ 0 and finite, else grape::Error). Inline: a
    /// step that stays in the frame is an add and a compare.
    void advance(double dt);
    /// Switches to clip `clip` (now, or when the current pass ends); throws grape::Error for
    /// an unknown clip. Playing the clip already playing with ClipSwitch::now restarts it.
    void play(std::string_view clip, ClipSwitch when = ClipSwitch::now);
    /// The same, by index.
    void play(std::size_t clip, ClipSwitch when = ClipSwitch::now);

    /// The sheet frame shown (index into sheet().frames()).
    std::size_t frame() const noexcept { return frame_; }
    /// The clip playing (index into sheet().clips()).
    std::size_t clip() const noexcept { return clip_; }
    /// Place in the clip's playback: 0 its first frame, counting every frame shown.
    std::int64_t step() const noexcept { return step_; }
    /// The pass playing (0 first; see ClipEvent::pass).
    std::int64_t pass() const noexcept;
    /// Milliseconds into the current frame, in [0, its duration] (the duration only at the end).
    double time_in_frame_ms() const noexcept { return time_; }
    /// The rate.
    double rate() const noexcept { return rate_; }
    /// Sets the rate (any finite value; grape::Error otherwise). Time already in the frame is kept.
    void set_rate(double rate);
    /// False when paused or when a clip with a repeat count has completed.
    bool playing() const noexcept { return playing_ && !finished_; }
    /// True once a clip with a repeat count has reached its end (until play()).
    bool finished() const noexcept { return finished_; }
    /// Stops advancing until resume().
    void pause() noexcept { playing_ = false; }
    /// Continues after pause() (a finished clip stays finished; play() restarts it).
    void resume() noexcept { playing_ = true; }
    /// The sheet.
    const SpriteSheet& sheet() const noexcept { return *sheet_; }
    /// Sets the event callback (empty to remove).
    void on_event(EventCallback callback);

private:
    [[noreturn]] static void bad_dt(double dt);
    void advance_across(double delta);
    void start(std::size_t clip, bool at_end) noexcept;
    std::size_t frame_at(std::int64_t step) const noexcept;
    std::size_t frame_in_period(std::int64_t place) const noexcept;
    std::int64_t pass_of(std::int64_t step) const noexcept;
    void enter(std::int64_t step) noexcept;
    void take_queued(bool forward, double over) noexcept;
    void fold(bool forward) noexcept;
    void walk(bool forward) noexcept;
    void emit(ClipEventKind kind, std::int64_t count = 1) noexcept;

    const SpriteSheet* sheet_;
    double time_ = 0.0;         // ms into the current frame
    double duration_ = 1.0;     // ms of the current frame
    double rate_ = 1.0;
    std::int64_t step_ = 0;     // frames shown since the clip's start (negative: before it, going backwards)
    std::int64_t steps_ = -1;   // frames in a finite playback; −1 forever
    std::int64_t period_ = 1;   // frames in one period of the looping sequence
    std::int64_t period_place_ = 0;  // step_ modulo period_
    double period_ms_ = 0.0;    // its duration
    double fold_ms_ = 0.0;      // a step beyond this counts whole periods instead of walking them
    std::size_t frame_ = 0;
    std::size_t clip_ = 0;
    std::size_t first_ = 0;     // clip's from
    std::size_t length_ = 1;    // clip's length
    std::size_t queued_ = 0;    // clip to switch to at the end of the pass
    ClipDirection direction_ = ClipDirection::forward;
    bool bounce_ = false;       // ping-pong over two frames or more
    bool has_queued_ = false;
    bool playing_ = true;
    bool finished_ = false;
    std::uint64_t callback_generation_ = 0;  // bumped by on_event, so a callback may replace itself
    EventCallback callback_;
};

// Forwards a frame holds [0, d) of its time, backwards (0, d]; time_ is always in [0, d].
inline void ClipPlayer::advance(double dt) {
    if (!(dt >= 0.0 && dt <= 1.7976931348623157e308)) bad_dt(dt);  // negative, NaN or infinite
    if (!playing_ || finished_) return;
    const double delta = rate_ * dt * 1000.0;  // milliseconds of clip time
    const double t = time_ + delta;
    // Strictly inside either way (time_ ∈ [0, d], so t > 0 going forwards and t < d going
    // backwards anyway): one test for both directions, which a mix of rates predicts.
    if (t > 0.0 && t < duration_) {
        time_ = t;
        return;
    }
    if (delta != 0.0) advance_across(delta);
}

}  // namespace grape
