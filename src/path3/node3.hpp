// grape — the nodes behind Path3 handles: what every kind shares (breaks, arc length, bounds,
// flattening, the description it was built from).
#pragma once

#include <grape/path3.hpp>

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace grape::detail {

class Path3Node {
public:
    explicit Path3Node(Path3Kind kind) noexcept : kind_(kind) {}
    virtual ~Path3Node() = default;
    Path3Node(const Path3Node&) = delete;
    Path3Node& operator=(const Path3Node&) = delete;

    Path3Kind kind() const noexcept { return kind_; }
    // u in [0, 1].
    virtual Vec3 point(double u) const noexcept = 0;
    virtual Vec3 d1(double u) const noexcept = 0;
    virtual Vec3 d2(double u) const noexcept = 0;
    virtual Vec3 d3(double u) const noexcept = 0;
    virtual double length_at(double u) const noexcept;
    // The limit of point from below u (u in (0, 1]): the end of the piece before a break,
    // where parts of a complex path need not meet. Default: point(u) (continuous kinds).
    virtual Vec3 point_before(double u) const noexcept { return point(u); }
    // An upper bound on |d2| over [a, b], a sub-interval of one piece (between two breaks).
    virtual double d2_bound(double a, double b) const noexcept = 0;
    virtual double u_at_length(double s) const noexcept;
    // Appends points after point(0) up to point(1), every point of the path within
    // `tolerance` of the polyline. Default: the chord error bound d2_bound·h²/8 per interval.
    virtual void append_flattened(double tolerance, std::vector<Vec3>& out) const;

    double length() const noexcept { return length_; }
    const std::vector<double>& breaks() const noexcept { return breaks_; }
    const Bounds3& bounds() const noexcept { return bounds_; }
    const Path3Spec& spec() const noexcept { return spec_; }
    // The factories record what they were given, once, before the node is shared.
    void set_spec(Path3Spec spec) { spec_ = std::move(spec); }

protected:
    // Interior u where derivatives may jump, increasing, inside (0, 1).
    virtual void interior_breaks(std::vector<double>& out) const;
    // Appends u in (0, 1), in any order, where |d1| may have a kink inside a piece (a stop,
    // where every component of d1 vanishes): the quadrature cuts there. Default: none.
    virtual void speed_kinks(std::vector<double>& out) const;
    // Kinds with a closed-form length set it in length_ themselves and return true.
    virtual bool closed_form_length() { return false; }
    // Tight box over [0, 1]. Default: per piece and axis, the roots of that component of d1
    // bracketed by 64 samples and bisected to the last bit, and the piece's ends.
    virtual Bounds3 compute_bounds() const;
    // Called last by every constructor: breaks, the per-piece lengths, the bounds.
    void finish();

    double length_ = 0.0;

private:
    double integrate_speed(double a, double b) const noexcept;

    Path3Kind kind_;
    std::vector<double> breaks_;
    std::vector<double> cuts_;        // breaks and speed kinks, increasing
    std::vector<double> cumulative_;  // length at each cut
    double quad_tolerance_ = 0.0;
    Bounds3 bounds_;
    Path3Spec spec_;
};

struct Path3Access {
    static const Path3Node& node(const Path3& p) noexcept { return *p.node_; }
    static Path3 make(std::shared_ptr<const Path3Node> node) noexcept { return Path3(std::move(node)); }
};

}  // namespace grape::detail
