// grape — complex paths: several paths in sequence, each over its span of u.
#include "kinds.hpp"

#include <algorithm>
#include <cmath>

namespace grape::detail {

// --- ComplexNode --------------------------------------------------------------------------

ComplexNode::ComplexNode(std::vector<Path> parts_in, std::vector<double> cues_in)
    : PathNode(PathKind::complex), parts(std::move(parts_in)), cues(std::move(cues_in)) {
    double s = 0.0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const double start = cues[i];
        const double end = i + 1 < parts.size() ? cues[i + 1] : 1.0;
        // An empty span is skipped; so is one too thin for 1/width (adjacent doubles).
        if (!(end > start) || !std::isfinite(1.0 / (end - start))) continue;
        const PathNode* node = &NodeAccess::node(parts[i]);
        pieces_.push_back(Piece{node, start, end - start, 1.0 / (end - start), s});
        starts_.push_back(start);
        s += node->length();
    }
}

const ComplexNode::Piece& ComplexNode::piece_at(double u) const noexcept {
    const auto it = std::upper_bound(starts_.begin(), starts_.end(), u);
    const std::size_t i = it == starts_.begin() ? 0 : static_cast<std::size_t>(it - starts_.begin()) - 1;
    return pieces_[i];
}

namespace {

// The part's own parameter; exactly 1 at the whole's end, whatever (1 − start)/width rounds to.
double local(double u, double start, double inv_width) noexcept {
    return u >= 1.0 ? 1.0 : std::clamp((u - start) * inv_width, 0.0, 1.0);
}

}  // namespace

Vec2 ComplexNode::point(double u) const noexcept {
    const Piece& p = piece_at(u);
    return p.node->point(local(u, p.start, p.inv_width));
}

Vec2 ComplexNode::d1(double u) const noexcept {
    const Piece& p = piece_at(u);  // chain rule: d/du = d/dv · dv/du, dv/du = 1/width
    return p.node->d1(local(u, p.start, p.inv_width)) * p.inv_width;
}

Vec2 ComplexNode::d2(double u) const noexcept {
    const Piece& p = piece_at(u);
    // Scaled in two steps: inv_width² alone overflows for spans under ~1e-154.
    return (p.node->d2(local(u, p.start, p.inv_width)) * p.inv_width) * p.inv_width;
}

double ComplexNode::length_at(double u) const noexcept {
    if (!(u > 0.0)) return 0.0;
    if (u >= 1.0) return pieces_.back().s0 + pieces_.back().node->length();
    const Piece& p = piece_at(u);
    return p.s0 + p.node->length_at(local(u, p.start, p.inv_width));
}

Bounds ComplexNode::compute_bounds() const {
    Bounds box;
    for (const Piece& p : pieces_) box.add(p.node->bounds());
    return box;
}

void ComplexNode::interior_breaks(std::vector<double>& out) const {
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
        const Piece& p = pieces_[i];
        if (i > 0 && p.start > out.back()) out.push_back(p.start);
        const auto& inner = p.node->breaks();
        for (std::size_t k = 1; k + 1 < inner.size(); ++k) {
            const double u = p.start + inner[k] * p.width;
            if (u > out.back() && u < p.start + p.width && u < 1.0) out.push_back(u);
        }
    }
}

void ComplexNode::append_flattened(double tolerance, std::vector<Vec2>& out) const {
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
        const Vec2 start = pieces_[i].node->point(0.0);
        if (i > 0 && (out.empty() || out.back() != start)) out.push_back(start);
        pieces_[i].node->append_flattened(tolerance, out);
    }
}

}  // namespace grape::detail
