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

// Each object of the array `key` of `j` (none when absent), with its pointer and its "kind".
template <class F>
void for_each_kind(const json& j, const std::string& pointer, std::string_view key, F&& f) {
    const auto list = j.find(key);
    if (list == j.end()) return;
    const std::string lp = child(pointer, key);
    if (!list->is_array()) fail(lp, "expected an array, got " + type_of(*list));
    for (std::size_t i = 0; i < list->size(); ++i) {
        const std::string p = child(lp, i);
        const json& o = (*list)[i];
        if (!o.is_object()) fail(p, "expected an object, got " + type_of(o));
        f(o, p, string_value(required(o, p, "kind"), child(p, "kind")));
    }
}

// The JSON array of `items`, each as `to_json` writes it.
template <class T, class F>
ordered array_json(const std::vector<T>& items, F&& to_json) {
    ordered a = ordered::array();
    for (const T& x : items) a.push_back(to_json(x));
    return a;
}

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
    for_each_kind(j, pointer, "forces", [&](const json& o, const std::string& p, const std::string& kind) {
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
    });
    // Constraints sharing a particle couple in the solve (a dense block per particle, the
    // square of its count): a particle has two degrees of freedom, a cloth's hold about a
    // dozen rods; more than this is a mistake that would stall the solver.
    std::vector<std::size_t> per_particle(n, 0);
    const auto hold = [&](std::size_t particle, const std::string& at) {
        if (++per_particle[particle] > max_constraints_per_particle)
            fail(at, "particle " + std::to_string(particle) + " is in more than " +
                         std::to_string(max_constraints_per_particle) + " constraints");
    };
    for_each_kind(j, pointer, "constraints", [&](const json& o, const std::string& p, const std::string& kind) {
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
    });
    return s;
}

ordered simulation_json(const SceneSimulation& s) {
    ordered j;
    if (!s.name.empty()) j["name"] = s.name;
    j["integrator"] = s.integrator;
    j["drift"] = s.drift;
    j["dt"] = s.dt;
    j["duration"] = s.duration;
    j["particles"] = array_json(s.particles, [](const SceneParticle& p) {
        ordered o = {{"position", point_json(p.position)}, {"velocity", point_json(p.velocity)}};
        if (std::isinf(p.mass)) o["mass"] = "pinned";
        else o["mass"] = p.mass;
        return o;
    });
    j["forces"] = array_json(s.forces, [](const SceneForce& f) {
        switch (f.kind) {
            case SceneForceKind::gravity: return ordered{{"kind", "gravity"}, {"acceleration", point_json(f.gravity)}};
            case SceneForceKind::drag: return ordered{{"kind", "drag"}, {"k", f.drag}};
            case SceneForceKind::spring: break;
        }
        return ordered{{"kind", "spring"}, {"a", f.a}, {"b", f.b}, {"rest_length", f.rest_length},
                       {"stiffness", f.stiffness}, {"damping", f.damping}};
    });
    j["constraints"] = array_json(s.constraints, [](const SceneConstraint& c) {
        switch (c.kind) {
            case SceneConstraintKind::distance: return ordered{{"kind", "distance"}, {"a", c.a}, {"b", c.b}, {"length", c.length}};
            case SceneConstraintKind::anchor:
                return ordered{{"kind", "anchor"}, {"a", c.a}, {"point", point_json(c.point)}, {"length", c.length}};
            case SceneConstraintKind::fixed_point: return ordered{{"kind", "fixed_point"}, {"a", c.a}, {"point", point_json(c.point)}};
            case SceneConstraintKind::conic: break;
        }
        ordered o = {{"kind", "conic"}, {"a", c.a}, {"coefficients", ordered::array()}};
        for (double k : c.conic) o["coefficients"].push_back(k);
        return o;
    });
    return j;
}


}  // namespace grape::scene_io
