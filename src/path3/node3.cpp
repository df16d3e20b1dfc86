// grape — what every 3-D path node shares: breaks and arc length by adaptive quadrature.
#include "node3.hpp"

#include <grape/error.hpp>
#include <grape/math.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace grape::detail {

void Path3Node::interior_breaks(std::vector<double>&) const {}
void Path3Node::speed_kinks(std::vector<double>&) const {}

void Path3Node::finish() {
    breaks_.clear();
    breaks_.push_back(0.0);
    interior_breaks(breaks_);
    breaks_.push_back(1.0);
    // The quadrature's own cuts: the breaks and the points where the speed may have a kink
    // inside a piece (a stop), so that no rule straddles one.
    cuts_ = breaks_;
    speed_kinks(cuts_);
    std::sort(cuts_.begin(), cuts_.end());
    cuts_.erase(std::unique(cuts_.begin(), cuts_.end()), cuts_.end());
    if (!closed_form_length()) {
        // The target is relative to the whole length, estimated by one rule per piece (as 2-D
        // paths do): 1e-14 of it leaves the sum of the pieces within ~1e-13.
        double estimate = 0.0;
        auto speed = [this](double u) noexcept { return grape::length(d1(u)); };
        for (std::size_t i = 0; i + 1 < cuts_.size(); ++i) estimate += gauss_legendre(speed, cuts_[i], cuts_[i + 1]);
        quad_tolerance_ = std::max(1e-14 * estimate, std::numeric_limits<double>::min());
        cumulative_.assign(cuts_.size(), 0.0);
        for (std::size_t i = 0; i + 1 < cuts_.size(); ++i) {
            cumulative_[i + 1] = cumulative_[i] + integrate_speed(cuts_[i], cuts_[i + 1]);
        }
        length_ = cumulative_.back();
    }
    if (!std::isfinite(length_)) {
        throw Error("Path3 (" + std::string(to_string(kind_)) +
                    "): the length overflows a double; coordinates or parameters are too large");
    }
    bounds_ = compute_bounds();
}

namespace {
double axis_of3(Vec3 v, int axis) noexcept { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }
}  // namespace

Bounds3 Path3Node::compute_bounds() const {
    Bounds3 box;
    constexpr int samples = 64;
    for (std::size_t i = 0; i + 1 < breaks_.size(); ++i) {
        const double a = breaks_[i], b = breaks_[i + 1];
        box.add(point(a));
        box.add(point(b));
        for (int axis = 0; axis < 3; ++axis) {
            double u0 = a, f0 = axis_of3(d1(a), axis);
            for (int k = 1; k <= samples; ++k) {
                const double u1 = k == samples ? b : a + (b - a) * k / samples;
                const double f1 = axis_of3(d1(u1), axis);
                if (f0 == 0.0) box.add(point(u0));
                if ((f0 < 0.0 && f1 > 0.0) || (f0 > 0.0 && f1 < 0.0)) {
                    // Bisection to adjacent doubles: each step halves the bracket (≤ 64 steps).
                    double lo = u0, hi = u1;
                    const bool rising = f0 < 0.0;
                    for (int step = 0; step < 64; ++step) {
                        const double mid = 0.5 * (lo + hi);
                        if (!(mid > lo && mid < hi)) break;
                        ((axis_of3(d1(mid), axis) < 0.0) == rising ? lo : hi) = mid;
                    }
                    box.add(point(lo));
                    box.add(point(hi));
                }
                u0 = u1;
                f0 = f1;
            }
        }
    }
    return box;
}

void Path3Node::append_flattened(double tolerance, std::vector<Vec3>& out) const {
    struct Span {
        double a, b;
        int depth;
    };
    // 40 halvings of a piece leave intervals below 1e-12 of it: the depth bounds the work for
    // a bound that does not shrink (an infinite one from a 2-D kind without derivative bounds,
    // where the deviation measured at three inner points decides instead).
    constexpr int max_depth = 40;
    std::vector<Span> stack;
    for (std::size_t i = 0; i + 1 < breaks_.size(); ++i) {
        if (i > 0) {
            // Where the pieces do not meet (parts of a complex path, seen through a slice or
            // a reparametrization) the polyline ends this piece at its own end and crosses
            // the gap straight. A jump below 1% of the tolerance is
            // rounding or within the slack the chord test leaves: the next piece's start
            // stands for both.
            const Vec3 end = point_before(breaks_[i]), next = point(breaks_[i]);
            if (distance(end, next) > 0.01 * tolerance) out.push_back(end);
            out.push_back(next);
        }
        stack.push_back({breaks_[i], breaks_[i + 1], 0});
        while (!stack.empty()) {
            const Span s = stack.back();
            stack.pop_back();
            const double h = s.b - s.a;
            const double bound = d2_bound(s.a, s.b);
            bool flat;
            if (std::isfinite(bound)) {
                flat = bound * h * h / 8.0 <= 0.99 * tolerance;
            } else {
                const Vec3 pa = point(s.a), pb = point(s.b);
                double worst = 0.0;
                for (const double t : {0.25, 0.5, 0.75}) {
                    const Vec3 p = point(s.a + h * t);
                    const Vec3 chord = pb - pa;
                    const double cc = dot(chord, chord);
                    const double w = cc > 0.0 ? std::clamp(dot(p - pa, chord) / cc, 0.0, 1.0) : 0.0;
                    worst = std::max(worst, distance(p, pa + chord * w));
                }
                flat = s.depth >= 3 && worst <= 0.5 * tolerance;
            }
            if (flat || s.depth >= max_depth || !(h > 0.0)) {
                if (s.b < breaks_[i + 1] || i + 2 == breaks_.size()) out.push_back(point(s.b));
                continue;
            }
            const double m = s.a + 0.5 * h;
            stack.push_back({m, s.b, s.depth + 1});
            stack.push_back({s.a, m, s.depth + 1});
        }
    }
}

double Path3Node::integrate_speed(double a, double b) const noexcept {
    auto speed = [this](double u) noexcept { return grape::length(d1(u)); };
    return integrate(speed, a, b, quad_tolerance_, 40);
}

double Path3Node::length_at(double u) const noexcept {
    if (!(u > 0.0)) return 0.0;
    if (u >= 1.0) return length_;
    const auto it = std::upper_bound(cuts_.begin(), cuts_.end(), u);
    const auto i = static_cast<std::size_t>(it - cuts_.begin()) - 1;
    return cumulative_[i] + integrate_speed(cuts_[i], u);
}

double Path3Node::u_at_length(double s) const noexcept {
    if (!(s > 0.0) || !(length_ > 0.0)) return 0.0;
    if (s >= length_) return 1.0;
    // The piece holding s, then Newton on length_at(u) − s (derivative: the speed), kept in
    // the piece by bisection.
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
    const auto i = std::min(static_cast<std::size_t>(it - cumulative_.begin()) - 1, cuts_.size() - 2);
    const double a = cuts_[i], b = cuts_[i + 1];
    const double base = cumulative_[i];
    auto fd = [&](double u) noexcept {
        return std::pair<double, double>{base + integrate_speed(a, u) - s, grape::length(d1(u))};
    };
    const double piece = cumulative_[i + 1] - base;
    const double guess = piece > 0.0 ? a + (b - a) * (s - base) / piece : 0.5 * (a + b);
    return find_root(fd, a, b, guess, 1e-16).x;
}

}  // namespace grape::detail
