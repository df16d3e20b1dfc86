// Witkin's constrained dynamics: J W Jᵀ λ = −J̇q̇ − J W Q − ks·C − kd·Ċ, force Jᵀλ.
// About 600 lines: the row evaluation, the assembly and the three factorizations (envelope,
// tridiagonal, sparse) share one row and block layout that would otherwise be exposed.
#include "witkin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grape::detail {

namespace {
// Pivots below this fraction of their diagonal entry mark J W Jᵀ as singular (redundant
// rows): a regular system of moderate condition keeps its pivots far above it, while a
// redundant row's pivot is round-off, ~1e-16 of its diagonal.
constexpr double singular_pivot_ratio = 1e-11;

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
    worst = SolveStatus::ok;
    evaluations = 0;
    cg_iterations = 0;
}

void SolverWorkspace::build_topology() {
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
        if (solver.method != LinearSolver::conjugate_gradient) sparse_ldlt.analyzePattern(sparse_matrix);
    }
    dirty = false;
}

void SolverWorkspace::evaluate_rows(std::span<const Vec2> x, std::span<const Vec2> v) {
    // The built-in kinds write Ċ and |∇C|² with their row; only user rows take the general
    // pass over their blocks at the end.
    std::uint32_t row = 0;
    bool any_user = false;
    for (const auto& r : view.constraints) {
        const std::uint32_t b = row_begin[row];
        switch (r.kind) {
        case ConstraintKind::distance: {
            const Vec2 d = x[r.b] - x[r.a];
            const Vec2 w = v[r.b] - v[r.a];
            c[row] = 0.5 * (dot(d, d) - r.length * r.length);
            jacobian[b] = -d;
            jacobian[b + 1] = d;
            jdot_v[row] = dot(w, w);
            c_dot[row] = dot(d, w);
            gradient_norm2[row] = 2.0 * dot(d, d);
            break;
        }
        case ConstraintKind::anchor: {
            const Vec2 d = x[r.a] - r.point;
            c[row] = 0.5 * (dot(d, d) - r.length * r.length);
            jacobian[b] = d;
            jdot_v[row] = dot(v[r.a], v[r.a]);
            c_dot[row] = dot(d, v[r.a]);
            gradient_norm2[row] = dot(d, d);
            break;
        }
        case ConstraintKind::fixed_point:
            c[row] = x[r.a].x - r.point.x;
            jacobian[b] = {1.0, 0.0};
            jdot_v[row] = 0.0;
            c_dot[row] = v[r.a].x;
            gradient_norm2[row] = 1.0;
            ++row;
            c[row] = x[r.a].y - r.point.y;
            jacobian[row_begin[row]] = {0.0, 1.0};
            jdot_v[row] = 0.0;
            c_dot[row] = v[r.a].y;
            gradient_norm2[row] = 1.0;
            break;
        case ConstraintKind::curve: {
            const CurveSample sample = view.curves[r.extra](x[r.a]);
            const Vec2 u = v[r.a];
            c[row] = sample.value;
            jacobian[b] = sample.gradient;
            jdot_v[row] = sample.hxx * u.x * u.x + 2.0 * sample.hxy * u.x * u.y + sample.hyy * u.y * u.y;
            c_dot[row] = dot(sample.gradient, u);
            gradient_norm2[row] = length_squared(sample.gradient);
            break;
        }
        case ConstraintKind::user: {
            const auto& user = view.users[r.extra];
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
            any_user = true;
            break;
        }
        }
        ++row;
    }
    if (!any_user) return;
    for (std::uint32_t r = 0; r < rows; ++r) {
        if (view.constraints[row_constraint[r]].kind != ConstraintKind::user) continue;
        double cd = 0.0, g2 = 0.0;
        for (std::uint32_t b = row_begin[r]; b < row_begin[r + 1]; ++b) {
            cd += dot(jacobian[b], v[block_particle[b]]);
            g2 += length_squared(jacobian[b]);
        }
        c_dot[r] = cd;
        gradient_norm2[r] = g2;
    }
}

double SolverWorkspace::evaluate_values(std::span<const Vec2> x, std::span<const Vec2> v) {
    // Rods, anchors and fixed points in one light pass; any other kind takes evaluate_rows.
    std::uint32_t row = 0;
    double worst2 = 0.0;  // max C²/|∇C|²
    for (const auto& r : view.constraints) {
        switch (r.kind) {
        case ConstraintKind::distance: {
            const Vec2 d = x[r.b] - x[r.a];
            const double d2 = dot(d, d);
            const double value = 0.5 * (d2 - r.length * r.length);
            c[row] = value;
            rhs(row) = -value;
            gradient_norm2[row] = 2.0 * d2;
            worst2 = std::max(worst2, value * value / (2.0 * d2));
            break;
        }
        case ConstraintKind::anchor: {
            const Vec2 d = x[r.a] - r.point;
            const double d2 = dot(d, d);
            const double value = 0.5 * (d2 - r.length * r.length);
            c[row] = value;
            rhs(row) = -value;
            gradient_norm2[row] = d2;
            worst2 = std::max(worst2, value * value / d2);
            break;
        }
        case ConstraintKind::fixed_point:
            c[row] = x[r.a].x - r.point.x;
            rhs(row) = -c[row];
            ++row;
            c[row] = x[r.a].y - r.point.y;
            rhs(row) = -c[row];
            worst2 = std::max({worst2, c[row - 1] * c[row - 1], c[row] * c[row]});
            break;
        case ConstraintKind::curve:
        case ConstraintKind::user:
            evaluate_rows(x, v);
            for (std::uint32_t k = 0; k < rows; ++k) rhs(k) = -c[k];
            return worst_distance();
        }
        ++row;
    }
    // A zero |∇C| with C ≠ 0 gave inf or NaN above: report it as worst_distance does.
    return std::isnan(worst2) ? std::numeric_limits<double>::infinity() : std::sqrt(worst2);
}

void SolverWorkspace::assemble() {
    const auto& w = view.inverse_masses;
    double* values = skyline ? sky_matrix.data() : sparse_matrix.valuePtr();
    const std::size_t count = skyline ? sky_matrix.size() : static_cast<std::size_t>(sparse_matrix.nonZeros());
    std::fill(values, values + count, 0.0);
    for (const auto& k : contributions) values[k.value] += w[k.particle] * dot(jacobian[k.block_i], jacobian[k.block_j]);
}

bool SolverWorkspace::factor_skyline() noexcept {
    // Unpivoted Cholesky: J W Jᵀ is symmetric positive definite unless rows are redundant.
    // Each pivot L_ii² is the part of A_ii not explained by the rows before it: a tiny ratio
    // means row i is (numerically) a combination of them.
    // The solves are serial chains of dependent operations, so the factor keeps 1/L_ii
    // (multiplications instead of divisions on the critical path).
    const double* a = sky_matrix.data();
    double* l = sky_factor.data();
    double* inverse = sky_inverse_diagonal.data();
    for (std::size_t i = 0; i < rows; ++i) {
        double* li = l + offset[i] - first[i];  // li[k] = L(i, k) for k ≥ first[i]
        for (std::size_t j = first[i]; j <= i; ++j) {
            const double* lj = l + offset[j] - first[j];
            double sum = a[offset[i] + j - first[i]];
            for (std::size_t k = std::max(first[i], first[j]); k < j; ++k) sum -= li[k] * lj[k];
            if (j < i) {
                li[j] = sum * inverse[j];
            } else {
                const double diagonal = a[offset[i] + i - first[i]];
                if (!(sum > singular_pivot_ratio * diagonal)) return false;
                li[i] = std::sqrt(sum);
                inverse[i] = 1.0 / li[i];
            }
        }
    }
    return true;
}

void SolverWorkspace::solve_skyline() noexcept {
    const double* l = sky_factor.data();
    const double* inverse = sky_inverse_diagonal.data();
    double* y = sky_work.data();
    for (std::size_t i = 0; i < rows; ++i) {  // L y = rhs
        const double* li = l + offset[i] - first[i];
        double sum = rhs(static_cast<Eigen::Index>(i));
        for (std::size_t k = first[i]; k < i; ++k) sum -= li[k] * y[k];
        y[i] = sum * inverse[i];
    }
    for (std::size_t i = rows; i-- > 0;) {  // Lᵀ λ = y, column by column
        const double* li = l + offset[i] - first[i];
        y[i] *= inverse[i];
        for (std::size_t k = first[i]; k < i; ++k) y[k] -= li[k] * y[i];
    }
    for (std::size_t i = 0; i < rows; ++i) lambda(static_cast<Eigen::Index>(i)) = y[i];
}

SolveStatus SolverWorkspace::solve_skyline_singular() {
    const auto m = static_cast<Eigen::Index>(rows);
    const SolverDef& def = *view.solver;
    if (rows <= 256) {
        // Redundant rows: the minimum-norm least-squares multipliers.
        Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, m);
        for (std::size_t i = 0; i < rows; ++i)
            for (std::size_t j = first[i]; j <= i; ++j)
                a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
                    a(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i)) = sky_matrix[offset[i] + j - first[i]];
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(a);
        cod.setThreshold(singular_pivot_ratio);
        lambda = cod.solve(rhs);
        return SolveStatus::singular;
    }
    // Large: Jacobi-preconditioned conjugate gradient on the envelope storage, warm-started.
    auto multiply = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
        y.setZero();
        for (std::size_t i = 0; i < rows; ++i)
            for (std::size_t j = first[i]; j <= i; ++j) {
                const double v = sky_matrix[offset[i] + j - first[i]];
                y(static_cast<Eigen::Index>(i)) += v * x(static_cast<Eigen::Index>(j));
                if (j != i) y(static_cast<Eigen::Index>(j)) += v * x(static_cast<Eigen::Index>(i));
            }
    };
    Eigen::VectorXd inverse_diagonal(m), r(m), z(m), p(m), q(m);
    for (std::size_t i = 0; i < rows; ++i) {
        const double d = sky_matrix[offset[i] + i - first[i]];
        inverse_diagonal(static_cast<Eigen::Index>(i)) = d > 0.0 ? 1.0 / d : 1.0;
    }
    lambda = lambda_previous;
    multiply(lambda, q);
    r = rhs - q;
    z = inverse_diagonal.cwiseProduct(r);
    p = z;
    double rz = r.dot(z);
    const double target = def.cg_tolerance * def.cg_tolerance * rhs.squaredNorm();
    const int limit = def.cg_max_iterations > 0 ? def.cg_max_iterations : static_cast<int>(4 * rows);
    int iterations = 0;
    while (r.squaredNorm() > target && iterations < limit) {
        multiply(p, q);
        const double pq = p.dot(q);
        if (!(pq > 0.0)) break;  // p in the null space: nothing left to reduce
        const double alpha = rz / pq;
        lambda += alpha * p;
        r -= alpha * q;
        z = inverse_diagonal.cwiseProduct(r);
        const double rz_next = r.dot(z);
        p = z + (rz_next / rz) * p;
        rz = rz_next;
        ++iterations;
    }
    cg_iterations += iterations;
    return r.squaredNorm() > target ? SolveStatus::not_converged : SolveStatus::singular;
}

bool SolverWorkspace::factor_tridiagonal() noexcept {
    // LDLᵀ of the tridiagonal envelope: d_i = a_ii − a_{i,i−1}²/d_{i−1}, with the multipliers
    // m_i = a_{i,i−1}/d_{i−1} (0 for a row that couples to nothing before it) and 1/d_i in
    // their own arrays, so the solves are two branch-free recurrences. The pivot test is the
    // Cholesky one (d_i is L_ii²).
    const double* a = sky_matrix.data();
    double* m = tri_multiplier.data();
    double* inverse = sky_inverse_diagonal.data();
    double d = a[0];
    if (!(d > 0.0)) return false;
    m[0] = 0.0;
    inverse[0] = 1.0 / d;
    for (std::size_t i = 1; i < rows; ++i) {
        const std::size_t at = offset[i];
        const double diagonal = a[offset[i + 1] - 1];
        const double below = first[i] == i ? 0.0 : a[at];
        m[i] = below * inverse[i - 1];
        d = diagonal - m[i] * below;
        if (!(d > singular_pivot_ratio * diagonal)) return false;
        inverse[i] = 1.0 / d;
    }
    return true;
}

void SolverWorkspace::solve_tridiagonal() noexcept {
    const double* m = tri_multiplier.data();
    const double* inverse = sky_inverse_diagonal.data();
    const double* b = rhs.data();
    double* y = lambda.data();
    double previous = b[0];
    y[0] = previous;
    for (std::size_t i = 1; i < rows; ++i) {  // L y = rhs (unit lower bidiagonal)
        previous = b[i] - m[i] * previous;
        y[i] = previous;
    }
    double next = y[rows - 1] * inverse[rows - 1];  // D Lᵀ λ = y
    y[rows - 1] = next;
    for (std::size_t i = rows - 1; i-- > 0;) {
        next = y[i] * inverse[i] - m[i + 1] * next;
        y[i] = next;
    }
}

void SolverWorkspace::factorize() {
    const SolverDef& def = *view.solver;
    factor_current = false;
    if (skyline && rows == 1) {
        factor = sky_matrix[0] > 0.0 ? Factor::ok : Factor::singular;
    } else if (skyline) {
        factor = (tridiagonal ? factor_tridiagonal() : factor_skyline()) ? Factor::ok : Factor::singular;
    } else if (def.method == LinearSolver::conjugate_gradient) {
        factor = Factor::iterative;
    } else {
        sparse_ldlt.factorize(sparse_matrix);
        bool ok = sparse_ldlt.info() == Eigen::Success;
        if (ok) {
            // The same test on the pivots D_ii against the diagonal (vectorD() returns a copy).
            const Eigen::VectorXd d = sparse_ldlt.vectorD();
            const Eigen::VectorXd a = sparse_matrix.diagonal();
            ok = (d.array() > singular_pivot_ratio * a.array()).all();
        }
        factor = ok ? Factor::ok : Factor::singular;
    }
}

SolveStatus SolverWorkspace::solve() {
    factorize();
    return solve_factored();
}

SolveStatus SolverWorkspace::solve_factored() {
    const SolverDef& def = *view.solver;
    SolveStatus status = SolveStatus::ok;
    if (skyline && rows == 1) {  // one row (a bead on a curve, a pendulum): a division
        const double a = sky_matrix[0];
        lambda(0) = factor == Factor::ok ? rhs(0) / a : 0.0;
        if (factor != Factor::ok) status = SolveStatus::singular;
    } else if (skyline) {
        if (factor == Factor::ok) {
            if (tridiagonal) solve_tridiagonal();
            else solve_skyline();
        } else {
            status = solve_skyline_singular();
        }
    } else if (factor == Factor::ok) {
        lambda = sparse_ldlt.solve(rhs);
    } else {
        // CG by choice, or because the LDLT failed (CG copes with a consistent semi-definite system).
        if (factor == Factor::singular) status = SolveStatus::singular;
        cg.setTolerance(def.cg_tolerance);
        cg.setMaxIterations(def.cg_max_iterations > 0 ? def.cg_max_iterations : static_cast<int>(4 * rows));
        cg.compute(sparse_matrix);
        lambda = cg.solveWithGuess(rhs, lambda_previous);
        cg_iterations += static_cast<int>(cg.iterations());
        if (cg.info() != Eigen::Success && status == SolveStatus::ok) status = SolveStatus::not_converged;
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

double SolverWorkspace::worst_distance() const noexcept {
    double worst_d = 0.0;
    for (std::uint32_t r = 0; r < rows; ++r) {
        const double d = gradient_norm2[r] > 0.0 ? std::abs(c[r]) / std::sqrt(gradient_norm2[r])
                                                 : (c[r] == 0.0 ? 0.0 : std::numeric_limits<double>::infinity());
        worst_d = std::max(worst_d, d);
    }
    return worst_d;
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
