// grape — data along a path (Unity's SplineData): a track of any Interpolatable value (double,
// Vec2, Vec3, Color, your own) keyed by arc length or by u, eased per interval by a Curve, and
// read at a u or an arc length of any path that gives length_at and u_at_length (Path, Path3,
// PathND). Header-only; link grape::curve for the Curve.
//
//   grape::PathData<double> width(grape::PathDataKey::arc_length, {{0.0, 1.0}, {12.0, 3.0}, {40.0, 0.5}});
//   double w = width.at_u(track, 0.3);   // arc length of track at u = 0.3, then the track
#pragma once

#include <grape/curve.hpp>
#include <grape/error.hpp>
#include <grape/value.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace grape {

/// \addtogroup along
/// @{

/// What the keys of a PathData are placed by.
enum class PathDataKey {
    arc_length,  ///< arc length from the start of the path, world units (≥ 0)
    u,           ///< the path's parameter u, in [0, 1]
};

/// One key of a PathData: a value at a place along the path.
template <class V>
struct PathDataPoint {
    double at = 0.0;  ///< arc length or u (PathDataKey), strictly increasing from key to key
    V value{};        ///< the value there
};

/// A value of type V along a path: keys at arc lengths or at u, strictly increasing, joined by
/// Interpolate<V>::lerp with each interval's progress eased by its Curve (linear without
/// curves). Before the first key and after the last the end values hold. An immutable value;
/// lookups throw and allocate only if V's copy or lerp does, and return a key's value itself
/// (no lerp) at its place, so keys come back exactly.
template <Interpolatable V>
class PathData {
public:
    /// Throws grape::Error naming the field: no keys; a place not finite, negative, above 1
    /// (keys by u) or not greater than the one before; a curve count other than keys − 1 or 0.
    PathData(PathDataKey key, std::vector<PathDataPoint<V>> points, std::vector<Curve> curves = {})
        : key_(key), points_(std::move(points)), curves_(std::move(curves)) {
        const std::string who = "PathData: ";
        if (points_.empty()) throw Error(who + "points: needs at least 1 point");
        for (std::size_t i = 0; i < points_.size(); ++i) {
            const double at = points_[i].at;
            const std::string name = who + "points[" + std::to_string(i) + "].at: ";
            if (!std::isfinite(at) || at < 0.0 || (key_ == PathDataKey::u && at > 1.0)) {
                throw Error(name + (key_ == PathDataKey::u ? "must lie in [0, 1]" : "must be finite and >= 0") +
                            " (got " + detail::number_text(at) + ")");
            }
            if (i > 0 && !(at > points_[i - 1].at)) {
                throw Error(name + "must be greater than the point before's (got " + detail::number_text(at) + " after " +
                            detail::number_text(points_[i - 1].at) + ")");
            }
        }
        if (!curves_.empty() && curves_.size() + 1 != points_.size()) {
            throw Error(who + "curves: needs one curve per interval, " + std::to_string(points_.size() - 1) + " (got " +
                        std::to_string(curves_.size()) + ")");
        }
    }

    PathDataKey key() const noexcept { return key_; }  ///< what the keys are placed by
    const std::vector<PathDataPoint<V>>& points() const noexcept { return points_; }  ///< the keys, in order

    /// The value at `at`, in the keys' own measure (arc length or u).
    V at_key(double at) const {
        if (!(at > points_.front().at)) return points_.front().value;  // NaN too
        if (at >= points_.back().at) return points_.back().value;
        const auto it = std::upper_bound(points_.begin(), points_.end(), at,
                                         [](double x, const PathDataPoint<V>& p) { return x < p.at; });
        const std::size_t i = static_cast<std::size_t>(it - points_.begin()) - 1;
        const PathDataPoint<V>& a = points_[i];
        const PathDataPoint<V>& b = points_[i + 1];
        const double t = (at - a.at) / (b.at - a.at);
        const double p = curves_.empty() ? t : curves_[i](t);
        if (p == 0.0) return a.value;
        if (p == 1.0) return b.value;
        return Interpolate<V>::lerp(a.value, b.value, p);
    }

    /// The value at u of `path`: keys by arc length read at path.length_at(u), keys by u at u.
    template <class P>
    V at_u(const P& path, double u) const {
        return key_ == PathDataKey::u ? at_key(u) : at_key(path.length_at(u));
    }

    /// The value at arc length s of `path`: keys by u read at path.u_at_length(s), keys by arc
    /// length at s.
    template <class P>
    V at_length(const P& path, double s) const {
        return key_ == PathDataKey::arc_length ? at_key(s) : at_key(path.u_at_length(s));
    }

private:
    PathDataKey key_;
    std::vector<PathDataPoint<V>> points_;
    std::vector<Curve> curves_;
};

/// @}

}  // namespace grape
