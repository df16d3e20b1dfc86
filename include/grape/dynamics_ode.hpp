// grape — dynamics: integrators of second-order systems q̈ = a(t, q, q̇) behind one
// interface (SecondOrderSystem + Stepper), usable for any model of your own, not only
// particles. Included by <grape/dynamics.hpp>.
#pragma once

#include <grape/error.hpp>
#include <grape/export_dynamics.hpp>

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace grape {

/// \addtogroup dynamics
/// @{

// ---------------------------------------------------------------------------------------
// Integrators: one interface, state (q, q̇) and derivative (q̇, q̈)
// ---------------------------------------------------------------------------------------

/// The numerical integrators. Constraint forces are recomputed at every stage of each.
/// With velocity-dependent accelerations (every curved constraint has one) semi-implicit
/// Euler and velocity Verlet are not symplectic: do not expect bounded energy from them.
enum class Integrator {
    euler,                ///< explicit Euler, order 1, 1 evaluation
    semi_implicit_euler,  ///< v += a·dt then q += v·dt, order 1, 1 evaluation
    midpoint,             ///< explicit midpoint, order 2, 2 evaluations
    rk4,                  ///< classical Runge–Kutta, order 4, 4 evaluations
    velocity_verlet,      ///< Verlet with a predicted velocity for a(q, v), order 2, 2 evaluations
    rk45,                 ///< Dormand–Prince 5(4), adaptive sub-steps with error control
    /// RATTLE (ParticleSystem): velocity Verlet whose positions are held on C = 0 (Newton,
    /// along the constraint gradients at the step's start) and velocities on Ċ = 0 at the
    /// end of every step. Symplectic and time-reversible with velocity-independent forces,
    /// order 2, one force evaluation and one factorization of J W Jᵀ per step (reused by
    /// the next step); DriftDef's method does not apply. A Stepper or Bead (no
    /// constraints) runs it as velocity_verlet.
    rattle,
};

/// The integrator's name in snake_case ("velocity_verlet").
GRAPE_DYNAMICS_API std::string_view to_string(Integrator integrator) noexcept;
/// The integrator named `name` (as to_string gives it, or the short forms "symplectic" and
/// "verlet"); throws grape::Error naming the unknown value.
GRAPE_DYNAMICS_API Integrator parse_integrator(std::string_view name);
/// Every integrator, in declaration order (for menus and name lists).
GRAPE_DYNAMICS_API std::span<const Integrator> all_integrators() noexcept;
/// The formal order of accuracy (rk45: 5 at a fixed step).
GRAPE_DYNAMICS_API int order(Integrator integrator) noexcept;

/// Settings of the adaptive Dormand–Prince integrator.
struct Rk45Def {
    double tolerance = 1e-10;  ///< per sub-step error bound, relative and absolute (0: no control, fixed step)
    double min_step = 1e-12;   ///< seconds; below it a sub-step is accepted anyway (and counted)
    /// Sub-steps (accepted and rejected) per step() at most, a guard against stiffness and
    /// against a dt far beyond the tolerance: when reached, the rest of the step is taken in
    /// one sub-step without error control and the step says so (StepStats::status is substep_limit).
    int max_substeps = 100000;
};

/// A system q̈ = a(t, q, q̇) of n coordinates: the only view integrators have of a model.
class SecondOrderSystem {
public:
    virtual ~SecondOrderSystem() = default;
    /// Number of coordinates n.
    virtual std::size_t size() const noexcept = 0;
    /// Writes q̈ (n values) for time t, coordinates q and velocities v (n each).
    virtual void acceleration(double t, std::span<const double> q, std::span<const double> v,
                              std::span<double> a) noexcept = 0;
};

/// How a step went, from best to worst: a step reports the worst over its sub-steps and solves.
enum class SolveStatus {
    ok,             ///< the step succeeded (and every J W Jᵀ was regular)
    /// redundant or degenerate constraints: a least-squares/CG solution was used, or a row
    /// could not be trusted at the current positions (see ParticleSystem::step)
    singular,
    not_converged,  ///< conjugate gradient stopped at its iteration limit
    /// rk45 reached Rk45Def::max_substeps within the step: the rest of dt was taken without
    /// error control (a dt far too long for the tolerance, or a stiff system)
    substep_limit,
    non_finite,     ///< the state left the finite range: the step was not taken (state and time unchanged)
};

/// The status name ("ok", "singular", "not_converged", "substep_limit", "non_finite").
GRAPE_DYNAMICS_API std::string_view to_string(SolveStatus status) noexcept;

/// What one step did: Stepper::step, Bead::step and ParticleSystem::step all report it.
struct StepStats {
    /// The worst outcome over the step. Stepper and Bead give ok, substep_limit (rk45 reached
    /// Rk45Def::max_substeps: the rest of the step was one sub-step without error control, not
    /// to be trusted) or non_finite (the state or rk45's error estimate left the finite range:
    /// the step stopped there, at once, and q, v are as before); a ParticleSystem's solves
    /// add singular and not_converged.
    SolveStatus status = SolveStatus::ok;
    int evaluations = 0;  ///< calls of acceleration() (a ParticleSystem: constraint solves)
    int substeps = 0;     ///< accepted sub-steps (1 for fixed-step integrators)
    int rejected = 0;     ///< rk45 sub-steps rejected by error control
    int forced = 0;       ///< rk45 sub-steps accepted at min_step despite the error
    int projection_iterations = 0;  ///< ParticleSystem: Newton iterations of the position projection
    int cg_iterations = 0;          ///< ParticleSystem: conjugate-gradient iterations, summed
};

/// The worse of two outcomes (SolveStatus is ordered from best to worst).
constexpr SolveStatus worse(SolveStatus a, SolveStatus b) noexcept {
    return static_cast<int>(a) >= static_cast<int>(b) ? a : b;
}

/// Advances any SecondOrderSystem by one step of the chosen integrator. Holds its scratch
/// buffers (allocated when the system size first grows), so steps do not allocate.
class GRAPE_DYNAMICS_API Stepper {
public:
    /// Throws grape::Error if rk45's tolerance is negative or not finite, its min_step is not
    /// positive and finite, or its max_substeps is below 1.
    explicit Stepper(Integrator integrator = Integrator::rk4, Rk45Def rk45 = {});
    /// Advances (q, v) from t to t + dt in place. rk45 takes as many sub-steps as its
    /// tolerance needs and remembers its last step size. dt must be positive.
    StepStats step(SecondOrderSystem& system, double t, std::span<double> q, std::span<double> v, double dt);
    Integrator integrator() const noexcept { return integrator_; }  ///< the integrator it steps with
    const Rk45Def& rk45() const noexcept { return rk45_; }  ///< rk45's settings

private:
    Integrator integrator_{};
    Rk45Def rk45_{};
    double rk45_step_ = 0.0;  // last accepted rk45 step, 0 before the first
    std::vector<double> buffer_{};
};

/// @}

}  // namespace grape
