// grape — the Path handle (evaluation at and beyond the ends, length, flattening), Path1D.
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

// --- Path1D ------------------------------------------------------------------------------

Path1D::Path1D(double from, double to) : from_(from), to_(to) {
    require_finite("Path1D", "from", from, "to", to);
}

}  // namespace grape
