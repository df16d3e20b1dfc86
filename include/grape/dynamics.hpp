// grape — dynamics: particles, forces, integrators, Witkin constraints, drift control and
// beads on any path.
//
// Two ways to keep a particle on a curve, as in the seed's parabola x² + 100y = 0:
//  * implicit (Witkin): a ParticleSystem with a constraint C(q) = 0. Each evaluation solves
//    J W Jᵀ λ = −J̇q̇ − J W Q − ks·C − kd·Ċ and applies the constraint force Jᵀλ, which does
//    no work along any legal velocity. Any number of particles and constraints, solved
//    together (Cholesky for small or banded systems, Eigen's sparse solvers for large ones).
//  * generalized coordinates (Lagrange): a Bead with one coordinate u on a parametric curve
//    x(u) (any grape::Path), q̈ = (x′·F/m − (x′·x″) q̇²)/|x′|². On the curve by construction.
//
// The seed's closed-form constraint force for the parabola,
//   Fc.y = (−50 m vx² − 100 x Fext.x − 2500 Fext.y)/(x² + 2500),  Fc.x = Fc.y·x/50,
// has the wrong coefficient on Fext.x: Jᵀλ (and the seed's own no-work argument) gives
// −50·x·Fext.x. With gravity alone the two agree; with any sideways force the seed's force
// leaves C̈ = −2·x·Fext.x/m and pushes the bead off the curve. The general solver below gives
// the corrected force (tests/test_dynamics.cpp checks both).
//
// Units: any consistent set (the seed uses pixels, seconds, mass 1, y down, g = (0, +g)).
//
//   grape::ParticleSystem system({.integrator = grape::Integrator::rk4});
//   auto bob = system.add_particle({.position = {100, 0}});
//   system.add_gravity({0, 500});
//   system.add_anchor(bob, {0, 0}, 100);       // a pendulum of length 100
//   for (int i = 0; i < 60; ++i) system.step(1.0 / 60);
//
// Threads: a ParticleSystem, a Bead and a Stepper each belong to one thread (step, add,
// queries and the force functions they call). Separate systems and beads share nothing and
// may step on separate threads at once, also when they read the same Path (shared
// read-only), or the same ImplicitCurve if its function is safe to call concurrently.
// The *_from_string and to_string functions may be called from any thread.
#pragma once

#include <grape/dynamics_jet.hpp>
#include <grape/error.hpp>
#include <grape/math.hpp>
#include <grape/path.hpp>

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

// ---------------------------------------------------------------------------------------
// Implicit curves C(x, y) = 0
// ---------------------------------------------------------------------------------------

/// C and its first and second derivatives at one point.
struct CurveSample {
    double value = 0.0;  ///< C(x, y), in the curve's own units
    Vec2 gradient{};     ///< ∇C
    double hxx = 0.0;    ///< ∂²C/∂x²
    double hxy = 0.0;    ///< ∂²C/∂x∂y
    double hyy = 0.0;    ///< ∂²C/∂y²
};

/// A curve C(x, y) = 0 that a particle is held on. Value, gradient and Hessian come either
/// from the user or from one templated function differentiated automatically (Jet2).
class ImplicitCurve {
public:
    /// User-supplied value, gradient and Hessian. Throws grape::Error if `evaluate` is empty.
    explicit ImplicitCurve(std::function<CurveSample(Vec2)> evaluate);

    /// From C written once for any number type: `[](auto x, auto y) { return x*x + 100*y; }`.
    /// Gradient and Hessian by forward-mode automatic differentiation.
    template <class F>
    static ImplicitCurve from_function(F function) {
        return ImplicitCurve(std::function<CurveSample(Vec2)>([function](Vec2 p) {
            const Jet2 c = function(Jet2::x(p.x), Jet2::y(p.y));
            return CurveSample{c.v, {c.gx, c.gy}, c.hxx, c.hxy, c.hyy};
        }));
    }

    /// C, ∇C and the Hessian at p.
    CurveSample operator()(Vec2 p) const { return evaluate_(p); }

private:
    std::function<CurveSample(Vec2)> evaluate_{};
};

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
std::string_view to_string(Integrator integrator) noexcept;
/// The integrator named `name` (as to_string gives it, or the short forms "symplectic" and
/// "verlet"); throws grape::Error naming the unknown value.
Integrator integrator_from_string(std::string_view name);
/// Every integrator, in declaration order (for menus and name lists).
std::span<const Integrator> all_integrators() noexcept;
/// The formal order of accuracy (rk45: 5 at a fixed step).
int order(Integrator integrator) noexcept;

/// Settings of the adaptive Dormand–Prince integrator.
struct Rk45Def {
    double tolerance = 1e-10;  ///< per sub-step error bound, relative and absolute (0: no control, fixed step)
    double min_step = 1e-12;   ///< seconds; below it a sub-step is accepted anyway (and counted)
    int max_substeps = 100000; ///< per step(), a guard against stiffness
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

/// What one Stepper::step did.
struct StepStats {
    int evaluations = 0;  ///< calls of acceleration()
    int substeps = 0;     ///< accepted sub-steps (1 for fixed-step integrators)
    int rejected = 0;     ///< rk45 sub-steps rejected by error control
    int forced = 0;       ///< rk45 sub-steps accepted at min_step despite the error
    /// False when the state or rk45's error estimate left the finite range: the step stopped
    /// there (rk45 at once, without rejecting sub-steps to max_substeps) and q, v are as before.
    bool finite = true;
};

/// Advances any SecondOrderSystem by one step of the chosen integrator. Holds its scratch
/// buffers (allocated when the system size first grows), so steps do not allocate.
class Stepper {
public:
    explicit Stepper(Integrator integrator = Integrator::rk4, Rk45Def rk45 = {});
    /// Advances (q, v) from t to t + dt in place. rk45 takes as many sub-steps as its
    /// tolerance needs and remembers its last step size. dt must be positive.
    StepStats step(SecondOrderSystem& system, double t, std::span<double> q, std::span<double> v, double dt);
    Integrator integrator() const noexcept { return integrator_; }
    const Rk45Def& rk45() const noexcept { return rk45_; }

private:
    Integrator integrator_{};
    Rk45Def rk45_{};
    double rk45_step_ = 0.0;  // last accepted rk45 step, 0 before the first
    std::vector<double> buffer_{};
};

// ---------------------------------------------------------------------------------------
// The particle system
// ---------------------------------------------------------------------------------------

/// A particle's handle: its index in creation order (particles are never removed).
struct ParticleId {
    std::uint32_t index = 0;
    friend constexpr bool operator==(ParticleId, ParticleId) noexcept = default;
};

/// A constraint's handle: its index in creation order (constraints are never removed).
struct ConstraintId {
    std::uint32_t index = 0;
    friend constexpr bool operator==(ConstraintId, ConstraintId) noexcept = default;
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
std::string_view to_string(DriftControl drift) noexcept;
/// The drift control named `name`; throws grape::Error naming the unknown value.
DriftControl drift_control_from_string(std::string_view name);
/// Every drift control, in declaration order (for menus and name lists).
std::span<const DriftControl> all_drift_controls() noexcept;

/// Drift-control settings.
struct DriftDef {
    DriftControl method = DriftControl::baumgarte;  ///< see DriftControl
    /// Baumgarte gains from the step: ω = omega_dt/dt, ks = ω², kd = 2ω (critical damping).
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

/// Outcome of the last constraint solve(s).
enum class SolveStatus {
    ok,             ///< J W Jᵀ was regular and the solve succeeded
    singular,       ///< redundant or degenerate constraints: a least-squares/CG solution was used
    not_converged,  ///< conjugate gradient stopped at its iteration limit
    non_finite,     ///< the state left the finite range: the step was not taken (state and time unchanged)
};

/// The status name ("ok", "singular", "not_converged", "non_finite").
std::string_view to_string(SolveStatus status) noexcept;

/// What one ParticleSystem::step did.
struct StepReport {
    SolveStatus status = SolveStatus::ok;  ///< worst status over the step's solves
    int evaluations = 0;                   ///< constraint solves inside the integrator
    int substeps = 0;                      ///< integrator sub-steps (rk45, or SubstepDef::automatic)
    int rejected = 0;                      ///< rk45 rejected sub-steps
    int projection_iterations = 0;         ///< Newton iterations of the position projection
    int cg_iterations = 0;                 ///< conjugate-gradient iterations, summed
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
    std::vector<ParticleId> particles{};
    std::function<void(std::span<const Vec2> x, std::span<const Vec2> v, UserConstraintOutput& out)> evaluate;
};

namespace detail {
struct SolverWorkspace;  // Eigen matrices and factorizations (src/dynamics/witkin.hpp)
}

/// Particles with forces and constraints, advanced by one integrator. State is kept as
/// arrays (positions, velocities, inverse masses, forces) in particle order.
/// Move-only: the solver keeps factorizations of its matrices.
class ParticleSystem {
public:
    /// Throws grape::Error if a setting is out of range (non-positive omega_dt, negative gains,
    /// tolerance or iteration counts).
    explicit ParticleSystem(ParticleSystemDef def = {});
    ~ParticleSystem();
    ParticleSystem(ParticleSystem&&) noexcept;
    ParticleSystem& operator=(ParticleSystem&&) noexcept;

    // -- particles --
    /// Adds a particle. Throws grape::Error if position or velocity is not finite or the mass
    /// is not positive (infinity pins it; its velocity is then set to zero).
    ParticleId add_particle(const ParticleDef& def);
    /// Number of particles.
    std::size_t size() const noexcept { return positions_.size(); }
    /// Positions, velocities, inverse masses (0 = pinned) and the forces of the last evaluation.
    std::span<const Vec2> positions() const noexcept { return positions_; }
    std::span<const Vec2> velocities() const noexcept { return velocities_; }
    std::span<const double> inverse_masses() const noexcept { return inverse_masses_; }
    std::span<const Vec2> forces() const noexcept { return forces_; }
    /// Constraint force Jᵀλ on each particle at the last evaluation.
    std::span<const Vec2> constraint_forces() const noexcept { return constraint_forces_; }
    Vec2 position(ParticleId id) const;  ///< throws grape::Error for an unknown id
    Vec2 velocity(ParticleId id) const;  ///< throws grape::Error for an unknown id
    double mass(ParticleId id) const;    ///< +infinity when pinned
    /// Moves a particle (no drift control is applied until the next step).
    void set_position(ParticleId id, Vec2 position);
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
    ConstraintId add_distance(ParticleId a, ParticleId b, double length);
    /// |xa − xb| held at its current value.
    ConstraintId add_distance(ParticleId a, ParticleId b);
    /// |xa − anchor| = length: a pendulum rod to a fixed point. Throws if length ≤ 0 or the
    /// particle sits at the anchor (the rod would have no direction).
    ConstraintId add_anchor(ParticleId a, Vec2 anchor, double length);
    /// xa = point (two rows). Throws for an unknown id or a non-finite point.
    ConstraintId add_fixed_point(ParticleId a, Vec2 point);
    /// C(xa) = 0 for an implicit curve. Throws if ∇C is zero at the particle (the centre of a
    /// circle: the constraint force would have no direction).
    ConstraintId add_curve(ParticleId a, ImplicitCurve curve);
    /// A user constraint. Throws if it has no particles, an unknown id or no function.
    ConstraintId add_constraint(UserConstraint constraint);
    /// Number of constraints (a fixed point counts once).
    std::size_t constraint_count() const noexcept { return constraints_.size(); }

    // -- settings --
    const ParticleSystemDef& def() const noexcept { return def_; }
    /// Changes the drift control (validated as in the constructor).
    void set_drift(const DriftDef& drift);
    /// Changes the integrator (its rk45 step memory restarts).
    void set_integrator(Integrator integrator);

    // -- simulation --
    /// Advances by dt seconds (> 0, finite; throws grape::Error otherwise): integrates with
    /// constraint forces at every stage, projects when drift control says so, clears exerted forces.
    /// A step that would leave the finite range is not taken (status non_finite). Throws
    /// grape::Error when a constraint's gradient is zero at the current positions (a particle
    /// at its anchor or on top of its distance partner, at the centre of a circle): its force
    /// would have no direction, and Baumgarte feedback would fling the particle away.
    StepReport step(double dt);
    /// Simulated time in seconds.
    double time() const noexcept { return time_; }

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
    friend struct detail::SolverWorkspace;
    struct Gravity { Vec2 g{}; };
    struct Drag { double k; };
    struct Spring { std::uint32_t a, b; SpringDef def; };
    struct UserForce { ForceFunction force; PotentialFunction potential; };
    struct Grab { std::uint32_t particle; Vec2 target; double k, c, max_force; };
    enum class GeneratorKind : std::uint8_t { gravity, drag, spring, user };
    struct Generator { GeneratorKind kind; std::uint32_t index; };
    enum class ConstraintKind : std::uint8_t { distance, anchor, fixed_point, curve, user };
    struct ConstraintRecord {
        ConstraintKind kind{};
        std::uint32_t a = 0, b = 0;  // particles (distance: both)
        Vec2 point{};                  // anchor or fixed point
        double length = 0.0;
        std::uint32_t extra = 0;     // index into curves_ or users_
    };

    std::uint32_t checked(ParticleId id, std::string_view where) const;
    ConstraintId push_constraint(const ConstraintRecord& record);
    void apply_forces(double t, std::span<const Vec2> x, std::span<const Vec2> v) noexcept;
    StepReport single_step(double dt);

    ParticleSystemDef def_{};
    double time_ = 0.0;
    std::vector<Vec2> positions_, velocities_, forces_, exerted_, constraint_forces_;
    std::vector<double> inverse_masses_{};
    std::vector<Generator> generators_{};
    std::vector<Gravity> gravities_{};
    std::vector<Drag> drags_{};
    std::vector<Spring> springs_{};
    std::vector<UserForce> user_forces_{};
    std::optional<Grab> grab_{};
    std::vector<ConstraintRecord> constraints_{};
    std::vector<ImplicitCurve> curves_{};
    std::vector<UserConstraint> users_{};
    Stepper stepper_{};
    std::unique_ptr<detail::SolverWorkspace> solver_{};
    detail::SolverWorkspace& evaluated_rows() const;  // rows evaluated at the current state
    void refuse_degenerate_rows(bool evaluated);       // throws for a violated row with ∇C = 0
    static_assert(sizeof(Vec2) == 2 * sizeof(double), "positions are viewed as 2n doubles");
};

// ---------------------------------------------------------------------------------------
// Generalized coordinates: a bead on a parametric curve
// ---------------------------------------------------------------------------------------

/// A parametric curve's point and its first two derivatives at one parameter value.
struct CurveFrame {
    Vec2 point{};  ///< x(u)
    Vec2 d1{};     ///< x′(u)
    Vec2 d2{};     ///< x″(u)
};

/// A user parametric curve: u ↦ (x, x′, x″), e.g. the seed's parabola (u, −u²/100).
using ParametricCurve = std::function<CurveFrame(double u)>;

/// The bead's coordinate acceleration: ü = (x′·F/m − (x′·x″) u̇²)/|x′|², 0 where x′ = 0
/// (the bead rests at a cusp rather than producing NaN).
inline double bead_acceleration(const CurveFrame& frame, Vec2 force, double mass, double u_rate) noexcept {
    const double s2 = length_squared(frame.d1);
    if (!(s2 > 0.0)) return 0.0;
    return (dot(frame.d1, force) / mass - dot(frame.d1, frame.d2) * u_rate * u_rate) / s2;
}

/// What happens when the bead reaches an end of an open path.
enum class BeadEnd {
    stop,    ///< the bead stops at the end (and may slide back if forces pull it)
    bounce,  ///< the bead's velocity reverses, scaled by `restitution`
};

/// A bead's settings.
struct BeadDef {
    double u = 0.0;          ///< starting parameter
    double speed = 0.0;      ///< starting speed along the path (world units/s, signed: + towards larger u)
    double mass = 1.0;       ///< positive, finite
    Vec2 gravity{};            ///< acceleration of gravity (force m·g, potential −m·g·x)
    double drag = 0.0;       ///< linear drag coefficient k ≥ 0 (force −k·v)
    BeadEnd ends = BeadEnd::stop;     ///< open ends of a Path
    double restitution = 1.0;         ///< bounce: fraction of speed kept, in [0, 1]
    Integrator integrator = Integrator::rk4;  ///< see Integrator
    Rk45Def rk45{};            ///< used when integrator is rk45
};

/// A bead sliding without friction on a curve, in its generalized coordinate u.
/// On a grape::Path u runs over [0, 1]; at each join of a ComplexPath (top level) the bead
/// moves to the next part keeping its speed along the path; a closed path (end point equal
/// to start point) wraps around; open ends stop or bounce (BeadDef::ends). On a user curve
/// u is unbounded. Inside one part u̇ is continuous, so where a path's own parametrization
/// has kinks or stops (LinearSplinePath corners, CosineSplinePath points, where x′ jumps or
/// vanishes) use path.reparametrized(): at constant |x′| the speed carries through.
class Bead {
public:
    /// On any path; a complex one (whatever its static type) keeps the speed along the path
    /// at joins between its parts. Throws grape::Error for a bad BeadDef (non-finite values,
    /// mass ≤ 0, drag < 0, restitution outside [0, 1], u outside [0, 1]).
    Bead(const Path& path, const BeadDef& def);
    /// On a ComplexPath: the same as Bead(const Path&, def).
    Bead(const ComplexPath& path, const BeadDef& def);
    /// On a user curve (u unbounded). Throws grape::Error if `curve` is empty or def is bad.
    Bead(ParametricCurve curve, const BeadDef& def);

    /// An extra force F(t, x, v) on the bead (e.g. wind, a mouse spring); empty to remove.
    void set_force(std::function<Vec2(double t, Vec2 x, Vec2 v)> force) { force_ = std::move(force); }
    /// Advances by dt seconds (> 0, finite; throws grape::Error otherwise).
    StepStats step(double dt);

    double time() const noexcept { return time_; }
    /// The parameter u on the whole path.
    double u() const noexcept;
    /// du/dt on the whole path.
    double u_rate() const noexcept;
    /// Position x(u).
    Vec2 position() const noexcept;
    /// Velocity x′(u)·u̇.
    Vec2 velocity() const noexcept;
    /// Signed speed along the path (+ towards larger u).
    double speed() const noexcept;
    /// ½m|v|² − m·g·x (the extra force and drag have no potential).
    double energy() const noexcept;
    /// ü at the current state (the equation of motion, for tests and tools).
    double acceleration() const noexcept;
    /// Number of ends and joins crossed so far.
    int crossings() const noexcept { return crossings_; }

private:
    // One smooth piece: its curve (a Path captured by value) and its span of the whole u.
    struct Part { ParametricCurve curve; double u0, u1; };
    class Ode;
    void init_parts(std::vector<Part> parts, const BeadDef& def);
    CurveFrame frame(double local_u) const noexcept;
    Vec2 applied_force(double t, Vec2 x, Vec2 v) const noexcept;
    void transfer(double speed, int direction);

    BeadDef def_{};
    std::vector<Part> parts_;  // one for a user curve (unbounded) or a plain path
    bool bounded_ = true;      // false for a user curve
    bool closed_ = false;
    std::size_t part_ = 0;
    double local_u_ = 0.0, local_rate_ = 0.0;
    double time_ = 0.0;
    int crossings_ = 0;
    std::function<Vec2(double, Vec2, Vec2)> force_{};
    Stepper stepper_{};
};

}  // namespace grape
