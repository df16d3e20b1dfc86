// Paths for JavaScript: every kind, SVG path data, point/d1/d2/length/reparametrized, the
// closest point and the frame (tangent, normal, curvature).
// Points are plain {x, y} objects; point lists are flat x, y arrays (Float64Array or Array).
#include "web_util.hpp"

#include <grape/path.hpp>
#include <grape/path_query.hpp>

#include <emscripten/bind.h>

#include <string>
#include <vector>

namespace grape::web {
namespace {

std::vector<Vec2> points_of(const val& xy, const char* where) {
    const std::vector<double> flat = numbers(xy);
    if (flat.size() % 2 != 0) throw Error(std::string(where) + ": points need x, y pairs (got " +
                                          std::to_string(flat.size()) + " numbers)");
    std::vector<Vec2> out(flat.size() / 2);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {flat[2 * i], flat[2 * i + 1]};
    return out;
}

std::vector<Path> paths_of(const val& array) {
    const auto n = array["length"].as<unsigned>();
    std::vector<Path> out;
    out.reserve(n);
    for (unsigned i = 0; i < n; ++i) out.push_back(array[i].as<Path>());
    return out;
}

CatmullRom catmull_rom_type(const std::string& name) {
    if (name == "uniform") return CatmullRom::uniform;
    if (name == "centripetal") return CatmullRom::centripetal;
    if (name == "chordal") return CatmullRom::chordal;
    throw Error("catmullRom: type must be uniform, centripetal or chordal (got '" + name + "')");
}

Path linear(Vec2 a, Vec2 b) { return LinearPath(a, b); }
Path circle(Vec2 c, double r, double a0, double a1) { return CirclePath(c, r, a0, a1); }
Path elliptical_arc(Vec2 c, double rx, double ry, double rotation, double a0, double a1) {
    return EllipticalArcPath(c, rx, ry, rotation, a0, a1);
}
Path spiral(Vec2 c, double r0, double r1, double a0, double a1) { return SpiralPath(c, r0, r1, a0, a1); }
Path sine_wave(Vec2 a, Vec2 b, double frequency, double amplitude) { return SineWavePath(a, b, frequency, amplitude); }
Path quadratic_bezier(Vec2 p0, Vec2 p1, Vec2 p2, bool reparametrize) {
    return QuadraticBezierPath(p0, p1, p2, reparametrize);
}
Path cubic_bezier(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, bool reparametrize) {
    return CubicBezierPath(p0, p1, p2, p3, reparametrize);
}
Path spiral_turn(Vec2 c, double r0, double r1) { return SpiralPath(c, r0, r1); }
Path quadratic_bezier3(Vec2 p0, Vec2 p1, Vec2 p2) { return QuadraticBezierPath(p0, p1, p2); }
Path cubic_bezier4(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3) { return CubicBezierPath(p0, p1, p2, p3); }
Path catmull_rom_uniform(val xy) { return CatmullRomSplinePath(points_of(xy, "catmullRom")); }
Path linear_spline(val xy) { return LinearSplinePath(points_of(xy, "linearSpline")); }
Path cosine_spline(val xy) { return CosineSplinePath(points_of(xy, "cosineSpline")); }
Path hermite_spline(val xy, val tangents) {
    return HermiteSplinePath(points_of(xy, "hermiteSpline"), points_of(tangents, "hermiteSpline"));
}
Path catmull_rom(val xy, std::string type) {
    return CatmullRomSplinePath(points_of(xy, "catmullRom"), catmull_rom_type(type));
}
Path physics(Vec2 position, Vec2 velocity, Vec2 acceleration, double seconds) {
    return PhysicsPath(position, velocity, acceleration, seconds);
}
ComplexPath complex(val parts, val cues) { return ComplexPath(paths_of(parts), numbers(cues)); }
ComplexPath complex_by_length(val parts) { return ComplexPath::by_length(paths_of(parts)); }
ComplexPath svg(std::string data) { return parse_svg_path(data); }

Path reparametrized(const Path& p) { return p.reparametrized(); }
val flatten(const Path& p, double tolerance) {
    const std::vector<Vec2> points = p.flatten(tolerance);
    return float64_array(&points.data()->x, 2 * points.size());
}
std::string kind(const Path& p) { return std::string(to_string(p.kind())); }
// u values in, x, y pairs out: one call for a whole polyline of samples.
val sample(const Path& p, val us) {
    const std::vector<double> u = numbers(us);
    std::vector<double> out(2 * u.size());
    for (std::size_t i = 0; i < u.size(); ++i) {
        const Vec2 q = p.point(u[i]);
        out[2 * i] = q.x;
        out[2 * i + 1] = q.y;
    }
    return float64_array(out.data(), out.size());
}
bool same(const Path& a, const Path& b) { return a == b; }

// Part by part: a Path handed to JavaScript inside an array would be freed with the call.
unsigned part_count(const ComplexPath& p) { return unsigned(p.parts().size()); }
Path part(const ComplexPath& p, unsigned i) {
    if (i >= p.parts().size())
        throw Error("ComplexPath.part: no part " + std::to_string(i) + " (" + std::to_string(p.parts().size()) + " parts)");
    return p.parts()[i];
}
val cues(const ComplexPath& p) { return float64_array(p.cues().data(), p.cues().size()); }

ClosestPoint closest(const Path& p, double x, double y) { return closest_point(p, {x, y}); }
ClosestPoint closest_in(const Path& p, double x, double y, double u0, double u1) { return closest_point(p, {x, y}, u0, u1); }
ClosestPoint closest_from(const Path& p, double x, double y, double last_u) { return closest_point_from(p, {x, y}, last_u); }
PathFrame frame_at(const Path& p, double u) { return frame(p, u); }

}  // namespace

EMSCRIPTEN_BINDINGS(grape_path) {
    using namespace emscripten;
    value_object<Vec2>("Vec2").field("x", &Vec2::x).field("y", &Vec2::y);
    value_object<Bounds>("Bounds").field("min", &Bounds::min).field("max", &Bounds::max);
    value_object<ClosestPoint>("ClosestPoint")
        .field("u", &ClosestPoint::u).field("point", &ClosestPoint::point).field("distance", &ClosestPoint::distance);
    value_object<PathFrame>("PathFrame")
        .field("point", &PathFrame::point).field("tangent", &PathFrame::tangent)
        .field("normal", &PathFrame::normal).field("curvature", &PathFrame::curvature);

    class_<Path>("Path")
        .constructor<>()
        .function("point", method<&Path::point>)
        .function("d1", method<&Path::d1>)
        .function("d2", method<&Path::d2>)
        .function("heading", method<&Path::heading>)
        .function("length", method<&Path::length>)
        .function("lengthAt", method<&Path::length_at>)
        .function("uAtLength", method<&Path::u_at_length>)
        .function("bounds", method<&Path::bounds>)
        .function("flatten", guarded<&flatten>)
        .function("sample", guarded<&sample>)
        .function("reparametrized", guarded<&reparametrized>)
        .function("closestPoint", guarded<&closest>)
        .function("closestPoint", guarded<&closest_in>)
        .function("closestPointFrom", guarded<&closest_from>)
        .function("frame", guarded<&frame_at>)
        .function("kind", &kind)
        .function("same", &same)
        .class_function("linear", guarded<&linear>)
        .class_function("circle", guarded<&circle>)
        .class_function("ellipticalArc", guarded<&elliptical_arc>)
        .class_function("spiral", guarded<&spiral>)
        .class_function("spiral", guarded<&spiral_turn>)
        .class_function("sineWave", guarded<&sine_wave>)
        .class_function("quadraticBezier", guarded<&quadratic_bezier>)
        .class_function("quadraticBezier", guarded<&quadratic_bezier3>)
        .class_function("cubicBezier", guarded<&cubic_bezier>)
        .class_function("cubicBezier", guarded<&cubic_bezier4>)
        .class_function("linearSpline", guarded<&linear_spline>)
        .class_function("cosineSpline", guarded<&cosine_spline>)
        .class_function("hermiteSpline", guarded<&hermite_spline>)
        .class_function("catmullRom", guarded<&catmull_rom>)
        .class_function("catmullRom", guarded<&catmull_rom_uniform>)
        .class_function("physics", guarded<&physics>)
        .class_function("complex", guarded<&complex>)
        .class_function("complexByLength", guarded<&complex_by_length>)
        .class_function("svg", guarded<&svg>);
    class_<ComplexPath, base<Path>>("ComplexPath")
        .function("partCount", &part_count)
        .function("part", guarded<&part>)
        .function("cues", &cues);
    function("parseSvgPath", guarded<&svg>);
}

}  // namespace grape::web
