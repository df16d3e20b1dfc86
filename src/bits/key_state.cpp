#include <grape/bits.hpp>
#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace grape {
namespace {

void check_repeat_time(double seconds, const char* name) {
    if (!std::isfinite(seconds) || seconds <= 0) {
        throw Error(std::string("KeyState: repeat.") + name + " must be a finite number of seconds > 0 (got " +
                    detail::number_text(seconds) + ")");
    }
}

// Repeats of a key pressed at `since` that fall due at or before time t: t0 + delay + k·interval
// <= t for k = 0 … count − 1. Capped at 2^52 so the conversion is exact and a huge gap cannot
// overflow.
std::size_t repeats_until(double t, double since, const KeyRepeatDef& r) noexcept {
    const double from_first = t - (since + r.delay);
    if (!(from_first >= 0)) return 0;
    return static_cast<std::size_t>(std::min(std::floor(from_first / r.interval), 4503599627370496.0)) + 1;
}

}  // namespace

KeyState::KeyState(std::size_t key_count, KeyRepeatDef repeat) : repeat_(repeat) {
    if (key_count == 0) throw Error("KeyState: key_count must be at least 1 (got 0)");
    check_repeat_time(repeat.delay, "delay");
    check_repeat_time(repeat.interval, "interval");
    down_ = BitVector(key_count);
    pressed_ = BitVector(key_count);
    released_ = BitVector(key_count);
    repeated_ = BitVector(key_count);
}

void KeyState::key_out_of_range(const std::string& key, const char* operation) const {
    throw Error(std::string("KeyState::") + operation + ": key " + key + " is out of range (key_count " +
                std::to_string(down_.size()) + ")");
}

void KeyState::press_index(std::size_t key) {
    if (down_.get(key)) return;  // a repeat of a held key is not a new press
    // Every allocation before any change. The released list keeps room for every key held,
    // so release() and release_all() never allocate.
    held_.reserve(held_.size() + 1);
    pressed_list_.reserve(pressed_list_.size() + 1);
    released_list_.reserve(released_list_.size() + held_.size() + 1);
    if (!pressed_.get(key)) {
        pressed_list_.push_back(key);
        pressed_.set(key);
    }
    down_.set(key);
    held_.push_back({key, time_});
}

void KeyState::release_index(std::size_t key) {
    if (!down_.get(key)) return;
    if (!released_.get(key)) {
        released_list_.push_back(key);
        released_.set(key);
    }
    down_.reset(key);
    held_.erase(std::find_if(held_.begin(), held_.end(), [key](const Held& h) { return h.key == key; }));
}

void KeyState::release_all() noexcept {
    for (const Held& h : held_) {
        if (!released_.get(h.key)) {
            // No allocation: press() left room for every key held.
            released_list_.push_back(h.key);
            released_.set(h.key);
        }
    }
    held_.clear();
    down_.clear_all();
}

std::size_t KeyState::repeat_count_index(std::size_t key) const noexcept {
    if (!test(repeated_, key)) return 0;
    const auto it = std::find(repeated_list_.begin(), repeated_list_.end(), key);
    return repeat_counts_[static_cast<std::size_t>(it - repeated_list_.begin())];
}

void KeyState::clear_frame() noexcept {
    for (const std::size_t key : pressed_list_) pressed_.reset(key);
    for (const std::size_t key : released_list_) released_.reset(key);
    for (const std::size_t key : repeated_list_) repeated_.reset(key);
    pressed_list_.clear();
    released_list_.clear();
    repeated_list_.clear();
    repeat_counts_.clear();
}

void KeyState::end_frame() noexcept { clear_frame(); }

void KeyState::end_frame(double dt) {
    if (!std::isfinite(dt) || dt < 0) {
        throw Error("KeyState::end_frame: dt must be a finite number of seconds >= 0 (got " + detail::number_text(dt) +
                    ")");
    }
    repeated_list_.reserve(held_.size());
    repeat_counts_.reserve(held_.size());
    clear_frame();
    const double before = time_, after = time_ + dt;
    for (const Held& h : held_) {
        const std::size_t count = repeats_until(after, h.since, repeat_) - repeats_until(before, h.since, repeat_);
        if (count == 0) continue;
        repeated_list_.push_back(h.key);
        repeat_counts_.push_back(count);
        repeated_.set(h.key);
    }
    time_ = after;
}

}  // namespace grape
