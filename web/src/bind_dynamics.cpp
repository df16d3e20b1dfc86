// Dynamics for JavaScript: a ParticleSystem with its constraints (positions and velocities
// as Float64Array views, 2n doubles), and a Bead on any path.
#include "web_util.hpp"

#include <grape/dynamics.hpp>

#include <emscripten/bind.h>

#include <limits>
#include <string>

namespace grape::web {
namespace {

DriftDef drift_def(const val& o, DriftDef def) {
    const char* where = "drift options";
    if (has(o, "drift")) def.method = parse_drift_control(string_or(o, "drift", "", where));
    def.omega_dt = number_or(o, "omegaDt", def.omega_dt, where);
    if (has(o, "stiffness")) def.stiffness = number_or(o, "stiffness", 0.0, where);
    if (has(o, "damping")) def.damping = number_or(o, "damping", 0.0, where);
    def.projection_iterations = int(number_or(o, "projectionIterations", def.projection_iterations, where));
    def.projection_tolerance = number_or(o, "projectionTolerance", def.projection_tolerance, where);
    return def;
}

LinearSolver parse_solver(const std::string& name) {
    if (name == "automatic") return LinearSolver::automatic;
    if (name == "dense") return LinearSolver::dense;
    if (name == "sparse_direct") return LinearSolver::sparse_direct;
    if (name == "conjugate_gradient") return LinearSolver::conjugate_gradient;
    throw Error("ParticleSystem: solver must be automatic, dense, sparse_direct or conjugate_gradient (got '" + name + "')");
}

ParticleSystemDef system_def(const val& o) {
    ParticleSystemDef def;
    if (has(o, "integrator")) def.integrator = parse_integrator(string_or(o, "integrator", "", "ParticleSystem"));
    def.drift = drift_def(o, def.drift);
    if (has(o, "solver")) def.solver.method = parse_solver(string_or(o, "solver", "", "ParticleSystem"));
    def.rk45.tolerance = number_or(o, "rk45Tolerance", def.rk45.tolerance, "ParticleSystem");
    return def;
}

val view(std::span<const Vec2> v) { return val(emscripten::typed_memory_view(2 * v.size(), &v.data()->x)); }
val residual_object(const ConstraintResidual& r) {
    val out = val::object();
    out.set("value", r.value);
    out.set("rate", r.rate);
    out.set("distance", r.distance);
    return out;
}

// C = a·x² + b·x·y + c·y² + d·x + e·y + f: every conic, with its exact gradient and Hessian
// (the seed's parabola x² + 100y is [1, 0, 0, 0, 100, 0]).
ImplicitFunction conic(const std::vector<double>& k) {
    if (k.size() != 6) throw Error("addConic: needs 6 coefficients a, b, c, d, e, f (got " + std::to_string(k.size()) + ")");
    for (double v : k)
        if (!std::isfinite(v)) throw Error("addConic: coefficients must be finite");
    return ImplicitFunction([a = k[0], b = k[1], c = k[2], d = k[3], e = k[4], f = k[5]](Vec2 p) {
        return ImplicitSample{.value = a * p.x * p.x + b * p.x * p.y + c * p.y * p.y + d * p.x + e * p.y + f,
                           .gradient = {2 * a * p.x + b * p.y + d, b * p.x + 2 * c * p.y + e},
                           .hxx = 2 * a,
                           .hxy = b,
                           .hyy = 2 * c};
    });
}

ParticleId pid(const ParticleSystem& s, unsigned i) {
    if (i >= s.size()) throw Error("ParticleSystem: no particle " + std::to_string(i) + " (" + std::to_string(s.size()) + " particles)");
    return ParticleId{i};
}

ParticleSystem* make_system(val options) {
    std::string message;
    try {
        return new ParticleSystem(system_def(options));
    } catch (const std::exception& e) {
        message = e.what();
    }
    throw_js(message);
}
ParticleSystem* make_default_system() { return make_system(val::undefined()); }
unsigned create_particle(ParticleSystem& s, Vec2 position, Vec2 velocity, double mass) {
    return s.create_particle({.position = position, .velocity = velocity, .mass = mass}).index;
}
double size(const ParticleSystem& s) { return double(s.size()); }
val positions(const ParticleSystem& s) { return view(s.positions()); }
val velocities(const ParticleSystem& s) { return view(s.velocities()); }
val inverse_masses(const ParticleSystem& s) {
    return val(emscripten::typed_memory_view(s.inverse_masses().size(), s.inverse_masses().data()));
}
Vec2 position(const ParticleSystem& s, unsigned i) { return s.position(pid(s, i)); }
Vec2 velocity(const ParticleSystem& s, unsigned i) { return s.velocity(pid(s, i)); }
double mass(const ParticleSystem& s, unsigned i) { return s.mass(pid(s, i)); }
void set_position(ParticleSystem& s, unsigned i, Vec2 p) { s.set_position(pid(s, i), p); }
void set_velocity(ParticleSystem& s, unsigned i, Vec2 v) { s.set_velocity(pid(s, i), v); }
void exert_force(ParticleSystem& s, unsigned i, Vec2 f) { s.exert_force(pid(s, i), f); }
void add_gravity(ParticleSystem& s, Vec2 g) { s.add_gravity(g); }
void add_drag(ParticleSystem& s, double k) { s.add_drag(k); }
void add_spring(ParticleSystem& s, unsigned a, unsigned b, double rest, double k, double c) {
    s.add_spring(pid(s, a), pid(s, b), {.rest_length = rest, .stiffness = k, .damping = c});
}
// length undefined: held at the current distance.
unsigned create_distance(ParticleSystem& s, unsigned a, unsigned b, val length) {
    if (length.isUndefined() || length.isNull()) return s.create_distance(pid(s, a), pid(s, b)).index;
    return s.create_distance(pid(s, a), pid(s, b), length.as<double>()).index;
}
unsigned add_held_distance(ParticleSystem& s, unsigned a, unsigned b) { return s.create_distance(pid(s, a), pid(s, b)).index; }
unsigned create_anchor(ParticleSystem& s, unsigned a, Vec2 anchor, double length) {
    return s.create_anchor(pid(s, a), anchor, length).index;
}
unsigned create_fixed_point(ParticleSystem& s, unsigned a, Vec2 p) { return s.create_fixed_point(pid(s, a), p).index; }
unsigned add_conic(ParticleSystem& s, unsigned a, val k) { return s.create_implicit(pid(s, a), conic(numbers(k))).index; }
// fn(x, y) → {value, gx, gy, hxx, hxy, hyy}: called at every integrator stage.
unsigned create_implicit(ParticleSystem& s, unsigned a, val fn) {
    if (fn.typeOf().as<std::string>() != "function") throw Error("addCurve: needs a function (x, y) => {value, gx, gy, hxx, hxy, hyy}");
    return s.create_implicit(pid(s, a), ImplicitFunction([fn](Vec2 p) {
                           const val r = fn(p.x, p.y);
                           return ImplicitSample{.value = r["value"].as<double>(),
                                              .gradient = {r["gx"].as<double>(), r["gy"].as<double>()},
                                              .hxx = r["hxx"].as<double>(),
                                              .hxy = r["hxy"].as<double>(),
                                              .hyy = r["hyy"].as<double>()};
                       })).index;
}
double constraint_count(const ParticleSystem& s) { return double(s.constraint_count()); }
void set_drift(ParticleSystem& s, val o) { s.set_drift(drift_def(o, s.def().drift)); }
void set_integrator(ParticleSystem& s, std::string name) { s.set_integrator(parse_integrator(name)); }
val step(ParticleSystem& s, double dt) {
    const StepStats r = s.step(dt);
    val out = val::object();
    out.set("status", std::string(to_string(r.status)));
    out.set("evaluations", r.evaluations);
    out.set("substeps", r.substeps);
    out.set("rejected", r.rejected);
    out.set("projectionIterations", r.projection_iterations);
    out.set("cgIterations", r.cg_iterations);
    return out;
}
// Steps n times by dt with no report (the cheap inner loop of a frame).
void steps(ParticleSystem& s, double dt, unsigned n) {
    for (unsigned i = 0; i < n; ++i) s.step(dt);
}
double time(const ParticleSystem& s) { return s.time(); }
double kinetic(const ParticleSystem& s) { return s.kinetic_energy(); }
double potential(const ParticleSystem& s) { return s.potential_energy(); }
double energy(const ParticleSystem& s) { return s.energy(); }
val max_residual(const ParticleSystem& s) { return residual_object(s.max_residual()); }
val residuals(const ParticleSystem& s) {
    val out = val::array();
    for (const ConstraintResidual& r : s.residuals()) out.call<void>("push", residual_object(r));
    return out;
}

// ---- Bead ----

BeadDef bead_def(const val& o) {
    const char* where = "Bead";
    BeadDef def;
    def.u = number_or(o, "u", def.u, where);
    def.speed = number_or(o, "speed", def.speed, where);
    def.mass = number_or(o, "mass", def.mass, where);
    def.gravity = vec2_or(o, "gravity", def.gravity, where);
    def.drag = number_or(o, "drag", def.drag, where);
    if (has(o, "ends")) {
        const std::string ends = string_or(o, "ends", "", where);
        if (ends == "stop") def.ends = BeadEnd::stop;
        else if (ends == "bounce") def.ends = BeadEnd::bounce;
        else throw Error("Bead: option 'ends' must be stop or bounce (got '" + ends + "')");
    }
    def.restitution = number_or(o, "restitution", def.restitution, where);
    if (has(o, "integrator")) def.integrator = parse_integrator(string_or(o, "integrator", "", where));
    return def;
}

// A ComplexPath keeps its joins (the bead carries its speed across them).
Bead* make_bead(val path, val options) {
    std::string message;
    try {
        const BeadDef def = bead_def(options);
        if (path.instanceof(val::module_property("ComplexPath"))) return new Bead(path.as<ComplexPath>(), def);
        return new Bead(path.as<Path>(), def);
    } catch (const std::exception& e) {
        message = e.what();
    }
    throw_js(message);
}
Bead* make_default_bead(val path) { return make_bead(path, val::undefined()); }
// fn(t, x, y, vx, vy) → {x, y}; null or undefined removes it.
void set_force(Bead& b, val fn) {
    if (fn.isNull() || fn.isUndefined()) {
        b.set_force({});
        return;
    }
    b.set_force([fn](double t, Vec2 x, Vec2 v) {
        const val f = fn(t, x.x, x.y, v.x, v.y);
        return Vec2{f["x"].as<double>(), f["y"].as<double>()};
    });
}
void bead_step(Bead& b, double dt) { b.step(dt); }
double bead_time(const Bead& b) { return b.time(); }
double bead_u(const Bead& b) { return b.u(); }
double bead_u_rate(const Bead& b) { return b.u_rate(); }
Vec2 bead_position(const Bead& b) { return b.position(); }
Vec2 bead_velocity(const Bead& b) { return b.velocity(); }
double bead_speed(const Bead& b) { return b.speed(); }
double bead_energy(const Bead& b) { return b.energy(); }
double bead_acceleration(const Bead& b) { return b.acceleration(); }
int bead_crossings(const Bead& b) { return b.crossings(); }

}  // namespace

EMSCRIPTEN_BINDINGS(grape_dynamics) {
    using namespace emscripten;
    class_<ParticleSystem>("ParticleSystem")
        .constructor(&make_system, allow_raw_pointers())
        .constructor(&make_default_system, allow_raw_pointers())
        .function("addParticle", guarded<&create_particle>)
        .function("size", &size)
        .function("positions", &positions)
        .function("velocities", &velocities)
        .function("inverseMasses", &inverse_masses)
        .function("position", guarded<&position>)
        .function("velocity", guarded<&velocity>)
        .function("mass", guarded<&mass>)
        .function("setPosition", guarded<&set_position>)
        .function("setVelocity", guarded<&set_velocity>)
        .function("exertForce", guarded<&exert_force>)
        .function("addGravity", guarded<&add_gravity>)
        .function("addDrag", guarded<&add_drag>)
        .function("addSpring", guarded<&add_spring>)
        .function("addDistance", guarded<&create_distance>)
        .function("addDistance", guarded<&add_held_distance>)
        .function("addAnchor", guarded<&create_anchor>)
        .function("addFixedPoint", guarded<&create_fixed_point>)
        .function("addConic", guarded<&add_conic>)
        .function("addCurve", guarded<&create_implicit>)
        .function("constraintCount", &constraint_count)
        .function("setDrift", guarded<&set_drift>)
        .function("setIntegrator", guarded<&set_integrator>)
        .function("step", guarded<&step>)
        .function("steps", guarded<&steps>)
        .function("time", &time)
        .function("kineticEnergy", &kinetic)
        .function("potentialEnergy", guarded<&potential>)
        .function("energy", guarded<&energy>)
        .function("maxResidual", guarded<&max_residual>)
        .function("residuals", guarded<&residuals>);
    class_<Bead>("Bead")
        .constructor(&make_bead, allow_raw_pointers())
        .constructor(&make_default_bead, allow_raw_pointers())
        .function("setForce", &set_force)
        .function("step", guarded<&bead_step>)
        .function("time", &bead_time)
        .function("u", &bead_u)
        .function("uRate", &bead_u_rate)
        .function("position", &bead_position)
        .function("velocity", &bead_velocity)
        .function("speed", &bead_speed)
        .function("energy", &bead_energy)
        .function("acceleration", &bead_acceleration)
        .function("crossings", &bead_crossings);
}

}  // namespace grape::web
