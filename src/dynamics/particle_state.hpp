// What a ParticleSystem holds behind its pointer: settings, the state arrays, the records of
// force generators and constraints, the integrator and the constraint solver.
#pragma once

#include "witkin.hpp"

#include <optional>
#include <vector>

namespace grape::detail {

struct ParticleState {
    ParticleSystemDef def{};
    double time = 0.0;
    std::vector<Vec2> positions, velocities, exerted;
    std::vector<Vec2> saved_positions, saved_velocities;  // before a projection (storage kept: no allocation per step)
    std::vector<double> inverse_masses;
    std::vector<Generator> generators;
    std::vector<Gravity> gravities;
    std::vector<Drag> drags;
    std::vector<Spring> springs;
    std::vector<UserForce> user_forces;
    std::optional<Grab> grab;
    std::vector<ConstraintRecord> constraints;
    std::vector<ImplicitFunction> curves;
    std::vector<UserConstraint> users;
    Stepper stepper{};
    SolverWorkspace solver{};

    // The solver's view of this state (valid until particles or constraints are added).
    SystemView view() const noexcept;
    // Exerted forces, then the generators in order, then the grab spring, at (t, x, v).
    void apply_forces(double t, std::span<const Vec2> x, std::span<const Vec2> v, std::span<Vec2> out) const noexcept;
};

// The solver workspace (scratch, not the state) with C, Ċ, J̇v and |∇C|² evaluated at the
// current state.
inline SolverWorkspace& evaluated_rows(ParticleState& state) {
    auto& s = state.solver;
    s.look_at(state.view());
    s.evaluate_rows(state.positions, state.velocities);
    return s;
}

// The integrators see positions and velocities as 2n doubles.
static_assert(sizeof(Vec2) == 2 * sizeof(double), "positions are viewed as 2n doubles");

}  // namespace grape::detail
