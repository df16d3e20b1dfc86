// grape — sprite sheets and clips: frames with their own durations, clips, slices, ClipPlayer.
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

#include <grape/export_sprite.hpp>
#include <grape/sprite.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grape {

/// \addtogroup sprite
/// @{

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
    int offset_x = 0;          ///< left of the trimmed pixels in the untrimmed image, pixels (spriteSourceSize.x; any sign for an untrimmed frame that keeps its position)
    int offset_y = 0;          ///< top of the trimmed pixels in the untrimmed image, pixels (spriteSourceSize.y; likewise)
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
    double scale = 1.0;               ///< the art's scale on the sheet (TexturePacker's meta.scale, > 0): 0.5 for an @1x sheet of @2x art
    std::vector<SpriteFrame> frames{};  ///< at least one
    std::vector<SpriteClip> clips{};    ///< named clips ("" names allowed; the first of a name wins)
    std::vector<SpriteSlice> slices{};  ///< named regions
};

/// A sheet of frames with durations, clips and slices. Immutable once built.
class GRAPE_SPRITE_API SpriteSheet {
public:
    /// Checks and keeps `def`: throws grape::Error naming the field (frames[3].duration_ms, …)
    /// when the sheet is empty, a trimmed frame leaves the sheet or its untrimmed image, a
    /// duration is not positive and finite, the scale is not positive and finite, or a clip or
    /// slice key names a frame past the end. A frame that is its whole untrimmed image may sit
    /// at any offset (TexturePacker's "crop, keep position"). A source size of 0 becomes the
    /// frame's own size.
    explicit SpriteSheet(SpriteSheetDef def);

    /// The sheet picture's name, as the data gave it.
    const std::string& image() const noexcept { return def_.image; }
    /// Sheet width, pixels.
    int width() const noexcept { return def_.width; }
    /// Sheet height, pixels.
    int height() const noexcept { return def_.height; }
    /// The art's scale on the sheet: every pixel value of the sheet is in the sheet picture's
    /// pixels; divide by scale for the art's own pixels (1 unless the packer scaled it).
    double scale() const noexcept { return def_.scale; }
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
class GRAPE_SPRITE_API ClipPlayer {
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

/// @}

}  // namespace grape
