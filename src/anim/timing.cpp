// The timing model: which play runs and how far into it, as a pure function of time. The
// engine's seek and tick, and the scene player, all go through play_at_position.
#include <grape/anim.hpp>

#include <algorithm>
#include <cmath>

namespace grape {

PlayState play_at_position(double position, double plays, bool reversed, bool yoyo) noexcept {
    PlayState s;
    if (std::isnan(position)) position = 0.0;
    if (plays > 0.0 && position >= plays - play_snap) {
        s.play = plays - 1.0;
        s.phase = 1.0;
        s.finished = true;
    } else if (position < 0.0) {
        s.phase = std::max(position, -1e300);  // −inf: waiting "forever", still a number
    } else {
        s.play = std::floor(position + play_snap);  // within play_snap of an end: the next play
        const double phase = position - s.play;
        // From 2⁵³ plays on there is no fraction; +inf − inf is NaN: both are a play's start.
        s.phase = phase > 0.0 ? phase : 0.0;
    }
    // Doubles from 2⁵³ on are even, and so is the limit +inf: fmod gives 0 or NaN there.
    const bool odd = std::fmod(s.play, 2.0) == 1.0;
    s.backward = reversed != (yoyo && odd);
    return s;
}

PlayState play_at_position(double position, double plays, bool reversed, bool yoyo, double gap) noexcept {
    if (!(gap > 0.0)) return play_at_position(position, plays, reversed, yoyo);
    PlayState s;
    if (std::isnan(position)) position = 0.0;
    const double cycle = 1.0 + gap;
    if (plays > 0.0 && position >= plays + (plays - 1.0) * gap - play_snap) {
        s.play = plays - 1.0;
        s.phase = 1.0;
        s.finished = true;
    } else if (position < 0.0) {
        s.phase = std::max(position, -1e300);
    } else {
        double k = std::floor(position / cycle);
        // The division rounds: the remainder may leave [0, cycle) by an ulp; inf − inf is NaN.
        double local = position - k * cycle;
        if (!(local > 0.0)) local = 0.0;
        if (local >= cycle - play_snap) {  // within play_snap of the gap's end: the next play
            k += 1.0;
            local = std::max(local - cycle, 0.0);
        }
        s.play = k;
        if (local >= 1.0 - play_snap) {
            s.phase = 1.0;
            s.gap = std::max(local - 1.0, 0.0);
        } else {
            s.phase = local;
        }
    }
    const bool odd = std::fmod(s.play, 2.0) == 1.0;
    s.backward = reversed != (yoyo && odd);
    return s;
}

namespace {
double plays_of(const AnimationDef& def) noexcept {
    return def.repeat < 0 ? 0.0 : static_cast<double>(def.repeat) + 1.0;
}
}  // namespace

PlayState play_at(const AnimationDef& def, double duration, double t) noexcept {
    // The engine's arithmetic: the phase starts at −delay/duration and grows at
    // time_scale/duration plays per second.
    const double start = def.delay > 0.0 ? -def.delay / duration : 0.0;
    return play_at_position(start + t * (def.time_scale / duration), plays_of(def), def.reversed, def.yoyo,
                            def.repeat_delay / duration);
}

double progress_at(const AnimationDef& def, double duration, double t) noexcept {
    const PlayState s = play_at(def, duration, t);
    const double phase = std::clamp(s.phase, 0.0, 1.0);
    return def.curve(s.backward ? 1.0 - phase : phase);
}

double end_time(const AnimationDef& def, double duration) noexcept {
    const double plays = plays_of(def);
    if (plays == 0.0 || !(def.time_scale > 0.0)) return HUGE_VAL;
    return (def.delay + duration * plays + def.repeat_delay * (plays - 1.0)) / def.time_scale;
}

}  // namespace grape
