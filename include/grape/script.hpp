// grape — cut-scenes as straight-line code: a C++20 coroutine driven by an Engine's tick.
//
//   grape::Script intro(grape::Engine& engine, Hero& hero) {
//       co_await engine.create_2d_animation(hero, walk_in, 2.0);   // until it completes or dies
//       co_await grape::wait(0.5);                                  // engine seconds, exact
//       co_await grape::until([&] { return hero.ready; });          // polled once per tick
//       co_await outro(engine, hero);                               // a nested script
//   }
//   grape::Script scene = intro(engine, hero);
//   scene.start(engine);        // runs to its first wait; then the engine's ticks drive it
//
// A script runs only inside start() and inside the tick listener it registers with
// `Engine::on_tick` (so it resumes after the tick's animations have advanced). It may await:
//  - anything handle-like (`alive()`; an `Animation`, a timeline handle, a started Script):
//    resumes in the first tick that ends with it not alive (at once if it already is not);
//  - `wait(s)` or a plain number: s engine seconds (scaled by nothing);
//  - `until(predicate)`: resumes in the first tick that ends with the predicate true (checked
//    at once first; a predicate that throws throws at the co_await);
//  - a Script not yet started: runs it nested, on this script's clock, and resumes when it
//    ends; an exception leaving it is rethrown at the co_await.
//
// Time is exact: a script has a clock (the sum of the dt of the ticks it has seen, summed
// without rounding drift) and a time `now` at which it stands. `wait(s)` ends at now + s, not
// s after the tick that resumed it: the script resumes inside the tick whose end reaches that
// time (within `script_snap`), its `now` becomes exactly the end of the wait, and the
// co_await gives the overshoot (clock − end ≥ 0: how long ago, at the tick's end, the wait
// ended). Successive waits therefore never drift, and one large dt ends many waits in order
// within one tick. Other awaits resume with now = the clock. A nested script shares the
// clock and the now of the script awaiting it. A script started with start() begins with
// clock and now at `ScriptDef::elapsed` (0 by default): the end of the tick it was started in.
//
// Cancellation: `cancel()` (and destroying the Script) stops it at the point where it is
// suspended and destroys its coroutine frame (locals are destroyed as on return), after
// killing what it awaits if `OnCancel::kill_awaited` (handles with `kill()` are killed, started
// scripts cancelled). A script that cancels itself, or a script containing it, from its own
// code stops at its next co_await, which then does not resume. Cancelling a nested script
// resumes the script awaiting it at the next tick, as a killed animation would (within the
// same tick when the chain's own code cancelled it).
//
// Errors: an exception leaving a nested script is rethrown at the co_await awaiting it; one
// leaving a started script ends it (failed(), error()) and goes to `ScriptDef::on_error`
// or, without a handler, leaves the start() or Engine::tick() that was running it (as an
// animation handler's exception does: the tick's remaining listeners do not run). Never lost.
//
// Lifetime: a Script may be destroyed at any time, also from its own code. The engine may be
// destroyed first: its scripts stop (cancelled(), nothing is killed) and their frames are
// destroyed with the Script objects; a script's locals must then not use the engine in their
// destructors. `Engine::kill_all` kills the animations scripts await, which resume as usual.
//
// As with any coroutine, what the script takes by reference must outlive it, and a lambda
// with captures must not itself be the coroutine (its captures die with the lambda). Awaited
// handles are copied into the frame; their kill() must not throw. A script started inside a
// tick (by another script or a handler) sees its first dt at the next tick.
//
// Running costs no allocation per tick: start() allocates the listener once, the frame is
// allocated when the coroutine is called. Threads: a script belongs to its engine's thread.
// Needs the standard <coroutine> header (g++ ≥ 11, clang 14 with libstdc++; not the libc++ of
// emscripten 3.1.6, so grape built for the web leaves scripts out).
#pragma once

#include <grape/anim.hpp>
#include <grape/export_anim.hpp>

#include <concepts>
#include <coroutine>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>

namespace grape {

/// \addtogroup script
/// @{

class Script;

/// A wait counts as ended when the clock is within this many seconds of its end: 60 ticks
/// of 1/60 s end a 1 s wait on the 60th tick although their double sum falls short by an ulp.
inline constexpr double script_snap = 1e-9;

/// What cancelling a script does to the animations (or other handles) it is awaiting.
enum class OnCancel : std::uint8_t {
    kill_awaited,   ///< kill them (handles with kill()) and cancel awaited started scripts
    leave_awaited,  ///< leave them running
};

/// How a started script runs; fill with designated initializers.
struct ScriptDef {
    OnCancel on_cancel = OnCancel::kill_awaited;  ///< what destruction and cancel() do
    /// Receives an exception that leaves the script (then start() and tick() do not throw it).
    std::function<void(std::exception_ptr)> on_error{};
    double elapsed = 0.0;  ///< seconds the script's clock starts at (≥ 0, finite): pass the
                           ///< overshoot of a wait to start another script exactly on time
};

/// Something a script can await: a handle whose `alive()` turns false when it is done.
template <class T>
concept ScriptHandle = requires(const T& handle) {
    { handle.alive() } -> std::convertible_to<bool>;
};

/// Awaitable: `co_await grape::wait(0.25)` resumes 0.25 engine seconds later (see the
/// header comment for exactness); gives the overshoot in seconds. seconds ≥ 0 (+inf: never);
/// a negative or NaN wait throws grape::Error at the co_await.
struct Wait {
    double seconds = 0.0;  ///< engine seconds to wait, ≥ 0 (+inf: never)
};
/// `co_await grape::wait(seconds)`: see Wait.
inline Wait wait(double seconds) noexcept { return {seconds}; }

/// Awaitable: resumes when `predicate()` returns true, checked at the co_await and then at
/// the end of every tick.
template <class F>
struct Until {
    F predicate;  ///< called with no arguments, returns true to resume
};
/// `co_await grape::until(predicate)`: see Until.
template <class F>
Until<std::decay_t<F>> until(F&& predicate) {
    return {std::forward<F>(predicate)};
}

namespace detail {

class ScriptPromise;
struct ScriptLink;

/// What a suspended script waits for: polled by the driver, type-erased over the awaiter
/// (which lives in the coroutine frame while suspended).
struct ScriptLeaf {
    void* awaiter = nullptr;
    bool (*ready)(void* awaiter) = nullptr;  ///< may throw: the exception goes to the co_await
    void (*stop)(void* awaiter) = nullptr;   ///< kill what it awaits (may be null)
    bool timed = false;                      ///< ready() sets the script's time itself (a wait)
};

/// A time as an unevaluated sum hi + lo (a double-double), so a clock summed over millions
/// of ticks keeps the ulp of its value.
struct GRAPE_ANIM_API ScriptTime {
    double hi = 0.0;
    double lo = 0.0;
    void add(double x) noexcept;
    friend double operator-(const ScriptTime& a, const ScriptTime& b) noexcept { return (a.hi - b.hi) + (a.lo - b.lo); }
};

enum class ScriptState : std::uint8_t { idle, running, done, failed, cancelled };

class GRAPE_ANIM_API ScriptPromise {
public:
    ScriptPromise() noexcept = default;
    ScriptPromise(const ScriptPromise&) = delete;
    ScriptPromise& operator=(const ScriptPromise&) = delete;
    ~ScriptPromise();

    Script get_return_object() noexcept;
    std::suspend_always initial_suspend() noexcept { return {}; }
    struct GRAPE_ANIM_API FinalAwaiter {
        bool await_ready() noexcept { return false; }
        std::coroutine_handle<> await_suspend(std::coroutine_handle<ScriptPromise> h) noexcept;
        void await_resume() noexcept {}
    };
    FinalAwaiter final_suspend() noexcept { return {}; }
    void return_void() noexcept {}
    void unhandled_exception() noexcept { error_ = std::current_exception(); }

    // --- awaitables (every co_await in a script goes through these) ---
    struct WaitAwaiter;
    template <class H>
    struct HandleAwaiter;
    template <class F>
    struct UntilAwaiter;
    struct ScriptAwaiter;

    WaitAwaiter await_transform(Wait w);
    template <class N>
        requires(std::is_arithmetic_v<N> && !std::is_same_v<N, bool>)
    WaitAwaiter await_transform(N seconds);
    template <class F>
    UntilAwaiter<F> await_transform(Until<F> u);
    ScriptAwaiter await_transform(Script& script);
    ScriptAwaiter await_transform(Script&& script);
    template <class H>
        requires(ScriptHandle<std::remove_cvref_t<H>> && !std::is_same_v<std::remove_cvref_t<H>, Script>)
    HandleAwaiter<std::remove_cvref_t<H>> await_transform(H&& handle);

    // --- used by the awaiters and the driver (script.cpp) ---
    ScriptPromise* root() noexcept { return root_; }
    bool stopping() const noexcept;        ///< a cancellation waits for the next co_await
    void suspend_on(ScriptLeaf leaf) noexcept;
    void rethrow_pending();                ///< an exception meant for this co_await
    bool wait_ended(ScriptTime end, double* overshoot) noexcept;
    ScriptTime now() const noexcept { return root_->now_; }

    std::coroutine_handle<ScriptPromise> handle() noexcept { return std::coroutine_handle<ScriptPromise>::from_promise(*this); }

    enum class Waiting : std::uint8_t { start, nothing, leaf, child, child_gone };

    Script* owner_ = nullptr;          // the Script object holding this frame (may be gone)
    ScriptPromise* root_ = this;       // the started script this one runs in
    ScriptPromise* parent_ = nullptr;  // the script awaiting this one (nested), else null
    ScriptPromise* child_ = nullptr;   // the nested script this one awaits
    ScriptLeaf leaf_{};
    Waiting waiting_ = Waiting::start;
    ScriptState state_ = ScriptState::idle;
    bool cancel_requested_ = false;
    OnCancel cancel_mode_ = OnCancel::kill_awaited;
    std::exception_ptr error_;         // left this frame
    std::exception_ptr pending_;       // to be thrown at the current co_await

    // Root only.
    Engine* engine_ = nullptr;
    std::size_t listener_ = 0;
    std::shared_ptr<ScriptLink> link_;
    ScriptDef def_{};
    ScriptTime clock_{};
    ScriptTime now_{};
    bool running_ = false;             // the driver or the script's code is on the stack
    bool cancel_pending_ = false;      // some frame of this chain asked to be cancelled
};

/// Shared between a started script and its engine listener: cleared when either goes away.
struct ScriptLink {
    ScriptPromise* owner = nullptr;
};

GRAPE_ANIM_API void cancel_script(ScriptPromise* p, OnCancel mode) noexcept;
GRAPE_ANIM_API bool script_link_alive(const std::shared_ptr<ScriptLink>& link) noexcept;
[[noreturn]] GRAPE_ANIM_API void throw_bad_wait(double seconds);

}  // namespace detail

/// A cut-scene as a coroutine: a function returning Script with co_await in it. Created
/// suspended; `start(engine)` runs it. Move-only; destroying it cancels the script.
class GRAPE_ANIM_API Script {
public:
    using promise_type = detail::ScriptPromise;  ///< what makes a function returning Script a coroutine

    Script() noexcept = default;
    Script(Script&& other) noexcept;  ///< takes other's script over; other is left empty
    /// Cancels the script held now (as the destructor does), then takes other's.
    Script& operator=(Script&& other) noexcept;
    ~Script();

    /// Runs the script until its first suspension, then at the end of every engine tick
    /// until it ends. Throws grape::Error if the script is empty, already running or ended,
    /// or def is bad; rethrows an exception leaving the script's first steps (see on_error).
    void start(Engine& engine, ScriptDef def = {});

    /// Started (or running nested) and not yet ended.
    bool alive() const noexcept { return state() == detail::ScriptState::running; }
    explicit operator bool() const noexcept { return alive(); }  ///< alive()
    /// Ran to its end without an exception.
    bool done() const noexcept { return state() == detail::ScriptState::done; }
    /// Ended by an exception (see error()).
    bool failed() const noexcept { return state() == detail::ScriptState::failed; }
    /// Stopped by cancel(), by destruction of the engine, or never started and cancelled.
    bool cancelled() const noexcept { return state() == detail::ScriptState::cancelled; }
    /// The exception that ended it (null unless failed()).
    std::exception_ptr error() const noexcept;

    /// Stops the script (see the header comment); the awaited animations are killed or left
    /// as ScriptDef::on_cancel says (kill_awaited for a script never started).
    void cancel() noexcept;
    /// The same, choosing what happens to the awaited animations.
    void cancel(OnCancel what) noexcept;

private:
    friend class detail::ScriptPromise;
    explicit Script(std::coroutine_handle<detail::ScriptPromise> h) noexcept : handle_(h) { h.promise().owner_ = this; }
    detail::ScriptState state() const noexcept { return handle_ ? handle_.promise().state_ : state_; }
    void release() noexcept;
    OnCancel default_on_cancel() const noexcept;

    std::coroutine_handle<detail::ScriptPromise> handle_{};
    detail::ScriptState state_ = detail::ScriptState::idle;  // once the frame is gone
    std::exception_ptr error_;
};

// --- awaiters ---------------------------------------------------------------------------------

namespace detail {

struct ScriptPromise::WaitAwaiter {
    ScriptPromise* p;
    ScriptTime end;
    double overshoot = 0.0;
    bool await_ready() noexcept { return p->wait_ended(end, &overshoot) && !p->stopping(); }
    void await_suspend(std::coroutine_handle<>) noexcept { p->suspend_on({this, &ready, nullptr, true}); }
    double await_resume() {
        p->rethrow_pending();
        return overshoot;
    }
    static bool ready(void* a) noexcept {
        auto* w = static_cast<WaitAwaiter*>(a);
        return w->p->wait_ended(w->end, &w->overshoot);
    }
};

template <class H>
struct ScriptPromise::HandleAwaiter {
    ScriptPromise* p;
    H handle;
    bool await_ready() { return !static_cast<bool>(handle.alive()) && !p->stopping(); }
    void await_suspend(std::coroutine_handle<>) noexcept {
        if constexpr (requires(H& h) { h.kill(); }) p->suspend_on({this, &ready, &stop});
        else p->suspend_on({this, &ready, nullptr});
    }
    void await_resume() { p->rethrow_pending(); }
    static bool ready(void* a) { return !static_cast<bool>(static_cast<HandleAwaiter*>(a)->handle.alive()); }
    static void stop(void* a) {
        if constexpr (requires(H& h) { h.kill(); }) static_cast<HandleAwaiter*>(a)->handle.kill();
    }
};

template <class F>
struct ScriptPromise::UntilAwaiter {
    ScriptPromise* p;
    F predicate;
    bool await_ready() { return static_cast<bool>(predicate()) && !p->stopping(); }
    void await_suspend(std::coroutine_handle<>) noexcept { p->suspend_on({this, &ready, nullptr}); }
    void await_resume() { p->rethrow_pending(); }
    static bool ready(void* a) { return static_cast<bool>(static_cast<UntilAwaiter*>(a)->predicate()); }
};

/// A nested script (runs inside this one) or a started one (polled like a handle).
struct GRAPE_ANIM_API ScriptPromise::ScriptAwaiter {
    ScriptPromise* p;
    ScriptPromise* child = nullptr;        // nested: not yet started when awaited
    std::shared_ptr<ScriptLink> started;   // started elsewhere: alive while its link is
    bool await_ready() noexcept;
    std::coroutine_handle<> await_suspend(std::coroutine_handle<ScriptPromise> h) noexcept;
    void await_resume();
    static bool ready(void* a) noexcept { return !script_link_alive(static_cast<ScriptAwaiter*>(a)->started); }
    static void stop(void* a) noexcept {
        auto* s = static_cast<ScriptAwaiter*>(a);
        if (script_link_alive(s->started)) cancel_script(s->started->owner, s->started->owner->def_.on_cancel);
    }
};

inline ScriptPromise::WaitAwaiter ScriptPromise::await_transform(Wait w) {
    if (!(w.seconds >= 0.0)) throw_bad_wait(w.seconds);
    ScriptTime end = now();
    end.add(w.seconds);
    return {this, end};
}

template <class N>
    requires(std::is_arithmetic_v<N> && !std::is_same_v<N, bool>)
ScriptPromise::WaitAwaiter ScriptPromise::await_transform(N seconds) {
    return await_transform(Wait{static_cast<double>(seconds)});
}

template <class F>
ScriptPromise::UntilAwaiter<F> ScriptPromise::await_transform(Until<F> u) {
    return {this, std::move(u.predicate)};
}

template <class H>
    requires(ScriptHandle<std::remove_cvref_t<H>> && !std::is_same_v<std::remove_cvref_t<H>, Script>)
ScriptPromise::HandleAwaiter<std::remove_cvref_t<H>> ScriptPromise::await_transform(H&& handle) {
    return {this, std::forward<H>(handle)};
}

}  // namespace detail

/// @}

}  // namespace grape
