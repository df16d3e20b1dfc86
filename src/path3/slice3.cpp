// grape — the part of a 3-D path between two parameters, as a path of its own.
#include "node3.hpp"

#include <grape/error.hpp>
#include <grape/math.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace grape {
namespace detail {
namespace {

class Slice3Node final : public Path3Node {
public:
    Slice3Node(Path3 source, double u0, double u1)
        : Path3Node(Path3Kind::slice), source_(std::move(source)), src_(&Path3Access::node(source_)), u0_(u0), u1_(u1), w_(u1 - u0) {
        s0_ = src_->length_at(u0_);
        finish();
    }
    Vec3 point(double v) const noexcept override { return src_->point(map(v)); }
    Vec3 point_before(double v) const noexcept override { return src_->point_before(map(v)); }
    Vec3 d1(double v) const noexcept override { return src_->d1(map(v)) * w_; }
    Vec3 d2(double v) const noexcept override { return src_->d2(map(v)) * w_ * w_; }
    Vec3 d3(double v) const noexcept override { return src_->d3(map(v)) * w_ * w_ * w_; }
    double length_at(double v) const noexcept override {
        if (!(v > 0.0)) return 0.0;
        if (v >= 1.0) return length_;
        return std::clamp(src_->length_at(map(v)) - s0_, 0.0, length_);
    }
    double u_at_length(double s) const noexcept override {
        if (!(s > 0.0) || !(length_ > 0.0)) return 0.0;
        if (s >= length_) return 1.0;
        return std::clamp((src_->u_at_length(s0_ + s) - u0_) / w_, 0.0, 1.0);
    }
    double d2_bound(double a, double b) const noexcept override {
        return src_->d2_bound(map(a), map(b)) * w_ * w_;
    }

private:
    // Exactly u0 at v = 0 and u1 at v = 1.
    double map(double v) const noexcept { return v >= 1.0 ? u1_ : u0_ + w_ * std::max(v, 0.0); }
    void interior_breaks(std::vector<double>& out) const override {
        for (const double b : src_->breaks()) {
            if (!(b > u0_ && b < u1_)) continue;
            const double v = (b - u0_) / w_;
            if (v > out.back() && v < 1.0) out.push_back(v);
        }
    }
    bool closed_form_length() override {
        length_ = std::max(src_->length_at(u1_) - s0_, 0.0);
        return true;
    }
    Path3 source_;
    const Path3Node* src_;
    double u0_, u1_, w_, s0_ = 0.0;
};

}  // namespace
}  // namespace detail

Path3 slice(const Path3& path, double u0, double u1) {
    const std::string where = "slice(Path3): ";
    if (!(std::isfinite(u0) && u0 >= 0.0 && u0 < 1.0)) throw Error(where + "u0: must be in [0, 1), got " + detail::number_text(u0));
    if (!(std::isfinite(u1) && u1 > u0 && u1 <= 1.0)) {
        throw Error(where + "u1: must be in (u0, 1] (u0 = " + detail::number_text(u0) + "), got " + detail::number_text(u1));
    }
    auto node = std::make_shared<detail::Slice3Node>(path, u0, u1);
    node->set_spec(Slice3Spec{path, u0, u1});
    return detail::Path3Access::make(std::move(node));
}

}  // namespace grape
