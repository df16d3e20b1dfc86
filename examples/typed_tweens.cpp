// Typed tweens: a colour mixed in linear light, an angle the short way round, a relative
// move queued after a delay, and sprites in a growing std::vector linked by element so their
// animations follow them when the vector reallocates and stop when they are removed.
#include <grape/anim.hpp>
#include <grape/color.hpp>
#include <grape/timeline.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

struct Sprite {
    double x = 0, y = 0;
    double angle = 3.0;  // radians
    grape::Color tint = grape::parse_color("#ff0000");
};

int main() {
    grape::Engine engine;
    Sprite hero;
    engine.animate(hero, &Sprite::tint, grape::to(grape::parse_color("#00ff00")), 1.0);  // from its current red
    engine.animate(hero, &Sprite::angle, grape::to(-3.0), 1.0, {}, grape::AngleLerp{});  // through ±π, 0.28 rad
    engine.animate(hero, &Sprite::x, grape::by(100.0), 0.5, {.delay = 1.0});              // then 100 px right
    grape::Timeline hop = engine.create_timeline();  // a hop: up 40, then down by 40 from where it is then
    hop.add(engine.animate(hero, &Sprite::y, grape::by(-40.0), 0.25))
        .add(engine.animate(hero, &Sprite::y, grape::by(40.0), 0.25), ">");

    auto boss = std::make_shared<Sprite>();
    engine.create_2d_animation(boss, grape::LinearPath({0, 0}, {0, 300}), 2.0);  // keeps a weak_ptr
    boss.reset();                                                               // stops cleanly

    std::vector<Sprite> crowd(2);
    engine.create_2d_animation(grape::element(crowd, 1), grape::LinearPath({0, 0}, {50, 0}), 1.0);
    crowd.resize(1000);  // reallocates: the animation writes to crowd[1] where it is now

    for (int frame = 0; frame < 90; ++frame) engine.tick(1.0 / 60.0);
    hop.kill();  // a finished timeline stays (to be replayed or reversed) until killed, with its children
    std::printf("tint %s, angle %.4f, x %.1f, y %.1f, crowd[1].x %.1f, animations left %zu\n",
                grape::to_hex(hero.tint).c_str(), hero.angle, hero.x, hero.y, crowd[1].x, engine.size());
    const bool ok = grape::to_hex(hero.tint) == "#00ff00" && std::abs(hero.angle - (2 * grape::pi - 3.0)) < 1e-12 &&
                    std::abs(hero.x - 100.0) < 1e-9 && hero.y == 0.0 && crowd[1].x == 50.0 && engine.size() == 0;
    return ok ? 0 : 1;
}
