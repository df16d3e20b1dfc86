// Key state from the event loop, and each colliding pair handled once per frame.
#include <grape/bits.hpp>

#include <cstdio>

int main() {
    grape::KeyState keys;  // SDL scancodes fit: 0 … 511
    const int ctrl = 224, s = 22;
    const grape::BitVector save = keys.mask({ctrl, s});
    keys.press(ctrl);
    keys.press(s);
    if (keys.all_down(save) && keys.pressed_this_frame(s)) std::puts("save!");
    keys.end_frame(1.0 / 64);  // each frame, with its length: held keys repeat on this clock
    int repeats = 0;
    for (int frame = 1; frame < 64; ++frame) {  // s held for a second: 0.5 s, then 30 per second
        if (keys.repeated_this_frame(s)) ++repeats;
        keys.end_frame(1.0 / 64);
    }

    grape::PairBits handled(100);  // 4,950 bits for 100 objects
    int collisions = 0;
    for (auto [a, b] : {std::pair{3, 7}, std::pair{7, 3}, std::pair{3, 9}}) {
        if (!handled.test_and_set(a, b)) ++collisions;  // {3,7} and {7,3} are one pair
    }
    for (auto [i, j] : handled.set_pairs()) std::printf("pair %zu-%zu\n", i, j);
    std::printf("%d pairs handled, %zu bits set, %d repeats of s\n", collisions, handled.bits().count(), repeats);
    return collisions == 2 && repeats == 15 ? 0 : 1;
}
