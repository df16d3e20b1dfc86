// The constraint rows of the Witkin system: C, ∇C, Ċ, J̇q̇ and the curvature of every row at
// (x, v), and the conditioning test that drops a row whose linearization cannot be trusted.
#include "witkin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grape::detail {

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


double SolverWorkspace::worst_distance() const noexcept {
    double worst_d = 0.0;
    for (std::uint32_t r = 0; r < rows; ++r) {
        const double d = gradient_norm2[r] > 0.0 ? std::abs(c[r]) / std::sqrt(gradient_norm2[r])
                                                 : (c[r] == 0.0 ? 0.0 : std::numeric_limits<double>::infinity());
        worst_d = std::max(worst_d, d);
    }
    return worst_d;
}


}  // namespace grape::detail
