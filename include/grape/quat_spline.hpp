// grape — QuatSpline: a C² orientation curve through keyed unit quaternions, for a camera or a
// ship turning smoothly through given poses (keyed by time, or by distance along a path).
//
//   grape::QuatSpline turn({0.0, 1.0, 2.5}, {q0, q1, q2});
//   ship.orientation = turn.orientation(t);      // exactly q1 at t = 1
//   grape::Vec3 w = turn.angular_velocity(t);    // rad per unit of t, world axes
#pragma once

#include <grape/export_math.hpp>
#include <grape/quat.hpp>
#include <grape/vec3.hpp>

#include <cstddef>
#include <vector>

namespace grape {

/// \addtogroup quat
/// @{

/// A C² unit-quaternion curve through keys q_0 … q_{n−1} at strictly increasing parameters
/// t_0 < … < t_{n−1} (time, arc length: the caller decides), in the cumulative form of Kim,
/// Kim and Shin (SIGGRAPH 1995). On [t_i, t_{i+1}], with u = (t − t_i)/h_i, h_i = t_{i+1} − t_i,
///   q(t) = q_i · exp(a_i·β₁(u)) · exp(b_i·β₂(u)) · exp(c_i·β₃(u)),
/// β₁ = 1 − (1 − u)³, β₂ = 3u² − 2u³, β₃ = u³ (the cumulative cubic Bernstein basis), a, b, c
/// half-angle vectors. At u = 0 every factor is the identity, so the curve is q_i exactly at
/// t_i; b_i = log(exp(−a_i)·q_i⁻¹q_{i+1}·exp(−c_i)) makes it q_{i+1} at the segment's end.
/// With a_i = h_i·v_i/6 and c_i = h_i·v_{i+1}/6 the angular velocity at key i is v_i (body
/// axes) from both sides: C¹. The v_i are solved so that the angular acceleration matches at
/// every inner key too (C²) and vanishes at both ends (natural ends): a nonlinear system whose
/// linear part is the tridiagonal system of a natural cubic spline's slopes. It is solved by
/// that linear solve, then Newton's method on the block-tridiagonal Jacobian (3×3 blocks by
/// forward differences, nine residuals a step; steps halved while they do not lower the
/// residual), to rounding: 4 to 6 steps, O(n) each, for keys up to 3 rad apart at steps within
/// a factor 3 of each other. Very uneven steps next to large turns (a 3 rad turn in a step a
/// hundredth of its neighbour's) ask for a curve that loops, and the solve may refuse them.
/// Keys about one fixed axis give exactly a natural cubic spline of the angle.
///
/// Keys are normalized and each is replaced by its negative where that is nearer the previous
/// one, so q and −q are the same key and the curve turns the short way (under half a turn)
/// between neighbours: keys more than half a turn apart need keys between them. Outside
/// [t_0, t_{n−1}] the orientation is clamped to the end key (angular velocity zero there).
/// Evaluation is noexcept and allocation-free: a binary search for the segment, three
/// exponentials.
class GRAPE_MATH_API QuatSpline {
public:
    /// Throws grape::Error naming the argument: fewer than one key; `params` and `keys` of
    /// different sizes; a parameter not finite or not greater than the one before; a key not
    /// finite or zero; a solve that does not converge within max_iterations (keys so far apart,
    /// and so unevenly spaced, that the curve would loop: add keys between them, or space them
    /// more evenly).
    QuatSpline(std::vector<double> params, std::vector<Quat> keys);

    /// The most iterations of the C² solve, bounding the work of a construction (O(n) each).
    static constexpr int max_iterations = 100;

    /// The orientation at t (unit within a few ulp; clamped outside the keys' range).
    Quat orientation(double t) const noexcept;
    /// The angular velocity at t in world axes, radians per unit of t: the ω with
    /// dq/dt = ½·ω·q. Zero outside [t_0, t_{n−1}]; at t_{n−1} the value arriving there.
    Vec3 angular_velocity(double t) const noexcept;

    std::size_t size() const noexcept { return params_.size(); }                ///< number of keys
    double parameter(std::size_t i) const noexcept { return params_[i]; }       ///< t_i (i < size())
    /// Key i as the curve holds it: normalized and turned to the side of key i − 1.
    const Quat& key(std::size_t i) const noexcept { return keys_[i]; }
    /// The angular velocity at key i in world axes (the solved v_i, rotated by the key).
    Vec3 key_angular_velocity(std::size_t i) const noexcept;
    /// Iterations the C² solve took (at most max_iterations).
    int iterations() const noexcept { return iterations_; }

private:
    struct Segment {
        Vec3 a, b, c;  // half-angle vectors of the three factors
        double inv_h;  // 1 / (t_{i+1} − t_i)
    };
    std::vector<double> params_;
    std::vector<Quat> keys_;
    std::vector<Vec3> velocity_;  // v_i, body axes of key i
    std::vector<Segment> segments_;
    int iterations_ = 0;

    std::size_t segment_of(double t) const noexcept;
};

/// @}

}  // namespace grape
