// The grab spring: a mouse's hand on one particle, tuned by frequency and damping ratio.
#include "particle_state.hpp"

#include <cmath>
#include <string>

namespace grape {

namespace {
using detail::number_text;
constexpr double two_pi = 6.283185307179586476925286766559;
}  // namespace

void ParticleSystem::grab(ParticleId id, Vec2 target, const GrabDef& def) {
    const auto i = checked(id, "grab");
    if (!(state_->inverse_masses[i] > 0.0)) throw Error("grab: particle " + std::to_string(i) + " is pinned and cannot be moved");
    if (!std::isfinite(target.x) || !std::isfinite(target.y))
        throw Error("grab: target must be finite (got " + number_text(target.x) + ", " + number_text(target.y) + ")");
    if (!(def.hertz > 0.0) || !std::isfinite(def.hertz))
        throw Error("GrabDef: hertz must be positive and finite (got " + number_text(def.hertz) + ")");
    if (!(def.damping_ratio >= 0.0) || !std::isfinite(def.damping_ratio))
        throw Error("GrabDef: damping_ratio must be finite and ≥ 0 (got " + number_text(def.damping_ratio) + ")");
    if (!(def.mass >= 0.0) || !std::isfinite(def.mass))
        throw Error("GrabDef: mass must be finite and ≥ 0 (0: the particle's own; got " + number_text(def.mass) + ")");
    if (!(def.max_force > 0.0))
        throw Error("GrabDef: max_force must be positive (got " + number_text(def.max_force) + ")");
    const double own = 1.0 / state_->inverse_masses[i];
    const double m = def.mass > 0.0 ? def.mass : own;
    const double omega = two_pi * def.hertz;
    const double k = m * omega * omega;
    state_->grab = detail::Grab{i, target, k, 2.0 * def.damping_ratio * std::sqrt(k * own), def.max_force};
}

void ParticleSystem::move_grab(Vec2 target) {
    if (!std::isfinite(target.x) || !std::isfinite(target.y))
        throw Error("move_grab: target must be finite (got " + number_text(target.x) + ", " + number_text(target.y) + ")");
    if (state_->grab) state_->grab->target = target;
}

void ParticleSystem::release_grab() noexcept { state_->grab.reset(); }

std::optional<ParticleId> ParticleSystem::grabbed() const noexcept {
    if (!state_->grab) return std::nullopt;
    return ParticleId{state_->grab->particle};
}

std::optional<ParticleId> ParticleSystem::nearest_particle(Vec2 point, double radius) const noexcept {
    std::optional<ParticleId> best;
    double best_distance = radius;
    for (std::size_t i = 0; i < state_->positions.size(); ++i) {
        const double d = distance(state_->positions[i], point);
        if (state_->inverse_masses[i] > 0.0 && d <= best_distance) {
            best_distance = d;
            best = ParticleId{static_cast<std::uint32_t>(i)};
        }
    }
    return best;
}

}  // namespace grape
