#include "seed_dynamics.hpp"

#include <grape/error.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace grape::scenes {

ImplicitFunction seed_parabola_curve() {
    return ImplicitFunction::from_function([](auto x, auto y) { return seed_parabola_c(x, y); });
}

ImplicitFunction seed_parabola_curve_analytic() {
    return ImplicitFunction([](Vec2 p) { return ImplicitSample{p.x * p.x + 100.0 * p.y, {2.0 * p.x, 100.0}, 2.0, 0.0, 0.0}; });
}

ParametricSample seed_parabola_frame(double q) noexcept { return {{q, -q * q / 100.0}, {1.0, -q / 50.0}, {0.0, -1.0 / 50.0}}; }

Vec2 seed_constraint_force(double mass, Vec2 x, Vec2 v, Vec2 f_ext) noexcept {
    const double fy = (-50.0 * mass * v.x * v.x - 100.0 * x.x * f_ext.x - 2500.0 * f_ext.y) / (x.x * x.x + 2500.0);
    return {fy * x.x / 50.0, fy};
}

Vec2 corrected_constraint_force(double mass, Vec2 x, Vec2 v, Vec2 f_ext) noexcept {
    const double fy = (-50.0 * mass * v.x * v.x - 50.0 * x.x * f_ext.x - 2500.0 * f_ext.y) / (x.x * x.x + 2500.0);
    return {fy * x.x / 50.0, fy};
}

double seed_parametric_acceleration(double q, double q_dot, double g) noexcept {
    return (-q * q_dot * q_dot - 50.0 * g * q) / (2500.0 + q * q);
}

std::string_view to_string(ParabolaMethod method) noexcept {
    switch (method) {
    case ParabolaMethod::implicit: return "implicit";
    case ParabolaMethod::parametric: return "parametric";
    case ParabolaMethod::seed: return "seed";
    }
    return "unknown";
}

ParabolaMethod parse_parabola_method(std::string_view name) {
    for (auto m : {ParabolaMethod::implicit, ParabolaMethod::parametric, ParabolaMethod::seed})
        if (name == to_string(m)) return m;
    throw Error("method: unknown name '" + std::string(name) + "' (expected implicit, parametric or seed)");
}

ParabolaRun::ParabolaRun(const ParabolaSetup& setup) : setup_(setup) {
    if (!std::isfinite(setup.x0)) throw Error("parabola: x0 must be finite (got " + std::to_string(setup.x0) + ")");
    if (!std::isfinite(setup.g)) throw Error("parabola: g must be finite (got " + std::to_string(setup.g) + ")");
    if (!std::isfinite(setup.force_x))
        throw Error("parabola: force_x must be finite (got " + std::to_string(setup.force_x) + ")");
    if (!(setup.mass > 0.0) || !std::isfinite(setup.mass))
        throw Error("parabola: mass must be positive and finite (got " + std::to_string(setup.mass) + ")");
    const Vec2 start{setup.x0, -setup.x0 * setup.x0 / 100.0};
    const double fx = setup.force_x;
    if (setup.method == ParabolaMethod::parametric) {
        bead_.emplace(ParametricFunction(seed_parabola_frame),
                      BeadDef{.u = setup.x0, .mass = setup.mass, .gravity = {0.0, setup.g},
                              .integrator = setup.integrator, .rk45 = setup.rk45});
        if (fx != 0.0) bead_->set_force([fx](double, Vec2, Vec2) { return Vec2{fx, 0.0}; });
        return;
    }
    system_.emplace(ParticleSystemDef{.integrator = setup.integrator,
                                      .drift = setup.method == ParabolaMethod::implicit ? setup.drift : DriftDef{.method = DriftControl::none},
                                      .rk45 = setup.rk45});
    const ParticleId p = system_->create_particle({.position = start, .mass = setup.mass});
    system_->add_gravity({0.0, setup.g});
    if (fx != 0.0)
        system_->add_force([fx](const ForceContext& c) { c.forces[0] += Vec2{fx, 0.0}; },
                           [fx](std::span<const Vec2> x) { return -fx * x[0].x; });
    if (setup.method == ParabolaMethod::implicit) {
        system_->create_implicit(p, seed_parabola_curve());
    } else {
        // The seed's harness: all applied forces are accumulated first, then its closed form reads them.
        const double m = setup.mass;
        system_->add_force([m](const ForceContext& c) {
            c.forces[0] += seed_constraint_force(m, c.positions[0], c.velocities[0], c.forces[0]);
        });
    }
}

bool ParabolaRun::step(double dt) {
    if (bead_) return bead_->step(dt).status != SolveStatus::non_finite;
    return system_->step(dt).status != SolveStatus::non_finite;
}

ParabolaState ParabolaRun::state() const {
    ParabolaState s;
    if (bead_) {
        s.t = bead_->time();
        s.x = bead_->position();
        s.v = bead_->velocity();
        s.energy = bead_->energy() - setup_.force_x * s.x.x;
    } else {
        s.t = system_->time();
        s.x = system_->positions()[0];
        s.v = system_->velocities()[0];
        s.energy = system_->energy();
    }
    s.residual = seed_parabola_c(s.x.x, s.x.y);
    s.distance = std::abs(s.residual) / std::hypot(2.0 * s.x.x, 100.0);
    return s;
}

ParabolaSummary run_parabola(const ParabolaSetup& setup, double dt, double seconds,
                             const std::function<void(const ParabolaState&)>& each) {
    if (!(dt > 0.0) || !std::isfinite(dt)) throw Error("parabola: dt must be positive and finite (got " + std::to_string(dt) + ")");
    if (!(seconds >= 0.0) || !std::isfinite(seconds))
        throw Error("parabola: seconds must be finite and ≥ 0 (got " + std::to_string(seconds) + ")");
    ParabolaRun run(setup);
    ParabolaSummary summary;
    summary.initial = run.state();
    const double e0 = summary.initial.energy;
    const auto steps = static_cast<long long>(std::llround(seconds / dt));
    ParabolaState s = summary.initial;
    for (long long i = 0; i < steps; ++i) {
        const bool finite = run.step(dt);
        s = run.state();
        s.finite = finite;
        summary.max_residual = std::max(summary.max_residual, std::abs(s.residual));
        summary.max_distance = std::max(summary.max_distance, s.distance);
        summary.max_energy_error = std::max(summary.max_energy_error, std::abs(s.energy - e0) / std::abs(e0));
        if (each) each(s);
        if (!finite) break;  // the state stands where the step refused to leave the finite range
    }
    summary.final = s;
    return summary;
}

ParticleSystem simple_pendulum(double length, double theta0, double g, const ParticleSystemDef& def) {
    ParticleSystem system(def);
    const ParticleId bob = system.create_particle({.position = {length * std::sin(theta0), length * std::cos(theta0)}});
    system.add_gravity({0.0, g});
    system.create_anchor(bob, {0.0, 0.0}, length);
    return system;
}

ParticleSystem double_pendulum(double length1, double length2, double g, const ParticleSystemDef& def) {
    ParticleSystem system(def);
    const ParticleId a = system.create_particle({.position = {length1, 0.0}});
    const ParticleId b = system.create_particle({.position = {length1 + length2, 0.0}});
    system.add_gravity({0.0, g});
    system.create_anchor(a, {0.0, 0.0}, length1);
    system.create_distance(a, b, length2);
    return system;
}

ParticleSystemDef chain_def() { return {.integrator = Integrator::rattle, .substeps = {.automatic = true}}; }

ParticleSystem chain(std::size_t links, double link_length, double g, const ParticleSystemDef& def, double release_angle) {
    ParticleSystem system(def);
    // Exactly along +x for the horizontal release (cos(π/2) is 6e-17, not 0).
    const Vec2 direction = release_angle == pi / 2 ? Vec2{1.0, 0.0} : Vec2{std::sin(release_angle), std::cos(release_angle)};
    ParticleId previous = system.create_particle({.position = {0.0, 0.0}, .mass = std::numeric_limits<double>::infinity()});
    for (std::size_t k = 1; k <= links; ++k) {
        const ParticleId next = system.create_particle({.position = direction * (static_cast<double>(k) * link_length)});
        system.create_distance(previous, next, link_length);
        previous = next;
    }
    system.add_gravity({0.0, g});
    return system;
}

ParticleSystem cloth_strip(int columns, int rows, double spacing, double g, const ParticleSystemDef& def, double release_angle) {
    if (columns < 2 || rows < 2)
        throw Error("cloth_strip: columns and rows must be at least 2 (got " + std::to_string(columns) + " × " +
                    std::to_string(rows) + ")");
    ParticleSystem system(def);
    std::vector<ParticleId> ids;
    const double x0 = -0.5 * spacing * (columns - 1);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c)
            ids.push_back(system.create_particle({.position = {x0 + (c + r * std::sin(release_angle)) * spacing,
                                                            r * std::cos(release_angle) * spacing},
                                               .mass = r == 0 ? std::numeric_limits<double>::infinity() : 1.0}));
    auto at = [&](int c, int r) { return ids[static_cast<std::size_t>(r * columns + c)]; };
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            if (c + 1 < columns && r > 0) system.create_distance(at(c, r), at(c + 1, r), spacing);
            if (r + 1 < rows) system.create_distance(at(c, r), at(c, r + 1), spacing);
        }
    system.add_gravity({0.0, g});
    return system;
}

double chain_link_error(const ParticleSystem& chain, double link_length) noexcept {
    const auto x = chain.positions();
    double worst = 0.0;
    for (std::size_t k = 1; k < x.size(); ++k) worst = std::max(worst, std::abs(distance(x[k], x[k - 1]) - link_length));
    return worst;
}

}  // namespace grape::scenes
