// The Witkin constraint solver behind ParticleSystem (private: Eigen stays out of the
// public header).
#pragma once

#include "particle_model.hpp"

#include <Eigen/Dense>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <cmath>
#include <cstdint>
#include <vector>

namespace grape::detail {

// Everything the constraint solve needs, and the ParticleSystem's view as a second-order
// system for the integrators. Rows: one per scalar constraint (a fixed point has two).
// Blocks: one per (row, particle) with the 2-vector ∂C_row/∂x_particle.
struct SolverWorkspace final : SecondOrderSystem {
    // The system as this step sees it (set by prepare() or view_of() callers each time).
    SystemView view{};
    // Forces and constraint forces Jᵀλ of the last evaluation, per particle.
    std::vector<Vec2> forces, constraint_forces;

    // -- topology, rebuilt when particles or constraints are added --
    bool dirty = true;
    // The (x, v) the rows were evaluated at by evaluate_rows_for_step, while still current.
    std::vector<Vec2> rows_x, rows_v;
    bool rows_remembered = false;
    std::size_t rows = 0;
    std::vector<std::uint32_t> row_constraint;  // row → constraint index
    std::vector<std::uint32_t> row_begin;       // row → first block (rows + 1 entries)
    std::vector<std::uint32_t> block_particle;  // block → particle
    struct Contribution {
        std::uint32_t value;  // index into the dense or sparse value array of J W Jᵀ
        std::uint32_t block_i, block_j;
        std::uint32_t particle;
    };
    std::vector<Contribution> contributions;
    // Small or narrow-banded systems (a chain in creation order has bandwidth 1) are factored
    // in skyline (envelope) storage of the lower triangle: row i holds columns first[i]..i,
    // and Cholesky fill-in stays inside that envelope. Anything else goes to Eigen's sparse
    // solvers.
    bool skyline = true;
    std::vector<std::uint32_t> first;    // per row: first stored column
    std::vector<std::size_t> offset;     // per row: index of (i, first[i]) in the arrays below
    std::vector<double> sky_matrix, sky_factor, sky_inverse_diagonal, sky_work;
    // Every row couples only to the one before it (a chain in creation order): the envelope
    // is tridiagonal and the factor and solves take the short loops of tridiagonal LDLᵀ.
    bool tridiagonal = false;
    bool two_block_rows = false;  // every row has two blocks (rods between particles)
    template <class Visit>
    void each_block(Visit visit) const;
    std::vector<double> tri_multiplier;  // tridiagonal LDLᵀ: L(i, i−1)

    // The factorization of the last assemble(): ok, failed (singular, the least-squares or
    // CG fallback solves), or conjugate gradient by choice.
    enum class Factor : std::uint8_t { ok, singular, iterative };
    Factor factor = Factor::singular;
    // RATTLE keeps the factor of J W Jᵀ at the positions it ended on for its next step;
    // anything that moves particles or changes the topology makes it stale.
    bool factor_current = false;

    // -- per evaluation --
    std::vector<Vec2> jacobian;  // per block
    std::vector<double> c, c_dot, jdot_v, gradient_norm2;  // per row
    // Per row: h = |H·n̂|, the rate at which ∇C changes along its own direction n̂ (H the
    // Hessian of C: rods 2, anchors 1, fixed points 0, curves from their second derivatives;
    // user rows 0, as they give none).
    std::vector<double> curvature;
    // Rows dropped by the conditioning test (mark_degenerate): their Jacobian blocks are zero,
    // their diagonal of J W Jᵀ is 1 and their right-hand side 0, so their multiplier is 0.
    std::vector<std::uint8_t> degenerate;
    bool any_degenerate = false;
    std::vector<std::size_t> diagonal_value;  // per row: index of (r, r) in the value array
    std::vector<Vec2> user_x, user_v;                       // scratch for user constraints

    Eigen::SparseMatrix<double> sparse_matrix;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> sparse_ldlt;
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
    Eigen::VectorXd rhs, lambda, lambda_previous;
    // Witkin multipliers of the last acceleration solve (constraint forces Jᵀλ): the
    // stiffness estimate of SubstepDef::automatic reads them.
    std::vector<double> witkin_lambda;
    bool have_witkin_lambda = false;
    // RATTLE scratch: the Jacobian at the step's start and the state before the step.
    std::vector<Vec2> jacobian_start, x_start, v_start;

    // -- gains and statistics of the current step --
    double ks = 0.0, kd = 0.0;
    SolveStatus worst = SolveStatus::ok;
    int evaluations = 0;
    int cg_iterations = 0;

    // Takes the step's view, rebuilds the topology if needed, sets the gains for dt.
    void prepare(const SystemView& system, double dt);
    // Takes a view for a diagnostic (no gains, no statistics reset).
    void look_at(const SystemView& system);
    void build_topology();

    // C, J, Ċ, J̇q̇ for every row at (x, v).
    void evaluate_rows(std::span<const Vec2> x, std::span<const Vec2> v);
    // evaluate_rows, remembering (x, v) so that the next acceleration() at exactly these
    // values (an integrator's first stage, on its own copy of the state) uses the rows as they
    // are instead of evaluating them again. Any other evaluation forgets them.
    void evaluate_rows_for_step(std::span<const Vec2> x, std::span<const Vec2> v);
    // C, rhs = −C and |∇C|² only (what a Newton iteration on positions needs); returns the largest
    // |C|/|∇C|. Jacobians and rates are left as they were unless a curve or user row forces
    // the full evaluation.
    double evaluate_values(std::span<const Vec2> x, std::span<const Vec2> v);
    // The conditioning of a row, κ = |C|·h/|∇C|²: over the Newton step s = |C|/|∇C| the
    // gradient changes by h·s (exactly for the quadratic rods and anchors), so for κ < 1 it
    // cannot vanish before C does, while for κ ≥ 1 the linearization overshoots (a rod
    // compressed below 1/√3 of its length, a bead near a circle's center) and Baumgarte's
    // −ks·C along a short gradient flings the particle away.
    // C limited to κ ≤ 1, |C| ≤ |∇C|²/h: what position corrections (Baumgarte's ks·C, the
    // Newton steps of the projection and of RATTLE) aim at, a trust region that the next
    // evaluation widens (an anchor's particle at r < L/√3 is sent to 2r). Notes singular
    // when it limits.
    double trusted_value(std::uint32_t r) noexcept {
        const double value = c[r], limit = gradient_norm2[r];
        if (!(std::abs(value) * curvature[r] > limit)) return value;
        note(SolveStatus::singular);
        return std::copysign(limit / curvature[r], value);
    }
    // Drops the rows with κ ≥ condition (by default degenerate_condition: a rod compressed
    // below 1/14 of its length) from the solve: their level sets are so much more curved than the constraint
    // that even C̈ = 0 along them is a stiff, tiny orbit. Notes singular when it drops one;
    // returns true when the set of dropped rows changed.
    static constexpr double degenerate_condition = 100.0;
    bool mark_degenerate(double condition = degenerate_condition);
    // J W Jᵀ from the current J and inverse masses (a dropped row's diagonal set to 1).
    void assemble();
    // Skyline Cholesky of sky_matrix into sky_factor; false when a pivot is (numerically) zero.
    bool factor_skyline() noexcept;
    void solve_skyline() noexcept;                 // lambda = A⁻¹ rhs with the factor
    bool factor_tridiagonal() noexcept;            // the same for a tridiagonal envelope
    void solve_tridiagonal() noexcept;
    SolveStatus solve_skyline_singular();          // least squares (small) or CG (large)
    // Solves J W Jᵀ λ = rhs into `lambda`: factorize() then solve_factored().
    SolveStatus solve();
    // Factors the assembled J W Jᵀ (sets `factor`).
    void factorize();
    // Solves with the factor of the last factorize() (or the fallbacks when it failed).
    SolveStatus solve_factored();
    void note(SolveStatus status) noexcept;

    // SecondOrderSystem: q = positions (2n), v = velocities (2n).
    std::size_t size() const noexcept override;
    void acceleration(double t, std::span<const double> q, std::span<const double> v,
                      std::span<double> a) noexcept override;

    // Newton projection of positions onto C = 0, then of velocities onto Ċ = 0; returns the
    // number of Newton iterations.
    int project(std::span<Vec2> x, std::span<Vec2> v);

    // One RATTLE step of h from t (src/dynamics/rattle.cpp): x, v advanced in place; false
    // when the state left the finite range (then x, v are as before). `iterations` gets the
    // Newton iterations of the position stage.
    bool rattle_step(double t, std::span<Vec2> x, std::span<Vec2> v, double h, int& iterations);
    // The largest |C|/|∇C| over the rows evaluated last.
    double worst_distance() const noexcept;
    // The bound on the stiffest mode's ω (rad/s) from witkin_lambda and the springs.
    double stiffest_mode() noexcept;
    std::vector<double> stiffness_sum;  // per particle, scratch of stiffest_mode
};

}  // namespace grape::detail
