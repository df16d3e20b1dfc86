// grape — roll along a 3-D path: a track of roll angles keyed by arc length, applied about
// the tangent on top of a Frames3 frame, and automatic banking from speed and curvature.
//
// Compiled into grape::anim (which links both grape::path and grape::curve): the per-interval
// easing is a grape::Curve, and grape::curve already depends on grape::path.
#pragma once

#include <grape/curve.hpp>
#include <grape/export_anim.hpp>
#include <grape/frames3.hpp>
#include <grape/path3.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace grape {

/// \addtogroup roll3
/// @{

/// One key of a RollTrack.
struct RollKey {
    double s = 0.0;     ///< arc length from the start of the path, world units
    double roll = 0.0;  ///< roll about the tangent there, radians (right-handed: normal toward binormal)
};

/// How a RollTrack fills the intervals between its keys.
enum class RollInterpolation {
    /// Each interval eases from its first key to the next by its own Curve (linear by default).
    curves,
    /// A C² cubic spline in s through all keys with zero second derivative at both ends.
    natural_spline,
    /// A C² cubic spline in s through all keys with the end slopes given (RollTrackDef).
    clamped_spline,
};

/// How a RollTrack is built (designated initializers).
struct RollTrackDef {
    RollInterpolation interpolation = RollInterpolation::curves;  ///< what fills the intervals
    /// Mode curves: one Curve per interval (keys − 1 of them), or empty for linear throughout.
    std::vector<Curve> curves{};
    double start_slope = 0.0;  ///< mode clamped_spline: droll/ds at the first key, radians per unit
    double end_slope = 0.0;    ///< mode clamped_spline: droll/ds at the last key, radians per unit
};

/// Roll angles keyed by arc length: an immutable value. roll_at(s) is noexcept, allocation-free
/// and a binary search plus one curve or cubic; it gives every key's roll exactly at its s, and
/// holds the first (last) key's roll before (after) the keys.
class GRAPE_ANIM_API RollTrack {
public:
    /// A track of roll 0 everywhere.
    RollTrack();
    /// Throws grape::Error naming the field: fewer than 1 key; a key's s or roll not finite,
    /// s negative or not strictly increasing; a curve count other than keys − 1 (or 0);
    /// slopes not finite. (One key: that roll everywhere.)
    explicit RollTrack(std::span<const RollKey> keys, const RollTrackDef& def = {});

    /// The roll at arc length s, radians.
    double roll_at(double s) const noexcept;
    std::span<const RollKey> keys() const noexcept { return keys_; }  ///< the keys, by s
    RollInterpolation interpolation() const noexcept { return interpolation_; }  ///< what fills the intervals

private:
    std::vector<RollKey> keys_;
    RollInterpolation interpolation_ = RollInterpolation::curves;
    std::vector<Curve> curves_;
    std::vector<double> second_;  // splines: d²roll/ds² at each key
};

/// Frames along a path rolled about the tangent by a RollTrack in arc length: the base frame
/// (any Frames3 mode; rotation-minimizing by default) turned by roll_at(s(u)), normal toward
/// binormal for a positive roll. The arc length s(u) is read from the Frames3's panel table
/// (Frames3::length_at, ~0.2 µs), not Path3::length_at (~1.5–2.4 µs).
class GRAPE_ANIM_API RolledFrames3 {
public:
    /// The frames `frames` rolled by `roll`.
    RolledFrames3(Frames3 frames, RollTrack roll);
    /// Rotation-minimizing frames of `path` from `up` at u = 0, rolled by `roll`.
    RolledFrames3(Path3 path, RollTrack roll, Vec3 up = {0.0, 0.0, 1.0});

    /// The rolled frame at u (clamped to [0, 1]).
    Frame3 frame(double u) const noexcept;
    /// The rolled frame at arc length s (u from Path3::u_at_length: several µs; prefer frame(u)).
    Frame3 frame_at_length(double s) const noexcept;
    /// The roll added at u, radians.
    double roll(double u) const noexcept;
    const Frames3& base() const noexcept { return frames_; }  ///< the frames before the roll
    const RollTrack& track() const noexcept { return roll_; }  ///< the roll track

private:
    Frames3 frames_;
    RollTrack roll_;
};

/// How automatic banking is worked out (designated initializers).
struct BankDef {
    double speed = 10.0;    ///< v, units per second: finite, ≥ 0
    double gravity = 9.81;  ///< g, units per second²: finite, > 0
    double max_angle = 0.7853981633974483;  ///< the clamp on |bank|, radians in [0, π/2] (default π/4)
    Vec3 up{0.0, 0.0, 1.0};  ///< world up: finite, not zero
    /// Arc length of the box window the bank is averaged over (0: none). The average of a
    /// bounded function over a window of fixed width is continuous, so the roll no longer
    /// jumps where the curvature does (a line joining an arc); it changes over `smoothing`.
    double smoothing = 0.0;
    /// bank_track: samples evenly spaced in arc length (≥ 2, ≤ 2^20), joined linearly.
    std::size_t samples = 513;
};

/// The bank at u, radians: atan(v²κ/g) clamped to max_angle, positive when the roll (right-
/// handed about the tangent, normal toward binormal) of a frame whose normal is world up tilts
/// it toward the horizontal part of the direction to the centre of curvature, so a vehicle
/// leans into the curve. 0 where κ = 0, where the path is vertical, or where the centre lies
/// straight above or below. Throws grape::Error naming the field of def that is out of range
/// (speed, gravity, max_angle, up).
GRAPE_ANIM_API double bank_angle(const Path3& path, double u, const BankDef& def);

/// A RollTrack of the bank: `samples` keys evenly spaced in arc length, each bank_angle there
/// (averaged over the window when `smoothing` > 0, the window shrinking to the path at its
/// ends), joined linearly. Use it on frames with mode reference_up and the same up (roll 0:
/// upright). Throws grape::Error naming the field of def that is out of range.
GRAPE_ANIM_API RollTrack bank_track(const Path3& path, const BankDef& def = {});

/// @}

}  // namespace grape
