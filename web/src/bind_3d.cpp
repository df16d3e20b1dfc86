// 3-D for JavaScript: Vec3, every Path3 kind, Frames3 in its modes, Quat and QuatSpline, roll
// tracks and automatic banking, View3 projections, and the engine's 3-D slots (Engine.add3).
// Points are plain {x, y, z} objects; point lists are flat x, y, z arrays (Float64Array or
// Array); quaternions are {w, x, y, z}.
#include "web_engine.hpp"

#include <grape/frames3.hpp>
#include <grape/path3.hpp>
#include <grape/quat.hpp>
#include <grape/quat_spline.hpp>
#include <grape/roll3.hpp>
#include <grape/view3.hpp>

#include <emscripten/bind.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace grape::web {
namespace {

Vec3 vec3_or(const val& options, const char* name, Vec3 fallback, const char* where) {
    if (!has(options, name)) return fallback;
    const val v = options[name];
    return {number_or(v, "x", 0.0, where), number_or(v, "y", 0.0, where), number_or(v, "z", 0.0, where)};
}

std::vector<Vec3> points3_of(const val& xyz, const char* where) {
    const std::vector<double> flat = numbers(xyz);
    if (flat.size() % 3 != 0) throw Error(std::string(where) + ": points need x, y, z triples (got " +
                                          std::to_string(flat.size()) + " numbers)");
    std::vector<Vec3> out(flat.size() / 3);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
    return out;
}

val float64_array3(const std::vector<Vec3>& points) {
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three doubles");
    return float64_array(points.empty() ? nullptr : &points.data()->x, 3 * points.size());
}

// ---- paths -----------------------------------------------------------------------------------

std::vector<Path3> paths3_of(const val& array) {
    const auto n = array["length"].as<unsigned>();
    std::vector<Path3> out;
    out.reserve(n);
    for (unsigned i = 0; i < n; ++i) out.push_back(array[i].as<Path3>());
    return out;
}

CatmullRom catmull_rom_type(const std::string& name) {
    if (name == "uniform") return CatmullRom::uniform;
    if (name == "centripetal") return CatmullRom::centripetal;
    if (name == "chordal") return CatmullRom::chordal;
    throw Error("Path3.catmullRom: type must be uniform, centripetal or chordal (got '" + name + "')");
}

Path3 line(Vec3 a, Vec3 b) { return Path3::line(a, b); }
Path3 quadratic_bezier(Vec3 p0, Vec3 p1, Vec3 p2) { return Path3::quadratic_bezier(p0, p1, p2); }
Path3 cubic_bezier(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3) { return Path3::cubic_bezier(p0, p1, p2, p3); }
Path3 catmull_rom(val xyz, std::string type, bool closed) {
    return Path3::catmull_rom(points3_of(xyz, "Path3.catmullRom"), catmull_rom_type(type), closed);
}
Path3 catmull_rom_typed(val xyz, std::string type) { return catmull_rom(xyz, type, false); }
Path3 catmull_rom_uniform(val xyz) { return catmull_rom(xyz, "uniform", false); }
Path3 hermite(val xyz, val tangents, bool closed) {
    return Path3::hermite(points3_of(xyz, "Path3.hermite"), points3_of(tangents, "Path3.hermite"), closed);
}
Path3 hermite_open(val xyz, val tangents) { return hermite(xyz, tangents, false); }
Path3 linear_spline(val xyz, bool closed) { return Path3::linear_spline(points3_of(xyz, "Path3.linearSpline"), closed); }
Path3 linear_spline_open(val xyz) { return linear_spline(xyz, false); }
Path3 helix(val o) {
    const char* where = "Path3.helix";
    HelixSpec s;
    s.center = vec3_or(o, "center", s.center, where);
    s.axis = vec3_or(o, "axis", s.axis, where);
    s.start = vec3_or(o, "start", s.start, where);
    s.radius = number_or(o, "radius", s.radius, where);
    s.rise = number_or(o, "rise", s.rise, where);
    s.turns = number_or(o, "turns", s.turns, where);
    return Path3::helix(s);
}
Path3 arc(val o) {
    const char* where = "Path3.arc";
    Arc3Spec s;
    s.center = vec3_or(o, "center", s.center, where);
    s.axis = vec3_or(o, "axis", s.axis, where);
    s.start = vec3_or(o, "start", s.start, where);
    s.radius = number_or(o, "radius", s.radius, where);
    s.start_angle = number_or(o, "startAngle", s.start_angle, where);
    s.end_angle = number_or(o, "endAngle", s.end_angle, where);
    return Path3::arc(s);
}
Path3 projectile(Vec3 position, Vec3 velocity, Vec3 acceleration, double seconds) {
    return Path3::projectile(position, velocity, acceleration, seconds);
}
Path3 on_plane(const Path& path, Vec3 origin, Vec3 x_axis, Vec3 y_axis) { return Path3::on_plane(path, origin, x_axis, y_axis); }
Path3 complex(val parts, val cues) { return Path3::complex(paths3_of(parts), numbers(cues)); }
Path3 complex_by_length(val parts) { return Path3::complex_by_length(paths3_of(parts)); }
Path3 fit(val xyz, val o) {
    FitPathDef def;
    def.tolerance = number_or(o, "tolerance", def.tolerance, "Path3.fit");
    def.corner_angle = number_or(o, "cornerAngle", def.corner_angle, "Path3.fit");
    const std::vector<Vec3> points = points3_of(xyz, "Path3.fit");
    return fit_path(points, def);
}
Path3 fit_default(val xyz) { return fit(xyz, val::undefined()); }

Path3 reparametrized(const Path3& p) { return p.reparametrized(); }
Path3 slice_of(const Path3& p, double u0, double u1) { return slice(p, u0, u1); }
Bounds3 bounds(const Path3& p) { return p.bounds(); }
val flatten(const Path3& p, double tolerance) { return float64_array3(p.flatten(tolerance)); }
std::string kind(const Path3& p) { return std::string(to_string(p.kind())); }
val breaks(const Path3& p) { return float64_array(p.breaks().data(), p.breaks().size()); }
// u values in, x, y, z triples out: one call for a whole polyline of samples.
val sample(const Path3& p, val us) {
    const std::vector<double> u = numbers(us);
    std::vector<Vec3> out(u.size());
    for (std::size_t i = 0; i < u.size(); ++i) out[i] = p.point(u[i]);
    return float64_array3(out);
}
Closest3 closest(const Path3& p, Vec3 q) { return closest_point(p, q); }
// Part by part, as the 2-D ComplexPath: a Path3 inside a returned array would be freed with the call.
unsigned part_count(const Path3& p) {
    const Path3Spec spec = describe(p);
    const auto* c = std::get_if<Complex3Spec>(&spec);
    return c ? unsigned(c->parts.size()) : 0u;
}
Path3 part(const Path3& p, unsigned i) {
    const Path3Spec spec = describe(p);
    const auto* c = std::get_if<Complex3Spec>(&spec);
    if (!c) throw Error("Path3.part: a " + kind(p) + " path has no parts");
    if (i >= c->parts.size())
        throw Error("Path3.part: no part " + std::to_string(i) + " (" + std::to_string(c->parts.size()) + " parts)");
    return c->parts[i];
}

// ---- frames ----------------------------------------------------------------------------------

FrameMode frame_mode(const std::string& name) {
    if (name == "rmf") return FrameMode::rotation_minimizing;
    if (name == "ends") return FrameMode::ends;
    if (name == "closed") return FrameMode::closed;
    if (name == "reference_up") return FrameMode::reference_up;
    if (name == "frenet") return FrameMode::frenet;
    throw Error("frames options: 'mode' must be rmf, ends, closed, reference_up or frenet (got '" + name + "')");
}
std::string frame_mode_name(FrameMode m) {
    switch (m) {
        case FrameMode::rotation_minimizing: return "rmf";
        case FrameMode::ends: return "ends";
        case FrameMode::closed: return "closed";
        case FrameMode::reference_up: return "reference_up";
        case FrameMode::frenet: return "frenet";
    }
    return "rmf";
}

FramesDef frames_def(const val& o) {
    const char* where = "frames options";
    FramesDef def;
    def.mode = frame_mode(string_or(o, "mode", "rmf", where));
    def.up = vec3_or(o, "up", def.up, where);
    def.end_up = vec3_or(o, "endUp", def.end_up, where);
    // An int field: whole numbers within ±10⁶ (a million turns is already no frame to look at).
    const double turns = number_or(o, "extraTurns", def.extra_turns, where);
    if (!(turns >= -1e6 && turns <= 1e6) || turns != std::floor(turns))
        throw Error("frames options: 'extraTurns' must be an integer within ±10⁶ (got " + detail::number_text(turns) + ")");
    def.extra_turns = static_cast<int>(turns);
    def.cone = number_or(o, "cone", def.cone, where);
    def.tolerance = number_or(o, "tolerance", def.tolerance, where);
    return def;
}

Frames3* make_frames(const Path3& path, val o) { return new Frames3(path, frames_def(o)); }
Frames3* make_default_frames(const Path3& path) { return new Frames3(path); }
Frame3 frame_at(const Frames3& f, double u) { return f.frame(u); }
Quat frames_orientation(const Frames3& f, double u) { return from_frame(f.frame(u)); }
Path3 frames_path(const Frames3& f) { return f.path(); }
std::string frames_mode(const Frames3& f) { return frame_mode_name(f.mode()); }
double cone_count(const Frames3& f) { return double(f.cone_count()); }

// Frames at many u: point, tangent, normal, binormal (12 numbers) per u.
template <class F>
val sample_frames(const F& frames, const val& us) {
    const std::vector<double> u = numbers(us);
    std::vector<Vec3> out(4 * u.size());
    for (std::size_t i = 0; i < u.size(); ++i) {
        const Frame3 f = frames.frame(u[i]);
        out[4 * i] = f.point;
        out[4 * i + 1] = f.tangent;
        out[4 * i + 2] = f.normal;
        out[4 * i + 3] = f.binormal;
    }
    return float64_array3(out);
}
val frames_sample(const Frames3& f, val us) { return sample_frames(f, us); }

// ---- roll and bank ---------------------------------------------------------------------------

RollInterpolation roll_interpolation(const std::string& name) {
    if (name == "curves") return RollInterpolation::curves;
    if (name == "natural_spline") return RollInterpolation::natural_spline;
    if (name == "clamped_spline") return RollInterpolation::clamped_spline;
    throw Error("roll options: 'interpolation' must be curves, natural_spline or clamped_spline (got '" + name + "')");
}
RollTrack* make_roll(val keys, val o) {
    const char* where = "roll options";
    const std::vector<double> flat = numbers(keys);
    if (flat.size() % 2 != 0)
        throw Error("RollTrack: keys need s, roll pairs (got " + std::to_string(flat.size()) + " numbers)");
    std::vector<RollKey> k(flat.size() / 2);
    for (std::size_t i = 0; i < k.size(); ++i) k[i] = {flat[2 * i], flat[2 * i + 1]};
    RollTrackDef def;
    def.interpolation = roll_interpolation(string_or(o, "interpolation", "curves", where));
    if (has(o, "curves")) {
        const val c = o["curves"];
        const auto n = c["length"].as<unsigned>();
        for (unsigned i = 0; i < n; ++i) {
            const val ci = c[i];
            def.curves.push_back(ci.isString() ? parse_curve(ci.as<std::string>()) : ci.as<Curve>());
        }
    }
    def.start_slope = number_or(o, "startSlope", def.start_slope, where);
    def.end_slope = number_or(o, "endSlope", def.end_slope, where);
    return new RollTrack(k, def);
}
RollTrack* make_default_roll(val keys) { return make_roll(keys, val::undefined()); }
double roll_at(const RollTrack& r, double s) { return r.roll_at(s); }

BankDef bank_def(const val& o) {
    const char* where = "bank options";
    BankDef def;
    def.speed = number_or(o, "speed", def.speed, where);
    def.gravity = number_or(o, "gravity", def.gravity, where);
    def.max_angle = number_or(o, "maxAngle", def.max_angle, where);
    def.up = vec3_or(o, "up", def.up, where);
    def.smoothing = number_or(o, "smoothing", def.smoothing, where);
    // BankDef's own range, checked here before the conversion to size_t.
    const double samples = number_or(o, "samples", double(def.samples), where);
    if (!(samples >= 2 && samples <= double(std::size_t{1} << 20)) || samples != std::floor(samples))
        throw Error("bank options: 'samples' must be an integer in [2, 2^20] (got " + detail::number_text(samples) + ")");
    def.samples = std::size_t(samples);
    return def;
}
double bank_angle_at(const Path3& p, double u, val o) { return bank_angle(p, u, bank_def(o)); }
RollTrack bank_track_of(const Path3& p, val o) { return bank_track(p, bank_def(o)); }
RollTrack bank_track_default(const Path3& p) { return bank_track(p); }

RolledFrames3* make_rolled(const Frames3& frames, const RollTrack& roll) { return new RolledFrames3(frames, roll); }
Frame3 rolled_frame(const RolledFrames3& f, double u) { return f.frame(u); }
Frame3 rolled_frame_at_length(const RolledFrames3& f, double s) { return f.frame_at_length(s); }
double rolled_roll(const RolledFrames3& f, double u) { return f.roll(u); }
Quat rolled_orientation(const RolledFrames3& f, double u) { return from_frame(f.frame(u)); }
val rolled_sample(const RolledFrames3& f, val us) { return sample_frames(f, us); }

// ---- quaternions -----------------------------------------------------------------------------

Quat quat_from_axis_angle(Vec3 axis, double angle) { return from_axis_angle(axis, angle); }
AxisAngle quat_axis_angle(Quat q) { return axis_angle(q); }
Quat quat_from_basis(Vec3 x, Vec3 y, Vec3 z) { return from_basis(x, y, z); }
Basis quat_to_basis(Quat q) { return to_basis(q); }
Quat quat_from_frame(Frame3 f) { return from_frame(f); }
Quat quat_unit(double w, double x, double y, double z) { return unit_quat(w, x, y, z); }
Quat quat_multiply(Quat a, Quat b) { return a * b; }
Quat quat_conjugate(Quat q) { return conjugate(q); }
Quat quat_normalized(Quat q) { return normalized(q); }
Vec3 quat_rotate(Quat q, Vec3 v) { return rotate(q, v); }
Quat quat_slerp(Quat a, Quat b, double t) { return slerp(a, b, t); }
Quat quat_from_rotation_vector(Vec3 r) { return from_rotation_vector(r); }
Vec3 quat_rotation_vector(Quat q) { return rotation_vector(q); }

EulerOrder euler_order(const std::string& name) {
    if (name == "xyz") return EulerOrder::xyz;
    if (name == "xzy") return EulerOrder::xzy;
    if (name == "yxz") return EulerOrder::yxz;
    if (name == "yzx") return EulerOrder::yzx;
    if (name == "zxy") return EulerOrder::zxy;
    if (name == "zyx") return EulerOrder::zyx;
    throw Error("euler order must be xyz, xzy, yxz, yzx, zxy or zyx (got '" + name + "')");
}
Quat quat_from_euler(EulerAngles a, std::string order) { return from_euler(a, euler_order(order)); }
EulerAngles quat_to_euler(Quat q, std::string order) { return to_euler(q, euler_order(order)); }

std::vector<Quat> quats_of(const val& array, const char* where) {
    if (!array.isArray()) throw Error(std::string(where) + ": keys must be an array of {w, x, y, z}");
    const auto n = array["length"].as<unsigned>();
    std::vector<Quat> out(n);
    for (unsigned i = 0; i < n; ++i) {
        const val q = array[i];
        out[i] = {number_or(q, "w", 0.0, where), number_or(q, "x", 0.0, where), number_or(q, "y", 0.0, where),
                  number_or(q, "z", 0.0, where)};
    }
    return out;
}
QuatSpline* make_quat_spline(val params, val keys) { return new QuatSpline(numbers(params), quats_of(keys, "QuatSpline")); }
void check_key(const QuatSpline& s, unsigned i, const char* what) {
    if (i >= s.size())
        throw Error(std::string("QuatSpline.") + what + ": no key " + std::to_string(i) + " (" + std::to_string(s.size()) + " keys)");
}
Quat spline_orientation(const QuatSpline& s, double t) { return s.orientation(t); }
Vec3 spline_angular_velocity(const QuatSpline& s, double t) { return s.angular_velocity(t); }
unsigned spline_size(const QuatSpline& s) { return unsigned(s.size()); }
double spline_parameter(const QuatSpline& s, unsigned i) { check_key(s, i, "parameter"); return s.parameter(i); }
Quat spline_key(const QuatSpline& s, unsigned i) { check_key(s, i, "key"); return s.key(i); }
Vec3 spline_key_velocity(const QuatSpline& s, unsigned i) { check_key(s, i, "keyAngularVelocity"); return s.key_angular_velocity(i); }
int spline_iterations(const QuatSpline& s) { return s.iterations(); }

// ---- views -----------------------------------------------------------------------------------

View3 oblique(double angle, double recede) { return View3::oblique(angle, recede); }
View3 oblique_default() { return View3::oblique(); }
View3 perspective(Vec3 eye, Vec3 target, Vec3 up, double fov_y) { return View3::perspective(eye, target, up, fov_y); }
View3 perspective_up(Vec3 eye, Vec3 target, Vec3 up) { return View3::perspective(eye, target, up); }
View3 perspective_default(Vec3 eye, Vec3 target) { return View3::perspective(eye, target); }
View3 orbit(Vec3 target, double distance, double azimuth, double elevation, double fov_y) {
    return View3::orbit(target, distance, azimuth, elevation, fov_y);
}
View3 orbit_default(Vec3 target, double distance, double azimuth, double elevation) {
    return View3::orbit(target, distance, azimuth, elevation);
}
Projected project(const View3& v, Vec3 p) { return v.project(p); }
// x, y, z triples in, x, y, depth triples out; x and y NaN where the point is not visible.
val project_many(const View3& v, val xyz) {
    const std::vector<Vec3> points = points3_of(xyz, "View3.projectMany");
    std::vector<Vec3> out(points.size());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Projected q = v.project(points[i]);
        out[i] = q.visible ? Vec3{q.point.x, q.point.y, q.depth} : Vec3{nan, nan, q.depth};
    }
    return float64_array3(out);
}
Vec3 view_direction(const View3& v, Vec3 p) { return v.view_direction(p); }
Vec3 view_eye(const View3& v) { return v.eye(); }
bool view_is_perspective(const View3& v) { return v.is_perspective(); }

// ---- motion ----------------------------------------------------------------------------------

Axis3 axis3(const val& o, const char* name, Axis3 fallback) {
    const std::string s = string_or(o, name, "", "motion options");
    if (s.empty() && !has(o, name)) return fallback;
    constexpr const char* names[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    for (int i = 0; i < 6; ++i)
        if (s == names[i]) return static_cast<Axis3>(i);
    throw Error(std::string("motion options: '") + name + "' must be +x, -x, +y, -y, +z or -z (got '" + s + "')");
}

Motion3Def motion_def(const val& o) {
    const char* where = "motion options";
    Motion3Def m;
    const std::string align = string_or(o, "align", "none", where);
    if (align == "none") m.align = Align3::none;
    else if (align == "frame") m.align = Align3::frame;
    else if (align == "world") m.align = Align3::world;
    else throw Error("motion options: 'align' must be none, frame or world (got '" + align + "')");
    if (has(o, "frames")) m.frames = frames_def(o["frames"]);
    if (has(o, "sharedFrames")) m.shared_frames = std::make_shared<const Frames3>(o["sharedFrames"].as<Frames3>());
    m.world_up = vec3_or(o, "worldUp", m.world_up, where);
    m.forward = axis3(o, "forward", m.forward);
    m.up = axis3(o, "up", m.up);
    m.face_travel = bool_or(o, "faceTravel", m.face_travel);
    m.normal_offset = number_or(o, "normalOffset", m.normal_offset, where);
    m.binormal_offset = number_or(o, "binormalOffset", m.binormal_offset, where);
    return m;
}

}  // namespace

unsigned WebEngine::add3(const Path3& path, val timing, val options, val motion) {
    if (used3_ >= capacity3_)
        throw Error("Engine.add3: all " + std::to_string(capacity3_) +
                    " 3-D slots are used (capacity3 is fixed at construction: new Engine(capacity, capacity3))");
    const AnimationDef def = animation_def(options);
    const Motion3Def m = motion_def(motion);
    Slot3& slot = slots3_[used3_];
    if (timing.isNumber()) {
        handles3_.push_back(engine_.create_3d_animation(slot, path, timing.as<double>(), def, m));
    } else if (has(timing, "speed")) {
        const Speed speed{number_or(timing, "speed", 1.0, "Engine.add3")};
        handles3_.push_back(engine_.create_3d_animation(slot, path, speed, def, m));
    } else {
        throw Error("Engine.add3: timing must be a duration in seconds or {speed: units per second}");
    }
    return used3_++;
}

EMSCRIPTEN_BINDINGS(grape_3d) {
    using namespace emscripten;
    value_object<Vec3>("Vec3").field("x", &Vec3::x).field("y", &Vec3::y).field("z", &Vec3::z);
    value_object<Quat>("Quat").field("w", &Quat::w).field("x", &Quat::x).field("y", &Quat::y).field("z", &Quat::z);
    value_object<Basis>("Basis").field("x", &Basis::x).field("y", &Basis::y).field("z", &Basis::z);
    value_object<AxisAngle>("AxisAngle").field("axis", &AxisAngle::axis).field("angle", &AxisAngle::angle);
    value_object<EulerAngles>("EulerAngles")
        .field("first", &EulerAngles::first).field("second", &EulerAngles::second).field("third", &EulerAngles::third);
    value_object<Bounds3>("Bounds3").field("min", &Bounds3::min).field("max", &Bounds3::max);
    value_object<Closest3>("Closest3")
        .field("u", &Closest3::u).field("point", &Closest3::point)
        .field("distance", &Closest3::distance).field("gap", &Closest3::gap);
    value_object<Frenet3>("Frenet3")
        .field("point", &Frenet3::point).field("tangent", &Frenet3::tangent).field("normal", &Frenet3::normal)
        .field("binormal", &Frenet3::binormal).field("curvature", &Frenet3::curvature)
        .field("torsion", &Frenet3::torsion).field("normalDefined", &Frenet3::normal_defined);
    value_object<Frame3>("Frame3")
        .field("point", &Frame3::point).field("tangent", &Frame3::tangent)
        .field("normal", &Frame3::normal).field("binormal", &Frame3::binormal);
    value_object<Projected>("Projected")
        .field("point", &Projected::point).field("depth", &Projected::depth).field("visible", &Projected::visible);

    class_<Path3>("Path3")
        .constructor<>()
        .function("point", method<&Path3::point>)
        .function("d1", method<&Path3::d1>)
        .function("d2", method<&Path3::d2>)
        .function("d3", method<&Path3::d3>)
        .function("tangent", method<&Path3::tangent>)
        .function("frenet", method<&Path3::frenet>)
        .function("length", method<&Path3::length>)
        .function("lengthAt", method<&Path3::length_at>)
        .function("uAtLength", method<&Path3::u_at_length>)
        .function("pointAtLength", method<&Path3::point_at_length>)
        .function("breaks", &breaks)
        .function("bounds", &bounds)
        .function("flatten", guarded<&flatten>)
        .function("sample", guarded<&sample>)
        .function("reparametrized", guarded<&reparametrized>)
        .function("slice", guarded<&slice_of>)
        .function("closestPoint", &closest)
        .function("kind", &kind)
        .function("partCount", &part_count)
        .function("part", guarded<&part>)
        .class_function("line", guarded<&line>)
        .class_function("quadraticBezier", guarded<&quadratic_bezier>)
        .class_function("cubicBezier", guarded<&cubic_bezier>)
        .class_function("catmullRom", guarded<&catmull_rom>)
        .class_function("catmullRom", guarded<&catmull_rom_typed>)
        .class_function("catmullRom", guarded<&catmull_rom_uniform>)
        .class_function("hermite", guarded<&hermite>)
        .class_function("hermite", guarded<&hermite_open>)
        .class_function("linearSpline", guarded<&linear_spline>)
        .class_function("linearSpline", guarded<&linear_spline_open>)
        .class_function("helix", guarded<&helix>)
        .class_function("arc", guarded<&arc>)
        .class_function("projectile", guarded<&projectile>)
        .class_function("onPlane", guarded<&on_plane>)
        .class_function("complex", guarded<&complex>)
        .class_function("complexByLength", guarded<&complex_by_length>)
        .class_function("fit", guarded<&fit>)
        .class_function("fit", guarded<&fit_default>);

    class_<Frames3>("Frames3")
        .constructor(guarded<&make_frames>, allow_raw_pointers())
        .constructor(guarded<&make_default_frames>, allow_raw_pointers())
        .function("frame", &frame_at)
        .function("orientation", &frames_orientation)
        .function("sample", guarded<&frames_sample>)
        .function("path", &frames_path)
        .function("mode", &frames_mode)
        .function("twist", method<&Frames3::twist>)
        .function("coneCount", &cone_count)
        .function("lengthAt", method<&Frames3::length_at>);

    class_<RollTrack>("RollTrack")
        .constructor(guarded<&make_roll>, allow_raw_pointers())
        .constructor(guarded<&make_default_roll>, allow_raw_pointers())
        .function("rollAt", &roll_at);
    class_<RolledFrames3>("RolledFrames3")
        .constructor(guarded<&make_rolled>, allow_raw_pointers())
        .function("frame", &rolled_frame)
        .function("frameAtLength", &rolled_frame_at_length)
        .function("roll", &rolled_roll)
        .function("orientation", &rolled_orientation)
        .function("sample", guarded<&rolled_sample>);
    function("bankAngle", guarded<&bank_angle_at>);
    function("bankTrack", guarded<&bank_track_of>);
    function("bankTrack", guarded<&bank_track_default>);

    function("quatFromAxisAngle", guarded<&quat_from_axis_angle>);
    function("quatAxisAngle", &quat_axis_angle);
    function("quatFromBasis", guarded<&quat_from_basis>);
    function("quatToBasis", &quat_to_basis);
    function("quatFromFrame", &quat_from_frame);
    function("quatFromEuler", guarded<&quat_from_euler>);
    function("quatToEuler", guarded<&quat_to_euler>);
    function("quatFromRotationVector", &quat_from_rotation_vector);
    function("quatRotationVector", &quat_rotation_vector);
    function("unitQuat", guarded<&quat_unit>);
    function("quatMultiply", &quat_multiply);
    function("quatConjugate", &quat_conjugate);
    function("quatNormalized", &quat_normalized);
    function("quatRotate", &quat_rotate);
    function("quatSlerp", &quat_slerp);

    class_<QuatSpline>("QuatSpline")
        .constructor(guarded<&make_quat_spline>, allow_raw_pointers())
        .function("orientation", &spline_orientation)
        .function("angularVelocity", &spline_angular_velocity)
        .function("size", &spline_size)
        .function("parameter", guarded<&spline_parameter>)
        .function("key", guarded<&spline_key>)
        .function("keyAngularVelocity", guarded<&spline_key_velocity>)
        .function("iterations", &spline_iterations);

    class_<View3>("View3")
        .constructor<>()
        .function("project", &project)
        .function("projectMany", guarded<&project_many>)
        .function("viewDirection", &view_direction)
        .function("eye", &view_eye)
        .function("isPerspective", &view_is_perspective)
        .class_function("oblique", guarded<&oblique>)
        .class_function("oblique", guarded<&oblique_default>)
        .class_function("perspective", guarded<&perspective>)
        .class_function("perspective", guarded<&perspective_up>)
        .class_function("perspective", guarded<&perspective_default>)
        .class_function("orbit", guarded<&orbit>)
        .class_function("orbit", guarded<&orbit_default>);
}

}  // namespace grape::web
