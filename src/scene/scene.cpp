// Scene files: JSON ↔ grape objects. Every read goes through a helper that knows the JSON
// pointer of the value, so each error names where it is and why.
#include <grape/scene.hpp>

#include <grape/error.hpp>

#include "atomic_file.hpp"

#include "file_text.hpp"
#include "json_pointer.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <system_error>

namespace grape {

namespace {

using json = nlohmann::json;
using ordered = nlohmann::ordered_json;

// Nested complex paths deeper than this are refused: no real scene needs it, and it bounds
// the recursion on hostile input.
constexpr int max_depth = 32;
// More simulation steps than this is a typo (or an attack), not a scene.
constexpr double max_steps = 1e7;

[[noreturn]] void fail(const std::string& pointer, const std::string& why) {
    throw Error("scene: " + (pointer.empty() ? std::string("/") : pointer) + ": " + why);
}

using detail::child;
using detail::number_text;
using detail::type_of;

// An object whose keys must all be among `allowed` (a typo such as "duraton" is an error,
// not a silently ignored field).
const json& object(const json& j, const std::string& pointer, std::initializer_list<std::string_view> allowed) {
    if (!j.is_object()) fail(pointer, "expected an object, got " + type_of(j));
    for (const auto& [key, value] : j.items()) {
        if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
            std::string list;
            for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
            fail(child(pointer, key), "unknown field \"" + key + "\" (expected one of: " + list + ")");
        }
    }
    return j;
}

const json& required(const json& obj, const std::string& pointer, std::string_view key) {
    const auto it = obj.find(key);
    if (it == obj.end()) fail(pointer, "missing field \"" + std::string(key) + "\"");
    return *it;
}

double number(const json& j, const std::string& pointer) {
    if (!j.is_number()) fail(pointer, "expected a number, got " + type_of(j));
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(pointer, "number out of range");
    return v;
}

double number_field(const json& obj, const std::string& pointer, std::string_view key) {
    return number(required(obj, pointer, key), child(pointer, key));
}

double number_field(const json& obj, const std::string& pointer, std::string_view key, double fallback) {
    const auto it = obj.find(key);
    return it == obj.end() ? fallback : number(*it, child(pointer, key));
}

double positive_field(const json& obj, const std::string& pointer, std::string_view key) {
    const double v = number_field(obj, pointer, key);
    if (!(v > 0.0)) fail(child(pointer, key), "must be positive (got " + number_text(v) + ")");
    return v;
}

double non_negative_field(const json& obj, const std::string& pointer, std::string_view key, double fallback) {
    const double v = number_field(obj, pointer, key, fallback);
    if (v < 0.0) fail(child(pointer, key), "must not be negative (got " + number_text(v) + ")");
    return v;
}

bool bool_field(const json& obj, const std::string& pointer, std::string_view key, bool fallback) {
    const auto it = obj.find(key);
    if (it == obj.end()) return fallback;
    if (!it->is_boolean()) fail(child(pointer, key), "expected true or false, got " + type_of(*it));
    return it->get<bool>();
}

std::string string_value(const json& j, const std::string& pointer) {
    if (!j.is_string()) fail(pointer, "expected a string, got " + type_of(j));
    return j.get<std::string>();
}

std::string string_field(const json& obj, const std::string& pointer, std::string_view key, std::string fallback) {
    const auto it = obj.find(key);
    return it == obj.end() ? fallback : string_value(*it, child(pointer, key));
}

long long integer(const json& j, const std::string& pointer) {
    const double v = number(j, pointer);
    if (v != std::floor(v) || std::abs(v) > 9e15) fail(pointer, "expected a whole number (got " + number_text(v) + ")");
    return static_cast<long long>(v);
}

Vec2 vec2(const json& j, const std::string& pointer) {
    if (!j.is_array() || j.size() != 2) fail(pointer, "expected a point [x, y], got " + type_of(j) + (j.is_array() ? " of " + std::to_string(j.size()) : ""));
    return {number(j[0], child(pointer, 0)), number(j[1], child(pointer, 1))};
}

Vec2 vec2_field(const json& obj, const std::string& pointer, std::string_view key) {
    return vec2(required(obj, pointer, key), child(pointer, key));
}

Vec2 vec2_field(const json& obj, const std::string& pointer, std::string_view key, Vec2 fallback) {
    const auto it = obj.find(key);
    return it == obj.end() ? fallback : vec2(*it, child(pointer, key));
}

const json& array_field(const json& obj, const std::string& pointer, std::string_view key) {
    const json& a = required(obj, pointer, key);
    if (!a.is_array()) fail(child(pointer, key), "expected an array, got " + type_of(a));
    return a;
}

std::vector<Vec2> points_field(const json& obj, const std::string& pointer, std::string_view key, std::size_t at_least) {
    const json& a = array_field(obj, pointer, key);
    const std::string p = child(pointer, key);
    if (a.size() < at_least)
        fail(p, "too few points: " + std::to_string(a.size()) + " (at least " + std::to_string(at_least) + ")");
    std::vector<Vec2> out;
    out.reserve(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) out.push_back(vec2(a[i], child(p, i)));
    return out;
}

// ------------------------------------------------------------------------------- paths

struct PathReader {
    const std::vector<NamedPath>* named = nullptr;  // references allowed when set
    // When set, SVG data is read by SVG's error rule (the path before the command holding
    // the first error) and the error is noted here; otherwise it is an error of the scene.
    std::vector<std::string>* warnings = nullptr;

    Path read(const json& j, const std::string& pointer, int depth) const {
        if (depth > max_depth) fail(pointer, "paths nested more than " + std::to_string(max_depth) + " deep");
        if (j.is_string()) {
            const std::string name = j.get<std::string>();
            if (named) {
                for (const NamedPath& p : *named)
                    if (p.name == name) return p.path;
            }
            fail(pointer, "unknown path \"" + name + "\" (name one listed earlier in /paths, or give a path object)");
        }
        if (!j.is_object()) fail(pointer, "expected a path object or a path name, got " + type_of(j));
        const std::string kind = string_value(required(j, pointer, "kind"), child(pointer, "kind"));
        try {
            return read_kind(j, pointer, kind, depth);
        } catch (const Error& e) {
            const std::string what = e.what();
            if (what.rfind("scene: ", 0) == 0) throw;
            fail(pointer, what);  // a path constructor's own message, placed
        }
    }

    Path read_kind(const json& j, const std::string& pointer, const std::string& kind, int depth) const {
        const bool reparam = bool_field(j, pointer, "reparametrize", false);
        const auto done = [&](Path p) { return reparam ? p.reparametrized() : p; };
        if (kind == "linear") {
            object(j, pointer, {"kind", "start", "end", "reparametrize"});
            return done(LinearPath(vec2_field(j, pointer, "start"), vec2_field(j, pointer, "end")));
        }
        if (kind == "circle") {
            object(j, pointer, {"kind", "centre", "radius", "start_angle", "end_angle", "reparametrize"});
            return done(CirclePath(vec2_field(j, pointer, "centre"), number_field(j, pointer, "radius"),
                                   number_field(j, pointer, "start_angle", 0.0),
                                   number_field(j, pointer, "end_angle", 2.0 * pi)));
        }
        if (kind == "elliptical_arc") {
            object(j, pointer, {"kind", "centre", "rx", "ry", "rotation", "start_angle", "end_angle", "reparametrize"});
            return done(EllipticalArcPath(vec2_field(j, pointer, "centre"), number_field(j, pointer, "rx"),
                                          number_field(j, pointer, "ry"), number_field(j, pointer, "rotation", 0.0),
                                          number_field(j, pointer, "start_angle", 0.0),
                                          number_field(j, pointer, "end_angle", 2.0 * pi)));
        }
        if (kind == "spiral") {
            object(j, pointer, {"kind", "centre", "start_radius", "end_radius", "start_angle", "end_angle", "reparametrize"});
            return done(SpiralPath(vec2_field(j, pointer, "centre"), number_field(j, pointer, "start_radius"),
                                   number_field(j, pointer, "end_radius"), number_field(j, pointer, "start_angle", 0.0),
                                   number_field(j, pointer, "end_angle", 2.0 * pi)));
        }
        if (kind == "sine_wave") {
            object(j, pointer, {"kind", "start", "end", "frequency", "amplitude", "reparametrize"});
            return done(SineWavePath(vec2_field(j, pointer, "start"), vec2_field(j, pointer, "end"),
                                     number_field(j, pointer, "frequency"), number_field(j, pointer, "amplitude")));
        }
        if (kind == "quadratic_bezier" || kind == "cubic_bezier") {
            object(j, pointer, {"kind", "points", "reparametrize"});
            const std::size_t n = kind == "quadratic_bezier" ? 3 : 4;
            const auto pts = points_field(j, pointer, "points", n);
            if (pts.size() != n)
                fail(child(pointer, "points"), "a " + kind + " has exactly " + std::to_string(n) + " points (got " +
                                                  std::to_string(pts.size()) + ")");
            if (n == 3) return QuadraticBezierPath(pts[0], pts[1], pts[2], reparam);
            return CubicBezierPath(pts[0], pts[1], pts[2], pts[3], reparam);
        }
        if (kind == "linear_spline" || kind == "cosine_spline") {
            object(j, pointer, {"kind", "points", "reparametrize"});
            const auto pts = points_field(j, pointer, "points", 2);
            if (kind == "linear_spline") return done(LinearSplinePath(std::span<const Vec2>(pts)));
            return done(CosineSplinePath(std::span<const Vec2>(pts)));
        }
        if (kind == "hermite_spline") {
            object(j, pointer, {"kind", "points", "tangents", "reparametrize"});
            const auto pts = points_field(j, pointer, "points", 2);
            const auto tangents = points_field(j, pointer, "tangents", 0);
            if (tangents.size() != pts.size())
                fail(child(pointer, "tangents"), "one tangent per point: " + std::to_string(pts.size()) +
                                                     " points but " + std::to_string(tangents.size()) + " tangents");
            return done(HermiteSplinePath(std::span<const Vec2>(pts), std::span<const Vec2>(tangents)));
        }
        if (kind == "catmull_rom_spline") {
            object(j, pointer, {"kind", "points", "type", "reparametrize"});
            const auto pts = points_field(j, pointer, "points", 2);
            const std::string type = string_field(j, pointer, "type", "uniform");
            CatmullRom t = CatmullRom::uniform;
            if (type == "centripetal") t = CatmullRom::centripetal;
            else if (type == "chordal") t = CatmullRom::chordal;
            else if (type != "uniform")
                fail(child(pointer, "type"), "unknown Catmull-Rom type \"" + type + "\" (uniform, centripetal, chordal)");
            return done(CatmullRomSplinePath(std::span<const Vec2>(pts), t));
        }
        if (kind == "physics") {
            object(j, pointer, {"kind", "position", "velocity", "acceleration", "seconds", "reparametrize"});
            return done(PhysicsPath(vec2_field(j, pointer, "position"), vec2_field(j, pointer, "velocity"),
                                    vec2_field(j, pointer, "acceleration"), number_field(j, pointer, "seconds")));
        }
        if (kind == "svg") {
            object(j, pointer, {"kind", "data", "reparametrize"});
            const std::string data = string_value(required(j, pointer, "data"), child(pointer, "data"));
            if (!warnings) return done(parse_svg_path(data));
            SvgPathParse parsed = parse_svg_path_prefix(data);
            if (parsed.error)
                warnings->push_back("scene: " + child(pointer, "data") + ": " + parsed.error->message +
                                    "; the path stops before it, as SVG draws it");
            return done(std::move(parsed.path));
        }
        if (kind == "complex") {
            object(j, pointer, {"kind", "parts", "cues", "reparametrize"});
            const json& parts_json = array_field(j, pointer, "parts");
            const std::string pp = child(pointer, "parts");
            if (parts_json.empty()) fail(pp, "a complex path needs at least one part");
            std::vector<Path> parts;
            parts.reserve(parts_json.size());
            for (std::size_t i = 0; i < parts_json.size(); ++i) parts.push_back(read(parts_json[i], child(pp, i), depth + 1));
            const auto cues_it = j.find("cues");
            if (cues_it == j.end() || (cues_it->is_string() && cues_it->get<std::string>() == "by_length"))
                return done(ComplexPath::by_length(std::move(parts)));
            const std::string cp = child(pointer, "cues");
            if (!cues_it->is_array()) fail(cp, "expected an array of numbers or \"by_length\", got " + type_of(*cues_it));
            if (cues_it->size() != parts.size())
                fail(cp, "one cue per part: " + std::to_string(parts.size()) + " parts but " +
                             std::to_string(cues_it->size()) + " cues");
            std::vector<double> cues;
            for (std::size_t i = 0; i < cues_it->size(); ++i) {
                const double c = number((*cues_it)[i], child(cp, i));
                if (i == 0 && c != 0.0) fail(child(cp, i), "the first cue must be 0 (got " + number_text(c) + ")");
                if (c < 0.0 || c > 1.0) fail(child(cp, i), "cues must lie in [0, 1] (got " + number_text(c) + ")");
                if (i > 0 && c < cues.back())
                    fail(child(cp, i), "cues must not decrease (" + number_text(c) + " after " + number_text(cues.back()) + ")");
                cues.push_back(c);
            }
            return done(ComplexPath(std::move(parts), std::move(cues)));
        }
        fail(child(pointer, "kind"),
             "unknown path kind \"" + kind +
                 "\" (linear, circle, elliptical_arc, spiral, sine_wave, quadratic_bezier, cubic_bezier, "
                 "linear_spline, cosine_spline, hermite_spline, catmull_rom_spline, physics, complex, svg)");
    }
};

ordered point_json(Vec2 p) { return ordered::array({p.x, p.y}); }

ordered points_json(std::span<const Vec2> points) {
    ordered a = ordered::array();
    for (Vec2 p : points) a.push_back(point_json(p));
    return a;
}

ordered path_json(const Path& path);

// One JSON object per spec; field names as the reader expects them.
struct SpecJson {
    ordered operator()(const LinearSpec& s) const {
        return {{"kind", "linear"}, {"start", point_json(s.start)}, {"end", point_json(s.end)}};
    }
    ordered operator()(const CircleSpec& s) const {
        return {{"kind", "circle"}, {"centre", point_json(s.centre)}, {"radius", s.radius},
                {"start_angle", s.start_angle}, {"end_angle", s.end_angle}};
    }
    ordered operator()(const EllipticalArcSpec& s) const {
        return {{"kind", "elliptical_arc"}, {"centre", point_json(s.centre)}, {"rx", s.rx}, {"ry", s.ry},
                {"rotation", s.rotation}, {"start_angle", s.start_angle}, {"end_angle", s.end_angle}};
    }
    ordered operator()(const SpiralSpec& s) const {
        return {{"kind", "spiral"}, {"centre", point_json(s.centre)}, {"start_radius", s.start_radius},
                {"end_radius", s.end_radius}, {"start_angle", s.start_angle}, {"end_angle", s.end_angle}};
    }
    ordered operator()(const SineWaveSpec& s) const {
        return {{"kind", "sine_wave"}, {"start", point_json(s.start)}, {"end", point_json(s.end)},
                {"frequency", s.frequency}, {"amplitude", s.amplitude}};
    }
    ordered operator()(const QuadraticBezierSpec& s) const {
        return {{"kind", "quadratic_bezier"}, {"points", points_json(s.control)}};
    }
    ordered operator()(const CubicBezierSpec& s) const {
        return {{"kind", "cubic_bezier"}, {"points", points_json(s.control)}};
    }
    ordered operator()(const LinearSplineSpec& s) const {
        return {{"kind", "linear_spline"}, {"points", points_json(s.points)}};
    }
    ordered operator()(const CosineSplineSpec& s) const {
        return {{"kind", "cosine_spline"}, {"points", points_json(s.points)}};
    }
    ordered operator()(const HermiteSplineSpec& s) const {
        return {{"kind", "hermite_spline"}, {"points", points_json(s.points)}, {"tangents", points_json(s.tangents)}};
    }
    ordered operator()(const CatmullRomSplineSpec& s) const {
        const char* type = s.type == CatmullRom::uniform       ? "uniform"
                           : s.type == CatmullRom::centripetal ? "centripetal"
                                                               : "chordal";
        return {{"kind", "catmull_rom_spline"}, {"points", points_json(s.points)}, {"type", type}};
    }
    ordered operator()(const PhysicsSpec& s) const {
        return {{"kind", "physics"}, {"position", point_json(s.position)}, {"velocity", point_json(s.velocity)},
                {"acceleration", point_json(s.acceleration)}, {"seconds", s.seconds}};
    }
    ordered operator()(const ComplexSpec& s) const {
        ordered parts = ordered::array();
        for (const Path& p : s.parts) parts.push_back(path_json(p));
        ordered j;
        j["kind"] = "complex";
        j["parts"] = std::move(parts);
        j["cues"] = s.cues;
        return j;
    }
    ordered operator()(const ReparametrizedSpec& s) const {
        ordered j = path_json(s.source);
        j["reparametrize"] = true;
        return j;
    }
};

ordered path_json(const Path& path) { return std::visit(SpecJson{}, describe(path)); }

// --------------------------------------------------------------------------- scene parts

const std::vector<std::string_view> integrators = {"euler", "semi_implicit_euler", "midpoint", "rk4", "velocity_verlet", "rk45"};
const std::vector<std::string_view> drifts = {"none", "baumgarte", "projection"};

std::string name_field(const json& obj, const std::string& pointer, std::set<std::string>* unique) {
    const std::string name = string_field(obj, pointer, "name", "");
    if (unique) {
        if (name.empty()) fail(child(pointer, "name"), "must not be empty");
        if (!unique->insert(name).second) fail(child(pointer, "name"), "duplicate name \"" + name + "\"");
    }
    return name;
}

std::string one_of(const json& obj, const std::string& pointer, std::string_view key, std::string fallback,
                   const std::vector<std::string_view>& allowed) {
    const std::string v = string_field(obj, pointer, key, std::move(fallback));
    if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
        std::string list;
        for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
        fail(child(pointer, key), "unknown value \"" + v + "\" (" + list + ")");
    }
    return v;
}

std::size_t particle_index(const json& obj, const std::string& pointer, std::string_view key, std::size_t count) {
    const long long i = integer(required(obj, pointer, key), child(pointer, key));
    if (i < 0 || static_cast<std::size_t>(i) >= count)
        fail(child(pointer, key), "no particle " + std::to_string(i) + " (the simulation has " + std::to_string(count) + ")");
    return static_cast<std::size_t>(i);
}

SceneSimulation read_simulation(const json& j, const std::string& pointer) {
    object(j, pointer, {"name", "integrator", "drift", "dt", "duration", "particles", "forces", "constraints"});
    SceneSimulation s;
    s.name = name_field(j, pointer, nullptr);
    s.integrator = one_of(j, pointer, "integrator", "rk4", integrators);
    s.drift = one_of(j, pointer, "drift", "baumgarte", drifts);
    s.dt = j.contains("dt") ? positive_field(j, pointer, "dt") : s.dt;
    s.duration = j.contains("duration") ? positive_field(j, pointer, "duration") : s.duration;
    if (s.duration / s.dt > max_steps)
        fail(child(pointer, "duration"), "more than 1e7 steps of dt (" + number_text(s.duration / s.dt) + ")");
    const json& particles = array_field(j, pointer, "particles");
    const std::string pp = child(pointer, "particles");
    if (particles.empty()) fail(pp, "a simulation needs at least one particle");
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const std::string p = child(pp, i);
        const json& o = object(particles[i], p, {"position", "velocity", "mass"});
        SceneParticle particle;
        particle.position = vec2_field(o, p, "position");
        particle.velocity = vec2_field(o, p, "velocity", {});
        const auto mass = o.find("mass");
        if (mass != o.end() && mass->is_string()) {
            if (mass->get<std::string>() != "pinned") fail(child(p, "mass"), "expected a positive number or \"pinned\"");
            particle.mass = std::numeric_limits<double>::infinity();
        } else if (mass != o.end()) {
            particle.mass = positive_field(o, p, "mass");
        }
        s.particles.push_back(particle);
    }
    const std::size_t n = s.particles.size();
    if (const auto forces = j.find("forces"); forces != j.end()) {
        const std::string fp = child(pointer, "forces");
        if (!forces->is_array()) fail(fp, "expected an array, got " + type_of(*forces));
        for (std::size_t i = 0; i < forces->size(); ++i) {
            const std::string p = child(fp, i);
            const json& o = (*forces)[i];
            if (!o.is_object()) fail(p, "expected an object, got " + type_of(o));
            const std::string kind = string_value(required(o, p, "kind"), child(p, "kind"));
            SceneForce f;
            if (kind == "gravity") {
                object(o, p, {"kind", "acceleration"});
                f.kind = SceneForceKind::gravity;
                f.gravity = vec2_field(o, p, "acceleration");
            } else if (kind == "drag") {
                object(o, p, {"kind", "k"});
                f.kind = SceneForceKind::drag;
                (void)required(o, p, "k");
                f.drag = non_negative_field(o, p, "k", 0.0);
            } else if (kind == "spring") {
                object(o, p, {"kind", "a", "b", "rest_length", "stiffness", "damping"});
                f.kind = SceneForceKind::spring;
                f.a = particle_index(o, p, "a", n);
                f.b = particle_index(o, p, "b", n);
                if (f.a == f.b) fail(child(p, "b"), "a spring joins two different particles");
                f.rest_length = non_negative_field(o, p, "rest_length", 0.0);
                (void)required(o, p, "stiffness");
                f.stiffness = non_negative_field(o, p, "stiffness", 0.0);
                f.damping = non_negative_field(o, p, "damping", 0.0);
            } else {
                fail(child(p, "kind"), "unknown force kind \"" + kind + "\" (gravity, drag, spring)");
            }
            s.forces.push_back(f);
        }
    }
    if (const auto constraints = j.find("constraints"); constraints != j.end()) {
        const std::string cp = child(pointer, "constraints");
        if (!constraints->is_array()) fail(cp, "expected an array, got " + type_of(*constraints));
        for (std::size_t i = 0; i < constraints->size(); ++i) {
            const std::string p = child(cp, i);
            const json& o = (*constraints)[i];
            if (!o.is_object()) fail(p, "expected an object, got " + type_of(o));
            const std::string kind = string_value(required(o, p, "kind"), child(p, "kind"));
            SceneConstraint c;
            if (kind == "distance") {
                object(o, p, {"kind", "a", "b", "length"});
                c.kind = SceneConstraintKind::distance;
                c.a = particle_index(o, p, "a", n);
                c.b = particle_index(o, p, "b", n);
                if (c.a == c.b) fail(child(p, "b"), "a distance joins two different particles");
                c.length = non_negative_field(o, p, "length", 0.0);
            } else if (kind == "anchor") {
                object(o, p, {"kind", "a", "point", "length"});
                c.kind = SceneConstraintKind::anchor;
                c.a = particle_index(o, p, "a", n);
                c.point = vec2_field(o, p, "point");
                c.length = positive_field(o, p, "length");
            } else if (kind == "fixed_point") {
                object(o, p, {"kind", "a", "point"});
                c.kind = SceneConstraintKind::fixed_point;
                c.a = particle_index(o, p, "a", n);
                c.point = vec2_field(o, p, "point");
            } else if (kind == "conic") {
                object(o, p, {"kind", "a", "coefficients"});
                c.kind = SceneConstraintKind::conic;
                c.a = particle_index(o, p, "a", n);
                const json& k = array_field(o, p, "coefficients");
                const std::string kp = child(p, "coefficients");
                if (k.size() != 6) fail(kp, "expected 6 coefficients A..F of Ax² + Bxy + Cy² + Dx + Ey + F (got " + std::to_string(k.size()) + ")");
                bool any = false;
                for (std::size_t m = 0; m < 6; ++m) {
                    c.conic[m] = number(k[m], child(kp, m));
                    any = any || (m < 5 && c.conic[m] != 0.0);
                }
                if (!any) fail(kp, "A to E are all zero: that is not a curve");
            } else {
                fail(child(p, "kind"), "unknown constraint kind \"" + kind + "\" (distance, anchor, fixed_point, conic)");
            }
            s.constraints.push_back(c);
        }
    }
    return s;
}

ordered simulation_json(const SceneSimulation& s) {
    ordered j;
    if (!s.name.empty()) j["name"] = s.name;
    j["integrator"] = s.integrator;
    j["drift"] = s.drift;
    j["dt"] = s.dt;
    j["duration"] = s.duration;
    ordered particles = ordered::array();
    for (const SceneParticle& p : s.particles) {
        ordered o;
        o["position"] = point_json(p.position);
        o["velocity"] = point_json(p.velocity);
        if (std::isinf(p.mass)) o["mass"] = "pinned";
        else o["mass"] = p.mass;
        particles.push_back(std::move(o));
    }
    j["particles"] = std::move(particles);
    ordered forces = ordered::array();
    for (const SceneForce& f : s.forces) {
        ordered o;
        switch (f.kind) {
            case SceneForceKind::gravity: o["kind"] = "gravity"; o["acceleration"] = point_json(f.gravity); break;
            case SceneForceKind::drag: o["kind"] = "drag"; o["k"] = f.drag; break;
            case SceneForceKind::spring:
                o["kind"] = "spring";
                o["a"] = f.a;
                o["b"] = f.b;
                o["rest_length"] = f.rest_length;
                o["stiffness"] = f.stiffness;
                o["damping"] = f.damping;
                break;
        }
        forces.push_back(std::move(o));
    }
    j["forces"] = std::move(forces);
    ordered constraints = ordered::array();
    for (const SceneConstraint& c : s.constraints) {
        ordered o;
        switch (c.kind) {
            case SceneConstraintKind::distance: o["kind"] = "distance"; o["a"] = c.a; o["b"] = c.b; o["length"] = c.length; break;
            case SceneConstraintKind::anchor: o["kind"] = "anchor"; o["a"] = c.a; o["point"] = point_json(c.point); o["length"] = c.length; break;
            case SceneConstraintKind::fixed_point: o["kind"] = "fixed_point"; o["a"] = c.a; o["point"] = point_json(c.point); break;
            case SceneConstraintKind::conic:
                o["kind"] = "conic";
                o["a"] = c.a;
                o["coefficients"] = ordered::array();
                for (double k : c.conic) o["coefficients"].push_back(k);
                break;
        }
        constraints.push_back(std::move(o));
    }
    j["constraints"] = std::move(constraints);
    return j;
}

Scene read_scene(const json& root) {
    object(root, "", {"grape_scene", "name", "view", "paths", "curves", "animations", "simulations"});
    if (const auto v = root.find("grape_scene"); v != root.end()) {
        if (integer(*v, "/grape_scene") != 1) fail("/grape_scene", "unsupported format version (this reader knows 1)");
    }
    Scene scene;
    scene.name = string_field(root, "", "name", "");
    if (const auto v = root.find("view"); v != root.end()) {
        object(*v, "/view", {"width", "height", "ticks"});
        const auto size = [&](std::string_view key, double fallback) {
            const double s = number_field(*v, "/view", key, fallback);
            if (!(s >= 1.0 && s <= 32768.0)) fail(child("/view", key), "must be in [1, 32768] (got " + number_text(s) + ")");
            return s;
        };
        scene.view.width = size("width", scene.view.width);
        scene.view.height = size("height", scene.view.height);
        scene.view.ticks = non_negative_field(*v, "/view", "ticks", 0.0);
        if (scene.view.ticks > 0.0 && scene.view.ticks < 1e-4)
            fail("/view/ticks", "ticks closer than 1e-4 would be a solid smear (got " + number_text(scene.view.ticks) + ")");
    }
    std::set<std::string> names;
    if (const auto v = root.find("paths"); v != root.end()) {
        if (!v->is_array()) fail("/paths", "expected an array, got " + type_of(*v));
        PathReader reader{&scene.paths, &scene.warnings};  // a path may use those listed before it
        for (std::size_t i = 0; i < v->size(); ++i) {
            const std::string p = child("/paths", i);
            const json& o = (*v)[i];
            if (!o.is_object()) fail(p, "expected an object with \"name\" and \"path\", got " + type_of(o));
            object(o, p, {"name", "path"});
            NamedPath named;
            named.name = name_field(o, p, &names);
            named.path = reader.read(required(o, p, "path"), child(p, "path"), 0);
            scene.paths.push_back(std::move(named));
        }
    }
    std::set<std::string> curve_names;
    if (const auto v = root.find("curves"); v != root.end()) {
        if (!v->is_array()) fail("/curves", "expected an array, got " + type_of(*v));
        for (std::size_t i = 0; i < v->size(); ++i) {
            const std::string p = child("/curves", i);
            const json& o = object((*v)[i], p, {"name", "curve"});
            NamedCurve named;
            named.name = name_field(o, p, &curve_names);
            const std::string text = string_value(required(o, p, "curve"), child(p, "curve"));
            try {
                named.curve = parse_curve(text);
            } catch (const Error& e) {
                fail(child(p, "curve"), e.what());
            }
            scene.curves.push_back(std::move(named));
        }
    }
    if (const auto v = root.find("animations"); v != root.end()) {
        if (!v->is_array()) fail("/animations", "expected an array, got " + type_of(*v));
        PathReader reader{&scene.paths, &scene.warnings};
        for (std::size_t i = 0; i < v->size(); ++i) {
            const std::string p = child("/animations", i);
            const json& o = object((*v)[i], p, {"name", "path", "curve", "duration", "delay", "repeat", "yoyo", "reversed"});
            SceneAnimation a;
            a.name = name_field(o, p, nullptr);
            const json& path = required(o, p, "path");
            if (path.is_string()) a.path_name = path.get<std::string>();
            a.path = reader.read(path, child(p, "path"), 0);
            if (const auto c = o.find("curve"); c != o.end()) {
                const std::string text = string_value(*c, child(p, "curve"));
                if (const NamedCurve* named = scene.find_curve(text)) {
                    a.curve = named->curve;
                    a.curve_name = text;
                } else {
                    try {
                        a.curve = parse_curve(text);
                    } catch (const Error& e) {
                        fail(child(p, "curve"), std::string(e.what()) + " (nor is it a name in /curves)");
                    }
                }
            }
            a.duration = positive_field(o, p, "duration");
            a.delay = non_negative_field(o, p, "delay", 0.0);
            if (const auto r = o.find("repeat"); r != o.end()) {
                const long long repeat = integer(*r, child(p, "repeat"));
                if (repeat < -1 || repeat > 1000000000)
                    fail(child(p, "repeat"), "must be −1 (forever) or a count in [0, 1e9] (got " + std::to_string(repeat) + ")");
                a.repeat = static_cast<int>(repeat);
            }
            a.yoyo = bool_field(o, p, "yoyo", false);
            a.reversed = bool_field(o, p, "reversed", false);
            scene.animations.push_back(std::move(a));
        }
    }
    if (const auto v = root.find("simulations"); v != root.end()) {
        if (!v->is_array()) fail("/simulations", "expected an array, got " + type_of(*v));
        for (std::size_t i = 0; i < v->size(); ++i) scene.simulations.push_back(read_simulation((*v)[i], child("/simulations", i)));
    }
    return scene;
}

ordered scene_json(const Scene& scene) {
    ordered j;
    j["grape_scene"] = 1;
    if (!scene.name.empty()) j["name"] = scene.name;
    j["view"] = {{"width", scene.view.width}, {"height", scene.view.height}, {"ticks", scene.view.ticks}};
    if (!scene.paths.empty()) {
        ordered a = ordered::array();
        for (const NamedPath& p : scene.paths) a.push_back({{"name", p.name}, {"path", path_json(p.path)}});
        j["paths"] = std::move(a);
    }
    if (!scene.curves.empty()) {
        ordered a = ordered::array();
        for (const NamedCurve& c : scene.curves) a.push_back({{"name", c.name}, {"curve", to_string(c.curve)}});
        j["curves"] = std::move(a);
    }
    if (!scene.animations.empty()) {
        ordered a = ordered::array();
        for (const SceneAnimation& anim : scene.animations) {
            ordered o;
            if (!anim.name.empty()) o["name"] = anim.name;
            // A reference is kept only while it still names this very path.
            const NamedPath* named = anim.path_name.empty() ? nullptr : scene.find_path(anim.path_name);
            if (named && named->path == anim.path) o["path"] = anim.path_name;
            else o["path"] = path_json(anim.path);
            const NamedCurve* curve = anim.curve_name.empty() ? nullptr : scene.find_curve(anim.curve_name);
            o["curve"] = curve && curve->curve == anim.curve ? anim.curve_name : to_string(anim.curve);
            o["duration"] = anim.duration;
            o["delay"] = anim.delay;
            o["repeat"] = anim.repeat;
            o["yoyo"] = anim.yoyo;
            o["reversed"] = anim.reversed;
            a.push_back(std::move(o));
        }
        j["animations"] = std::move(a);
    }
    if (!scene.simulations.empty()) {
        ordered a = ordered::array();
        for (const SceneSimulation& s : scene.simulations) a.push_back(simulation_json(s));
        j["simulations"] = std::move(a);
    }
    return j;
}

json parse_text(std::string_view text, const std::string& where) {
    try {
        return json::parse(text.begin(), text.end());
    } catch (const json::parse_error& e) {
        throw Error(where + "JSON syntax error at byte " + std::to_string(e.byte) + ": " +
                    std::string(e.what()).substr(std::string(e.what()).find(':') + 2));
    } catch (const json::exception& e) {
        throw Error(where + "invalid JSON: " + e.what());
    }
}

}  // namespace

// --------------------------------------------------------------------------------- public

AnimationDef SceneAnimation::def() const noexcept {
    return {.curve = curve, .delay = delay, .repeat = repeat, .reversed = reversed, .yoyo = yoyo};
}

double SceneAnimation::progress(double t) const noexcept {
    if (!(duration > 0.0)) return curve(reversed ? 1.0 : 0.0);  // not playable: its start
    return progress_at(def(), duration, t);
}

double SceneAnimation::end_time() const noexcept { return grape::end_time(def(), duration); }

const NamedPath* Scene::find_path(std::string_view name) const noexcept {
    for (const NamedPath& p : paths)
        if (p.name == name) return &p;
    return nullptr;
}

const NamedCurve* Scene::find_curve(std::string_view name) const noexcept {
    for (const NamedCurve& c : curves)
        if (c.name == name) return &c;
    return nullptr;
}

Scene load_scene(std::string_view text) { return read_scene(parse_text(text, "scene: ")); }

Scene load_scene_file(const std::filesystem::path& file) {
    const std::string text = detail::read_file_text(file, "a scene file");
    try {
        return load_scene(text);
    } catch (const Error& e) {
        throw Error(file.string() + ": " + e.what());
    }
}

std::string save_scene(const Scene& scene) { return scene_json(scene).dump(2) + "\n"; }

void save_scene_file(const Scene& scene, const std::filesystem::path& file) {
    detail::write_file_atomically(file, save_scene(scene));
}

double conic_value(const SceneConstraint& c, Vec2 p) noexcept {
    return c.conic[0] * p.x * p.x + c.conic[1] * p.x * p.y + c.conic[2] * p.y * p.y + c.conic[3] * p.x +
           c.conic[4] * p.y + c.conic[5];
}

std::string path_to_json(const Path& path) { return path_json(path).dump(2); }

Path path_from_json(std::string_view text) {
    const json j = parse_text(text, "path: ");
    return PathReader{}.read(j, "", 0);
}

}  // namespace grape
