// Factorizations and solves of J W Jᵀ λ = b: envelope (skyline) Cholesky, tridiagonal LDLᵀ,
// Eigen's sparse LDLᵀ, and the least-squares / conjugate-gradient fallbacks for singular systems.
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
}  // namespace

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
    if (any_degenerate)  // a dropped row asks for no correction
        for (std::uint32_t r = 0; r < rows; ++r)
            if (degenerate[r]) rhs(r) = 0.0;
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


}  // namespace grape::detail
