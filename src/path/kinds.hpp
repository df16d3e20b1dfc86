// grape — the node types behind the path kinds not exposed in path_node.hpp.
// Each stores what its evaluation needs, precomputed at construction.
#pragma once

#include "path_node.hpp"

#include <array>
#include <cmath>
#include <span>
#include <vector>

namespace grape::detail {

/// Index of the segment holding x in [0, count) and the local parameter in [0, 1]; NaN-safe.
inline std::size_t segment_of(double x, std::size_t count, double& local) noexcept {
    if (!(x > 0.0)) {
        local = 0.0;
        return 0;
    }
    if (x >= static_cast<double>(count)) {
        local = 1.0;
        return count - 1;
    }
    const auto i = static_cast<std::size_t>(x);
    local = x - static_cast<double>(i);
    return i;
}

/// The breaks k / segments, k = 1 … segments − 1, of `segments` equal pieces.
inline void even_breaks(std::size_t segments, std::vector<double>& out) {
    for (std::size_t k = 1; k < segments; ++k) out.push_back(static_cast<double>(k) / static_cast<double>(segments));
}

/// An arc of an ellipse (a circle when rx == ry and rotation == 0).
class ArcNode final : public PathNode {
public:
    ArcNode(PathKind kind, Vec2 center, double rx, double ry, double rotation, double a0, double a1) noexcept;
    Vec2 point(double u) const noexcept override;
    Vec2 d1(double u) const noexcept override;
    Vec2 d2(double u) const noexcept override;
    DerivativeBounds derivative_bounds(double a, double b) const noexcept override;
    double length_at(double u) const noexcept override;
    void append_flattened(double tolerance, std::vector<Vec2>& out) const override;

    const Vec2 center;
    const double rx, ry, rotation, a0, a1;

    /// Position at angle θ.
    Vec2 at_angle(double theta) const noexcept;

protected:
    bool closed_form_length() const noexcept override { return rx == ry; }
    Bounds compute_bounds() const override;
    void interior_breaks(std::vector<double>& out) const override;

private:
    Vec2 ex_, ey_;  // the rotated axes scaled by rx and ry
    double span_;   // a1 − a0
};

/// A circle with a radius interpolated linearly.
class SpiralNode final : public PathNode {
public:
    SpiralNode(Vec2 center, double r0, double r1, double a0, double a1) noexcept;
    Vec2 point(double u) const noexcept override;
    Vec2 d1(double u) const noexcept override;
    Vec2 d2(double u) const noexcept override;
    DerivativeBounds derivative_bounds(double a, double b) const noexcept override;
    double length_at(double u) const noexcept override;

    const Vec2 center;
    const double r0, r1, a0, a1;

protected:
    bool closed_form_length() const noexcept override { return closed_; }
    void interior_breaks(std::vector<double>& out) const override;

private:
    bool closed_;  // the closed form is used unless it would cancel (nearly constant radius)
};

/// A sine wave along a segment.
class SineWaveNode final : public PathNode {
public:
    SineWaveNode(Vec2 a, Vec2 b, double frequency, double amplitude) noexcept;
    Vec2 point(double u) const noexcept override;
    Vec2 d1(double u) const noexcept override;
    Vec2 d2(double u) const noexcept override;
    DerivativeBounds derivative_bounds(double a, double b) const noexcept override;

    const Vec2 a, b;
    const double frequency, amplitude;

    double length_at(double u) const noexcept override;

protected:
    void interior_breaks(std::vector<double>& out) const override;
    int samples_per_piece() const noexcept override { return 8; }
    bool closed_form_length() const noexcept override { return true; }

private:
    double from_crest(double r) const noexcept;

    Vec2 delta_, normal_;
    double omega_;
    double half_;         // a half wave's span in u, 1/(2|frequency|) (+inf without waves)
    double half_length_;  // its arc length (0 when half_ ≥ 1)
};

/// A quadratic Bézier, also used (with the time scale folded in) for projectiles.
class QuadraticNode final : public PathNode {
public:
    /// x(u) = c0 + c1·u + c2·u²; `inputs` and `seconds` are what the user gave (control
    /// points, or position, velocity, acceleration and duration of a projectile).
    QuadraticNode(PathKind kind, Vec2 c0, Vec2 c1, Vec2 c2, std::array<Vec2, 3> inputs,
                  double seconds) noexcept;
    Vec2 point(double u) const noexcept override { return (c[2] * u + c[1]) * u + c[0]; }
    Vec2 d1(double u) const noexcept override { return 2.0 * c[2] * u + c[1]; }
    Vec2 d2(double) const noexcept override { return 2.0 * c[2]; }
    DerivativeBounds derivative_bounds(double, double) const noexcept override {
        return {2.0 * grape::length(c[2]), 0.0};
    }
    double length_at(double u) const noexcept override;

    const Vec2 c[3];
    const std::array<Vec2, 3> inputs;
    const double seconds;

protected:
    bool closed_form_length() const noexcept override { return closed_; }
    Bounds compute_bounds() const override;

private:
    bool closed_;
    double t0_, k_, scale_;  // speed = scale·sqrt((u − t0)² + k²)
};

/// Straight segments through points; `cosine` eases each segment with (1 − cos πt)/2.
class PolylineNode final : public PathNode {
public:
    PolylineNode(PathKind kind, std::vector<Vec2> points);
    const std::vector<Vec2> points;

    Vec2 point(double u) const noexcept override;
    Vec2 d1(double u) const noexcept override;
    Vec2 d2(double u) const noexcept override;
    // Length and flattening are exact for straight segments (the cosine ease only retimes them).
    double length_at(double u) const noexcept override;
    void append_flattened(double tolerance, std::vector<Vec2>& out) const override;
    DerivativeBounds derivative_bounds(double a, double b) const noexcept override;

protected:
    bool closed_form_length() const noexcept override { return true; }
    Bounds compute_bounds() const override;
    void interior_breaks(std::vector<double>& out) const override;

private:
    bool cosine_;
    std::vector<double> cumulative_;  // arc length at each point
};

/// Piecewise cubic (Hermite and Catmull–Rom): per segment x(t) = c0 + c1·t + c2·t² + c3·t³.
class CubicSplineNode final : public PathNode {
public:
    struct Segment {
        Vec2 c0, c1, c2, c3;
    };
    CubicSplineNode(PathKind kind, std::vector<Vec2> points, std::vector<Vec2> tangents,
                    CatmullRom type);
    Vec2 point(double u) const noexcept override;
    Vec2 d1(double u) const noexcept override;
    Vec2 d2(double u) const noexcept override;
    DerivativeBounds derivative_bounds(double a, double b) const noexcept override;

    const std::vector<Vec2> points;
    const std::vector<Vec2> tangents;  ///< d/dt of each segment's local t at each point
    const CatmullRom type;
    std::vector<Segment> segments;

protected:
    Bounds compute_bounds() const override;
    void interior_breaks(std::vector<double>& out) const override;
};

/// Several paths in sequence, each over its span of u.
class ComplexNode : public PathNode {  // SvgNode (svg_parser.hpp) adds the commands
public:
    ComplexNode(std::vector<Path> parts, std::vector<double> cues);
    Vec2 point(double u) const noexcept override;
    Vec2 d1(double u) const noexcept override;
    Vec2 d2(double u) const noexcept override;
    double length_at(double u) const noexcept override;
    void append_flattened(double tolerance, std::vector<Vec2>& out) const override;

    const std::vector<Path> parts;
    const std::vector<double> cues;

protected:
    bool closed_form_length() const noexcept override { return true; }
    Bounds compute_bounds() const override;
    void interior_breaks(std::vector<double>& out) const override;

private:
    // The parts whose span is not empty, with their spans.
    struct Piece {
        const PathNode* node;
        double start, width, inv_width, s0;  // s0: arc length before the piece
    };
    const Piece& piece_at(double u) const noexcept;
    std::vector<Piece> pieces_;
    std::vector<double> starts_;  // pieces_[i].start, for binary search

public:
    /// The parts whose span is not empty, in order, with their spans (for the path queries).
    std::span<const Piece> pieces() const noexcept { return pieces_; }
};

}  // namespace grape::detail
