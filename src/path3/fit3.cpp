// grape — fitting 3-D cubic Béziers to sampled points, the 2-D fit (src/path/fit.cpp) in 3-D,
// after P. J. Schneider, "An Algorithm for Automatically Fitting Digitized Curves" (Graphics
// Gems, 1990): per run between corners, end tangents from the data, chord-length parameters,
// least-squares handle lengths along the tangents, Newton steps on the parameters while the
// error is near the goal, and a split at the worst point (tangent there from its neighbours)
// otherwise.
#include <grape/error.hpp>
#include <grape/path3.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace grape {

namespace {

struct FitBezier3 {
    Vec3 p[4];
    Vec3 at(double t) const noexcept {
        const double s = 1.0 - t;
        return p[0] * (s * s * s) + p[1] * (3.0 * s * s * t) + p[2] * (3.0 * s * t * t) + p[3] * (t * t * t);
    }
    Vec3 d1(double t) const noexcept {
        const double s = 1.0 - t;
        return 3.0 * (s * s * (p[1] - p[0]) + 2.0 * s * t * (p[2] - p[1]) + t * t * (p[3] - p[2]));
    }
    Vec3 d2(double t) const noexcept { return 6.0 * ((1.0 - t) * (p[2] - 2.0 * p[1] + p[0]) + t * (p[3] - 2.0 * p[2] + p[1])); }
};

struct Fitter3 {
    const std::vector<Vec3>& pts;
    double tolerance;
    std::vector<FitBezier3> out;

    // Handles at a third of the chord: the fallback when least squares degenerates.
    FitBezier3 thirds(std::size_t first, std::size_t last, Vec3 t1, Vec3 t2) const {
        const double d = distance(pts[first], pts[last]) / 3.0;
        return {{pts[first], pts[first] + t1 * d, pts[last] + t2 * d, pts[last]}};
    }

    FitBezier3 least_squares(std::size_t first, std::size_t last, const std::vector<double>& u, Vec3 t1, Vec3 t2) const {
        const Vec3 a = pts[first], b = pts[last];
        double c00 = 0, c01 = 0, c11 = 0, x0 = 0, x1 = 0;
        for (std::size_t i = first; i <= last; ++i) {
            const double t = u[i - first], s = 1.0 - t;
            const double b0 = s * s * s, b1 = 3 * s * s * t, b2 = 3 * s * t * t, b3 = t * t * t;
            const Vec3 a1 = t1 * b1, a2 = t2 * b2;
            const Vec3 rest = pts[i] - (a * (b0 + b1) + b * (b2 + b3));
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
    double worst(const FitBezier3& q, std::size_t first, std::size_t last, const std::vector<double>& u, std::size_t& at) const {
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

    void fit(std::size_t first, std::size_t last, Vec3 t1, Vec3 t2) {
        if (last - first == 1) {
            out.push_back(thirds(first, last, t1, t2));
            return;
        }
        std::vector<double> u(last - first + 1, 0.0);
        for (std::size_t i = first + 1; i <= last; ++i) u[i - first] = u[i - first - 1] + distance(pts[i], pts[i - 1]);
        for (double& v : u) v /= u.back();
        FitBezier3 q = least_squares(first, last, u, t1, t2);
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
                    const Vec3 r = q.at(t) - pts[i], g = q.d1(t), h = q.d2(t);
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
        const Vec3 center = normalized(pts[split - 1] - pts[split + 1]);
        fit(first, split, t1, center);
        fit(split, last, -center, t2);
    }
};

[[noreturn]] void fit3_fail(const std::string& what) { throw Error("fit_path (3-D): " + what); }

}  // namespace

Path3 fit_path(std::span<const Vec3> points, const FitPathDef& def) {
    if (!(def.tolerance > 0.0) || !std::isfinite(def.tolerance)) {
        fit3_fail("tolerance must be positive and finite (got " + detail::number_text(def.tolerance) + ")");
    }
    if (!(def.corner_angle > 0.0 && def.corner_angle <= pi)) {
        fit3_fail("corner_angle must lie in (0, π] radians (got " + detail::number_text(def.corner_angle) + ")");
    }
    std::vector<Vec3> pts;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!is_finite(points[i])) fit3_fail("points[" + std::to_string(i) + "] must be finite");
        if (pts.empty() || !(points[i] == pts.back())) pts.push_back(points[i]);
    }
    if (pts.size() < 2) fit3_fail("needs at least 2 distinct points (got " + std::to_string(pts.size()) + ")");

    // Runs between corners: where successive chords turn by more than the corner angle.
    std::vector<std::size_t> ends{0};
    const double cos_corner = std::cos(def.corner_angle);
    for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
        const Vec3 a = normalized(pts[i] - pts[i - 1]), b = normalized(pts[i + 1] - pts[i]);
        if (dot(a, b) < cos_corner) ends.push_back(i);
    }
    ends.push_back(pts.size() - 1);

    Fitter3 fitter{pts, def.tolerance, {}};
    for (std::size_t r = 0; r + 1 < ends.size(); ++r) {
        const std::size_t first = ends[r], last = ends[r + 1];
        fitter.fit(first, last, normalized(pts[first + 1] - pts[first]), normalized(pts[last - 1] - pts[last]));
    }
    std::vector<Path3> parts;
    parts.reserve(fitter.out.size());
    for (const FitBezier3& b : fitter.out) parts.push_back(Path3::cubic_bezier(b.p[0], b.p[1], b.p[2], b.p[3]));
    return Path3::complex_by_length(std::move(parts));
}

}  // namespace grape
