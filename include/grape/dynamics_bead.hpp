// grape — dynamics: a bead sliding without friction on any path (or a user parametric
// curve) in its generalized coordinate u. Included by <grape/dynamics.hpp>.
#pragma once

#include <grape/dynamics_ode.hpp>
#include <grape/error.hpp>
#include <grape/export_dynamics.hpp>
#include <grape/math.hpp>
#include <grape/path.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace grape {

/// \addtogroup dynamics
/// @{

// ---------------------------------------------------------------------------------------
// Generalized coordinates: a bead on a parametric curve
// ---------------------------------------------------------------------------------------

/// A parametric curve's point and its first two derivatives at one parameter value.
struct ParametricSample {
    Vec2 point{};  ///< x(u)
    Vec2 d1{};     ///< x′(u)
    Vec2 d2{};     ///< x″(u)
};

/// A user parametric curve: u ↦ (x, x′, x″), e.g. the seed's parabola (u, −u²/100).
using ParametricFunction = std::function<ParametricSample(double u)>;

/// The bead's coordinate acceleration: ü = (x′·F/m − (x′·x″) u̇²)/|x′|², 0 where x′ = 0
/// (the bead rests at a cusp rather than producing NaN).
inline double bead_acceleration(const ParametricSample& frame, Vec2 force, double mass, double u_rate) noexcept {
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
class GRAPE_DYNAMICS_API Bead {
public:
    /// On any path; a complex one (whatever its static type) keeps the speed along the path
    /// at joins between its parts. Throws grape::Error for a bad BeadDef (non-finite values,
    /// mass ≤ 0, drag < 0, restitution outside [0, 1], u outside [0, 1]).
    Bead(const Path& path, const BeadDef& def);
    /// On a ComplexPath: the same as Bead(const Path&, def).
    Bead(const ComplexPath& path, const BeadDef& def);
    /// On a user curve (u unbounded). Throws grape::Error if `curve` is empty or def is bad.
    Bead(ParametricFunction curve, const BeadDef& def);

    /// An extra force F(t, x, v) on the bead (e.g. wind, a mouse spring); empty to remove.
    void set_force(std::function<Vec2(double t, Vec2 x, Vec2 v)> force) { force_ = std::move(force); }
    /// Advances by dt seconds (> 0, finite; throws grape::Error otherwise).
    StepStats step(double dt);

    double time() const noexcept { return time_; }  ///< seconds simulated so far
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
    struct Part { ParametricFunction curve; double u0, u1; };
    class Ode;
    void init_parts(std::vector<Part> parts, const BeadDef& def);
    ParametricSample frame(double local_u) const noexcept;
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

/// @}

}  // namespace grape
