// grape — the arc-length reparametrization of a 3-D path: a table of spans, each holding the
// quintic Hermite model of the source parameter as a function of arc length.
#include "node3.hpp"

#include <grape/error.hpp>
#include <grape/math.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace grape {
namespace detail {
namespace {

class Reparametrized3Node final : public Path3Node {
public:
    explicit Reparametrized3Node(Path3 source)
        : Path3Node(Path3Kind::reparametrized), source_(std::move(source)), src_(&Path3Access::node(source_)) {
        total_ = src_->length();
        build();
        finish();
    }

    // The source parameter at arc length u·L.
    double source_u(double u) const noexcept {
        if (u >= 1.0) return 1.0;  // the ends are exact
        const double s = u * total_;
        if (!(s > 0.0)) return 0.0;  // also catches NaN and a path of length 0
        const auto it = std::upper_bound(starts_.begin(), starts_.end(), s);
        const std::size_t i = it == starts_.begin() ? 0 : static_cast<std::size_t>(it - starts_.begin()) - 1;
        const Span& sp = spans_[i];
        if (sp.newton) return src_->u_at_length(s);
        return sp.v0 + model(sp, std::clamp((s - sp.s0) / sp.ds, 0.0, 1.0));
    }
    Vec3 point(double u) const noexcept override { return src_->point(source_u(u)); }
    Vec3 point_before(double u) const noexcept override { return src_->point_before(source_u(u)); }
    Vec3 d1(double u) const noexcept override {
        const double v = source_u(u);
        const Vec3 x1 = src_->d1(v);
        const double w = grape::length(x1);
        if (w > 0.0) return x1 * (total_ / w);
        // At a stop the direction of travel is that of the first derivative that is not zero.
        Vec3 t = normalized(src_->d2(v));
        if (t == Vec3{}) t = normalized(src_->d3(v));
        return t * total_;
    }
    // With w = |x′| and v(s): v′ = 1/w, v″ = −w′/w³, v‴ = −w″/w⁴ + 3w′²/w⁵ (primes on w are
    // d/dv), x_ss = x″v′² + x′v″, x_sss = x‴v′³ + 3x″v′v″ + x′v‴; scaled by L² and L³ for u.
    Vec3 d2(double u) const noexcept override {
        const double v = source_u(u);
        const Vec3 x1 = src_->d1(v), x2 = src_->d2(v);
        const double w = grape::length(x1);
        if (!(w > 0.0)) return {};
        const double wv = dot(x1, x2) / w;
        const double a = 1.0 / w, b = -wv / (w * w * w);
        return (x2 * (a * a) + x1 * b) * (total_ * total_);
    }
    Vec3 d3(double u) const noexcept override {
        const double v = source_u(u);
        const Vec3 x1 = src_->d1(v), x2 = src_->d2(v), x3 = src_->d3(v);
        const double w = grape::length(x1);
        if (!(w > 0.0)) return {};
        const double wv = dot(x1, x2) / w;
        const double wvv = (dot(x2, x2) + dot(x1, x3)) / w - wv * wv / w;
        const double a = 1.0 / w, b = -wv / (w * w * w);
        const double c = -wvv / (w * w * w * w) + 3.0 * wv * wv / (w * w * w * w * w);
        return (x3 * (a * a * a) + x2 * (3.0 * a * b) + x1 * c) * (total_ * total_ * total_);
    }
    double length_at(double u) const noexcept override { return std::clamp(u, 0.0, 1.0) * total_; }
    double u_at_length(double s) const noexcept override {
        return total_ > 0.0 ? std::clamp(s / total_, 0.0, 1.0) : 0.0;
    }
    // |x_uu| = L²·κ ≤ L²·sup|x″| / inf|x′|² over the source's [va, vb]; the speed is bounded
    // below by |x′| at the middle less sup|x″|·half-width. The ends are widened by 1e-6 of
    // the width (clamped to the piece) to cover the model's error in v; unknown (∞) where the
    // source may stop.
    double d2_bound(double a, double b) const noexcept override {
        const auto& br = src_->breaks();
        double va = source_u(a), vb = source_u(b);
        const double mid = 0.5 * (va + vb);
        const auto it = std::upper_bound(br.begin(), br.end(), mid);
        const std::size_t k = std::min(static_cast<std::size_t>(it == br.begin() ? 0 : it - br.begin() - 1), br.size() - 2);
        const double pad = 1e-6 * (vb - va);
        va = std::max(va - pad, br[k]);
        vb = std::min(vb + pad, br[k + 1]);
        const double k2 = src_->d2_bound(va, vb);
        const double slow = grape::length(src_->d1(0.5 * (va + vb))) - k2 * 0.5 * (vb - va);
        if (!(slow > 0.0)) return std::numeric_limits<double>::infinity();
        return total_ * total_ * k2 / (slow * slow) * (1.0 + 1e-12);
    }
    // The same shape: the source's polyline.
    void append_flattened(double tolerance, std::vector<Vec3>& out) const override {
        src_->append_flattened(tolerance, out);
    }

private:
    struct Span {
        double s0, ds;       // arc length at the start, and over the span
        double v0, dv;       // source parameter at the start, and over the span
        double d0, d1;       // dv/dσ at σ = 0 and 1 (σ = (s − s0)/ds)
        double e0, e1;       // d²v/dσ² at σ = 0 and 1
        bool newton;         // solve u_at_length instead of the model
    };
    // v − v0 at σ by the quintic Hermite basis.
    static double model(const Span& sp, double t) noexcept {
        const double t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t;
        const double h1 = t - 6.0 * t3 + 8.0 * t4 - 3.0 * t5;
        const double h2 = 0.5 * t2 - 1.5 * t3 + 1.5 * t4 - 0.5 * t5;
        const double h3 = 0.5 * t3 - t4 + 0.5 * t5;
        const double h4 = -4.0 * t3 + 7.0 * t4 - 3.0 * t5;
        const double h5 = 10.0 * t3 - 15.0 * t4 + 6.0 * t5;
        return sp.d0 * h1 + sp.e0 * h2 + sp.e1 * h3 + sp.d1 * h4 + sp.dv * h5;
    }
    // dv/ds and d²v/ds² at v; false where the source stops.
    bool slopes(double v, double& dvds, double& d2vds2) const noexcept {
        const Vec3 x1 = src_->d1(v), x2 = src_->d2(v);
        const double w = grape::length(x1);
        if (!(w > 1e-9 * total_)) return false;
        dvds = 1.0 / w;
        d2vds2 = -dot(x1, x2) / (w * w * w * w);
        return std::isfinite(d2vds2);
    }

    void build() {
        const auto& br = src_->breaks();
        const std::size_t pieces = br.size() - 1;
        // The span budget, per piece so that a hard piece cannot starve the rest: ample for a
        // smooth piece (a few spans), bounding the work of a build by the number of pieces
        // (beyond it, the piece's remaining spans solve u_at_length).
        max_spans_ = 256;
        // The model is accepted when it misses the arc length by at most 1e-10·L, a tenth of
        // the contract, at the span's quarter points.
        target_ = 1e-10 * total_;
        for (std::size_t i = 0; i < pieces; ++i) {
            const double a = br[i], b = br[i + 1];
            piece_first_ = spans_.size();
            // Four spans per piece to start, so no check straddles all of a piece's shape.
            double va = a, sa = src_->length_at(a);
            for (int k = 1; k <= 4; ++k) {
                const double vb = k == 4 ? b : a + (b - a) * k / 4.0;
                const double sb = src_->length_at(vb);
                add_span(va, vb, sa, sb, 0);
                va = vb;
                sa = sb;
            }
        }
        if (spans_.empty()) spans_.push_back(Span{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, true});
        starts_.reserve(spans_.size());
        for (const Span& sp : spans_) starts_.push_back(sp.s0);
    }

    void add_span(double va, double vb, double sa, double sb, int depth) {
        const double ds = sb - sa;
        if (!(ds > 0.0)) return;  // the source stands still: no arc length to map
        Span sp{sa, ds, va, vb - va, 0.0, 0.0, 0.0, 0.0, false};
        double g0, g1, h0, h1;
        bool ok = slopes(va, g0, h0) && slopes(vb, g1, h1);
        if (ok) {
            sp.d0 = g0 * ds;
            sp.d1 = g1 * ds;
            sp.e0 = h0 * ds * ds;
            sp.e1 = h1 * ds * ds;
            for (const double t : {0.25, 0.5, 0.75}) {
                const double v = va + model(sp, t);
                if (!(v >= va && v <= vb) || !(std::abs(src_->length_at(v) - (sa + t * ds)) <= target_)) {
                    ok = false;
                    break;
                }
            }
        }
        if (ok) {
            spans_.push_back(sp);
            return;
        }
        // Each split halves a span; 30 levels is far below a double's resolution of a piece.
        if (depth < 30 && spans_.size() - piece_first_ + 2 <= max_spans_) {
            const double vm = va + 0.5 * (vb - va);
            if (vm > va && vm < vb) {
                const double sm = src_->length_at(vm);
                add_span(va, vm, sa, sm, depth + 1);
                add_span(vm, vb, sm, sb, depth + 1);
                return;
            }
        }
        sp.newton = true;
        spans_.push_back(sp);
    }

    void interior_breaks(std::vector<double>& out) const override {
        if (!(total_ > 0.0)) return;
        const auto& br = src_->breaks();
        for (std::size_t k = 1; k + 1 < br.size(); ++k) {
            const double u = src_->length_at(br[k]) / total_;
            if (u > out.back() && u < 1.0) out.push_back(u);
        }
    }
    bool closed_form_length() override {
        length_ = total_;
        return true;
    }
    Bounds3 compute_bounds() const override { return src_->bounds(); }

    Path3 source_;
    const Path3Node* src_;
    double total_ = 0.0;
    double target_ = 0.0;
    std::size_t max_spans_ = 0;    // per piece
    std::size_t piece_first_ = 0;  // the first span of the piece being built
    std::vector<Span> spans_;
    std::vector<double> starts_;
};

}  // namespace
}  // namespace detail

Path3 Path3::reparametrized() const {
    if (kind() == Path3Kind::reparametrized) return *this;
    auto node = std::make_shared<detail::Reparametrized3Node>(*this);
    node->set_spec(Reparametrized3Spec{*this});
    return detail::Path3Access::make(std::move(node));
}

}  // namespace grape
