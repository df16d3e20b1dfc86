// grape — what a 3-D animation writes besides its position: how it turns the target (none, the
// path's moving frame, or upright in the world), which of the model's axes face forward and up,
// and offsets from the path along the frame. Engine::create_3d_animation (anim.hpp) takes it.
//
//   struct Drone { double x, y, z; grape::Quat orientation; } drone;  // or a Basis, a Frame3
//   engine.create_3d_animation(drone, track, 4.0, {.repeat = -1},
//                              {.align = grape::Align3::frame, .forward = grape::Axis3::neg_z});
#pragma once

#include <grape/frames3.hpp>
#include <grape/path3.hpp>
#include <grape/quat.hpp>
#include <grape/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>

namespace grape {

/// \addtogroup anim
/// @{

/// How a 3-D animation turns its target's `orientation` member.
enum class Align3 : std::uint8_t {
    none,   ///< writes no orientation
    frame,  ///< the path's moving frame (Motion3Def::frames: rotation-minimizing, Frenet, reference-up, ...)
    /// Upright in the world: forward is the tangent without its part along Motion3Def::world_up,
    /// up is world_up (yaw only, no pitch or roll: a character on a ramp). Where the tangent is
    /// within 1e-9 rad of ±world_up that has no direction and forward is
    /// any_perpendicular(world_up).
    world,
};

/// A signed axis of the model's own coordinates.
enum class Axis3 : std::uint8_t {
    pos_x,  ///< +x
    neg_x,  ///< −x
    pos_y,  ///< +y
    neg_y,  ///< −y
    pos_z,  ///< +z
    neg_z,  ///< −z
};

/// The unit vector of a signed axis.
constexpr Vec3 axis_vector(Axis3 a) noexcept {
    switch (a) {
        case Axis3::pos_x: return {1, 0, 0};
        case Axis3::neg_x: return {-1, 0, 0};
        case Axis3::pos_y: return {0, 1, 0};
        case Axis3::neg_y: return {0, -1, 0};
        case Axis3::pos_z: return {0, 0, 1};
        case Axis3::neg_z: return {0, 0, -1};
    }
    return {};
}

/// Constant speed for a 3-D animation, in world units per second of animation time: the path
/// is reparametrized by arc length once, at creation, and each play lasts length / speed.
struct Speed {
    double units_per_second = 1.0;  ///< > 0 and finite
};

/// How a 3-D animation places and turns its target beyond its timing (AnimationDef); fill with
/// designated initializers. Every field is checked at creation (grape::Error names it).
struct Motion3Def {
    /// What the target's `orientation` member (a grape::Frame3, grape::Basis or grape::Quat)
    /// receives; any alignment but none needs one.
    Align3 align = Align3::none;
    /// The frame for Align3::frame and for the offsets, built once at creation (on the path
    /// played: the reparametrized one in speed mode).
    FramesDef frames{};
    /// A frame table built once and shared by many animations of the same path (the one
    /// played): used instead of building one from `frames`. It must frame that path (the same
    /// Path3 value, or a copy of it).
    std::shared_ptr<const Frames3> shared_frames{};
    Vec3 world_up{0.0, 0.0, 1.0};  ///< Align3::world: the world's up; finite, not zero
    /// The model's axis that faces along the path (the frame's tangent): +z for models that
    /// face +z, neg_z for the OpenGL camera convention. Basis and Quat members only (a Frame3
    /// member gets the frame itself).
    Axis3 forward = Axis3::pos_z;
    /// The model's axis that takes the frame's normal (Align3::world: world_up); it must be
    /// perpendicular to `forward`. The third axis follows (right-handed).
    Axis3 up = Axis3::pos_y;
    /// On plays that run backwards (reversed, yoyo, a range that runs back, reverse()) turn
    /// the orientation by π about the normal, so the model faces where it goes, as the 2-D
    /// heading does; false: it faces the path's own direction and backs up.
    bool face_travel = true;
    /// World units along the frame's normal: the position is point + normal_offset·N +
    /// binormal_offset·B (a car in its lane, a camera above the rail); finite.
    double normal_offset = 0.0;
    double binormal_offset = 0.0;  ///< world units along the frame's binormal; finite
};

namespace detail {
/// What an orientation member is.
enum class Orient3Member : std::uint8_t { none, frame, basis, quat };
/// Where a 3-D animation writes: byte offsets of x, y, z and of the orientation member.
struct Layout3 {
    std::size_t x = 0, y = 0, z = 0;
    bool is_float = false;
    std::size_t orientation = 0;
    Orient3Member member = Orient3Member::none;
};
template <class M>
constexpr Orient3Member orient3_member_of() noexcept {
    if constexpr (std::is_same_v<M, Frame3>) return Orient3Member::frame;
    else if constexpr (std::is_same_v<M, Basis>) return Orient3Member::basis;
    else if constexpr (std::is_same_v<M, Quat>) return Orient3Member::quat;
    else return Orient3Member::none;
}
}  // namespace detail

/// @}

}  // namespace grape
