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

class ScenePlayer {
public:
    /// Checks the scene's timelines (grape::Error naming the JSON pointer). With
    /// RECORD_TRAILS every particle position after every step is kept (for the picture's
    /// bounds); without it memory stays at the particles' current state.
    explicit ScenePlayer(const Scene& scene, bool record_trails = false);

    /// Moves to scene time t: animations to any time, simulations only forwards (each capped
    /// at its duration; without the dynamics module they stay at rest).
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
