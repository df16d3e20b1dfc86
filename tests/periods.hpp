// Periods for the dynamics tests: the complete elliptic integrals E(m) and K(m) of the closed
// forms, and the zero crossings a measured period is read from.
#pragma once

#include <grape/math.hpp>

#include <cmath>
#include <utility>
#include <vector>

namespace grape::testing {

// Complete elliptic integrals in parameter form by adaptive Gauss–Legendre quadrature of
// their defining integrals (smooth integrands for m < 1).
inline double elliptic_e(double m) {
    return integrate([m](double t) { return std::sqrt(1.0 - m * std::sin(t) * std::sin(t)); }, 0.0, pi / 2, 1e-15);
}
inline double elliptic_k(double m) {
    return integrate([m](double t) { return 1.0 / std::sqrt(1.0 - m * std::sin(t) * std::sin(t)); }, 0.0, pi / 2,
                     1e-15);
}

// Times where a sampled signal s(t) (with derivative ds) crosses zero, each located by the
// root of the cubic Hermite interpolant over its step.
struct ZeroCrossings {
    std::vector<double> times;
    bool have = false;
    double t0 = 0, s0 = 0, d0 = 0;
    void add(double t, double s, double d) {
        if (have && ((s0 < 0.0 && s >= 0.0) || (s0 > 0.0 && s <= 0.0))) {
            const double h = t - t0;
            auto hermite = [&](double u) {
                const double u2 = u * u, u3 = u2 * u;
                return std::pair{(2 * u3 - 3 * u2 + 1) * s0 + (u3 - 2 * u2 + u) * h * d0 + (-2 * u3 + 3 * u2) * s +
                                     (u3 - u2) * h * d,
                                 (6 * u2 - 6 * u) * s0 + (3 * u2 - 4 * u + 1) * h * d0 + (-6 * u2 + 6 * u) * s +
                                     (3 * u2 - 2 * u) * h * d};
            };
            times.push_back(t0 + h * find_root(hermite, 0.0, 1.0, 0.5, 1e-15).x);
        }
        have = true;
        t0 = t;
        s0 = s;
        d0 = d;
    }
    // Full period from the first and last crossing (crossings are half a period apart).
    double period() const { return 2.0 * (times.back() - times.front()) / static_cast<double>(times.size() - 1); }
};

}  // namespace grape::testing
