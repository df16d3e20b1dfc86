// A scene's "paths3" and "animations3": read with every error at its JSON pointer, written so
// that save → load → save gives the same text (docs/scene-format.md, "3-D animations").
#include "scene_json.hpp"

#include <grape/error.hpp>
#include <grape/scene_animation3.hpp>

#include <cmath>
#include <set>
#include <string>
#include <type_traits>
#include <variant>

namespace grape::scene_io {

namespace {

constexpr std::string_view axis3_names[] = {"+x", "-x", "+y", "-y", "+z", "-z"};

Axis3 read_axis3(const json& obj, const std::string& pointer, std::string_view key, Axis3 fallback) {
    const std::string fallback_name(axis3_names[static_cast<std::size_t>(fallback)]);
    const std::string v = one_of(obj, pointer, key, fallback_name, {std::begin(axis3_names), std::end(axis3_names)});
    for (std::size_t i = 0; i < std::size(axis3_names); ++i)
        if (v == axis3_names[i]) return static_cast<Axis3>(i);
    return fallback;
}

ordered vec3_json(Vec3 v) { return ordered::array({v.x, v.y, v.z}); }

ordered vec3s_json(std::span<const Vec3> points) {
    ordered a = ordered::array();
    for (const Vec3& p : points) a.push_back(vec3_json(p));
    return a;
}

// The JSON object read_path3 reads back to the same path, from the path's description.
struct Path3Json {
    std::string pointer;

    ordered operator()(const Line3Spec& s) const {
        return {{"kind", "line"}, {"points", ordered::array({vec3_json(s.a), vec3_json(s.b)})}};
    }
    ordered operator()(const QuadraticBezier3Spec& s) const { return {{"kind", "quadratic"}, {"points", vec3s_json(s.control)}}; }
    ordered operator()(const CubicBezier3Spec& s) const { return {{"kind", "cubic"}, {"points", vec3s_json(s.control)}}; }
    ordered operator()(const CatmullRom3Spec& s) const {
        const double alpha = s.type == CatmullRom::centripetal ? 0.5 : s.type == CatmullRom::chordal ? 1.0 : 0.0;
        return {{"kind", "catmull-rom"}, {"points", vec3s_json(s.points)}, {"alpha", alpha}, {"closed", s.closed}};
    }
    ordered operator()(const HelixSpec& s) const {
        return {{"kind", "helix"}, {"center", vec3_json(s.center)}, {"axis", vec3_json(s.axis)}, {"start", vec3_json(s.start)},
                {"radius", s.radius}, {"rise_per_turn", s.rise}, {"turns", s.turns}};
    }
    ordered operator()(const Complex3Spec& s) const {
        ordered parts = ordered::array();
        for (std::size_t i = 0; i < s.parts.size(); ++i)
            parts.push_back(std::visit(Path3Json{child(child(pointer, "parts"), i)}, describe(s.parts[i])));
        return {{"kind", "complex"}, {"parts", std::move(parts)}, {"cues", s.cues}};
    }
    ordered operator()(const Hermite3Spec& s) const {
        return {{"kind", "hermite"}, {"points", vec3s_json(s.points)}, {"tangents", vec3s_json(s.tangents)}, {"closed", s.closed}};
    }
    ordered operator()(const LinearSpline3Spec& s) const {
        return {{"kind", "linear"}, {"points", vec3s_json(s.points)}, {"closed", s.closed}};
    }
    ordered operator()(const Arc3Spec& s) const {
        return {{"kind", "arc"}, {"center", vec3_json(s.center)}, {"axis", vec3_json(s.axis)}, {"start", vec3_json(s.start)},
                {"radius", s.radius}, {"start_angle", s.start_angle}, {"end_angle", s.end_angle}};
    }
    ordered operator()(const Projectile3Spec& s) const {
        return {{"kind", "projectile"}, {"position", vec3_json(s.position)}, {"velocity", vec3_json(s.velocity)},
                {"acceleration", vec3_json(s.acceleration)}, {"seconds", s.seconds}};
    }
    ordered operator()(const OnPlane3Spec& s) const {
        return {{"kind", "on_plane"}, {"path", path_json(s.path)}, {"origin", vec3_json(s.origin)},
                {"x_axis", vec3_json(s.x_axis)}, {"y_axis", vec3_json(s.y_axis)}};
    }
    [[noreturn]] ordered operator()(const Reparametrized3Spec&) const {
        fail(pointer, "a reparametrized 3-D path has no JSON form (play its source with \"speed\")");
    }
    [[noreturn]] ordered operator()(const Slice3Spec&) const {
        fail(pointer, "a slice of a 3-D path has no JSON form (play its source with \"range\")");
    }
};

const char* frame_mode_name(SceneFrameMode m) noexcept {
    switch (m) {
        case SceneFrameMode::rmf: return "rmf";
        case SceneFrameMode::frenet: return "frenet";
        case SceneFrameMode::up: return "up";
    }
    return "rmf";
}

const char* align3_name(Align3 a) noexcept {
    switch (a) {
        case Align3::none: return "none";
        case Align3::frame: return "frame";
        case Align3::world: return "world";
    }
    return "none";
}

void read_frame3(const json& o, const std::string& p, SceneAnimation3& a) {
    const auto f = o.find("frame");
    if (f == o.end()) return;
    const std::string fp = child(p, "frame");
    object(*f, fp, {"mode", "up", "cone"});
    const std::string mode = one_of(*f, fp, "mode", "rmf", {"rmf", "frenet", "up"});
    a.frame = mode == "frenet" ? SceneFrameMode::frenet : mode == "up" ? SceneFrameMode::up : SceneFrameMode::rmf;
    if (const auto u = f->find("up"); u != f->end()) {
        a.up = vec3(*u, child(fp, "up"));
        if (!(length(a.up) > 0.0) || !std::isfinite(length(a.up))) fail(child(fp, "up"), "must not be the zero vector");
    }
    if (f->contains("cone")) {
        if (a.frame != SceneFrameMode::up) fail(child(fp, "cone"), "is for \"mode\": \"up\" only");
        a.cone = number_field(*f, fp, "cone");
        if (!(a.cone >= 0.05 && a.cone <= 1.5)) fail(child(fp, "cone"), "must be in [0.05, 1.5] radians (got " + number_text(a.cone) + ")");
    }
}

void read_roll3(const json& o, const std::string& p, SceneAnimation3& a) {
    if (const auto r = o.find("roll"); r != o.end()) {
        const std::string rp = child(p, "roll");
        if (!r->is_array() || r->empty()) fail(rp, "expected an array of [s, radians] keys (at least one), got " + type_of(*r));
        for (std::size_t k = 0; k < r->size(); ++k) {
            const std::string kp = child(rp, k);
            const json& key = (*r)[k];
            if (!key.is_array() || key.size() != 2) fail(kp, "expected a key [s, radians], got " + type_of(key));
            const RollKey rk{number(key[0], child(kp, 0)), number(key[1], child(kp, 1))};
            if (rk.s < 0.0) fail(child(kp, 0), "arc length must be ≥ 0 (got " + number_text(rk.s) + ")");
            if (!a.roll.empty() && !(rk.s > a.roll.back().s))
                fail(child(kp, 0), "keys must be in increasing arc length (" + number_text(rk.s) + " after " +
                                       number_text(a.roll.back().s) + ")");
            a.roll.push_back(rk);
        }
    }
    if (const auto b = o.find("bank"); b != o.end()) {
        const std::string bp = child(p, "bank");
        if (!a.roll.empty()) fail(bp, "give \"roll\" or \"bank\", not both");
        object(*b, bp, {"speed", "gravity", "max_angle", "smoothing", "samples"});
        a.banked = true;
        a.bank.speed = number_field(*b, bp, "speed");
        if (!(a.bank.speed >= 0.0)) fail(child(bp, "speed"), "must be ≥ 0 (got " + number_text(a.bank.speed) + ")");
        if (b->contains("gravity")) a.bank.gravity = positive_field(*b, bp, "gravity");
        a.bank.max_angle = number_field(*b, bp, "max_angle", a.bank.max_angle);
        if (!(a.bank.max_angle >= 0.0 && a.bank.max_angle <= pi / 2))
            fail(child(bp, "max_angle"), "must be in [0, π/2] radians (got " + number_text(a.bank.max_angle) + ")");
        a.bank.smoothing = non_negative_field(*b, bp, "smoothing", 0.0);
        if (const auto n = b->find("samples"); n != b->end()) {
            const long long samples = integer(*n, child(bp, "samples"));
            if (samples < 2 || samples > (1LL << 20))
                fail(child(bp, "samples"), "must be in [2, 1048576] (got " + std::to_string(samples) + ")");
            a.bank.samples = static_cast<std::size_t>(samples);
        }
    }
}

// Orientation keys bound the spline's solve: O(n) a Newton step, at most QuatSpline::max_iterations.
constexpr std::size_t max_orientation_keys = 65536;

void read_orientation3(const json& o, const std::string& p, SceneAnimation3& a, bool keyed) {
    const auto r = o.find("orientation");
    if (r == o.end()) {
        if (keyed) fail(child(p, "align"), "\"keys\" needs \"orientation\": [[s, [w, x, y, z]], ...]");
        return;
    }
    const std::string rp = child(p, "orientation");
    if (!keyed) fail(rp, "gives the orientation itself: it needs \"align\": \"keys\"");
    if (!r->is_array() || r->empty() || r->size() > max_orientation_keys)
        fail(rp, "expected an array of 1 to 65536 [s, [w, x, y, z]] keys, got " + type_of(*r));
    for (std::size_t k = 0; k < r->size(); ++k) {
        const std::string kp = child(rp, k);
        const json& key = (*r)[k];
        if (!key.is_array() || key.size() != 2) fail(kp, "expected a key [s, [w, x, y, z]], got " + type_of(key));
        const double s = number(key[0], child(kp, 0));
        if (s < 0.0) fail(child(kp, 0), "arc length must be ≥ 0 (got " + number_text(s) + ")");
        if (!a.orientation.empty() && !(s > a.orientation.back().s))
            fail(child(kp, 0), "keys must be in increasing arc length (" + number_text(s) + " after " +
                                   number_text(a.orientation.back().s) + ")");
        const json& q = key[1];
        const std::string qp = child(kp, 1);
        if (!q.is_array() || q.size() != 4) fail(qp, "expected a quaternion [w, x, y, z], got " + type_of(q));
        const Quat value{number(q[0], child(qp, 0)), number(q[1], child(qp, 1)), number(q[2], child(qp, 2)),
                         number(q[3], child(qp, 3))};
        if (!(length(value) > 0.0) || !std::isfinite(length(value))) fail(qp, "must not be the zero quaternion");
        a.orientation.push_back({s, value});
    }
}

// Building the evaluator checks what only the path can tell (a frame's up along the tangent, a
// path of length 0 in speed mode); its messages name the field, placed under the animation.
void check_motion3(const SceneAnimation3& a, const std::string& p) {
    try {
        (void)SceneMotion3(a);
    } catch (const Error& e) {
        const std::string what = e.what();
        const std::size_t colon = what.find(": ");
        const std::string field = colon == std::string::npos ? std::string() : what.substr(0, colon);
        for (const char* key : {"speed", "frame", "axes", "roll", "bank", "orientation"})
            if (field == key) fail(child(p, key), what.substr(colon + 2));
        fail(p, what);
    }
}

SceneAnimation3 read_animation3(const json& j, const std::string& p, const Scene& scene) {
    const json& o = object(j, p, {"name", "path", "curve", "duration", "speed", "delay", "repeat", "yoyo", "reversed",
                                  "repeat_delay", "range", "align", "frame", "axes", "face_travel", "offset", "roll", "bank", "orientation"});
    SceneAnimation3 a;
    a.name = name_field(o, p, nullptr);
    const json& path = required(o, p, "path");
    if (path.is_string()) {
        a.path_name = path.get<std::string>();
        const NamedPath3* named = nullptr;
        for (const NamedPath3& n : scene.paths3)
            if (n.name == a.path_name) named = &n;
        if (!named) fail(child(p, "path"), "unknown 3-D path \"" + a.path_name + "\" (not in /paths3)");
        a.path = named->path;
    } else {
        a.path = read_path3(path, child(p, "path"), 0);
    }
    curve_field(o, p, scene, a.curve, a.curve_name);
    const bool has_duration = o.contains("duration"), has_speed = o.contains("speed");
    if (has_duration == has_speed) fail(p, "give exactly one of \"duration\" (seconds per play) and \"speed\" (units per second)");
    if (has_duration) a.duration = positive_field(o, p, "duration");
    else a.speed = positive_field(o, p, "speed");
    a.delay = non_negative_field(o, p, "delay", 0.0);
    a.repeat = repeat_field(o, p, a.repeat);
    a.yoyo = bool_field(o, p, "yoyo", false);
    a.reversed = bool_field(o, p, "reversed", false);
    a.repeat_delay = non_negative_field(o, p, "repeat_delay", 0.0);
    if (const auto r = o.find("range"); r != o.end()) {
        const std::string rp = child(p, "range");
        if (!r->is_array() || r->size() != 2) fail(rp, "expected [u0, u1] with both in [0, 1], got " + type_of(*r));
        for (std::size_t k = 0; k < 2; ++k) {
            const double u = number((*r)[k], child(rp, k));
            if (!(u >= 0.0 && u <= 1.0)) fail(child(rp, k), "must be in [0, 1] (got " + number_text(u) + ")");
            (k == 0 ? a.range_start : a.range_end) = u;
        }
    }
    const std::string align = one_of(o, p, "align", "none", {"none", "frame", "world", "keys"});
    a.align = align == "frame" ? Align3::frame : align == "world" ? Align3::world : Align3::none;
    read_orientation3(o, p, a, align == "keys");
    read_frame3(o, p, a);
    if (const auto ax = o.find("axes"); ax != o.end()) {
        const std::string ap = child(p, "axes");
        object(*ax, ap, {"forward", "up"});
        a.forward = read_axis3(*ax, ap, "forward", a.forward);
        a.model_up = read_axis3(*ax, ap, "up", a.model_up);
        if (dot(axis_vector(a.forward), axis_vector(a.model_up)) != 0.0)
            fail(child(ap, "up"), "must be perpendicular to forward (got " + std::string(axis3_names[static_cast<std::size_t>(a.forward)]) +
                                      " and " + std::string(axis3_names[static_cast<std::size_t>(a.model_up)]) + ")");
    }
    a.face_travel = bool_field(o, p, "face_travel", true);
    if (const auto off = o.find("offset"); off != o.end()) {
        const std::string op = child(p, "offset");
        if (!off->is_array() || off->size() != 2) fail(op, "expected [along the normal, along the binormal], got " + type_of(*off));
        a.normal_offset = number((*off)[0], child(op, 0));
        a.binormal_offset = number((*off)[1], child(op, 1));
    }
    read_roll3(o, p, a);
    check_motion3(a, p);
    return a;
}

}  // namespace

void read_paths3(const json& v, Scene& scene) {
    if (!v.is_array()) fail("/paths3", "expected an array, got " + type_of(v));
    std::set<std::string> names;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const std::string p = child("/paths3", i);
        if (!v[i].is_object()) fail(p, "expected an object with \"name\" and \"path\", got " + type_of(v[i]));
        const json& o = object(v[i], p, {"name", "path"});
        NamedPath3 named;
        named.name = name_field(o, p, &names);
        named.path = read_path3(required(o, p, "path"), child(p, "path"), 0);
        scene.paths3.push_back(std::move(named));
    }
}

void read_animations3(const json& v, Scene& scene) {
    if (!v.is_array()) fail("/animations3", "expected an array, got " + type_of(v));
    for (std::size_t i = 0; i < v.size(); ++i) scene.animations3.push_back(read_animation3(v[i], child("/animations3", i), scene));
}

ordered path3_json(const Path3& path, const std::string& pointer) { return std::visit(Path3Json{pointer}, describe(path)); }

ordered paths3_json(const Scene& scene) {
    ordered a = ordered::array();
    for (std::size_t i = 0; i < scene.paths3.size(); ++i)
        a.push_back({{"name", scene.paths3[i].name},
                     {"path", path3_json(scene.paths3[i].path, child(child("/paths3", i), "path"))}});
    return a;
}

ordered animations3_json(const Scene& scene) {
    ordered out = ordered::array();
    for (std::size_t i = 0; i < scene.animations3.size(); ++i) {
        const SceneAnimation3& a = scene.animations3[i];
        const std::string p = child("/animations3", i);
        ordered o;
        if (!a.name.empty()) o["name"] = a.name;
        ordered path = path3_json(a.path, child(p, "path"));
        // A reference is kept only while the named path still describes this very path.
        const NamedPath3* named = nullptr;
        for (const NamedPath3& n : scene.paths3)
            if (!a.path_name.empty() && n.name == a.path_name) named = &n;
        if (named && path3_json(named->path, child(p, "path")) == path) o["path"] = a.path_name;
        else o["path"] = std::move(path);
        const NamedCurve* curve = a.curve_name.empty() ? nullptr : scene.find_curve(a.curve_name);
        o["curve"] = curve && curve->curve == a.curve ? a.curve_name : saved_curve(a.curve, child(p, "curve"));
        if (a.speed > 0.0) o["speed"] = a.speed;
        else o["duration"] = a.duration;
        o["delay"] = a.delay;
        o["repeat"] = a.repeat;
        o["yoyo"] = a.yoyo;
        o["reversed"] = a.reversed;
        if (a.repeat_delay != 0.0) o["repeat_delay"] = a.repeat_delay;
        if (a.range_start != 0.0 || a.range_end != 1.0) o["range"] = {a.range_start, a.range_end};
        o["align"] = a.keyed() ? "keys" : align3_name(a.align);
        ordered frame = {{"mode", frame_mode_name(a.frame)}, {"up", vec3_json(a.up)}};
        if (a.frame == SceneFrameMode::up) frame["cone"] = a.cone;
        o["frame"] = std::move(frame);
        o["axes"] = {{"forward", axis3_names[static_cast<std::size_t>(a.forward)]},
                     {"up", axis3_names[static_cast<std::size_t>(a.model_up)]}};
        o["face_travel"] = a.face_travel;
        if (a.normal_offset != 0.0 || a.binormal_offset != 0.0) o["offset"] = {a.normal_offset, a.binormal_offset};
        if (!a.roll.empty()) {
            ordered keys = ordered::array();
            for (const RollKey& k : a.roll) keys.push_back({k.s, k.roll});
            o["roll"] = std::move(keys);
        }
        if (a.keyed()) {
            ordered keys = ordered::array();
            for (const SceneOrientationKey& k : a.orientation) keys.push_back({k.s, {k.q.w, k.q.x, k.q.y, k.q.z}});
            o["orientation"] = std::move(keys);
        }
        if (a.banked)
            o["bank"] = {{"speed", a.bank.speed}, {"gravity", a.bank.gravity}, {"max_angle", a.bank.max_angle},
                         {"smoothing", a.bank.smoothing}, {"samples", a.bank.samples}};
        out.push_back(std::move(o));
    }
    return out;
}

}  // namespace grape::scene_io
