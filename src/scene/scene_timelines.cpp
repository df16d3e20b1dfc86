// Scene timelines: read and written as JSON, laid out by the anim module's pure timeline
// layout, and evaluated down their chain of parents with the one timing model
// (the engine timelines' arithmetic for timelines, progress_at for the animations and tweens
// they drive).
#include <grape/scene.hpp>

#include <grape/error.hpp>
#include <grape/timeline_layout.hpp>

#include "scene_json.hpp"

#include <algorithm>
#include <charconv>
#include <set>
#include <cmath>
#include <map>
#include <string>
#include <utility>

namespace grape {

namespace scene_io {

namespace {

// A label is referred to by a position string, so its name must read back as itself: not
// "take-2" (the label "take" − 2), not "2nd" (a number).
void check_label_name(const std::string& name, const std::string& pointer) {
    bool same = false;
    try {
        const TimelinePosition p = parse_timeline_position(name);
        same = p.anchor == TimelinePosition::Anchor::label && p.label == name && p.offset == 0.0;
    } catch (const Error&) {
    }
    if (!same)
        fail(pointer, "\"" + name + "\" cannot be a label: a position reads it as something else (a label must not start with a digit, '.', '<', '>' or '=', nor hold '+' or '-' before a number)");
}

TimelinePosition read_position(const json& j, const std::string& pointer) {
    if (j.is_number()) return timeline_position_at(number(j, pointer));
    if (!j.is_string()) fail(pointer, "expected a number (seconds from the timeline's start) or a position string, got " + type_of(j));
    try {
        return parse_timeline_position(j.get<std::string>());
    } catch (const Error& e) {
        fail(pointer, e.what());
    }
}

SceneTimelineChild read_child(const json& j, const std::string& pointer) {
    const json& o = object(j, pointer, {"animation", "animation3", "tween", "timeline", "label", "gap", "at"});
    SceneTimelineChild c;
    int kinds = 0;
    for (const auto& [key, kind] : {std::pair{"animation", SceneTimelineChildKind::animation},
                                    std::pair{"animation3", SceneTimelineChildKind::animation3},
                                    std::pair{"tween", SceneTimelineChildKind::tween},
                                    std::pair{"timeline", SceneTimelineChildKind::timeline},
                                    std::pair{"label", SceneTimelineChildKind::label},
                                    std::pair{"gap", SceneTimelineChildKind::gap}}) {
        const auto v = o.find(key);
        if (v == o.end()) continue;
        ++kinds;
        c.kind = kind;
        if (kind == SceneTimelineChildKind::gap) {
            c.gap = non_negative_field(o, pointer, "gap", 0.0);
        } else {
            c.name = string_value(*v, child(pointer, key));
            if (c.name.empty()) fail(child(pointer, key), "must not be empty");
        }
        if (kind == SceneTimelineChildKind::label) check_label_name(c.name, child(pointer, key));
    }
    if (kinds != 1)
        fail(pointer, "expected exactly one of \"animation\", \"animation3\", \"tween\", \"timeline\", \"label\" and \"gap\" (got " + std::to_string(kinds) + ")");
    if (const auto at = o.find("at"); at != o.end()) c.at = read_position(*at, child(pointer, "at"));
    return c;
}

// The JSON of a position: a number for an absolute time, otherwise the position syntax;
// null for the default (after everything placed so far), which is left out.
ordered position_json(const TimelinePosition& at) {
    if (at.anchor == TimelinePosition::Anchor::start) return at.offset;
    if (at.anchor == TimelinePosition::Anchor::end && at.offset == 0.0) return nullptr;
    return to_string(at);
}

}  // namespace

std::vector<SceneTimeline> read_timelines(const json& v, const std::string& pointer) {
    if (!v.is_array()) fail(pointer, "expected an array, got " + type_of(v));
    std::vector<SceneTimeline> out;
    std::set<std::string> names;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const std::string p = child(pointer, i);
        const json& o = object(v[i], p, {"name", "delay", "repeat", "repeat_delay", "yoyo", "time_scale", "children"});
        SceneTimeline tl;
        tl.name = name_field(o, p, &names);
        tl.delay = non_negative_field(o, p, "delay", 0.0);
        tl.repeat = repeat_field(o, p, tl.repeat);
        tl.repeat_delay = non_negative_field(o, p, "repeat_delay", 0.0);
        tl.yoyo = bool_field(o, p, "yoyo", false);
        if (o.contains("time_scale")) tl.time_scale = positive_field(o, p, "time_scale");
        const json& children = array_field(o, p, "children");
        for (std::size_t c = 0; c < children.size(); ++c) tl.children.push_back(read_child(children[c], child(child(p, "children"), c)));
        out.push_back(std::move(tl));
    }
    return out;
}

ordered timelines_json(const std::vector<SceneTimeline>& timelines) {
    ordered a = ordered::array();
    for (const SceneTimeline& tl : timelines) {
        ordered o = {{"name", tl.name}, {"delay", tl.delay}, {"repeat", tl.repeat},
                     {"repeat_delay", tl.repeat_delay}, {"yoyo", tl.yoyo}, {"time_scale", tl.time_scale}};
        ordered children = ordered::array();
        for (const SceneTimelineChild& c : tl.children) {
            ordered e;
            switch (c.kind) {
                case SceneTimelineChildKind::animation: e["animation"] = c.name; break;
                case SceneTimelineChildKind::animation3: e["animation3"] = c.name; break;
                case SceneTimelineChildKind::tween: e["tween"] = c.name; break;
                case SceneTimelineChildKind::timeline: e["timeline"] = c.name; break;
                case SceneTimelineChildKind::label: e["label"] = c.name; break;
                case SceneTimelineChildKind::gap: e["gap"] = c.gap; break;
            }
            if (ordered at = position_json(c.at); !at.is_null()) e["at"] = std::move(at);
            children.push_back(std::move(e));
        }
        o["children"] = std::move(children);
        a.push_back(std::move(o));
    }
    return a;
}

}  // namespace scene_io

AnimationDef SceneTimeline::def() const noexcept {
    AnimationDef d{.delay = delay, .repeat = repeat, .yoyo = yoyo, .time_scale = time_scale};
    d.repeat_delay = repeat_delay;
    return d;
}

// ------------------------------------------------------------------------------ SceneTiming

namespace {

using scene_io::child;
using scene_io::fail;

// Timelines nested deeper than this are refused: no real scene needs it, and it bounds the
// recursion of the evaluation (one frame per level).
constexpr int max_nesting = 32;

std::string pointer_of(std::size_t timeline, std::size_t child_index) {
    return child(child(child("/timelines", timeline), "children"), child_index);
}

// Builds the layouts depth first, children before their parents.
class Resolver {
public:
    Resolver(const Scene& scene, std::vector<SceneTimelineLayout>& layouts) : scene_(scene), layouts_(layouts) {
        for (std::size_t i = 0; i < scene.animations.size(); ++i)
            if (!scene.animations[i].name.empty()) animations_.emplace(scene.animations[i].name, i);
        for (std::size_t i = 0; i < scene.tweens.size(); ++i)
            if (!scene.tweens[i].name.empty()) tweens_.emplace(scene.tweens[i].name, i);
        for (std::size_t i = 0; i < scene.animations3.size(); ++i)
            if (!scene.animations3[i].name.empty()) animations3_.emplace(scene.animations3[i].name, i);
        for (std::size_t k = 0; k < scene.timelines.size(); ++k) {
            const std::string& name = scene.timelines[k].name;
            if (name.empty()) fail(child(child("/timelines", k), "name"), "must not be empty");
            if (!timelines_.emplace(name, k).second) fail(child(child("/timelines", k), "name"), "duplicate name \"" + name + "\"");
        }
        state_.assign(scene.timelines.size(), 0);
        placed_animation_.assign(scene.animations.size(), std::string());
        placed_at_.assign(scene.animations.size(), {-1, 0});
        placed_tween_.assign(scene.tweens.size(), std::string());
        placed_animation3_.assign(scene.animations3.size(), std::string());
        placed_animation3_at_.assign(scene.animations3.size(), {-1, 0});
        placed_tween_at_.assign(scene.tweens.size(), {-1, 0});
        placed_timeline_.assign(scene.timelines.size(), std::string());
        layouts_.assign(scene.timelines.size(), {});
    }

    /// The animation named by child c of timeline k (its index).
    std::size_t animation(std::size_t k, std::size_t c, const std::string& name) {
        return place_unique(animations_, placed_animation_, placed_at_, k, c, "animation", name);
    }

    /// The tween named by child c of timeline k (its index).
    std::size_t tween(std::size_t k, std::size_t c, const std::string& name) {
        return place_unique(tweens_, placed_tween_, placed_tween_at_, k, c, "tween", name);
    }

    /// The 3-D animation named by child c of timeline k (its index).
    std::size_t animation3(std::size_t k, std::size_t c, const std::string& name) {
        return place_unique(animations3_, placed_animation3_, placed_animation3_at_, k, c, "animation3", name);
    }

    std::size_t timeline(std::size_t k, std::size_t c, const std::string& name) {
        const std::string p = child(pointer_of(k, c), "timeline");
        const auto it = timelines_.find(name);
        if (it == timelines_.end()) fail(p, "no timeline named \"" + name + "\" in /timelines");
        place(placed_timeline_[it->second], p, "timeline", name);
        return it->second;
    }

    // Lays out timeline k (and, first, the timelines placed in it).
    void resolve(std::size_t k, int depth) {
        if (state_[k] == 2) return;
        const SceneTimeline& tl = scene_.timelines[k];
        SceneTimelineLayout& layout = layouts_[k];
        state_[k] = 1;
        std::vector<TimelineEntry> entries;
        layout.index.assign(tl.children.size(), -1);
        for (std::size_t c = 0; c < tl.children.size(); ++c) {
            const SceneTimelineChild& ch = tl.children[c];
            TimelineEntry e{.at = ch.at};
            switch (ch.kind) {
                case SceneTimelineChildKind::animation:
                case SceneTimelineChildKind::animation3:
                case SceneTimelineChildKind::tween: {
                    const bool is_animation = ch.kind == SceneTimelineChildKind::animation;
                    const bool is_animation3 = ch.kind == SceneTimelineChildKind::animation3;
                    const std::size_t i = is_animation    ? animation(k, c, ch.name)
                                          : is_animation3 ? animation3(k, c, ch.name)
                                                          : tween(k, c, ch.name);
                    e.duration = is_animation    ? scene_.animations[i].end_time()
                                 : is_animation3 ? scene_.animations3[i].end_time()
                                                 : scene_.tweens[i].end_time();
                    const char* what = is_animation ? "animation" : is_animation3 ? "animation3" : "tween";
                    if (!std::isfinite(e.duration))
                        fail(child(pointer_of(k, c), what), std::string(what) + " \"" + ch.name + "\" repeats forever: a timeline can only hold what ends");
                    layout.index[c] = static_cast<std::ptrdiff_t>(i);
                    break;
                }
                case SceneTimelineChildKind::timeline: {
                    const std::size_t n = timeline(k, c, ch.name);
                    const std::string p = child(pointer_of(k, c), "timeline");
                    if (state_[n] == 1) fail(p, "timeline \"" + ch.name + "\" contains itself (a cycle of timelines)");
                    if (depth + 1 >= max_nesting) fail(p, "timelines nested deeper than " + std::to_string(max_nesting));
                    resolve(n, depth + 1);
                    e.duration = layouts_[n].end_time;
                    if (!std::isfinite(e.duration))
                        fail(p, "timeline \"" + ch.name + "\" repeats forever: a timeline can only hold what ends");
                    layouts_[n].parent = static_cast<std::ptrdiff_t>(k);
                    layout.index[c] = static_cast<std::ptrdiff_t>(n);
                    break;
                }
                case SceneTimelineChildKind::label:
                    e.kind = TimelineEntry::Kind::label;
                    e.label = ch.name;
                    break;
                case SceneTimelineChildKind::gap:
                    if (!(ch.gap >= 0.0) || !std::isfinite(ch.gap)) fail(child(pointer_of(k, c), "gap"), "must be finite and ≥ 0");
                    e.kind = TimelineEntry::Kind::gap;
                    e.duration = ch.gap;
                    break;
            }
            entries.push_back(std::move(e));
        }
        TimelineLayout laid;
        try {
            laid = layout_timeline(entries);
        } catch (const Error& err) {
            fail_at_entry(k, err.what());
        }
        layout.start = laid.start;
        layout.length.resize(entries.size());
        for (std::size_t c = 0; c < entries.size(); ++c) layout.length[c] = entries[c].duration;
        layout.duration = laid.duration;
        layout.end_time = grape::end_time(tl.def(), laid.duration);
        for (std::size_t c = 0; c < entries.size(); ++c)
            if (tl.children[c].kind == SceneTimelineChildKind::timeline)
                layouts_[static_cast<std::size_t>(layout.index[c])].start_in_parent = layout.start[c];
        state_[k] = 2;
    }

    /// Where each placed animation is: its timeline and start (−1 when free).
    std::pair<std::ptrdiff_t, double> placement(std::size_t i) const {
        const auto [k, c] = placed_at_[i];
        if (k < 0) return {-1, 0.0};
        return {k, layouts_[static_cast<std::size_t>(k)].start[c]};
    }

    /// Where each placed 3-D animation is: its timeline and start (−1 when free).
    std::pair<std::ptrdiff_t, double> animation3_placement(std::size_t i) const {
        const auto [k, c] = placed_animation3_at_[i];
        if (k < 0) return {-1, 0.0};
        return {k, layouts_[static_cast<std::size_t>(k)].start[c]};
    }

    /// Where each placed tween is: its timeline and start (−1 when free).
    std::pair<std::ptrdiff_t, double> tween_placement(std::size_t i) const {
        const auto [k, c] = placed_tween_at_[i];
        if (k < 0) return {-1, 0.0};
        return {k, layouts_[static_cast<std::size_t>(k)].start[c]};
    }

    /// Refuses nesting deeper than max_nesting (the evaluation recurses once per level).
    void check_depth() const {
        for (std::size_t k = 0; k < layouts_.size(); ++k) {
            int depth = 0;
            for (std::ptrdiff_t p = layouts_[k].parent; p >= 0; p = layouts_[static_cast<std::size_t>(p)].parent)
                if (++depth >= max_nesting)
                    fail(placed_timeline_[k] + "/timeline", "timelines nested deeper than " + std::to_string(max_nesting));
        }
    }

private:
    // The one entry of `names` called `name` (an animation or a tween: `what`), placed at child c
    // of timeline k.
    std::size_t place_unique(const std::multimap<std::string, std::size_t>& names, std::vector<std::string>& placed,
                             std::vector<std::pair<std::ptrdiff_t, std::size_t>>& placed_at, std::size_t k, std::size_t c,
                             const std::string& what, const std::string& name) {
        const std::string p = child(pointer_of(k, c), what);
        const std::string list = what == "animation3" ? std::string("/animations3") : "/" + what + "s";
        const auto [first, last] = names.equal_range(name);
        if (first == last) fail(p, "no " + what + " named \"" + name + "\" in " + list);
        if (std::next(first) != last)
            fail(p, "the name \"" + name + "\" is ambiguous (" + list + "/" + std::to_string(first->second) + " and " + list + "/" +
                        std::to_string(std::next(first)->second) + ")");
        place(placed[first->second], p, what.c_str(), name);
        placed_at[first->second] = {static_cast<std::ptrdiff_t>(k), c};
        return first->second;
    }

    void place(std::string& where, const std::string& pointer, const char* what, const std::string& name) {
        if (!where.empty()) fail(pointer, std::string(what) + " \"" + name + "\" is already placed at " + where);
        where = pointer.substr(0, pointer.rfind('/'));
    }

    // The layout names its entries "entries[i]: why"; the scene names the JSON pointer.
    [[noreturn]] void fail_at_entry(std::size_t k, const std::string& what) {
        const std::string prefix = "entries[";
        if (const auto at = what.find(prefix); at != std::string::npos) {
            std::size_t index = 0;
            const char* first = what.data() + at + prefix.size();
            const auto [end, ec] = std::from_chars(first, what.data() + what.size(), index);
            if (ec == std::errc() && std::string_view(end, 3) == "]: " && index < scene_.timelines[k].children.size()) {
                const std::string rest = what.substr(static_cast<std::size_t>(end - what.data()) + 3);
                // A duplicate label is the label's fault; anything else is its position's.
                const bool label = rest.find("duplicate") != std::string::npos;
                fail(label ? pointer_of(k, index) : child(pointer_of(k, index), "at"), rest);
            }
        }
        fail(child(child("/timelines", k), "children"), what);
    }

    const Scene& scene_;
    std::vector<SceneTimelineLayout>& layouts_;
    std::multimap<std::string, std::size_t> animations_;
    std::multimap<std::string, std::size_t> tweens_;
    std::multimap<std::string, std::size_t> animations3_;
    std::map<std::string, std::size_t> timelines_;
    std::vector<int> state_;  // 0 not yet laid out, 1 being laid out, 2 done
    std::vector<std::string> placed_animation_;  // where each is placed ("" : nowhere yet)
    std::vector<std::string> placed_timeline_;
    std::vector<std::pair<std::ptrdiff_t, std::size_t>> placed_at_;  // per animation: timeline and child (−1: free)
    std::vector<std::string> placed_tween_;
    std::vector<std::pair<std::ptrdiff_t, std::size_t>> placed_tween_at_;  // per tween
    std::vector<std::string> placed_animation3_;
    std::vector<std::pair<std::ptrdiff_t, std::size_t>> placed_animation3_at_;  // per 3-D animation
};

}  // namespace

SceneTiming::SceneTiming(const Scene& scene) {
    std::vector<SceneTimelineLayout> layouts;
    Resolver resolver(scene, layouts);
    for (std::size_t k = 0; k < scene.timelines.size(); ++k) resolver.resolve(k, 0);
    resolver.check_depth();
    for (std::size_t i = 0; i < scene.animations.size(); ++i) {
        const SceneAnimation& a = scene.animations[i];
        const auto [driver, start] = resolver.placement(i);
        animations_.push_back({a.def(), a.duration, driver, start});
    }
    for (std::size_t i = 0; i < scene.animations3.size(); ++i) {
        const SceneAnimation3& a = scene.animations3[i];
        const auto [driver, start] = resolver.animation3_placement(i);
        animations3_.push_back({a.def(), a.seconds(), driver, start});
    }
    std::vector<std::pair<std::ptrdiff_t, double>> placed;  // read before the layouts move
    for (std::size_t i = 0; i < scene.tweens.size(); ++i) placed.push_back(resolver.tween_placement(i));
    for (std::size_t k = 0; k < scene.timelines.size(); ++k) timelines_.push_back({scene.timelines[k].def(), std::move(layouts[k])});
    for (std::size_t i = 0; i < scene.tweens.size(); ++i) {
        const SceneTween& tw = scene.tweens[i];
        const auto [driver, start] = placed[i];
        Tween out{tw.def(), tw.duration, driver, start, 0.0};
        // The first play begins where the chain of timelines first reaches the tween's place:
        // a timeline's first play is at local time x at (delay + x) / time_scale of its parent.
        double x = driver < 0 ? (tw.delay > 0.0 ? tw.delay / tw.time_scale : 0.0) : start;
        for (std::ptrdiff_t k = driver; k >= 0;) {
            const Timeline& tl = timelines_[static_cast<std::size_t>(k)];
            x = (tl.def.delay + x) / tl.def.time_scale + tl.layout.start_in_parent;
            k = tl.layout.parent;
        }
        out.entry = x;
        tweens_.push_back(out);
    }
}

// The time at scene time t of what timeline `driver` holds at `start` (a free one: t itself).
double SceneTiming::driven_time(std::ptrdiff_t driver, double start, double t) const noexcept {
    if (driver < 0) return t;
    return driving_time(static_cast<std::size_t>(driver), t) - start;
}

double SceneTiming::tween_time(std::size_t i, double t) const noexcept {
    return driven_time(tweens_[i].driver, tweens_[i].start, t);
}

double SceneTiming::tween_progress(std::size_t i, double t) const noexcept {
    const Tween& tw = tweens_[i];
    return progress_at(tw.def, tw.duration, tween_time(i, t));
}

bool SceneTiming::tween_reached(std::size_t i, double t) const noexcept {
    const Tween& tw = tweens_[i];
    if (!(t >= tw.entry)) return false;
    return tw.driver < 0 || tween_time(i, t) >= 0.0;
}

double SceneTiming::timeline_time(std::size_t k, double t) const noexcept {
    return std::min(driving_time(k, t), std::max(timelines_[k].layout.duration, 0.0));
}

double SceneTiming::driving_time(std::size_t k, double t) const noexcept {
    const Timeline& tl = timelines_[k];
    const std::ptrdiff_t parent = tl.layout.parent;
    const double in_parent = parent < 0 ? t : driving_time(static_cast<std::size_t>(parent), t) - tl.layout.start_in_parent;
    const double d = tl.layout.duration;
    if (!(d > 0.0)) {
        // Nothing but labels: always at its start. Children whose lengths underflowed to 0
        // (time scales of 1e300 nested) have happened at any time after its start.
        const bool holds = std::any_of(tl.layout.index.begin(), tl.layout.index.end(), [](std::ptrdiff_t i) { return i >= 0; });
        return holds && in_parent * tl.def.time_scale - tl.def.delay > 0.0 ? HUGE_VAL : 0.0;
    }
    // The engine's timelines' arithmetic (its time at its own scale, less the delay, over the
    // play's length), so that the scene and an engine ticking the same times agree bit for
    // bit: timeline_local_time's −delay/d + t·(scale/d) rounds differently when d is not a
    // power of two.
    const double plays = tl.def.repeat < 0 ? 0.0 : tl.def.repeat + 1.0;
    const PlayState s = play_at_position((in_parent * tl.def.time_scale - tl.def.delay) / d, plays, false, tl.def.yoyo,
                                         tl.def.repeat_delay / d);
    const double phase = std::clamp(s.phase, 0.0, 1.0);
    return s.backward ? (1.0 - phase) * d : phase * d;
}

double SceneTiming::animation_time(std::size_t i, double t) const noexcept {
    return driven_time(animations_[i].driver, animations_[i].start, t);
}

double SceneTiming::progress(std::size_t i, double t) const noexcept {
    const Animation& a = animations_[i];
    if (!(a.duration > 0.0)) return a.def.curve(a.def.reversed ? 1.0 : 0.0);  // not playable: its start
    return progress_at(a.def, a.duration, animation_time(i, t));
}

double SceneTiming::animation3_time(std::size_t i, double t) const noexcept {
    return driven_time(animations3_[i].driver, animations3_[i].start, t);
}

double SceneTiming::animation3_progress(std::size_t i, double t) const noexcept {
    const Animation& a = animations3_[i];
    if (!(a.duration > 0.0)) return a.def.curve(a.def.reversed ? 1.0 : 0.0);  // not playable: its start
    return progress_at(a.def, a.duration, animation3_time(i, t));
}

bool SceneTiming::animation3_backward(std::size_t i, double t) const noexcept {
    const Animation& a = animations3_[i];
    if (!(a.duration > 0.0)) return a.def.reversed;
    return play_at(a.def, a.duration, animation3_time(i, t)).backward;
}

double SceneTiming::end_time() const noexcept {
    double end = 0.0;
    for (const Animation& a : animations_)
        if (a.driver < 0) end = std::max(end, a.duration > 0.0 ? grape::end_time(a.def, a.duration) : 0.0);
    for (const Animation& a : animations3_)
        if (a.driver < 0) end = std::max(end, a.duration > 0.0 ? grape::end_time(a.def, a.duration) : 0.0);
    for (const Tween& tw : tweens_)
        if (tw.driver < 0) end = std::max(end, grape::end_time(tw.def, tw.duration));
    for (const Timeline& tl : timelines_)
        if (tl.layout.parent < 0) end = std::max(end, tl.layout.end_time);
    return end;
}

}  // namespace grape
