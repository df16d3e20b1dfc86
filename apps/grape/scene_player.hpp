// The scene as `grape render` plays it: every animation where its own timing, or the timeline
// driving it, puts it at the scene time; simulations stepped forward to that time.
#pragma once

#include <grape/math.hpp>
#include <grape/scene.hpp>

#if GRAPE_HAS_DYNAMICS
#include <grape/dynamics.hpp>
#endif

#include <cstddef>
#include <vector>

namespace grape::tool {

/// rk45's sub-steps per step of a scene's simulation at most (its dt is a frame-like step:
/// needing more means a dt far too long for the tolerance, or a stiff system).
constexpr int scene_rk45_substeps = 100;

/// The scene time up to which the world box runs every simulation: t_end, or each
/// simulation's whole run up to 20000 steps when that is longer.
double bounds_horizon(const Scene& scene, double t_end);

/// The integration work of playing a scene up to t_end (the world box's run and the frames'),
/// counted before running it: force evaluations a step at most (rk45: every sub-step up to
/// scene_rk45_substeps; projection: its Newton iterations) × particles and constraints.
struct SimulationWork {
    double steps = 0.0;                 ///< integration steps of dt, both runs
    double evaluations_per_step = 0.0;  ///< force and constraint evaluations a step at most
    double size = 0.0;                  ///< particles + constraints
    double work = 0.0;                  ///< steps × evaluations_per_step × size
    double trail_bytes = 0.0;           ///< the world box run's record of every position
};
SimulationWork simulation_work(const Scene& scene, std::size_t i, double t_end);

class ScenePlayer {
public:
    /// Checks the scene's timelines (grape::Error naming the JSON pointer). With
    /// RECORD_TRAILS every particle position after every step is kept (for the picture's
    /// bounds); without it memory stays at the particles' current state.
    explicit ScenePlayer(const Scene& scene, bool record_trails = false);

    /// Moves to scene time t: animations to any time, simulations only forwards (each capped
    /// at its duration; without the dynamics module they stay at rest). Throws grape::Error
    /// naming the simulation when a step leaves the finite range or rk45 reaches
    /// scene_rk45_substeps: what follows could not be trusted.
    void advance_to(double t);
    /// The scene time of the last advance_to (0 at first).
    double time() const noexcept { return time_; }

    /// Where each animation and timeline lies in time.
    const SceneTiming& timing() const noexcept { return timing_; }
    /// Where animation i stands now.
    Vec2 animation_position(std::size_t i) const noexcept;
    /// The particles of simulation i now.
    std::vector<Vec2> particle_positions(std::size_t i) const;
    /// 1/mass of each particle of simulation i (0 for pinned ones).
    std::vector<double> inverse_masses(std::size_t i) const;
    /// Per simulation, every particle's position after every step (with RECORD_TRAILS).
    const std::vector<std::vector<Vec2>>& trails() const noexcept { return trails_; }

private:
    void record(std::size_t i);

    const Scene& scene_;
    SceneTiming timing_;
    bool record_trails_;
    double time_ = 0.0;
#if GRAPE_HAS_DYNAMICS
    std::vector<ParticleSystem> systems_;
#endif
    std::vector<std::vector<Vec2>> trails_;
};

}  // namespace grape::tool
