// Scene properties and tweens read and written as JSON: each value checked against its
// property's type at its JSON pointer; colours as CSS text (or [r, g, b, a] when no text
// holds them exactly), so save → load gives the same doubles.
#include <grape/scene.hpp>

#include <grape/color.hpp>
#include <grape/error.hpp>

#include "scene_json.hpp"

#include <cmath>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>

namespace grape {

namespace scene_io {

namespace {

std::string_view type_name(ScenePropertyType type) noexcept {
    switch (type) {
        case ScenePropertyType::number: return "number";
        case ScenePropertyType::angle: return "angle";
        case ScenePropertyType::vec2: return "vec2";
        case ScenePropertyType::color: return "color";
        case ScenePropertyType::vec3: return "vec3";
        case ScenePropertyType::quat: return "quat";
    }
    return "number";
}

std::string curve_text(const Curve& c, const std::string& pointer) {
    if (c.kind() == CurveKind::function)
        fail(pointer, "a curve from a function (Curve::from_function) has no text form and cannot be saved in a scene");
    return to_string(c);
}

Color color_value(const json& j, const std::string& pointer) {
    if (j.is_string()) {
        try {
            return parse_color(j.get<std::string>());
        } catch (const Error& e) {
            fail(pointer, e.what());
        }
    }
    if (j.is_array() && j.size() == 4) {
        Color c;
        double* v[4] = {&c.r, &c.g, &c.b, &c.a};
        for (std::size_t k = 0; k < 4; ++k) *v[k] = number(j[k], child(pointer, k));
        return c;
    }
    fail(pointer, "expected a colour (CSS text such as \"#ff8000\" or \"rgb(255 128 0 / 50%)\", or [r, g, b, a] sRGB-encoded numbers), got " +
                      type_of(j) + (j.is_array() ? " of " + std::to_string(j.size()) : ""));
}

}  // namespace

SceneValue read_value(const json& j, const std::string& pointer, ScenePropertyType type) {
    switch (type) {
        case ScenePropertyType::number:
        case ScenePropertyType::angle: {
            if (!j.is_number())
                fail(pointer, std::string("expected a number (the property is ") +
                                  (type == ScenePropertyType::angle ? "an angle" : "a number") + "), got " + type_of(j));
            return number(j, pointer);
        }
        case ScenePropertyType::vec2: return vec2(j, pointer);
        case ScenePropertyType::color: return color_value(j, pointer);
        case ScenePropertyType::vec3: return vec3(j, pointer);
        case ScenePropertyType::quat: {
            if (!j.is_array() || j.size() != 4) fail(pointer, "expected a quaternion [w, x, y, z], got " + type_of(j));
            const Quat q{number(j[0], child(pointer, 0)), number(j[1], child(pointer, 1)), number(j[2], child(pointer, 2)),
                         number(j[3], child(pointer, 3))};
            if (!(length(q) > 0.0)) fail(pointer, "a quaternion must not be zero (it is normalized to an orientation)");
            return q;
        }
    }
    return 0.0;
}

ordered value_json(const SceneValue& v) {
    if (const double* d = std::get_if<double>(&v)) return *d;
    if (const Vec2* p = std::get_if<Vec2>(&v)) return point_json(*p);
    if (const Vec3* p = std::get_if<Vec3>(&v)) return ordered::array({p->x, p->y, p->z});
    if (const Quat* q = std::get_if<Quat>(&v)) return ordered::array({q->w, q->x, q->y, q->z});
    const Color& c = std::get<Color>(v);
    // Hex when it reads back as these very doubles (any colour read from hex does), else the numbers.
    const std::string hex = to_hex(c);
    if (parse_color(hex) == c) return hex;
    return ordered::array({c.r, c.g, c.b, c.a});
}

void read_properties(const json& v, Scene& scene) {
    if (!v.is_array()) fail("/properties", "expected an array, got " + type_of(v));
    std::set<std::string> names;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const std::string p = child("/properties", i);
        const json& o = object(v[i], p, {"name", "type", "value", "space", "turn", "unit"});
        SceneProperty prop;
        prop.name = name_field(o, p, &names);
        const std::string type = one_of(o, p, "type", "number", {"number", "angle", "vec2", "color", "vec3", "quat"});
        prop.type = type == "angle"  ? ScenePropertyType::angle
                    : type == "vec2" ? ScenePropertyType::vec2
                    : type == "color" ? ScenePropertyType::color
                    : type == "vec3" ? ScenePropertyType::vec3
                    : type == "quat" ? ScenePropertyType::quat
                                      : ScenePropertyType::number;
        const auto only_for = [&](const char* key, ScenePropertyType t, const char* what) {
            if (o.contains(key) && prop.type != t)
                fail(child(p, key), std::string("only ") + what + " have \"" + key + "\" (this property is a " + type + ")");
        };
        only_for("space", ScenePropertyType::color, "colours");
        only_for("turn", ScenePropertyType::angle, "angles");
        only_for("unit", ScenePropertyType::angle, "angles");
        prop.space = one_of(o, p, "space", "linear", {"linear", "oklab"}) == "oklab" ? ColorSpace::oklab : ColorSpace::linear_srgb;
        prop.shortest = one_of(o, p, "turn", "shortest", {"shortest", "every"}) == "shortest";
        prop.degrees = one_of(o, p, "unit", "radians", {"radians", "degrees"}) == "degrees";
        prop.value = read_value(required(o, p, "value"), child(p, "value"), prop.type);
        scene.properties.push_back(std::move(prop));
    }
}

ordered properties_json(const Scene& scene) {
    ordered a = ordered::array();
    for (const SceneProperty& prop : scene.properties) {
        ordered o;
        o["name"] = prop.name;
        o["type"] = type_name(prop.type);
        o["value"] = value_json(prop.value);
        if (prop.type == ScenePropertyType::color) o["space"] = prop.space == ColorSpace::oklab ? "oklab" : "linear";
        if (prop.type == ScenePropertyType::angle) {
            o["turn"] = prop.shortest ? "shortest" : "every";
            o["unit"] = prop.degrees ? "degrees" : "radians";
        }
        a.push_back(std::move(o));
    }
    return a;
}

void read_tweens(const json& v, Scene& scene) {
    if (!v.is_array()) fail("/tweens", "expected an array, got " + type_of(v));
    // Hashed: one lookup per tween, not Scene::find_property's scan of every property.
    std::unordered_map<std::string_view, std::size_t> properties;
    properties.reserve(scene.properties.size());
    for (std::size_t k = 0; k < scene.properties.size(); ++k) properties.emplace(scene.properties[k].name, k);
    for (std::size_t i = 0; i < v.size(); ++i) {
        const std::string p = child("/tweens", i);
        const json& o = object(v[i], p, {"name", "property", "from", "to", "by", "duration", "curve", "delay", "repeat",
                                          "repeat_delay", "yoyo", "reversed", "time_scale"});
        SceneTween tw;
        tw.name = name_field(o, p, nullptr);
        tw.property = string_value(required(o, p, "property"), child(p, "property"));
        const auto found = properties.find(tw.property);
        if (found == properties.end()) fail(child(p, "property"), "no property named \"" + tw.property + "\" in /properties");
        const SceneProperty& prop = scene.properties[found->second];
        const bool has_from = o.contains("from"), has_to = o.contains("to"), has_by = o.contains("by");
        if (has_to && has_by) fail(p, "\"to\" and \"by\" both given (a tween goes to a value or by an amount)");
        if (!has_to && !has_by) fail(p, "missing field \"to\" or \"by\"");
        if (has_from && has_by) fail(child(p, "by"), "\"by\" moves from the value when the tween begins; with \"from\", give \"to\"");
        if (has_by && prop.type == ScenePropertyType::color)
            fail(child(p, "by"), "a colour cannot move by an amount (property \"" + prop.name + "\" is a color): give \"to\"");
        if (has_by && prop.type == ScenePropertyType::quat)
            fail(child(p, "by"), "a quaternion cannot move by an amount (property \"" + prop.name + "\" is a quat): give \"to\"");
        tw.mode = has_from ? ValueMode::from_to : has_by ? ValueMode::relative : ValueMode::from_current;
        if (has_from) tw.from = read_value(o["from"], child(p, "from"), prop.type);
        else tw.from = prop.value;  // unused; of the property's type
        const char* end = has_by ? "by" : "to";
        tw.to = read_value(o[end], child(p, end), prop.type);
        curve_field(o, p, scene, tw.curve, tw.curve_name);
        tw.duration = positive_field(o, p, "duration");
        tw.delay = non_negative_field(o, p, "delay", 0.0);
        tw.repeat = repeat_field(o, p, tw.repeat);
        tw.repeat_delay = non_negative_field(o, p, "repeat_delay", 0.0);
        tw.yoyo = bool_field(o, p, "yoyo", false);
        tw.reversed = bool_field(o, p, "reversed", false);
        if (o.contains("time_scale")) tw.time_scale = positive_field(o, p, "time_scale");
        if (!std::isfinite(tw.end_time()) && tw.repeat != -1)
            fail(p, "the tween's length overflows (delay, duration, repeats and time scale)");
        scene.tweens.push_back(std::move(tw));
    }
}

ordered tweens_json(const Scene& scene) {
    ordered a = ordered::array();
    for (std::size_t i = 0; i < scene.tweens.size(); ++i) {
        const SceneTween& tw = scene.tweens[i];
        const std::string p = child("/tweens", i);
        ordered o;
        if (!tw.name.empty()) o["name"] = tw.name;
        o["property"] = tw.property;
        if (tw.mode == ValueMode::from_to) o["from"] = value_json(tw.from);
        o[tw.mode == ValueMode::relative ? "by" : "to"] = value_json(tw.to);
        o["duration"] = tw.duration;
        const NamedCurve* curve = tw.curve_name.empty() ? nullptr : scene.find_curve(tw.curve_name);
        o["curve"] = curve && curve->curve == tw.curve ? tw.curve_name : curve_text(tw.curve, child(p, "curve"));
        if (tw.delay != 0.0) o["delay"] = tw.delay;
        if (tw.repeat != 0) o["repeat"] = tw.repeat;
        if (tw.repeat_delay != 0.0) o["repeat_delay"] = tw.repeat_delay;
        if (tw.yoyo) o["yoyo"] = true;
        if (tw.reversed) o["reversed"] = true;
        if (tw.time_scale != 1.0) o["time_scale"] = tw.time_scale;
        a.push_back(std::move(o));
    }
    return a;
}

std::string saved_curve(const Curve& curve, const std::string& pointer) { return curve_text(curve, pointer); }

}  // namespace scene_io

AnimationDef SceneTween::def() const noexcept {
    AnimationDef d{.curve = curve, .delay = delay, .repeat = repeat, .reversed = reversed, .yoyo = yoyo, .time_scale = time_scale};
    d.repeat_delay = repeat_delay;
    return d;
}

double SceneTween::end_time() const noexcept { return grape::end_time(def(), duration); }

std::ptrdiff_t Scene::find_property(std::string_view name) const noexcept {
    for (std::size_t k = 0; k < properties.size(); ++k)
        if (properties[k].name == name) return static_cast<std::ptrdiff_t>(k);
    return -1;
}

}  // namespace grape
