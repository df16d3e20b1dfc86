// Witkin's constrained dynamics: J W Jᵀ λ = −J̇q̇ − J W Q − ks·C − kd·Ċ, force Jᵀλ.
#include "witkin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grape::detail {

namespace {
// Pivots below this fraction of the largest one mark J W Jᵀ as singular (redundant rows):
// a regular system of moderate condition keeps its pivots far above it, while a redundant
// row's pivot is round-off, ~1e-16 of the largest.
constexpr double singular_pivot_ratio = 1e-11;

std::span<const Vec2> as_vec2(std::span<const double> values) noexcept {
    return {reinterpret_cast<const Vec2*>(values.data()), values.size() / 2};
}
std::span<Vec2> as_vec2(std::span<double> values) noexcept {
    return {reinterpret_cast<Vec2*>(values.data()), values.size() / 2};
}
}  // namespace

void SolverWorkspace::prepare(ParticleSystem& system, double dt) {
    owner = &system;
    if (dirty) build_topology();
    const DriftDef& drift = system.def_.drift;
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
    worst = SolveStatus::ok;
    evaluations = 0;
    cg_iterations = 0;
}

void SolverWorkspace::build_topology() {
    const ParticleSystem& s = *owner;
    row_constraint.clear();
    row_begin.assign(1, 0);
    block_particle.clear();
    for (std::uint32_t k = 0; k < s.constraints_.size(); ++k) {
        const auto& r = s.constraints_[k];
        auto add_row = [&](std::initializer_list<std::uint32_t> particles) {
            row_constraint.push_back(k);
            for (auto p : particles) block_particle.push_back(p);
            row_begin.push_back(static_cast<std::uint32_t>(block_particle.size()));
        };
        switch (r.kind) {
        case ParticleSystem::ConstraintKind::distance: add_row({r.a, r.b}); break;
        case ParticleSystem::ConstraintKind::anchor:
        case ParticleSystem::ConstraintKind::curve: add_row({r.a}); break;
        case ParticleSystem::ConstraintKind::fixed_point:
            add_row({r.a});
            add_row({r.a});
            break;
        case ParticleSystem::ConstraintKind::user: {
            row_constraint.push_back(k);
            for (ParticleId p : s.users_[r.extra].particles) block_particle.push_back(p.index);
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
    rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(rows));
    lambda = rhs;
    lambda_previous = rhs;

    // Which (row, row) pairs of J W Jᵀ each particle couples.
    std::vector<std::uint32_t> block_row(blocks);
    for (std::uint32_t r = 0; r < rows; ++r)
        for (std::uint32_t b = row_begin[r]; b < row_begin[r + 1]; ++b) block_row[b] = r;
    std::vector<std::vector<std::uint32_t>> blocks_of(s.size());
    for (std::uint32_t b = 0; b < blocks; ++b) blocks_of[block_particle[b]].push_back(b);

    const SolverDef& solver = s.def_.solver;
    dense = solver.method == LinearSolver::dense ||
            (solver.method == LinearSolver::automatic && rows <= solver.dense_limit);
    contributions.clear();
    std::vector<Eigen::Triplet<double>> triplets;
    for (std::uint32_t p = 0; p < blocks_of.size(); ++p) {
        for (auto bi : blocks_of[p]) {
            for (auto bj : blocks_of[p]) {
                const auto i = block_row[bi], j = block_row[bj];
                contributions.push_back({0, bi, bj, p});
                if (!dense) triplets.emplace_back(static_cast<int>(i), static_cast<int>(j), 1.0);
            }
        }
    }
    // The diagonal is always present, so rows touching only pinned particles still have a slot.
    const auto m = static_cast<Eigen::Index>(rows);
    if (dense) {
        dense_matrix = Eigen::MatrixXd::Zero(m, m);
        for (auto& k : contributions)
            k.value = block_row[k.block_i] + block_row[k.block_j] * static_cast<std::uint32_t>(rows);
    } else {
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
        if (solver.method != LinearSolver::conjugate_gradient) sparse_ldlt.analyzePattern(sparse_matrix);
    }
    dirty = false;
}

void SolverWorkspace::evaluate_rows(std::span<const Vec2> x, std::span<const Vec2> v) {
    const ParticleSystem& s = *owner;
    std::uint32_t row = 0;
    for (const auto& r : s.constraints_) {
        const std::uint32_t b = row_begin[row];
        switch (r.kind) {
        case ParticleSystem::ConstraintKind::distance: {
            const Vec2 d = x[r.b] - x[r.a];
            const Vec2 w = v[r.b] - v[r.a];
            c[row] = 0.5 * (dot(d, d) - r.length * r.length);
            jacobian[b] = -d;
            jacobian[b + 1] = d;
            jdot_v[row] = dot(w, w);
            break;
        }
        case ParticleSystem::ConstraintKind::anchor: {
            const Vec2 d = x[r.a] - r.point;
            c[row] = 0.5 * (dot(d, d) - r.length * r.length);
            jacobian[b] = d;
            jdot_v[row] = dot(v[r.a], v[r.a]);
            break;
        }
        case ParticleSystem::ConstraintKind::fixed_point:
            c[row] = x[r.a].x - r.point.x;
            jacobian[b] = {1.0, 0.0};
            jdot_v[row] = 0.0;
            ++row;
            c[row] = x[r.a].y - r.point.y;
            jacobian[row_begin[row]] = {0.0, 1.0};
            jdot_v[row] = 0.0;
            break;
        case ParticleSystem::ConstraintKind::curve: {
            const CurveSample sample = s.curves_[r.extra](x[r.a]);
            const Vec2 u = v[r.a];
            c[row] = sample.value;
            jacobian[b] = sample.gradient;
            jdot_v[row] = sample.hxx * u.x * u.x + 2.0 * sample.hxy * u.x * u.y + sample.hyy * u.y * u.y;
            break;
        }
        case ParticleSystem::ConstraintKind::user: {
            const auto& user = s.users_[r.extra];
            const std::size_t k = user.particles.size();
            user_x.resize(k);
            user_v.resize(k);
            for (std::size_t i = 0; i < k; ++i) {
                user_x[i] = x[user.particles[i].index];
                user_v[i] = v[user.particles[i].index];
            }
            UserConstraintOutput out{0.0, std::span<Vec2>(jacobian.data() + b, k), 0.0};
            for (auto& j : out.jacobian) j = {};
            user.evaluate(user_x, user_v, out);
            c[row] = out.value;
            jdot_v[row] = out.jdot_v;
            break;
        }
        }
        ++row;
    }
    for (std::uint32_t r = 0; r < rows; ++r) {
        double cd = 0.0, g2 = 0.0;
        for (std::uint32_t b = row_begin[r]; b < row_begin[r + 1]; ++b) {
            cd += dot(jacobian[b], v[block_particle[b]]);
            g2 += length_squared(jacobian[b]);
        }
        c_dot[r] = cd;
        gradient_norm2[r] = g2;
    }
}

void SolverWorkspace::assemble() {
    const auto& w = owner->inverse_masses_;
    double* values = dense ? dense_matrix.data() : sparse_matrix.valuePtr();
    const std::size_t count = dense ? rows * rows : static_cast<std::size_t>(sparse_matrix.nonZeros());
    std::fill(values, values + count, 0.0);
    for (const auto& k : contributions) values[k.value] += w[k.particle] * dot(jacobian[k.block_i], jacobian[k.block_j]);
}

SolveStatus SolverWorkspace::solve() {
    const auto m = static_cast<Eigen::Index>(rows);
    const SolverDef& def = owner->def_.solver;
    SolveStatus status = SolveStatus::ok;
    if (dense) {
        if (m == 1) {  // one row (a bead, a pendulum): no factorization needed
            const double a = dense_matrix(0, 0);
            if (a > 0.0) {
                lambda(0) = rhs(0) / a;
            } else {
                lambda(0) = 0.0;
                status = SolveStatus::singular;
            }
        } else {
            ldlt.compute(dense_matrix);
            // Full expressions on vectorD(): no temporary vector, no allocation per solve.
            const double d_min = ldlt.vectorD().cwiseAbs().minCoeff();
            const double d_max = ldlt.vectorD().cwiseAbs().maxCoeff();
            if (ldlt.info() == Eigen::Success && d_min > singular_pivot_ratio * d_max) {
                lambda = ldlt.solve(rhs);
            } else {
                // Redundant rows: the minimum-norm least-squares multipliers.
                Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(dense_matrix);
                cod.setThreshold(singular_pivot_ratio);
                lambda = cod.solve(rhs);
                status = SolveStatus::singular;
            }
        }
    } else {
        bool use_cg = def.method == LinearSolver::conjugate_gradient;
        if (!use_cg) {
            sparse_ldlt.factorize(sparse_matrix);
            bool ok = sparse_ldlt.info() == Eigen::Success;
            if (ok) {
                const Eigen::VectorXd d = sparse_ldlt.vectorD().cwiseAbs();  // returned by value
                ok = d.minCoeff() > singular_pivot_ratio * d.maxCoeff();
            }
            if (ok) {
                lambda = sparse_ldlt.solve(rhs);
            } else {
                use_cg = true;  // CG copes with a consistent semi-definite system
                status = SolveStatus::singular;
            }
        }
        if (use_cg) {
            cg.setTolerance(def.cg_tolerance);
            cg.setMaxIterations(def.cg_max_iterations > 0 ? def.cg_max_iterations : static_cast<int>(4 * rows));
            cg.compute(sparse_matrix);
            lambda = cg.solveWithGuess(rhs, lambda_previous);
            cg_iterations += static_cast<int>(cg.iterations());
            if (cg.info() != Eigen::Success && status == SolveStatus::ok) status = SolveStatus::not_converged;
        }
    }
    if (!lambda.allFinite()) {
        lambda.setZero();
        status = SolveStatus::singular;
    }
    lambda_previous = lambda;
    note(status);
    return status;
}

void SolverWorkspace::note(SolveStatus status) noexcept {
    if (static_cast<int>(status) > static_cast<int>(worst)) worst = status;
}

std::size_t SolverWorkspace::size() const noexcept { return 2 * owner->size(); }

void SolverWorkspace::acceleration(double t, std::span<const double> q, std::span<const double> v,
                                   std::span<double> a) noexcept {
    ParticleSystem& s = *owner;
    const auto x = as_vec2(q);
    const auto u = as_vec2(v);
    s.apply_forces(t, x, u);
    auto& f = s.forces_;
    auto& fc = s.constraint_forces_;
    const auto& w = s.inverse_masses_;
    std::fill(fc.begin(), fc.end(), Vec2{});
    if (rows > 0) {
        evaluate_rows(x, u);
        assemble();
        for (std::uint32_t r = 0; r < rows; ++r) {
            double jwq = 0.0;
            for (std::uint32_t b = row_begin[r]; b < row_begin[r + 1]; ++b) {
                const auto p = block_particle[b];
                jwq += w[p] * dot(jacobian[b], f[p]);
            }
            rhs(r) = -jdot_v[r] - jwq - ks * c[r] - kd * c_dot[r];
        }
        solve();
        ++evaluations;
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
    const auto& w = owner->inverse_masses_;
    const DriftDef& drift = owner->def_.drift;
    auto worst_distance = [&] {
        double worst_d = 0.0;
        for (std::uint32_t r = 0; r < rows; ++r) {
            const double d = gradient_norm2[r] > 0.0 ? std::abs(c[r]) / std::sqrt(gradient_norm2[r])
                                                     : (c[r] == 0.0 ? 0.0 : std::numeric_limits<double>::infinity());
            worst_d = std::max(worst_d, d);
        }
        return worst_d;
    };
    // Positions: Newton on C(x + W Jᵀ δ) = 0 (mass-weighted, so pinned particles stay put).
    // Round-off floor of the distance |C|/|∇C| at the scene's coordinate scale: no Newton
    // iteration can go below it, so reaching it ends the projection.
    double scale = 1.0;
    for (const Vec2& p : x) scale = std::max(scale, 1.0 + std::max(std::abs(p.x), std::abs(p.y)));
    const double tolerance = std::max(drift.projection_tolerance, 8.0 * std::numeric_limits<double>::epsilon() * scale);
    int iterations = 0;
    evaluate_rows(x, v);
    double before = worst_distance();
    while (iterations < drift.projection_iterations && before > tolerance) {
        assemble();
        for (std::uint32_t r = 0; r < rows; ++r) rhs(r) = -c[r];
        solve();
        for (std::uint32_t r = 0; r < rows; ++r)
            for (std::uint32_t b = row_begin[r]; b < row_begin[r + 1]; ++b) {
                const auto p = block_particle[b];
                x[p] += w[p] * lambda(r) * jacobian[b];
            }
        ++iterations;
        evaluate_rows(x, v);
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
