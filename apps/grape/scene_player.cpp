#include "scene_player.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace grape::tool {

namespace {

[[maybe_unused]] std::string simulation_name(const Scene& scene, std::size_t i) {
    const std::string& name = scene.simulations[i].name;
    const std::string pointer = "/simulations/" + std::to_string(i);
    return name.empty() ? "simulation " + pointer : "simulation '" + name + "' (" + pointer + ")";
}

}  // namespace

double bounds_horizon(const Scene& scene, double t_end) {
    double horizon = t_end;
    for (const SceneSimulation& s : scene.simulations) horizon = std::max(horizon, std::min(s.duration, 20000.0 * s.dt));
    return horizon;
}

SimulationWork simulation_work(const Scene& scene, std::size_t i, double t_end) {
    const SceneSimulation& s = scene.simulations[i];
    // Projection and RATTLE: DriftDef's default of 8 Newton iterations, and one velocity solve.
    constexpr double projection = 8.0 + 1.0;
    double per_step = 4.0;
    if (s.integrator == "euler" || s.integrator == "semi_implicit_euler") per_step = 1.0;
    else if (s.integrator == "midpoint" || s.integrator == "velocity_verlet") per_step = 2.0;
    else if (s.integrator == "rk45") per_step = 6.0 * scene_rk45_substeps + 1.0;  // first same as last
    else if (s.integrator == "rattle") per_step = 1.0 + projection;
    if (s.drift == "projection" && s.integrator != "rattle") per_step += projection;
    SimulationWork w;
    const double bounds_steps = std::ceil(std::min(bounds_horizon(scene, t_end), s.duration) / s.dt);
    const double frame_steps = std::ceil(std::min(t_end, s.duration) / s.dt);
    w.steps = bounds_steps + frame_steps;
    w.evaluations_per_step = per_step;
    w.size = static_cast<double>(s.particles.size() + s.constraints.size());
    w.work = w.steps * w.evaluations_per_step * w.size;
    w.trail_bytes = (bounds_steps + 1.0) * static_cast<double>(s.particles.size()) * sizeof(Vec2);
    return w;
}

ScenePlayer::ScenePlayer(const Scene& scene, bool record_trails)
    : scene_(scene), timing_(scene), record_trails_(record_trails) {
#if GRAPE_HAS_DYNAMICS
    for (const SceneSimulation& s : scene.simulations) {
        systems_.push_back(make_particle_system(s));
        if (s.integrator == "rk45") systems_.back().set_rk45({.max_substeps = scene_rk45_substeps});
    }
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
            const double at = systems_[i].time();
            const SolveStatus status = systems_[i].step(s.dt).status;
            if (status == SolveStatus::non_finite)
                throw Error(simulation_name(scene_, i) + ": the step at t = " + detail::number_text(at) +
                            " s leaves the finite range (try a smaller dt, or smaller forces and speeds)");
            if (status == SolveStatus::substep_limit)
                throw Error(simulation_name(scene_, i) + ": rk45 needs more than " + std::to_string(scene_rk45_substeps) +
                            " sub-steps for the step at t = " + detail::number_text(at) + " s (dt = " + detail::number_text(s.dt) +
                            " s is too long for its tolerance, or the system is stiff; try a smaller dt)");
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
