// ParticleSystem: particles, force generators and constraints, each validated beside the
// record it adds; the step is in particle_step.cpp, the diagnostics in particle_diagnostics.cpp.
#include "particle_state.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace grape {

namespace {

using detail::ConstraintKind;
using detail::ConstraintRecord;
using detail::Generator;
using detail::GeneratorKind;
using detail::Gravity;
using detail::Grab;
using detail::Spring;
using detail::UserForce;
using detail::number_text;

void validate(const SubstepDef& substeps) {
    if (!(substeps.omega_h > 0.0) || !std::isfinite(substeps.omega_h))
        throw Error("SubstepDef: omega_h must be positive and finite (got " + number_text(substeps.omega_h) + ")");
    if (substeps.max < 1) throw Error("SubstepDef: max must be at least 1 (got " + std::to_string(substeps.max) + ")");
}

void validate(const DriftDef& d) {
    if (!(d.omega_dt > 0.0) || !std::isfinite(d.omega_dt))
        throw Error("DriftDef: omega_dt must be positive and finite (got " + number_text(d.omega_dt) + ")");
    if (d.stiffness && (!(*d.stiffness >= 0.0) || !std::isfinite(*d.stiffness)))
        throw Error("DriftDef: stiffness must be finite and ≥ 0 (got " + number_text(*d.stiffness) + ")");
    if (d.damping && (!(*d.damping >= 0.0) || !std::isfinite(*d.damping)))
        throw Error("DriftDef: damping must be finite and ≥ 0 (got " + number_text(*d.damping) + ")");
    if (d.projection_iterations < 1)
        throw Error("DriftDef: projection_iterations must be at least 1 (got " +
                    std::to_string(d.projection_iterations) + ")");
    if (!(d.projection_tolerance >= 0.0) || !std::isfinite(d.projection_tolerance))
        throw Error("DriftDef: projection_tolerance must be finite and ≥ 0 (got " + number_text(d.projection_tolerance) + ")");
}

}  // namespace

std::string_view to_string(DriftControl drift) noexcept {
    switch (drift) {
    case DriftControl::none: return "none";
    case DriftControl::baumgarte: return "baumgarte";
    case DriftControl::projection: return "projection";
    }
    return "unknown";
}

std::span<const DriftControl> all_drift_controls() noexcept {
    static constexpr DriftControl all[] = {DriftControl::none, DriftControl::baumgarte, DriftControl::projection};
    return all;
}

DriftControl parse_drift_control(std::string_view name) {
    for (DriftControl d : all_drift_controls())
        if (name == to_string(d)) return d;
    throw Error("drift control: unknown name '" + std::string(name) + "' (expected none, baumgarte or projection)");
}

std::string_view to_string(SolveStatus status) noexcept {
    switch (status) {
    case SolveStatus::ok: return "ok";
    case SolveStatus::singular: return "singular";
    case SolveStatus::not_converged: return "not_converged";
    case SolveStatus::substep_limit: return "substep_limit";
    case SolveStatus::non_finite: return "non_finite";
    }
    return "unknown";
}

ImplicitFunction::ImplicitFunction(std::function<ImplicitSample(Vec2)> evaluate) : evaluate_(std::move(evaluate)) {
    if (!evaluate_) throw Error("ImplicitFunction: evaluate must be a callable (got an empty function)");
}

ParticleSystem::ParticleSystem(ParticleSystemDef def) : state_(std::make_unique<detail::ParticleState>()) {
    state_->def = def;
    state_->stepper = Stepper(def.integrator, def.rk45);
    validate(def.drift);
    if (!(def.solver.cg_tolerance > 0.0) || !std::isfinite(def.solver.cg_tolerance))
        throw Error("SolverDef: cg_tolerance must be positive and finite (got " + number_text(def.solver.cg_tolerance) + ")");
    validate(def.substeps);
    if (def.solver.cg_max_iterations < 0)
        throw Error("SolverDef: cg_max_iterations must be ≥ 0 (got " + std::to_string(def.solver.cg_max_iterations) + ")");
}

ParticleSystem::~ParticleSystem() = default;

std::size_t ParticleSystem::size() const noexcept { return state_->positions.size(); }
std::span<const Vec2> ParticleSystem::positions() const noexcept { return state_->positions; }
std::span<const Vec2> ParticleSystem::velocities() const noexcept { return state_->velocities; }
std::span<const double> ParticleSystem::inverse_masses() const noexcept { return state_->inverse_masses; }
std::span<const Vec2> ParticleSystem::forces() const noexcept { return state_->solver.forces; }
std::span<const Vec2> ParticleSystem::constraint_forces() const noexcept { return state_->solver.constraint_forces; }
std::size_t ParticleSystem::constraint_count() const noexcept { return state_->constraints.size(); }
const ParticleSystemDef& ParticleSystem::def() const noexcept { return state_->def; }
double ParticleSystem::time() const noexcept { return state_->time; }
ParticleSystem::ParticleSystem(ParticleSystem&&) noexcept = default;
ParticleSystem& ParticleSystem::operator=(ParticleSystem&&) noexcept = default;

ParticleId ParticleSystem::create_particle(const ParticleDef& def) {
    if (!is_finite(def.position))
        throw Error("create_particle: position must be finite (got " + number_text(def.position.x) + ", " + number_text(def.position.y) + ")");
    if (!is_finite(def.velocity))
        throw Error("create_particle: velocity must be finite (got " + number_text(def.velocity.x) + ", " + number_text(def.velocity.y) + ")");
    if (!(def.mass > 0.0))
        throw Error("create_particle: mass must be positive, or infinity to pin (got " + number_text(def.mass) + ")");
    // A denormal mass has an infinite inverse: every acceleration would be inf or NaN.
    if (!std::isinf(def.mass) && !std::isfinite(1.0 / def.mass))
        throw Error("create_particle: mass must be at least " + number_text(1.0 / std::numeric_limits<double>::max()) +
                    " (its inverse overflows; got " + number_text(def.mass) + ")");
    const bool pinned = std::isinf(def.mass);
    state_->positions.push_back(def.position);
    state_->velocities.push_back(pinned ? Vec2{} : def.velocity);
    state_->inverse_masses.push_back(pinned ? 0.0 : 1.0 / def.mass);
    state_->solver.forces.push_back({});
    state_->exerted.push_back({});
    state_->solver.constraint_forces.push_back({});
    state_->solver.dirty = true;
    return {static_cast<std::uint32_t>(state_->positions.size() - 1)};
}

std::uint32_t ParticleSystem::checked(ParticleId id, std::string_view where) const {
    if (id.index >= state_->positions.size())
        throw Error(std::string(where) + ": particle " + std::to_string(id.index) + " does not exist (" +
                    std::to_string(state_->positions.size()) + " particles)");
    return id.index;
}

Vec2 ParticleSystem::position(ParticleId id) const { return state_->positions[checked(id, "position")]; }
Vec2 ParticleSystem::velocity(ParticleId id) const { return state_->velocities[checked(id, "velocity")]; }
double ParticleSystem::mass(ParticleId id) const {
    const double w = state_->inverse_masses[checked(id, "mass")];
    return w > 0.0 ? 1.0 / w : std::numeric_limits<double>::infinity();
}

void ParticleSystem::set_position(ParticleId id, Vec2 position) {
    const auto i = checked(id, "set_position");
    if (!is_finite(position)) throw Error("set_position: position must be finite");
    state_->positions[i] = position;
    state_->solver.factor_current = false;
}

void ParticleSystem::set_velocity(ParticleId id, Vec2 velocity) {
    const auto i = checked(id, "set_velocity");
    if (!is_finite(velocity)) throw Error("set_velocity: velocity must be finite");
    if (state_->inverse_masses[i] > 0.0) state_->velocities[i] = velocity;
}

void ParticleSystem::exert_force(ParticleId id, Vec2 force) {
    const auto i = checked(id, "exert_force");
    if (!is_finite(force)) throw Error("exert_force: force must be finite (got " + number_text(force.x) + ", " + number_text(force.y) + ")");
    state_->exerted[i] += force;
}

void ParticleSystem::add_gravity(Vec2 g) {
    if (!is_finite(g)) throw Error("add_gravity: g must be finite (got " + number_text(g.x) + ", " + number_text(g.y) + ")");
    state_->generators.push_back({GeneratorKind::gravity, static_cast<std::uint32_t>(state_->gravities.size())});
    state_->gravities.push_back({g});
}

void ParticleSystem::add_drag(double k) {
    if (!(k >= 0.0) || !std::isfinite(k)) throw Error("add_drag: k must be finite and ≥ 0 (got " + number_text(k) + ")");
    state_->generators.push_back({GeneratorKind::drag, static_cast<std::uint32_t>(state_->drags.size())});
    state_->drags.push_back({k});
}

void ParticleSystem::add_spring(ParticleId a, ParticleId b, const SpringDef& def) {
    const auto ia = checked(a, "add_spring"), ib = checked(b, "add_spring");
    if (ia == ib) throw Error("add_spring: a and b must be different particles (both " + std::to_string(ia) + ")");
    if (!(def.rest_length >= 0.0) || !std::isfinite(def.rest_length))
        throw Error("add_spring: rest_length must be finite and ≥ 0 (got " + number_text(def.rest_length) + ")");
    if (!(def.stiffness >= 0.0) || !std::isfinite(def.stiffness))
        throw Error("add_spring: stiffness must be finite and ≥ 0 (got " + number_text(def.stiffness) + ")");
    if (!(def.damping >= 0.0) || !std::isfinite(def.damping))
        throw Error("add_spring: damping must be finite and ≥ 0 (got " + number_text(def.damping) + ")");
    state_->generators.push_back({GeneratorKind::spring, static_cast<std::uint32_t>(state_->springs.size())});
    state_->springs.push_back({ia, ib, def});
}

void ParticleSystem::add_force(ForceFunction force, PotentialFunction potential) {
    if (!force) throw Error("add_force: force must be a callable (got an empty function)");
    state_->generators.push_back({GeneratorKind::user, static_cast<std::uint32_t>(state_->user_forces.size())});
    state_->user_forces.push_back({std::move(force), std::move(potential)});
}

namespace {
ConstraintId push_constraint(detail::ParticleState& state, const detail::ConstraintRecord& record) {
    state.constraints.push_back(record);
    state.solver.dirty = true;
    return {static_cast<std::uint32_t>(state.constraints.size() - 1)};
}
}  // namespace

ConstraintId ParticleSystem::create_distance(ParticleId a, ParticleId b, double length) {
    const auto ia = checked(a, "create_distance"), ib = checked(b, "create_distance");
    if (ia == ib) throw Error("create_distance: a and b must be different particles (both " + std::to_string(ia) + ")");
    if (!(length > 0.0) || !std::isfinite(length))
        throw Error("create_distance: length must be positive and finite (got " + number_text(length) + ")");
    if (state_->positions[ia] == state_->positions[ib])
        throw Error("create_distance: particles " + std::to_string(ia) + " and " + std::to_string(ib) +
                    " are at the same point, where the rod has no direction; start them apart");
    return push_constraint(*state_, {ConstraintKind::distance, ia, ib, {}, length, 0});
}

ConstraintId ParticleSystem::create_distance(ParticleId a, ParticleId b) {
    const auto ia = checked(a, "create_distance"), ib = checked(b, "create_distance");
    return create_distance(a, b, distance(state_->positions[ia], state_->positions[ib]));
}

ConstraintId ParticleSystem::create_anchor(ParticleId a, Vec2 anchor, double length) {
    const auto ia = checked(a, "create_anchor");
    if (!is_finite(anchor)) throw Error("create_anchor: anchor must be finite (got " + number_text(anchor.x) + ", " + number_text(anchor.y) + ")");
    if (!(length > 0.0) || !std::isfinite(length))
        throw Error("create_anchor: length must be positive and finite (got " + number_text(length) + ")");
    if (state_->positions[ia] == anchor)
        throw Error("create_anchor: particle " + std::to_string(ia) +
                    " sits at the anchor, where the rod has no direction; start it at a distance");
    return push_constraint(*state_, {ConstraintKind::anchor, ia, 0, anchor, length, 0});
}

ConstraintId ParticleSystem::create_fixed_point(ParticleId a, Vec2 point) {
    const auto ia = checked(a, "create_fixed_point");
    if (!is_finite(point)) throw Error("create_fixed_point: point must be finite (got " + number_text(point.x) + ", " + number_text(point.y) + ")");
    return push_constraint(*state_, {ConstraintKind::fixed_point, ia, 0, point, 0.0, 0});
}

ConstraintId ParticleSystem::create_implicit(ParticleId a, ImplicitFunction curve) {
    const auto ia = checked(a, "create_implicit");
    const ImplicitSample at = curve(state_->positions[ia]);
    if (at.gradient == Vec2{} && at.value != 0.0)
        throw Error("create_implicit: the curve's gradient is zero at particle " + std::to_string(ia) +
                    " (C = " + number_text(at.value) + ", as at the center of a circle), so its force has no direction; "
                    "start the particle elsewhere");
    state_->curves.push_back(std::move(curve));
    return push_constraint(*state_, {ConstraintKind::curve, ia, 0, {}, 0.0, static_cast<std::uint32_t>(state_->curves.size() - 1)});
}

ConstraintId ParticleSystem::create_constraint(UserConstraint constraint) {
    if (constraint.particles.empty()) throw Error("create_constraint: particles must not be empty");
    for (ParticleId p : constraint.particles) checked(p, "create_constraint");
    if (!constraint.evaluate) throw Error("create_constraint: evaluate must be a callable (got an empty function)");
    state_->users.push_back(std::move(constraint));
    return push_constraint(*state_, {ConstraintKind::user, 0, 0, {}, 0.0, static_cast<std::uint32_t>(state_->users.size() - 1)});
}

void ParticleSystem::set_drift(const DriftDef& drift) {
    validate(drift);
    state_->def.drift = drift;
}

void ParticleSystem::set_substeps(const SubstepDef& substeps) {
    validate(substeps);
    state_->def.substeps = substeps;
}

void ParticleSystem::set_integrator(Integrator integrator) {
    state_->def.integrator = integrator;
    state_->stepper = Stepper(integrator, state_->def.rk45);
}

void ParticleSystem::set_rk45(const Rk45Def& rk45) {
    state_->stepper = Stepper(state_->def.integrator, rk45);  // validates
    state_->def.rk45 = rk45;
}

void detail::ParticleState::apply_forces(double t, std::span<const Vec2> x, std::span<const Vec2> v,
                                        std::span<Vec2> out) const noexcept {
    std::copy(exerted.begin(), exerted.end(), out.begin());
    for (const Generator& g : generators) {
        switch (g.kind) {
        case GeneratorKind::gravity: {
            const Vec2 acc = gravities[g.index].g;
            for (std::size_t p = 0; p < out.size(); ++p)
                if (inverse_masses[p] > 0.0) out[p] += acc / inverse_masses[p];
            break;
        }
        case GeneratorKind::drag: {
            const double k = drags[g.index].k;
            for (std::size_t p = 0; p < out.size(); ++p) out[p] -= k * v[p];
            break;
        }
        case GeneratorKind::spring: {
            const Spring& s = springs[g.index];
            const Vec2 d = x[s.b] - x[s.a];
            const double len = length(d);
            if (len > 0.0) {
                const Vec2 n = d / len;
                const double f = s.def.stiffness * (len - s.def.rest_length) + s.def.damping * dot(v[s.b] - v[s.a], n);
                out[s.a] += f * n;
                out[s.b] -= f * n;
            }
            break;
        }
        case GeneratorKind::user:
            user_forces[g.index].force(ForceContext{t, x, v, inverse_masses, out});
            break;
        }
    }
    if (grab) {
        const Grab& g = *grab;
        Vec2 force = g.k * (g.target - x[g.particle]) - g.c * v[g.particle];
        const double size = length(force);
        if (size > g.max_force) force = force * (g.max_force / size);
        out[g.particle] += force;
    }
}

detail::SystemView detail::ParticleState::view() const noexcept {
    return {.particles = positions.size(),
            .positions = positions,
            .inverse_masses = inverse_masses,
            .constraints = constraints,
            .curves = curves,
            .users = users,
            .springs = springs,
            .grab = grab ? &*grab : nullptr,
            .solver = &def.solver,
            .drift = &def.drift,
            .apply_forces = [](const void* system, double t, std::span<const Vec2> x, std::span<const Vec2> v,
                               std::span<Vec2> out) noexcept {
                static_cast<const ParticleState*>(system)->apply_forces(t, x, v, out);
            },
            .system = this};
}

}  // namespace grape
