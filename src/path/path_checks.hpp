// The checks the path kinds' constructors make, each error naming the constructor and the
// argument, shared by the Path handle (path.cpp) and the kinds (path_kinds.cpp). Internal.
#pragma once

#include <grape/error.hpp>
#include <grape/path.hpp>

#include "kinds.hpp"
#include "path_node.hpp"

#include <cmath>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace grape::path_checks {

using detail::make_node;

inline std::string text(double v) { return detail::number_text(v); }

inline std::string text(Vec2 v) {
    std::string s = "(";
    s += text(v.x);
    s += ", ";
    s += text(v.y);
    s += ')';
    return s;
}

[[noreturn]] inline void fail(const char* who, const std::string& what) { throw Error(std::string(who) + ": " + what); }

inline void require_finite(const char* who, const char* name, double v) {
    if (!std::isfinite(v)) fail(who, std::string(name) + " must be finite (got " + text(v) + ")");
}

inline void require_finite(const char* who, const char* name, Vec2 v) {
    if (!is_finite(v)) fail(who, std::string(name) + " must be finite (got " + text(v) + ")");
}

// Each (name, value) pair in turn, the first that is not finite named in the error.
template <class T, class... Rest>
inline void require_finite(const char* who, const char* name, T v, Rest... rest) {
    require_finite(who, name, v);
    require_finite(who, rest...);
}

// Polynomial kinds evaluate power-basis coefficients by Horner's rule. Every partial sum, and
// the derivatives (factors up to 6), stay finite for u in [0, 1] when 6·Σ|c| does: beyond
// that a point of the curve could come out infinite although the curve itself is finite.
inline void require_evaluable(const char* who, const char* what, std::initializer_list<Vec2> coefficients) {
    double x = 0.0;
    double y = 0.0;
    for (const Vec2 c : coefficients) {
        x += std::abs(c.x);
        y += std::abs(c.y);
    }
    if (!(std::isfinite(6.0 * x) && std::isfinite(6.0 * y)))
        fail(who, std::string(what) + " are too large to evaluate in double precision (coefficients overflow)");
}

// Work for length, bounds and flattening grows with the turns: a million is far beyond any
// drawing and keeps every construction bounded.
inline constexpr double max_turns = 1e6;

inline void require_turns(const char* who, double a0, double a1) {
    if (std::abs(a1 - a0) > 2.0 * pi * max_turns) {
        fail(who, "end_angle − start_angle must be at most a million turns (got " + text(a1 - a0) + " radians)");
    }
}

inline std::vector<Vec2> checked_points(const char* who, const char* name, std::span<const Vec2> points, std::size_t at_least) {
    if (points.size() < at_least) {
        fail(who, std::string(name) + " needs at least " + std::to_string(at_least) + " points (got " +
                      std::to_string(points.size()) + ")");
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!is_finite(points[i])) {
            fail(who, std::string(name) + "[" + std::to_string(i) + "] must be finite (got " + text(points[i]) + ")");
        }
    }
    return {points.begin(), points.end()};
}

// Flat x, y pairs as points (the seed's Number vectors).
inline std::vector<Vec2> pairs(const char* who, const char* name, std::span<const double> xy) {
    if (xy.size() % 2 != 0) {
        fail(who, std::string(name) + " must hold x, y pairs: an even number of coordinates (got " +
                      std::to_string(xy.size()) + ")");
    }
    std::vector<Vec2> points(xy.size() / 2);
    for (std::size_t i = 0; i < points.size(); ++i) points[i] = {xy[2 * i], xy[2 * i + 1]};
    return points;
}

template <class T>
const T& underlying(const detail::PathNode& node) noexcept {
    if (node.kind() == PathKind::reparametrized) {
        return static_cast<const T&>(detail::NodeAccess::node(static_cast<const detail::ReparametrizedNode&>(node).source()));
    }
    return static_cast<const T&>(node);
}

}  // namespace grape::path_checks
