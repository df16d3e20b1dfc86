// grape — a 2-D path lifted onto a plane in 3-D: the affine image of its point and derivatives.
#include "node3.hpp"

#include "../path/kinds.hpp"

#include <grape/error.hpp>
#include <grape/math.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace grape {
namespace detail {
namespace {

// sup |x″| over [a, b] inside one smooth piece of a 2-D node. A complex node gives none itself:
// the part holding the interval does, scaled by the chain rule. ∞ where unknown.
double flat_d2_bound(const PathNode& n, double a, double b) noexcept {
    if (const auto* c = dynamic_cast<const ComplexNode*>(&n)) {
        const auto pieces = c->pieces();
        if (pieces.empty()) return std::numeric_limits<double>::infinity();
        const double m = 0.5 * (a + b);
        const auto it = std::upper_bound(pieces.begin(), pieces.end(), m, [](double u, const auto& p) { return u < p.start; });
        const auto& p = *(it == pieces.begin() ? it : it - 1);
        auto local = [&p](double u) { return std::clamp((u - p.start) * p.inv_width, 0.0, 1.0); };
        return flat_d2_bound(*p.node, local(a), local(b)) * p.inv_width * p.inv_width;
    }
    return n.derivative_bounds(a, b).d2;
}

class OnPlane3Node final : public Path3Node {
public:
    OnPlane3Node(Path path, Vec3 origin, Vec3 x_axis, Vec3 y_axis, double scale)
        : Path3Node(Path3Kind::on_plane),
          path_(std::move(path)),
          flat_(&NodeAccess::node(path_)),
          o_(origin),
          x_(x_axis),
          y_(y_axis),
          scale_(scale) {
        finish();
    }
    Vec3 point(double u) const noexcept override {
        const Vec2 p = flat_->point(u);
        return o_ + x_ * p.x + y_ * p.y;
    }
    Vec3 d1(double u) const noexcept override { return image(flat_->d1(u)); }
    Vec3 d2(double u) const noexcept override { return image(flat_->d2(u)); }
    // A central difference of d2 inside the piece holding u (one-sided, second order, within a
    // step of its ends). The step is eps^(1/3) of the piece's width, where the truncation
    // (h²·|x⁽⁵⁾|/6) and the rounding (eps·|x″|/h) of the difference balance.
    Vec3 d3(double u) const noexcept override {
        const auto& b = breaks();
        const auto it = std::upper_bound(b.begin(), b.end(), u);
        const std::size_t i = std::min(static_cast<std::size_t>(it == b.begin() ? 0 : it - b.begin() - 1), b.size() - 2);
        const double lo = b[i], hi = b[i + 1];
        const double h = 6e-6 * (hi - lo);
        if (!(h > 0.0)) return {};
        u = std::clamp(u, lo, hi);
        Vec2 d;
        if (u - h < lo) {
            d = (flat_->d2(u + h) * 4.0 - flat_->d2(u) * 3.0 - flat_->d2(u + 2.0 * h)) / (2.0 * h);
        } else if (u + h > hi) {
            d = (flat_->d2(u) * 3.0 - flat_->d2(u - h) * 4.0 + flat_->d2(u - 2.0 * h)) / (2.0 * h);
        } else {
            d = (flat_->d2(u + h) - flat_->d2(u - h)) / (2.0 * h);
        }
        return image(d);
    }
    double length_at(double u) const noexcept override { return scale_ * flat_->length_at(std::clamp(u, 0.0, 1.0)); }
    double u_at_length(double s) const noexcept override { return path_.u_at_length(s / scale_); }
    // Distances scale by s, so |image(x″)| = s·|x″|. A 2-D kind without bounds (a
    // reparametrized one) gives ∞.
    double d2_bound(double a, double b) const noexcept override {
        return scale_ * flat_d2_bound(*flat_, a, b) * (1.0 + 1e-12);
    }
    // The 2-D flattening at tolerance / s, lifted: the map scales every distance by s.
    void append_flattened(double tolerance, std::vector<Vec3>& out) const override {
        const std::vector<Vec2> flat = path_.flatten(tolerance / scale_);
        for (std::size_t i = 1; i < flat.size(); ++i) out.push_back(o_ + x_ * flat[i].x + y_ * flat[i].y);
        // The 2-D end may be computed apart from point(1), to rounding.
        if (flat.size() < 2) out.push_back(point(1.0)); else out.back() = point(1.0);
    }

private:
    Vec3 image(Vec2 p) const noexcept { return x_ * p.x + y_ * p.y; }
    void interior_breaks(std::vector<double>& out) const override {
        const auto& b = flat_->breaks();
        for (std::size_t k = 1; k + 1 < b.size(); ++k) out.push_back(b[k]);
    }
    bool closed_form_length() override {
        length_ = scale_ * flat_->length();
        return true;
    }
    Path path_;
    const PathNode* flat_;
    Vec3 o_, x_, y_;
    double scale_;
};

}  // namespace
}  // namespace detail

Path3 Path3::on_plane(Path path, Vec3 origin, Vec3 x_axis, Vec3 y_axis) {
    const std::string where = "Path3::on_plane: ";
    if (!is_finite(origin)) throw Error(where + "origin: not finite");
    if (!is_finite(x_axis)) throw Error(where + "x_axis: not finite");
    if (!is_finite(y_axis)) throw Error(where + "y_axis: not finite");
    const double sx = grape::length(x_axis), sy = grape::length(y_axis);
    if (!(sx > 0.0)) throw Error(where + "x_axis: zero vector");
    if (!(sy > 0.0)) throw Error(where + "y_axis: zero vector");
    // 1e-12 relative: far above the rounding of axes computed from unit vectors (a few ulp),
    // far below any intended skew or stretch.
    if (!(std::abs(sy - sx) <= 1e-12 * sx)) {
        throw Error(where + "y_axis: must have the length of x_axis (" + detail::number_text(sx) + "), got " +
                    detail::number_text(sy));
    }
    if (!(std::abs(dot(x_axis / sx, y_axis / sy)) <= 1e-12)) throw Error(where + "y_axis: not orthogonal to x_axis");
    OnPlane3Spec spec{path, origin, x_axis, y_axis};
    auto node = std::make_shared<detail::OnPlane3Node>(std::move(path), origin, x_axis, y_axis, sx);
    node->set_spec(std::move(spec));
    return detail::Path3Access::make(std::move(node));
}

}  // namespace grape
