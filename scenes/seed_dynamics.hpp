// Named dynamics scenes: the seed's parabola by both methods (and by the seed's own closed
// form), its closed forms as written and corrected, pendulums and chains. Shared by the
// tests, the benchmarks and the tool.
#pragma once

#include <grape/dynamics.hpp>

#include <string_view>

namespace grape::scenes {

// ---- the seed's parabola x² + 100y = 0 (screen coordinates, y down, gravity m·g·(0, 1)) ----

/// C(x, y) = x² + 100y, written once for doubles and Jet2.
template <class T>
T seed_parabola_c(T x, T y) {
    return x * x + 100.0 * y;
}

/// The parabola as an implicit curve (gradient and Hessian by automatic differentiation).
ImplicitFunction seed_parabola_curve();
/// The parabola with hand-written gradient (2x, 100) and Hessian diag(2, 0).
ImplicitFunction seed_parabola_curve_analytic();
/// The parametric form x(q) = (q, −q²/100) with its derivatives.
ParametricSample seed_parabola_frame(double q) noexcept;

/// The seed's closed-form constraint force, AS WRITTEN in the blog (wrong Fext.x coefficient):
/// Fc.y = (−50 m vx² − 100 x Fext.x − 2500 Fext.y)/(x² + 2500), Fc.x = Fc.y·x/50.
Vec2 seed_constraint_force(double mass, Vec2 x, Vec2 v, Vec2 f_ext) noexcept;
/// The corrected closed form (Witkin's Jᵀλ): −50·x·Fext.x in place of −100·x·Fext.x.
Vec2 corrected_constraint_force(double mass, Vec2 x, Vec2 v, Vec2 f_ext) noexcept;
/// The seed's parametric equation q̈ = (−q q̇² − 50 g q)/(2500 + q²).
double seed_parametric_acceleration(double q, double q_dot, double g) noexcept;

/// How the parabola is simulated.
enum class ParabolaMethod {
    implicit,    ///< ParticleSystem + curve constraint (general Witkin solver)
    parametric,  ///< Bead on the parametric curve (generalized coordinate)
    seed,        ///< one particle with the seed's closed-form force as written (no solver)
};
std::string_view to_string(ParabolaMethod method) noexcept;
/// Throws grape::Error naming the unknown value.
ParabolaMethod parse_parabola_method(std::string_view name);

/// A parabola run: released from rest at (x0, −x0²/100).
struct ParabolaSetup {
    ParabolaMethod method = ParabolaMethod::implicit;
    Integrator integrator = Integrator::rk4;
    double x0 = 100.0;       ///< release point, px
    double g = 500.0;        ///< px/s²
    double mass = 1.0;
    double force_x = 0.0;    ///< constant sideways force (potential −force_x·x)
    DriftDef drift{.method = DriftControl::none};  ///< implicit method only
    Rk45Def rk45{};
};

/// The state of a parabola run in world coordinates.
struct ParabolaState {
    double t = 0.0;
    Vec2 x, v;
    double residual = 0.0;  ///< C = x² + 100y (px²)
    double distance = 0.0;  ///< |C|/|∇C| (px, first order)
    double energy = 0.0;    ///< ½m|v|² − m·g·y − force_x·x
    /// False when the last step would have left the finite range and was not taken (the
    /// state is the one before it).
    bool finite = true;
};

/// One parabola simulation, any method.
class ParabolaRun {
public:
    /// Throws grape::Error for bad values (non-finite, mass ≤ 0, ...).
    explicit ParabolaRun(const ParabolaSetup& setup);
    /// One step; false when it would leave the finite range (then nothing changes).
    bool step(double dt);
    ParabolaState state() const;
    const ParabolaSetup& setup() const noexcept { return setup_; }

private:
    ParabolaSetup setup_;
    std::optional<ParticleSystem> system_;
    std::optional<Bead> bead_;
};

/// Maxima over a whole run.
struct ParabolaSummary {
    ParabolaState initial, final;
    double max_residual = 0.0;  ///< max |C| over the run (px²)
    double max_distance = 0.0;  ///< max |C|/|∇C| (px)
    double max_energy_error = 0.0;  ///< max |E − E0|/|E0|
};

/// Runs `seconds` at step dt, calling `each` (if given) after every step.
ParabolaSummary run_parabola(const ParabolaSetup& setup, double dt, double seconds,
                             const std::function<void(const ParabolaState&)>& each = {});

// ---- pendulums and chains (pivot at the origin, y down, g along +y) ----

/// A simple pendulum: bob of mass 1 at distance `length` from the origin, released from
/// rest at `theta0` radians from the downward vertical, held by an anchor constraint.
ParticleSystem simple_pendulum(double length, double theta0, double g, const ParticleSystemDef& def);

/// A double pendulum of unit masses with both rods horizontal (bobs at (L1, 0) and
/// (L1 + L2, 0)), from rest: rod 1 an anchor constraint, rod 2 a distance constraint.
ParticleSystem double_pendulum(double length1, double length2, double g, const ParticleSystemDef& def);

/// The catalogue chain's settings: RATTLE (links held at round-off every step) with
/// sub-steps chosen from the chain's stiffest mode, so a chain of any length runs at any
/// frame rate as given, with no sub-step count to pick.
ParticleSystemDef chain_def();

/// A chain of `links` unit-mass particles, `link_length` apart, hanging from a pinned particle
/// at the origin, straight and at rest, `release_angle` radians from the downward vertical
/// (π/2, the default: horizontal along +x; 0: hanging): particle 0 is the pin, link k joins
/// particles k−1 and k.
ParticleSystem chain(std::size_t links, double link_length, double g, const ParticleSystemDef& def = chain_def(),
                     double release_angle = pi / 2);

/// A strip of cloth: columns × rows unit masses `spacing` apart, the top row pinned, held by
/// distance constraints along the rows (below the top) and the columns, released sheared by
/// `release_angle` radians (every link keeps its length) so it starts swinging; centered on
/// x = 0, rows going down (+y). Particle (c, r) is number r·columns + c.
ParticleSystem cloth_strip(int columns, int rows, double spacing, double g, const ParticleSystemDef& def = chain_def(),
                           double release_angle = 0.5);

/// The largest | |x_k − x_{k−1}| − L | over a chain's links.
double chain_link_error(const ParticleSystem& chain, double link_length) noexcept;

}  // namespace grape::scenes
