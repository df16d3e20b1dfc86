// Typed value records, exact time scales, the heading's offset, unwrapping and cusps, and the
// hold of a record paused by its own loop handler.
#include "engine_impl.hpp"

#include <grape/error.hpp>

#include <cmath>
#include <limits>

namespace grape::detail {

Animation EngineImpl::create_value(void* object, std::unique_ptr<TargetRef> ref, std::unique_ptr<ValueTrack> track,
                                   double duration, const AnimationDef& def) {
    validate("animate", duration, def);
    if (def.range_start != 0.0 || def.range_end != 1.0 || def.offset != 0.0)
        throw Error("animate: range_start, range_end and offset apply to path animations, not to typed values");
    if (!object) throw Error("animate: the target is null");
    Hot h = custom_hot(object, duration, def);
    Extra extra;
    extra.value = std::move(track);
    extra.ref = std::move(ref);
    extra.overwrite = def.overwrite;
    if (def.repeat_delay > 0.0 && def.repeat != 0) {
        extra.repeat_gap = def.repeat_delay / duration;
        h.flags |= flag_listens;
    }
    h.path = acquire_path(Path());  // shared placeholder: the value comes from the track
    const std::uint16_t curve = acquire_curve_for(h.path, def.curve);
    const Animation a = add(h, curve, duration, def, std::move(extra));
    if (find(a.slot_, a.generation_)) remember_scale(a.slot_, def.time_scale);  // unless a handler killed it
    return a;
}

// --- exact time scales -----------------------------------------------------------------------
// The hot record keeps rate = scale / duration (the tick needs it, and play_at computes the
// same quotient); rate·duration is within a few ulps of the scale, and the ulps are kept.

namespace {
double step_ulps(double x, int k) noexcept {
    const double toward = k > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    for (int i = 0; i < (k > 0 ? k : -k); ++i) x = std::nextafter(x, toward);
    return x;
}
}  // namespace

void EngineImpl::remember_scale(std::uint32_t slot, double scale) noexcept {
    if (slot >= slots_.size() || (slots_[slot].dense & free_bit)) return;  // gone during its creation
    const std::uint32_t dense = slots_[slot].dense;
    Cold& c = cold_[dense];
    const double base = std::fabs(hot_[dense].rate) * c.duration;
    // Up to 8 steps: the product of a correctly rounded quotient and its divisor is within
    // 2 ulps of the dividend unless it under- or overflows; those cases use the Extra.
    for (int k = 0; k <= 8; ++k) {
        for (int sign : {1, -1}) {
            if (step_ulps(base, sign * k) == scale) {
                c.scale_ulps = static_cast<std::int8_t>(sign * k);
                return;
            }
        }
    }
    try {
        extra_for(slot).time_scale = scale;
        c.scale_ulps = scale_in_extra;
    } catch (...) {  // out of memory: the scale reads back as rate·duration
        c.scale_ulps = 0;
    }
}

double EngineImpl::time_scale_of(std::uint32_t dense) const noexcept {
    const Cold& c = cold_[dense];
    if (c.scale_ulps == scale_in_extra) return extra(c.slot)->time_scale;
    return step_ulps(std::fabs(hot_[dense].rate) * c.duration, c.scale_ulps);
}

// --- heading ---------------------------------------------------------------------------------

double EngineImpl::next_heading(const Path& path, double u, bool backward, Extra& e) const noexcept {
    const Vec2 d = path.d1(u);
    double angle;
    if (length(d) > e.still) {
        angle = std::atan2(d.y, d.x);
    } else if (e.have_heading) {
        return e.heading;  // a cusp or a stop: the direction it came in with
    } else {
        // Starting on a cusp: the direction leaving it, d1/|d1| → d2/|d2| (0 if standing still).
        const Vec2 d2 = path.d2(u);
        angle = (d2.x == 0.0 && d2.y == 0.0) ? 0.0 : std::atan2(d2.y, d2.x);
    }
    if (backward) angle += pi;
    angle += e.heading_offset;
    if (e.heading_continuous) {
        if (e.have_heading) angle += 2.0 * pi * std::nearbyint((e.heading - angle) / (2.0 * pi));
    } else if (backward || e.heading_offset != 0.0) {
        angle = std::remainder(angle, 2.0 * pi);
    }
    e.have_heading = true;
    return angle;
}

// --- pause from on_loop ----------------------------------------------------------------------

void EngineImpl::hold_at_play(std::uint32_t dense, double play) {
    Hot& h = hot_[dense];
    Cold& c = cold_[dense];
    const PlayState s =
        play_at_position(play, static_cast<double>(c.plays()), c.reversed, (h.flags & flag_yoyo) != 0);
    c.set_play(s.finished ? c.plays() - 1 : wrap_plays(s.play));
    h.phase = s.phase;
    h.flags = play_flags(h.flags, s.backward, c);
    write_state(dense);
}

}  // namespace grape::detail
