// grape — PathND: N numbers through keyframes, linear or by cubic splines, and their arc length.
#include "kinds.hpp"
#include "path_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace grape {

using namespace path_checks;

namespace {

constexpr double eps_nd = std::numeric_limits<double>::epsilon();

std::vector<double> checked_keys(std::size_t dimension, std::span<const double> keys, const char* name = "keyframes") {
    const char* who = "PathND";
    if (dimension == 0) fail(who, "dimension must be at least 1 (got 0)");
    if (keys.size() % dimension != 0) {
        fail(who, std::string(name) + " must hold a multiple of dimension " + std::to_string(dimension) + " values (got " +
                      std::to_string(keys.size()) + ")");
    }
    if (keys.size() / dimension < 2) {
        fail(who, std::string(name) + " needs at least 2 keyframes (got " + std::to_string(keys.size() / dimension) + ")");
    }
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (!std::isfinite(keys[i])) {
            fail(who, std::string(name) + "[" + std::to_string(i) + "] must be finite (got " + text(keys[i]) + ")");
        }
    }
    return {keys.begin(), keys.end()};
}

std::vector<double> joined(std::span<const double> from, std::span<const double> to) {
    if (from.size() != to.size()) {
        fail("PathND", "from and to must have the same size (got " + std::to_string(from.size()) + " and " +
                           std::to_string(to.size()) + ")");
    }
    std::vector<double> keys(from.begin(), from.end());
    keys.insert(keys.end(), to.begin(), to.end());
    return keys;
}

double distance_nd(const double* a, const double* b, std::size_t n) noexcept {
    double sum = 0.0;
    for (std::size_t k = 0; k < n; ++k) sum += (b[k] - a[k]) * (b[k] - a[k]);
    return std::sqrt(sum);
}

// Appends c0..c3 of the cubic Hermite segment from p1 to p2 with tangents m1, m2 (per local t).
void push_hermite_nd(std::vector<double>& coef, const double* p1, const double* p2, const double* m1, const double* m2,
                     std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
        coef.push_back(p1[k]);
        coef.push_back(m1[k]);
        coef.push_back(3.0 * (p2[k] - p1[k]) - 2.0 * m1[k] - m2[k]);
        coef.push_back(2.0 * (p1[k] - p2[k]) + m1[k] + m2[k]);
    }
}

// Panels of [a, b] on which `rule` agrees with its two halves within `allowed` (or 64 ulp of
// the panel's share of `whole_speed` per unit u, the rounding of the speed itself), after at
// least 2 halvings (halves that agree by chance on a coarse panel end nothing). Work is
// bounded: at most 40 halvings and `budget` panels.
template <class Rule>
void panels_nd(const Rule& rule, double a, double b, double whole, double allowed, double speed, int depth,
               std::size_t& budget, std::vector<double>& u, std::vector<double>& len) {
    const double m = 0.5 * (a + b);
    const double left = rule(a, m), right = rule(m, b);
    const double resolved = allowed + (b - a) * 64 * eps_nd * speed + 64 * eps_nd * whole;
    if (depth >= 40 || budget <= 2 || (depth >= 2 && std::abs(left + right - whole) <= resolved) || !(a < m && m < b)) {
        u.push_back(a);
        len.push_back(left + right);
        if (budget > 0) --budget;
        return;
    }
    --budget;
    panels_nd(rule, a, m, left, allowed, speed, depth + 1, budget, u, len);
    panels_nd(rule, m, b, right, allowed, speed, depth + 1, budget, u, len);
}

// The t in (0, 1) where the speed of one segment (c: c0..c3 per dimension) has a minimum or a
// maximum: roots of d|P′|²/dt / 2 = P′·P″, a cubic, each bracketed between the cubic's own
// turning points and bisected to adjacent doubles. The speed has a kink where it reaches 0
// (a 1-D value turning back, a cusp) and bends sharply near a small minimum; with a panel edge
// there, each side is smooth for the Gauss rule.
std::vector<double> speed_turns_nd(const double* c, std::size_t n) {
    double a0 = 0.0, a1 = 0.0, a2 = 0.0, a3 = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        // (A + B·t + C·t²)(D + E·t) with P′ = A + B·t + C·t², P″ = D + E·t.
        const double A = c[4 * k + 1], B = 2.0 * c[4 * k + 2], C = 3.0 * c[4 * k + 3], D = B, E = 6.0 * c[4 * k + 3];
        a0 += A * D;
        a1 += A * E + B * D;
        a2 += B * E + C * D;
        a3 += C * E;
    }
    auto f = [&](double t) { return ((a3 * t + a2) * t + a1) * t + a0; };
    std::vector<double> edges{0.0};
    // Turning points of the cubic: 3·a3·t² + 2·a2·t + a1 = 0.
    const double qa = 3.0 * a3, qb = 2.0 * a2, qc = a1;
    if (qa != 0.0) {
        const double disc = qb * qb - 4.0 * qa * qc;
        if (disc > 0.0) {
            const double r = std::sqrt(disc);
            const double t0 = (-qb - r) / (2.0 * qa), t1 = (-qb + r) / (2.0 * qa);
            for (const double t : {std::min(t0, t1), std::max(t0, t1)}) {
                if (t > 0.0 && t < 1.0) edges.push_back(t);
            }
        }
    } else if (qb != 0.0) {
        const double t = -qc / qb;
        if (t > 0.0 && t < 1.0) edges.push_back(t);
    }
    edges.push_back(1.0);
    std::vector<double> roots;
    for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
        double lo = edges[i], hi = edges[i + 1];
        double flo = f(lo);
        const double fhi = f(hi);
        if (flo == 0.0 || fhi == 0.0 || (flo < 0.0) == (fhi < 0.0)) continue;
        for (int step = 0; step < 80; ++step) {
            const double mid = 0.5 * (lo + hi);
            if (!(lo < mid && mid < hi)) break;
            const double fm = f(mid);
            if ((fm < 0.0) == (flo < 0.0)) {
                lo = mid;
                flo = fm;
            } else {
                hi = mid;
            }
        }
        const double t = 0.5 * (lo + hi);
        if (t > 0.0 && t < 1.0 && (roots.empty() || t > roots.back())) roots.push_back(t);
    }
    return roots;
}

}  // namespace

PathND::PathND(std::span<const double> from, std::span<const double> to)
    : PathND(from.size(), std::span<const double>(joined(from, to))) {}

PathND::PathND(std::size_t dimension, std::span<const double> keyframes)
    : dimension_(dimension), keys_(checked_keys(dimension, keyframes)) {}

PathND::PathND(PathNDKind kind, std::size_t dimension, std::vector<double> keys, std::vector<double> coefficients)
    : kind_(kind), dimension_(dimension), keys_(std::move(keys)), coef_(std::move(coefficients)) {
    const std::size_t segments = keyframe_count() - 1;
    const double width = 1.0 / static_cast<double>(segments);
    std::vector<double> len;
    for (std::size_t i = 0; i < segments; ++i) {
        const double a = static_cast<double>(i) * width, b = i + 1 == segments ? 1.0 : static_cast<double>(i + 1) * width;
        const auto rule = [this](double x, double y) { return gauss(x, y); };
        const double whole = gauss(a, b);
        std::vector<double> cuts{a};
        for (const double t : speed_turns_nd(coef_.data() + 4 * i * dimension_, dimension_)) {
            const double c = a + (b - a) * t;
            if (c > cuts.back() && c < b) cuts.push_back(c);
        }
        cuts.push_back(b);
        std::size_t budget = 4096;
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
            const double x = cuts[k], y = cuts[k + 1];
            panels_nd(rule, x, y, gauss(x, y), 1e-15 * whole * (y - x) / (b - a), whole / (b - a), 0, budget, panel_u_, len);
        }
    }
    panel_s_.reserve(panel_u_.size() + 1);
    double s = 0.0;
    for (const double l : len) {
        panel_s_.push_back(s);
        s += l;
    }
    panel_u_.push_back(1.0);
    panel_s_.push_back(s);
}

PathND PathND::catmull_rom(std::size_t dimension, std::span<const double> keyframes, CatmullRom type) {
    std::vector<double> keys = checked_keys(dimension, keyframes);
    const std::size_t n = keys.size() / dimension, d = dimension;
    const double alpha = type == CatmullRom::uniform ? 0.0 : type == CatmullRom::centripetal ? 0.5 : 1.0;
    // Knot spacing |Δp|^α; coincident points would give 0, so they fall back to 1 (uniform).
    auto spacing = [alpha, d](const double* a, const double* b) {
        const double s = alpha == 0.0 ? 1.0 : std::pow(distance_nd(a, b, d), alpha);
        return s > 0.0 ? s : 1.0;
    };
    std::vector<double> coef, p0(d), p3(d), m1(d), m2(d);
    coef.reserve(4 * (n - 1) * d);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const double* p1 = keys.data() + i * d;
        const double* p2 = p1 + d;
        // Phantom points mirror the neighbour at the ends.
        for (std::size_t k = 0; k < d; ++k) {
            p0[k] = i > 0 ? keys[(i - 1) * d + k] : 2.0 * p1[k] - p2[k];  // the key before p1
            p3[k] = i + 2 < n ? keys[(i + 2) * d + k] : 2.0 * p2[k] - p1[k];  // the key after p2
        }
        const double d01 = spacing(p0.data(), p1), d12 = spacing(p1, p2), d23 = spacing(p2, p3.data());
        // Barry–Goldman tangents in knot units, scaled to the segment's local t by d12.
        for (std::size_t k = 0; k < d; ++k) {
            m1[k] = ((p1[k] - p0[k]) / d01 - (p2[k] - p0[k]) / (d01 + d12) + (p2[k] - p1[k]) / d12) * d12;
            m2[k] = ((p2[k] - p1[k]) / d12 - (p3[k] - p1[k]) / (d12 + d23) + (p3[k] - p2[k]) / d23) * d12;
        }
        push_hermite_nd(coef, p1, p2, m1.data(), m2.data(), d);
    }
    return PathND(PathNDKind::catmull_rom, dimension, std::move(keys), std::move(coef));
}

PathND PathND::hermite(std::size_t dimension, std::span<const double> keyframes, std::span<const double> tangents) {
    std::vector<double> keys = checked_keys(dimension, keyframes);
    if (tangents.size() != keys.size()) {
        fail("PathND", "tangents must hold as many values as keyframes (got " + std::to_string(tangents.size()) + " and " +
                           std::to_string(keys.size()) + ")");
    }
    const std::vector<double> tans = checked_keys(dimension, tangents, "tangents");
    const std::size_t n = keys.size() / dimension, d = dimension;
    std::vector<double> coef;
    coef.reserve(4 * (n - 1) * d);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        push_hermite_nd(coef, keys.data() + i * d, keys.data() + (i + 1) * d, tans.data() + i * d, tans.data() + (i + 1) * d, d);
    }
    return PathND(PathNDKind::hermite, dimension, std::move(keys), std::move(coef));
}

void PathND::point(double u, std::span<double> out) const noexcept {
    const std::size_t segments = keyframe_count() - 1;
    const std::size_t n = std::min(out.size(), dimension_);
    double t;
    if (kind_ == PathNDKind::linear) {
        // Outside [0, 1] the end segments extend linearly (t leaves [0, 1]).
        std::size_t i = detail::segment_of(u * static_cast<double>(segments), segments, t);
        if (u < 0.0) t = u * static_cast<double>(segments);
        if (u > 1.0) t = 1.0 + (u - 1.0) * static_cast<double>(segments);
        const double* a = keys_.data() + i * dimension_;
        const double* b = a + dimension_;
        for (std::size_t k = 0; k < n; ++k) out[k] = a[k] + (b[k] - a[k]) * t;
        return;
    }
    const std::size_t i = detail::segment_of(u * static_cast<double>(segments), segments, t);
    const double* c = coef_.data() + 4 * i * dimension_;
    if (t == 1.0) {
        // The last keyframe exactly (the cubic's sum c0 + c1 + c2 + c3 rounds), then along the
        // end tangent beyond it.
        const double* key = keys_.data() + (i + 1) * dimension_;
        const double beyond = u > 1.0 ? (u - 1.0) * static_cast<double>(segments) : 0.0;
        for (std::size_t k = 0; k < n; ++k) {
            const double* ck = c + 4 * k;
            out[k] = key[k] + (ck[1] + 2.0 * ck[2] + 3.0 * ck[3]) * beyond;
        }
        return;
    }
    const double before = u < 0.0 ? u * static_cast<double>(segments) : 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double* ck = c + 4 * k;
        out[k] = u < 0.0 ? ck[0] + ck[1] * before : ((ck[3] * t + ck[2]) * t + ck[1]) * t + ck[0];
    }
}

void PathND::d1(double u, std::span<double> out) const noexcept {
    const std::size_t segments = keyframe_count() - 1;
    const std::size_t n = std::min(out.size(), dimension_);
    double t;
    const std::size_t i = detail::segment_of(u * static_cast<double>(segments), segments, t);
    const double scale = static_cast<double>(segments);
    if (kind_ == PathNDKind::linear) {
        const double* a = keys_.data() + i * dimension_;
        const double* b = a + dimension_;
        for (std::size_t k = 0; k < n; ++k) out[k] = (b[k] - a[k]) * scale;
        return;
    }
    const double* c = coef_.data() + 4 * i * dimension_;
    for (std::size_t k = 0; k < n; ++k) {
        const double* ck = c + 4 * k;
        out[k] = ((3.0 * ck[3] * t + 2.0 * ck[2]) * t + ck[1]) * scale;
    }
}

double PathND::speed(double u) const noexcept {
    const std::size_t segments = keyframe_count() - 1;
    double t;
    const std::size_t i = detail::segment_of(u * static_cast<double>(segments), segments, t);
    const double* c = coef_.data() + 4 * i * dimension_;
    double sum = 0.0;
    for (std::size_t k = 0; k < dimension_; ++k) {
        const double* ck = c + 4 * k;
        const double v = (3.0 * ck[3] * t + 2.0 * ck[2]) * t + ck[1];
        sum += v * v;
    }
    return std::sqrt(sum) * static_cast<double>(segments);
}

// 5-point Gauss–Legendre rule for the length on [a, b] (inside one segment).
double PathND::gauss(double a, double b) const noexcept {
    static constexpr double x[5] = {0.0, 0.5384693101056831, -0.5384693101056831, 0.9061798459386640, -0.9061798459386640};
    static constexpr double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                                    0.2369268850561891};
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    double sum = 0.0;
    for (int k = 0; k < 5; ++k) sum += w[k] * speed(mid + half * x[k]);
    return sum * half;
}

double PathND::length() const noexcept {
    if (kind_ != PathNDKind::linear) return panel_s_.back();
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < keyframe_count(); ++i) {
        sum += distance_nd(keys_.data() + i * dimension_, keys_.data() + (i + 1) * dimension_, dimension_);
    }
    return sum;
}

double PathND::length_at(double u) const noexcept {
    if (!(u > 0.0)) return 0.0;  // NaN too
    if (u >= 1.0) return length();
    if (kind_ != PathNDKind::linear) {
        const auto it = std::upper_bound(panel_u_.begin(), panel_u_.end(), u);
        const std::size_t j = std::min(static_cast<std::size_t>(it - panel_u_.begin()) - 1, panel_u_.size() - 2);
        return panel_s_[j] + gauss(panel_u_[j], u);
    }
    const std::size_t segments = keyframe_count() - 1;
    double t;
    const std::size_t i = detail::segment_of(u * static_cast<double>(segments), segments, t);
    double sum = 0.0;
    for (std::size_t k = 0; k < i; ++k) {
        sum += distance_nd(keys_.data() + k * dimension_, keys_.data() + (k + 1) * dimension_, dimension_);
    }
    return sum + t * distance_nd(keys_.data() + i * dimension_, keys_.data() + (i + 1) * dimension_, dimension_);
}

double PathND::u_at_length(double s) const noexcept {
    if (!(s > 0.0)) return 0.0;  // NaN too
    const std::size_t segments = keyframe_count() - 1;
    if (kind_ == PathNDKind::linear) {
        double sum = 0.0;
        for (std::size_t i = 0; i < segments; ++i) {
            const double len = distance_nd(keys_.data() + i * dimension_, keys_.data() + (i + 1) * dimension_, dimension_);
            if (s <= sum + len) {
                const double t = len > 0.0 ? std::clamp((s - sum) / len, 0.0, 1.0) : 0.0;
                return std::min(1.0, (static_cast<double>(i) + t) / static_cast<double>(segments));
            }
            sum += len;
        }
        return 1.0;
    }
    if (s >= panel_s_.back()) return 1.0;
    const auto it = std::upper_bound(panel_s_.begin(), panel_s_.end(), s);
    const std::size_t j = std::min(static_cast<std::size_t>(it - panel_s_.begin()) - 1, panel_s_.size() - 2);
    const double u0 = panel_u_[j], u1 = panel_u_[j + 1], s0 = panel_s_[j], s1 = panel_s_[j + 1];
    if (!(s1 > s0)) return u0;
    // Newton on length_at(u) − s inside the panel, kept in its bracket by bisection.
    double lo = u0, hi = u1;
    double u = u0 + (u1 - u0) * std::clamp((s - s0) / (s1 - s0), 0.0, 1.0);
    for (int step = 0; step < 60; ++step) {
        const double f = s0 + gauss(u0, u) - s;
        if (f == 0.0) return u;
        if (f > 0.0) hi = u;
        else lo = u;
        const double v = speed(u);
        double next = v > 0.0 ? u - f / v : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - u) <= 2.0 * eps_nd * std::max(u, 1e-300)) return next;
        u = next;
    }
    return u;
}

}  // namespace grape
