// A damped spring as a curve: m·x″ + c·x′ + k·x = 0, x(0) = 1, x′(0) = −v0, progress 1 − x,
// in closed form. With ρ = ζ·ω0 = c/(2m) and B = ρ − v0:
//   under-damped (ζ < 1), ωd = ω0·√(1 − ζ²):  x = e^(−ρτ)·(cos ωdτ + B·sin(ωdτ)/ωd)
//   critically damped (ζ = 1):               x = e^(−ρτ)·(1 + B·τ)
//   over-damped (ζ > 1), γ = ω0·√(ζ² − 1):    x = e^(−ρτ)·(cosh γτ + B·sinh(γτ)/γ)
// The three are one formula (sin(ωτ)/ω → τ ← sinh(γτ)/γ), so springs next to ζ = 1 lose nothing.
#include "curve_data.hpp"

#include <grape/curve.hpp>
#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace grape {

namespace detail {

double spring_offset(const SpringData& d, double tau) noexcept {
    const double decay = std::exp(-d.zeta_omega * tau);
    switch (d.regime) {
        case SpringData::Regime::under: {
            const double a = d.omega * tau;
            return decay * (std::cos(a) + d.b * (std::sin(a) / d.omega));
        }
        case SpringData::Regime::critical: return decay * (1.0 + d.b * tau);
        case SpringData::Regime::over: {
            const double a = d.omega * tau;
            if (a < 20.0) return decay * (std::cosh(a) + d.b * (std::sinh(a) / d.omega));
            // cosh and sinh would overflow long before e^(−ρτ) underflows: the two modes apart,
            // e^(−(ρ−γ)τ) with ρ − γ = ω0²/(ρ + γ) (no cancellation), e^(−(ρ+γ)τ) ≤ e^(−40) of it.
            const double r = d.b / d.omega;
            return 0.5 * (std::exp(-d.slow * tau) * (1.0 + r) + std::exp(-(d.zeta_omega + d.omega) * tau) * (1.0 - r));
        }
    }
    return 0.0;
}

double spring_eval(const CurveData& base, double t) noexcept {
    const auto& d = static_cast<const SpringData&>(base);
    if (!(t > 0.0)) return std::isnan(t) ? t : 0.0;
    if (t >= 1.0) return 1.0;
    return 1.0 - spring_offset(d, t * d.span) + t * d.end_offset;
}

}  // namespace detail

namespace {

using detail::number_text;
using detail::SpringData;

// The τ in [lo, hi] where |x| falls to the tolerance, |x| decreasing through it there
// (|x(lo)| > tol ≥ |x(hi)|): bisection to adjacent doubles.
double fall_time(const SpringData& d, double lo, double hi) noexcept {
    for (int i = 0; i < 2100; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        (std::abs(detail::spring_offset(d, mid)) > spring_settle_tolerance ? lo : hi) = mid;
    }
    return hi;
}

// Half-oscillations of an under-damped spring before it settles, at most: a million, far more
// than any animation shows (a frame would hold thousands of swings).
constexpr double max_half_periods = 1e6;

// The spring time after which |x| stays within the tolerance: the last fall of |x| through it;
// NaN for an under-damped spring that swings more than max_half_periods times first.
// |x| is monotone between consecutive extrema of x, so the fall lies after the last extremum
// (or the release) where |x| still exceeds the tolerance, before the next extremum.
double settle_time(const SpringData& d, double v0) noexcept {
    const double tol = spring_settle_tolerance;
    const double rho = d.zeta_omega;
    if (d.regime == SpringData::Regime::under) {
        // x′ = −e^(−ρτ)·(v0·cos ωdτ + (ωd + ρB/ωd)·sin ωdτ): extrema at τn = (φ + nπ)/ωd, and
        // x(τn + π/ωd) = −e^(−ρπ/ωd)·x(τn), so |x| at the extrema falls by a fixed ratio.
        const double w = d.omega;
        constexpr double pi = 3.141592653589793;
        double phi = std::atan2(-v0, w + rho * d.b / w);  // tan φ = −v0 / (ωd + ρB/ωd), φ in [0, π)
        if (phi < 0.0) phi += pi;
        if (phi >= pi) phi -= pi;
        const double half = pi / w;
        const auto at = [&](double n) { return phi / w + n * half; };
        const double first = std::abs(detail::spring_offset(d, at(0.0)));
        if (!(first > tol)) return fall_time(d, 0.0, at(0.0));  // |x| falls from 1 before the first extremum
        double n = std::floor(std::log(first / tol) / (rho * half));
        // Beyond max_half_periods no animation could show the swings, and n ± 1 stops
        // changing n long before n reaches 2^53: refused (NaN) rather than stepped through.
        if (!(n <= max_half_periods)) return std::nan("");
        // n is the exact count to rounding: a step or two corrects it
        for (int k = 0; k < 64 && n > 0.0 && !(std::abs(detail::spring_offset(d, at(n))) > tol); ++k) n -= 1.0;
        for (int k = 0; k < 64 && std::abs(detail::spring_offset(d, at(n + 1.0))) > tol; ++k) n += 1.0;
        return fall_time(d, at(n), at(n + 1.0));
    }
    // Critical and over-damped: at most one extremum after release, where x′ = 0.
    double extremum = 0.0;
    if (d.regime == SpringData::Regime::critical) {
        // x′ = −e^(−ρτ)·(v0 + ρBτ)
        const double e = -v0 / (rho * d.b);
        if (e > 0.0 && std::isfinite(e)) extremum = e;
    } else {
        // x′ = −e^(−ρτ)·(v0·cosh γτ + (ρB/γ − γ)·sinh γτ): tanh γτ = v0·γ / (γ² − ρB)
        const double g = d.omega;
        const double r = v0 * g / (g * g - rho * d.b);
        if (r > 0.0 && r < 1.0) extremum = std::atanh(r) / g;
    }
    double lo = 0.0;
    if (extremum > 0.0 && std::abs(detail::spring_offset(d, extremum)) > tol) lo = extremum;
    // Past lo, |x| decreases until it crosses the tolerance (or 0, then rises to the extremum,
    // which stays within it): double the step until |x| is within it.
    const double rate = d.regime == SpringData::Regime::over ? d.slow : rho;
    double hi = lo + 1.0 / rate;
    if (extremum > lo) hi = std::min(hi, extremum);
    for (int i = 0; i < 2100 && std::abs(detail::spring_offset(d, hi)) > tol; ++i) hi = lo + 2.0 * (hi - lo);
    return fall_time(d, lo, hi);
}

void check_positive(const char* where, const char* what, double v) {
    if (!(std::isfinite(v) && v > 0.0))
        throw Error(std::string(where) + ": " + what + " must be finite and > 0 (got " + number_text(v) + ")");
}

}  // namespace

Curve Curve::spring(const SpringCurveDef& def) {
    const char* where = "Curve::spring";
    check_positive(where, "stiffness", def.stiffness);
    check_positive(where, "damping", def.damping);
    check_positive(where, "mass", def.mass);
    if (!std::isfinite(def.velocity))
        throw Error(std::string(where) + ": velocity must be finite (got " + number_text(def.velocity) + ")");
    const double omega0 = std::sqrt(def.stiffness / def.mass);
    const double zeta = def.damping / (2.0 * std::sqrt(def.stiffness * def.mass));
    auto d = std::make_shared<SpringData>();
    d->zeta_omega = def.damping / (2.0 * def.mass);
    d->b = d->zeta_omega - def.velocity;
    if (zeta < 1.0) {
        d->regime = SpringData::Regime::under;
        d->omega = omega0 * std::sqrt((1.0 - zeta) * (1.0 + zeta));
    } else if (zeta > 1.0) {
        d->regime = SpringData::Regime::over;
        d->omega = omega0 * std::sqrt((zeta - 1.0) * (zeta + 1.0));
        d->slow = omega0 * omega0 / (d->zeta_omega + d->omega);
    } else {
        d->regime = SpringData::Regime::critical;
    }
    if (!(std::isfinite(omega0) && omega0 > 0.0 && std::isfinite(zeta) && zeta > 0.0 && std::isfinite(d->b) &&
          (d->regime == SpringData::Regime::critical || (std::isfinite(d->omega) && d->omega > 0.0))))
        throw Error(std::string(where) + ": stiffness " + number_text(def.stiffness) + ", damping " +
                    number_text(def.damping) + " and mass " + number_text(def.mass) +
                    " give a spring whose rates a double cannot hold");
    d->span = settle_time(*d, def.velocity);
    if (std::isnan(d->span))
        throw Error(std::string(where) + ": the spring swings more than a million times before it settles (stiffness " +
                    number_text(def.stiffness) + ", damping " + number_text(def.damping) + ", mass " +
                    number_text(def.mass) + ")");
    if (!(std::isfinite(d->span) && d->span > 0.0))
        throw Error(std::string(where) + ": the spring does not settle in a time a double can hold (stiffness " +
                    number_text(def.stiffness) + ", damping " + number_text(def.damping) + ")");
    d->end_offset = detail::spring_offset(*d, d->span);
    Curve c;
    c.kind_ = CurveKind::spring;
    c.p_[0] = def.stiffness;
    c.p_[1] = def.damping;
    c.p_[2] = def.mass;
    c.p_[3] = def.velocity;
    c.data_ = std::move(d);
    return c;
}

Curve Curve::spring_duration(double duration, double bounce, double velocity) {
    const char* where = "Curve::spring_duration";
    check_positive(where, "duration", duration);
    if (!(bounce > -1.0 && bounce < 1.0))
        throw Error(std::string(where) + ": bounce must be in (-1, 1) (got " + number_text(bounce) + ")");
    constexpr double two_pi = 2.0 * 3.141592653589793;
    const double omega0 = two_pi / duration;
    const double damping = bounce >= 0.0 ? 2.0 * omega0 * (1.0 - bounce) : 2.0 * omega0 / (1.0 + bounce);
    Curve c = spring({.stiffness = omega0 * omega0, .damping = damping, .mass = 1.0, .velocity = velocity});
    auto d = std::make_shared<SpringData>(detail::data_of<SpringData>(c));
    d->by_duration = true;
    c.data_ = std::move(d);
    c.p_[0] = duration;
    c.p_[1] = bounce;
    c.p_[2] = velocity;
    c.p_[3] = 0.0;
    return c;
}

}  // namespace grape
