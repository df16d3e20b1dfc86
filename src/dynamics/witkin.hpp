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
    bool dense = true;

    // -- per evaluation --
    std::vector<Vec2> jacobian;  // per block
    std::vector<double> c, c_dot, jdot_v, gradient_norm2;  // per row
    std::vector<Vec2> user_x, user_v;                       // scratch for user constraints

    Eigen::MatrixXd dense_matrix;
    Eigen::LDLT<Eigen::MatrixXd> ldlt;
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
