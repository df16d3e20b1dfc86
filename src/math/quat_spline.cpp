// The C² quaternion spline: keys aligned, the angular velocities at the keys solved for C²,
// evaluation of the cumulative form and of its angular velocity.
#include <grape/error.hpp>
#include <grape/quat_spline.hpp>

#include "math/quat_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace grape {

namespace {

// The cumulative cubic Bernstein basis and its derivatives in u.
struct SplineBasis {
    double b1, b2, b3, d1, d2, d3;
};
SplineBasis spline_basis(double u) noexcept {
    const double v = 1.0 - u;
    return {1.0 - v * v * v, u * u * (3.0 - 2.0 * u), u * u * u, 3.0 * v * v, 6.0 * u * v, 3.0 * u * u};
}

// A symmetric tridiagonal system (lower = upper) factored once (Thomas), solved for three
// right-hand sides at a time (the components of Vec3s).
struct SplineTridiagonal {
    std::vector<double> diag, off, m, dinv;  // off[i] couples i and i + 1
    void factor() {
        const std::size_t n = diag.size();
        m.assign(n, 0.0);
        dinv.assign(n, 0.0);
        double d = diag[0];
        dinv[0] = 1.0 / d;
        for (std::size_t i = 1; i < n; ++i) {
            m[i] = off[i - 1] * dinv[i - 1];
            d = diag[i] - m[i] * off[i - 1];
            dinv[i] = 1.0 / d;
        }
    }
    void solve(std::vector<Vec3>& x) const noexcept {
        const std::size_t n = diag.size();
        for (std::size_t i = 1; i < n; ++i) x[i] -= x[i - 1] * m[i];
        x[n - 1] *= dinv[n - 1];
        for (std::size_t i = n - 1; i-- > 0;) x[i] = (x[i] - x[i + 1] * off[i]) * dinv[i];
    }
};

// A 3×3 block of the Jacobian of the C² conditions.
struct SplineBlock {
    double m[3][3] = {};
    SplineBlock operator*(const SplineBlock& o) const noexcept {
        SplineBlock r;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) r.m[i][j] = m[i][0] * o.m[0][j] + m[i][1] * o.m[1][j] + m[i][2] * o.m[2][j];
        return r;
    }
    SplineBlock operator-(const SplineBlock& o) const noexcept {
        SplineBlock r;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) r.m[i][j] = m[i][j] - o.m[i][j];
        return r;
    }
    Vec3 operator*(Vec3 v) const noexcept {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
};
// The inverse by cofactors (the blocks are well conditioned: near the linear solution each is
// −2(1/h + 1/h′)·I plus terms of the size of the turns).
SplineBlock spline_inverse(const SplineBlock& a) noexcept {
    const auto& m = a.m;
    SplineBlock r;
    r.m[0][0] = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    r.m[0][1] = m[0][2] * m[2][1] - m[0][1] * m[2][2];
    r.m[0][2] = m[0][1] * m[1][2] - m[0][2] * m[1][1];
    r.m[1][0] = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    r.m[1][1] = m[0][0] * m[2][2] - m[0][2] * m[2][0];
    r.m[1][2] = m[0][2] * m[1][0] - m[0][0] * m[1][2];
    r.m[2][0] = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    r.m[2][1] = m[0][1] * m[2][0] - m[0][0] * m[2][1];
    r.m[2][2] = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    const double det = m[0][0] * r.m[0][0] + m[0][1] * r.m[1][0] + m[0][2] * r.m[2][0];
    for (auto& row : r.m)
        for (double& x : row) x /= det;
    return r;
}
double& spline_component(Vec3& v, int k) noexcept { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

std::string spline_index_text(std::size_t i) { return std::to_string(i); }

}  // namespace

QuatSpline::QuatSpline(std::vector<double> params, std::vector<Quat> keys)
    : params_(std::move(params)), keys_(std::move(keys)) {
    const std::size_t n = keys_.size();
    if (n == 0) throw Error("QuatSpline: keys is empty (one key at least)");
    if (params_.size() != n)
        throw Error("QuatSpline: params has " + spline_index_text(params_.size()) + " values for " +
                    spline_index_text(n) + " keys");
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(params_[i])) throw Error("QuatSpline: params[" + spline_index_text(i) + "] is not finite");
        if (i > 0 && !(params_[i] > params_[i - 1]))
            throw Error("QuatSpline: params[" + spline_index_text(i) + "] is not greater than params[" +
                        spline_index_text(i - 1) + "]");
        // The step to the next parameter must be finite too (1e308 − (−1e308) is not).
        if (i > 0 && !std::isfinite(params_[i] - params_[i - 1]))
            throw Error("QuatSpline: params[" + spline_index_text(i) + "] − params[" + spline_index_text(i - 1) +
                        "] is not finite");
        const Quat& k = keys_[i];
        if (!is_finite(k)) throw Error("QuatSpline: keys[" + spline_index_text(i) + "] is not finite");
        if (k.w == 0.0 && k.x == 0.0 && k.y == 0.0 && k.z == 0.0)
            throw Error("QuatSpline: keys[" + spline_index_text(i) + "] is zero");
        keys_[i] = normalized(k);
        if (i > 0 && dot(keys_[i - 1], keys_[i]) < 0.0) keys_[i] = -keys_[i];
    }
    velocity_.assign(n, Vec3{});
    if (n == 1) return;

    const std::size_t m = n - 1;
    std::vector<double> h(m);
    std::vector<Quat> rel(m);
    for (std::size_t i = 0; i < m; ++i) {
        h[i] = params_[i + 1] - params_[i];
        rel[i] = conjugate(keys_[i]) * keys_[i + 1];
    }
    // The linear part of the C² conditions in v (see residual below): the system of a natural
    // cubic spline's slopes.
    SplineTridiagonal j;
    j.diag.assign(n, 0.0);
    j.off.assign(m, 0.0);
    for (std::size_t i = 0; i < m; ++i) {
        j.diag[i] += 2.0 / h[i];
        j.diag[i + 1] += 2.0 / h[i];
        j.off[i] = 1.0 / h[i];
    }
    j.factor();

    segments_.assign(m, Segment{});
    std::vector<Vec3> f(n), f2(n), v2(n), back(m);
    // The residual of the C² conditions at v: 6× the jumps of the angular acceleration over
    // two, in the body axes of key i. Its linear part at v = 0 is rhs − J·v, J the tridiagonal
    // above, so the first step from v = 0 is the linear (natural cubic) solution.
    const auto residual = [&](const std::vector<Vec3>& v, std::vector<Vec3>& out) {
        for (std::size_t i = 0; i < m; ++i) {
            Segment& s = segments_[i];
            s.inv_h = 1.0 / h[i];
            s.a = v[i] * (h[i] / 6.0);
            s.c = v[i + 1] * (h[i] / 6.0);
            s.b = detail::log_half(detail::exp_half(-s.a) * rel[i] * detail::exp_half(-s.c));
            back[i] = rotate(conjugate(detail::exp_half(s.c)), s.b);  // b seen from the segment's end
        }
        for (std::size_t i = 0; i < n; ++i) {
            Vec3 r{};
            if (i < m) r += (segments_[i].b - segments_[i].a) * (6.0 / (h[i] * h[i]));
            if (i > 0) r -= (segments_[i - 1].c - back[i - 1]) * (6.0 / (h[i - 1] * h[i - 1]));
            out[i] = r;
        }
    };
    // Newton's method on the block-tridiagonal Jacobian (F_i depends on v_{i−1}, v_i, v_{i+1}),
    // its columns by forward differences: perturbing every third v at once gives three columns
    // of nine blocks in one residual, so nine residuals make the whole Jacobian. The differences'
    // relative error (~1e-7) only slows the final steps, each of which still gains seven digits.
    std::vector<SplineBlock> lower(n), diag(n), upper(n);
    std::vector<double> eta(n, 0.0);
    residual(velocity_, f);
    j.solve(f);
    for (std::size_t i = 0; i < n; ++i) velocity_[i] += f[i];  // the linear solution
    double previous = std::numeric_limits<double>::infinity();
    bool converged = false;
    std::vector<Vec3> residual_at_start(n);
    const auto norm_of = [&](const std::vector<Vec3>& r) {
        double sum = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const double w = std::max(i < m ? h[i] : 0.0, i > 0 ? h[i - 1] : 0.0);
            sum += length_squared(r[i]) * (w * w);
        }
        return sum;
    };
    for (iterations_ = 1; iterations_ <= max_iterations; ++iterations_) {
        residual(velocity_, f);
        residual_at_start = f;
        for (int color = 0; color < 3; ++color) {
            for (int k = 0; k < 3; ++k) {
                std::fill(eta.begin(), eta.end(), 0.0);
                v2 = velocity_;
                for (std::size_t i = static_cast<std::size_t>(color); i < n; i += 3) {
                    const double hi = std::min(i < m ? h[i] : h[i - 1], i > 0 ? h[i - 1] : h[i]);
                    eta[i] = 0x1p-26 * std::max(length(velocity_[i]), 1.0 / hi);  // √ε of its scale
                    spline_component(v2[i], k) += eta[i];
                }
                residual(v2, f2);
                for (std::size_t i = 0; i < n; ++i) {
                    // Row i feels the one perturbed v among i − 1, i, i + 1.
                    const std::size_t jcol = i % 3 == static_cast<std::size_t>(color)       ? i
                                             : (i + 1) % 3 == static_cast<std::size_t>(color) ? i + 1
                                                                                              : i - 1;
                    if (jcol >= n) continue;
                    const Vec3 col = (f2[i] - f[i]) / eta[jcol];
                    SplineBlock& b = jcol == i ? diag[i] : jcol == i + 1 ? upper[i] : lower[i];
                    b.m[0][k] = col.x;
                    b.m[1][k] = col.y;
                    b.m[2][k] = col.z;
                }
            }
        }
        // Solve J·Δ = −F (block Thomas: J is diagonally dominant near the linear solution).
        for (std::size_t i = 0; i < n; ++i) f[i] = -f[i];
        for (std::size_t i = 1; i < n; ++i) {
            const SplineBlock g = lower[i] * spline_inverse(diag[i - 1]);
            diag[i] = diag[i] - g * upper[i - 1];
            f[i] -= g * f[i - 1];
        }
        f[n - 1] = spline_inverse(diag[n - 1]) * f[n - 1];
        for (std::size_t i = n - 1; i-- > 0;) f[i] = spline_inverse(diag[i]) * (f[i] - upper[i] * f[i + 1]);
        // Damped: the step is halved (up to 20 times) while it does not lower the residual's
        // norm, rows weighted by their longer step (a Newton step is a descent direction for
        // any such fixed weighting). Far from the solution, with uneven spacing and large turns,
        // the full step can overshoot into a worse region.
        // Steps that move no control by more than 1e-3 rad are left whole: there the residual
        // is quadratic in the step to within 1e-6 of itself, and near the solution rounding noise
        // would otherwise read as growth.
        double full = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            full = std::max(full, length(f[i]) * std::max(i < m ? h[i] : 0.0, i > 0 ? h[i - 1] : 0.0) / 6.0);
        const double before = norm_of(residual_at_start);
        double lambda = 1.0;
        for (int halvings = 0;; ++halvings) {
            for (std::size_t i = 0; i < n; ++i) v2[i] = velocity_[i] + f[i] * lambda;
            if (full <= 1e-3) break;
            residual(v2, f2);
            const double after = norm_of(f2);
            if (after <= before || halvings == 20) break;
            lambda *= 0.5;
        }
        double step = 0.0, size = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            velocity_[i] = v2[i];
            // Steps measured as the half angles they move a control by (v·h/6).
            const double hi = std::max(i < m ? h[i] : 0.0, i > 0 ? h[i - 1] : 0.0);
            step = std::max(step, length(f[i]) * lambda * hi / 6.0);
            size = std::max(size, length(velocity_[i]) * hi / 6.0);
        }
        if (!std::isfinite(step)) break;
        if (lambda < 1.0) {  // not yet in Newton's region: the tests below are for full steps
            previous = std::numeric_limits<double>::infinity();
            continue;
        }
        // Converged to rounding: a step below 2⁻⁵⁰ of the controls, or one that no longer
        // shrinks tenfold once below 1e-12 of them (rounding noise in the residual).
        if (step <= 0x1p-50 * std::max(size, 1e-300) || (step <= 1e-12 * size && step > 0.1 * previous)) {
            converged = true;
            break;
        }
        previous = step;
    }
    if (!converged)
        throw Error("QuatSpline: keys: the C² solve did not converge in " + spline_index_text(max_iterations) +
                    " iterations (neighbouring keys too far apart for their spacing in params)");
    residual(velocity_, f);  // the segments of the final v
}

std::size_t QuatSpline::segment_of(double t) const noexcept {
    const auto it = std::upper_bound(params_.begin(), params_.end(), t);
    const std::size_t i = static_cast<std::size_t>(it - params_.begin());
    return std::min(i == 0 ? 0 : i - 1, segments_.size() - 1);
}

Quat QuatSpline::orientation(double t) const noexcept {
    if (!(t > params_.front()) || segments_.empty()) return keys_.front();  // NaN too
    if (t >= params_.back()) return keys_.back();
    const std::size_t i = segment_of(t);
    const Segment& s = segments_[i];
    const SplineBasis b = spline_basis((t - params_[i]) * s.inv_h);
    return keys_[i] * detail::exp_half(s.a * b.b1) * detail::exp_half(s.b * b.b2) * detail::exp_half(s.c * b.b3);
}

Vec3 QuatSpline::angular_velocity(double t) const noexcept {
    if (segments_.empty() || !(t >= params_.front()) || t > params_.back()) return {};
    const std::size_t i = segment_of(t);
    const Segment& s = segments_[i];
    const SplineBasis b = spline_basis(std::min(1.0, (t - params_[i]) * s.inv_h));
    const Quat e1 = detail::exp_half(s.a * b.b1), e2 = detail::exp_half(s.b * b.b2), e3 = detail::exp_half(s.c * b.b3);
    // q⁻¹·dq/du = Ad((e2·e3)⁻¹)(a·β₁′) + Ad(e3⁻¹)(b·β₂′) + c·β₃′; the body angular velocity is
    // twice that over h, the world one that rotated by q.
    const Vec3 body = rotate(conjugate(e3), rotate(conjugate(e2), s.a * b.d1) + s.b * b.d2) + s.c * b.d3;
    return rotate(keys_[i] * e1 * e2 * e3, body * (2.0 * s.inv_h));
}

Vec3 QuatSpline::key_angular_velocity(std::size_t i) const noexcept { return rotate(keys_[i], velocity_[i]); }

}  // namespace grape
