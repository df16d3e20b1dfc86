#include <grape/error.hpp>
#include <grape/sprite.hpp>

#include "math/number_text.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace grape {
namespace {

// As a stream writes it (six significant digits), but in every locale.
std::string number(double x) { return detail::general_text(x, 6); }

// Frame counts up to 2^30 keep 2n − 2 in the 32-bit position (sums are formed in 64 bits).
constexpr std::size_t max_frame_count = std::size_t{1} << 30;

}  // namespace

namespace detail {

// A slot whose function can be replaced (or removed) by the function itself while it runs:
// the running copy is moved out first and put back only if nobody assigned the slot meanwhile.
// Named, not anonymous: SpritePlayer::Callbacks holds it, and in a unity build a member whose
// type has internal linkage is a -Wsubobject-linkage warning.
template <class F>
struct CallbackSlot {
    F fn;
    std::uint64_t generation = 0;

    void assign(F f) {
        fn = std::move(f);
        ++generation;
    }
    template <class... Args>
    void fire(Args... args) {
        if (!fn) return;
        F running = std::move(fn);
        fn = nullptr;
        const std::uint64_t before = generation;
        running(args...);
        if (generation == before) fn = std::move(running);
    }
};

}  // namespace detail

struct SpritePlayer::Callbacks {
    Playable* playable = nullptr;
    detail::CallbackSlot<FrameCallback> frame;
    detail::CallbackSlot<CompleteCallback> complete;
    detail::CallbackSlot<LoopCallback> loop;
    std::size_t cycles_done = 0;  // since `loop` was set
};

Playable* SpritePlayer::playable_ptr() const noexcept {
    return has_callbacks() ? callbacks_block()->playable : reinterpret_cast<Playable*>(link_);
}

Playable* SpritePlayer::playable() const noexcept { return playable_ptr(); }

void SpritePlayer::set_shown(Playable* playable) noexcept {
    if (has_callbacks()) {
        callbacks_block()->playable = playable;
    } else {
        link_ = reinterpret_cast<std::uintptr_t>(playable);
    }
}

// Deletes the callbacks, keeping the playable in link_.
void SpritePlayer::release_callbacks() noexcept {
    if (!has_callbacks()) return;
    Callbacks* cb = callbacks_block();
    link_ = reinterpret_cast<std::uintptr_t>(cb->playable);
    delete cb;
}

SpritePlayer::SpritePlayer(Playable& playable, const SpritePlayerDef& def) {
    const std::size_t n = playable.frame_count();
    if (n == 0) throw Error("SpritePlayer: playable has no frames (frame_count() is 0)");
    link_ = reinterpret_cast<std::uintptr_t>(&playable);
    init(n, def);
    playable.show_frame(frame());
}

SpritePlayer::SpritePlayer(std::size_t frame_count, const SpritePlayerDef& def) {
    if (frame_count == 0) throw Error("SpritePlayer: frame_count must be at least 1 (got 0)");
    init(frame_count, def);
}

SpritePlayer::SpritePlayer(const SpritePlayer& other)
    : position_(other.position_), frame_count_(other.frame_count_), whole_(other.whole_), mode_(other.mode_),
      playing_(other.playing_), finished_(other.finished_), plain_(other.plain_), fraction_(other.fraction_),
      remainder_(other.remainder_), link_(other.link_) {
    if (other.has_callbacks()) link_ = reinterpret_cast<std::uintptr_t>(new Callbacks(*other.callbacks_block())) | 1u;
}

// The moved-from player keeps its playable and loses its callbacks (as a moved-from
// unique_ptr would).
SpritePlayer::SpritePlayer(SpritePlayer&& other) noexcept
    : position_(other.position_), frame_count_(other.frame_count_), whole_(other.whole_), mode_(other.mode_),
      playing_(other.playing_), finished_(other.finished_), plain_(other.plain_), fraction_(other.fraction_),
      remainder_(other.remainder_), link_(other.link_) {
    if (other.has_callbacks()) {
        other.link_ = reinterpret_cast<std::uintptr_t>(callbacks_block()->playable);
        other.refresh();
    }
}

SpritePlayer& SpritePlayer::operator=(SpritePlayer&& other) noexcept {
    if (this != &other) {
        release_callbacks();
        position_ = other.position_;
        frame_count_ = other.frame_count_;
        whole_ = other.whole_;
        mode_ = other.mode_;
        playing_ = other.playing_;
        finished_ = other.finished_;
        plain_ = other.plain_;
        fraction_ = other.fraction_;
        remainder_ = other.remainder_;
        link_ = other.link_;
        if (other.has_callbacks()) {
            other.link_ = reinterpret_cast<std::uintptr_t>(callbacks_block()->playable);
            other.refresh();
        }
    }
    return *this;
}

SpritePlayer& SpritePlayer::operator=(const SpritePlayer& other) {
    if (this != &other) {
        SpritePlayer copy(other);
        *this = std::move(copy);
    }
    return *this;
}

SpritePlayer::~SpritePlayer() { release_callbacks(); }

void SpritePlayer::init(std::size_t frame_count, const SpritePlayerDef& def) {
    if (frame_count > max_frame_count) {
        throw Error("SpritePlayer: frame_count " + std::to_string(frame_count) + " is too large (max 2^30)");
    }
    if (def.start_frame >= frame_count) {
        throw Error("SpritePlayer: start_frame " + std::to_string(def.start_frame) +
                    " is past the last frame (frame_count " + std::to_string(frame_count) + ")");
    }
    frame_count_ = static_cast<std::int32_t>(frame_count);
    mode_ = def.mode;
    refresh();
    set_rate(def.rate);
    position_ = static_cast<std::int32_t>(def.start_frame);
}

std::int64_t SpritePlayer::period() const noexcept {
    const std::int64_t n = frame_count_;
    if (mode_ != PlayMode::ping_pong) return n;
    return n > 1 ? 2 * n - 2 : 1;
}

std::size_t SpritePlayer::frame_at(std::int64_t position) const noexcept {
    // The ping-pong cycle 0 … n−1 … 1 folds back onto the frames.
    if (mode_ == PlayMode::ping_pong && position >= frame_count_) position = 2 * std::int64_t{frame_count_} - 2 - position;
    return static_cast<std::size_t>(position);
}

std::size_t SpritePlayer::frame() const noexcept { return frame_at(position_); }

void SpritePlayer::set_rate(double rate) {
    if (!std::isfinite(rate)) throw Error("SpritePlayer: rate must be finite (got " + number(rate) + ")");
    // |rate| < n keeps every step's move within one frame range, so a single wrap suffices.
    const double cap = std::nextafter(static_cast<double>(frame_count_), 0.0);
    if (rate > cap) rate = cap;
    if (rate < -cap) rate = -cap;
    set_rate_parts(rate);
}

void SpritePlayer::set_rate_parts(double rate) noexcept {
    const double whole = std::trunc(rate);
    whole_ = static_cast<std::int32_t>(whole);
    fraction_ = rate - whole;  // exact: it only clears the integer bits of rate; whole + fraction == rate
}

void SpritePlayer::set_mode(PlayMode mode) noexcept {
    const std::size_t shown = frame();
    mode_ = mode;
    refresh();
    position_ = static_cast<std::int32_t>(shown);
}

void SpritePlayer::set_frame(std::size_t k) {
    if (k >= frame_count()) {
        throw Error("SpritePlayer::set_frame: k " + std::to_string(k) + " is past the last frame (frame_count " +
                    std::to_string(frame_count_) + ")");
    }
    const std::size_t shown = frame();
    position_ = static_cast<std::int32_t>(k);
    remainder_ = 0.0;
    finished_ = false;
    if (Playable* p = playable_ptr(); p && shown != k) p->show_frame(k);
}

void SpritePlayer::play() noexcept {
    if (finished_) {
        finished_ = false;
        remainder_ = 0.0;
        const std::size_t shown = frame();
        position_ = rate() < 0.0 ? frame_count_ - 1 : 0;
        if (Playable* p = playable_ptr(); p && shown != frame()) p->show_frame(frame());
    }
    playing_ = true;
    refresh();
}

void SpritePlayer::set_playable(Playable& playable) {
    const std::size_t n = playable.frame_count();
    if (n == 0) throw Error("SpritePlayer::set_playable: playable has no frames (frame_count() is 0)");
    if (n > max_frame_count) {
        throw Error("SpritePlayer::set_playable: frame_count " + std::to_string(n) + " is too large (max 2^30)");
    }
    const std::size_t shown = frame() < n ? frame() : n - 1;
    set_shown(&playable);
    frame_count_ = static_cast<std::int32_t>(n);
    position_ = static_cast<std::int32_t>(shown);
    set_rate(rate());  // re-apply the cap for the new frame count
    playable.show_frame(shown);
}

SpritePlayer::Callbacks& SpritePlayer::callbacks() {
    if (!has_callbacks()) {
        auto* cb = new Callbacks;
        cb->playable = reinterpret_cast<Playable*>(link_);
        link_ = reinterpret_cast<std::uintptr_t>(cb) | 1u;
    }
    plain_ = false;  // the general step reports to them
    return *callbacks_block();
}

void SpritePlayer::on_frame(FrameCallback callback) { callbacks().frame.assign(std::move(callback)); }
void SpritePlayer::on_complete(CompleteCallback callback) { callbacks().complete.assign(std::move(callback)); }
void SpritePlayer::on_loop(LoopCallback callback) {
    Callbacks& cb = callbacks();
    cb.loop.assign(std::move(callback));
    cb.cycles_done = 0;
}

void SpritePlayer::on_loop(std::function<void(std::size_t cycle)> callback) {
    if (!callback) return on_loop(LoopCallback{});
    on_loop(LoopCallback([f = std::move(callback)](std::size_t cycle, std::size_t) { f(cycle); }));
}

// The seed's step: take the integer part of the rate, accumulate the fraction, carry ±1 when
// the remainder reaches ±1. Additions and comparisons only; the carry and the wrap are
// computed without branches because with many players at different rates they are
// unpredictable (a mispredicted branch costs more than the whole step). The looping case
// without callbacks is inline in the header; this is every other case.
void SpritePlayer::advance_general() noexcept {
    if (!playing_) return;
    const double r = remainder_ + fraction_;  // in (−2, 2)
    const int carry = static_cast<int>(r >= 1.0) - static_cast<int>(r <= -1.0);
    remainder_ = r - static_cast<double>(carry);  // exact: r ∓ 1 for r in [1, 2) or (−2, −1] is exact (Sterbenz)
    const std::int64_t delta = std::int64_t{whole_} + carry;
    move_by(delta, 0, delta >= 0 ? 1 : -1);
}

void SpritePlayer::advance(double dt, double fps) {
    if (!(std::isfinite(dt) && dt >= 0.0)) {
        throw Error("SpritePlayer::advance: dt must be finite and >= 0 seconds (got " + number(dt) + ")");
    }
    if (!(std::isfinite(fps) && fps > 0.0)) {
        throw Error("SpritePlayer::advance: fps must be finite and > 0 (got " + number(fps) + ")");
    }
    const double frames = rate() * fps * dt;
    if (!std::isfinite(frames)) {
        throw Error("SpritePlayer::advance: rate*fps*dt overflows (rate " + number(rate()) + ", fps " + number(fps) +
                    ", dt " + number(dt) + ")");
    }
    if (!playing_) return;
    // trunc through a 64-bit conversion (one instruction) when it fits, the libm call otherwise.
    const double whole = std::fabs(frames) < 0x1p62 ? static_cast<double>(static_cast<std::int64_t>(frames))
                                                    : std::trunc(frames);
    // The same bookkeeping as advance(): exact fraction, branch-free carry at ±1.
    const double r = remainder_ + (frames - whole);
    const int carry = static_cast<int>(r >= 1.0) - static_cast<int>(r <= -1.0);
    remainder_ = r - static_cast<double>(carry);
    const double total = whole + static_cast<double>(carry);
    // The direction of travel comes from the move itself: after whole cycles are dropped the
    // rest may be 0 (a backward move by exactly two cycles), which has no sign of its own.
    const std::int64_t direction = total >= 0.0 ? 1 : -1;
    const double p = static_cast<double>(period());
    if (std::fabs(total) <= p) {
        move_by(static_cast<std::int64_t>(total), 0, direction);
    } else if (mode_ == PlayMode::once) {
        move_by(total > 0.0 ? std::int64_t{frame_count_} : -std::int64_t{frame_count_}, 0, direction);  // past the end either way
    } else {
        // A long time step: whole cycles are dropped (fmod is exact) and counted for on_loop.
        const double cycles = std::trunc(std::fabs(total) / p);
        const double rest = std::fmod(total, p);
        const auto extra = cycles >= static_cast<double>(std::numeric_limits<std::size_t>::max() / 2)
                               ? std::numeric_limits<std::size_t>::max() / 2
                               : static_cast<std::size_t>(cycles);
        move_by(static_cast<std::int64_t>(rest), extra, direction);
    }
}

// Moves by delta positions (|delta| ≤ period, so one wrap suffices) and reports what happened;
// `direction` (±1) is the sign of the whole move, whole cycles included.
void SpritePlayer::move_by(std::int64_t delta, std::size_t extra_cycles, std::int64_t direction) noexcept {
    const std::int64_t from = position_;
    std::int64_t next = position_ + delta;
    if (mode_ == PlayMode::once) {
        bool done = false;
        if (next >= frame_count_) {
            next = frame_count_ - 1;
            done = true;
        } else if (next < 0) {
            next = 0;
            done = true;
        }
        const std::int64_t steps = next >= from ? next - from : from - next;
        position_ = static_cast<std::int32_t>(next);
        if (done) {
            playing_ = false;
            plain_ = false;
            finished_ = true;
            remainder_ = 0.0;
        }
        if (Playable* p = playable_ptr(); p && frame_at(next) != frame_at(from)) p->show_frame(frame_at(next));
        if (has_callbacks()) report(next, steps, direction, 0, done);
        return;
    }
    const std::int64_t p = period();
    const bool under = next < 0;
    const bool over = next >= p;
    next += (p & -static_cast<std::int64_t>(under)) - (p & -static_cast<std::int64_t>(over));
    const std::size_t cycles = extra_cycles + static_cast<std::size_t>(under || over);
    position_ = static_cast<std::int32_t>(next);
    if (Playable* p = playable_ptr(); p && frame_at(next) != frame_at(from)) p->show_frame(frame_at(next));
    if (has_callbacks()) {
        const std::int64_t moved = delta >= 0 ? delta : -delta;
        report(next, extra_cycles > 0 || moved > p ? p : moved, direction, cycles, false);
    }
}

void SpritePlayer::report(std::int64_t target, std::int64_t steps, std::int64_t direction, std::size_t cycles,
                          bool completed) noexcept {
    Callbacks& cb = *callbacks_block();
    if (cb.frame.fn && steps > 0) {
        // The positions entered, in order of travel: target − direction·(steps − 1) … target.
        const std::int64_t p = mode_ == PlayMode::once ? frame_count_ : period();
        for (std::int64_t k = steps - 1; k >= 0; --k) {
            std::int64_t q = target - direction * k;
            if (q < 0) {
                q += p;
            } else if (q >= p) {
                q -= p;
            }
            cb.frame.fire(frame_at(q));
        }
    }
    if (cycles > 0) {
        const std::size_t room = std::numeric_limits<std::size_t>::max() - cb.cycles_done;
        cb.cycles_done += cycles < room ? cycles : room;
        cb.loop.fire(cb.cycles_done, cycles - 1);
    }
    if (completed) cb.complete.fire();
}

}  // namespace grape
