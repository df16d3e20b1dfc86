// The integrators: every one sees a SecondOrderSystem as the first-order state y = (q, v)
// with derivative (v, a(t, q, v)).
#include <grape/dynamics.hpp>

#include <algorithm>
#include <cmath>

namespace grape {

std::string_view to_string(Integrator integrator) noexcept {
    switch (integrator) {
    case Integrator::euler: return "euler";
    case Integrator::semi_implicit_euler: return "semi_implicit_euler";
    case Integrator::midpoint: return "midpoint";
    case Integrator::rk4: return "rk4";
    case Integrator::velocity_verlet: return "velocity_verlet";
    case Integrator::rk45: return "rk45";
    case Integrator::rattle: return "rattle";
    }
    return "unknown";
}

Integrator parse_integrator(std::string_view name) {
    for (Integrator i : all_integrators())
        if (name == to_string(i)) return i;
    if (name == "symplectic" || name == "symplectic_euler") return Integrator::semi_implicit_euler;
    if (name == "verlet") return Integrator::velocity_verlet;
    throw Error("integrator: unknown name '" + std::string(name) +
                "' (expected euler, symplectic, midpoint, rk4, verlet, rk45 or rattle)");
}

std::span<const Integrator> all_integrators() noexcept {
    static constexpr Integrator all[] = {Integrator::euler, Integrator::semi_implicit_euler, Integrator::midpoint,
                                         Integrator::rk4,   Integrator::velocity_verlet,     Integrator::rk45,
                                         Integrator::rattle};
    return all;
}

int order(Integrator integrator) noexcept {
    switch (integrator) {
    case Integrator::euler:
    case Integrator::semi_implicit_euler: return 1;
    case Integrator::midpoint:
    case Integrator::velocity_verlet:
    case Integrator::rattle: return 2;
    case Integrator::rk4: return 4;
    case Integrator::rk45: return 5;
    }
    return 0;
}

Stepper::Stepper(Integrator integrator, Rk45Def rk45) : integrator_(integrator), rk45_(rk45) {
    if (!(rk45.tolerance >= 0.0) || !std::isfinite(rk45.tolerance))
        throw Error("Rk45Def: tolerance must be finite and ≥ 0 (got " + std::to_string(rk45.tolerance) + ")");
    if (!(rk45.min_step > 0.0) || !std::isfinite(rk45.min_step))
        throw Error("Rk45Def: min_step must be positive and finite (got " + std::to_string(rk45.min_step) + ")");
    if (rk45.max_substeps < 1)
        throw Error("Rk45Def: max_substeps must be at least 1 (got " + std::to_string(rk45.max_substeps) + ")");
}

namespace {

// y = (q, v) as one array of 2n; dy = (v, a).
struct FirstOrder {
    SecondOrderSystem& system;
    std::size_t n;
    int evaluations = 0;
    void operator()(double t, const double* y, double* dy) noexcept {
        std::copy(y + n, y + 2 * n, dy);
        system.acceleration(t, {y, n}, {y + n, n}, {dy + n, n});
        ++evaluations;
    }
};

// Dormand–Prince 5(4) tableau (Hairer, Nørsett & Wanner, table 5.2).
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192, a75 = -2187.0 / 6784,
                 a76 = 11.0 / 84;
// 5th-order weights minus the embedded 4th-order ones: the local error estimate.
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                 e6 = 22.0 / 525, e7 = -1.0 / 40;

}  // namespace

StepStats Stepper::step(SecondOrderSystem& system, double t, std::span<double> q, std::span<double> v, double dt) {
    const std::size_t n = system.size();
    const std::size_t N = 2 * n;
    StepStats stats;
    if (n == 0) {
        stats.substeps = 1;
        return stats;
    }
    if (buffer_.size() < 11 * N) buffer_.resize(11 * N);
    double* y = buffer_.data();
    double* tmp = y + N;
    double* k1 = tmp + N;
    double* k2 = k1 + N;
    double* k3 = k2 + N;
    double* k4 = k3 + N;
    double* k5 = k4 + N;
    double* k6 = k5 + N;
    double* k7 = k6 + N;
    double* ynew = k7 + N;
    std::copy(q.begin(), q.end(), y);
    std::copy(v.begin(), v.end(), y + n);
    FirstOrder f{system, n};

    switch (integrator_) {
    case Integrator::euler:
        f(t, y, k1);
        for (std::size_t i = 0; i < N; ++i) y[i] += dt * k1[i];
        break;
    case Integrator::semi_implicit_euler:
        f(t, y, k1);
        for (std::size_t i = 0; i < n; ++i) {
            y[n + i] += dt * k1[n + i];
            y[i] += dt * y[n + i];
        }
        break;
    case Integrator::midpoint:
        f(t, y, k1);
        for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + 0.5 * dt * k1[i];
        f(t + 0.5 * dt, tmp, k2);
        for (std::size_t i = 0; i < N; ++i) y[i] += dt * k2[i];
        break;
    case Integrator::rk4:
        f(t, y, k1);
        for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + 0.5 * dt * k1[i];
        f(t + 0.5 * dt, tmp, k2);
        for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + 0.5 * dt * k2[i];
        f(t + 0.5 * dt, tmp, k3);
        for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + dt * k3[i];
        f(t + dt, tmp, k4);
        for (std::size_t i = 0; i < N; ++i) y[i] += dt / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
        break;
    case Integrator::velocity_verlet:
    case Integrator::rattle: {  // without constraints RATTLE is velocity Verlet
        // a depends on v here (curvature terms), so the new acceleration is taken at a
        // predicted velocity v + a·dt: still second order, no longer symplectic.
        f(t, y, k1);
        for (std::size_t i = 0; i < n; ++i) {
            tmp[i] = y[i] + dt * y[n + i] + 0.5 * dt * dt * k1[n + i];
            tmp[n + i] = y[n + i] + dt * k1[n + i];
        }
        f(t + dt, tmp, k2);
        for (std::size_t i = 0; i < n; ++i) {
            y[i] = tmp[i];
            y[n + i] += 0.5 * dt * (k1[n + i] + k2[n + i]);
        }
        break;
    }
    case Integrator::rk45: {
        const double tol = rk45_.tolerance;
        double h = tol > 0.0 && rk45_step_ > 0.0 ? std::min(rk45_step_, dt) : dt;
        double done = 0.0;
        bool have_k1 = false;
        bool last_rejected = false;
        while (done < dt) {
            // Split what is left of the frame into equal sub-steps no longer than h, so the
            // frame does not end with a sliver step.
            const double left = dt - done;
            const bool last = h >= left;
            if (last) h = left;
            else if (tol > 0.0) h = left / std::ceil(left / h);
            const double ts = t + done;
            if (!have_k1) f(ts, y, k1);
            for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + h * a21 * k1[i];
            f(ts + c2 * h, tmp, k2);
            for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + h * (a31 * k1[i] + a32 * k2[i]);
            f(ts + c3 * h, tmp, k3);
            for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + h * (a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
            f(ts + c4 * h, tmp, k4);
            for (std::size_t i = 0; i < N; ++i)
                tmp[i] = y[i] + h * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
            f(ts + c5 * h, tmp, k5);
            for (std::size_t i = 0; i < N; ++i)
                tmp[i] = y[i] + h * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
            f(ts + h, tmp, k6);
            for (std::size_t i = 0; i < N; ++i)
                ynew[i] = y[i] + h * (a71 * k1[i] + a73 * k3[i] + a74 * k4[i] + a75 * k5[i] + a76 * k6[i]);
            f(ts + h, ynew, k7);
            double err = 0.0;
            bool finite = true;
            for (std::size_t i = 0; i < N; ++i) finite = finite && std::isfinite(ynew[i]);
            if (tol > 0.0) {
                for (std::size_t i = 0; i < N; ++i) {
                    const double e = h * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
                    const double scale = tol * (1.0 + std::max(std::abs(y[i]), std::abs(ynew[i])));
                    const double ratio = std::abs(e) / scale;
                    if (!(ratio <= err)) err = ratio;  // keeps a NaN, which std::max would drop
                }
                finite = finite && std::isfinite(err);
            }
            // A non-finite state or error estimate does not improve with smaller sub-steps
            // (a NaN stays NaN): stop now instead of rejecting until max_substeps.
            if (!finite) {
                stats.status = SolveStatus::non_finite;
                break;
            }
            const bool forced = h <= rk45_.min_step || stats.substeps + stats.rejected >= rk45_.max_substeps;
            if (err <= 1.0 || forced || tol == 0.0) {
                std::copy(ynew, ynew + N, y);
                std::copy(k7, k7 + N, k1);  // first same as last
                have_k1 = true;
                done = last ? dt : done + h;
                ++stats.substeps;
                if (err > 1.0 && tol > 0.0) ++stats.forced;
                if (tol > 0.0) {
                    // Elementary controller, safety 0.9, growth limited to ×5 (×1 after a rejection).
                    double grow = err > 0.0 ? 0.9 * std::pow(err, -0.2) : 5.0;
                    grow = std::clamp(grow, 0.2, last_rejected ? 1.0 : 5.0);
                    // A step clipped to land on dt says nothing about the right size: keep the old one.
                    if (!last || rk45_step_ == 0.0 || h >= rk45_step_) rk45_step_ = h * grow;
                    h = rk45_step_;
                }
                last_rejected = false;
                if (stats.substeps + stats.rejected >= rk45_.max_substeps && done < dt) {
                    h = dt - done;  // give up control: finish the frame in one sub-step
                    stats.status = SolveStatus::substep_limit;
                }
            } else {
                ++stats.rejected;
                h *= std::clamp(0.9 * std::pow(err, -0.2), 0.1, 0.5);
                h = std::max(h, rk45_.min_step);
                last_rejected = true;
            }
        }
        break;
    }
    }
    bool finite = stats.status != SolveStatus::non_finite;
    for (std::size_t i = 0; i < N && finite; ++i) finite = std::isfinite(y[i]);
    if (!finite) stats.status = SolveStatus::non_finite;
    if (finite) {  // otherwise q and v stay as they were
        std::copy(y, y + n, q.begin());
        std::copy(y + n, y + N, v.begin());
    }
    stats.evaluations = f.evaluations;
    if (integrator_ != Integrator::rk45) stats.substeps = 1;
    return stats;
}

}  // namespace grape
