// grape — how an animation plays (AnimationDef) and the one timing model: pure functions of
// time that give the play, the phase and the progress at any time. The Engine, the scene
// player and the timelines all play by them (anim.hpp includes this header).
#pragma once

#include <grape/curve.hpp>
#include <grape/export_anim.hpp>

namespace grape {

/// \addtogroup anim
/// @{

/// How an animation plays; fill with designated initializers:
/// `{.curve = Curve::quad_in_out(), .repeat = -1, .yoyo = true}`.
struct AnimationDef {
    Curve curve{};            ///< progress over each play's normalized time (default linear)
    double delay = 0.0;       ///< seconds (animation time) before the first play; ≥ 0
    int repeat = 0;           ///< extra plays after the first: 0 plays once, −1 forever
    double repeat_delay = 0.0;  ///< seconds (animation time) between plays, holding the end of
                                ///< the play just finished; ≥ 0 (on_loop fires when the next
                                ///< play starts, after it)
    bool reversed = false;    ///< play from the path's end to its start
    bool yoyo = false;        ///< every second play runs backwards (reverse on loop)
    double time_scale = 1.0;  ///< animation seconds per engine second; ≥ 0
    bool paused = false;      ///< create paused (resume() starts it)
    bool heading = false;     ///< also track the path's heading (radians); 2-D animations
                              ///< bound to a target with a `rotation` member write it there
    double heading_offset = 0.0;      ///< radians added to the heading (a sprite drawn facing
                                      ///< up instead of along +x: π/2)
    bool heading_continuous = false;  ///< unwrapped: each heading within π of the previous
                                      ///< update's, so a spinning object never jumps by 2π
                                      ///< (else wrapped into (−π, π])
    bool overwrite = false;   ///< when its first play begins, kill the target's other started
                              ///< animations that write any of the same bytes (GSAP's
                              ///< overwrite "auto"); found through the target index
    double range_start = 0.0; ///< path animations: the path's u where each play starts, in
                              ///< [0, 1] (GSAP's motion-path `start`); the play covers
                              ///< u = range_start + progress·(range_end − range_start)
    double range_end = 1.0;   ///< the path's u where each play ends, in [0, 1]; below
                              ///< range_start the part runs backwards (GSAP's `end`)
    double offset = 0.0;      ///< 2-D path animations: sideways distance from the path, world
                              ///< units, towards its normal (offset_point: point + d·normal,
                              ///< a car in a lane; Godot's h_offset); the heading stays the
                              ///< path's direction of travel
};

// --- the timing model: pure functions of time ------------------------------------------------

/// A play counts as finished within this much of its end, in plays: summed frame times such
/// as 60 × 1/60 fall short of 1 by a few ulp and must still complete on that frame.
inline constexpr double play_snap = 1e-9;

/// The most on_loop calls one tick makes per animation. A tick that starts more plays calls
/// on_loop once, for the last of them, with the number it skipped.
inline constexpr int max_loop_events = 16;

/// Where an animation stands: which play runs, how far into it, which way.
struct PlayState {
    double play = 0.0;       ///< plays begun before the current one (a whole number ≥ 0; +inf
                             ///< after infinitely many)
    double phase = 0.0;      ///< fraction of the current play elapsed, in [0, 1]; < 0 while
                             ///< waiting (−phase·duration seconds of delay left)
    bool backward = false;   ///< the current play runs from the path's end to its start
    bool finished = false;   ///< at the end of the last play (never for endless animations)
    double gap = 0.0;        ///< plays of repeat delay elapsed after the current play (> 0 only
                             ///< while holding at its end, phase 1, before the next play)
};

/// The state `position` plays after the first play began (negative: waiting), for an
/// animation of `plays` plays (0: endless) whose first play runs `backward` when `reversed`,
/// and every second one the other way when `yoyo`. Snap rule: a play within play_snap of its
/// end counts as ended; from 2⁵³ plays on the phase is 0 (a double has no fraction left
/// there), and +inf gives the start of a play after infinitely many. NaN counts as 0.
GRAPE_ANIM_API PlayState play_at_position(double position, double plays, bool reversed, bool yoyo) noexcept;

/// The same with a repeat delay of `gap` plays (≥ 0) after every play but the last: a cycle is
/// 1 + gap plays long, and the last play of `plays` ends at plays + (plays − 1)·gap. During a
/// gap the state is the end of the play just finished (phase 1, `gap` > 0); within play_snap of
/// a gap's end the next play has begun. gap 0 is the four-argument form bit for bit.
GRAPE_ANIM_API PlayState play_at_position(double position, double plays, bool reversed, bool yoyo,
                                          double gap) noexcept;

/// The state at `t` seconds (engine time) after an animation of `def` and `duration`
/// seconds per play was created, as the Engine plays it: animation time runs at
/// def.time_scale, the first play starts after def.delay seconds of animation time.
GRAPE_ANIM_API PlayState play_at(const AnimationDef& def, double duration, double t) noexcept;

/// The path parameter u at engine time t: def.curve of the play fraction, run backwards
/// (curve(1 − τ)) on backward plays; the start while waiting, the end once finished.
GRAPE_ANIM_API double progress_at(const AnimationDef& def, double duration, double t) noexcept;

/// Engine seconds from creation until the last play ends: (delay + duration·plays +
/// repeat_delay·(plays − 1)) / time_scale; +inf for endless animations or time_scale 0.
GRAPE_ANIM_API double end_time(const AnimationDef& def, double duration) noexcept;

/// @}

}  // namespace grape
