// Key state from the event loop, and each colliding pair handled once per frame.
#include <grape/bits.hpp>

#include <cstdio>

int main() {
    grape::KeyState keys;  // SDL scancodes fit: 0 … 511
    const std::size_t ctrl = 224, s = 22;
    const grape::BitVector save = keys.mask({ctrl, s});
    keys.press(ctrl);
    keys.press(s);
    if (keys.all_down(save) && keys.pressed_this_frame(s)) std::puts("save!");
    keys.end_frame();

    grape::PairBits handled(100);  // 4,950 bits for 100 objects
    int collisions = 0;
    for (auto [a, b] : {std::pair{3, 7}, std::pair{7, 3}, std::pair{3, 9}}) {
        if (!handled.test_and_set(a, b)) ++collisions;  // {3,7} and {7,3} are one pair
    }
    std::printf("%d pairs handled, %zu bits set\n", collisions, handled.bits().count());
    return collisions == 2 ? 0 : 1;
}
