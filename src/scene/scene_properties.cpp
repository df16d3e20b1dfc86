// Scene properties evaluated at any time: their tweens ordered by entry, from-current and
// relative starts resolved once in that order, the value at t found from the last tween
// begun (the rule in grape/scene_values.hpp).
#include <grape/scene_values.hpp>

#include <grape/error.hpp>

#include "scene_json.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <string_view>
#include <unordered_map>

namespace grape {

namespace {

using scene_io::child;
using scene_io::fail;

// AngleLerp in degrees: the same arithmetic with a turn of 360.
double degrees_lerp(double a, double b, double t, bool shortest) noexcept {
    if (!shortest) return grape::lerp(a, b, t);
    const double turn = b - a;
    const double d = std::abs(turn) <= 180.0 ? turn : std::remainder(turn, 360.0);
    return t == 1.0 ? a + d : a + d * t;
}

std::size_t index_of(ScenePropertyType type) noexcept {
    switch (type) {
        case ScenePropertyType::number:
        case ScenePropertyType::angle: return 0;
        case ScenePropertyType::vec2: return 1;
        case ScenePropertyType::color: return 2;
        case ScenePropertyType::vec3: return 3;
        case ScenePropertyType::quat: return 4;
    }
    return 0;
}

const char* what_of(ScenePropertyType type) noexcept {
    switch (type) {
        case ScenePropertyType::number: return "a number";
        case ScenePropertyType::angle: return "an angle (a number)";
        case ScenePropertyType::vec2: return "a vec2 [x, y]";
        case ScenePropertyType::color: return "a colour";
        case ScenePropertyType::vec3: return "a vec3 [x, y, z]";
        case ScenePropertyType::quat: return "a quat [w, x, y, z]";
    }
    return "a number";
}

SceneValue add(const SceneValue& a, const SceneValue& b) noexcept {
    if (const double* x = std::get_if<double>(&a)) return *x + std::get<double>(b);
    if (const Vec3* p = std::get_if<Vec3>(&a)) return *p + std::get<Vec3>(b);
    return std::get<Vec2>(a) + std::get<Vec2>(b);
}

bool finite(const SceneValue& v) noexcept {
    if (const double* x = std::get_if<double>(&v)) return std::isfinite(*x);
    if (const Vec2* p = std::get_if<Vec2>(&v)) return std::isfinite(p->x) && std::isfinite(p->y);
    if (const Vec3* p = std::get_if<Vec3>(&v)) return is_finite(*p);
    if (const Quat* q = std::get_if<Quat>(&v)) return is_finite(*q);
    const Color& c = std::get<Color>(v);
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && std::isfinite(c.a);
}

void check_value(const SceneValue& v, const SceneProperty& prop, const std::string& pointer) {
    if (v.index() != index_of(prop.type))
        fail(pointer, std::string("expected ") + what_of(prop.type) + " (the type of property \"" + prop.name + "\")");
    if (!finite(v)) fail(pointer, "number out of range");
    if (const Quat* q = std::get_if<Quat>(&v); q && !(length(*q) > 0.0))
        fail(pointer, "a quaternion must not be zero (it is normalized to an orientation)");
}

// Quaternions are evaluated as the unit ones they stand for; the scene keeps them as written,
// so that it saves what it read.
SceneValue unit_value(const SceneValue& v) noexcept {
    if (const Quat* q = std::get_if<Quat>(&v)) return normalized(*q);
    return v;
}

// The progress a curve covers over t ∈ [0, 1]: the range of 257 samples and its ends, widened
// by 1/64 of its width for peaks between samples; an elastic curve's swings can be narrower
// than the samples, so its amplitude counts as reached either way.
struct ProgressRange {
    double lo = 0.0, hi = 1.0;
};
ProgressRange progress_range(const Curve& curve) noexcept {
    ProgressRange r;
    for (int k = 0; k <= 256; ++k) {
        const double u = curve(k / 256.0);
        r.lo = std::min(r.lo, u);
        r.hi = std::max(r.hi, u);
    }
    const double widen = (r.hi - r.lo) / 64.0;
    r.lo -= widen;
    r.hi += widen;
    const CurveKind kind = curve.kind();
    if (kind >= CurveKind::elastic_in && kind <= CurveKind::elastic_out_in) {
        r.lo = std::min(r.lo, -curve.parameter(0));
        r.hi = std::max(r.hi, 1.0 + curve.parameter(0));
    }
    return r;
}

// True when every value the tween writes for progress in `range` is finite. Numbers, vec2 and
// angles are linear in the progress, so finite at both ends (products included: an overflowing
// product is infinite there) means finite between; a colour mixes through powers and cube
// roots of each end, so half way is checked too.
bool stays_finite(const SceneProperty& prop, const SceneValue& a, const SceneValue& b, ProgressRange range) noexcept {
    if (!finite(a) || !finite(b)) return false;
    for (double u : {range.lo, 0.5, range.hi})
        if (!finite(interpolate(prop, a, b, u))) return false;
    return true;
}

}  // namespace

SceneValue interpolate(const SceneProperty& property, const SceneValue& a, const SceneValue& b, double u) noexcept {
    switch (property.type) {
        case ScenePropertyType::number: return grape::lerp(std::get<double>(a), std::get<double>(b), u);
        case ScenePropertyType::angle: {
            const double x = std::get<double>(a), y = std::get<double>(b);
            return property.degrees ? degrees_lerp(x, y, u, property.shortest) : AngleLerp{property.shortest}(x, y, u);
        }
        case ScenePropertyType::vec2: return grape::lerp(std::get<Vec2>(a), std::get<Vec2>(b), u);
        case ScenePropertyType::color: return mix(std::get<Color>(a), std::get<Color>(b), u, property.space);
        case ScenePropertyType::vec3: return grape::lerp(std::get<Vec3>(a), std::get<Vec3>(b), u);
        case ScenePropertyType::quat: return slerp(normalized(std::get<Quat>(a)), normalized(std::get<Quat>(b)), u);
    }
    return a;
}

SceneProperties::SceneProperties(const Scene& scene, const SceneTiming& timing)
    : properties_(scene.properties), timing_(timing) {
    // Properties by name, hashed: a scene of 10⁵ properties and tweens loads in linear time
    // (comparing each name with every other took minutes).
    std::unordered_map<std::string_view, std::size_t> by_name;
    by_name.reserve(properties_.size());
    for (std::size_t k = 0; k < properties_.size(); ++k) {
        const SceneProperty& prop = properties_[k];
        const std::string p = child("/properties", k);
        if (prop.name.empty()) fail(child(p, "name"), "must not be empty");
        if (!by_name.emplace(prop.name, k).second) fail(child(p, "name"), "duplicate name \"" + prop.name + "\"");
        check_value(prop.value, prop, child(p, "value"));
        properties_[k].value = unit_value(prop.value);
    }
    if (timing.tween_count() != scene.tweens.size())
        throw Error("scene: /tweens: the timing was built from another scene (" + std::to_string(timing.tween_count()) +
                    " tweens, the scene has " + std::to_string(scene.tweens.size()) + ")");
    order_.assign(properties_.size(), {});
    for (std::size_t i = 0; i < scene.tweens.size(); ++i) {
        const SceneTween& tw = scene.tweens[i];
        const std::string p = child("/tweens", i);
        const auto found = by_name.find(tw.property);
        if (found == by_name.end()) fail(child(p, "property"), "no property named \"" + tw.property + "\" in /properties");
        const std::size_t k = found->second;
        const SceneProperty& prop = properties_[k];
        if (tw.mode == ValueMode::from_to) check_value(tw.from, prop, child(p, "from"));
        if (tw.mode == ValueMode::relative && prop.type == ScenePropertyType::color)
            fail(child(p, "by"), "a colour cannot move by an amount (property \"" + prop.name + "\" is a color): give \"to\"");
        if (tw.mode == ValueMode::relative && prop.type == ScenePropertyType::quat)
            fail(child(p, "by"), "a quaternion cannot move by an amount (property \"" + prop.name + "\" is a quat): give \"to\"");
        check_value(tw.to, prop, child(p, tw.mode == ValueMode::relative ? "by" : "to"));
        if (!(tw.duration > 0.0) || !std::isfinite(tw.duration)) fail(child(p, "duration"), "must be positive and finite");
        if (!(tw.delay >= 0.0) || !std::isfinite(tw.delay)) fail(child(p, "delay"), "must be finite and ≥ 0");
        if (!(tw.repeat_delay >= 0.0) || !std::isfinite(tw.repeat_delay)) fail(child(p, "repeat_delay"), "must be finite and ≥ 0");
        if (!(tw.time_scale > 0.0) || !std::isfinite(tw.time_scale)) fail(child(p, "time_scale"), "must be positive and finite");
        if (tw.repeat < -1) fail(child(p, "repeat"), "must be −1 (forever) or a count ≥ 0");
        const double u0 = tw.curve(tw.reversed ? 1.0 : 0.0);
        tweens_.push_back({unit_value(tw.mode == ValueMode::from_to ? tw.from : prop.value), unit_value(tw.to), k, u0});
        order_[k].push_back(i);
        entry_.push_back(timing.tween_entry(i));
    }
    // Each property's tweens by entry (ties: their order in "tweens"); then, in that order,
    // each from-current or relative start is the value the tweens before it give at its entry.
    for (std::size_t k = 0; k < order_.size(); ++k) {
        std::vector<std::size_t>& list = order_[k];
        std::stable_sort(list.begin(), list.end(), [&](std::size_t a, std::size_t b) { return entry_[a] < entry_[b]; });
        for (std::size_t n = 0; n < list.size(); ++n) {
            const std::size_t i = list[n];
            const ValueMode mode = scene.tweens[i].mode;
            if (mode == ValueMode::from_to) continue;
            const SceneValue start = value_of(k, n, entry_[i]);
            tweens_[i].from = start;
            if (mode == ValueMode::relative) tweens_[i].to = add(start, scene.tweens[i].to);
        }
    }
    // Values that overflow on the way (a start of 1e308 moved by 1e308, a colour whose linear
    // light is past the largest double) would write infinities or NaN: refused, naming the
    // end the tween gives.
    for (std::size_t i = 0; i < tweens_.size(); ++i) {
        const SceneTween& tw = scene.tweens[i];
        const SceneProperty& prop = properties_[tweens_[i].property];
        if (!stays_finite(prop, tweens_[i].from, tweens_[i].to, progress_range(tw.curve)))
            fail(child(child("/tweens", i), tw.mode == ValueMode::relative ? "by" : "to"),
                 "the values from the start to this end overflow the range of a double (property \"" + prop.name + "\")");
    }
}

SceneValue SceneProperties::value(std::size_t property, double t) const noexcept {
    return value_of(property, order_[property].size(), t);
}

// The value at t given only the first `count` tweens of the property's order.
SceneValue SceneProperties::value_of(std::size_t property, std::size_t count, double t) const noexcept {
    const SceneProperty& prop = properties_[property];
    const std::vector<std::size_t>& list = order_[property];
    // The tweens entered by t are a prefix of the order.
    const auto first = list.begin();
    const auto entered = std::upper_bound(first, first + static_cast<std::ptrdiff_t>(count), t,
                                          [&](double time, std::size_t i) { return time < entry_[i]; });
    if (entered == first) return prop.value;
    for (auto it = entered; it != first;) {
        const std::size_t i = *--it;
        if (timing_.tween_reached(i, t)) return interpolate(prop, tweens_[i].from, tweens_[i].to, timing_.tween_progress(i, t));
    }
    // Entered, but none has begun its current play (a timeline looped back before them): the
    // first rests at its start.
    const Tween& rest = tweens_[*first];
    return interpolate(prop, rest.from, rest.to, rest.start_u);
}

}  // namespace grape
