// grape — where the children of a timeline go: positions (GSAP's position parameter) resolved
// into start times, pure functions shared by the engine's timelines and the scene format.
//
//   std::vector<grape::TimelineEntry> entries = {
//       {.duration = 1.0},                                                  // at 0
//       {.kind = grape::TimelineEntry::Kind::label, .label = "hit"},       // at 1
//       {.at = grape::parse_timeline_position("<+0.25"), .duration = 2.0}, // at 0.25
//       {.at = grape::parse_timeline_position("hit+1"), .duration = 0.5},  // at 2
//   };
//   grape::TimelineLayout layout = grape::layout_timeline(entries);  // duration 2.5
#pragma once

#include <grape/anim.hpp>
#include <grape/export_anim.hpp>

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace grape {

/// \addtogroup timeline
/// @{

/// Where a child goes in a timeline (GSAP's position parameter).
struct TimelinePosition {
    /// What a position counts from (see `anchor`).
    enum class Anchor { start, end, previous_end, previous_start, label };
    Anchor anchor = Anchor::end;  ///< start: `offset` seconds from the timeline's start (a number);
                                  ///< end: the end of everything placed so far ("+=0.5", "-=0.2",
                                  ///< the default); previous_end ">" / previous_start "<": the
                                  ///< previously placed child or gap (the timeline's start if none);
                                  ///< label: a label's time ("intro", "intro+1", "intro-=0.25")
    std::string label{};          ///< for Anchor::label
    double offset = 0.0;          ///< seconds added to the anchor (finite)
};

/// Parses GSAP-style positions: "1.5" (absolute seconds), ">", "<", ">+0.5", "<-0.2", "+=0.5",
/// "-=0.5", "intro", "intro+1", "intro-=0.25" (">" and "<" also take "+=" and "-="). A label is
/// the text before the first '+' or '-' that is followed by a number ("my-label-1" is
/// "my-label" − 1); it must not start with a digit, '.', '<', '>' or '='. Throws grape::Error
/// naming the text and the reason.
GRAPE_ANIM_API TimelinePosition parse_timeline_position(std::string_view text);
/// An absolute position (seconds from the timeline's start).
GRAPE_ANIM_API TimelinePosition timeline_position_at(double seconds) noexcept;
/// The text parse_timeline_position reads back as `position` (17 significant digits).
GRAPE_ANIM_API std::string to_string(const TimelinePosition& position);

/// One entry of a timeline as laid out: a child with a duration (an animation's or a nested
/// timeline's total length in the parent's seconds, finite and ≥ 0), a gap (occupies
/// `duration` seconds, plays nothing), a label (a point, `label` set) or a callback (a point).
struct TimelineEntry {
    /// What an entry is: a child with a duration, a gap, a label or a callback.
    enum class Kind { child, gap, label, callback };
    Kind kind = Kind::child;  ///< what the entry is
    TimelinePosition at{};  ///< where it goes
    double duration = 0.0;  ///< seconds in the parent's time; ignored for labels and callbacks
    std::string label{};    ///< Kind::label: its name
};

/// Entries resolved to start times.
struct TimelineLayout {
    std::vector<double> start;                           ///< per entry, seconds from the timeline's start (≥ 0)
    std::vector<std::pair<std::string, double>> labels;  ///< in definition order
    double duration = 0.0;  ///< the end of the last-ending entry (labels and callbacks count as points)
};

/// Resolves positions in entry order: "end" is the latest end placed so far; ">" and "<" refer
/// to the previous child or gap (labels and callbacks do not change it); a label position
/// refers to a label defined by an earlier entry. Throws grape::Error "entries[i]: ..." for an
/// unknown or duplicate label, a negative resulting start, a non-finite or negative duration
/// or a non-finite offset.
GRAPE_ANIM_API TimelineLayout layout_timeline(std::span<const TimelineEntry> entries);

/// Seconds into one play of a timeline of `duration` seconds per play, at `t` seconds of the
/// parent's time since the timeline was placed, under `def`'s delay, repeat, repeat_delay,
/// yoyo, reversed and time_scale (curve ignored): the same play_at model animations use.
/// Before the first play: 0 (or `duration` when reversed); during a repeat delay and after
/// the last play: the end of the play just finished (0 for a backward play). 0 for duration 0.
GRAPE_ANIM_API double timeline_local_time(const AnimationDef& def, double duration, double t) noexcept;

/// @}

}  // namespace grape
