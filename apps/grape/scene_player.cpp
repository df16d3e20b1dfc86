#include "scene_player.hpp"

#include <algorithm>
#include <cmath>

namespace grape::tool {

ScenePlayer::ScenePlayer(const Scene& scene, bool record_trails)
    : scene_(scene), timing_(scene), record_trails_(record_trails) {
#if GRAPE_HAS_DYNAMICS
    for (const SceneSimulation& s : scene.simulations) systems_.push_back(make_particle_system(s));
#endif
    trails_.resize(scene.simulations.size());
    for (std::size_t i = 0; i < scene.simulations.size(); ++i) record(i);
}

void ScenePlayer::advance_to(double t) {
    time_ = t;
#if GRAPE_HAS_DYNAMICS
    for (std::size_t i = 0; i < systems_.size(); ++i) {
        const SceneSimulation& s = scene_.simulations[i];
        const double target = std::min(t, s.duration);
        // Whole steps of dt; the half-step slack keeps rounding from adding one more.
        while (systems_[i].time() + 0.5 * s.dt < target) {
            systems_[i].step(s.dt);
            record(i);
        }
    }
#endif
}

Vec2 ScenePlayer::animation_position(std::size_t i) const noexcept {
    return scene_.animations[i].position_at(timing_.progress(i, time_));
}

std::vector<Vec2> ScenePlayer::particle_positions(std::size_t i) const {
#if GRAPE_HAS_DYNAMICS
    const auto p = systems_[i].positions();
    return {p.begin(), p.end()};
#else
    std::vector<Vec2> out;
    for (const SceneParticle& p : scene_.simulations[i].particles) out.push_back(p.position);
    return out;
#endif
}

std::vector<double> ScenePlayer::inverse_masses(std::size_t i) const {
    std::vector<double> out;
    for (const SceneParticle& p : scene_.simulations[i].particles) out.push_back(std::isinf(p.mass) ? 0.0 : 1.0 / p.mass);
    return out;
}

void ScenePlayer::record(std::size_t i) {
    if (!record_trails_) return;
    const auto p = particle_positions(i);
    trails_[i].insert(trails_[i].end(), p.begin(), p.end());
}

}  // namespace grape::tool
