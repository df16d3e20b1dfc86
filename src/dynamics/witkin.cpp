// Witkin's constrained dynamics: J W Jᵀ λ = −J̇q̇ − J W Q − ks·C − kd·Ċ, force Jᵀλ.
// This file: the gains, the row and block layout, the assembly, the acceleration solve and
// the projection; the rows are evaluated in witkin_rows.cpp, factored in witkin_factor.cpp.
#include "witkin.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace grape::detail {

namespace {
std::span<const Vec2> as_vec2(std::span<const double> values) noexcept {
    return {reinterpret_cast<const Vec2*>(values.data()), values.size() / 2};
}
std::span<Vec2> as_vec2(std::span<double> values) noexcept {
    return {reinterpret_cast<Vec2*>(values.data()), values.size() / 2};
}
}  // namespace

void SolverWorkspace::look_at(const SystemView& system) {
    view = system;
    if (dirty) build_topology();
}

void SolverWorkspace::prepare(const SystemView& system, double dt) {
    look_at(system);
    const DriftDef& drift = *view.drift;
    if (drift.method == DriftControl::baumgarte) {
        if (drift.stiffness) {
            ks = *drift.stiffness;
            kd = drift.damping ? *drift.damping : 2.0 * std::sqrt(ks);
        } else if (dt > 0.0) {
            const double omega = drift.omega_dt / dt;
            ks = omega * omega;
            kd = drift.damping ? *drift.damping : 2.0 * omega;
        }
    } else {
        ks = kd = 0.0;
    }
    if (dt > 0.0) {
        // At most the gains of omega_dt = ½ (ks ≤ 1/(4dt²), kd ≤ 1/dt: the damping removes at
        // most the whole drift rate Ċ within one step, critically damped): stronger feedback
        // corrects more than the violation within one step, an overshoot that the explicit
        // integrators amplify (semi-implicit Euler already diverges at omega_dt = 1).
        ks = std::min(ks, 0.25 / (dt * dt));
        kd = std::min(kd, 1.0 / dt);
    }
    worst = SolveStatus::ok;
    evaluations = 0;
    cg_iterations = 0;
}

void SolverWorkspace::build_topology() {
    rows_remembered = false;
    row_constraint.clear();
    row_begin.assign(1, 0);
    block_particle.clear();
    for (std::uint32_t k = 0; k < view.constraints.size(); ++k) {
        const auto& r = view.constraints[k];
        auto add_row = [&](std::initializer_list<std::uint32_t> particles) {
            row_constraint.push_back(k);
            for (auto p : particles) block_particle.push_back(p);
            row_begin.push_back(static_cast<std::uint32_t>(block_particle.size()));
        };
        switch (r.kind) {
        case ConstraintKind::distance: add_row({r.a, r.b}); break;
        case ConstraintKind::anchor:
        case ConstraintKind::curve: add_row({r.a}); break;
        case ConstraintKind::fixed_point:
            add_row({r.a});
            add_row({r.a});
            break;
        case ConstraintKind::user: {
            row_constraint.push_back(k);
            for (ParticleId p : view.users[r.extra].particles) block_particle.push_back(p.index);
            row_begin.push_back(static_cast<std::uint32_t>(block_particle.size()));
            break;
        }
        }
    }
    rows = row_constraint.size();
    const std::size_t blocks = block_particle.size();
    jacobian.assign(blocks, Vec2{});
    c.assign(rows, 0.0);
    c_dot.assign(rows, 0.0);
    jdot_v.assign(rows, 0.0);
    gradient_norm2.assign(rows, 0.0);
    curvature.assign(rows, 0.0);
    degenerate.assign(rows, 0);
    any_degenerate = false;
    diagonal_value.assign(rows, 0);
    rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(rows));
    lambda = rhs;
    lambda_previous = rhs;

    // Which (row, row) pairs of J W Jᵀ each particle couples.
    std::vector<std::uint32_t> block_row(blocks);
    for (std::uint32_t r = 0; r < rows; ++r)
        for (std::uint32_t b = row_begin[r]; b < row_begin[r + 1]; ++b) block_row[b] = r;
    std::vector<std::vector<std::uint32_t>> blocks_of(view.particles);
    for (std::uint32_t b = 0; b < blocks; ++b) blocks_of[block_particle[b]].push_back(b);

    const SolverDef& solver = *view.solver;
    // Envelope of the lower triangle: the first column each row couples to.
    first.resize(rows);
    for (std::uint32_t r = 0; r < rows; ++r) first[r] = r;
    if (solver.method == LinearSolver::dense) {
        std::fill(first.begin(), first.end(), 0u);
    } else {
        for (std::uint32_t p = 0; p < blocks_of.size(); ++p)
            for (auto bi : blocks_of[p])
                for (auto bj : blocks_of[p]) {
                    const auto i = block_row[bi], j = block_row[bj];
                    if (j < first[i]) first[i] = j;
                }
    }
    std::size_t envelope = 0;
    for (std::uint32_t r = 0; r < rows; ++r) envelope += r - first[r] + 1;
    skyline = solver.method == LinearSolver::dense ||
              (solver.method == LinearSolver::automatic &&
               (rows <= solver.dense_limit || envelope <= 16 * static_cast<std::size_t>(rows)));
    tridiagonal = skyline && rows > 1 && solver.method != LinearSolver::dense;
    for (std::uint32_t r = 1; r < rows && tridiagonal; ++r) tridiagonal = first[r] + 1 >= r;
    two_block_rows = true;
    for (std::uint32_t r = 0; r < rows && two_block_rows; ++r) two_block_rows = row_begin[r] == 2 * r && row_begin[r + 1] == 2 * r + 2;
    factor_current = false;
    have_witkin_lambda = false;
    witkin_lambda.assign(rows, 0.0);
    contributions.clear();
    const auto m = static_cast<Eigen::Index>(rows);
    if (skyline) {
        offset.resize(rows + 1);
        offset[0] = 0;
        for (std::uint32_t r = 0; r < rows; ++r) offset[r + 1] = offset[r] + (r - first[r] + 1);
        for (std::uint32_t r = 0; r < rows; ++r) diagonal_value[r] = offset[r + 1] - 1;
        sky_matrix.assign(envelope, 0.0);
        sky_factor.assign(envelope, 0.0);
        sky_work.assign(rows, 0.0);
        sky_inverse_diagonal.assign(rows, 0.0);
        tri_multiplier.assign(rows, 0.0);
        for (std::uint32_t p = 0; p < blocks_of.size(); ++p)
            for (auto bi : blocks_of[p])
                for (auto bj : blocks_of[p]) {
                    const auto i = block_row[bi], j = block_row[bj];
                    if (j <= i)
                        contributions.push_back({static_cast<std::uint32_t>(offset[i] + (j - first[i])), bi, bj, p});
                }
    } else {
        std::vector<Eigen::Triplet<double>> triplets;
        for (std::uint32_t p = 0; p < blocks_of.size(); ++p)
            for (auto bi : blocks_of[p])
                for (auto bj : blocks_of[p]) {
                    contributions.push_back({0, bi, bj, p});
                    triplets.emplace_back(static_cast<int>(block_row[bi]), static_cast<int>(block_row[bj]), 1.0);
                }
        // The diagonal is always present, so rows touching only pinned particles still have a slot.
        for (std::uint32_t r = 0; r < rows; ++r) triplets.emplace_back(static_cast<int>(r), static_cast<int>(r), 1.0);
        sparse_matrix.resize(m, m);
        sparse_matrix.setFromTriplets(triplets.begin(), triplets.end());
        sparse_matrix.makeCompressed();
        const int* outer = sparse_matrix.outerIndexPtr();
        const int* inner = sparse_matrix.innerIndexPtr();
        for (auto& k : contributions) {
            const int i = static_cast<int>(block_row[k.block_i]);
            const int j = static_cast<int>(block_row[k.block_j]);
            const int* at = std::lower_bound(inner + outer[j], inner + outer[j + 1], i);
            k.value = static_cast<std::uint32_t>(at - inner);
        }
        for (std::uint32_t r = 0; r < rows; ++r)
            diagonal_value[r] = static_cast<std::size_t>(
                std::lower_bound(inner + outer[r], inner + outer[r + 1], static_cast<int>(r)) - inner);
        if (solver.method != LinearSolver::conjugate_gradient) sparse_ldlt.analyzePattern(sparse_matrix);
    }
    dirty = false;
}

void SolverWorkspace::assemble() {
    const auto& w = view.inverse_masses;
    double* values = skyline ? sky_matrix.data() : sparse_matrix.valuePtr();
    const std::size_t count = skyline ? sky_matrix.size() : static_cast<std::size_t>(sparse_matrix.nonZeros());
    std::fill(values, values + count, 0.0);
    for (const auto& k : contributions) values[k.value] += w[k.particle] * dot(jacobian[k.block_i], jacobian[k.block_j]);
    if (any_degenerate)
        for (std::uint32_t r = 0; r < rows; ++r)
            if (degenerate[r]) values[diagonal_value[r]] = 1.0;  // decoupled: its J blocks are zero
}
std::size_t SolverWorkspace::size() const noexcept { return 2 * view.particles; }

void SolverWorkspace::acceleration(double t, std::span<const double> q, std::span<const double> v,
                                   std::span<double> a) noexcept {
    const auto x = as_vec2(q);
    const auto u = as_vec2(v);
    view.apply_forces(view.system, t, x, u, forces);
    auto& f = forces;
    auto& fc = constraint_forces;
    const auto& w = view.inverse_masses;
    std::fill(fc.begin(), fc.end(), Vec2{});
    if (rows > 0) {
        // Bit for bit the values the rows were evaluated at: the same rows (the bytes
        // compared, so −0 against 0 or one NaN against another evaluates again).
        const bool same = rows_remembered && rows_x.size() == x.size() && rows_v.size() == u.size() &&
                          std::memcmp(rows_x.data(), x.data(), x.size_bytes()) == 0 &&
                          std::memcmp(rows_v.data(), u.data(), u.size_bytes()) == 0;
        if (!same) evaluate_rows(x, u);
        rows_remembered = false;
        mark_degenerate();
        assemble();
        for (std::uint32_t r = 0; r < rows; ++r) {
            double jwq = 0.0;
            for (std::uint32_t b = row_begin[r]; b < row_begin[r + 1]; ++b) {
                const auto p = block_particle[b];
                jwq += w[p] * dot(jacobian[b], f[p]);
            }
            rhs(r) = -jdot_v[r] - jwq - (ks > 0.0 ? ks * trusted_value(r) : 0.0) - kd * c_dot[r];
        }
        solve();
        ++evaluations;
        for (std::uint32_t r = 0; r < rows; ++r) witkin_lambda[r] = lambda(r);
        have_witkin_lambda = true;
        for (std::uint32_t r = 0; r < rows; ++r)
            for (std::uint32_t b = row_begin[r]; b < row_begin[r + 1]; ++b)
                fc[block_particle[b]] += lambda(r) * jacobian[b];
        for (std::size_t p = 0; p < f.size(); ++p) f[p] += fc[p];
    }
    auto acc = as_vec2(a);
    for (std::size_t p = 0; p < f.size(); ++p) acc[p] = w[p] * f[p];
}

int SolverWorkspace::project(std::span<Vec2> x, std::span<Vec2> v) {
    if (rows == 0) return 0;
    const auto& w = view.inverse_masses;
    const DriftDef& drift = *view.drift;
    // Positions: Newton on C(x + W Jᵀ δ) = 0 (mass-weighted, so pinned particles stay put).
    // Round-off floor of the distance |C|/|∇C| at the scene's coordinate scale: no Newton
    // iteration can go below it, so reaching it ends the projection.
    double scale = 1.0;
    for (const Vec2& p : x) scale = std::max(scale, 1.0 + std::max(std::abs(p.x), std::abs(p.y)));
    const double tolerance = std::max(drift.projection_tolerance, 8.0 * std::numeric_limits<double>::epsilon() * scale);
    int iterations = 0;
    evaluate_rows(x, v);
    mark_degenerate();
    double before = worst_distance();
    while (iterations < drift.projection_iterations && before > tolerance) {
        assemble();
        for (std::uint32_t r = 0; r < rows; ++r) rhs(r) = -trusted_value(r);
        solve();
        for (std::uint32_t r = 0; r < rows; ++r)
            for (std::uint32_t b = row_begin[r]; b < row_begin[r + 1]; ++b) {
                const auto p = block_particle[b];
                x[p] += w[p] * lambda(r) * jacobian[b];
            }
        ++iterations;
        evaluate_rows(x, v);
        mark_degenerate();
        const double after = worst_distance();
        // Quadratic convergence ends at round-off, where the residual stops shrinking.
        if (!(after < 0.5 * before)) break;
        before = after;
    }
    // Velocities: the W-weighted projection onto J v = 0 (one linear solve).
    assemble();
    for (std::uint32_t r = 0; r < rows; ++r) rhs(r) = -c_dot[r];
    solve();
    for (std::uint32_t r = 0; r < rows; ++r)
        for (std::uint32_t b = row_begin[r]; b < row_begin[r + 1]; ++b) {
            const auto p = block_particle[b];
            v[p] += w[p] * lambda(r) * jacobian[b];
        }
    return iterations;
}

}  // namespace grape::detail
