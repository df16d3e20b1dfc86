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

void Path3Node::finish() {
    breaks_.clear();
    breaks_.push_back(0.0);
    interior_breaks(breaks_);
    breaks_.push_back(1.0);
    if (!closed_form_length()) {
        // The target is relative to the whole length, estimated by one rule per piece (as 2-D
        // paths do): 1e-14 of it leaves the sum of the pieces within ~1e-13.
        double estimate = 0.0;
        auto speed = [this](double u) noexcept { return grape::length(d1(u)); };
        for (std::size_t i = 0; i + 1 < breaks_.size(); ++i) estimate += gauss_legendre(speed, breaks_[i], breaks_[i + 1]);
        quad_tolerance_ = std::max(1e-14 * estimate, std::numeric_limits<double>::min());
        cumulative_.assign(breaks_.size(), 0.0);
        for (std::size_t i = 0; i + 1 < breaks_.size(); ++i) {
            cumulative_[i + 1] = cumulative_[i] + integrate_speed(breaks_[i], breaks_[i + 1]);
        }
        length_ = cumulative_.back();
    }
    if (!std::isfinite(length_)) {
        throw Error("Path3 (" + std::string(to_string(kind_)) +
                    "): the length overflows a double; coordinates or parameters are too large");
    }
}

double Path3Node::integrate_speed(double a, double b) const noexcept {
    auto speed = [this](double u) noexcept { return grape::length(d1(u)); };
    return integrate(speed, a, b, quad_tolerance_, 40);
}

double Path3Node::length_at(double u) const noexcept {
    if (!(u > 0.0)) return 0.0;
    if (u >= 1.0) return length_;
    const auto it = std::upper_bound(breaks_.begin(), breaks_.end(), u);
    const auto i = static_cast<std::size_t>(it - breaks_.begin()) - 1;
    return cumulative_[i] + integrate_speed(breaks_[i], u);
}

double Path3Node::u_at_length(double s) const noexcept {
    if (!(s > 0.0) || !(length_ > 0.0)) return 0.0;
    if (s >= length_) return 1.0;
    // The piece holding s, then Newton on length_at(u) − s (derivative: the speed), kept in
    // the piece by bisection.
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
    const auto i = std::min(static_cast<std::size_t>(it - cumulative_.begin()) - 1, breaks_.size() - 2);
    const double a = breaks_[i], b = breaks_[i + 1];
    const double base = cumulative_[i];
    auto fd = [&](double u) noexcept {
        return std::pair<double, double>{base + integrate_speed(a, u) - s, grape::length(d1(u))};
    };
    const double piece = cumulative_[i + 1] - base;
    const double guess = piece > 0.0 ? a + (b - a) * (s - base) / piece : 0.5 * (a + b);
    return find_root(fd, a, b, guess, 1e-16).x;
}

}  // namespace grape::detail
