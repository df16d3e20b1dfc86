// grape — a 2-D profile swept along a 3-D path with chosen frames: a triangle mesh (tubes,
// rails, ribbons), and its Wavefront OBJ text.
#pragma once

#include <grape/export_path.hpp>
#include <grape/frames3.hpp>
#include <grape/math.hpp>
#include <grape/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace grape {

/// A triangle mesh: one position, normal and uv per vertex, triangles counter-clockwise seen
/// from the side their normals point to.
struct Mesh3 {
    std::vector<Vec3> positions;  ///< world units
    std::vector<Vec3> normals;    ///< unit, one per position
    /// One per position: (share of the profile's length from its first vertex, arc length s
    /// along the path). A closed profile's seam vertex has u = 0 on both sides.
    std::vector<Vec2> uv;
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< indices into positions
    /// Sweeps: the u of each distinct ring (a closed seam's last ring is the first, not repeated).
    std::vector<double> ring_u;
    std::size_t ring_size = 0;  ///< sweeps: vertices per ring (ring i is positions[i·ring_size …])
};

/// How a profile is swept (designated initializers).
struct SweepDef {
    /// The profile, ≥ 2 points, in the frame's plane: x along its normal, y along its binormal.
    /// Counter-clockwise (positive area) puts the normals outward, clockwise inward.
    std::vector<Vec2> profile;
    bool closed_profile = true;  ///< join the last profile point to the first (shared vertices)
    /// World units, > 0: how far the faces between consecutive rings may stray from the true
    /// swept surface. Each profile vertex's chord is checked against its true path at a
    /// quarter, half and three quarters of the step, and each face's twist (how far its two
    /// triangles part from the patch through its four corners) is added to the worse of its
    /// two columns.
    double tolerance = 1e-3;
    /// Closed profile on an open path: close both ends with fans about the profile's origin
    /// (right for profiles star-shaped about it), with their own vertices and normals ∓T.
    bool caps = false;
    std::size_t max_rings = std::size_t{1} << 16;  ///< more are refused with grape::Error
};

/// A regular polygon of `sides` ≥ 3 vertices on a circle of `radius` > 0 about the origin,
/// counter-clockwise from (radius, 0): a tube's profile. Throws grape::Error otherwise.
GRAPE_PATH_API std::vector<Vec2> circle_profile(double radius, int sides);

/// The profile swept along frames.path(): a ring of profile vertices at each of a set of u
/// that includes every break, bisected until the tolerance holds (more rings where the path
/// bends or the frame twists, few on straight stretches). Where the path's ends coincide
/// and the frames there agree (within 1e-9), as mode closed makes them, the last ring is the
/// first. Normals are the profile's 2-D vertex normals (mean of its edges') carried by the
/// frame: exact for a circular tube. Throws grape::Error naming the field for a bad profile
/// (fewer than 2 points, or 3 for a closed one; not finite), tolerance, or when more than
/// max_rings rings are needed.
GRAPE_PATH_API Mesh3 sweep(const Frames3& frames, const SweepDef& def);

/// The mesh as Wavefront OBJ text (v, vn, vt, and f a/a/a with 1-based indices), numbers with
/// 17 significant digits in every locale, so any viewer reads back the same doubles.
GRAPE_PATH_API std::string to_obj(const Mesh3& mesh);

}  // namespace grape
