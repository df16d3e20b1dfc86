// The constraint rows of the Witkin system: C, ∇C, Ċ, J̇q̇ and the curvature of every row at
// (x, v), and the conditioning test that drops a row whose linearization cannot be trusted.
#include "witkin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grape::detail {

void SolverWorkspace::evaluate_rows_for_step(std::span<const Vec2> x, std::span<const Vec2> v) {
    evaluate_rows(x, v);
    rows_x.assign(x.begin(), x.end());
    rows_v.assign(v.begin(), v.end());
    rows_remembered = true;
}

void SolverWorkspace::evaluate_rows(std::span<const Vec2> x, std::span<const Vec2> v) {
    rows_remembered = false;
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
            curvature[row] = 2.0;  // the Hessian [I −I; −I I] of ½|xb − xa|²
            break;
        }
        case ConstraintKind::anchor: {
            const Vec2 d = x[r.a] - r.point;
            c[row] = 0.5 * (dot(d, d) - r.length * r.length);
            jacobian[b] = d;
            jdot_v[row] = dot(v[r.a], v[r.a]);
            c_dot[row] = dot(d, v[r.a]);
            gradient_norm2[row] = dot(d, d);
            curvature[row] = 1.0;
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
            const ImplicitSample sample = view.curves[r.extra](x[r.a]);
            const Vec2 u = v[r.a];
            c[row] = sample.value;
            jacobian[b] = sample.gradient;
            jdot_v[row] = sample.hxx * u.x * u.x + 2.0 * sample.hxy * u.x * u.y + sample.hyy * u.y * u.y;
            c_dot[row] = dot(sample.gradient, u);
            gradient_norm2[row] = length_squared(sample.gradient);
            // |H·n̂|, n̂ = ∇C/|∇C|: how fast the gradient changes along the Newton step.
            const double g = std::sqrt(gradient_norm2[row]);
            const Vec2 n = g > 0.0 ? sample.gradient / g : Vec2{};
            curvature[row] = std::hypot(sample.hxx * n.x + sample.hxy * n.y, sample.hxy * n.x + sample.hyy * n.y);
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
    rows_remembered = false;
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
            gradient_norm2[row] = 2.0 * d2;
            rhs(row) = -trusted_value(row);
            if (!degenerate[row]) worst2 = std::max(worst2, value * value / (2.0 * d2));
            break;
        }
        case ConstraintKind::anchor: {
            const Vec2 d = x[r.a] - r.point;
            const double d2 = dot(d, d);
            const double value = 0.5 * (d2 - r.length * r.length);
            c[row] = value;
            gradient_norm2[row] = d2;
            rhs(row) = -trusted_value(row);
            if (!degenerate[row]) worst2 = std::max(worst2, value * value / d2);
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
            for (std::uint32_t k = 0; k < rows; ++k) rhs(k) = -trusted_value(k);
            return worst_distance();
        }
        ++row;
    }
    // A zero |∇C| with C ≠ 0 gave inf or NaN above: report it as worst_distance does.
    return std::isnan(worst2) ? std::numeric_limits<double>::infinity() : std::sqrt(worst2);
}


double SolverWorkspace::worst_distance() const noexcept {
    double worst_d = 0.0;
    for (std::uint32_t r = 0; r < rows; ++r) {
        if (degenerate[r]) continue;  // dropped: no correction is made along it
        const double d = gradient_norm2[r] > 0.0 ? std::abs(c[r]) / std::sqrt(gradient_norm2[r])
                                                 : (c[r] == 0.0 ? 0.0 : std::numeric_limits<double>::infinity());
        worst_d = std::max(worst_d, d);
    }
    return worst_d;
}


bool SolverWorkspace::mark_degenerate(double condition) {
    bool changed = false, any = false;
    for (std::uint32_t r = 0; r < rows; ++r) {
        // κ = |C|·h/|∇C|² ≥ condition, without the division (a zero gradient with C ≠ 0 is degenerate too).
        const double g2 = gradient_norm2[r];
        const bool bad = g2 > 0.0 ? std::abs(c[r]) * curvature[r] >= condition * g2 : c[r] != 0.0;
        changed = changed || bad != static_cast<bool>(degenerate[r]);
        degenerate[r] = bad;
        any = any || bad;
        if (bad)
            for (std::uint32_t b = row_begin[r]; b < row_begin[r + 1]; ++b) jacobian[b] = {};
    }
    any_degenerate = any;
    if (any) note(SolveStatus::singular);
    if (changed) factor_current = false;
    return changed;
}

}  // namespace grape::detail
