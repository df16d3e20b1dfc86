// A SceneSimulation as a running grape::ParticleSystem (built only with the dynamics module).
#include <grape/scene.hpp>

#include <grape/dynamics.hpp>
#include <grape/error.hpp>

namespace grape {

ParticleSystem make_particle_system(const SceneSimulation& simulation) {
    ParticleSystemDef def;
    def.integrator = parse_integrator(simulation.integrator);
    def.drift.method = parse_drift_control(simulation.drift);
    ParticleSystem system(def);
    std::vector<ParticleId> ids;
    for (const SceneParticle& p : simulation.particles)
        ids.push_back(system.create_particle({.position = p.position, .velocity = p.velocity, .mass = p.mass}));
    const auto id = [&](std::size_t i) {
        if (i >= ids.size()) throw Error("make_particle_system: no particle " + std::to_string(i));
        return ids[i];
    };
    for (const SceneForce& f : simulation.forces) {
        switch (f.kind) {
            case SceneForceKind::gravity: system.add_gravity(f.gravity); break;
            case SceneForceKind::drag: system.add_drag(f.drag); break;
            case SceneForceKind::spring:
                system.add_spring(id(f.a), id(f.b),
                                  {.rest_length = f.rest_length, .stiffness = f.stiffness, .damping = f.damping});
                break;
        }
    }
    for (const SceneConstraint& c : simulation.constraints) {
        switch (c.kind) {
            case SceneConstraintKind::distance:
                if (c.length > 0.0) system.create_distance(id(c.a), id(c.b), c.length);
                else system.create_distance(id(c.a), id(c.b));
                break;
            case SceneConstraintKind::anchor: system.create_anchor(id(c.a), c.point, c.length); break;
            case SceneConstraintKind::fixed_point: system.create_fixed_point(id(c.a), c.point); break;
            case SceneConstraintKind::conic: {
                const double k0 = c.conic[0], k1 = c.conic[1], k2 = c.conic[2], k3 = c.conic[3], k4 = c.conic[4],
                             k5 = c.conic[5];
                system.create_implicit(id(c.a), ImplicitFunction::from_function([=](auto x, auto y) {
                                     return k0 * x * x + k1 * x * y + k2 * y * y + k3 * x + k4 * y + k5;
                                 }));
                break;
            }
        }
    }
    return system;
}

}  // namespace grape
