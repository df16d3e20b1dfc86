// Simulations in scene files: particles, forces, constraints, integrator and drift.
#include "scene_json.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace grape::scene_io {

namespace {

const std::vector<std::string_view> integrators = {"euler", "semi_implicit_euler", "midpoint", "rk4", "velocity_verlet", "rk45", "rattle"};
const std::vector<std::string_view> drifts = {"none", "baumgarte", "projection"};

}  // namespace

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
        // Constraints sharing a particle couple in the solve (a dense block per particle, the
        // square of its count): a particle has two degrees of freedom, a cloth's hold about a
        // dozen rods; more than this is a mistake that would stall the solver.
        std::vector<std::size_t> per_particle(n, 0);
        const auto hold = [&](std::size_t particle, const std::string& at) {
            if (++per_particle[particle] > max_constraints_per_particle)
                fail(at, "particle " + std::to_string(particle) + " is in more than " +
                             std::to_string(max_constraints_per_particle) + " constraints");
        };
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
            hold(c.a, p);
            if (c.kind == SceneConstraintKind::distance) hold(c.b, p);
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


}  // namespace grape::scene_io
