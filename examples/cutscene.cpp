// A cut-scene as straight-line code: the hero walks in, waits, the door opens, five sparkles
// burst in a stagger from the center, and the hero bows (a nested script). The engine's tick
// drives the script; cancelling it (or destroying it) would stop it where it waits.
#include <grape/script.hpp>
#include <grape/stagger.hpp>

#include <cstdio>
#include <vector>

struct Sprite {
    double x = 0, y = 0;
};

struct Door {
    double angle = 0;
};

grape::Script bow(grape::Engine& engine, Sprite& hero) {
    const grape::LinearPath down({hero.x, hero.y}, {hero.x, hero.y + 10});
    co_await engine.create_2d_animation(hero, down, 0.25, {.repeat = 1, .yoyo = true});
    std::puts("the hero bows");
}

grape::Script intro(grape::Engine& engine, Sprite& hero, Door& door, std::vector<Sprite>& sparkles, const int& frame) {
    const grape::LinearPath walk({-50, 100}, {200, 100});
    co_await engine.create_2d_animation(hero, walk, 2.0, {.curve = grape::Curve::quad_out()});
    std::printf("frame %d: the hero arrives\n", frame);

    co_await grape::wait(0.5);
    engine.create_property_animation(door, {&Door::angle}, {0.0}, {90.0}, 1.0);
    co_await grape::until([&] { return door.angle >= 45.0; });  // half open is enough
    std::printf("frame %d: the door is half open\n", frame);

    const std::vector<grape::Animation> bursts =
        grape::stagger(sparkles.size(), {.each = 0.1, .from = grape::StaggerFrom::center}, [&](std::size_t i, double delay) {
            const grape::LinearPath up({200.0 + 10.0 * static_cast<double>(i), 100}, {200.0 + 10.0 * static_cast<double>(i), 40});
            return engine.create_2d_animation(sparkles[i], up, 0.5, {.delay = delay});
        });
    for (const grape::Animation& b : bursts) co_await b;  // all of them
    std::printf("frame %d: the sparkles are up\n", frame);

    co_await bow(engine, hero);
}

int main() {
    grape::Engine engine;
    Sprite hero;
    Door door;
    std::vector<Sprite> sparkles(5);
    int frame = 0;

    grape::Script scene = intro(engine, hero, door, sparkles, frame);
    scene.start(engine);
    for (; frame < 6 * 60 && scene.alive(); ++frame) engine.tick(1.0 / 60.0);

    std::printf("frame %d: done %s, hero at (%.1f, %.1f)\n", frame, scene.done() ? "yes" : "no", hero.x, hero.y);
    return scene.done() ? 0 : 1;
}
