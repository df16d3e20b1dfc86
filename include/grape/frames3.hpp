// grape — moving frames along a 3-D path beyond plain rotation-minimizing ones: ends given,
// closed loops that close up, a world-up (camera) mode, and Frenet frames, behind one type.
#pragma once

#include <grape/export_path.hpp>
#include <grape/path3.hpp>
#include <grape/quat.hpp>
#include <grape/vec3.hpp>

#include <cstddef>
#include <vector>

namespace grape {

/// Which frame a Frames3 table follows.
enum class FrameMode {
    /// Rotation-minimizing (parallel transport) from `up` at u = 0; the end is wherever
    /// the path's holonomy takes it.
    rotation_minimizing,
    /// Rotation-minimizing from `up` at u = 0, then twisted so that the normal at u = 1 is
    /// `end_up` made perpendicular to the tangent there.
    ends,
    /// Rotation-minimizing from `up` at u = 0, then twisted so that the frame at u = 1 equals
    /// the frame at u = 0: for a closed path (point(1) = point(0)), so a rail or a tube
    /// meets itself without a seam in its roll.
    closed,
    /// The normal is `up` (world up) without its part along the tangent, except inside a cone
    /// about the direction of ±up, where that is undefined and the frame blends into the
    /// rotation-minimizing one (see Frames3): what a camera on a track wants.
    reference_up,
    /// The Frenet frame (normal toward the centre of curvature). Where the curvature vanishes
    /// the normal is undefined and Path3::frenet's fallback is used: it may jump there.
    frenet,
};

/// How a Frames3 table is built (designated initializers; defaults give an RMF from +z).
struct FramesDef {
    FrameMode mode = FrameMode::rotation_minimizing;  ///< which frame
    /// The normal at u = 0 (modes rotation_minimizing, ends, closed), or the world up
    /// (reference_up), without its part along the tangent. Finite, not zero.
    Vec3 up{0.0, 0.0, 1.0};
    Vec3 end_up{0.0, 0.0, 1.0};  ///< mode ends: the normal at u = 1, made ⟂ the tangent there
    /// Modes ends and closed: full turns of twist added to the least one (either sign).
    int extra_turns = 0;
    /// Mode reference_up: half-angle in radians, in [0.05, 1.5], of the cone about ±up inside
    /// which the frame leaves the world up. A circular vertical loop spends 2·cone·R of arc
    /// inside it and rolls by π there (the roll a camera must make to stay upright on both
    /// sides), at up to 1.5 times the mean rate: 1 rad keeps a loop's roll within 0.85° per
    /// 1/1000 of its length.
    double cone = 1.0;
    double tolerance = 1e-9;  ///< radians: the rotation-minimizing table's (see RotationMinimizingFrames)
};

/// Frames along one path, built once as a table (a RotationMinimizingFrames plus the twist or
/// the blends), evaluated by frame(u), noexcept and allocation-free, orthonormal within a few
/// ulp.
///
/// Modes ends and closed twist the rotation-minimizing frame by a roll φ(s) that grows
/// linearly in arc length s from 0 to the mismatch Φ at the end. Of all frames with those two
/// end normals this one has the least ∫|ω|² ds: the angular velocity is ω = ω_rmf + φ′·T with
/// ω_rmf ⟂ T, so ∫|ω|² = ∫|ω_rmf|² + ∫φ′², and with φ(0) = 0, φ(L) = Φ fixed, ∫φ′² is least
/// for φ′ constant. Φ is the mismatch in (−π, π] plus 2π·extra_turns. The RMF is continuous
/// across the joins of complex paths (it turns by the least rotation at a corner) and φ is
/// continuous in s, so the twisted frame is too.
///
/// Mode reference_up: let α be the angle between the tangent and the line of up. Where
/// α ≥ cone the normal is normalize(up − (up·T)T) exactly. Each stretch where α < cone is
/// found by sampling α at the RMF's knots and their midpoints (at least 64 per piece) and
/// bisecting its ends; across it the roll relative to the RMF is the cubic in arc length
/// (Hermite) that meets the world-up roll and its rate at both ends, turning by the least
/// angle, so the frame is C¹ there and a loop-the-loop or a corkscrew never flips. A
/// stretch that reaches an end of the path (a path that starts, ends or stays vertical)
/// holds the roll of its other end, that is, follows the RMF; a path inside the cone
/// throughout is the RMF from any_perpendicular of its first tangent. A dip into the cone
/// shorter than the sampling misses it, and the frame then turns quickly there.
class GRAPE_PATH_API Frames3 {
public:
    /// Throws grape::Error naming the field: up or end_up not finite, or parallel to the
    /// tangent where it is used; cone or tolerance out of range; mode closed on a path whose
    /// ends are more than 1e-9·length apart; and whatever RotationMinimizingFrames refuses.
    Frames3(Path3 path, const FramesDef& def = {});

    /// The frame at u (clamped to [0, 1]).
    Frame3 frame(double u) const noexcept;
    const Path3& path() const noexcept;      ///< the path framed
    FrameMode mode() const noexcept;         ///< the mode built
    /// Modes ends and closed: the total twist Φ added to the RMF from u = 0 to u = 1, radians
    /// (positive: right-handed about the tangent); 0 otherwise.
    double twist() const noexcept;
    /// Mode reference_up: how many stretches inside the cone were found.
    std::size_t cone_count() const noexcept;

private:
    struct Blend {
        double u0, u1;    // the stretch inside the cone
        double s0, s1;    // its arc lengths
        double psi0, psi1;  // roll relative to the RMF at the ends (psi1 unwrapped near psi0)
        double rate0, rate1;  // their rates per unit length
    };
    Path3 path_;
    FrameMode mode_;
    Vec3 up_;
    RotationMinimizingFrames rmf_;
    double twist_ = 0.0;
    double length_ = 0.0;
    std::vector<Blend> blends_;
    // Modes ends, closed and reference_up read the arc length at u: panels of u on which a
    // 5-point Gauss rule is resolved to rounding, with the length from u = 0 to each start.
    std::vector<double> arc_u_, arc_s_;

    double arc_length_at(double u) const noexcept;
    static RotationMinimizingFrames make_rmf(const Path3& path, const FramesDef& def);
    double reference_roll(double u) const noexcept;
};

/// The orientation of a frame: the rotation taking (1, 0, 0) to its tangent, (0, 1, 0) to its
/// normal and (0, 0, 1) to its binormal (from_basis_unchecked: frames of a Frames3 or a
/// RotationMinimizingFrames are orthonormal within a few ulp), w ≥ 0. An object modelled
/// facing +x with +y up then moves along the path facing forward with its up on the normal.
inline Quat from_frame(const Frame3& f) noexcept { return from_basis_unchecked(f.tangent, f.normal, f.binormal); }

}  // namespace grape
