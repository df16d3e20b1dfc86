// The particle system's model as the solver sees it: the records of force generators and
// constraints, and the per-step view (b2StepContext's idea: recreated at every step, spans
// of the arrays the solver works on and a force callback; no back-pointer to the system).
#pragma once

#include <grape/dynamics_particles.hpp>

#include <cstdint>
#include <span>

namespace grape::detail {

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
    Vec2 point{};                // anchor or fixed point
    double length = 0.0;
    std::uint32_t extra = 0;     // index into the curves or the user constraints
};

// Writes the system's forces at (t, x, v) into `out` (exerted forces, generators in order,
// the grab spring).
using ApplyForces = void (*)(const void* system, double t, std::span<const Vec2> x, std::span<const Vec2> v,
                             std::span<Vec2> out) noexcept;

// What the solver reads of the system for one step (or one diagnostic evaluation).
struct SystemView {
    std::size_t particles = 0;
    std::span<const Vec2> positions;  // at the step's start (the springs' stretch for the stiffness bound)
    std::span<const double> inverse_masses;
    std::span<const ConstraintRecord> constraints;
    std::span<const ImplicitFunction> curves;
    std::span<const UserConstraint> users;
    std::span<const Spring> springs;
    const Grab* grab = nullptr;
    const SolverDef* solver = nullptr;
    const DriftDef* drift = nullptr;
    ApplyForces apply_forces = nullptr;
    const void* system = nullptr;  // apply_forces' first argument
};

}  // namespace grape::detail
