// grape — dynamics: the particle system: particles, force generators, Witkin constraints,
// drift control, the grab spring and sub-steps. Included by <grape/dynamics.hpp>, whose
// comment gives the overview and an example.
#pragma once

#include <grape/dynamics_implicit.hpp>
#include <grape/dynamics_ode.hpp>
#include <grape/error.hpp>
#include <grape/export_dynamics.hpp>
#include <grape/math.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace grape {

/// \addtogroup dynamics
/// @{

// ---------------------------------------------------------------------------------------
// The particle system
// ---------------------------------------------------------------------------------------

/// A particle's handle: its index in creation order (particles are never removed).
struct ParticleId {
    std::uint32_t index = 0;  ///< creation order, from 0
    friend constexpr bool operator==(ParticleId, ParticleId) noexcept = default;  ///< the same particle
};

/// A constraint's handle: its index in creation order (constraints are never removed).
struct ConstraintId {
    std::uint32_t index = 0;  ///< creation order, from 0
    friend constexpr bool operator==(ConstraintId, ConstraintId) noexcept = default;  ///< the same constraint
};

/// A new particle.
struct ParticleDef {
    Vec2 position{};     ///< world units
    Vec2 velocity{};     ///< world units per second
    double mass = 1.0;   ///< positive; +infinity pins the particle (inverse mass 0)
};

/// A damped spring between two particles: F = −(k·(|d| − L) + c·(ḋ·d̂))·d̂ on b, opposite on a.
struct SpringDef {
    double rest_length = 0.0;  ///< L, world units, ≥ 0
    double stiffness = 0.0;    ///< k, force per unit stretch, ≥ 0
    double damping = 0.0;      ///< c, force per unit stretching speed, ≥ 0
};

/// How constraint drift is held in check.
enum class DriftControl {
    none,        ///< only C̈ = 0 is enforced: C drifts with the truncation error
    baumgarte,   ///< feedback −ks·C − kd·Ċ in the solve (Witkin's spring and damper)
    projection,  ///< after each step, Newton projection of positions onto C = 0, then of velocities onto Ċ = 0
};

/// The drift-control name ("none", "baumgarte", "projection").
GRAPE_DYNAMICS_API std::string_view to_string(DriftControl drift) noexcept;
/// The drift control named `name`; throws grape::Error naming the unknown value.
GRAPE_DYNAMICS_API DriftControl parse_drift_control(std::string_view name);
/// Every drift control, in declaration order (for menus and name lists).
GRAPE_DYNAMICS_API std::span<const DriftControl> all_drift_controls() noexcept;

/// Drift-control settings.
struct DriftDef {
    DriftControl method = DriftControl::baumgarte;  ///< see DriftControl
    /// Baumgarte gains from the step: ω = omega_dt/dt, ks = ω², kd = 2ω (critical damping).
    /// Whatever the settings, a step uses ks ≤ 1/(4dt²) and kd ≤ 1/dt (the gains of
    /// omega_dt = ½): stronger feedback overshoots the violation within one step.
    double omega_dt = 0.05;
    std::optional<double> stiffness{};  ///< ks in 1/s², overrides omega_dt (kd then defaults to 2√ks)
    std::optional<double> damping{};    ///< kd in 1/s, overrides the default
    int projection_iterations = 8;       ///< Newton iterations at most per projection
    /// Stop when every |C|/|∇C| ≤ this, world units (0: at round-off, 8ε·(1 + max |x|)).
    double projection_tolerance = 0.0;
};

/// The linear solver for J W Jᵀ λ = b.
enum class LinearSolver {
    automatic,           ///< Cholesky in envelope storage when small or banded (chains), else sparse_direct
    dense,               ///< dense Cholesky; minimum-norm least squares when rows are redundant
    sparse_direct,       ///< Eigen simplicial LDLT (fill-reducing order); conjugate gradient when singular
    conjugate_gradient,  ///< Eigen conjugate gradient on the sparse J W Jᵀ, warm-started
};

/// Linear-solver settings.
struct SolverDef {
    LinearSolver method = LinearSolver::automatic;  ///< see LinearSolver
    std::size_t dense_limit = 48;  ///< rows up to which `automatic` always uses the envelope Cholesky
    double cg_tolerance = 1e-13;   ///< conjugate gradient: relative residual |r|/|b|
    int cg_max_iterations = 0;     ///< conjugate gradient: 0 means 4 × rows
};

/// How step(dt) divides dt into sub-steps.
struct SubstepDef {
    /// False: one integrator step per step(dt). True: equal sub-steps, re-chosen after each,
    /// so that ω·h ≤ omega_h, where ω bounds the stiffest mode from the latest constraint
    /// forces (tension of distance and anchor rods, by Gershgorin: ω² ≤ max over particles
    /// of w·Σ 2|λ| over its rods) and spring stiffnesses.
    bool automatic = false;
    /// rad per sub-step, > 0: velocity Verlet and RATTLE are stable up to ω·h = 2, RK4 up to 2.8,
    /// and the bound ω is at or above the true one, so 1 leaves a factor of 2 at least.
    double omega_h = 1.0;
    int max = 64;          ///< sub-steps per step() at most, ≥ 1
};

/// A particle system's settings, for designated initializers.
struct ParticleSystemDef {
    Integrator integrator = Integrator::rk4;  ///< see Integrator
    DriftDef drift{};                           ///< see DriftDef
    SolverDef solver{};                         ///< see SolverDef
    Rk45Def rk45{};                             ///< used when integrator is rk45
    SubstepDef substeps{};                      ///< see SubstepDef
};



/// Residuals of one constraint (for a two-row constraint, the larger row).
struct ConstraintResidual {
    double value = 0.0;     ///< |C|, in the constraint's units
    double rate = 0.0;      ///< |Ċ|
    double distance = 0.0;  ///< |C|/|∇C|, in world units: how far the particles are off
};

/// One scalar row of the constraint system at the current state (a fixed point has two).
struct ConstraintRow {
    ConstraintId constraint{};  ///< the constraint the row belongs to
    double value = 0.0;         ///< C
    double rate = 0.0;          ///< Ċ = J·v
    double jdot_v = 0.0;        ///< J̇q̇ = C̈ at zero acceleration
    double gradient_norm = 0.0; ///< |∇C| = |J| over all the row's coordinates
};

/// What a force function sees and writes: the state being evaluated (an integrator stage)
/// and the forces accumulated so far (exerted, then earlier generators in order).
struct ForceContext {
    double time{};                          ///< seconds
    std::span<const Vec2> positions;      ///< one per particle
    std::span<const Vec2> velocities;     ///< one per particle
    std::span<const double> inverse_masses;  ///< 0 for pinned particles
    std::span<Vec2> forces;               ///< add to these
};

/// A user force generator.
using ForceFunction = std::function<void(const ForceContext&)>;
/// A generator's potential energy at the given positions (world units of energy).
using PotentialFunction = std::function<double(std::span<const Vec2> positions)>;

/// A grab spring (the hand of a mouse, as Box2D's samples make a mouse joint once): on one
/// particle F = k·(target − x) − c·v, scaled down to max_force when longer.
struct GrabDef {
    double hertz = 5.0;          ///< f > 0: k = m·(2πf)² for the mass m below
    /// ζ ≥ 0: c = 2ζ·√(k·mₚ) for the grabbed particle's own mass mₚ (1: it is critically
    /// damped on the spring, whatever mass the spring is tuned for)
    double damping_ratio = 1.0;
    /// The mass m the spring is tuned for, ≥ 0 (0: the grabbed particle's own). A hand that
    /// should hold a whole chain takes the chain's mass: its weight then hardly stretches it.
    double mass = 0.0;
    double max_force = std::numeric_limits<double>::infinity();  ///< N, > 0 (Box2D: a multiple of m·g)
};

/// What a user constraint writes for the current positions and velocities of its particles.
struct UserConstraintOutput {
    double value = 0.0;         ///< C
    std::span<Vec2> jacobian;   ///< ∂C/∂xᵢ, one per particle of the constraint
    double jdot_v = 0.0;        ///< J̇q̇ = Σᵢ (dJᵢ/dt)·vᵢ
};

/// A user constraint: one scalar C over `particles`. `evaluate` gets their positions and
/// velocities (same order) and must fill an output consistent with C (Ċ = J·v).
struct UserConstraint {
    std::vector<ParticleId> particles{};  ///< the particles C depends on (at least one)
    std::function<void(std::span<const Vec2> x, std::span<const Vec2> v, UserConstraintOutput& out)> evaluate;  ///< fills `out` from positions and velocities
};

namespace detail {
struct ParticleState;  // the system's arrays, records and solver (private: Eigen stays out of this header)
}

/// Particles with forces and constraints, advanced by one integrator. State is kept as
/// arrays (positions, velocities, inverse masses, forces) in particle order, behind a
/// pointer: the spans below stay valid until particles are added.
/// Move-only: the solver keeps factorizations of its matrices.
class GRAPE_DYNAMICS_API ParticleSystem {
public:
    /// Throws grape::Error if a setting is out of range (non-positive omega_dt, negative gains,
    /// tolerance or iteration counts).
    explicit ParticleSystem(ParticleSystemDef def = {});
    ~ParticleSystem();
    ParticleSystem(ParticleSystem&&) noexcept;  ///< takes the particles over; the moved-from system may only be destroyed or assigned to
    ParticleSystem& operator=(ParticleSystem&&) noexcept;  ///< as the move constructor

    // -- particles --
    /// Adds a particle. Throws grape::Error if position or velocity is not finite or the mass
    /// is not positive (infinity pins it; its velocity is then set to zero).
    ParticleId create_particle(const ParticleDef& def);
    /// Number of particles.
    std::size_t size() const noexcept;
    /// Positions, velocities, inverse masses (0 = pinned) and the forces of the last evaluation.
    std::span<const Vec2> positions() const noexcept;
    std::span<const Vec2> velocities() const noexcept;  ///< units per second, particle order
    std::span<const double> inverse_masses() const noexcept;  ///< 1/kg, 0 = pinned
    std::span<const Vec2> forces() const noexcept;  ///< applied forces at the last evaluation
    /// Constraint force Jᵀλ on each particle at the last evaluation.
    std::span<const Vec2> constraint_forces() const noexcept;
    Vec2 position(ParticleId id) const;  ///< throws grape::Error for an unknown id
    Vec2 velocity(ParticleId id) const;  ///< throws grape::Error for an unknown id
    double mass(ParticleId id) const;    ///< +infinity when pinned
    /// Moves a particle (no drift control is applied until the next step).
    void set_position(ParticleId id, Vec2 position);
    /// Sets a particle's velocity (pinned particles keep zero). Throws grape::Error for an unknown
    /// id or a velocity that is not finite.
    void set_velocity(ParticleId id, Vec2 velocity);
    /// Adds a force held for the next step, then cleared (as the seed's exertForce).
    void exert_force(ParticleId id, Vec2 force);

    // -- force generators (applied in the order added) --
    /// Weight m·g on every particle, potential −m·g·x. Throws if g is not finite.
    void add_gravity(Vec2 g);
    /// Linear drag −k·v on every particle (no potential). Throws if k < 0 or not finite.
    void add_drag(double k);
    /// A damped spring (potential ½k(|d| − L)²). Throws for unknown ids, a == b or bad values.
    void add_spring(ParticleId a, ParticleId b, const SpringDef& def);
    /// A user force, with an optional potential counted in energy(). Throws if `force` is empty.
    void add_force(ForceFunction force, PotentialFunction potential = {});

    // -- the grab spring (one at a time, applied after the generators) --
    /// Grabs particle `id` with a spring to `target` (replacing any grab). Its potential
    /// ½k|target − x|² counts in energy() and its k in stiffest_mode(). Throws grape::Error
    /// for an unknown or pinned particle, a non-finite target or a bad GrabDef.
    void grab(ParticleId id, Vec2 target, const GrabDef& def = {});
    /// Moves the grab's target (nothing happens when nothing is grabbed). Throws if not finite.
    void move_grab(Vec2 target);
    /// Lets go.
    void release_grab() noexcept;
    /// The grabbed particle, if any.
    std::optional<ParticleId> grabbed() const noexcept;
    /// The particle nearest to `point` within `radius` (pinned particles skipped): what a click grabs.
    std::optional<ParticleId> nearest_particle(Vec2 point, double radius) const noexcept;

    // -- constraints --
    /// |xa − xb| = length (C = ½(|d|² − L²)). Throws for unknown ids, a == b, length ≤ 0, or
    /// particles at the same point.
    ConstraintId create_distance(ParticleId a, ParticleId b, double length);
    /// |xa − xb| held at its current value.
    ConstraintId create_distance(ParticleId a, ParticleId b);
    /// |xa − anchor| = length: a pendulum rod to a fixed point. Throws if length ≤ 0 or the
    /// particle sits at the anchor (the rod would have no direction).
    ConstraintId create_anchor(ParticleId a, Vec2 anchor, double length);
    /// xa = point (two rows). Throws for an unknown id or a non-finite point.
    ConstraintId create_fixed_point(ParticleId a, Vec2 point);
    /// C(xa) = 0 for an implicit curve. Throws if ∇C is zero at the particle (the center of a
    /// circle: the constraint force would have no direction).
    ConstraintId create_implicit(ParticleId a, ImplicitFunction curve);
    /// A user constraint. Throws if it has no particles, an unknown id or no function.
    ConstraintId create_constraint(UserConstraint constraint);
    /// Number of constraints (a fixed point counts once).
    std::size_t constraint_count() const noexcept;

    // -- settings --
    const ParticleSystemDef& def() const noexcept;  ///< the settings in force
    /// Changes the drift control (validated as in the constructor).
    void set_drift(const DriftDef& drift);
    /// Changes the sub-step rule (validated as in the constructor).
    void set_substeps(const SubstepDef& substeps);
    /// Changes the integrator (its rk45 step memory restarts).
    void set_integrator(Integrator integrator);
    /// Changes the rk45 settings (validated as in Stepper; its step memory restarts).
    void set_rk45(const Rk45Def& rk45);

    // -- simulation --
    /// Advances by dt seconds (> 0, finite; throws grape::Error otherwise): integrates with
    /// constraint forces at every stage, projects when drift control says so, clears exerted forces.
    /// A step that would leave the finite range is not taken (status non_finite). Throws
    /// grape::Error when a constraint's gradient is zero at the current positions (a particle
    /// at its anchor or on top of its distance partner, at the center of a circle): its force
    /// would have no direction, and Baumgarte feedback would fling the particle away.
    /// Near such a point (a rod compressed far below its length, a bead near a circle's
    /// center) a row is judged by κ = |C|·|H·n̂|/|∇C|² (H the Hessian of C, n̂ the gradient's
    /// direction; rods and anchors exactly, curves from their second derivatives, user rows
    /// not at all): for κ > 1 the gradient may vanish within the correction's reach, so
    /// Baumgarte feedback and projection aim only at |C| = |∇C|²/|H·n̂| (a trust region the
    /// next step widens), RATTLE leaves the row out of the step, and for κ ≥ 100 (an anchor's
    /// particle within L/14 of it) the row is left out of the solve; such steps report
    /// singular. The particle then moves under its other forces until the row is trusted.
    StepStats step(double dt);
    /// Simulated time in seconds.
    double time() const noexcept;

    // -- diagnostics (at the current state) --
    /// Σ ½ m|v|² over particles that are not pinned.
    double kinetic_energy() const noexcept;
    /// Σ of the generators' potentials (gravity, springs, user potentials).
    double potential_energy() const;
    /// kinetic + potential.
    double energy() const { return kinetic_energy() + potential_energy(); }
    /// Residuals of every constraint, in creation order.
    std::vector<ConstraintResidual> residuals() const;
    /// Every scalar row: C, Ċ, J̇q̇ and |∇C| (to check a constraint's derivatives).
    std::vector<ConstraintRow> constraint_rows() const;
    /// The largest residual over all constraints (zeros when there are none).
    ConstraintResidual max_residual() const;
    /// The bound ω on the stiffest mode that SubstepDef::automatic uses, rad/s, from the
    /// constraint forces of the last evaluation (0 before the first).
    double stiffest_mode() const noexcept;
    /// Evaluates the constrained accelerations at the current state without stepping
    /// (fills forces() and constraint_forces(); Baumgarte gains are the last step's);
    /// returns the solve status.
    SolveStatus evaluate(std::span<Vec2> accelerations);

private:
    std::uint32_t checked(ParticleId id, std::string_view where) const;
    StepStats single_step(double dt);
    void refuse_degenerate_rows();  // throws for a violated row with ∇C = 0 (rows evaluated)
    std::unique_ptr<detail::ParticleState> state_;  // model, state and solver (src/dynamics/particle_state.hpp)
};

/// @}

}  // namespace grape
