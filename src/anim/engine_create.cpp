// Creating animations: validation, the records, the extras.
#include "engine_impl.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <string_view>

namespace grape::detail {

void validate_plays(const std::string& w, double delay, int repeat, double repeat_delay, double time_scale) {
    if (!(std::isfinite(delay) && delay >= 0.0)) throw Error(w + ": delay must be >= 0 and finite (got " + number_text(delay) + ")");
    if (repeat < -1) throw Error(w + ": repeat must be >= 0, or -1 for forever (got " + std::to_string(repeat) + ")");
    if (!(std::isfinite(repeat_delay) && repeat_delay >= 0.0))
        throw Error(w + ": repeat_delay must be >= 0 and finite (got " + number_text(repeat_delay) + ")");
    if (!(std::isfinite(time_scale) && time_scale >= 0.0))
        throw Error(w + ": time_scale must be >= 0 and finite (got " + number_text(time_scale) + ")");
}

Hot custom_hot(void* target, double duration, const AnimationDef& def) noexcept {
    Hot h{};
    h.rate = def.time_scale / duration;
    h.target = static_cast<char*>(target);
    h.kind = kind_byte(def.curve.kind(), LaneKernel::other);  // add() puts in the path's
    h.flags = static_cast<std::uint8_t>(flag_custom | (def.paused ? flag_paused : 0) | (def.yoyo ? flag_yoyo : 0));
    return h;
}

void validate(std::string_view where, double duration, const AnimationDef& def) {
    const std::string w(where);
    if (!(std::isfinite(duration) && duration > 0.0))
        throw Error(w + ": duration must be positive and finite (got " + number_text(duration) + ")");
    if (!std::isfinite(1.0 / duration))
        throw Error(w + ": duration is too small: 1 / duration overflows (got " + number_text(duration) + ")");
    validate_plays(w, def.delay, def.repeat, def.repeat_delay, def.time_scale);
    // The record keeps plays per second and the delay in plays; both, and the end of the last
    // play in seconds, must be numbers.
    if (!std::isfinite(def.time_scale / duration))
        throw Error(w + ": time_scale / duration overflows (time_scale " + number_text(def.time_scale) +
                    ", duration " + number_text(duration) + ")");
    if (!std::isfinite(def.delay / duration))
        throw Error(w + ": delay / duration overflows (delay " + number_text(def.delay) + ", duration " +
                    number_text(duration) + ")");
    if (def.repeat >= 0 && !std::isfinite(def.delay + duration * (static_cast<double>(def.repeat) + 1.0)))
        throw Error(w + ": delay + duration · (repeat + 1) overflows (delay " + number_text(def.delay) +
                    ", duration " + number_text(duration) + ", repeat " + std::to_string(def.repeat) + ")");
    if (!std::isfinite(def.repeat_delay / duration))
        throw Error(w + ": repeat_delay / duration overflows (repeat_delay " + number_text(def.repeat_delay) +
                    ", duration " + number_text(duration) + ")");
    if (def.repeat >= 0 && !std::isfinite(def.delay + duration * (static_cast<double>(def.repeat) + 1.0) +
                                          def.repeat_delay * static_cast<double>(def.repeat)))
        throw Error(w + ": delay + duration · (repeat + 1) + repeat_delay · repeat overflows (delay " +
                    number_text(def.delay) + ", duration " + number_text(duration) + ", repeat " +
                    std::to_string(def.repeat) + ", repeat_delay " + number_text(def.repeat_delay) + ")");
}

namespace {

bool has_range(const AnimationDef& def) noexcept { return def.range_start != 0.0 || def.range_end != 1.0; }

// The part of the path a play covers and the sideways offset: numbers the point can use.
void validate_placement(std::string_view where, const AnimationDef& def, bool sideways) {
    const std::string w(where);
    for (const auto& [name, u] : {std::pair{"range_start", def.range_start}, std::pair{"range_end", def.range_end}})
        if (!(u >= 0.0 && u <= 1.0))
            throw Error(w + ": " + name + " must be in [0, 1] (got " + number_text(u) + ")");
    if (!std::isfinite(def.offset))
        throw Error(w + ": offset must be finite (got " + number_text(def.offset) + ")");
    if (!sideways && def.offset != 0.0)
        throw Error(w + ": offset applies to 2-D path animations only (got " + number_text(def.offset) + ")");
}

}  // namespace

Animation EngineImpl::add(Hot hot, std::uint16_t curve, double duration, const AnimationDef& def,
                          std::optional<Extra> extra) {
    std::uint32_t slot;
    if (free_slot_ != UINT32_MAX) {
        slot = free_slot_;
        free_slot_ = slots_[slot].dense & ~free_bit;
        if (free_slot_ == (UINT32_MAX & ~free_bit)) free_slot_ = UINT32_MAX;
    } else {
        if (slots_.size() >= free_bit) throw Error("Engine: too many animations (2^31)");
        slot = static_cast<std::uint32_t>(slots_.size());
        slots_.push_back({0, 0});
    }
    const auto dense = static_cast<std::uint32_t>(hot_.size());
    hot.phase = def.delay > 0.0 ? -def.delay / duration : 0.0;
    // bound to nothing (a null target): no lean run, so that theirs need not test the target
    hot.kind = kind_byte(curve_kind(hot), hot.target ? lane_kernel(path_kind_[hot.path]) : LaneKernel::other);
    if (def.reversed) hot.flags |= flag_backward;
    const std::uint32_t plays = def.repeat < 0 ? 0u : static_cast<std::uint32_t>(def.repeat) + 1u;
    const Cold cold{duration, Cold::count_of(plays), slot, curve, 0, def.reversed};
    hot.flags = with_more(hot.flags, cold);
    hot_.push_back(hot);
    cold_.push_back(cold);
    slots_[slot].dense = dense;
    if (driven_begin_ != dense) {  // the first driven record moves to the end; this one takes its place
        const std::uint32_t first = driven_begin_;
        std::swap(hot_[first], hot_[dense]);
        std::swap(cold_[first], cold_[dense]);
        slots_[cold_[dense].slot].dense = dense;
        slots_[cold_[first].slot].dense = first;
    }
    ++driven_begin_;
    if (extra) extras_.insert_or_assign(slot, std::move(*extra));
    ++live_;
    if (index_on_) index_insert(slots_[slot].dense);
    const Animation handle(owner_, slot, slots_[slot].generation);
    {
        Dispatch d(*this);
        write_state(slots_[slot].dense);  // the start state, unless a delay holds it back
    }
    return handle;
}

Animation EngineImpl::create(void* target, std::size_t x_offset, std::size_t y_offset, bool is_float,
                             std::ptrdiff_t rotation_offset, const Path& path, double duration,
                             const AnimationDef& def, std::function<void(Vec2, double)> on_update, Bind bind) {
    const char* where = target ? "create_2d_animation" : "create_animation";
    validate(where, duration, def);
    validate_placement(where, def, true);
    const auto y_from_x = static_cast<std::ptrdiff_t>(y_offset) - static_cast<std::ptrdiff_t>(x_offset);
    if (y_from_x < -32768 || y_from_x > 32767)
        throw Error("create_2d_animation: target.x and target.y must lie within 32 KiB of each other (got " +
                    std::to_string(y_from_x) + " bytes apart)");
    Hot h{};
    h.rate = def.time_scale / duration;
    h.target = target ? static_cast<char*>(target) + x_offset : nullptr;
    h.y_offset = static_cast<std::int16_t>(y_from_x);
    h.kind = kind_byte(def.curve.kind(), LaneKernel::other);  // add() puts in the path's
    h.flags = static_cast<std::uint8_t>((is_float ? flag_float : 0) | (def.paused ? flag_paused : 0) |
                                        (def.yoyo ? flag_yoyo : 0));
    std::optional<Extra> extra;
    if (def.heading || on_update || bind.ref || def.overwrite || has_range(def) || def.offset != 0.0) {
        extra.emplace();
        extra->track_heading = def.heading;
        extra->write_rotation = target && rotation_offset >= 0;
        extra->rotation_offset = rotation_offset - static_cast<std::ptrdiff_t>(x_offset);
        if (on_update) extra->on_update_2d = std::make_shared<const std::function<void(Vec2, double)>>(std::move(on_update));
        extra->rotation_float = bind.rotation_float.value_or(is_float);
        extra->ref = std::move(bind.ref);
        extra->target_offset = static_cast<std::ptrdiff_t>(x_offset);
        extra->overwrite = def.overwrite;
        extra->heading_offset = def.heading_offset;
        extra->heading_continuous = def.heading_continuous;
        extra->still = 1e-12 * path.length();  // |d1| ~ length: round-off of d1 at a cusp is far below
        extra->range_start = def.range_start;
        extra->range_end = def.range_end;
        extra->offset = def.offset;
        h.flags |= flag_custom;
    }
    if (def.repeat_delay > 0.0 && def.repeat != 0) {
        if (!extra) extra.emplace();
        extra->repeat_gap = def.repeat_delay / duration;
        h.flags |= flag_listens;
    }
    h.path = acquire_path(path);
    const std::uint16_t curve = acquire_curve_for(h.path, def.curve);
    const Animation a = add(h, curve, duration, def, std::move(extra));
    if (find(a.slot_, a.generation_)) remember_scale(a.slot_, def.time_scale);  // unless a handler killed it
    return a;
}

Animation EngineImpl::create_nd(void* target, std::vector<MemberRef> members, PathND path, double duration,
                                const AnimationDef& def, std::function<void(std::span<const double>)> on_update) {
    const char* where = target ? "create_property_animation" : "create_animation";
    validate(where, duration, def);
    validate_placement(where, def, false);
    if (target && members.size() != path.dimension())
        throw Error(std::string(where) + ": members and values must match (" + std::to_string(members.size()) +
                    " members, " + std::to_string(path.dimension()) + " values)");
    Hot h = custom_hot(target, duration, def);
    Extra extra;
    extra.range_start = def.range_start;
    extra.range_end = def.range_end;
    extra.values.assign(path.dimension(), 0.0);
    path.point(along_range(extra, def.reversed ? 1.0 : 0.0), extra.values);  // the start values, readable while waiting
    extra.nd.emplace(std::move(path));
    extra.members = std::move(members);
    if (on_update)
        extra.on_update_nd = std::make_shared<const std::function<void(std::span<const double>)>>(std::move(on_update));
    extra.overwrite = def.overwrite;
    if (def.repeat_delay > 0.0 && def.repeat != 0) {
        extra.repeat_gap = def.repeat_delay / duration;
        h.flags |= flag_listens;
    }
    h.path = acquire_path(Path());  // shared placeholder: N-D values come from the Extra
    const std::uint16_t curve = acquire_curve_for(h.path, def.curve);
    const Animation a = add(h, curve, duration, def, std::move(extra));
    if (find(a.slot_, a.generation_)) remember_scale(a.slot_, def.time_scale);  // unless a handler killed it
    return a;
}

}  // namespace grape::detail
