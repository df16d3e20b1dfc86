// grape — the Path handle (evaluation at and beyond the ends, length, flattening), Path1D, PathND.
#include "path_checks.hpp"

#include <cstdio>
#include <string>

namespace grape {

using namespace path_checks;

namespace {

const std::shared_ptr<const detail::PathNode>& origin_node() {
    static const std::shared_ptr<const detail::PathNode> node = make_node<detail::LinearNode>(Vec2{}, Vec2{});
    return node;
}

}  // namespace

std::string_view to_string(PathKind kind) noexcept {
    switch (kind) {
        case PathKind::linear: return "linear";
        case PathKind::circle: return "circle";
        case PathKind::elliptical_arc: return "elliptical_arc";
        case PathKind::spiral: return "spiral";
        case PathKind::sine_wave: return "sine_wave";
        case PathKind::quadratic_bezier: return "quadratic_bezier";
        case PathKind::cubic_bezier: return "cubic_bezier";
        case PathKind::linear_spline: return "linear_spline";
        case PathKind::cosine_spline: return "cosine_spline";
        case PathKind::hermite_spline: return "hermite_spline";
        case PathKind::catmull_rom_spline: return "catmull_rom_spline";
        case PathKind::physics: return "physics";
        case PathKind::complex: return "complex";
        case PathKind::reparametrized: return "reparametrized";
    }
    return "unknown";
}

// --- Path ---------------------------------------------------------------------------------

Path::Path() : node_(origin_node()) {}

Path::Path(std::shared_ptr<const detail::PathNode> node) noexcept : node_(std::move(node)) {}

Vec2 Path::point(double u) const noexcept {
    if (u < 0.0) return node_->point(0.0) + node_->d1(0.0) * u;
    if (u > 1.0) return node_->point(1.0) + node_->d1(1.0) * (u - 1.0);
    return node_->point(u);
}

Vec2 Path::d1(double u) const noexcept {
    if (u < 0.0) return node_->d1(0.0);
    if (u > 1.0) return node_->d1(1.0);
    return node_->d1(u);
}

Vec2 Path::d2(double u) const noexcept {
    if (u < 0.0 || u > 1.0) return {};
    return node_->d2(u);
}

double Path::heading(double u) const noexcept {
    const Vec2 d = d1(u);
    if (d.x == 0.0 && d.y == 0.0) return 0.0;
    return std::atan2(d.y, d.x);
}

double Path::length() const noexcept { return node_->length(); }

double Path::length_at(double u) const noexcept {
    if (!(u > 0.0)) return 0.0;
    if (u >= 1.0) return node_->length();
    return node_->length_at(u);
}

double Path::u_at_length(double s) const noexcept {
    const double total = node_->length();
    if (!(s > 0.0) || !(total > 0.0)) return 0.0;
    if (s >= total) return 1.0;
    if (node_->kind() == PathKind::reparametrized || node_->kind() == PathKind::linear) return s / total;
    // Newton on length_at(u) − s (derivative: the speed), kept in its bracket by bisection.
    const detail::PathNode& n = *node_;
    auto fd = [&n, s](double u) noexcept {
        return std::pair<double, double>{n.length_at(u) - s, grape::length(n.d1(u))};
    };
    return find_root(fd, 0.0, 1.0, s / total, 1e-15).x;
}

Bounds Path::bounds() const noexcept { return node_->bounds(); }

std::vector<Vec2> Path::flatten(double tolerance) const {
    if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
        fail("Path::flatten", "tolerance must be positive and finite (got " + text(tolerance) + ")");
    }
    // Below ~1e-12 of the path's size the rounding of the points themselves dominates.
    const Vec2 size = node_->bounds().size();
    tolerance = std::max(tolerance, 1e-12 * std::max({std::abs(size.x), std::abs(size.y), 1e-300}));
    std::vector<Vec2> out{node_->point(0.0)};
    node_->append_flattened(tolerance, out);
    if (out.size() == 1) out.push_back(out.front());
    return out;
}

Path Path::reparametrized() const {
    if (node_->kind() == PathKind::reparametrized) return *this;
    return Path(make_node<detail::ReparametrizedNode>(*this));
}

PathKind Path::kind() const noexcept { return node_->kind(); }

// --- Path1D, PathND -----------------------------------------------------------------------

Path1D::Path1D(double from, double to) : from_(from), to_(to) {
    require_finite("Path1D", "from", from, "to", to);
}

namespace {

std::vector<double> checked_keys(std::size_t dimension, std::span<const double> keys) {
    const char* who = "PathND";
    if (dimension == 0) fail(who, "dimension must be at least 1 (got 0)");
    if (keys.size() % dimension != 0) {
        fail(who, "keyframes must hold a multiple of dimension " + std::to_string(dimension) + " values (got " +
                      std::to_string(keys.size()) + ")");
    }
    if (keys.size() / dimension < 2) {
        fail(who, "keyframes needs at least 2 keyframes (got " + std::to_string(keys.size() / dimension) + ")");
    }
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (!std::isfinite(keys[i])) {
            fail(who, "keyframes[" + std::to_string(i) + "] must be finite (got " + text(keys[i]) + ")");
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

}  // namespace

PathND::PathND(std::span<const double> from, std::span<const double> to)
    : PathND(from.size(), std::span<const double>(joined(from, to))) {}

PathND::PathND(std::size_t dimension, std::span<const double> keyframes)
    : dimension_(dimension), keys_(checked_keys(dimension, keyframes)) {}

void PathND::point(double u, std::span<double> out) const noexcept {
    const std::size_t segments = keyframe_count() - 1;
    double t;
    // Outside [0, 1] the end segments extend linearly (t leaves [0, 1]).
    std::size_t i = detail::segment_of(u * static_cast<double>(segments), segments, t);
    if (u < 0.0) t = u * static_cast<double>(segments);
    if (u > 1.0) t = 1.0 + (u - 1.0) * static_cast<double>(segments);
    const double* a = keys_.data() + i * dimension_;
    const double* b = a + dimension_;
    const std::size_t n = std::min(out.size(), dimension_);
    for (std::size_t k = 0; k < n; ++k) out[k] = a[k] + (b[k] - a[k]) * t;
}

void PathND::d1(double u, std::span<double> out) const noexcept {
    const std::size_t segments = keyframe_count() - 1;
    double t;
    const std::size_t i = detail::segment_of(u * static_cast<double>(segments), segments, t);
    const double* a = keys_.data() + i * dimension_;
    const double* b = a + dimension_;
    const std::size_t n = std::min(out.size(), dimension_);
    for (std::size_t k = 0; k < n; ++k) out[k] = (b[k] - a[k]) * static_cast<double>(segments);
}

}  // namespace grape
