// ParticleSystem diagnostics at the current state: energies and constraint residuals.
#include "particle_state.hpp"

#include <algorithm>
#include <cmath>

namespace grape {

using detail::evaluated_rows;
using detail::Gravity;
using detail::Spring;
using detail::UserForce;

double ParticleSystem::kinetic_energy() const noexcept {
    double e = 0.0;
    for (std::size_t p = 0; p < state_->positions.size(); ++p)
        if (state_->inverse_masses[p] > 0.0) e += 0.5 * length_squared(state_->velocities[p]) / state_->inverse_masses[p];
    return e;
}

double ParticleSystem::potential_energy() const {
    double e = 0.0;
    for (const Gravity& g : state_->gravities)
        for (std::size_t p = 0; p < state_->positions.size(); ++p)
            if (state_->inverse_masses[p] > 0.0) e -= dot(g.g, state_->positions[p]) / state_->inverse_masses[p];
    for (const Spring& s : state_->springs) {
        const double stretch = distance(state_->positions[s.a], state_->positions[s.b]) - s.def.rest_length;
        e += 0.5 * s.def.stiffness * stretch * stretch;
    }
    for (const UserForce& u : state_->user_forces)
        if (u.potential) e += u.potential(state_->positions);
    if (state_->grab) e += 0.5 * state_->grab->k * length_squared(state_->grab->target - state_->positions[state_->grab->particle]);
    return e;
}

std::vector<ConstraintResidual> ParticleSystem::residuals() const {
    auto& s = evaluated_rows(*state_);
    std::vector<ConstraintResidual> out(state_->constraints.size());
    for (std::uint32_t r = 0; r < s.rows; ++r) {
        auto& o = out[s.row_constraint[r]];
        const double value = std::abs(s.c[r]);
        const double g = std::sqrt(s.gradient_norm2[r]);
        const double d = g > 0.0 ? value / g : (value == 0.0 ? 0.0 : std::numeric_limits<double>::infinity());
        o.value = std::max(o.value, value);
        o.rate = std::max(o.rate, std::abs(s.c_dot[r]));
        o.distance = std::max(o.distance, d);
    }
    return out;
}

std::vector<ConstraintRow> ParticleSystem::constraint_rows() const {
    auto& s = evaluated_rows(*state_);
    std::vector<ConstraintRow> out(s.rows);
    for (std::uint32_t r = 0; r < s.rows; ++r)
        out[r] = {{s.row_constraint[r]}, s.c[r], s.c_dot[r], s.jdot_v[r], std::sqrt(s.gradient_norm2[r])};
    return out;
}

ConstraintResidual ParticleSystem::max_residual() const {
    ConstraintResidual worst;
    for (const auto& r : residuals()) {
        worst.value = std::max(worst.value, r.value);
        worst.rate = std::max(worst.rate, r.rate);
        worst.distance = std::max(worst.distance, r.distance);
    }
    return worst;
}


}  // namespace grape
