// Scripts: the driver that resumes a chain of nested coroutines from an engine tick listener,
// cancellation (at once, or deferred while the chain's code is on the stack) and lifetimes.
#include <grape/script.hpp>

#include <grape/error.hpp>

#include <cmath>
#include <string>

namespace grape {
namespace detail {

void ScriptTime::add(double x) noexcept {
    const double s = hi + x;
    if (!std::isfinite(s)) {  // an endless wait: no low part to keep
        hi = s;
        lo = 0.0;
        return;
    }
    // Knuth's two-sum: s + err is hi + x exactly; lo collects the errors, then hi + lo is
    // renormalized so that |lo| stays below an ulp of hi.
    const double b = s - hi;
    const double err = (hi - (s - b)) + (x - b);
    const double l = lo + err;
    hi = s + l;
    lo = l - (hi - s);
}

void throw_bad_wait(double seconds) {
    throw Error("Script: wait seconds must be >= 0 (got " + number_text(seconds) + ")");
}

bool script_link_alive(const std::shared_ptr<ScriptLink>& link) noexcept {
    return link && link->owner && link->owner->state_ == ScriptState::running;
}

namespace {

using Waiting = ScriptPromise::Waiting;

/// The frame of the chain that is suspended on something other than a nested script.
ScriptPromise* innermost(ScriptPromise* p) noexcept {
    while (p->waiting_ == Waiting::child && p->child_) p = p->child_;
    return p;
}

/// The engine went away with its listeners: the script stops where it is; its frame stays
/// until the Script object lets go of it, and nothing may reach the engine any more.
void engine_gone(ScriptPromise* root) noexcept {
    root->engine_ = nullptr;
    root->listener_ = 0;
    if (root->link_) root->link_->owner = nullptr;
    for (ScriptPromise* q = root; q; q = q->waiting_ == Waiting::child ? q->child_ : nullptr) q->state_ = ScriptState::cancelled;
}

/// Cancels p and the scripts it awaits, now: nothing of the chain may be on the stack.
void cancel_now(ScriptPromise* p, OnCancel mode) noexcept {
    ScriptPromise* root = p->root_;
    ScriptPromise* q = innermost(p);
    if (mode == OnCancel::kill_awaited && root->engine_ && q->waiting_ == Waiting::leaf && q->leaf_.stop) {
        root->running_ = true;  // a kill that reaches back here only asks
        q->leaf_.stop(q->leaf_.awaiter);
        root->running_ = false;
    }
    for (ScriptPromise* r = p; r; r = r->waiting_ == Waiting::child ? r->child_ : nullptr) {
        r->leaf_ = {};
        r->state_ = ScriptState::cancelled;  // nested Scripts destroyed with p's frame just free theirs
    }
    // A frame below p whose Script went away while it ran belongs to nobody: freed here,
    // innermost first. The others go with the Scripts (or the frames) holding them.
    for (ScriptPromise* r = innermost(p); r != p;) {
        ScriptPromise* up = r->parent_;
        if (!r->owner_) r->handle().destroy();
        r = up;
    }
    p->handle().destroy();  // the promise's destructor tells the awaiting script, the owner, the engine
}

/// The root's coroutine has returned: report the outcome and free the frame.
void finish_root(ScriptPromise* root) {
    std::exception_ptr error = root->error_;
    root->state_ = error ? ScriptState::failed : ScriptState::done;
    std::function<void(std::exception_ptr)> on_error;
    if (error) on_error = std::move(root->def_.on_error);
    root->handle().destroy();
    if (error) {
        if (on_error) on_error(error);
        else std::rethrow_exception(error);
    }
}

/// Runs root's chain as far as it can go at the current time. May destroy root's frame.
void drive(ScriptPromise* root) {
    bool poll = true;  // leaves set during this pass are fresh: they were checked when set
    for (;;) {
        if (root->cancel_pending_) {
            root->cancel_pending_ = false;
            ScriptPromise* target = nullptr;
            for (ScriptPromise* q = root; q && !target; q = q->waiting_ == Waiting::child ? q->child_ : nullptr) {
                if (q->cancel_requested_) target = q;
            }
            if (target == root) {
                cancel_now(root, root->cancel_mode_);
                return;
            }
            if (target) cancel_now(target, target->cancel_mode_);  // its parent resumes below
            continue;
        }
        if (root->handle().done()) {
            finish_root(root);
            return;
        }
        ScriptPromise* q = innermost(root);
        bool go = false;
        root->running_ = true;
        switch (q->waiting_) {
            case Waiting::start:
                go = true;
                break;
            case Waiting::child_gone:
                go = true;
                root->now_ = root->clock_;
                break;
            case Waiting::leaf:
                if (!poll) break;
                try {
                    go = q->leaf_.ready(q->leaf_.awaiter);
                } catch (...) {
                    q->pending_ = std::current_exception();  // thrown at the co_await
                    go = true;
                }
                if (go && !q->leaf_.timed) root->now_ = root->clock_;
                break;
            default:
                break;
        }
        if (!go || root->cancel_pending_) {
            root->running_ = false;
            if (root->cancel_pending_) continue;
            return;
        }
        q->waiting_ = Waiting::nothing;
        q->leaf_ = {};
        q->handle().resume();
        root->running_ = false;
        poll = false;
    }
}

/// Lives in the engine's listener; its destruction without the script letting go first
/// means the engine is being destroyed.
struct ListenerToken {
    std::shared_ptr<ScriptLink> link;
    explicit ListenerToken(std::shared_ptr<ScriptLink> l) noexcept : link(std::move(l)) {}
    ListenerToken(const ListenerToken&) = delete;
    ListenerToken& operator=(const ListenerToken&) = delete;
    ~ListenerToken() {
        if (link->owner) engine_gone(link->owner);
    }
};

struct Listener {
    std::shared_ptr<ListenerToken> token;
    ScriptLink* link;  // token's: one load less on every tick
    void operator()(double dt) const {
        if (ScriptPromise* root = link->owner) {
            root->clock_.add(dt);
            drive(root);
        }
    }
};

}  // namespace

void cancel_script(ScriptPromise* p, OnCancel mode) noexcept {
    if (p->state_ != ScriptState::running) {
        if (p->state_ == ScriptState::idle) p->state_ = ScriptState::cancelled;
        p->handle().destroy();  // never started, or a nested frame that ended, or engine gone
        return;
    }
    ScriptPromise* root = p->root_;
    if (root->running_) {  // its code, or code it called, is on the stack: stop at the next co_await
        p->cancel_requested_ = true;
        p->cancel_mode_ = mode;
        root->cancel_pending_ = true;
        return;
    }
    cancel_now(p, mode);
}

ScriptPromise::~ScriptPromise() {
    if (child_ && child_->parent_ == this) child_->parent_ = nullptr;  // held elsewhere: outlives this
    if (parent_ && parent_->child_ == this) {
        parent_->child_ = nullptr;
        parent_->waiting_ = Waiting::child_gone;
    }
    if (root_ == this) {
        if (link_) link_->owner = nullptr;
        if (engine_ && listener_) engine_->remove_tick_listener(listener_);
    }
    if (owner_) {
        owner_->handle_ = {};
        owner_->state_ = state_;
        owner_->error_ = error_;
    }
}

Script ScriptPromise::get_return_object() noexcept { return Script(handle()); }

std::coroutine_handle<> ScriptPromise::FinalAwaiter::await_suspend(std::coroutine_handle<ScriptPromise> h) noexcept {
    ScriptPromise& c = h.promise();
    c.state_ = c.error_ ? ScriptState::failed : ScriptState::done;
    ScriptPromise* parent = c.parent_;
    if (!parent) return std::noop_coroutine();  // a root: the driver finishes it
    parent->child_ = nullptr;
    parent->waiting_ = Waiting::nothing;
    if (c.error_) parent->pending_ = c.error_;
    c.parent_ = nullptr;
    if (!c.owner_) h.destroy();  // its Script went away while it ran: nobody else will
    return parent->handle();
}

// Only a cancellation of this frame or of one awaiting it holds this co_await: one asked by
// a nested script that has since ended concerns nobody here.
bool ScriptPromise::stopping() const noexcept {
    if (!root_->cancel_pending_) return false;
    for (const ScriptPromise* q = this; q; q = q->parent_) {
        if (q->cancel_requested_) return true;
    }
    return false;
}

void ScriptPromise::suspend_on(ScriptLeaf leaf) noexcept {
    leaf_ = leaf;
    waiting_ = Waiting::leaf;
}

void ScriptPromise::rethrow_pending() {
    if (pending_) {
        std::exception_ptr e = std::move(pending_);
        pending_ = nullptr;
        std::rethrow_exception(e);
    }
}

bool ScriptPromise::wait_ended(ScriptTime end, double* overshoot) noexcept {
    ScriptPromise* r = root_;
    const double d = r->clock_ - end;
    if (!(d >= -script_snap)) return false;
    r->now_ = end;
    *overshoot = d > 0.0 ? d : 0.0;
    return true;
}

ScriptPromise::ScriptAwaiter ScriptPromise::await_transform(Script& script) {
    ScriptAwaiter a{this, nullptr, {}};
    if (!script.handle_) return a;  // empty or ended: nothing to wait for
    ScriptPromise& c = script.handle_.promise();
    if (c.state_ == ScriptState::idle) {
        a.child = &c;
    } else if (c.state_ == ScriptState::running) {
        if (c.root_ != &c || !c.link_) throw Error("Script: co_await on a script another script is already awaiting");
        a.started = c.link_;
    }
    return a;
}

ScriptPromise::ScriptAwaiter ScriptPromise::await_transform(Script&& script) { return await_transform(script); }

bool ScriptPromise::ScriptAwaiter::await_ready() noexcept {
    if (p->stopping()) return false;
    if (child) return false;
    return !script_link_alive(started);
}

std::coroutine_handle<> ScriptPromise::ScriptAwaiter::await_suspend(std::coroutine_handle<ScriptPromise>) noexcept {
    if (p->stopping()) {
        p->waiting_ = Waiting::nothing;  // the driver cancels; nothing to poll
        return std::noop_coroutine();
    }
    if (child) {
        child->parent_ = p;
        child->root_ = p->root_;
        child->state_ = ScriptState::running;
        child->waiting_ = Waiting::nothing;
        p->child_ = child;
        p->waiting_ = Waiting::child;
        return child->handle();  // runs now, on this script's clock
    }
    p->suspend_on({this, &ready, &stop});
    return std::noop_coroutine();
}

void ScriptPromise::ScriptAwaiter::await_resume() { p->rethrow_pending(); }

}  // namespace detail

// --- Script ----------------------------------------------------------------------------------

Script::Script(Script&& other) noexcept
    : handle_(std::exchange(other.handle_, {})), state_(other.state_), error_(std::move(other.error_)) {
    if (handle_) handle_.promise().owner_ = this;
}

Script& Script::operator=(Script&& other) noexcept {
    if (this != &other) {
        release();
        handle_ = std::exchange(other.handle_, {});
        state_ = other.state_;
        error_ = std::move(other.error_);
        if (handle_) handle_.promise().owner_ = this;
    }
    return *this;
}

Script::~Script() { release(); }

void Script::release() noexcept {
    if (!handle_) return;
    detail::cancel_script(&handle_.promise(), default_on_cancel());
    if (handle_) {  // deferred: the driver frees the frame once the chain is off the stack
        handle_.promise().owner_ = nullptr;
        handle_ = {};
    }
}

void Script::start(Engine& engine, ScriptDef def) {
    if (!handle_) throw Error("Script::start: the script is empty (default-constructed, moved from or ended)");
    detail::ScriptPromise& p = handle_.promise();
    if (p.state_ != detail::ScriptState::idle) throw Error("Script::start: the script is already running or has ended");
    if (!(std::isfinite(def.elapsed) && def.elapsed >= 0.0))
        throw Error("Script::start: def.elapsed must be finite and >= 0 (got " + detail::number_text(def.elapsed) + ")");
    auto link = std::make_shared<detail::ScriptLink>();
    const std::size_t id = engine.on_tick(detail::Listener{std::make_shared<detail::ListenerToken>(link), link.get()});
    link->owner = &p;  // only now: a failed on_tick must not read as the engine going away
    p.engine_ = &engine;
    p.listener_ = id;
    p.link_ = std::move(link);
    p.clock_ = {def.elapsed, 0.0};
    p.def_ = std::move(def);
    p.state_ = detail::ScriptState::running;
    detail::drive(&p);
}

std::exception_ptr Script::error() const noexcept { return handle_ ? handle_.promise().error_ : error_; }

void Script::cancel() noexcept {
    if (handle_) cancel(default_on_cancel());
}

// The started script's choice; only a running frame's root is sure to exist.
OnCancel Script::default_on_cancel() const noexcept {
    const detail::ScriptPromise& p = handle_.promise();
    return p.state_ == detail::ScriptState::running ? p.root_->def_.on_cancel : OnCancel::kill_awaited;
}

void Script::cancel(OnCancel what) noexcept {
    if (handle_) detail::cancel_script(&handle_.promise(), what);
}

}  // namespace grape
