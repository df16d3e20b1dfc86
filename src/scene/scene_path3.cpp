// 3-D paths as JSON objects: one reader for `grape path3` and for scene files, so that every
// error names the JSON pointer of the bad value (docs/scene-format.md, "3-D paths").
#include "scene_json.hpp"

#include <grape/error.hpp>
#include <grape/math.hpp>
#include <grape/scene_path3.hpp>

#include <string>
#include <vector>

namespace grape::scene_io {

namespace {

// The array `key` of `obj` as points [x, y, z]: at least `at_least` of them, and exactly that
// many when `exact`.
std::vector<Vec3> points3_field(const json& obj, const std::string& pointer, const std::string& kind,
                                std::size_t at_least, bool exact) {
    const json& a = array_field(obj, pointer, "points");
    const std::string p = child(pointer, "points");
    if (exact && a.size() != at_least)
        fail(p, "a " + kind + " has exactly " + std::to_string(at_least) + " points (got " + std::to_string(a.size()) + ")");
    if (a.size() < at_least)
        fail(p, "too few points: " + std::to_string(a.size()) + " (at least " + std::to_string(at_least) + ")");
    std::vector<Vec3> out;
    out.reserve(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) out.push_back(vec3(a[i], child(p, i)));
    return out;
}

Vec3 vec3_field3(const json& obj, const std::string& pointer, std::string_view key) {
    return vec3(required(obj, pointer, key), child(pointer, key));
}

// The helix's own checks, made here first so that each names its field (Path3::helix's
// thresholds: a zero vector, or a start within ~1e-8 rad of the axis).
Path3 helix3(const json& j, const std::string& pointer) {
    object(j, pointer, {"kind", "center", "axis", "start", "radius", "rise_per_turn", "turns"});
    HelixSpec spec;
    spec.center = vec3_field3(j, pointer, "center");
    spec.axis = vec3_field3(j, pointer, "axis");
    spec.start = vec3_field3(j, pointer, "start");
    spec.radius = positive_field(j, pointer, "radius");
    spec.rise = number_field(j, pointer, "rise_per_turn", 0.0);
    spec.turns = positive_field(j, pointer, "turns");
    const Vec3 axis = normalized(spec.axis);
    if (!(length(axis) > 0.5)) fail(child(pointer, "axis"), "must not be the zero vector");
    const Vec3 start = normalized(spec.start);
    if (!(length(start) > 0.5)) fail(child(pointer, "start"), "must not be the zero vector");
    if (!(length(start - axis * dot(start, axis)) > 1e-8))
        fail(child(pointer, "start"), "is parallel to the axis (it gives the direction from the axis to the first point)");
    return Path3::helix(spec);
}

Path3 catmull_rom3(const json& j, const std::string& pointer) {
    object(j, pointer, {"kind", "points", "alpha", "closed"});
    const bool closed = bool_field(j, pointer, "closed", false);
    const std::vector<Vec3> points = points3_field(j, pointer, "catmull-rom", closed ? 3 : 2, false);
    const double alpha = number_field(j, pointer, "alpha", 0.0);
    CatmullRom type = CatmullRom::uniform;
    if (alpha == 0.5) type = CatmullRom::centripetal;
    else if (alpha == 1.0) type = CatmullRom::chordal;
    else if (alpha != 0.0)
        fail(child(pointer, "alpha"), "must be 0 (uniform), 0.5 (centripetal) or 1 (chordal) (got " + number_text(alpha) + ")");
    return Path3::catmull_rom(points, type, closed);
}

Path3 complex3(const json& j, const std::string& pointer, int depth) {
    object(j, pointer, {"kind", "parts", "cues"});
    const json& parts_json = array_field(j, pointer, "parts");
    const std::string pp = child(pointer, "parts");
    if (parts_json.empty()) fail(pp, "a complex path needs at least one part");
    std::vector<Path3> parts;
    parts.reserve(parts_json.size());
    for (std::size_t i = 0; i < parts_json.size(); ++i) parts.push_back(read_path3(parts_json[i], child(pp, i), depth + 1));
    const auto cues_it = j.find("cues");
    if (cues_it == j.end() || (cues_it->is_string() && cues_it->get<std::string>() == "by_length"))
        return Path3::complex_by_length(std::move(parts));
    const std::string cp = child(pointer, "cues");
    if (!cues_it->is_array()) fail(cp, "expected an array of numbers or \"by_length\", got " + type_of(*cues_it));
    if (cues_it->size() != parts.size())
        fail(cp, "one cue per part: " + std::to_string(parts.size()) + " parts but " + std::to_string(cues_it->size()) +
                     " cues");
    std::vector<double> cues;
    cues.reserve(parts.size());
    for (std::size_t i = 0; i < cues_it->size(); ++i) {
        const double c = number((*cues_it)[i], child(cp, i));
        if (i == 0 && c != 0.0) fail(child(cp, i), "the first cue must be 0 (got " + number_text(c) + ")");
        if (c < 0.0 || c > 1.0) fail(child(cp, i), "cues must lie in [0, 1] (got " + number_text(c) + ")");
        if (i > 0 && c < cues.back())
            fail(child(cp, i), "cues must not decrease (" + number_text(c) + " after " + number_text(cues.back()) + ")");
        cues.push_back(c);
    }
    return Path3::complex(std::move(parts), std::move(cues));
}

Path3 hermite3(const json& j, const std::string& pointer) {
    object(j, pointer, {"kind", "points", "tangents", "closed"});
    const bool closed = bool_field(j, pointer, "closed", false);
    const std::vector<Vec3> points = points3_field(j, pointer, "hermite", closed ? 3 : 2, false);
    const json& t = array_field(j, pointer, "tangents");
    const std::string tp = child(pointer, "tangents");
    if (t.size() != points.size())
        fail(tp, "one tangent per point: " + std::to_string(points.size()) + " points but " + std::to_string(t.size()) +
                     " tangents");
    std::vector<Vec3> tangents;
    tangents.reserve(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) tangents.push_back(vec3(t[i], child(tp, i)));
    return Path3::hermite(points, tangents, closed);
}

Path3 arc3(const json& j, const std::string& pointer) {
    object(j, pointer, {"kind", "center", "axis", "start", "radius", "start_angle", "end_angle"});
    Arc3Spec spec;
    spec.center = vec3_field3(j, pointer, "center");
    spec.axis = vec3_field3(j, pointer, "axis");
    spec.start = vec3_field3(j, pointer, "start");
    spec.radius = positive_field(j, pointer, "radius");
    spec.start_angle = number_field(j, pointer, "start_angle", 0.0);
    spec.end_angle = number_field(j, pointer, "end_angle", 2.0 * pi);
    return Path3::arc(spec);
}

// A 2-D path object (any kind a scene holds, SVG data strictly) on a plane in space.
Path3 on_plane3(const json& j, const std::string& pointer, int depth) {
    object(j, pointer, {"kind", "path", "origin", "x_axis", "y_axis"});
    const Path flat = PathReader{}.read_any(required(j, pointer, "path"), child(pointer, "path"), depth + 1);
    return Path3::on_plane(flat, vec3_field3(j, pointer, "origin"), vec3_field3(j, pointer, "x_axis"),
                           vec3_field3(j, pointer, "y_axis"));
}

Path3 kind3(const json& j, const std::string& pointer, const std::string& kind, int depth) {
    if (kind == "line") {
        object(j, pointer, {"kind", "points"});
        const auto p = points3_field(j, pointer, kind, 2, true);
        return Path3::line(p[0], p[1]);
    }
    if (kind == "quadratic") {
        object(j, pointer, {"kind", "points"});
        const auto p = points3_field(j, pointer, kind, 3, true);
        return Path3::quadratic_bezier(p[0], p[1], p[2]);
    }
    if (kind == "cubic") {
        object(j, pointer, {"kind", "points"});
        const auto p = points3_field(j, pointer, kind, 4, true);
        return Path3::cubic_bezier(p[0], p[1], p[2], p[3]);
    }
    if (kind == "helix") return helix3(j, pointer);
    if (kind == "catmull-rom") return catmull_rom3(j, pointer);
    if (kind == "complex") return complex3(j, pointer, depth);
    if (kind == "hermite") return hermite3(j, pointer);
    if (kind == "linear") {
        object(j, pointer, {"kind", "points", "closed"});
        const bool closed = bool_field(j, pointer, "closed", false);
        return Path3::linear_spline(points3_field(j, pointer, kind, closed ? 3 : 2, false), closed);
    }
    if (kind == "arc") return arc3(j, pointer);
    if (kind == "projectile") {
        object(j, pointer, {"kind", "position", "velocity", "acceleration", "seconds"});
        return Path3::projectile(vec3_field3(j, pointer, "position"), vec3_field3(j, pointer, "velocity"),
                                 vec3_field3(j, pointer, "acceleration"), positive_field(j, pointer, "seconds"));
    }
    if (kind == "on_plane") return on_plane3(j, pointer, depth);
    fail(child(pointer, "kind"), "unknown 3-D path kind \"" + kind +
                                     "\" (line, quadratic, cubic, helix, catmull-rom, complex, hermite, linear, arc, "
                                     "projectile, on_plane)");
}

}  // namespace

Vec3 vec3(const json& j, const std::string& pointer) {
    if (!j.is_array() || j.size() != 3)
        fail(pointer, "expected a point [x, y, z], got " + type_of(j) + (j.is_array() ? " of " + std::to_string(j.size()) : ""));
    return {number(j[0], child(pointer, 0)), number(j[1], child(pointer, 1)), number(j[2], child(pointer, 2))};
}

Path3 read_path3(const json& j, const std::string& pointer, int depth) {
    if (depth > max_depth) fail(pointer, "paths nested more than " + std::to_string(max_depth) + " deep");
    if (!j.is_object()) fail(pointer, "expected a 3-D path object, got " + type_of(j));
    const std::string kind = string_value(required(j, pointer, "kind"), child(pointer, "kind"));
    try {
        return kind3(j, pointer, kind, depth);
    } catch (const Error& e) {
        const std::string what = e.what();
        if (what.rfind("scene: ", 0) == 0) throw;
        // A Path3 constructor's own message, "Path3::arc: start: parallel to the axis": at the
        // field it names when the object has that field, else at the object.
        const std::size_t name_at = what.find(": ");
        const std::size_t name_end = name_at == std::string::npos ? name_at : what.find(": ", name_at + 2);
        if (name_end != std::string::npos) {
            const std::string field = what.substr(name_at + 2, name_end - name_at - 2);
            if (j.contains(field)) fail(child(pointer, field), what.substr(name_end + 2));
        }
        fail(pointer, what);
    }
}

}  // namespace grape::scene_io

namespace grape {

Path3 parse_path3_json(std::string_view text) {
    const scene_io::json j = scene_io::parse_text(text, "path3: ");
    try {
        return scene_io::read_path3(j, "", 0);
    } catch (const Error& e) {
        // The reader speaks as part of a scene; alone, the object is a 3-D path.
        std::string what = e.what();
        if (what.rfind("scene: ", 0) == 0) what.replace(0, 7, "path3: ");
        throw Error(what);
    }
}

}  // namespace grape
