// grape — scene properties: the typed values of a scene (numbers, angles, Vec2, colours, Vec3,
// quaternions) as their tweens drive them, evaluated at any scene time as a pure function of it.
//
// The rule (docs/scene-format.md, "Properties and tweens"): a property's tweens are ordered
// by when their first play begins (SceneTiming::tween_entry; ties in the order of "tweens").
// At time t the value is that of the last tween in that order that has begun its current
// play (SceneTiming::tween_reached), at its progress then (after its end: its end); when
// none has but one has begun before (a timeline looping back), the first one's start; before
// any, the property's own value. A from-current tween starts from the value at its entry of
// the tweens before it in the order, a relative one moves by its amount from there: what the
// anim engine's Engine::animate with grape::to / grape::by reads when its first play begins.
//
//   grape::Scene scene = grape::load_scene_file("scenes/typed_values.json");
//   grape::SceneTiming timing(scene);
//   grape::SceneProperties values(scene, timing);
//   grape::Color tint = std::get<grape::Color>(values.value(0, 1.5));
#pragma once

#include <grape/export_scene.hpp>
#include <grape/scene.hpp>

#include <cstddef>
#include <vector>

namespace grape {

/// \addtogroup scene
/// @{

/// The value between a and b at curve progress u as the property mixes them: lerp for
/// numbers, Vec2 and Vec3, AngleLerp (or its degrees form) for angles, grape::mix in the
/// property's space for colours, slerp of normalized(a) and normalized(b) on the shortest arc
/// for quaternions. a and b hold the property's type.
GRAPE_SCENE_API SceneValue interpolate(const SceneProperty& property, const SceneValue& a, const SceneValue& b,
                                       double u) noexcept;

/// A scene's properties as its tweens drive them. Built once (the from-current and relative
/// starts resolved in order); value() is noexcept, allocation-free and O(tweens of the
/// property) at worst (O(log n) when the last begun tween is found at once).
class GRAPE_SCENE_API SceneProperties {
public:
    SceneProperties() = default;
    /// Checks every tween against its property and resolves their starts. `timing` is
    /// SceneTiming(scene). Throws grape::Error "scene: POINTER: WHY" for a property name
    /// empty or repeated, a value of another type than its property's, an unknown property,
    /// "by" on a colour or a quaternion, a bad duration, delay, repeat delay or time scale.
    SceneProperties(const Scene& scene, const SceneTiming& timing);

    std::size_t property_count() const noexcept { return properties_.size(); }  ///< the scene's properties, in file order
    /// Property p's value at scene time t.
    SceneValue value(std::size_t property, double t) const noexcept;
    /// Tween i's start as resolved (from-current and relative ones: the value at their entry).
    const SceneValue& tween_from(std::size_t tween) const noexcept { return tweens_[tween].from; }
    /// Tween i's end as resolved (relative ones: their start plus the amount).
    const SceneValue& tween_to(std::size_t tween) const noexcept { return tweens_[tween].to; }

private:
    struct Tween {
        SceneValue from, to;
        std::size_t property = 0;
        double start_u = 0.0;  // progress of the first play's start
    };
    SceneValue value_of(std::size_t property, std::size_t count, double t) const noexcept;
    std::vector<SceneProperty> properties_;
    std::vector<Tween> tweens_;
    std::vector<std::vector<std::size_t>> order_;  // per property, its tweens by entry
    std::vector<double> entry_;                    // per tween
    SceneTiming timing_;
};

/// @}

}  // namespace grape
