// grape — 3-D paths and 3-D animations in scene files (part of grape::scene; the fields:
// docs/scene-format.md, "3-D animations"): a scene's "paths3" hold the path objects that
// `grape path3` reads, its "animations3" play them as Engine::create_3d_animation does, with
// the frame's orientation, a roll keyed by arc length or automatic banking on top.
//
//   grape::Scene scene = grape::load_scene_file("scenes/camera_rail3d.json");
//   grape::SceneTiming timing(scene);
//   grape::SceneMotion3 camera(scene.animations3[0]);   // frame tables built once
//   grape::Vec3 eye = camera.position_at(timing.animation3_progress(0, 2.5));
//   grape::Quat look = camera.orientation_at(timing.animation3_progress(0, 2.5),
//                                            timing.animation3_backward(0, 2.5));
#pragma once

#include <grape/anim3.hpp>
#include <grape/anim_timing.hpp>
#include <grape/curve.hpp>
#include <grape/export_scene.hpp>
#include <grape/frames3.hpp>
#include <grape/path3.hpp>
#include <grape/quat.hpp>
#include <grape/quat_spline.hpp>
#include <grape/roll3.hpp>
#include <grape/vec3.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace grape {

/// \addtogroup scene
/// @{

/// A 3-D path with a name, listed in the scene's "paths3" and referred to by 3-D animations.
struct NamedPath3 {
    std::string name;  ///< unique among the 3-D paths, not empty
    Path3 path;        ///< the path
};

/// The frame a 3-D animation turns its target by (JSON "frame": {"mode": ...}).
enum class SceneFrameMode : std::uint8_t {
    rmf,     ///< "rmf": rotation-minimizing from `up` at the start (FrameMode::rotation_minimizing)
    frenet,  ///< "frenet": the Frenet frame (FrameMode::frenet; `up` unused)
    up,      ///< "up": the world's up without its part along the tangent (FrameMode::reference_up)
};

/// Automatic banking of a 3-D animation (JSON "bank"): bank_track of the path played with
/// these fields and the frame's `up` as the world's up.
struct SceneBank {
    double speed = 10.0;    ///< v, units per second: finite, ≥ 0
    double gravity = 9.81;  ///< g, units per second²: finite, > 0
    double max_angle = 0.7853981633974483;  ///< clamp on |bank|, radians in [0, π/2]
    double smoothing = 0.0;  ///< arc length of the averaging window, ≥ 0
    std::size_t samples = 513;  ///< keys of the track, in [2, 2^20]
};

/// An orientation key of a 3-D animation (JSON "orientation": [[s, [w, x, y, z]], ...]): the
/// target's orientation at arc length s of the path played.
struct SceneOrientationKey {
    double s = 0.0;  ///< arc length from the path's start: finite, ≥ 0, increasing along the keys
    Quat q{};        ///< as written (finite, not zero); evaluated normalized
};

/// A 3-D animation: a 3-D path, a curve and its timing, the orientation written and offsets
/// along the frame, as Engine::create_3d_animation plays them, plus an optional roll about the
/// tangent (keys in arc length, or automatic banking) on top of the frame.
struct GRAPE_SCENE_API SceneAnimation3 {
    std::string name{};        ///< label ("" allowed); timelines place it by name ("animation3")
    Path3 path{};              ///< where
    std::string path_name{};   ///< the NamedPath3 it uses; "" when the path is given inline
    Curve curve{};             ///< when (default linear)
    std::string curve_name{};  ///< the NamedCurve it uses; "" when given by its own name
    double duration = 1.0;     ///< seconds per play, > 0 (unused when speed > 0)
    /// Constant speed, units per second (> 0; 0: off): the path is played reparametrized by
    /// arc length and each play lasts path.length() / speed (JSON "speed" instead of "duration").
    double speed = 0.0;
    double delay = 0.0;        ///< seconds before the first play, ≥ 0
    int repeat = 0;            ///< plays after the first: 0 plays once, −1 forever
    bool yoyo = false;         ///< every other play runs backwards
    bool reversed = false;     ///< the first play runs from the path's end to its start
    double repeat_delay = 0.0; ///< seconds between plays, ≥ 0
    double range_start = 0.0;  ///< u where a play starts, in [0, 1]
    double range_end = 1.0;    ///< u where a play ends, in [0, 1]
    Align3 align = Align3::none;  ///< the orientation written: none, the frame's, or upright in the world
    SceneFrameMode frame = SceneFrameMode::rmf;  ///< the frame (for align frame and the offsets)
    Vec3 up{0.0, 0.0, 1.0};    ///< the frame's up: the normal at the start (rmf) or the world's up (up, world alignment)
    double cone = 1.0;         ///< frame mode up: FramesDef::cone, radians in [0.05, 1.5]
    Axis3 forward = Axis3::pos_z;  ///< the model's axis along the tangent (Motion3Def::forward)
    Axis3 model_up = Axis3::pos_y;  ///< the model's axis on the normal (Motion3Def::up)
    bool face_travel = true;   ///< on backward plays, turn by π about the normal (Motion3Def::face_travel)
    double normal_offset = 0.0;    ///< world units along the (rolled) frame's normal
    double binormal_offset = 0.0;  ///< world units along the (rolled) frame's binormal
    /// Roll about the tangent keyed by arc length of the path (s, radians), joined linearly;
    /// empty: none. Needs align frame.
    std::vector<RollKey> roll{};
    bool banked = false;       ///< automatic banking (`bank`) instead of roll keys; needs frame mode up
    SceneBank bank{};          ///< banking, when `banked`
    /// Orientation keys (JSON "align": "keys"): the orientation itself, keyed by arc length and
    /// joined by a C² QuatSpline (constant before the first key and after the last), in place
    /// of a frame's; `align` is then Align3::none, the axes, face_travel and the roll do not
    /// apply, and the offsets still follow the frame. Empty: the orientation follows `align`.
    std::vector<SceneOrientationKey> orientation{};

    /// True when the orientation comes from keys (`orientation` not empty).
    bool keyed() const noexcept { return !orientation.empty(); }

    /// Seconds per play: path.length() / speed in speed mode, else duration.
    double seconds() const noexcept;
    /// The AnimationDef the anim engine plays this with (curve and timing).
    AnimationDef def() const noexcept;
    /// The Motion3Def Engine::create_3d_animation takes for it (without the roll, which the
    /// engine does not apply).
    Motion3Def motion() const noexcept;
    /// Seconds until the last play ends (infinity when repeating forever).
    double end_time() const noexcept;
};

/// A SceneAnimation3 ready to evaluate: the path played (reparametrized in speed mode), the
/// frame table and the roll, built once. Evaluation is noexcept and allocation-free, and
/// without roll gives what Engine::create_3d_animation writes at the same progress, bit for bit.
class GRAPE_SCENE_API SceneMotion3 {
public:
    SceneMotion3() = default;
    /// Builds the tables. Throws grape::Error naming the field ("frame: up: ...", "bank: speed:
    /// ...", "roll: ...", "orientation: ...") for what Frames3, RollTrack or bank_track refuse, and "speed" for a
    /// path of length 0 in speed mode.
    explicit SceneMotion3(const SceneAnimation3& animation);

    /// The path's u at curve progress p: range_start + p·(range_end − range_start).
    double u_at(double p) const noexcept { return range_start_ + p * (range_end_ - range_start_); }
    /// Where it is at curve progress p (SceneTiming::animation3_progress): the point of the path
    /// played plus the offsets along the (rolled) frame.
    Vec3 position_at(double p) const noexcept;
    /// The (rolled) frame at curve progress p. Only an animation aligned to its frame, offset
    /// along it or rolled builds a frame table; any other gives Frame3{} at the point.
    Frame3 frame_at(double p) const noexcept;
    /// The orientation at curve progress p on a play running `backward`
    /// (SceneTiming::animation3_backward): the model's axes `forward` and `model_up` on the
    /// frame's tangent and normal (align frame) or upright (align world), turned by π about the
    /// normal when face_travel and the play runs against the path's direction; the orientation
    /// keys' spline at the arc length reached (keyed; `backward` unused); the identity for
    /// align none.
    Quat orientation_at(double p, bool backward) const noexcept;
    Align3 align() const noexcept { return align_; }  ///< the orientation written (none when keyed)
    /// True when an orientation is written: align frame or world, or orientation keys.
    bool writes_orientation() const noexcept { return align_ != Align3::none || keys_; }
    const Path3& path() const noexcept { return path_; }  ///< the path played

private:
    Path3 path_;
    double range_start_ = 0.0, range_end_ = 1.0;
    Align3 align_ = Align3::none;
    bool face_travel_ = true;
    Vec3 world_up_{0.0, 0.0, 1.0};
    double normal_offset_ = 0.0, binormal_offset_ = 0.0;
    std::array<std::int8_t, 3> pick_{1, 2, 3};  // model axis i takes ±(T, N, B)[|pick| − 1]
    std::shared_ptr<const Frames3> frames_;       // null when nothing needs a frame
    std::shared_ptr<const RolledFrames3> rolled_;  // null without roll or bank
    std::shared_ptr<const QuatSpline> keys_;       // null without orientation keys
};

/// @}

}  // namespace grape
