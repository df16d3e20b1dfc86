// Safe targets: kill and find an object's animations (every kind, through the target index),
// overwrite, and the linked forms stopping cleanly when their target dies or moving with it
// when a vector reallocates. Run under AddressSanitizer too (build-asan): a write through a
// dead or moved target is a heap-use-after-free there.
#include <grape/anim.hpp>
#include <grape/color.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

using grape::Animation;
using grape::Engine;
using grape::Vec2;

namespace {

struct Sprite {
    double x = 0, y = 0;
    double rotation = 0;
    double alpha = 1;
    grape::Color tint{};
};

struct Scene {
    Sprite a;
    Sprite b;
};

// A plain object whose animations die with it.
struct Enemy : grape::Animated {
    double x = 0, y = 0;
    double hp = 100;
};

const grape::LinearPath line({0, 0}, {10, 0});

}  // namespace

TEST(Targets, KillAnimationsOfFindsEveryKindAndOnlyThatObject) {
    Engine engine;
    Scene scene;
    engine.create_2d_animation(scene.a, line, 1.0);
    engine.create_property_animation(scene.a, {&Sprite::alpha}, {1.0}, {0.0}, 1.0);
    engine.animate(scene.a, &Sprite::tint, grape::to(grape::Color{1, 0, 0, 1}), 1.0);
    Animation other = engine.create_2d_animation(scene.b, line, 1.0);
    engine.animate(scene.b, &Sprite::alpha, grape::to(0.0), 1.0);
    engine.create_animation(line, 1.0);  // bound to nothing: never anyone's
    EXPECT_EQ(engine.animations_of(scene.a).size(), 3u);
    EXPECT_EQ(engine.animations_of(scene.b).size(), 2u);
    EXPECT_EQ(engine.animations_of(scene).size(), 5u);  // the members' bytes are the scene's
    EXPECT_EQ(engine.animations_of(scene.a.tint).size(), 1u);
    EXPECT_EQ(engine.kill_animations_of(scene.a), 3u);
    EXPECT_EQ(engine.size(), 3u);
    EXPECT_TRUE(other.alive());
    EXPECT_TRUE(engine.animations_of(scene.a).empty());
    // Created after the index is on: found too; killing from inside a handler is safe.
    engine.create_2d_animation(scene.a, line, 0.5).on_complete([&] { engine.kill_animations_of(scene.b); });
    engine.tick(0.5);
    EXPECT_FALSE(other.alive());
    EXPECT_EQ(engine.size(), 1u);  // the callback-only one
}

TEST(Targets, TheIndexScalesAndMatchesAScan) {
    Engine engine;
    std::vector<Sprite> sprites(2000);
    for (std::size_t i = 0; i < sprites.size(); ++i) {
        engine.create_2d_animation(sprites[i], line, 1.0 + static_cast<double>(i % 7));
        if (i % 3 == 0) engine.animate(sprites[i], &Sprite::alpha, grape::to(0.0), 1.0);
    }
    for (std::size_t i = 0; i < sprites.size(); i += 97)
        EXPECT_EQ(engine.animations_of(sprites[i]).size(), i % 3 == 0 ? 2u : 1u) << i;
    std::size_t killed = 0;
    for (std::size_t i = 0; i < sprites.size(); i += 2) killed += engine.kill_animations_of(sprites[i]);
    EXPECT_EQ(killed, 1000u + 334u);
    EXPECT_EQ(engine.size(), 2000u + 667u - killed);
    for (std::size_t i = 1; i < sprites.size(); i += 2) ASSERT_FALSE(engine.animations_of(sprites[i]).empty());
}

TEST(Targets, OverwriteKillsTheStartedAnimationsOfTheSameMembers) {
    Engine engine;
    Sprite s;
    Animation first = engine.create_2d_animation(s, line, 2.0);
    Animation fade = engine.animate(s, &Sprite::alpha, grape::to(0.0), 2.0);
    engine.tick(0.5);
    // A later move of x: kills the path animation (it writes x), leaves the fade alone.
    engine.animate(s, &Sprite::x, grape::to(-5.0), 1.0, {.overwrite = true});
    EXPECT_FALSE(first.alive());
    EXPECT_TRUE(fade.alive());
    engine.tick(1.0);
    EXPECT_EQ(s.x, -5.0);
    EXPECT_EQ(s.y, 0.0);
    // With a delay it overwrites when it starts, not before.
    Animation move = engine.create_2d_animation(s, line, 2.0);
    Animation later = engine.create_2d_animation(s, line, 1.0, {.delay = 0.5, .overwrite = true});
    engine.tick(0.25);
    EXPECT_TRUE(move.alive());
    engine.tick(0.5);
    EXPECT_FALSE(move.alive());
    EXPECT_TRUE(later.alive());
    // Without overwrite both run (the later-created one wins each tick).
    Animation p = engine.animate(s, &Sprite::alpha, grape::from_to(1.0, 0.0), 1.0);
    Animation q = engine.animate(s, &Sprite::alpha, grape::from_to(0.0, 1.0), 1.0);
    engine.tick(0.5);
    EXPECT_TRUE(p.alive() && q.alive());
    EXPECT_EQ(s.alpha, 0.5);
}

TEST(Targets, SharedPtrTargetsStopWhenTheObjectDies) {
    Engine engine;
    auto sprite = std::make_shared<Sprite>();
    Animation move = engine.create_2d_animation(sprite, line, 1.0);
    Animation tint = engine.animate(sprite, &Sprite::tint, grape::to(grape::Color{0, 0, 1, 1}), 1.0);
    bool completed = false;
    move.on_complete([&] { completed = true; });
    engine.tick(0.5);
    EXPECT_DOUBLE_EQ(sprite->x, 5.0);
    EXPECT_EQ(engine.animations_of(sprite).size(), 2u);
    sprite.reset();  // the engine kept only a weak_ptr
    engine.tick(0.25);  // ASan: no write to the freed sprite
    EXPECT_FALSE(move.alive());
    EXPECT_FALSE(tint.alive());
    EXPECT_FALSE(completed);  // stopped, not completed
    EXPECT_EQ(engine.size(), 0u);
}

TEST(Targets, AnAnimatedBaseOrALinkEndsTheAnimationsWithTheObject) {
    Engine engine;
    auto enemy = std::make_unique<Enemy>();
    Animation walk = engine.create_2d_animation(*enemy, line, 1.0);  // linked through the base
    Animation hurt = engine.animate(*enemy, &Enemy::hp, grape::to(0.0), 1.0);
    engine.tick(0.5);
    EXPECT_DOUBLE_EQ(enemy->x, 5.0);
    {
        const Enemy copy = *enemy;  // a copy has a token of its own: destroying it ends nothing
    }
    engine.tick(0.1);
    EXPECT_TRUE(walk.alive());
    enemy.reset();
    engine.tick(0.1);  // ASan: nothing written to the freed enemy
    EXPECT_FALSE(walk.alive());
    EXPECT_FALSE(hurt.alive());

    struct Plain {
        double x = 0, y = 0;
        grape::AnimationLink link;
    };
    auto plain = std::make_unique<Plain>();
    Animation a = engine.create_2d_animation(grape::linked(*plain, plain->link), line, 1.0);
    Animation s = engine.animate(grape::linked(*plain, plain->link), &Plain::x, grape::to(3.0), 1.0);
    engine.tick(0.2);
    plain.reset();
    a.seek(0.5);  // a seek after the target went stops it the same way
    EXPECT_FALSE(a.alive());
    engine.tick(0.1);
    EXPECT_FALSE(s.alive());
}

TEST(Targets, VectorElementsSurviveReallocation) {
    Engine engine;
    std::vector<Sprite> sprites(4);
    sprites.shrink_to_fit();
    Animation a = engine.create_2d_animation(grape::element(sprites, 2), line, 1.0);
    Animation t = engine.animate(grape::element(sprites, 3), &Sprite::alpha, grape::from_to(1.0, 0.0), 1.0);
    engine.tick(0.25);
    const Sprite* before = sprites.data();
    for (int k = 0; k < 100; ++k) sprites.push_back({});  // reallocates: the old storage is freed
    ASSERT_NE(sprites.data(), before);
    // Found where it is now, before any tick has followed it.
    EXPECT_EQ(engine.animations_of(sprites[2]).size(), 1u);
    engine.tick(0.25);  // ASan: writes go to the new storage
    EXPECT_DOUBLE_EQ(sprites[2].x, 5.0);
    EXPECT_DOUBLE_EQ(sprites[3].alpha, 0.5);
    sprites.resize(3);  // index 3 is gone: that animation stops
    engine.tick(0.25);
    EXPECT_FALSE(t.alive());
    EXPECT_TRUE(a.alive());
    EXPECT_DOUBLE_EQ(sprites[2].x, 7.5);
    EXPECT_EQ(engine.kill_animations_of(sprites[2]), 1u);
}

TEST(Targets, AccessorsFollowYourOwnRegistry) {
    Engine engine;
    std::vector<std::unique_ptr<Sprite>> registry;
    registry.push_back(std::make_unique<Sprite>());
    const std::size_t id = 0;
    Animation a = engine.animate(grape::accessor<Sprite>([&]() -> Sprite* { return registry[id].get(); }),
                                 &Sprite::rotation, grape::to(1.0), 1.0);
    engine.tick(0.5);
    EXPECT_DOUBLE_EQ(registry[0]->rotation, 0.5);
    registry[0].reset();  // the registry says: gone
    engine.tick(0.25);
    EXPECT_FALSE(a.alive());
}
