// A timeline: a card slides in, its title drops in a quarter second later, a callback plays
// a sound at a label, and the card wobbles after the title; the whole runs twice, the second
// time backwards (yoyo). Seeking to a label jumps there with no callbacks.
#include <grape/timeline.hpp>

#include <cstdio>

struct Item {
    double x = 0, y = 0;
};

int main() {
    grape::Engine engine;
    Item card, title;
    const grape::LinearPath slide_in({-200, 100}, {100, 100});
    const grape::LinearPath drop({100, 0}, {100, 60});
    const grape::LinearPath wobble({100, 100}, {110, 100});
    int dings = 0;

    grape::Timeline intro = engine.create_timeline({.repeat = 1, .yoyo = true});
    intro.add(engine.create_2d_animation(card, slide_in, 1.0, {.curve = grape::Curve::quad_out()}))  // 0 – 1
        .label("shown")                                                                             // 1
        .add(engine.create_2d_animation(title, drop, 0.5), "<+0.25")  // 0.25 – 0.75, with the slide
        .call([&] { ++dings; }, "shown+0.25")                         // 1.25
        .add(engine.create_2d_animation(card, wobble, 0.3, {.repeat = 1, .yoyo = true}), ">");  // 0.75 – 1.35
    intro.on_complete([] { std::puts("intro done"); });

    for (int frame = 0; frame < 3 * 60; ++frame) engine.tick(1.0 / 60.0);  // 2.7 s: two plays
    std::printf("card at (%.1f, %.1f), title at (%.1f, %.1f), %d dings\n", card.x, card.y, title.x, title.y, dings);
    intro.seek("shown");  // to the label in the first play (the wobble is under way): no callback fires
    std::printf("at 'shown': card at (%.1f, %.1f)\n", card.x, card.y);
    return dings == 2 ? 0 : 1;  // once each way
}
