// RATTLE on the Witkin system (Andersen 1983; Leimkuhler & Reich, "Simulating Hamiltonian
// Dynamics", §7.2): with G₀ = ∇C(x₀)ᵀ and W the inverse masses,
//   v½ = v₀ + ½h·W(f₀ + G₀ᵀλ),  x₁ = x₀ + h·v½,  C(x₁) = 0        (λ: SHAKE's multiplier)
//   v₁ = v½ + ½h·W(f₁ + G₁ᵀμ),  G₁·v₁ = 0                        (μ: one linear solve)
// λ starts at Witkin's multiplier (the acceleration solve at x₀, whose J̇q̇ term makes the
// predicted x₁ miss C = 0 by O(h³) only) and is corrected by Newton on C(x₀ + h·v½(λ)) with
// the factor of G₀WG₀ᵀ, the chord method: it converges at the rate the rods turn in one step.
// Where they turn fast the iteration refactors at the current positions (full Newton, along
// the current gradients: the correction left then is round-off). The factor of G₁WG₁ᵀ serves
// the velocity stage and is kept for the next step's start, so a step factors once.
#include "witkin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grape::detail {

namespace {
// The chord iteration is kept while each pass shrinks the worst distance at least this much;
// slower than that (rods turning by more than ~0.25 rad per step), a fresh factor pays off.
constexpr double chord_rate = 0.25;
constexpr double chord_passes = 2.0;
}  // namespace

// Calls visit(row, block, particle) for every block of every row; rows of two blocks each
// (rods between particles, the common case) take a loop without the per-row bounds.
template <class Visit>
void SolverWorkspace::each_block(Visit visit) const {
    if (two_block_rows) {
        for (std::uint32_t r = 0; r < rows; ++r) {
            visit(r, 2 * r, block_particle[2 * r]);
            visit(r, 2 * r + 1, block_particle[2 * r + 1]);
        }
        return;
    }
    for (std::uint32_t r = 0; r < rows; ++r)
        for (std::uint32_t b = row_begin[r]; b < row_begin[r + 1]; ++b) visit(r, b, block_particle[b]);
}

bool SolverWorkspace::rattle_step(double t, std::span<Vec2> x, std::span<Vec2> v, double h, int& iterations) {
    // The rows were evaluated at (x₀, v₀) by the caller (which refuses degenerate ones).
    const auto& w = view.inverse_masses;
    auto& f = forces;
    auto& fc = constraint_forces;
    const std::size_t n = x.size();
    x_start.assign(x.begin(), x.end());
    v_start.assign(v.begin(), v.end());
    iterations = 0;

    // Kick and drift with a first guess of the multipliers at x₀: the previous step's SHAKE
    // multipliers when its factor is still current (they are forces, and change by O(h)
    // per step, as Witkin's do within one), else Witkin's.
    view.apply_forces(view.system, t, x, v, f);
    std::fill(fc.begin(), fc.end(), Vec2{});
    if (rows > 0) {
        // SHAKE must reach C(x₁) = 0 within the step: rows whose linearization cannot (κ ≥ 1)
        // are dropped from the whole step (their G₀ blocks are zero).
        mark_degenerate(1.0);
        jacobian_start.assign(jacobian.begin(), jacobian.end());
        if (!factor_current || !have_witkin_lambda) {
            assemble();
            factorize();
            for (std::uint32_t r = 0; r < rows; ++r) rhs(r) = -jdot_v[r];
            each_block([&](std::uint32_t r, std::uint32_t b, std::uint32_t p) { rhs(r) -= w[p] * dot(jacobian[b], f[p]); });
            solve_factored();
            ++evaluations;
            for (std::uint32_t r = 0; r < rows; ++r) witkin_lambda[r] = lambda(r);
            have_witkin_lambda = true;
        }
        each_block([&](std::uint32_t r, std::uint32_t b, std::uint32_t p) { fc[p] += witkin_lambda[r] * jacobian[b]; });
    }
    double scale = 1.0;  // coordinate scale for the round-off floor of the projection
    for (std::size_t p = 0; p < n; ++p) {
        v[p] += (0.5 * h * w[p]) * (f[p] + fc[p]);
        x[p] += h * v[p];
        scale = std::max(scale, 1.0 + std::max(std::abs(x[p].x), std::abs(x[p].y)));
    }

    if (rows > 0) {
        // SHAKE: Newton on C(x₁) = 0, x₁ moving along W G₀ᵀ (and v½ with it, by 1/h).
        const DriftDef& drift = *view.drift;
        const double tolerance = std::max(drift.projection_tolerance, 8.0 * std::numeric_limits<double>::epsilon() * scale);
        const double inverse_h = 1.0 / h;
        const double to_force = 2.0 / (h * h);  // a correction W G₀ᵀδ is δ·2/h² of multiplier
        double before = evaluate_values(x, v);
        bool chord = true;  // with G₀'s factor; false: refactored at the current positions
        while (iterations < drift.projection_iterations && before > tolerance) {
            if (!chord) {
                evaluate_rows(x, v);
                mark_degenerate(1.0);
                assemble();
                factorize();
                for (std::uint32_t r = 0; r < rows; ++r) rhs(r) = -trusted_value(r);
            }
            solve_factored();  // rhs = −C, written by evaluate_values
            const std::vector<Vec2>& g = chord ? jacobian_start : jacobian;
            const double* l = lambda.data();
            each_block([&](std::uint32_t r, std::uint32_t b, std::uint32_t p) {
                const Vec2 dx = (w[p] * l[r]) * g[b];
                x[p] += dx;
                v[p] += inverse_h * dx;
            });
            for (std::uint32_t r = 0; r < rows; ++r) witkin_lambda[r] += to_force * lambda(r);
            ++iterations;
            const double after = evaluate_values(x, v);
            if (!(after < before)) {
                if (!chord) break;  // round-off: Newton no longer gains
                chord = false;
            } else if (chord && after > tolerance) {
                // Linear convergence at rate ρ needs log(tol/after)/log(ρ) more passes; past
                // chord_passes of them one factor at the current positions is cheaper.
                const double rate = after / before;
                if (rate > chord_rate || std::log(tolerance / after) < chord_passes * std::log(rate)) chord = false;
            }
            before = after;
        }
    }
    // Kick with f₁, then project v₁ onto G₁v = 0 with G₁WG₁ᵀ factored once.
    view.apply_forces(view.system, t + h, x, v, f);
    bool ok = true;  // finite x and v here, with a finite μ (solve_factored's guarantee), stay finite
    for (std::size_t p = 0; p < n; ++p) {
        v[p] += (0.5 * h * w[p]) * f[p];
        ok = ok && is_finite(x[p]) && is_finite(v[p]);
    }
    if (rows > 0) {
        evaluate_rows(x, v);
        mark_degenerate(1.0);
        assemble();
        factorize();
        for (std::uint32_t r = 0; r < rows; ++r) rhs(r) = -c_dot[r];
        solve_factored();
        const double* l = lambda.data();
        each_block([&](std::uint32_t r, std::uint32_t b, std::uint32_t p) { v[p] += (w[p] * l[r]) * jacobian[b]; });
        factor_current = factor == Factor::ok;
    }
    if (!ok) {
        std::copy(x_start.begin(), x_start.end(), x.begin());
        std::copy(v_start.begin(), v_start.end(), v.begin());
        factor_current = false;
        have_witkin_lambda = false;
    }
    return ok;
}

double SolverWorkspace::stiffest_mode() noexcept {
    // Gershgorin on W·K, K the stiffness of the constraint forces (λ times the Hessian of
    // C = ½(|d|² − L²): ±λ·I blocks, row sum 2|λ| for a rod between two particles, |λ|
    // for a rod to an anchor) and of the springs (k along the spring plus the tension
    // |T|/len across it, row sum ≤ 2(k + |T|/len); the grab spring's k).
    std::vector<double>& sum = stiffness_sum;
    sum.assign(view.particles, 0.0);  // no allocation once sized
    if (have_witkin_lambda) {
        std::uint32_t row = 0;
        for (const auto& r : view.constraints) {
            const double l = std::abs(witkin_lambda[row]);
            switch (r.kind) {
            case ConstraintKind::distance:
                sum[r.a] += 2.0 * l;
                sum[r.b] += 2.0 * l;
                break;
            case ConstraintKind::anchor: sum[r.a] += l; break;
            case ConstraintKind::fixed_point: ++row; break;  // constant gradient: no stiffness
            case ConstraintKind::curve:
            case ConstraintKind::user: break;  // their Hessians are not known here
            }
            ++row;
        }
    }
    for (const auto& spring : view.springs) {
        const Vec2 d = view.positions[spring.b] - view.positions[spring.a];
        const double len = length(d);
        const double k = spring.def.stiffness;
        const double across = len > 0.0 ? std::abs(k * (len - spring.def.rest_length)) / len : 0.0;
        sum[spring.a] += 2.0 * (k + across);
        sum[spring.b] += 2.0 * (k + across);
    }
    if (view.grab) sum[view.grab->particle] += view.grab->k;  // a spring to a fixed point: k·I
    double omega2 = 0.0;
    for (std::size_t p = 0; p < sum.size(); ++p) omega2 = std::max(omega2, view.inverse_masses[p] * sum[p]);
    return std::sqrt(omega2);
}

}  // namespace grape::detail
