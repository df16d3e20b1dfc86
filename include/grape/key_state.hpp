// grape — which keys are down, their edges and repeats, as bits indexed by key code.
#pragma once

#include <grape/bits.hpp>
#include <grape/export_bits.hpp>

#include <concepts>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace grape {

/// \addtogroup bits
/// @{

/// A type usable as a key code: any integer type but bool, or any enumeration (plain enums
/// such as SDL_Scancode, integer typedefs such as SDL_Keycode, scoped `enum class` keys).
template <class K>
concept KeyCode = (std::integral<K> && !std::same_as<std::remove_cv_t<K>, bool>) || std::is_enum_v<K>;

namespace detail {
/// The key's value as an index, or BitVector::npos when it is negative or beyond std::size_t.
template <KeyCode K>
constexpr std::size_t key_index(K key) noexcept {
    if constexpr (std::is_enum_v<K>) {
        return key_index(static_cast<std::underlying_type_t<K>>(key));
    } else {
        if constexpr (std::is_signed_v<K>) {
            if (key < 0) return BitVector::npos;
        }
        const auto value = static_cast<unsigned long long>(key);
        if constexpr (sizeof(unsigned long long) > sizeof(std::size_t)) {
            if (value > (std::numeric_limits<std::size_t>::max)()) return BitVector::npos;
        }
        return static_cast<std::size_t>(value);
    }
}
/// The key's value as decimal text, for error messages.
template <KeyCode K>
std::string key_text(K key) {
    if constexpr (std::is_enum_v<K>) {
        return key_text(static_cast<std::underlying_type_t<K>>(key));
    } else if constexpr (std::is_signed_v<K>) {
        return std::to_string(static_cast<long long>(key));
    } else {
        return std::to_string(static_cast<unsigned long long>(key));
    }
}
}  // namespace detail

/// How a held key repeats (KeyState): the first repeat `delay` seconds after the press, then
/// one every `interval` seconds while the key stays down. The defaults are typical desktop
/// settings (X11 and Windows ship 0.25–0.66 s and 25–33 repeats per second).
struct KeyRepeatDef {
    double delay = 0.5;          ///< seconds from the press to the first repeat (finite, > 0)
    double interval = 1.0 / 30;  ///< seconds between repeats (finite, > 0)
};

/// Which keys are down, as bits indexed by key code, with the edges since the last
/// end_frame(). Feed it from the event loop (press/release), query it from game logic,
/// and call end_frame() once per frame after the logic ran. A tap that presses and releases
/// within one frame still reports pressed_this_frame and released_this_frame.
///
/// Key repeat, reported as SDL reports repeated SDL_KEYDOWN events and raylib
/// IsKeyPressedRepeat(): the state keeps a clock, which starts at 0 and which end_frame(dt)
/// moves on by dt seconds; events fed during a frame happen at the clock's current time T.
/// A key pressed at time t0 repeats at t0 + delay + k·interval (k = 0, 1, 2, …) for as long
/// as it is down. end_frame(dt) gathers the repeats due in (T, T + dt] of the keys down at that
/// call, and the frame that follows reports them: repeated_this_frame(key), with
/// repeat_count(key) of them (several when a frame is longer than the interval, as SDL would
/// queue several events), listed by repeated_keys(). A key released in that frame still
/// reports the repeats that fell due before (the release is stamped at the end of the span).
/// The press itself is never a repeat, and a press of a key already down (an OS repeat)
/// changes nothing. Times are compared as the doubles given: with dyadic times (1/64, 0.5, …)
/// the reports are exact.
class GRAPE_BITS_API KeyState {
public:
    /// Codes 0 … key_count − 1 are tracked; 512 fits every SDL scancode (SDL_NUM_SCANCODES).
    static constexpr std::size_t default_key_count = 512;

    /// Tracks key codes below `key_count` (throws grape::Error when key_count is 0 or the
    /// repeat times are not finite and positive).
    explicit KeyState(std::size_t key_count = default_key_count, KeyRepeatDef repeat = {});

    /// One more than the largest key code tracked.
    std::size_t key_count() const noexcept { return down_.size(); }
    /// The repeat delay and interval.
    const KeyRepeatDef& repeat() const noexcept { return repeat_; }
    /// The clock, in seconds: the sum of the dt given to end_frame().
    double time() const noexcept { return time_; }

    /// Marks the key down at time() (a press of a key already down is not a new press);
    /// throws grape::Error when the key is negative or >= key_count().
    template <KeyCode K>
    void press(K key) { press_index(checked_index(key, "press")); }
    /// Marks the key up; throws grape::Error when the key is negative or >= key_count().
    template <KeyCode K>
    void release(K key) { release_index(checked_index(key, "release")); }
    /// Releases every key (e.g. when the window loses focus), recording the edges.
    void release_all() noexcept;

    /// The key is down now (false for codes outside the range).
    template <KeyCode K>
    bool is_down(K key) const noexcept { return test(down_, detail::key_index(key)); }
    /// The key went down since the last end_frame() (false for codes outside the range).
    template <KeyCode K>
    bool pressed_this_frame(K key) const noexcept { return test(pressed_, detail::key_index(key)); }
    /// The key went up since the last end_frame() (false for codes outside the range).
    template <KeyCode K>
    bool released_this_frame(K key) const noexcept { return test(released_, detail::key_index(key)); }
    /// At least one repeat of the held key fell due in the span the last end_frame(dt) covered.
    template <KeyCode K>
    bool repeated_this_frame(K key) const noexcept { return test(repeated_, detail::key_index(key)); }
    /// pressed_this_frame or repeated_this_frame: what text fields and menus act on.
    template <KeyCode K>
    bool pressed_or_repeated(K key) const noexcept { return pressed_this_frame(key) || repeated_this_frame(key); }
    /// How many repeats of the key fell due in that span (0 if none).
    template <KeyCode K>
    std::size_t repeat_count(K key) const noexcept { return repeat_count_index(detail::key_index(key)); }

    /// The keys that went down since the last end_frame(), each once, in the order of their
    /// first press (kept as they happen: no scan over the key codes).
    std::span<const std::size_t> pressed_keys() const noexcept { return pressed_list_; }
    /// The keys that went up since the last end_frame(), each once, in order.
    std::span<const std::size_t> released_keys() const noexcept { return released_list_; }
    /// The keys with repeats in this frame, each once, in the order they were pressed.
    std::span<const std::size_t> repeated_keys() const noexcept { return repeated_list_; }

    /// Forgets this frame's edges and repeats; the keys held stay down; the clock stays.
    void end_frame() noexcept;
    /// Forgets this frame's edges, moves the clock on by dt seconds and gathers the repeats
    /// due in (time(), time() + dt] for the next frame. Throws grape::Error when dt is
    /// negative or not finite. Work: this frame's events plus the keys held.
    void end_frame(double dt);

    /// A mask for a key combination, sized for this state: `mask({ctrl, s})` with keys of any
    /// one KeyCode type; throws grape::Error for a key that is negative or >= key_count().
    template <KeyCode K>
    BitVector mask(std::initializer_list<K> keys) const {
        BitVector m(down_.size());
        for (const K key : keys) m.set(checked_index(key, "mask"));
        return m;
    }
    /// The empty combination (`mask({})`), or keys given as std::size_t.
    BitVector mask(std::initializer_list<std::size_t> keys) const { return mask<std::size_t>(keys); }
    /// A mask from keys of mixed KeyCode types: `mask(SDL_SCANCODE_LCTRL, 22)`.
    template <KeyCode... K>
        requires(sizeof...(K) > 0)
    BitVector mask(K... keys) const {
        BitVector m(down_.size());
        (m.set(checked_index(keys, "mask")), ...);
        return m;
    }
    /// Every key of the mask is down (true for an empty mask); throws grape::Error when the
    /// mask's size is not key_count().
    bool all_down(const BitVector& mask) const { return mask.is_subset_of(down_); }
    /// Some key of the mask is down; throws grape::Error when the mask's size is not key_count().
    bool any_down(const BitVector& mask) const { return mask.intersects(down_); }
    /// The keys down now.
    const BitVector& down() const noexcept { return down_; }

private:
    struct Held {
        std::size_t key;
        double since;  // clock time of the press
    };
    static bool test(const BitVector& bits, std::size_t i) noexcept { return i < bits.size() && bits.get(i); }
    template <KeyCode K>
    std::size_t checked_index(K key, const char* operation) const {
        const std::size_t i = detail::key_index(key);
        if (i >= down_.size()) key_out_of_range(detail::key_text(key), operation);
        return i;
    }
    [[noreturn]] void key_out_of_range(const std::string& key, const char* operation) const;
    void press_index(std::size_t key);
    void release_index(std::size_t key);
    std::size_t repeat_count_index(std::size_t key) const noexcept;
    void clear_frame() noexcept;

    KeyRepeatDef repeat_;
    double time_ = 0.0;
    BitVector down_;
    BitVector pressed_;
    BitVector released_;
    BitVector repeated_;
    std::vector<std::size_t> pressed_list_;
    std::vector<std::size_t> released_list_;
    std::vector<std::size_t> repeated_list_;
    std::vector<std::size_t> repeat_counts_;  // parallel to repeated_list_
    std::vector<Held> held_;                  // the keys down, in the order they were pressed
};

/// @}

}  // namespace grape
