// grape — animations and the engine: a path (where) played by a curve (when) over time.
//
// The `Engine` is an ordinary object the application owns; `tick(dt)` advances every live
// animation. Animations live in the engine's contiguous storage and are reached through
// `Animation` handles, which are generation-checked: once an animation has completed or been
// killed its handles are inert (queries say so, commands do nothing), never dangling.
// A handle must not outlive its engine.
//
//   grape::Engine engine;
//   grape::SpiralPath spiral({100, 100}, 200, 0);
//   grape::Animation anim = engine.create_2d_animation(view, spiral, 2.0);  // view.x, view.y
//   anim.on_complete([] { /* done */ });
//   engine.tick(1.0 / 60.0);
//
// Time: an animation keeps the phase of its current play (in plays) and each tick adds
// dt·time_scale/duration to it, so ticking a dt sequence that sums to T lands where seek(T)
// and `play_at` (the one timing model, a pure function also used by scenes and timelines:
// anim_timing.hpp) put it up to the rounding of those additions: about an ulp of the phase
// per tick, not bit for bit (the tests hold tick and seek within 1e-12 on a unit-sized path
// over up to 300 ticks, repeats, yoyo, delays and time scales included). Ends of plays go by
// one snap rule, the same for tick and seek: a play counts as finished within play_snap
// (1e-9) of its length, in plays, so 60 ticks of 1/60 s end a 1 s play on the 60th tick
// although the sum falls short by an ulp, and any time within 1e-9 plays before an end is
// that end. One large dt fires the loop events it crosses in order, up to `max_loop_events`
// per animation per tick (then one event for the last play, counting the skipped ones).
// Arc-length (reparametrized) linear and cubic Bézier paths are evaluated
// from a table the path module builds once per shared path, within 2e-10·length of
// Path::point.
//
// Targets: `create_2d_animation(object, ...)`, `create_property_animation` and
// `animate(object, ...)` write to the object's address (raw: it must outlive the animation and
// stay in place); the linked forms of target.hpp (std::shared_ptr, grape::Animated,
// grape::linked, grape::element, grape::accessor) are looked up at each update and stop
// cleanly when the object is gone. Typed values (colours, angles, your own types) go through
// `animate` and value.hpp's one interpolation point.
//
// Limits: at most 65,535 distinct curves with parameters (back, elastic, cubic-bezier, steps,
// monotone; equal curves share one) alive in one engine at once, and 2³¹ animations;
// creation throws grape::Error beyond them.
//
// Threads: an Engine and its animations belong to one thread: tick, create, seek, pause,
// kill, the handles' queries and every event handler run on the thread that owns the
// engine, and the targets it writes must not be read by another thread during a tick.
// Engine::set_parallel adds worker threads that the engine owns: they run only the plain
// updates of its ticks (no user code), and every handler still runs on the owner's thread.
// Separate engines share nothing and may run on separate threads at once; the Paths and
// Curves they play may be shared between them (see path.hpp and curve.hpp).
#pragma once

#include <grape/anim3.hpp>
#include <grape/anim_timing.hpp>
#include <grape/curve.hpp>
#include <grape/error.hpp>
#include <grape/export_anim.hpp>
#include <grape/math.hpp>
#include <grape/path.hpp>
#include <grape/target.hpp>
#include <grape/value.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <span>
#include <type_traits>
#include <vector>

namespace grape {

/// \addtogroup anim
/// @{

class Engine;
class Timeline;
struct TimelineDef;

/// A member of T that a property animation drives: a `double T::*` or a `float T::*`.
template <class T>
struct Member {
    /// A `double` member.
    Member(double T::*m) noexcept : d(m) {}  // NOLINT: implicit on purpose, {&T::a, &T::b}
    /// A `float` member.
    Member(float T::*m) noexcept : f(m) {}   // NOLINT
    double T::*d = nullptr;  ///< the double member, or null
    float T::*f = nullptr;  ///< the float member, or null
};

namespace detail {
class EngineImpl;
class TimelineStore;
struct LiveRecord;
/// Where a property animation writes one value: a byte offset into the target and its type.
struct MemberRef {
    std::size_t offset;
    bool is_float;
};
template <class T, class M>
std::size_t offset_in(const T& object, const M& member) noexcept {
    return static_cast<std::size_t>(reinterpret_cast<const char*>(&member) - reinterpret_cast<const char*>(&object));
}
}  // namespace detail

/// A handle to an animation in an Engine. Default-constructed or stale handles are inert:
/// queries return neutral values and `alive()` is false; commands do nothing.
class GRAPE_ANIM_API Animation {
public:
    Animation() noexcept = default;

    /// Waiting for its delay, playing or paused (false once completed or killed).
    bool alive() const noexcept;
    explicit operator bool() const noexcept { return alive(); }  ///< alive()
    /// Still inside its delay: nothing has been written to the target yet.
    bool waiting() const noexcept;
    bool paused() const noexcept;  ///< alive and held by pause()

    /// The current 2-D position; while waiting, where the first play starts (the path's start,
    /// or its end for a reversed animation); {0, 0} if not alive, N-D, typed or 3-D (value3()).
    Vec2 value() const noexcept;
    /// The current position of a 3-D animation (offsets included); while waiting, where the
    /// first play starts; {0, 0, 0} if not alive or not 3-D.
    Vec3 value3() const noexcept;
    /// The current values of an N-D animation (empty if not alive or 2-D).
    std::span<const double> values() const noexcept;
    /// Direction of travel in radians, atan2 of the path's derivative at the current point,
    /// turned by π while playing backwards (0 if not alive or 3-D: a 3-D target's orientation
    /// member has its direction).
    double heading() const noexcept;
    /// Curve progress of the current play (the path parameter u; may leave [0, 1]).
    double progress() const noexcept;
    /// Seconds of animation time since the first play began (negative while waiting;
    /// counts all plays and repeat delays, so it runs to duration·(repeat + 1) +
    /// repeat_delay·repeat).
    double time() const noexcept;
    /// Which play is running: 0 for the first, 1 after the first loop, ... (saturating at
    /// INT32_MAX; time() goes on counting: plays are counted in 64 bits).
    int repetition() const noexcept;
    /// Seconds per play (0 if not alive).
    double duration() const noexcept;
    /// Animation seconds per engine second, exactly as set (0 if not alive).
    double time_scale() const noexcept;

    /// Stops advancing (keeps its state and its target's values). Called from its own on_loop
    /// handler, it also stops the tick that fired the event: the animation holds at the start
    /// of that play and fires no further loop events in that tick.
    void pause() const noexcept;
    /// Advances again from where it paused.
    void resume() const noexcept;
    /// Jumps to `seconds` of animation time since the first play began (negative: back into
    /// the delay, that many seconds before the start; past the end of a finite animation:
    /// its end, and it completes on the next tick). Writes the new state to the target at
    /// once; fires no event (events come from tick). Non-finite seconds are ignored.
    void seek(double seconds) const noexcept;
    /// Changes the speed (≥ 0 and finite; other values are ignored).
    void set_time_scale(double scale) const noexcept;
    /// Removes the animation now (inside a tick: no further events; storage reclaimed at the
    /// tick's end). Its target keeps its last values. Completion does not fire.
    void kill() const noexcept;

    /// Calls `handler` once when the animation completes (after its last play has written its
    /// end state). The handler may create, pause, seek or kill any animation, this one
    /// included; seeking this one back into its plays from the handler restarts it. If the
    /// handler throws, the animation has completed all the same and the error leaves tick().
    void on_complete(std::function<void()> handler) const;
    /// Calls `handler(play)` each time a new play starts (play = 1, 2, ..., saturating at
    /// INT32_MAX), once per play when one tick starts up to max_loop_events plays; beyond
    /// that, once for the last play started (the others are skipped).
    void on_loop(std::function<void(int)> handler) const;
    /// The same with `skipped`: how many plays started in this tick before `play` without an
    /// event of their own (0 unless the tick started more than max_loop_events plays;
    /// saturates at UINT64_MAX).
    void on_loop(std::function<void(int play, std::uint64_t skipped)> handler) const;

    /// Plays backwards from where it is (at the engine's time scale), back through earlier
    /// plays to the first one's start, where on_reverse_complete fires and it holds (alive).
    /// Inside its delay it waits. No loop events going back.
    void reverse() const noexcept;
    /// Plays forwards again from where it is (and resumes it).
    void play() const noexcept;
    /// Running backwards now (after reverse()).
    bool reversed() const noexcept;
    /// Calls `handler` after every change of state (each tick that moves it, each seek).
    void on_update(std::function<void()> handler) const;
    /// Calls `handler` when the first play begins (after the delay; in a timeline, each time
    /// the timeline's time carries it forward across that point).
    void on_start(std::function<void()> handler) const;
    /// Calls `handler` when the animation comes back to its start running backwards (after
    /// reverse(), or in a timeline running backwards).
    void on_reverse_complete(std::function<void()> handler) const;

    /// The same animation (the same slot and generation in the same engine).
    friend bool operator==(const Animation&, const Animation&) noexcept = default;

private:
    friend class Engine;
    friend class detail::EngineImpl;
    friend class detail::TimelineStore;
    Animation(Engine* engine, std::uint32_t slot, std::uint32_t generation) noexcept
        : engine_(engine), slot_(slot), generation_(generation) {}
    detail::LiveRecord record() const noexcept;  // the record of a live handle (false when stale)
    Engine* engine_ = nullptr;
    std::uint32_t slot_ = 0;
    std::uint32_t generation_ = 0;
};

/// The most threads Engine::set_parallel takes.
inline constexpr int max_tick_threads = 256;

/// How Engine::set_parallel shares a tick among threads; fill with designated initializers:
/// `{.threads = 2}`.
struct ParallelDef {
    int threads = 2;  ///< threads in all, the calling one included: [1, max_tick_threads]
    /// Below this many animations (the engine's own, not those timelines drive) phase 1 runs
    /// on the calling thread alone. Ticked once per 60 Hz frame, two threads broke even at
    /// about 32,000 animations on a 2-core machine and gave 1.1–1.2× at 65,536
    /// (bench/RESULTS.md); ticks back to back (sub-steps) gain from ~16,000. Lower it for those.
    std::size_t min_animations = 65536;
    /// Seconds a worker stays awake after its share of a tick, waiting for the next one,
    /// before it sleeps: [0, 1]. Ticks that come sooner (sub-steps, several engines) skip
    /// the wake-up, tens of µs each; a worker awake keeps its core busy meanwhile. Ticks
    /// that come once a frame (after a gap longer than this) are timed: a sleeping worker
    /// wakes this long before the next is due and waits for it awake up to this long after,
    /// so a worker spends up to twice this per frame awake. 0: workers never spin and are
    /// only woken by a tick (no timed wake either).
    double awake = 200e-6;
};

/// Owns and advances animations. Not copyable or movable (handles refer to it).
///
/// Order within a tick: every animation that was alive when the tick began advances by dt
/// (events fire as each one crosses a loop or completes), then every top-level timeline
/// (timeline.hpp; the animations placed in timelines are driven there, not here), then tick
/// listeners run.
/// Handlers may create, pause, resume, seek or kill animations: an animation created during
/// a tick first advances on the next tick; a killed one gets no further events; a change
/// to an animation the tick has not reached yet applies before its own update in that tick.
///
/// Two-phase ticks (set_parallel): the same work in two phases, the first shared among
/// threads. Phase 1 advances every *plain* animation: not paused, past its delay by the
/// tick's end, written by the engine itself to a raw 2-D target (no update callback, N-D,
/// heading, typed value, linked target or function curve), and neither completing, running
/// back to its start, nor calling any handler in this tick. Nothing but those updates
/// runs in phase 1, and each writes only its own record and target. Phase 2, on the calling
/// thread: every other animation in the one-pass order, with its events, then the timelines,
/// then the tick listeners. The results are the same bit for bit for any number of threads
/// and any min_animations (a second thread changes only the speed). They equal the one-pass
/// tick's except where a handler touches a plain animation: the handler sees that
/// animation's state (and its target) after this tick's update, and its change (seek, pause,
/// kill, time scale, reverse) applies after that update instead of before it. If a handler
/// throws, phase 1 is complete and the animations after it in phase 2 do not advance.
/// Plain animations write their targets from several threads: no two animations may write
/// the same bytes (overwrite = true keeps one per member), and, as for every tick, no other
/// thread may touch the targets while it runs.
class GRAPE_ANIM_API Engine {
public:
    Engine();
    ~Engine();
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    /// Advances every live animation by dt engine seconds (finite, ≥ 0; throws grape::Error
    /// otherwise, or when called from inside one of its own handlers). Work is bounded per
    /// animation whatever dt is (see max_loop_events).
    void tick(double dt);

    /// From the next tick on, ticks in two phases (see above), phase 1 shared among
    /// def.threads threads: def.threads − 1 workers started here, once, awake for def.awake
    /// after each tick and asleep after that; no allocation per tick once the engine has
    /// stopped growing. threads = 1 gives the two-phase order on the calling thread alone
    /// (the same results as any thread count). Throws grape::Error for threads outside
    /// [1, max_tick_threads], awake outside [0, 1], or when called from inside one of the
    /// engine's own handlers (std::system_error if a thread cannot start).
    void set_parallel(const ParallelDef& def = {});
    /// Back to the one-pass tick on the calling thread; stops the workers. Throws grape::Error
    /// when called from inside one of the engine's own handlers.
    void set_serial();
    /// The threads a two-phase tick uses (def.threads of set_parallel); 0 for the one-pass tick.
    int tick_threads() const noexcept;

    /// Moves `target.x` and `target.y` (both double or both float) along a 2-D path for
    /// `duration` seconds (> 0 and finite) per play. With `def.heading` and a `rotation`
    /// member (double or float; any other type does not compile), the heading is written
    /// there too. A T deriving from grape::Animated is linked (see target.hpp). Every creation throws
    /// grape::Error for a bad duration or def, and for timings a double cannot hold: plays
    /// per second (time_scale / duration), delay / duration or the end time overflowing.
    template <class T>
        requires(!detail::wrapped_target<std::remove_cv_t<T>>)
    Animation create_2d_animation(T& target, const Path& path, double duration, const AnimationDef& def = {});

    /// Moves any double/float members of `target` from `from` to `to` (one value per member).
    template <class T>
    Animation create_property_animation(T& target, std::initializer_list<Member<std::type_identity_t<T>>> members,
                                        std::initializer_list<double> from, std::initializer_list<double> to,
                                        double duration, const AnimationDef& def = {});
    /// Moves members of `target` through the keyframes of an N-D path (N = members.size()).
    template <class T>
    Animation create_property_animation(T& target, std::initializer_list<Member<std::type_identity_t<T>>> members, PathND path,
                                        double duration, const AnimationDef& def = {});

    /// An animation bound to nothing: read its state from the handle, or get it in
    /// `on_update(position, heading)` after each change (tick or seek).
    Animation create_animation(const Path& path, double duration, const AnimationDef& def = {},
                               std::function<void(Vec2, double)> on_update = {});
    /// The N-D form: `on_update(values)` after each change.
    Animation create_animation(PathND path, double duration, const AnimationDef& def = {},
                               std::function<void(std::span<const double>)> on_update = {});

    /// The same on a linked target (std::shared_ptr, grape::linked, grape::element,
    /// grape::accessor; see target.hpp): stops cleanly once the target is gone.
    template <class Target>
        requires detail::wrapped_target<std::remove_cvref_t<Target>>
    Animation create_2d_animation(Target&& target, const Path& path, double duration, const AnimationDef& def = {});

    /// Moves `target.x`, `target.y` and `target.z` (all double or all float) along a 3-D path for
    /// `duration` seconds (> 0 and finite) per play, timed by `def` exactly as a 2-D animation
    /// (curve, delay, repeat, yoyo, reversed, time scale, range; def.heading and def.offset are
    /// 2-D only and refused). With `motion.align` other than none, the target's `orientation`
    /// member (grape::Frame3, grape::Basis or grape::Quat) receives the orientation at each update (see
    /// Motion3Def). At curve progress u the position is path.point(at) plus the offsets along
    /// frame(at), at = range_start + u·(range_end − range_start), the frame's table built once
    /// at creation; updates then allocate nothing. A T deriving from grape::Animated is linked.
    /// Throws grape::Error naming the field for a bad duration, def or motion.
    template <class T>
        requires(!detail::wrapped_target<std::remove_cv_t<T>>)
    Animation create_3d_animation(T& target, const Path3& path, double duration, const AnimationDef& def = {},
                                  const Motion3Def& motion = {});
    /// The same at constant speed: plays path.reparametrized() (built here, once) for
    /// length / speed seconds per play, so that with a linear curve the distance travelled
    /// along the path grows by speed·dt (to the reparametrization's 1e-9·length). Throws
    /// grape::Error for a speed that is not positive and finite or a path of length 0.
    template <class T>
        requires(!detail::wrapped_target<std::remove_cv_t<T>>)
    Animation create_3d_animation(T& target, const Path3& path, Speed speed, const AnimationDef& def = {},
                                  const Motion3Def& motion = {});
    /// The 3-D forms on a linked target (std::shared_ptr, grape::linked, grape::element,
    /// grape::accessor; see target.hpp): stops cleanly once the target is gone.
    template <class Target>
        requires detail::wrapped_target<std::remove_cvref_t<Target>>
    Animation create_3d_animation(Target&& target, const Path3& path, double duration, const AnimationDef& def = {},
                                  const Motion3Def& motion = {});
    /// The linked form at constant speed.
    template <class Target>
        requires detail::wrapped_target<std::remove_cvref_t<Target>>
    Animation create_3d_animation(Target&& target, const Path3& path, Speed speed, const AnimationDef& def = {},
                                  const Motion3Def& motion = {});

    /// Drives `member` of the target (any type `Interpolate` knows: double, float, Vec2, Color,
    /// your own through a lerp; see value.hpp) as `tween` says: grape::from_to(a, b), grape::to(b)
    /// (from the member's value when the first play begins) or grape::by(d) (by d from that
    /// value). The value at curve progress u is interp(from, to, u): AngleLerp{} for angles,
    /// ColorLerp{} for colours in OKLab. The target is an object (raw: it must stay alive and
    /// in place while the animation runs) or a linked form (target.hpp). Nothing is written
    /// while waiting; the member's start is read once, when the first play begins (seek and
    /// reverse replay the captured values). Throws grape::Error for a gone target too.
    template <class Target, class M, class Interp = Lerp>
    Animation animate(Target&& target, M member, Tween<detail::member_value_t<M>> tween, double duration,
                      const AnimationDef& def = {}, Interp interp = {});

    /// Kills every animation that writes into `object`'s bytes (a std::shared_ptr: the
    /// object it points to), no events; returns how many. Finds 2-D, property, typed and linked
    /// animations (linked ones where their target is now). The first call builds the target
    /// index (one pass); from then on creation and removal keep it (O(log n) each).
    template <class T>
    std::size_t kill_animations_of(const T& object);
    /// The live animations that write into `object`'s bytes, in no particular order.
    template <class T>
    std::vector<Animation> animations_of(const T& object);

    /// A new timeline, empty and at its start (see timeline.hpp; include it to call these).
    Timeline create_timeline();
    /// A new timeline that plays as `def` says; throws grape::Error for a negative or non-finite
    /// delay, repeat delay or time scale, or a repeat below −1.
    Timeline create_timeline(const TimelineDef& def);

    /// Calls `listener(dt)` at the end of every tick; returns an id for remove_tick_listener.
    std::size_t on_tick(std::function<void(double)> listener);
    /// Stops a tick listener (safe inside a tick: it is not called again).
    void remove_tick_listener(std::size_t id) noexcept;

    /// Kills every animation (no events).
    void kill_all() noexcept;
    /// Live animations (waiting, playing or paused).
    std::size_t size() const noexcept;
    /// Bytes the engine's per-animation storage holds now (capacity included), not counting
    /// shared paths and curves or handler state.
    std::size_t storage_bytes() const noexcept;
    /// Bytes of storage each plain 2-D animation needs (hot + cold + handle slot).
    static std::size_t bytes_per_animation() noexcept;

private:
    friend class Animation;
    friend class Timeline;
    friend class detail::TimelineStore;
    Animation create_bound_2d(void* target, std::size_t x_offset, std::size_t y_offset, bool is_float,
                              std::ptrdiff_t rotation_offset, const Path& path, double duration,
                              const AnimationDef& def, bool rotation_float = false,
                              std::unique_ptr<detail::TargetRef> ref = nullptr);
    Animation create_bound_3d(void* object, const detail::Layout3& layout, std::unique_ptr<detail::TargetRef> ref,
                              const Path3& path, double duration, const Speed* speed, const AnimationDef& def,
                              const Motion3Def& motion);
    template <class T>
    static detail::Layout3 layout3_of(const T& object) noexcept;
    Animation create_bound_value(void* object, std::unique_ptr<detail::TargetRef> ref,
                                 std::unique_ptr<detail::ValueTrack> track, double duration, const AnimationDef& def);
    std::size_t kill_in(const void* object, std::size_t bytes);
    std::vector<Animation> find_in(const void* object, std::size_t bytes);
    template <class T>
    static std::pair<const void*, std::size_t> bytes_of(const T& object) noexcept;
    Animation create_bound_nd(void* target, std::vector<detail::MemberRef> members, PathND path, double duration,
                              const AnimationDef& def);
    std::unique_ptr<detail::EngineImpl> impl_;
};

// --- templates ------------------------------------------------------------------------------

template <class T>
    requires(!detail::wrapped_target<std::remove_cv_t<T>>)
Animation Engine::create_2d_animation(T& target, const Path& path, double duration, const AnimationDef& def) {
    using X = std::remove_cvref_t<decltype(target.x)>;
    using Y = std::remove_cvref_t<decltype(target.y)>;
    static_assert(std::is_same_v<X, Y> && (std::is_same_v<X, double> || std::is_same_v<X, float>),
                  "create_2d_animation: target.x and target.y must both be double or both float");
    std::ptrdiff_t rotation = -1;
    bool rotation_float = false;
    if constexpr (requires { target.rotation; }) {
        using R = std::remove_cvref_t<decltype(target.rotation)>;
        static_assert(std::is_same_v<R, double> || std::is_same_v<R, float>,
                      "create_2d_animation: target.rotation receives the heading (.heading = true) and must be "
                      "double or float; animate another type through create_animation's callback");
        if (def.heading) rotation = static_cast<std::ptrdiff_t>(detail::offset_in(target, target.rotation));
        rotation_float = std::is_same_v<R, float>;
    }
    return create_bound_2d(&target, detail::offset_in(target, target.x), detail::offset_in(target, target.y),
                           std::is_same_v<X, float>, rotation, path, duration, def, rotation_float,
                           detail::TargetForm<T>::ref(target));
}

template <class Target>
    requires detail::wrapped_target<std::remove_cvref_t<Target>>
Animation Engine::create_2d_animation(Target&& target, const Path& path, double duration, const AnimationDef& def) {
    using Form = detail::TargetForm<std::remove_cvref_t<Target>>;
    using T = typename Form::object_type;
    T* now = Form::now(target);
    if (!now) throw Error("create_2d_animation: the linked target is gone");
    using X = std::remove_cvref_t<decltype(now->x)>;
    using Y = std::remove_cvref_t<decltype(now->y)>;
    static_assert(std::is_same_v<X, Y> && (std::is_same_v<X, double> || std::is_same_v<X, float>),
                  "create_2d_animation: target.x and target.y must both be double or both float");
    std::ptrdiff_t rotation = -1;
    bool rotation_float = false;
    if constexpr (requires { now->rotation; }) {
        using R = std::remove_cvref_t<decltype(now->rotation)>;
        static_assert(std::is_same_v<R, double> || std::is_same_v<R, float>,
                      "create_2d_animation: target.rotation receives the heading (.heading = true) and must be "
                      "double or float; animate another type through create_animation's callback");
        if (def.heading) rotation = static_cast<std::ptrdiff_t>(detail::offset_in(*now, now->rotation));
        rotation_float = std::is_same_v<R, float>;
    }
    return create_bound_2d(now, detail::offset_in(*now, now->x), detail::offset_in(*now, now->y), std::is_same_v<X, float>,
                           rotation, path, duration, def, rotation_float, Form::ref(target));
}

template <class T>
detail::Layout3 Engine::layout3_of(const T& object) noexcept {
    using X = std::remove_cvref_t<decltype(object.x)>;
    using Y = std::remove_cvref_t<decltype(object.y)>;
    using Z = std::remove_cvref_t<decltype(object.z)>;
    static_assert(std::is_same_v<X, Y> && std::is_same_v<X, Z> && (std::is_same_v<X, double> || std::is_same_v<X, float>),
                  "create_3d_animation: target.x, target.y and target.z must all be double or all float");
    detail::Layout3 l;
    l.x = detail::offset_in(object, object.x);
    l.y = detail::offset_in(object, object.y);
    l.z = detail::offset_in(object, object.z);
    l.is_float = std::is_same_v<X, float>;
    if constexpr (requires { object.orientation; }) {
        using O = std::remove_cvref_t<decltype(object.orientation)>;
        static_assert(detail::orient3_member_of<O>() != detail::Orient3Member::none,
                      "create_3d_animation: target.orientation receives the orientation and must be a "
                      "grape::Frame3, a grape::Basis or a grape::Quat");
        l.orientation = detail::offset_in(object, object.orientation);
        l.member = detail::orient3_member_of<O>();
    }
    return l;
}

template <class T>
    requires(!detail::wrapped_target<std::remove_cv_t<T>>)
Animation Engine::create_3d_animation(T& target, const Path3& path, double duration, const AnimationDef& def,
                                      const Motion3Def& motion) {
    return create_bound_3d(&target, layout3_of(target), detail::TargetForm<T>::ref(target), path, duration, nullptr, def,
                           motion);
}

template <class T>
    requires(!detail::wrapped_target<std::remove_cv_t<T>>)
Animation Engine::create_3d_animation(T& target, const Path3& path, Speed speed, const AnimationDef& def,
                                      const Motion3Def& motion) {
    return create_bound_3d(&target, layout3_of(target), detail::TargetForm<T>::ref(target), path, 0.0, &speed, def,
                           motion);
}

template <class Target>
    requires detail::wrapped_target<std::remove_cvref_t<Target>>
Animation Engine::create_3d_animation(Target&& target, const Path3& path, double duration, const AnimationDef& def,
                                      const Motion3Def& motion) {
    using Form = detail::TargetForm<std::remove_cvref_t<Target>>;
    auto* now = Form::now(target);
    if (!now) throw Error("create_3d_animation: the linked target is gone");
    return create_bound_3d(now, layout3_of(*now), Form::ref(target), path, duration, nullptr, def, motion);
}

template <class Target>
    requires detail::wrapped_target<std::remove_cvref_t<Target>>
Animation Engine::create_3d_animation(Target&& target, const Path3& path, Speed speed, const AnimationDef& def,
                                      const Motion3Def& motion) {
    using Form = detail::TargetForm<std::remove_cvref_t<Target>>;
    auto* now = Form::now(target);
    if (!now) throw Error("create_3d_animation: the linked target is gone");
    return create_bound_3d(now, layout3_of(*now), Form::ref(target), path, 0.0, &speed, def, motion);
}

template <class Target, class M, class Interp>
Animation Engine::animate(Target&& target, M member, Tween<detail::member_value_t<M>> tween, double duration,
                          const AnimationDef& def, Interp interp) {
    using Form = detail::TargetForm<std::remove_cvref_t<Target>>;
    using T = typename Form::object_type;
    using V = detail::member_value_t<M>;
    using C = typename detail::member_traits<M>::class_type;
    static_assert(std::is_base_of_v<C, T>, "animate: the member must belong to the target's type");
    static_assert(std::is_invocable_r_v<V, const Interp&, const V&, const V&, double>,
                  "animate: no interpolation for this type: give it a lerp(a, b, t) found beside it, specialize "
                  "grape::Interpolate, or pass an interpolator taking (V, V, double)");
    if constexpr (!detail::relative_value<V>) {
        if (tween.mode == ValueMode::relative)
            throw Error("animate: grape::by needs a type with + (or Interpolate<V>::compose)");
    }
    T* now = Form::now(target);
    if (!now) throw Error("animate: the linked target is gone");
    auto track = std::make_unique<detail::MemberTrack<T, C, V, Interp>>(member, std::move(tween), std::move(interp));
    C& base = *now;
    track->offset = static_cast<std::size_t>(reinterpret_cast<const char*>(&(base.*member)) -
                                             reinterpret_cast<const char*>(now));
    track->size = sizeof(V);
    return create_bound_value(now, Form::ref(target), std::move(track), duration, def);
}

template <class T>
std::pair<const void*, std::size_t> Engine::bytes_of(const T& object) noexcept {
    if constexpr (requires { typename T::element_type; object.get(); *object; }) {
        if (!object) return {nullptr, 0};
        return {std::addressof(*object), sizeof(*object)};
    } else {
        return {std::addressof(object), sizeof(T)};
    }
}

template <class T>
std::size_t Engine::kill_animations_of(const T& object) {
    const auto [at, bytes] = bytes_of(object);
    return at ? kill_in(at, bytes) : 0;
}

template <class T>
std::vector<Animation> Engine::animations_of(const T& object) {
    const auto [at, bytes] = bytes_of(object);
    return at ? find_in(at, bytes) : std::vector<Animation>();
}

template <class T>
Animation Engine::create_property_animation(T& target, std::initializer_list<Member<std::type_identity_t<T>>> members, PathND path,
                                            double duration, const AnimationDef& def) {
    std::vector<detail::MemberRef> refs;
    refs.reserve(members.size());
    for (const Member<T>& m : members) {
        if (m.d) refs.push_back({detail::offset_in(target, target.*(m.d)), false});
        else refs.push_back({detail::offset_in(target, target.*(m.f)), true});
    }
    return create_bound_nd(&target, std::move(refs), std::move(path), duration, def);
}

template <class T>
Animation Engine::create_property_animation(T& target, std::initializer_list<Member<std::type_identity_t<T>>> members,
                                            std::initializer_list<double> from, std::initializer_list<double> to,
                                            double duration, const AnimationDef& def) {
    return create_property_animation(target, members,
                                     PathND(std::span<const double>(from.begin(), from.size()),
                                            std::span<const double>(to.begin(), to.size())),
                                     duration, def);
}

/// @}

}  // namespace grape
