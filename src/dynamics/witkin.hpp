// The Witkin constraint solver behind ParticleSystem (private: Eigen stays out of the
// public header).
#pragma once

#include <grape/dynamics.hpp>

#include <Eigen/Dense>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <cstdint>
#include <vector>

namespace grape::detail {

// Everything the constraint solve needs, and the ParticleSystem's view as a second-order
// system for the integrators. Rows: one per scalar constraint (a fixed point has two).
// Blocks: one per (row, particle) with the 2-vector ∂C_row/∂x_particle.
struct SolverWorkspace final : SecondOrderSystem {
    ParticleSystem* owner = nullptr;

    // -- topology, rebuilt when particles or constraints are added --
    bool dirty = true;
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

    // -- per evaluation --
    std::vector<Vec2> jacobian;  // per block
    std::vector<double> c, c_dot, jdot_v, gradient_norm2;  // per row
    std::vector<Vec2> user_x, user_v;                       // scratch for user constraints

    Eigen::SparseMatrix<double> sparse_matrix;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> sparse_ldlt;
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
    Eigen::VectorXd rhs, lambda, lambda_previous;

    // -- gains and statistics of the current step --
    double ks = 0.0, kd = 0.0;
    SolveStatus worst = SolveStatus::ok;
    int evaluations = 0;
    int cg_iterations = 0;

    // Sets the owner (it may have moved), rebuilds the topology if needed, sets the gains for dt.
    void prepare(ParticleSystem& system, double dt);
    void build_topology();

    // C, J, Ċ, J̇q̇ for every row at (x, v).
    void evaluate_rows(std::span<const Vec2> x, std::span<const Vec2> v);
    // J W Jᵀ from the current J and inverse masses.
    void assemble();
    // Skyline Cholesky of sky_matrix into sky_factor; false when a pivot is (numerically) zero.
    bool factor_skyline() noexcept;
    void solve_skyline() noexcept;                 // lambda = A⁻¹ rhs with the factor
    SolveStatus solve_skyline_singular();          // least squares (small) or CG (large)
    // Solves J W Jᵀ λ = rhs into `lambda`.
    SolveStatus solve();
    void note(SolveStatus status) noexcept;

    // SecondOrderSystem: q = positions (2n), v = velocities (2n).
    std::size_t size() const noexcept override;
    void acceleration(double t, std::span<const double> q, std::span<const double> v,
                      std::span<double> a) noexcept override;

    // Newton projection of positions onto C = 0, then of velocities onto Ċ = 0; returns the
    // number of Newton iterations.
    int project(std::span<Vec2> x, std::span<Vec2> v);
};

}  // namespace grape::detail
