// grape — scene: JSON files describing paths, curves, animations, simulations, timelines,
// sprites, and typed properties with their tweens (format: docs/scene-format.md, schema:
// docs/scene.schema.json; properties evaluate through grape/scene_values.hpp).
//
// Loading validates everything and throws grape::Error naming the JSON pointer of the bad
// value and the reason ("scene: /animations/3/path/cues/2: cues must not decrease (0.4 after
// 0.5)"). Saving writes every number with 17 significant digits, so save → load gives the
// same objects.
//
//   grape::Scene scene = grape::load_scene_file("scenes/seed_complex.json");
//   grape::Vec2 where = scene.animations[0].position(1.5);   // 1.5 s into the scene
//   grape::SceneTiming timing(scene);                         // with its timelines
//   double u = timing.progress(0, 1.5);                        // as its timeline plays it
//   grape::save_scene_file(scene, "copy.json");
#pragma once

#include <grape/config.hpp>
#include <grape/anim.hpp>
#include <grape/color.hpp>
#include <grape/curve.hpp>
#include <grape/export_scene.hpp>
#include <grape/math.hpp>
#include <grape/path.hpp>
#include <grape/scene_animation3.hpp>
#include <grape/timeline_layout.hpp>
#include <grape/sprite.hpp>

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace grape {

/// \addtogroup scene
/// @{

/// A curve with a name, listed in the scene's "curves" and referred to by animations.
struct NamedCurve {
    std::string name;  ///< unique within the scene, not empty
    Curve curve;       ///< the easing
};

/// An animation: a path, a curve and its timing, as the anim module plays it.
struct GRAPE_SCENE_API SceneAnimation {
    std::string name;        ///< label ("" allowed)
    Path path;               ///< where
    std::string path_name;   ///< the NamedPath it uses; "" when the path is given inline
    Curve curve;             ///< when (default linear)
    std::string curve_name;  ///< the NamedCurve it uses; "" when given by its own name
    double duration = 1.0;   ///< seconds per play, > 0
    double delay = 0.0;      ///< seconds before the first play, ≥ 0
    int repeat = 0;          ///< plays after the first: 0 plays once, −1 forever
    bool yoyo = false;       ///< every other play runs backwards
    bool reversed = false;   ///< the first play runs from the path's end to its start
    double repeat_delay = 0.0;  ///< seconds between plays, ≥ 0 (the state holds at the end of the play just finished)
    double range_start = 0.0;  ///< u where a play starts, in [0, 1] ("range": [start, end])
    double range_end = 1.0;    ///< u where a play ends, in [0, 1] (below range_start: runs backwards)
    double offset = 0.0;       ///< sideways distance from the path, world units, to the frame's normal side

    /// The AnimationDef the anim engine plays this with (curve and timing).
    AnimationDef def() const noexcept;
    /// Progress u along the path at scene time t seconds: progress_at(def(), duration, t),
    /// the anim module's timing model (curve(τ) going forwards, curve(1 − τ) going
    /// backwards; before the delay at its start, after its last play at its end).
    double progress(double t) const noexcept;
    /// The path's u at scene time t: range_start + progress(t)·(range_end − range_start).
    double u(double t) const noexcept;
    /// Where it is at scene time t: path.point(u(t)), moved `offset` along the path's normal
    /// there (offset_point).
    Vec2 position(double t) const noexcept;
    /// Where it is at curve progress p (a timeline's SceneTiming::progress, say): the range
    /// maps p to u, then the offset applies as in position().
    Vec2 position_at(double p) const noexcept;
    /// Seconds until the last play ends (infinity when repeating forever).
    double end_time() const noexcept;
};

/// What a scene property holds.
enum class ScenePropertyType {
    number,  ///< a double
    angle,   ///< a double in radians (or degrees, SceneProperty::degrees), turning as `shortest` says
    vec2,    ///< a Vec2
    color,   ///< a Color (sRGB-encoded components), mixed in `space`
    vec3,    ///< a Vec3, mixed by lerp
    quat,    ///< a Quat (an orientation [w, x, y, z], not zero; evaluated normalized), mixed by slerp on the shortest arc
};

/// A property's value: a double (number, angle), a Vec2, a Color, a Vec3 or a Quat, as its type says.
using SceneValue = std::variant<double, Vec2, Color, Vec3, Quat>;

/// A typed value of the scene that tweens drive (a tint, an angle, a scale), like a member
/// the engine's `animate` drives.
struct SceneProperty {
    std::string name;                                  ///< unique among the properties, not empty
    ScenePropertyType type = ScenePropertyType::number;  ///< what it holds
    SceneValue value = 0.0;                            ///< its value before any tween has begun
    ColorSpace space = ColorSpace::linear_srgb;        ///< colours: where they are mixed
    bool shortest = true;                              ///< angles: the turn of at most half a turn (AngleLerp)
    bool degrees = false;                              ///< angles: values in degrees (360 a turn), else radians
};

/// A tween of a property: from → to, from its value when the first play begins to `to`, or
/// by an amount from that value (ValueMode), with a curve and the timing of an animation.
struct GRAPE_SCENE_API SceneTween {
    std::string name;          ///< label ("" allowed); timelines place it by name
    std::string property;      ///< the SceneProperty it drives
    ValueMode mode = ValueMode::from_current;  ///< from_to ("from" given), from_current ("to" alone), relative ("by")
    SceneValue from = 0.0;     ///< from_to: the start (unused otherwise)
    SceneValue to = 0.0;       ///< the end, or the amount for ValueMode::relative
    Curve curve;               ///< default linear
    std::string curve_name;    ///< the NamedCurve it uses; "" when given by its own name
    double duration = 1.0;     ///< seconds per play, > 0
    double delay = 0.0;        ///< seconds (its own time) before the first play, ≥ 0
    int repeat = 0;            ///< plays after the first: 0 plays once, −1 forever
    double repeat_delay = 0.0; ///< seconds between plays, ≥ 0
    bool yoyo = false;         ///< every other play runs backwards
    bool reversed = false;     ///< the first play runs from `to` to the start
    double time_scale = 1.0;   ///< its seconds per second of the scene (or its timeline), > 0

    /// The AnimationDef the anim engine plays this with (curve and timing).
    AnimationDef def() const noexcept;
    /// Seconds (of the scene or its timeline) until the last play ends (+inf when repeating forever).
    double end_time() const noexcept;
};

/// What a child of a timeline is.
enum class SceneTimelineChildKind {
    animation,   ///< one of the scene's animations (JSON "animation")
    timeline,    ///< a nested timeline
    label,       ///< a named time
    gap,         ///< seconds of nothing
    tween,       ///< a property's tween
    animation3,  ///< one of the scene's 3-D animations (JSON "animation3")
};

/// One child of a SceneTimeline, in the order placed.
struct SceneTimelineChild {
    SceneTimelineChildKind kind = SceneTimelineChildKind::animation;  ///< what the child is
    std::string name{};   ///< the animation's, 3-D animation's, tween's, nested timeline's or label's name (unused for gaps)
    double gap = 0.0;     ///< gap: seconds it occupies, ≥ 0
    TimelinePosition at{};  ///< where it goes; the default: after everything placed so far
};

/// A timeline: animations, nested timelines, labels and gaps placed in time, played like an
/// animation. An animation placed in a timeline is driven by it and does not play on its
/// own: before its start in the timeline it rests at its start, after its end at its end.
struct GRAPE_SCENE_API SceneTimeline {
    std::string name;            ///< unique among the timelines, not empty
    double delay = 0.0;          ///< seconds (of its parent) before the first play, ≥ 0
    int repeat = 0;              ///< plays after the first: 0 plays once, −1 forever (top level only)
    double repeat_delay = 0.0;   ///< seconds between plays, ≥ 0
    bool yoyo = false;           ///< every other play runs backwards
    double time_scale = 1.0;     ///< timeline seconds per parent second, > 0
    std::vector<SceneTimelineChild> children;  ///< in placement order

    /// The timing as an AnimationDef (curve linear): what timeline_local_time plays.
    AnimationDef def() const noexcept;
};

/// A particle of a simulation.
struct SceneParticle {
    Vec2 position;        ///< world units
    Vec2 velocity;        ///< world units per second
    double mass = 1.0;    ///< > 0; infinity pins the particle ("mass": "pinned" in JSON)
};

/// What kind of force a SceneForce is.
enum class SceneForceKind { gravity, drag, spring };

/// A force generator of a simulation; the fields used depend on the kind.
struct SceneForce {
    SceneForceKind kind = SceneForceKind::gravity;  ///< which force; says which fields are used
    Vec2 gravity;              ///< gravity: acceleration, world units/s²
    double drag = 0.0;         ///< drag: k ≥ 0 in F = −k·v
    /// spring: the two particles' indices, a ≠ b.
    std::size_t a = 0, b = 0;  ///< spring: particle indices, a ≠ b
    double rest_length = 0.0;  ///< spring: L ≥ 0
    double stiffness = 0.0;    ///< spring: k ≥ 0
    double damping = 0.0;      ///< spring: c ≥ 0
};

/// What kind of constraint a SceneConstraint is.
enum class SceneConstraintKind {
    distance,     ///< |x_a − x_b| = length (length 0 in JSON: the starting distance)
    anchor,       ///< |x_a − point| = length
    fixed_point,  ///< x_a = point
    conic,        ///< A·x² + B·x·y + C·y² + D·x + E·y + F = 0 (the seed's parabola: 1,0,0,0,100,0)
};

/// A constraint of a simulation; the fields used depend on the kind.
struct SceneConstraint {
    SceneConstraintKind kind = SceneConstraintKind::distance;  ///< which constraint; says which fields are used
    /// The particles' indices (b: distance only).
    std::size_t a = 0, b = 0;    ///< particle indices (b: distance only)
    double length = 0.0;         ///< distance, anchor: world units (> 0 for anchor)
    Vec2 point;                  ///< anchor, fixed_point
    double conic[6] = {};        ///< conic: A, B, C, D, E, F
};

/// A particle simulation (the dynamics module runs it).
struct SceneSimulation {
    std::string name;                          ///< label ("" allowed)
    std::string integrator = "rk4";            ///< euler, semi_implicit_euler, midpoint, rk4, velocity_verlet, rk45
    std::string drift = "baumgarte";           ///< none, baumgarte, projection
    double dt = 1.0 / 60.0;                    ///< step, seconds, > 0
    double duration = 10.0;                    ///< seconds to run, > 0
    std::vector<SceneParticle> particles;      ///< at least one
    std::vector<SceneForce> forces;            ///< applied in order
    std::vector<SceneConstraint> constraints;  ///< solved together
};

/// A sprite: frames of a sprite sheet (Aseprite or TexturePacker JSON and its picture) played
/// at a rate from scene time 0, standing at a point or moving along an animation.
struct GRAPE_SCENE_API SceneSprite {
    std::string name;               ///< label ("" allowed)
    std::string sheet_file;         ///< the sheet's JSON as written, relative to the scene file's folder
    std::string clip;               ///< the clip (tag) played; "" when frames are given
    std::size_t first_frame = 0;    ///< with no clip: the frames first … last play forward in a loop
    std::size_t last_frame = 0;     ///< inclusive, ≥ first_frame
    double rate = 1.0;              ///< 1 normal, 0.5 half, −1 backwards (finite)
    double scale = 1.0;             ///< world units per sheet pixel, > 0
    std::string animation;          ///< the animation it moves along (its name); "" stands at `at`
    Vec2 at;                        ///< where its pivot stands without an animation, world units
    /// The sheet, once read (load_scene_file, load_scene_sprite_sheets; nullptr before).
    std::shared_ptr<const SpriteSheet> sheet;
    std::filesystem::path sheet_path;  ///< the JSON file the sheet was read from
    std::size_t clip_index = 0;        ///< the clip of `sheet` played (one of its own for a frame range)

    /// The sheet frame shown at scene time t ≥ 0: a ClipPlayer of the clip at the rate advanced
    /// by t seconds. Throws grape::Error when the sheet is not loaded or t is negative or not finite.
    std::size_t frame_at(double t) const;
};

/// How a scene is shown by `grape render`.
struct SceneView {
    double width = 640.0;       ///< output units, in [1, 32768]
    double height = 480.0;      ///< output units, in [1, 32768]
    double ticks = 0.0;         ///< Δu between parametrization ticks on paths (0: none)
};

/// Everything a scene file holds.
struct GRAPE_SCENE_API Scene {
    std::string name;                         ///< title ("" allowed)
    SceneView view;                           ///< picture settings
    std::vector<NamedPath> paths;             ///< named paths (drawn, and used by animations)
    std::vector<NamedCurve> curves;           ///< named curves
    std::vector<SceneAnimation> animations;   ///< animations (their paths are drawn too)
    std::vector<SceneSimulation> simulations; ///< particle simulations
    std::vector<SceneTimeline> timelines;     ///< timelines driving some of the animations
    std::vector<SceneSprite> sprites;         ///< sprites from sprite sheets
    std::vector<SceneProperty> properties;    ///< typed values driven by tweens
    std::vector<SceneTween> tweens;           ///< tweens of the properties
    std::vector<NamedPath3> paths3;           ///< named 3-D paths (JSON "paths3")
    std::vector<SceneAnimation3> animations3; ///< 3-D animations (JSON "animations3")
    /// What loading forgave, one message each: SVG path data with a syntax error is read by
    /// SVG's error rule (the path before the command holding the error). Not saved.
    std::vector<std::string> warnings;

    /// The named path; nullptr when there is none.
    const NamedPath* find_path(std::string_view name) const noexcept;
    /// The named curve; nullptr when there is none.
    const NamedCurve* find_curve(std::string_view name) const noexcept;
    /// The named 3-D path; nullptr when there is none.
    const NamedPath3* find_path3(std::string_view name) const noexcept;
    /// The named property's index; −1 when there is none.
    std::ptrdiff_t find_property(std::string_view name) const noexcept;
};

/// One play of a timeline as laid out, and where it is placed.
struct SceneTimelineLayout {
    std::vector<double> start;        ///< per child, seconds from the timeline's start
    std::vector<double> length;       ///< per child, seconds it lasts in the timeline (labels 0)
    std::vector<std::ptrdiff_t> index;  ///< per child, the animation's, 3-D animation's, tween's or timeline's index (−1 for labels, gaps)
    double duration = 0.0;            ///< seconds of one play (the end of the last-ending child)
    double end_time = 0.0;            ///< seconds of its parent until its last play ends (+inf: forever)
    std::ptrdiff_t parent = -1;       ///< the timeline it is placed in (−1: it plays from scene time 0)
    double start_in_parent = 0.0;     ///< seconds from the parent's start (0 at the top level)
};

/// A scene's animations and timelines placed in time: which timeline drives each animation
/// and where. Built once from a scene (which it then no longer needs); evaluation is
/// noexcept and allocation-free, the same timing model the anim engine plays (progress_at,
/// play_at_position as the engine's timelines call it).
class GRAPE_SCENE_API SceneTiming {
public:
    SceneTiming() = default;
    /// Lays out every timeline. Throws grape::Error "scene: POINTER: WHY" for an unknown or
    /// ambiguous animation, tween, timeline or label, a cycle of timelines, nesting deeper than 32,
    /// an animation, tween or timeline placed twice, a child repeating forever, a negative start.
    explicit SceneTiming(const Scene& scene);

    std::size_t animation_count() const noexcept { return animations_.size(); }  ///< the scene's animations, in file order
    std::size_t timeline_count() const noexcept { return timelines_.size(); }  ///< the scene's timelines, in file order
    /// The timeline driving animation i (−1: it plays on its own from scene time 0).
    std::ptrdiff_t driver(std::size_t animation) const noexcept { return animations_[animation].driver; }
    /// Timeline k's layout and placement.
    const SceneTimelineLayout& layout(std::size_t timeline) const noexcept { return timelines_[timeline].layout; }

    /// Seconds into one play of timeline k at scene time t, down its chain of parents, with
    /// the engine's timeline arithmetic ((t·time_scale − delay) / duration in plays, as
    /// play_at_position takes them): an engine ticking to the same times agrees bit for bit.
    double timeline_time(std::size_t timeline, double t) const noexcept;
    /// The time animation i plays at at scene time t: t itself when free, otherwise the
    /// seconds since its start in its timeline (negative before it, past its end after).
    double animation_time(std::size_t animation, double t) const noexcept;
    /// Progress u of animation i at scene time t: progress_at(def, duration, animation_time).
    double progress(std::size_t animation, double t) const noexcept;
    /// Scene seconds until every free animation (2-D or 3-D), free tween and top-level timeline has ended
    /// (+inf when one repeats forever).
    double end_time() const noexcept;

    std::size_t animation3_count() const noexcept { return animations3_.size(); }  ///< the scene's 3-D animations, in file order
    /// The timeline driving 3-D animation i (−1: it plays on its own from scene time 0).
    std::ptrdiff_t animation3_driver(std::size_t animation) const noexcept { return animations3_[animation].driver; }
    /// The time 3-D animation i plays at at scene time t (as animation_time).
    double animation3_time(std::size_t animation, double t) const noexcept;
    /// Progress of 3-D animation i at scene time t: progress_at(def, seconds, animation3_time);
    /// SceneMotion3::position_at takes it.
    double animation3_progress(std::size_t animation, double t) const noexcept;
    /// 3-D animation i's current play runs backwards at scene time t (play_at's `backward`):
    /// what SceneMotion3::orientation_at takes to face the way it goes.
    bool animation3_backward(std::size_t animation, double t) const noexcept;

    std::size_t tween_count() const noexcept { return tweens_.size(); }  ///< the scene's tweens, in file order
    /// The timeline driving tween i (−1: it plays on its own from scene time 0).
    std::ptrdiff_t tween_driver(std::size_t tween) const noexcept { return tweens_[tween].driver; }
    /// The time tween i plays at at scene time t (as animation_time).
    double tween_time(std::size_t tween, double t) const noexcept;
    /// Progress u of tween i at scene time t: progress_at(def, duration, tween_time).
    double tween_progress(std::size_t tween, double t) const noexcept;
    /// Scene seconds when tween i's first play begins: its delay / time_scale when free; in a
    /// timeline, when the timeline first reaches its place (its own delay runs inside, at its start).
    double tween_entry(std::size_t tween) const noexcept { return tweens_[tween].entry; }
    /// Tween i has begun its current play at scene time t: t ≥ tween_entry, and in a timeline
    /// the timeline's time is at or past its place in the current play.
    bool tween_reached(std::size_t tween, double t) const noexcept;

private:
    // timeline_time as the timeline's children see it: for a timeline whose length underflowed
    // to 0 although it holds something (time scales of 1e300 nested), +inf after its start,
    // so that they stand at their ends.
    double driving_time(std::size_t timeline, double t) const noexcept;
    // The time at scene time t of what timeline `driver` holds at `start` (a free one: t).
    double driven_time(std::ptrdiff_t driver, double start, double t) const noexcept;
    struct Animation {
        AnimationDef def;
        double duration = 1.0;
        std::ptrdiff_t driver = -1;
        double start = 0.0;  // in the driver's time
    };
    struct Timeline {
        AnimationDef def;
        SceneTimelineLayout layout;
    };
    struct Tween {
        AnimationDef def;
        double duration = 1.0;
        std::ptrdiff_t driver = -1;
        double start = 0.0;  // in the driver's time
        double entry = 0.0;  // scene seconds of the first play's start
    };
    std::vector<Animation> animations_;
    std::vector<Animation> animations3_;
    std::vector<Timeline> timelines_;
    std::vector<Tween> tweens_;
};

/// Parses scene JSON text. Throws grape::Error naming the JSON pointer and the reason
/// (or the byte offset of a syntax error).
GRAPE_SCENE_API Scene load_scene(std::string_view json);
/// Reads and parses a scene file and the sprite sheets it names (relative to its folder);
/// errors also name the file.
GRAPE_SCENE_API Scene load_scene_file(const std::filesystem::path& file);
/// Reads the sheets of the scene's sprites (sheet_file relative to `folder`) and finds their
/// clips; throws grape::Error naming the sprite's JSON pointer ("scene: /sprites/0/clip: ...").
GRAPE_SCENE_API void load_scene_sprite_sheets(Scene& scene, const std::filesystem::path& folder);
/// The scene as JSON text (indented, 17 significant digits). Paths built in code save too;
/// a curve from a function (Curve::from_function) has no text form: grape::Error naming its
/// pointer ("scene: /tweens/0/curve: ...").
GRAPE_SCENE_API std::string save_scene(const Scene& scene);
/// Writes the scene to a file (through a temporary: a failure leaves no partial file).
GRAPE_SCENE_API void save_scene_file(const Scene& scene, const std::filesystem::path& file);

/// A path as scene JSON (one object, as it appears in "paths" or inline).
GRAPE_SCENE_API std::string path_to_json(const Path& path);
/// A path from scene JSON text (one object). Throws grape::Error naming the JSON pointer.
GRAPE_SCENE_API Path parse_path_json(std::string_view json);

#if GRAPE_HAS_DYNAMICS
class ParticleSystem;
/// The simulation as a ParticleSystem ready to step (particles in order, then forces, then
/// constraints; a distance of length 0 keeps the starting distance). Only when grape::scene
/// was built with grape::dynamics (GRAPE_HAS_DYNAMICS in grape/config.hpp).
GRAPE_SCENE_API ParticleSystem make_particle_system(const SceneSimulation& simulation);
#endif

/// C(p) of a conic constraint: A·x² + B·x·y + C·y² + D·x + E·y + F.
GRAPE_SCENE_API double conic_value(const SceneConstraint& constraint, Vec2 p) noexcept;

/// @}

}  // namespace grape
