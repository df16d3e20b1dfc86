// grape — rotation-minimizing frames by double reflection on knots placed by the error.
#include "node3.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace grape {
namespace {

// r without its part along the unit t, made unit again: keeps the frame orthonormal3 to a few
// ulp however many steps it has been carried.
Vec3 orthonormal3(Vec3 r, Vec3 t) noexcept {
    const Vec3 q = normalized(r - t * dot(r, t));
    return q == Vec3{} ? any_perpendicular(t) : q;
}

// The least rotation taking the unit a to the unit b, applied to r (Rodrigues with k = a × b,
// |k| = sin θ, c = cos θ). Opposite tangents (a cusp) leave r as it is: still ⟂ b.
Vec3 turn3(Vec3 a, Vec3 b, Vec3 r) noexcept {
    const Vec3 k = cross(a, b);
    const double c = dot(a, b);
    if (!(c > -1.0 + 1e-12)) return r;
    return r * c + cross(k, r) + k * (dot(k, r) / (1.0 + c));
}

}  // namespace

Vec3 RotationMinimizingFrames::double_reflection(Vec3 x0, Vec3 t0, Vec3 r0, Vec3 x1, Vec3 t1) noexcept {
    // Reflection 1 in the bisecting plane of x0 and x1, then reflection 2 taking the
    // reflected tangent to t1 (Wang et al. 2008, Algorithm 1).
    const Vec3 v1 = x1 - x0;
    const double c1 = dot(v1, v1);
    Vec3 rl = r0, tl = t0;
    if (c1 > 0.0) {
        rl = r0 - v1 * (2.0 * dot(v1, r0) / c1);
        tl = t0 - v1 * (2.0 * dot(v1, t0) / c1);
    }
    const Vec3 v2 = t1 - tl;
    const double c2 = dot(v2, v2);
    const Vec3 r1 = c2 > 0.0 ? rl - v2 * (2.0 * dot(v2, rl) / c2) : rl;
    return orthonormal3(r1, t1);
}

RotationMinimizingFrames::RotationMinimizingFrames(Path3 path, Vec3 up, double tolerance) : path_(std::move(path)) {
    const std::string where = "RotationMinimizingFrames: ";
    if (!is_finite(up)) throw Error(where + "up: not finite");
    if (!(tolerance >= 1e-13 && tolerance <= 0.1)) {
        throw Error(where + "tolerance: must be in [1e-13, 0.1] radians, got " + detail::number_text(tolerance));
    }
    const Vec3 t0 = path_.tangent(0.0);
    const Vec3 across = up - t0 * dot(up, t0);
    // Within ~1e-6 rad of the tangent the normal would be mostly rounding.
    if (!(length(across) > 1e-6 * length(up))) throw Error(where + "up: zero or parallel to the tangent at u = 0");

    const double total = path_.length();
    const std::span<const double> breaks = path_.breaks();
    Vec3 r = orthonormal3(across, t0);
    auto keep = [this](double u, Vec3 normal) { knots_.push_back({u, normal, path_.point(u), path_.tangent(u)}); };
    keep(0.0, r);
    auto step = [this](double a, Vec3 ra, double b) noexcept {
        return double_reflection(path_.point(a), path_.tangent(a), ra, path_.point(b), path_.tangent(b));
    };
    for (std::size_t piece = 0; piece + 1 < breaks.size(); ++piece) {
        const double a = breaks[piece], b = breaks[piece + 1];
        if (piece > 0) {
            // At a break, the tangent arriving (the limit from the left) turns into the one
            // leaving by the least rotation.
            const Vec3 leaving = path_.tangent(a);
            r = orthonormal3(turn3(path_.tangent(std::nextafter(a, 0.0)), leaving, r), leaving);
            keep(a, r);
        }
        double u = a;
        // The least step keeps u moving (u + h_min > u for u ≤ 1); a piece narrower than it
        // is crossed in one step.
        const double h_min = std::min(b - a, std::max((b - a) * 1e-12, 16.0 * std::numeric_limits<double>::epsilon()));
        double h = std::max((b - a) / 8.0, h_min);
        while (u < b) {
            const double u1 = b - u <= h * 1.000001 ? b : u + h;
            // At the end of a piece, the tangent is its own (from the left).
            const double e1 = u1 == b && piece + 2 < breaks.size() ? std::nextafter(b, 0.0) : u1;
            const double um = 0.5 * (u + u1);
            const Vec3 one = step(u, r, e1);
            const Vec3 half = step(um, step(u, r, um), e1);
            // The roll error of the two half steps kept, radians: with a local error c·h⁵ the
            // single step is off by 16 times the pair, so one − half ≈ 15 times the pair's.
            const double error = length(one - half) / 15.0;
            const double chord = distance(path_.point(u), path_.point(u1));
            const double taken = u1 - u;
            // Half by chord, half by u: the shares of all steps sum to at most `tolerance`.
            const double allowed = 0.5 * tolerance * (total > 0.0 ? std::max(chord / total, taken) : 1.0);
            // An estimate at rounding level (a few ulps of a unit vector) cannot be refined away:
            // a smaller step would only add roundings.
            constexpr double rounding = 64.0 * std::numeric_limits<double>::epsilon();
            const double within = std::max(allowed, rounding);
            if (error <= within || h <= h_min) {
                // Keep the two half steps, whose error the estimate is.
                if (knots_.size() + 3 > max_knots) {
                    throw Error(where + "path: needs more than " + std::to_string(max_knots) + " knots for a tolerance of " +
                                detail::number_text(tolerance) + " rad near u = " + detail::number_text(u) +
                                " (a cusp, where the frame is undefined?)");
                }
                keep(um, step(u, r, um));
                if (u1 < b) keep(u1, half);
                r = half;
                u = u1;
            }
            // Local error ∝ h⁵: aim at 0.9 of the allowance, growing at most twice.
            const double grow = error > 0.0 ? 0.9 * std::pow(within / error, 0.2) : 2.0;
            h = std::max(h_min, taken * std::clamp(grow, 0.2, 2.0));
        }
        if (piece + 2 == breaks.size()) keep(1.0, r);
    }
    // As many buckets as knots: where knots are evenly spread in u a lookup scans about one.
    const std::size_t n = knots_.size();
    bucket_.resize(n + 1);
    buckets_ = static_cast<double>(n);
    std::size_t k = 0;
    for (std::size_t i = 0; i <= n; ++i) {
        const double at = static_cast<double>(i) / buckets_;
        while (k + 1 < n && knots_[k + 1].u <= at) ++k;
        bucket_[i] = static_cast<std::uint32_t>(k);
    }
}

Frame3 RotationMinimizingFrames::frame(double u) const noexcept {
    u = std::clamp(u, 0.0, 1.0);
    // The last knot at or before u: from the bucket's knot (back one where u·n rounded up to
    // the bucket's own u), then forward while the next knot is not past u.
    std::size_t i = bucket_[static_cast<std::size_t>(u * buckets_)];
    while (i > 0 && knots_[i].u > u) --i;
    while (i + 1 < knots_.size() && knots_[i + 1].u <= u) ++i;
    const Knot& k = knots_[i];
    Frame3 f;
    f.point = path_.point(u);
    f.tangent = path_.tangent(u);
    f.normal = k.u == u ? orthonormal3(k.normal, f.tangent)
                        : double_reflection(k.point, k.tangent, k.normal, f.point, f.tangent);
    f.binormal = cross(f.tangent, f.normal);
    return f;
}

const Path3& RotationMinimizingFrames::path() const noexcept { return path_; }
std::size_t RotationMinimizingFrames::knot_count() const noexcept { return knots_.size(); }
double RotationMinimizingFrames::knot_u(std::size_t i) const noexcept { return knots_[i].u; }

}  // namespace grape
