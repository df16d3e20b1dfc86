// ClipPlayer: a clip's frames with their own durations at a real rate.
//
// The playback is a sequence of steps (frames shown), numbered from the clip's start: a clip
// forever is the periodic sequence (period = its length, 2·length − 2 for ping-pong), a clip
// with a repeat count is the first `steps_` of it. The player keeps the step and the time into
// it; an advance adds rate·dt and, only when that leaves the frame, walks step by step,
// subtracting (or adding) each frame's duration, so the time left over always carries into the
// next frame. Going forwards a frame holds [0, d) of its time, going backwards (0, d]: reverse
// play is the mirror image of forward play.
#include <grape/error.hpp>
#include <grape/sprite.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace grape {
namespace {

// Frames one advance walks before whole periods are counted instead of walked: bounds the
// work of a huge time step while still reporting every frame of any normal step.
constexpr double walk_budget = 65536.0;

std::int64_t floor_div(std::int64_t a, std::int64_t n) {
    const std::int64_t q = a / n;
    return q - static_cast<std::int64_t>((a % n != 0) && ((a < 0) != (n < 0)));
}

std::int64_t floor_mod(std::int64_t a, std::int64_t n) { return a - floor_div(a, n) * n; }

void check_rate(double rate, const char* what) {
    if (!std::isfinite(rate)) {
        throw Error(std::string(what) + ": rate must be finite (got " + detail::number_text(rate) + ")");
    }
}

}  // namespace

ClipPlayer::ClipPlayer(const SpriteSheet& sheet, std::string_view clip, const ClipPlayerDef& def)
    : ClipPlayer(sheet, sheet.clip_index(clip), def) {}

ClipPlayer::ClipPlayer(const SpriteSheet& sheet, std::size_t clip, const ClipPlayerDef& def) : sheet_(&sheet) {
    check_rate(def.rate, "ClipPlayer");
    if (clip >= sheet.clips().size()) {
        throw Error("ClipPlayer: clip " + std::to_string(clip) + " is past the last clip (the sheet has " +
                    std::to_string(sheet.clips().size()) + ")");
    }
    rate_ = def.rate;
    start(clip, rate_ < 0.0);
}

void ClipPlayer::set_rate(double rate) {
    check_rate(rate, "ClipPlayer::set_rate");
    rate_ = rate;
}

void ClipPlayer::on_event(EventCallback callback) {
    callback_ = std::move(callback);
    ++callback_generation_;
}

void ClipPlayer::play(std::string_view clip, ClipSwitch when) { play(sheet_->clip_index(clip), when); }

void ClipPlayer::play(std::size_t clip, ClipSwitch when) {
    if (clip >= sheet_->clips().size()) {
        throw Error("ClipPlayer::play: clip " + std::to_string(clip) + " is past the last clip (the sheet has " +
                    std::to_string(sheet_->clips().size()) + ")");
    }
    if (when == ClipSwitch::now || finished_) {
        has_queued_ = false;
        start(clip, rate_ < 0.0);
    } else {
        queued_ = clip;
        has_queued_ = true;
    }
}

void ClipPlayer::start(std::size_t clip, bool at_end) noexcept {
    const SpriteClip& c = sheet_->clips()[clip];
    clip_ = clip;
    first_ = c.from;
    length_ = c.length();
    direction_ = c.direction;
    const auto n = static_cast<std::int64_t>(length_);
    const bool bounce = (direction_ == ClipDirection::ping_pong || direction_ == ClipDirection::ping_pong_reverse) && n > 1;
    bounce_ = bounce;
    period_ = bounce ? 2 * n - 2 : n;
    // Aseprite counts a ping-pong pass per direction; passes after the first share their
    // first frame with the previous pass's last, so they add length − 1 frames each.
    steps_ = c.repeat == 0 ? -1 : (bounce ? n + (c.repeat - 1) * (n - 1) : c.repeat * n);
    period_ms_ = 0.0;
    for (std::int64_t k = 0; k < period_; ++k) period_ms_ += sheet_->frame(frame_at(k)).duration_ms;
    fold_ms_ = period_ms_ * std::max(2.0, std::ceil(walk_budget / static_cast<double>(period_)));
    finished_ = false;
    step_ = at_end ? (steps_ > 0 ? steps_ - 1 : -1) : 0;
    period_place_ = floor_mod(step_, period_);
    frame_ = frame_in_period(period_place_);
    duration_ = sheet_->frame(frame_).duration_ms;
    time_ = at_end ? duration_ : 0.0;
}

std::size_t ClipPlayer::frame_at(std::int64_t step) const noexcept { return frame_in_period(floor_mod(step, period_)); }

std::size_t ClipPlayer::frame_in_period(std::int64_t k) const noexcept {
    const auto n = static_cast<std::int64_t>(length_);
    std::int64_t offset = 0;
    switch (direction_) {
        case ClipDirection::forward: offset = k; break;
        case ClipDirection::reverse: offset = n - 1 - k; break;
        case ClipDirection::ping_pong: offset = k < n ? k : 2 * n - 2 - k; break;
        case ClipDirection::ping_pong_reverse: offset = k < n ? n - 1 - k : k - n + 1; break;
    }
    return first_ + static_cast<std::size_t>(offset);
}

std::int64_t ClipPlayer::pass() const noexcept { return pass_of(step_); }

std::int64_t ClipPlayer::pass_of(std::int64_t step) const noexcept {
    const auto n = static_cast<std::int64_t>(length_);
    if (!bounce_) return floor_div(step, n);  // forward, reverse, or a single frame
    // Ping-pong: the first pass has n frames, every later one n − 1; before the start
    // (playing backwards from it) passes of n − 1 frames count down from −1.
    if (step >= n) return 1 + (step - n) / (n - 1);
    if (step >= 0) return 0;
    return -1 - floor_div(-step - 1, n - 1);
}

void ClipPlayer::bad_dt(double dt) {
    throw Error("ClipPlayer::advance: dt must be finite and >= 0 seconds (got " + detail::number_text(dt) + ")");
}

// The step leaves the frame (the inline advance handled the rest).
void ClipPlayer::advance_across(double delta) {
    if (!std::isfinite(time_ + delta)) {
        throw Error("ClipPlayer::advance: rate*dt overflows (rate " + detail::number_text(rate_) + ", " +
                    detail::number_text(delta) + " ms)");
    }
    time_ += delta;
    walk(delta > 0.0);
}

void ClipPlayer::emit(ClipEventKind kind, std::int64_t count) noexcept {
    if (!callback_) return;
    const ClipEvent event{.kind = kind, .frame = frame_, .clip = clip_, .pass = pass_of(step_), .count = count};
    // The callback may replace or remove itself: run a moved-out copy, put it back unless replaced.
    EventCallback running = std::move(callback_);
    callback_ = nullptr;
    const std::uint64_t before = callback_generation_;
    running(event);
    if (callback_generation_ == before) callback_ = std::move(running);
}

// Moves to an adjacent step (the one after, or before), reporting a pass boundary crossed
// and the frame entered.
void ClipPlayer::enter(std::int64_t step) noexcept {
    // The place in the period moves by one (no division); passes matter only for events.
    const bool boundary = callback_ && pass_of(step) != pass_of(step_);
    period_place_ += step > step_ ? 1 : -1;
    if (period_place_ == period_) period_place_ = 0;
    if (period_place_ < 0) period_place_ = period_ - 1;
    step_ = step;
    frame_ = frame_in_period(period_place_);
    duration_ = sheet_->frame(frame_).duration_ms;
    if (callback_) {
        if (boundary) emit(ClipEventKind::loop);
        emit(ClipEventKind::frame);
    }
}

// Takes over the queued clip where the current pass ended, keeping the time left over
// (`over` ms past the boundary, in the direction of travel).
void ClipPlayer::take_queued(bool forward, double over) noexcept {
    has_queued_ = false;
    start(queued_, !forward);
    time_ = forward ? over : duration_ - over;
    emit(ClipEventKind::switched);
    emit(ClipEventKind::frame);
}

void ClipPlayer::fold(bool forward) noexcept {
    // Whole periods past the budget are counted, not walked; a finite playback keeps at
    // least one period to walk before its end, so completion is still reached frame by frame.
    const double ahead = forward ? time_ - duration_ : -time_;
    if (!(ahead > fold_ms_) || has_queued_) return;
    double periods = std::floor(ahead / period_ms_) - 1.0;
    if (steps_ >= 0) {
        const std::int64_t room = forward ? (steps_ - 1 - step_) / period_ : step_ / period_;
        periods = std::min(periods, static_cast<double>(room - 1));
    }
    if (periods < 1.0) return;
    // The step count is bounded so step_ stays far inside int64 (2^52 frames is beyond any
    // game's run); past that (a clip forever and an absurd step) only the place in the period
    // matters, and the pass count stops there.
    const double cap = std::ldexp(1.0, 52) / static_cast<double>(period_);
    const auto c = static_cast<std::int64_t>(std::min(periods, cap));
    const std::int64_t before = pass_of(step_);
    step_ += forward ? c * period_ : -c * period_;
    if (periods <= cap) {
        time_ += forward ? -periods * period_ms_ : periods * period_ms_;
    } else {
        const double rest = std::fmod(ahead, period_ms_) + period_ms_;  // in [1, 2) periods: walked
        time_ = forward ? duration_ + rest : -rest;
    }
    const std::int64_t crossed = pass_of(step_) - before;
    emit(ClipEventKind::loop, crossed >= 0 ? crossed : -crossed);
}

void ClipPlayer::walk(bool forward) noexcept {
    fold(forward);
    if (forward) {
        while (time_ >= duration_ && playing_ && !finished_) {
            const double over = time_ - duration_;
            if (steps_ >= 0 && step_ == steps_ - 1) {  // the end of a finite playback
                if (has_queued_) {
                    take_queued(true, over);
                    continue;
                }
                time_ = duration_;
                finished_ = true;
                emit(ClipEventKind::complete);
                return;
            }
            if (has_queued_ && pass_of(step_ + 1) != pass_of(step_)) {
                take_queued(true, over);
                continue;
            }
            time_ = over;
            enter(step_ + 1);
        }
    } else {
        while (time_ <= 0.0 && playing_ && !finished_) {
            const double over = -time_;  // ms before this frame's start
            if (steps_ >= 0 && step_ == 0) {
                if (has_queued_) {
                    take_queued(false, over);
                    continue;
                }
                time_ = 0.0;
                finished_ = true;
                emit(ClipEventKind::complete);
                return;
            }
            if (has_queued_ && pass_of(step_ - 1) != pass_of(step_)) {
                take_queued(false, over);
                continue;
            }
            enter(step_ - 1);
            time_ = duration_ - over;
        }
    }
}

}  // namespace grape
