// grape — the 3-D path kinds (Bézier pieces, helix, complex) and the Path3 handle.
#include "node3.hpp"

#include <grape/error.hpp>
#include <grape/math.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace grape {
namespace detail {
namespace {

// Points of a Bézier of degree k ≤ 3 and of its differences, so that every derivative is a
// Bézier of its own evaluated by de Casteljau (exact at the piece's ends, and a line's d2 is
// exactly zero).
struct Bezier3Piece {
    int degree = 1;
    std::array<Vec3, 4> p{};   // control points
    std::array<Vec3, 3> q{};   // first derivative's control points (degree − 1)
    std::array<Vec3, 2> w{};   // second derivative's
    Vec3 c{};                  // third derivative (constant)
};

template <std::size_t N>
Vec3 casteljau3(const std::array<Vec3, N>& pts, int count, double t) noexcept {
    std::array<Vec3, N> b = pts;
    for (int level = count - 1; level > 0; --level) {
        for (int i = 0; i < level; ++i) b[static_cast<std::size_t>(i)] = lerp(b[static_cast<std::size_t>(i)], b[static_cast<std::size_t>(i) + 1], t);
    }
    return b[0];
}

Bezier3Piece make_piece3(std::span<const Vec3> pts) {
    Bezier3Piece s;
    s.degree = static_cast<int>(pts.size()) - 1;
    const double k = s.degree;
    for (std::size_t i = 0; i < pts.size(); ++i) s.p[i] = pts[i];
    for (int i = 0; i < s.degree; ++i) s.q[static_cast<std::size_t>(i)] = k * (pts[static_cast<std::size_t>(i) + 1] - pts[static_cast<std::size_t>(i)]);
    for (int i = 0; i + 1 < s.degree; ++i) s.w[static_cast<std::size_t>(i)] = (k - 1.0) * (s.q[static_cast<std::size_t>(i) + 1] - s.q[static_cast<std::size_t>(i)]);
    if (s.degree == 3) s.c = (k - 2.0) * (s.w[1] - s.w[0]);
    return s;
}

// Bézier pieces of one degree, each over an equal share of u.
class Bezier3Node final : public Path3Node {
public:
    Bezier3Node(Path3Kind kind, std::vector<Bezier3Piece> pieces) : Path3Node(kind), pieces_(std::move(pieces)) {
        n_ = static_cast<double>(pieces_.size());
        finish();
    }
    Vec3 point(double u) const noexcept override {
        double t;
        const Bezier3Piece& s = at(u, t);
        return casteljau3(s.p, s.degree + 1, t);
    }
    Vec3 d1(double u) const noexcept override {
        double t;
        const Bezier3Piece& s = at(u, t);
        return casteljau3(s.q, s.degree, t) * n_;
    }
    // The piece ending at u, at its local t (exactly 1 at a break).
    Vec3 point_before(double u) const noexcept override {
        const double x = std::clamp(u, 0.0, 1.0) * n_;
        const double i = std::clamp(std::ceil(x) - 1.0, 0.0, n_ - 1.0);
        const Bezier3Piece& s = pieces_[static_cast<std::size_t>(i)];
        return casteljau3(s.p, s.degree + 1, std::min(x - i, 1.0));
    }
    Vec3 d2(double u) const noexcept override {
        double t;
        const Bezier3Piece& s = at(u, t);
        return s.degree < 2 ? Vec3{} : casteljau3(s.w, s.degree - 1, t) * n_ * n_;
    }
    Vec3 d3(double u) const noexcept override {
        double t;
        const Bezier3Piece& s = at(u, t);
        return s.degree < 3 ? Vec3{} : s.c * n_ * n_ * n_;
    }

    // d2 of a piece is a Bézier of degree ≤ 1: its sup over [a, b] is at an end (exact).
    double d2_bound(double a, double b) const noexcept override {
        double ta, tb;
        const Bezier3Piece& s = at(0.5 * (a + b), ta);
        const double i = static_cast<double>(&s - pieces_.data());
        ta = std::clamp(a * n_ - i, 0.0, 1.0);
        tb = std::clamp(b * n_ - i, 0.0, 1.0);
        if (s.degree < 2) return 0.0;
        const double m = std::max(grape::length(casteljau3(s.w, s.degree - 1, ta)), grape::length(casteljau3(s.w, s.degree - 1, tb)));
        return m * n_ * n_ * (1.0 + 1e-12);  // the margin covers the rounding of the ends' values
    }

private:
    void interior_breaks(std::vector<double>& out) const override {
        for (std::size_t i = 1; i < pieces_.size(); ++i) out.push_back(static_cast<double>(i) / n_);
    }
    // A stop lies where every component of d1 vanishes, hence at a root of each: the roots of
    // every component (as the 2-D cubic's breaks) hold every stop. Roots within 1e-9 of a
    // piece's ends are left to the ends.
    void speed_kinks(std::vector<double>& out) const override {
        for (std::size_t i = 0; i < pieces_.size(); ++i) {
            const Bezier3Piece& s = pieces_[i];
            for (int axis = 0; axis < 3; ++axis) {
                double r[2];
                const int n = derivative_roots(s, axis, r);
                for (int k = 0; k < n; ++k) {
                    if (r[k] > 1e-9 && r[k] < 1.0 - 1e-9) out.push_back((static_cast<double>(i) + r[k]) / n_);
                }
            }
        }
    }
    // The roots in (−∞, ∞) of one component of a piece's d1 (a Bernstein polynomial of degree
    // ≤ 2); their count.
    static int derivative_roots(const Bezier3Piece& s, int axis, double r[2]) noexcept {
        auto c = [axis](Vec3 v) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; };
        if (s.degree == 2) {
            const double q0 = c(s.q[0]), q1 = c(s.q[1]);
            if (q0 == q1) return 0;
            r[0] = q0 / (q0 - q1);
            return 1;
        }
        if (s.degree != 3) return 0;
        // q0·(1−t)² + 2·q1·t(1−t) + q2·t² = a·t² + b·t + q0.
        const double q0 = c(s.q[0]), q1 = c(s.q[1]), q2 = c(s.q[2]);
        const double a = q0 - 2.0 * q1 + q2, b = 2.0 * (q1 - q0);
        if (a == 0.0) {
            if (b == 0.0) return 0;
            r[0] = -q0 / b;
            return 1;
        }
        const double disc = b * b - 4.0 * a * q0;
        if (disc < 0.0) return 0;
        // The root away from cancellation first, the other from the product of roots.
        const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
        if (q == 0.0) {
            r[0] = 0.0;
            return 1;
        }
        r[0] = q / a;
        r[1] = q0 / q;
        return 2;
    }
    // Per piece and axis, the roots in (0, 1) of that component of d1, a Bernstein polynomial
    // of degree ≤ 2, and the piece's ends.
    Bounds3 compute_bounds() const override {
        Bounds3 box;
        for (const Bezier3Piece& s : pieces_) {
            box.add(s.p[0]);
            box.add(s.p[static_cast<std::size_t>(s.degree)]);
            auto add_at = [&](double t) {
                if (t > 0.0 && t < 1.0) box.add(casteljau3(s.p, s.degree + 1, t));
            };
            for (int axis = 0; axis < 3; ++axis) {
                double r[2];
                const int n = derivative_roots(s, axis, r);
                for (int k = 0; k < n; ++k) add_at(r[k]);
            }
        }
        return box;
    }
    // The piece holding u (the later one at a shared end) and the local t in [0, 1].
    const Bezier3Piece& at(double u, double& t) const noexcept {
        const double x = std::clamp(u, 0.0, 1.0) * n_;
        const double i = std::min(std::floor(x), n_ - 1.0);
        t = x - i;
        return pieces_[static_cast<std::size_t>(i)];
    }
    std::vector<Bezier3Piece> pieces_;
    double n_ = 1.0;
};

// Circular motion about an axis with an optional steady climb along it: θ = θ0 + dθ·u,
// point = center + radius·(e1·cos θ + e2·sin θ) + axis·(climb·u). An arc climbs 0; a helix
// starts at θ0 = 0.
class Circular3Node final : public Path3Node {
public:
    struct Frame {
        Vec3 center, a, e1, e2;
        double radius, theta0, dtheta, climb, length;
    };
    Circular3Node(Path3Kind kind, const Frame& f) : Path3Node(kind), f_(f) { finish(); }
    Vec3 point(double u) const noexcept override {
        const double th = f_.theta0 + f_.dtheta * u;
        return f_.center + (f_.e1 * std::cos(th) + f_.e2 * std::sin(th)) * f_.radius + f_.a * (f_.climb * u);
    }
    Vec3 d1(double u) const noexcept override {
        const double th = f_.theta0 + f_.dtheta * u;
        return (f_.e2 * std::cos(th) - f_.e1 * std::sin(th)) * (f_.radius * f_.dtheta) + f_.a * f_.climb;
    }
    Vec3 d2(double u) const noexcept override {
        const double th = f_.theta0 + f_.dtheta * u;
        return (f_.e1 * std::cos(th) + f_.e2 * std::sin(th)) * (-f_.radius * f_.dtheta * f_.dtheta);
    }
    Vec3 d3(double u) const noexcept override {
        const double th = f_.theta0 + f_.dtheta * u;
        return (f_.e2 * std::cos(th) - f_.e1 * std::sin(th)) * (-f_.radius * f_.dtheta * f_.dtheta * f_.dtheta);
    }
    double length_at(double u) const noexcept override { return std::clamp(u, 0.0, 1.0) * length_; }
    // |d2| = R·dθ² everywhere.
    double d2_bound(double, double) const noexcept override {
        return f_.radius * f_.dtheta * f_.dtheta * (1.0 + 1e-12);
    }
    double u_at_length(double s) const noexcept override {
        return length_ > 0.0 ? std::clamp(s / length_, 0.0, 1.0) : 0.0;
    }

private:
    // The speed is constant: the length is given in closed form.
    bool closed_form_length() override {
        length_ = f_.length;
        return true;
    }
    // Per axis i, d(point_i)/dθ = A·cos(θ + φ) + k with A = R·|(e1_i, e2_i)| and k the climb
    // per radian: its roots are θ = −φ ± acos(−k/A) + 2πn. Along one family the circular part
    // repeats and the climb is monotone, so only its first and last root in range can be extremes.
    Bounds3 compute_bounds() const override {
        Bounds3 box;
        box.add(point(0.0));
        box.add(point(1.0));
        if (!(f_.dtheta != 0.0)) return box;
        const double lo = std::min(f_.theta0, f_.theta0 + f_.dtheta), hi = std::max(f_.theta0, f_.theta0 + f_.dtheta);
        const double e1[] = {f_.e1.x, f_.e1.y, f_.e1.z}, e2[] = {f_.e2.x, f_.e2.y, f_.e2.z}, ax[] = {f_.a.x, f_.a.y, f_.a.z};
        for (int i = 0; i < 3; ++i) {
            const double h = std::hypot(e1[i], e2[i]);
            if (!(h > 0.0)) continue;
            const double amp = f_.radius * h;
            const double k = ax[i] * f_.climb / f_.dtheta;
            const double c = -k / amp;
            if (!(std::abs(c) <= 1.0)) continue;
            const double phi = std::atan2(e1[i], e2[i]);
            const double alpha = std::acos(c);
            for (const double beta : {-phi + alpha, -phi - alpha}) {
                const double n0 = std::ceil((lo - beta) / (2.0 * pi)), n1 = std::floor((hi - beta) / (2.0 * pi));
                if (n0 > n1) continue;
                for (const double n : {n0, n1}) {
                    const double th = beta + 2.0 * pi * n;
                    box.add(point(std::clamp((th - f_.theta0) / f_.dtheta, 0.0, 1.0)));
                }
            }
        }
        return box;
    }
    Frame f_;
};

class Complex3Node final : public Path3Node {
public:
    Complex3Node(std::vector<Path3> parts, std::vector<double> cues)
        : Path3Node(Path3Kind::complex), parts_(std::move(parts)) {
        double s = 0.0;
        for (std::size_t i = 0; i < parts_.size(); ++i) {
            const double start = cues[i];
            const double end = i + 1 < parts_.size() ? cues[i + 1] : 1.0;
            // An empty span is skipped; so is one too thin for 1/width (adjacent doubles).
            if (!(end > start) || !std::isfinite(1.0 / (end - start))) continue;
            const Path3Node* node = &Path3Access::node(parts_[i]);
            pieces_.push_back(Piece{node, start, 1.0 / (end - start), s});
            starts_.push_back(start);
            s += node->length();
        }
        finish();
    }
    Vec3 point(double u) const noexcept override {
        const Piece& p = at(u);
        return p.node->point(local(u, p));
    }
    // The piece that starts before u, at its end when u is the next piece's cue.
    Vec3 point_before(double u) const noexcept override {
        const auto it = std::lower_bound(starts_.begin(), starts_.end(), u);
        const std::size_t i = it == starts_.begin() ? 0 : static_cast<std::size_t>(it - starts_.begin()) - 1;
        const Piece& p = pieces_[i];
        const bool at_end = i + 1 < pieces_.size() && u >= pieces_[i + 1].start;
        return p.node->point_before(at_end ? 1.0 : local(u, p));
    }
    Vec3 d1(double u) const noexcept override {
        const Piece& p = at(u);
        return p.node->d1(local(u, p)) * p.inv_width;
    }
    Vec3 d2(double u) const noexcept override {
        const Piece& p = at(u);  // scaled in steps: inv_width² alone may overflow
        return p.node->d2(local(u, p)) * p.inv_width * p.inv_width;
    }
    Vec3 d3(double u) const noexcept override {
        const Piece& p = at(u);
        return p.node->d3(local(u, p)) * p.inv_width * p.inv_width * p.inv_width;
    }
    double length_at(double u) const noexcept override {
        if (!(u > 0.0)) return 0.0;
        if (u >= 1.0) return length_;
        const Piece& p = at(u);
        return p.s0 + p.node->length_at(local(u, p));
    }
    double d2_bound(double a, double b) const noexcept override {
        const Piece& p = at(0.5 * (a + b));
        return p.node->d2_bound(local(a, p), local(b, p)) * p.inv_width * p.inv_width;
    }
    // The parts flattened in turn, each from its own start: where parts do not meet the
    // polyline crosses the gap straight.
    void append_flattened(double tolerance, std::vector<Vec3>& out) const override {
        for (const Piece& p : pieces_) {
            const Vec3 start = p.node->point(0.0);
            if (!(start == out.back())) out.push_back(start);
            p.node->append_flattened(tolerance, out);
        }
    }
    double u_at_length(double s) const noexcept override {
        if (!(s > 0.0) || !(length_ > 0.0)) return 0.0;
        if (s >= length_) return 1.0;
        // The last piece starting at or before s (pieces of length 0 are passed over).
        std::size_t i = 0;
        while (i + 1 < pieces_.size() && pieces_[i + 1].s0 <= s) ++i;
        const Piece& p = pieces_[i];
        const double v = p.node->u_at_length(s - p.s0);
        const double end = i + 1 < pieces_.size() ? pieces_[i + 1].start : 1.0;
        return std::min(p.start + v / p.inv_width, end);
    }

private:
    struct Piece {
        const Path3Node* node;
        double start;
        double inv_width;
        double s0;  // length before the piece
    };
    Bounds3 compute_bounds() const override {
        Bounds3 box;
        for (const Piece& p : pieces_) box.add(p.node->bounds());
        return box;
    }
    void interior_breaks(std::vector<double>& out) const override {
        for (std::size_t i = 0; i < pieces_.size(); ++i) {
            const Piece& p = pieces_[i];
            if (i > 0) out.push_back(p.start);
            const auto& inner = p.node->breaks();
            for (std::size_t k = 1; k + 1 < inner.size(); ++k) {
                const double u = p.start + inner[k] / p.inv_width;
                if (u > out.back() && u < 1.0) out.push_back(u);
            }
        }
    }
    const Piece& at(double u) const noexcept {
        const auto it = std::upper_bound(starts_.begin(), starts_.end(), u);
        const std::size_t i = it == starts_.begin() ? 0 : static_cast<std::size_t>(it - starts_.begin()) - 1;
        return pieces_[i];
    }
    // The part's own parameter; exactly 1 at the whole's end.
    static double local(double u, const Piece& p) noexcept {
        return u >= 1.0 ? 1.0 : std::clamp((u - p.start) * p.inv_width, 0.0, 1.0);
    }
    std::vector<Path3> parts_;
    std::vector<Piece> pieces_;
    std::vector<double> starts_;
};

void check_point3(const char* where, const char* name, Vec3 p) {
    if (!is_finite(p)) throw Error(std::string(where) + ": " + name + ": not finite");
}

// A node wrapped in its handle, with the arguments it was built from.
Path3 wrap3(std::shared_ptr<Path3Node> node, Path3Spec spec) {
    node->set_spec(std::move(spec));
    return Path3Access::make(std::move(node));
}

Path3 bezier3(Path3Kind kind, std::span<const Vec3> pts, const char* where, Path3Spec spec) {
    static const char* const names[] = {"p0", "p1", "p2", "p3"};
    for (std::size_t i = 0; i < pts.size(); ++i) {
        check_point3(where, kind == Path3Kind::line ? (i == 0 ? "a" : "b") : names[i], pts[i]);
    }
    return wrap3(std::make_shared<Bezier3Node>(kind, std::vector<Bezier3Piece>{make_piece3(pts)}), std::move(spec));
}

void check_points3(const std::string& where, const char* name, std::span<const Vec3> points, std::size_t least) {
    if (points.size() < least) {
        throw Error(where + ": " + name + ": need at least " + std::to_string(least) + ", got " +
                    std::to_string(points.size()));
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!is_finite(points[i])) throw Error(where + ": " + name + "[" + std::to_string(i) + "]: not finite");
    }
}

// The unit axis and the unit start direction across it; `where` names the factory.
void circle_frame3(const std::string& where, Vec3 axis, Vec3 start, Vec3& a, Vec3& e1, Vec3& e2) {
    if (!is_finite(axis)) throw Error(where + ": axis: not finite");
    if (!is_finite(start)) throw Error(where + ": start: not finite");
    a = normalized(axis);
    if (!(grape::length(a) > 0.5)) throw Error(where + ": axis: zero vector");
    const Vec3 s = normalized(start);
    if (!(grape::length(s) > 0.5)) throw Error(where + ": start: zero vector");
    const Vec3 across = s - a * dot(s, a);
    // A start within ~1e-8 rad of the axis leaves no reliable direction.
    if (!(grape::length(across) > 1e-8)) throw Error(where + ": start: parallel to the axis");
    e1 = normalized(across);
    e2 = cross(a, e1);
}

}  // namespace
}  // namespace detail

std::string_view to_string(Path3Kind kind) noexcept {
    switch (kind) {
        case Path3Kind::line: return "line";
        case Path3Kind::quadratic_bezier: return "quadratic_bezier";
        case Path3Kind::cubic_bezier: return "cubic_bezier";
        case Path3Kind::catmull_rom: return "catmull_rom";
        case Path3Kind::helix: return "helix";
        case Path3Kind::complex: return "complex";
        case Path3Kind::hermite: return "hermite";
        case Path3Kind::linear_spline: return "linear_spline";
        case Path3Kind::arc: return "arc";
        case Path3Kind::projectile: return "projectile";
        case Path3Kind::on_plane: return "on_plane";
        case Path3Kind::reparametrized: return "reparametrized";
        case Path3Kind::slice: return "slice";
    }
    return "unknown";
}

Path3::Path3() : Path3(line(Vec3{}, Vec3{})) {}

Path3::Path3(std::shared_ptr<const detail::Path3Node> node) noexcept : node_(std::move(node)) {}

Path3 Path3::line(Vec3 a, Vec3 b) {
    const Vec3 pts[] = {a, b};
    return detail::bezier3(Path3Kind::line, pts, "Path3::line", Line3Spec{a, b});
}

Path3 Path3::quadratic_bezier(Vec3 p0, Vec3 p1, Vec3 p2) {
    const Vec3 pts[] = {p0, p1, p2};
    return detail::bezier3(Path3Kind::quadratic_bezier, pts, "Path3::quadratic_bezier",
                           QuadraticBezier3Spec{{p0, p1, p2}});
}

Path3 Path3::cubic_bezier(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3) {
    const Vec3 pts[] = {p0, p1, p2, p3};
    return detail::bezier3(Path3Kind::cubic_bezier, pts, "Path3::cubic_bezier", CubicBezier3Spec{{p0, p1, p2, p3}});
}

Path3 Path3::catmull_rom(std::span<const Vec3> points, CatmullRom type, bool closed) {
    const std::string where = "Path3::catmull_rom";
    const std::size_t n = points.size();
    if (n < (closed ? 3u : 2u)) {
        throw Error(where + ": points: need at least " + (closed ? "3 for a closed" : "2 for an open") +
                    " spline, got " + std::to_string(n));
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!is_finite(points[i])) throw Error(where + ": points[" + std::to_string(i) + "]: not finite");
    }
    const double alpha = type == CatmullRom::uniform ? 0.0 : type == CatmullRom::centripetal ? 0.5 : 1.0;
    auto spacing = [alpha](Vec3 a, Vec3 b) {
        const double d = alpha == 0.0 ? 1.0 : std::pow(distance(a, b), alpha);
        return d > 0.0 ? d : 1.0;
    };
    const std::size_t segments = closed ? n : n - 1;
    std::vector<detail::Bezier3Piece> pieces;
    pieces.reserve(segments);
    for (std::size_t i = 0; i < segments; ++i) {
        const Vec3 p1 = points[i], p2 = points[(i + 1) % n];
        Vec3 p0, p3;
        if (closed) {
            p0 = points[(i + n - 1) % n];
            p3 = points[(i + 2) % n];
        } else {
            // Phantom points mirror the neighbour at the ends, as in 2-D.
            p0 = i > 0 ? points[i - 1] : 2.0 * p1 - p2;
            p3 = i + 2 < n ? points[i + 2] : 2.0 * p2 - p1;
        }
        const double d01 = spacing(p0, p1), d12 = spacing(p1, p2), d23 = spacing(p2, p3);
        // Barry–Goldman tangents in knot units, scaled to the segment's t by d12; the segment
        // is the cubic Hermite with these tangents, written as a Bézier.
        const Vec3 m1 = ((p1 - p0) / d01 - (p2 - p0) / (d01 + d12) + (p2 - p1) / d12) * d12;
        const Vec3 m2 = ((p2 - p1) / d12 - (p3 - p1) / (d12 + d23) + (p3 - p2) / d23) * d12;
        const Vec3 pts[] = {p1, p1 + m1 / 3.0, p2 - m2 / 3.0, p2};
        pieces.push_back(detail::make_piece3(pts));
    }
    return detail::wrap3(std::make_shared<detail::Bezier3Node>(Path3Kind::catmull_rom, std::move(pieces)),
                         CatmullRom3Spec{{points.begin(), points.end()}, type, closed});
}

Path3 Path3::helix(const HelixSpec& h) {
    const std::string where = "Path3::helix";
    if (!is_finite(h.center)) throw Error(where + ": center: not finite");
    if (!(std::isfinite(h.radius) && h.radius > 0.0)) throw Error(where + ": radius: must be finite and > 0, got " + detail::number_text(h.radius));
    if (!std::isfinite(h.rise)) throw Error(where + ": rise: not finite");
    if (!(std::isfinite(h.turns) && h.turns > 0.0)) throw Error(where + ": turns: must be finite and > 0, got " + detail::number_text(h.turns));
    detail::Circular3Node::Frame f{};
    detail::circle_frame3(where, h.axis, h.start, f.a, f.e1, f.e2);
    f.center = h.center;
    f.radius = h.radius;
    f.theta0 = 0.0;
    f.dtheta = 2.0 * pi * h.turns;
    f.climb = h.rise * h.turns;
    // L = turns·√((2πR)² + rise²).
    f.length = h.turns * std::hypot(2.0 * pi * h.radius, h.rise);
    return detail::wrap3(std::make_shared<detail::Circular3Node>(Path3Kind::helix, f), h);
}

Path3 Path3::arc(const Arc3Spec& spec) {
    const std::string where = "Path3::arc";
    if (!is_finite(spec.center)) throw Error(where + ": center: not finite");
    if (!(std::isfinite(spec.radius) && spec.radius > 0.0)) throw Error(where + ": radius: must be finite and > 0, got " + detail::number_text(spec.radius));
    if (!std::isfinite(spec.start_angle)) throw Error(where + ": start_angle: not finite");
    if (!std::isfinite(spec.end_angle)) throw Error(where + ": end_angle: not finite");
    detail::Circular3Node::Frame f{};
    detail::circle_frame3(where, spec.axis, spec.start, f.a, f.e1, f.e2);
    f.center = spec.center;
    f.radius = spec.radius;
    f.theta0 = spec.start_angle;
    f.dtheta = spec.end_angle - spec.start_angle;
    if (!std::isfinite(f.dtheta)) throw Error(where + ": end_angle: its difference from start_angle overflows a double");
    f.climb = 0.0;
    f.length = spec.radius * std::abs(f.dtheta);
    return detail::wrap3(std::make_shared<detail::Circular3Node>(Path3Kind::arc, f), spec);
}

Path3 Path3::hermite(std::span<const Vec3> points, std::span<const Vec3> tangents, bool closed) {
    const std::string where = "Path3::hermite";
    detail::check_points3(where, "points", points, closed ? 3 : 2);
    if (tangents.size() != points.size()) {
        throw Error(where + ": tangents: need one per point (" + std::to_string(points.size()) + "), got " +
                    std::to_string(tangents.size()));
    }
    detail::check_points3(where, "tangents", tangents, 0);
    const std::size_t n = points.size(), segments = closed ? n : n - 1;
    std::vector<detail::Bezier3Piece> pieces;
    pieces.reserve(segments);
    for (std::size_t i = 0; i < segments; ++i) {
        const std::size_t j = (i + 1) % n;
        const Vec3 pts[] = {points[i], points[i] + tangents[i] / 3.0, points[j] - tangents[j] / 3.0, points[j]};
        pieces.push_back(detail::make_piece3(pts));
    }
    return detail::wrap3(std::make_shared<detail::Bezier3Node>(Path3Kind::hermite, std::move(pieces)),
                         Hermite3Spec{{points.begin(), points.end()}, {tangents.begin(), tangents.end()}, closed});
}

Path3 Path3::linear_spline(std::span<const Vec3> points, bool closed) {
    detail::check_points3("Path3::linear_spline", "points", points, closed ? 3 : 2);
    const std::size_t n = points.size(), segments = closed ? n : n - 1;
    std::vector<detail::Bezier3Piece> pieces;
    pieces.reserve(segments);
    for (std::size_t i = 0; i < segments; ++i) {
        const Vec3 pts[] = {points[i], points[(i + 1) % n]};
        pieces.push_back(detail::make_piece3(pts));
    }
    return detail::wrap3(std::make_shared<detail::Bezier3Node>(Path3Kind::linear_spline, std::move(pieces)),
                         LinearSpline3Spec{{points.begin(), points.end()}, closed});
}

Path3 Path3::projectile(Vec3 position, Vec3 velocity, Vec3 acceleration, double seconds) {
    const std::string where = "Path3::projectile";
    detail::check_point3(where.c_str(), "position", position);
    detail::check_point3(where.c_str(), "velocity", velocity);
    detail::check_point3(where.c_str(), "acceleration", acceleration);
    if (!(std::isfinite(seconds) && seconds > 0.0)) throw Error(where + ": seconds: must be finite and > 0, got " + detail::number_text(seconds));
    // p + v·t + ½·g·t² over t in [0, T] is the quadratic Bézier p, p + v·T/2, p + v·T + g·T²/2.
    const Vec3 pts[] = {position, position + velocity * (0.5 * seconds),
                        position + velocity * seconds + acceleration * (0.5 * seconds * seconds)};
    for (std::size_t i = 0; i < 3; ++i) {
        if (!is_finite(pts[i])) throw Error(where + ": seconds: the path's points overflow a double");
    }
    return detail::wrap3(std::make_shared<detail::Bezier3Node>(Path3Kind::projectile, std::vector<detail::Bezier3Piece>{detail::make_piece3(pts)}),
                         Projectile3Spec{position, velocity, acceleration, seconds});
}

Path3 Path3::complex(std::vector<Path3> parts, std::vector<double> cues) {
    const std::string where = "Path3::complex";
    if (parts.empty()) throw Error(where + ": parts: empty");
    if (cues.size() != parts.size()) {
        throw Error(where + ": cues: need one per part (" + std::to_string(parts.size()) + "), got " +
                    std::to_string(cues.size()));
    }
    for (std::size_t i = 0; i < cues.size(); ++i) {
        const std::string name = where + ": cues[" + std::to_string(i) + "]: ";
        if (!std::isfinite(cues[i]) || cues[i] < 0.0 || cues[i] > 1.0) throw Error(name + "must be in [0, 1], got " + detail::number_text(cues[i]));
        if (i == 0 && cues[i] != 0.0) throw Error(name + "must be 0, got " + detail::number_text(cues[i]));
        if (i > 0 && cues[i] < cues[i - 1]) throw Error(name + "decreases (below cues[" + std::to_string(i - 1) + "])");
    }
    Complex3Spec spec{parts, cues};
    return detail::wrap3(std::make_shared<detail::Complex3Node>(std::move(parts), std::move(cues)), std::move(spec));
}

Path3 Path3::complex_by_length(std::vector<Path3> parts) {
    if (parts.empty()) throw Error("Path3::complex_by_length: parts: empty");
    double total = 0.0;
    for (const Path3& p : parts) total += p.length();
    std::vector<double> cues(parts.size(), 0.0);
    double s = 0.0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        cues[i] = total > 0.0 ? std::min(s / total, 1.0) : static_cast<double>(i) / static_cast<double>(parts.size());
        s += parts[i].length();
    }
    return complex(std::move(parts), std::move(cues));
}

Path3Kind Path3::kind() const noexcept { return node_->kind(); }

// Outside [0, 1] the path continues along its end tangents (as a 2-D Path does).
Vec3 Path3::point(double u) const noexcept {
    if (u < 0.0) return node_->point(0.0) + node_->d1(0.0) * u;
    if (u > 1.0) return node_->point(1.0) + node_->d1(1.0) * (u - 1.0);
    return node_->point(u);
}
Vec3 Path3::d1(double u) const noexcept { return node_->d1(std::clamp(u, 0.0, 1.0)); }
Vec3 Path3::d2(double u) const noexcept { return u < 0.0 || u > 1.0 ? Vec3{} : node_->d2(u); }
Vec3 Path3::d3(double u) const noexcept { return u < 0.0 || u > 1.0 ? Vec3{} : node_->d3(u); }

Vec3 Path3::tangent(double u) const noexcept {
    u = std::clamp(u, 0.0, 1.0);
    // At a stop (zero speed) the direction of motion is the limit of d1/|d1|: that of the
    // first derivative that is not zero.
    Vec3 t = normalized(node_->d1(u));
    if (t == Vec3{}) t = normalized(node_->d2(u));
    if (t == Vec3{}) t = normalized(node_->d3(u));
    if (t == Vec3{}) t = {1.0, 0.0, 0.0};
    return t;
}

Frenet3 Path3::frenet(double u) const noexcept {
    u = std::clamp(u, 0.0, 1.0);
    Frenet3 f;
    f.point = node_->point(u);
    const Vec3 r1 = node_->d1(u), r2 = node_->d2(u), r3 = node_->d3(u);
    f.tangent = tangent(u);
    const Vec3 c = cross(r1, r2);
    const double speed = grape::length(r1);
    const double cn = grape::length(c);
    // |r′ × r″| below the rounding noise of its own products counts as zero curvature.
    const double noise = 16.0 * std::numeric_limits<double>::epsilon() * speed * grape::length(r2);
    if (speed > 0.0 && cn > noise) {
        f.normal_defined = true;
        f.binormal = c / cn;
        f.normal = cross(f.binormal, f.tangent);
        f.curvature = cn / speed / speed / speed;  // in steps: speed³ alone may overflow
        f.torsion = dot(c / cn, r3) / cn;
    } else {
        f.normal = any_perpendicular(f.tangent);
        f.binormal = cross(f.tangent, f.normal);
    }
    return f;
}

double Path3::length() const noexcept { return node_->length(); }
double Path3::length_at(double u) const noexcept { return node_->length_at(std::clamp(u, 0.0, 1.0)); }
double Path3::u_at_length(double s) const noexcept { return node_->u_at_length(s); }
Vec3 Path3::point_at_length(double s) const noexcept { return node_->point(u_at_length(s)); }
std::span<const double> Path3::breaks() const noexcept { return node_->breaks(); }
const Bounds3& Path3::bounds() const noexcept { return node_->bounds(); }

std::vector<Vec3> Path3::flatten(double tolerance) const {
    if (!(std::isfinite(tolerance) && tolerance > 0.0)) {
        throw Error("Path3::flatten: tolerance: must be finite and > 0, got " + detail::number_text(tolerance));
    }
    const Bounds3& b = node_->bounds();
    const Vec3 size = b.size();
    const double extent = std::max({std::abs(size.x), std::abs(size.y), std::abs(size.z), 0.0});
    // Below 1e-12 of the size the rounding of the points themselves is the error.
    tolerance = std::max(tolerance, 1e-12 * (std::isfinite(extent) ? extent : 0.0));
    std::vector<Vec3> out{node_->point(0.0)};
    node_->append_flattened(tolerance, out);
    return out;
}

}  // namespace grape
