// grape — fitting cubic Béziers to sampled points, after P. J. Schneider, "An Algorithm for
// Automatically Fitting Digitized Curves" (Graphics Gems, 1990): per run between corners, end
// tangents from the data, chord-length parameters, least-squares handle lengths along the
// tangents, Newton steps on the parameters while the error is near the goal, and a split at the
// worst point (tangent there from its neighbours) otherwise.
#include <grape/error.hpp>
#include <grape/path_query.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace grape {

namespace {

struct Bezier {
    Vec2 p[4];
    Vec2 at(double t) const noexcept {
        const double s = 1.0 - t;
        return p[0] * (s * s * s) + p[1] * (3.0 * s * s * t) + p[2] * (3.0 * s * t * t) + p[3] * (t * t * t);
    }
    Vec2 d1(double t) const noexcept {
        const double s = 1.0 - t;
        return 3.0 * (s * s * (p[1] - p[0]) + 2.0 * s * t * (p[2] - p[1]) + t * t * (p[3] - p[2]));
    }
    Vec2 d2(double t) const noexcept { return 6.0 * ((1.0 - t) * (p[2] - 2.0 * p[1] + p[0]) + t * (p[3] - 2.0 * p[2] + p[1])); }
};

struct Fitter {
    const std::vector<Vec2>& pts;
    double tolerance;
    std::vector<Bezier> out;

    // Handles at a third of the chord: the fallback when least squares degenerates.
    Bezier thirds(std::size_t first, std::size_t last, Vec2 t1, Vec2 t2) const {
        const double d = distance(pts[first], pts[last]) / 3.0;
        return {{pts[first], pts[first] + t1 * d, pts[last] + t2 * d, pts[last]}};
    }

    Bezier least_squares(std::size_t first, std::size_t last, const std::vector<double>& u, Vec2 t1, Vec2 t2) const {
        const Vec2 a = pts[first], b = pts[last];
        double c00 = 0, c01 = 0, c11 = 0, x0 = 0, x1 = 0;
        for (std::size_t i = first; i <= last; ++i) {
            const double t = u[i - first], s = 1.0 - t;
            const double b0 = s * s * s, b1 = 3 * s * s * t, b2 = 3 * s * t * t, b3 = t * t * t;
            const Vec2 a1 = t1 * b1, a2 = t2 * b2;
            const Vec2 rest = pts[i] - (a * (b0 + b1) + b * (b2 + b3));
            c00 += dot(a1, a1);
            c01 += dot(a1, a2);
            c11 += dot(a2, a2);
            x0 += dot(a1, rest);
            x1 += dot(a2, rest);
        }
        const double det = c00 * c11 - c01 * c01;
        const double chord = distance(a, b);
        double l1 = det != 0.0 ? (x0 * c11 - x1 * c01) / det : 0.0;
        double l2 = det != 0.0 ? (c00 * x1 - c01 * x0) / det : 0.0;
        // A handle pointing backwards or vanishing makes loops and cusps: use the thirds instead.
        if (!(l1 > 1e-6 * chord) || !(l2 > 1e-6 * chord) || !std::isfinite(l1 + l2)) return thirds(first, last, t1, t2);
        return {{a, a + t1 * l1, b + t2 * l2, b}};
    }

    // Largest |Q(u_i) − p_i| (an upper bound on the point's distance from the curve) and where.
    double worst(const Bezier& q, std::size_t first, std::size_t last, const std::vector<double>& u, std::size_t& at) const {
        double e = 0.0;
        at = (first + last) / 2;
        for (std::size_t i = first + 1; i < last; ++i) {
            const double d = distance(q.at(u[i - first]), pts[i]);
            if (d > e) {
                e = d;
                at = i;
            }
        }
        return e;
    }

    void fit(std::size_t first, std::size_t last, Vec2 t1, Vec2 t2) {
        if (last - first == 1) {
            out.push_back(thirds(first, last, t1, t2));
            return;
        }
        std::vector<double> u(last - first + 1, 0.0);
        for (std::size_t i = first + 1; i <= last; ++i) u[i - first] = u[i - first - 1] + distance(pts[i], pts[i - 1]);
        for (double& v : u) v /= u.back();
        Bezier q = least_squares(first, last, u, t1, t2);
        std::size_t split = 0;
        double e = worst(q, first, last, u, split);
        if (e <= tolerance) {
            out.push_back(q);
            return;
        }
        // Near the goal, better parameters (the foot of each point on the curve) usually suffice.
        if (e <= 4.0 * tolerance) {
            for (int iteration = 0; iteration < 20; ++iteration) {
                for (std::size_t i = first + 1; i < last; ++i) {
                    double& t = u[i - first];
                    const Vec2 r = q.at(t) - pts[i], g = q.d1(t), h = q.d2(t);
                    const double den = dot(g, g) + dot(r, h);
                    if (den > 0.0) t = std::clamp(t - dot(r, g) / den, 0.0, 1.0);
                }
                q = least_squares(first, last, u, t1, t2);
                e = worst(q, first, last, u, split);
                if (e <= tolerance) {
                    out.push_back(q);
                    return;
                }
            }
        }
        const Vec2 center = normalized(pts[split - 1] - pts[split + 1]);
        fit(first, split, t1, center);
        fit(split, last, -center, t2);
    }
};

[[noreturn]] void fit_fail(const std::string& what) { throw Error("fit_path: " + what); }

}  // namespace

ComplexPath fit_path(std::span<const Vec2> points, const FitPathDef& def) {
    if (!(def.tolerance > 0.0) || !std::isfinite(def.tolerance)) {
        fit_fail("tolerance must be positive and finite (got " + detail::number_text(def.tolerance) + ")");
    }
    if (!(def.corner_angle > 0.0 && def.corner_angle <= pi)) {
        fit_fail("corner_angle must lie in (0, π] radians (got " + detail::number_text(def.corner_angle) + ")");
    }
    std::vector<Vec2> pts;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!is_finite(points[i])) fit_fail("points[" + std::to_string(i) + "] must be finite");
        if (pts.empty() || points[i] != pts.back()) pts.push_back(points[i]);
    }
    if (pts.size() < 2) fit_fail("needs at least 2 distinct points (got " + std::to_string(pts.size()) + ")");

    // Runs between corners: where successive chords turn by more than the corner angle.
    std::vector<std::size_t> ends{0};
    const double cos_corner = std::cos(def.corner_angle);
    for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
        const Vec2 a = normalized(pts[i] - pts[i - 1]), b = normalized(pts[i + 1] - pts[i]);
        if (dot(a, b) < cos_corner) ends.push_back(i);
    }
    ends.push_back(pts.size() - 1);

    Fitter fitter{pts, def.tolerance, {}};
    for (std::size_t r = 0; r + 1 < ends.size(); ++r) {
        const std::size_t first = ends[r], last = ends[r + 1];
        fitter.fit(first, last, normalized(pts[first + 1] - pts[first]), normalized(pts[last - 1] - pts[last]));
    }
    std::vector<Path> parts;
    parts.reserve(fitter.out.size());
    for (const Bezier& b : fitter.out) parts.push_back(CubicBezierPath(b.p[0], b.p[1], b.p[2], b.p[3]));
    return ComplexPath::by_length(std::move(parts));
}

}  // namespace grape
