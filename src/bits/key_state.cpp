#include <grape/bits.hpp>
#include <grape/error.hpp>

#include <string>

namespace grape {

KeyState::KeyState(std::size_t key_count) {
    if (key_count == 0) throw Error("KeyState: key_count must be at least 1 (got 0)");
    down_ = BitVector(key_count);
    pressed_ = BitVector(key_count);
    released_ = BitVector(key_count);
}

void KeyState::check_key(std::size_t key, const char* operation) const {
    if (key >= down_.size()) {
        throw Error(std::string("KeyState::") + operation + ": key " + std::to_string(key) +
                    " is out of range (key_count " + std::to_string(down_.size()) + ")");
    }
}

void KeyState::press(std::size_t key) {
    check_key(key, "press");
    if (!down_.test_and_set(key)) pressed_.set(key);
}

void KeyState::release(std::size_t key) {
    check_key(key, "release");
    if (down_.get(key)) {
        down_.reset(key);
        released_.set(key);
    }
}

void KeyState::release_all() noexcept {
    released_ |= down_;  // same sizes by construction: cannot throw
    down_.clear_all();
}

void KeyState::end_frame() noexcept {
    pressed_.clear_all();
    released_.clear_all();
}

BitVector KeyState::mask(std::initializer_list<std::size_t> keys) const {
    BitVector m(down_.size());
    for (const std::size_t key : keys) {
        check_key(key, "mask");
        m.set(key);
    }
    return m;
}

}  // namespace grape
