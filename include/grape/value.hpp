// grape — typed values: the one interpolation point every typed animation goes through, the
// value specs (from → to, from the current value, by an amount) and angles.
//
// An animation of a member of type V writes `Interpolate<V>::lerp(from, to, u)` with u the
// curve's progress. The primary template calls `lerp(a, b, t)` found by ordinary lookup in
// grape (double, float, Vec2) or by argument-dependent lookup in V's namespace (Color, your
// own types); specialize `Interpolate<V>` instead when V's namespace is not yours. A lerp
// must give a at t = 0 and b at t = 1, extrapolate outside [0, 1] (overshooting curves), and
// not throw (it runs inside the engine's tick).
//
//   namespace game { struct Hsv { double h, s, v; };
//                    Hsv lerp(const Hsv& a, const Hsv& b, double t) noexcept; }
//   engine.animate(light, &Light::hsv, grape::from_to(dark, bright), 2.0);
#pragma once

#include <grape/math.hpp>

#include <cmath>
#include <concepts>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>

namespace grape {

/// \addtogroup value
/// @{

namespace detail {
// Unqualified, so both grape's overloads and V's own (by ADL) are found.
template <class V>
concept has_lerp = requires(const V& a, const V& b, double t) {
    { lerp(a, b, t) } -> std::convertible_to<V>;
};
template <class V>
V call_lerp(const V& a, const V& b, double t) {
    return static_cast<V>(lerp(a, b, t));
}
}  // namespace detail

/// The customization point: `lerp(a, b, t)` for V (specialize for types you cannot add a
/// lerp beside). A specialization may also give `static P prepare(const V& a, const V& b)`,
/// P callable as `V(double t)` with P(t) == lerp(a, b, t): animations then prepare their ends
/// once (colours convert them to linear light once, not at every update); and `static V
/// compose(const V& from, const V& amount)`, the end of grape::by(amount) in place of
/// from + amount (grape/quat.hpp: rotations compose).
template <class V>
struct Interpolate {
    /// The unqualified `lerp(a, b, t)`: one of grape's overloads or V's own, found beside V.
    static V lerp(const V& a, const V& b, double t)
        requires detail::has_lerp<V>
    {
        return detail::call_lerp(a, b, t);
    }
};

/// A type an animation can drive: Interpolate<V>::lerp exists and V can be copied.
template <class V>
concept Interpolatable = std::copyable<V> && requires(const V& a, const V& b, double t) {
    { Interpolate<V>::lerp(a, b, t) } -> std::convertible_to<V>;
};

/// The default interpolator of typed animations: Interpolate<V>::lerp.
struct Lerp {
    /// Interpolate<V>::lerp(a, b, t).
    template <Interpolatable V>
    V operator()(const V& a, const V& b, double t) const {
        return Interpolate<V>::lerp(a, b, t);
    }
    /// Interpolate<V>::prepare(a, b), for the types that have it.
    template <Interpolatable V>
        requires requires(const V& a) { Interpolate<V>::prepare(a, a); }
    auto prepare(const V& a, const V& b) const {
        return Interpolate<V>::prepare(a, b);
    }
};

/// Angles in radians from a to b. Shortest: the turn of at most half a turn that ends on b's
/// direction (a + remainder(b − a, 2π)·t, so from 3 rad to −3 rad it turns 0.28 rad through
/// ±π and ends on 2π − 3, not on −3: the value never jumps by 2π); a difference of half a
/// turn plus whole turns goes by +π or −π as std::remainder rounds it (b − a itself when
/// |b − a| = π). Not shortest: plain lerp, every turn kept.
struct AngleLerp {
    bool shortest = true;  ///< take the shortest turn; false: plain lerp
    /// The angle at t (t = 0: a; t = 1: b, or b's direction when shortest).
    double operator()(double a, double b, double t) const noexcept {
        if (!shortest) return grape::lerp(a, b, t);
        const double turn = b - a;
        const double d = std::abs(turn) <= pi ? turn : std::remainder(turn, 2.0 * pi);
        return t == 1.0 ? a + d : a + d * t;
    }
};

/// How a typed animation's start and end are found.
enum class ValueMode {
    from_to,       ///< from `from` to `to`, both given
    from_current,  ///< from the member's value when the first play begins, to `to`
    relative,      ///< from the member's value when the first play begins, by `to` (from + to)
};

/// The values of a typed animation; make one with from_to, to or by.
template <class V>
struct Tween {
    V from{};  ///< the start (ValueMode::from_to only)
    V to{};  ///< the end, or the amount for ValueMode::relative
    ValueMode mode = ValueMode::from_to;  ///< how start and end are found

    Tween() = default;
    /// From `f` to `t` in mode `m`.
    Tween(V f, V t, ValueMode m) : from(std::move(f)), to(std::move(t)), mode(m) {}
    /// From a Tween of another type (grape::to(1) for a double member).
    template <class U>
        requires(!std::same_as<U, V> && std::convertible_to<const U&, V>)
    Tween(const Tween<U>& o)  // NOLINT: implicit on purpose
        : from(static_cast<V>(o.from)), to(static_cast<V>(o.to)), mode(o.mode) {}
};

namespace detail {
/// One typed member a value animation writes (the engine owns one per such animation).
struct ValueTrack {
    virtual ~ValueTrack() = default;
    /// The first play begins: from-current and relative animations read the member now.
    virtual void start(void* object) = 0;
    /// Writes the value at curve progress u.
    virtual void write(void* object, double u) = 0;
    std::size_t offset = 0;  ///< the member's first byte within the object
    std::size_t size = 0;    ///< its bytes
};

template <class M>
struct member_traits;
template <class V, class C>
struct member_traits<V C::*> {
    using value_type = V;
    using class_type = C;
};
/// V of a `V C::*`.
template <class M>
using member_value_t = typename member_traits<M>::value_type;

template <class V>
concept addable = requires(const V& a, const V& b) {
    { a + b } -> std::convertible_to<V>;
};
/// Interpolate<V>::compose(from, amount) gives the end of by(amount) (rotations compose, they do not add).
template <class V>
concept composable = requires(const V& a, const V& b) {
    { Interpolate<V>::compose(a, b) } -> std::convertible_to<V>;
};
/// A type grape::by works for: it composes, or it has +.
template <class V>
concept relative_value = composable<V> || addable<V>;

/// Member `member` of a T (derived from C), from → to through `interp`.
/// An interpolator that can prepare its ends once: interp.prepare(a, b)(t).
template <class Interp, class V>
concept preparable = requires(const Interp& i, const V& a, double t) {
    { i.prepare(a, a)(t) } -> std::convertible_to<V>;
};
struct Unprepared {};
template <class Interp, class V, bool = preparable<Interp, V>>
struct prepared_type {
    using type = Unprepared;
};
template <class Interp, class V>
struct prepared_type<Interp, V, true> {
    using type = std::optional<decltype(std::declval<const Interp&>().prepare(std::declval<const V&>(),
                                                                                 std::declval<const V&>()))>;
};

template <class T, class C, class V, class Interp>
struct MemberTrack final : ValueTrack {
    using Prepared = typename prepared_type<Interp, V>::type;
    V C::*member;
    V from;
    V to;
    V amount;  // relative: kept apart, so a start read again (placing in a timeline) adds it once
    ValueMode mode;
    Interp interp;
    Prepared prepared{};
    MemberTrack(V C::*m, Tween<V> tween, Interp i)
        : member(m), from(std::move(tween.from)), to(tween.to), amount(std::move(tween.to)), mode(tween.mode),
          interp(std::move(i)) {
        if (mode == ValueMode::from_to) prepare();
    }
    void prepare() {
        if constexpr (preparable<Interp, V>) prepared.emplace(interp.prepare(from, to));
    }
    static C& object(void* o) noexcept { return *static_cast<C*>(static_cast<T*>(o)); }
    void start(void* o) override {
        if (mode == ValueMode::from_to) return;
        from = object(o).*member;
        if constexpr (composable<V>) {
            if (mode == ValueMode::relative) to = static_cast<V>(Interpolate<V>::compose(from, amount));
        } else if constexpr (addable<V>) {
            if (mode == ValueMode::relative) to = static_cast<V>(from + amount);
        }
        prepare();
    }
    void write(void* o, double u) override {
        if constexpr (preparable<Interp, V>) object(o).*member = static_cast<V>((*prepared)(u));
        else object(o).*member = static_cast<V>(interp(from, to, u));
    }
};
}  // namespace detail

/// From `from` to `to`.
template <class V>
Tween<V> from_to(V from, V to) {
    return Tween<V>(std::move(from), std::move(to), ValueMode::from_to);
}
/// From the member's value when the first play begins (after the delay) to `to`.
template <class V>
Tween<V> to(V to) {
    return Tween<V>(V{}, std::move(to), ValueMode::from_current);
}
/// By `amount` from the member's value when the first play begins: to from + amount, or to
/// Interpolate<V>::compose(from, amount) where V has it (a Quat composes: from · amount).
template <class V>
Tween<V> by(V amount) {
    return Tween<V>(V{}, std::move(amount), ValueMode::relative);
}

/// @}

}  // namespace grape
