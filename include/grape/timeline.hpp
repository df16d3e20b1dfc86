// grape — timelines: animations, nested timelines, callbacks, labels and gaps placed in time,
// played as one (delay, repeat, repeat delay, yoyo, time scale, pause, seek, run-time reverse).
//
//   grape::Timeline intro = engine.create_timeline({.repeat = 1, .yoyo = true});
//   intro.add(engine.create_2d_animation(logo, slide_in, 1.0))          // at 0
//        .label("shown")                                                 // at 1
//        .add(engine.create_2d_animation(title, drop, 0.5), "<+0.25")    // with the slide, ¼ s in
//        .call([] { play_sound("ding"); }, "shown+0.5")
//        .add(engine.create_2d_animation(logo, wobble, 0.3), ">");       // after the title
//
// A child's time is a pure function of its timeline's time, so ticking any dt sequence lands
// where seek gives the same time. An animation placed in a timeline is driven by it (the
// engine no longer ticks it on its own; pause, resume, seek and set_time_scale on it are
// ignored; it stays alive when it ends, to be played again): before its start it rests at its
// start, after its end at its end. It plays from its beginning, its own delay, repeats and
// time scale included; its length in the timeline is its end_time.
//
// Positions (see timeline_layout.hpp) resolve when a child is added: "the end so far", ">"
// and "<" refer to what was added before it, a label to one added before it.
//
// Events. Timelines: on_start (a play from the start begins, after the delay), on_update
// (after every change of time), on_loop(play) (a new play begins, after its repeat delay, up
// to max_loop_events per tick as for animations; going forward only: playing backward crosses
// plays without loop events, as an animation reversed at run time does), on_complete (the end of the last play is
// reached going forward), on_reverse_complete (the start is reached going backward). Children
// and callbacks inside one update fire in time order in the direction of travel: at equal
// times, children ending first, then callbacks, then children starting (the mirror going
// backward); the children running meanwhile are brought to each such point before it fires,
// so a nested timeline's callbacks and a child animation's events come in time order with
// their parent's. Two nested timelines running side by side are brought to a point one after
// the other: within one update, the first one's events up to that point come before the
// second one's. Each callback fires once per crossing (forward: when time reaches it; backward:
// when time goes back to it), also when one large dt crosses many. A yoyo play running back
// crosses its callbacks backward. Work per update is bounded as for loop events: an update
// that starts more than max_loop_events plays of one timeline (either way) fires what it
// crosses in the play it leaves and in the play it reaches, and crosses the plays between
// silently (their callbacks and children's events do not fire; their state is reached).
// Children that are animations fire their on_start, on_loop, on_complete and
// on_reverse_complete as the timeline drives them across those points, not dying at their
// end.
//
// Handlers may create, kill, pause, seek or reverse anything, this timeline included. A
// handler that seeks, pauses, reverses, re-times or kills a timeline ends that timeline's
// update (the rest of that dt is dropped for it): it keeps the time its update had reached
// (the point where the handler ran; the end of that tick's step when the handler ran inside
// a child running across it), and whatever in it had not been brought there yet goes there
// silently, so its state is the one seek gives for that time. Adding children from a handler
// applies at once (a longer play moves where the time falls in it, not the time). Nested timelines are driven by their parent: pause,
// resume, seek, reverse, play and set_time_scale on them are ignored.
//
// Cost: a tick walks the top-level timelines; each advances only its children that are
// active now (kept sorted by start and by end, with an active window), plus those whose start
// or end the tick crosses; a loop resets the children once. No allocation per tick. A timeline
// with no on_update handler and no nested timeline, whose time stays inside one play and
// crosses no child start or end nor callback, with at most one animation active (a plain one:
// no on_update, N-D or linked target), takes a fast path over a dense per-timeline entry that
// gives the same bits as the general update; those timelines run no handler in that tick, so
// a handler of another timeline may find them already advanced.
#pragma once

#include <grape/anim.hpp>
#include <grape/export_anim.hpp>
#include <grape/timeline_layout.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace grape {

/// \addtogroup timeline
/// @{

/// How a timeline plays; fill with designated initializers: `{.repeat = -1, .yoyo = true}`.
struct TimelineDef {
    double delay = 0.0;         ///< seconds (timeline time) before the first play; ≥ 0
    int repeat = 0;             ///< extra plays after the first: 0 plays once, −1 forever
    double repeat_delay = 0.0;  ///< seconds between plays, holding the end of the last one; ≥ 0
    bool yoyo = false;          ///< every second play runs backwards
    double time_scale = 1.0;    ///< timeline seconds per parent (engine) second; ≥ 0
    bool paused = false;        ///< create paused (resume() starts it)
};

/// A handle to a timeline in an Engine. Default-constructed or killed handles are inert:
/// queries return neutral values, commands do nothing. A handle must not outlive its engine.
class GRAPE_ANIM_API Timeline {
public:
    /// A position argument: a TimelinePosition, seconds from the timeline's start, or position
    /// text (">", "<+0.5", "+=1", "intro-0.25"; see parse_timeline_position).
    struct At {
        At() = default;
        /// A position as it is.
        At(TimelinePosition p) : position(std::move(p)) {}                  // NOLINT: implicit on purpose
        /// `seconds` from the timeline's start.
        At(double seconds) : position(timeline_position_at(seconds)) {}     // NOLINT
        /// Whole seconds from the timeline's start.
        At(int seconds) : position(timeline_position_at(seconds)) {}        // NOLINT
        /// Position text; throws grape::Error as parse_timeline_position does.
        At(const char* text) : position(parse_timeline_position(text)) {}   // NOLINT
        /// Position text; throws grape::Error as parse_timeline_position does.
        At(std::string_view text) : position(parse_timeline_position(text)) {}  // NOLINT
        /// Position text; throws grape::Error as parse_timeline_position does.
        At(const std::string& text) : position(parse_timeline_position(text)) {}  // NOLINT
        TimelinePosition position;  ///< where the child goes
    };

    Timeline() noexcept = default;

    /// Not killed.
    bool alive() const noexcept;
    explicit operator bool() const noexcept { return alive(); }  ///< alive()

    /// Places an animation (alive and in no timeline, of finite length) at `at`; the timeline
    /// drives it from now on and kills it with itself. Throws grape::Error otherwise.
    Timeline& add(const Animation& animation, At at = {});
    /// Places a timeline (top-level, not this one or one containing it, of finite length) at
    /// `at`; it plays inside this one from now on, its length the parent seconds of all its
    /// plays and delays. Throws grape::Error otherwise (cycles included).
    Timeline& add(const Timeline& child, At at = {});
    /// Calls `handler` whenever the timeline's time crosses `at` (a point: does not extend
    /// "previous" for ">" and "<").
    Timeline& call(std::function<void()> handler, At at = {});
    /// Names the time `at` (unique per timeline).
    Timeline& label(std::string_view name, At at = {});
    /// Leaves `seconds` (≥ 0, finite) empty at `at` (counts as the previous child for ">").
    Timeline& gap(double seconds, At at = {});

    /// Seconds per play: the end of the last-ending child, label, callback or gap (0 if not alive).
    double duration() const noexcept;
    /// Timeline seconds from the first play's start to the last play's end (+inf if endless).
    double total_duration() const noexcept;
    /// Seconds of timeline time since the first play began (negative while waiting; counts
    /// all plays and repeat delays).
    double time() const noexcept;
    /// Seconds into the current play (0 to duration; runs back on yoyo plays).
    double local_time() const noexcept;
    /// local_time / duration (0 for an empty timeline).
    double progress() const noexcept;
    /// Which play is running, from 0.
    int repetition() const noexcept;
    /// A label's time in the timeline (NaN if there is no such label).
    double label_time(std::string_view name) const noexcept;

    bool paused() const noexcept;  ///< alive and held by pause()
    void pause() const noexcept;  ///< holds the timeline, its children with it, where it is
    void resume() const noexcept;  ///< lets a paused timeline play on
    /// Plays backwards from where it is (time runs down to the start, which fires
    /// on_reverse_complete and stays there).
    void reverse() const noexcept;
    /// Plays forwards from where it is (and resumes it).
    void play() const noexcept;
    /// Runs backwards now.
    bool reversed() const noexcept;
    /// Timeline seconds per engine second (≥ 0 and finite; others ignored).
    void set_time_scale(double scale) const noexcept;
    double time_scale() const noexcept;  ///< timeline seconds per engine second
    /// Jumps to `seconds` since the first play began (as time(); clamped to the delay's start
    /// and the last play's end). Fires nothing unless `fire_events`: then the callbacks, child
    /// and timeline events it crosses fire in order, as a tick to there would fire them.
    /// Non-finite seconds are ignored.
    void seek(double seconds, bool fire_events = false) const;
    /// Jumps to a label's time in the first play (unknown labels: grape::Error).
    void seek(std::string_view label, bool fire_events = false) const;
    /// Kills the timeline, its nested timelines and its animations (no events).
    void kill() const noexcept;

    /// Calls `handler` when the first play begins (after the delay).
    void on_start(std::function<void()> handler) const;
    /// Calls `handler` after every change of state (each tick that moves it, each seek).
    void on_update(std::function<void()> handler) const;
    /// Calls `handler(play)` each time a new play starts (play = 1, 2, ...).
    void on_loop(std::function<void(int play)> handler) const;
    /// Calls `handler` when the last play ends.
    void on_complete(std::function<void()> handler) const;
    /// Calls `handler` when the timeline comes back to its start running backwards.
    void on_reverse_complete(std::function<void()> handler) const;

    /// The same timeline (the same slot and generation in the same engine).
    friend bool operator==(const Timeline&, const Timeline&) noexcept = default;

private:
    friend class Engine;
    friend class detail::TimelineStore;
    Timeline(Engine* engine, std::uint32_t slot, std::uint32_t generation) noexcept
        : engine_(engine), slot_(slot), generation_(generation) {}
    Engine* engine_ = nullptr;
    std::uint32_t slot_ = 0;
    std::uint32_t generation_ = 0;
};

/// @}

}  // namespace grape
