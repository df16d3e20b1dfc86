// Paths in scene files: read from JSON objects (or names), written from their descriptions.
#include "scene_json.hpp"

#include <grape/error.hpp>
#include <grape/path_query.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>
#include <string>

#include <type_traits>
#include <variant>

namespace grape::scene_io {

namespace {

// Levels of complex paths in the object path_json writes for `path` (0 for the other kinds):
// what reading that object back counts against max_depth. A named path is written in full, and
// a closed Catmull–Rom spline or SVG data as a complex path of its segments, so the written
// object can be deeper than the one read.
int written_depth(const Path& path) {
    // Other kinds are leaves: no description needed (describe copies a spline's points).
    if (path.kind() != PathKind::complex && path.kind() != PathKind::reparametrized) return 0;
    return std::visit(
        [](const auto& s) -> int {
            using S = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<S, ComplexSpec>) {
                int deepest = 0;
                for (const Path& p : s.parts) deepest = std::max(deepest, written_depth(p));
                return 1 + deepest;
            } else if constexpr (std::is_same_v<S, ReparametrizedSpec>) {
                return written_depth(s.source);
            } else {
                return 0;
            }
        },
        describe(path));
}

}  // namespace

// A whole path (depth 0) must also be within max_depth as written out, so that every scene
// that loads saves to one that loads (save_scene, path_to_json).
Path PathReader::read(const json& j, const std::string& pointer, int depth) const {
    Path path = read_any(j, pointer, depth);
    if (depth == 0 && !j.is_string() && written_depth(path) > max_depth)
        fail(pointer, "paths nested more than " + std::to_string(max_depth) +
                          " deep as written out (named paths are written in full, a closed Catmull–Rom spline and "
                          "SVG data as complex paths of their segments)");
    return path;
}

Path PathReader::read_any(const json& j, const std::string& pointer, int depth) const {
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
    if (const auto old = j.find("centre"); old != j.end()) {  // the key's older spelling, still read
        if (j.contains("center")) fail(child(pointer, "centre"), "give \"center\" only (\"centre\" is its older spelling)");
        json renamed = j;
        renamed["center"] = *old;
        renamed.erase("centre");
        return read_any(renamed, pointer, depth);
    }
    try {
        const auto s = j.find("slice");
        if (s == j.end()) return read_kind(j, pointer, kind, depth);
        // Any kind may be sliced: the rest of the object is the path, "slice" the u range kept.
        const std::string sp = child(pointer, "slice");
        if (!s->is_array() || s->size() != 2) fail(sp, "expected [u0, u1] with 0 ≤ u0 < u1 ≤ 1, got " + type_of(*s));
        const double u0 = number((*s)[0], child(sp, 0)), u1 = number((*s)[1], child(sp, 1));
        if (!(0.0 <= u0 && u0 < u1 && u1 <= 1.0))
            fail(sp, "expected 0 ≤ u0 < u1 ≤ 1 (got [" + number_text(u0) + ", " + number_text(u1) + "])");
        json rest = j;
        rest.erase("slice");
        const Path whole = read_kind(rest, pointer, kind, depth);
        try {
            return slice(whole, u0, u1);
        } catch (const Error& e) {
            fail(sp, e.what());
        }
    } catch (const Error& e) {
        const std::string what = e.what();
        if (what.rfind("scene: ", 0) == 0) throw;
        fail(pointer, what);  // a path constructor's own message, placed
    }
}

Path PathReader::read_kind(const json& j, const std::string& pointer, const std::string& kind, int depth) const {
    const bool reparam = bool_field(j, pointer, "reparametrize", false);
    const auto done = [&](Path p) { return reparam ? p.reparametrized() : p; };
    if (kind == "linear") {
        object(j, pointer, {"kind", "start", "end", "reparametrize"});
        return done(LinearPath(vec2_field(j, pointer, "start"), vec2_field(j, pointer, "end")));
    }
    if (kind == "circle") {
        object(j, pointer, {"kind", "center", "radius", "start_angle", "end_angle", "reparametrize"});
        return done(CirclePath(vec2_field(j, pointer, "center"), number_field(j, pointer, "radius"),
                               number_field(j, pointer, "start_angle", 0.0),
                               number_field(j, pointer, "end_angle", 2.0 * pi)));
    }
    if (kind == "elliptical_arc") {
        object(j, pointer, {"kind", "center", "rx", "ry", "rotation", "start_angle", "end_angle", "reparametrize"});
        return done(EllipticalArcPath(vec2_field(j, pointer, "center"), number_field(j, pointer, "rx"),
                                      number_field(j, pointer, "ry"), number_field(j, pointer, "rotation", 0.0),
                                      number_field(j, pointer, "start_angle", 0.0),
                                      number_field(j, pointer, "end_angle", 2.0 * pi)));
    }
    if (kind == "spiral") {
        object(j, pointer, {"kind", "center", "start_radius", "end_radius", "start_angle", "end_angle", "reparametrize"});
        return done(SpiralPath(vec2_field(j, pointer, "center"), number_field(j, pointer, "start_radius"),
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
    // Splines that may be loops: "closed": true joins the last point to the first (at least 3).
    const auto is_closed = [&] { return bool_field(j, pointer, "closed", false); };
    const auto spline_points = [&](bool loop) { return points_field(j, pointer, "points", loop ? 3 : 2); };
    if (kind == "linear_spline") {
        object(j, pointer, {"kind", "points", "reparametrize"});
        return done(LinearSplinePath(std::span<const Vec2>(spline_points(false))));
    }
    if (kind == "cosine_spline") {
        object(j, pointer, {"kind", "points", "closed", "reparametrize"});
        const bool loop = is_closed();
        const auto pts = spline_points(loop);
        if (loop) return done(closed_cosine_spline(pts));
        return done(CosineSplinePath(std::span<const Vec2>(pts)));
    }
    if (kind == "hermite_spline") {
        object(j, pointer, {"kind", "points", "tangents", "closed", "reparametrize"});
        const bool loop = is_closed();
        const auto pts = spline_points(loop);
        const auto tangents = points_field(j, pointer, "tangents", 0);
        if (tangents.size() != pts.size())
            fail(child(pointer, "tangents"), "one tangent per point: " + std::to_string(pts.size()) +
                                                 " points but " + std::to_string(tangents.size()) + " tangents");
        if (loop) return done(closed_hermite_spline(pts, tangents));
        return done(HermiteSplinePath(std::span<const Vec2>(pts), std::span<const Vec2>(tangents)));
    }
    if (kind == "catmull_rom_spline") {
        object(j, pointer, {"kind", "points", "type", "closed", "reparametrize"});
        const bool loop = is_closed();
        const auto pts = spline_points(loop);
        const std::string type = string_field(j, pointer, "type", "uniform");
        CatmullRom t = CatmullRom::uniform;
        if (type == "centripetal") t = CatmullRom::centripetal;
        else if (type == "chordal") t = CatmullRom::chordal;
        else if (type != "uniform")
            fail(child(pointer, "type"), "unknown Catmull-Rom type \"" + type + "\" (uniform, centripetal, chordal)");
        if (loop) return done(closed_catmull_rom_spline(pts, t));
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
        for (std::size_t i = 0; i < parts_json.size(); ++i) parts.push_back(read_any(parts_json[i], child(pp, i), depth + 1));
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

ordered point_json(Vec2 p) { return ordered::array({p.x, p.y}); }

ordered points_json(std::span<const Vec2> points) {
    ordered a = ordered::array();
    for (Vec2 p : points) a.push_back(point_json(p));
    return a;
}

// One JSON object per spec; field names as the reader expects them.
struct SpecJson {
    ordered operator()(const LinearSpec& s) const {
        return {{"kind", "linear"}, {"start", point_json(s.start)}, {"end", point_json(s.end)}};
    }
    ordered operator()(const CircleSpec& s) const {
        return {{"kind", "circle"}, {"center", point_json(s.center)}, {"radius", s.radius},
                {"start_angle", s.start_angle}, {"end_angle", s.end_angle}};
    }
    ordered operator()(const EllipticalArcSpec& s) const {
        return {{"kind", "elliptical_arc"}, {"center", point_json(s.center)}, {"rx", s.rx}, {"ry", s.ry},
                {"rotation", s.rotation}, {"start_angle", s.start_angle}, {"end_angle", s.end_angle}};
    }
    ordered operator()(const SpiralSpec& s) const {
        return {{"kind", "spiral"}, {"center", point_json(s.center)}, {"start_radius", s.start_radius},
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
    // A spline whose last point (and tangent) repeats its first is the loop "closed": true
    // builds from the others, bit for bit: written that way.
    static bool same(Vec2 a, Vec2 b) {  // bits, so a −0 is never written as 0
        return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
               std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y);
    }
    static bool loop(const std::vector<Vec2>& v) { return v.size() >= 4 && same(v.front(), v.back()); }
    static std::span<const Vec2> open_part(const std::vector<Vec2>& v) { return {v.data(), v.size() - 1}; }
    ordered operator()(const CosineSplineSpec& s) const {
        if (loop(s.points))
            return {{"kind", "cosine_spline"}, {"points", points_json(open_part(s.points))}, {"closed", true}};
        return {{"kind", "cosine_spline"}, {"points", points_json(s.points)}};
    }
    ordered operator()(const HermiteSplineSpec& s) const {
        if (loop(s.points) && s.tangents.size() == s.points.size() && same(s.tangents.front(), s.tangents.back()))
            return {{"kind", "hermite_spline"}, {"points", points_json(open_part(s.points))},
                    {"tangents", points_json(open_part(s.tangents))}, {"closed", true}};
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

}  // namespace grape::scene_io

namespace grape {

using namespace scene_io;

std::string path_to_json(const Path& path) { return path_json(path).dump(2); }

Path parse_path_json(std::string_view text) {
    const json j = parse_text(text, "path: ");
    return PathReader{}.read(j, "", 0);
}


}  // namespace grape
