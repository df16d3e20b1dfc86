// scene properties and tweens: scenes/typed_values.json against the same set-up built with
// Engine::animate (grape::to / grape::by / grape::from_to, free and placed in engine
// Timelines) ticked frame by frame, values at play boundaries and on linear stretches derived
// by hand, save → load bit for bit, and every kind of bad input naming its JSON pointer.
#include <grape/anim.hpp>
#include <grape/color.hpp>
#include <grape/error.hpp>
#include <grape/scene.hpp>
#include <grape/scene_values.hpp>
#include <grape/timeline.hpp>

#include "error_text.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace {

using grape::Color;
using grape::Scene;
using grape::SceneProperties;
using grape::SceneTiming;
using grape::Vec2;
using grape::testing::expect_error;

const std::filesystem::path scenes_dir = GRAPE_SCENES_DIR;

Scene typed_values() { return grape::load_scene_file(scenes_dir / "typed_values.json"); }

std::size_t property(const Scene& s, const std::string& name) {
    const std::ptrdiff_t k = s.find_property(name);
    EXPECT_GE(k, 0) << name;
    return static_cast<std::size_t>(k);
}

double number_at(const SceneProperties& v, std::size_t k, double t) { return std::get<double>(v.value(k, t)); }
Color color_at(const SceneProperties& v, std::size_t k, double t) { return std::get<Color>(v.value(k, t)); }

// The members the engine drives, one per property of the scene (dial, in degrees, is
// checked by hand below: the engine's AngleLerp turns in radians).
struct Thing {
    Color tint, glow;
    double heading = 0.0, height = 0.0;
    Vec2 offset;
};

// The example's set-up built with Engine::animate, ticked by `dt` for 4 s; after each tick the
// scene's values at k·dt must be within `tolerance` of the members (0: the same doubles).
void compare_with_engine(double dt, int frames, double tolerance) {
    const Scene scene = typed_values();
    const SceneTiming timing(scene);
    const SceneProperties values(scene, timing);
    const Thing initial{grape::parse_color("#ff0000"), grape::parse_color("#000000"), 3.0, 0.0, {0.0, 0.0}};

    grape::Engine engine;
    Thing thing = initial;
    const auto curve = [](const char* text) { return grape::parse_curve(text); };
    // The timelines first: placing a child writes its start state, so the members are set
    // back to the scene's initial values afterwards; their first plays begin (and read the
    // members) when the timelines reach them.
    grape::Timeline hop = engine.create_timeline({.delay = 0.5, .repeat = 1, .repeat_delay = 0.25});
    hop.add(engine.animate(thing, &Thing::height, grape::by(40.0), 0.5, {.curve = curve("spring-duration(0.5,0.25,0)")}))
        .add(engine.animate(thing, &Thing::height, grape::by(-40.0), 0.5, {.curve = curve("bounce-out")}), ">");
    grape::Timeline pulse = engine.create_timeline({.repeat = 1, .yoyo = true});
    pulse.add(engine.animate(thing, &Thing::glow, grape::from_to(grape::parse_color("#000000"), grape::parse_color("#ffcc00")), 0.5))
        .add(engine.animate(thing, &Thing::glow, grape::to(grape::parse_color("rgba(255, 255, 255, 0.5)")), 1.5,
                            {.curve = curve("cubic-out-in")}));
    thing = initial;
    // Free tweens, in the order of the scene's "tweens" (the engine updates them in creation order).
    const grape::ColorLerp oklab{grape::ColorSpace::oklab};
    engine.animate(thing, &Thing::tint, grape::to(grape::parse_color("#00ff00")), 1.0, {.curve = curve("quad-in-out")}, oklab);
    engine.animate(thing, &Thing::tint, grape::to(grape::parse_color("rgb(0 0 255)")), 1.0, {.delay = 1.5}, oklab);
    engine.animate(thing, &Thing::heading, grape::to(-3.0), 0.5, {.delay = 0.25}, grape::AngleLerp{});
    engine.animate(thing, &Thing::offset, grape::by(Vec2{16.0, -8.0}), 2.0, {.curve = curve("svg(M0,0 C0.5,0 0.5,1 1,1)")});

    const std::size_t tint = property(scene, "tint"), glow = property(scene, "glow"), heading = property(scene, "heading"),
                      height = property(scene, "height"), offset = property(scene, "offset");
    const auto near = [&](double a, double b) {
        if (tolerance == 0.0) EXPECT_EQ(a, b);
        else EXPECT_NEAR(a, b, tolerance);
    };
    const auto near_color = [&](const Color& a, const Color& b) {
        near(a.r, b.r), near(a.g, b.g), near(a.b, b.b), near(a.a, b.a);
    };
    for (int frame = 0; frame <= frames; ++frame) {
        if (frame > 0) engine.tick(dt);
        const double t = frame * dt;
        SCOPED_TRACE("t = " + std::to_string(t));
        near_color(color_at(values, tint, t), thing.tint);
        near_color(color_at(values, glow, t), thing.glow);
        near(number_at(values, heading, t), thing.heading);
        near(number_at(values, height, t), thing.height);
        near(std::get<Vec2>(values.value(offset, t)).x, thing.offset.x);
        near(std::get<Vec2>(values.value(offset, t)).y, thing.offset.y);
    }
    // Where they end (4 s: every tween and timeline has ended; pulse back at its start).
    EXPECT_EQ(thing.tint, grape::parse_color("#0000ff"));
    EXPECT_EQ(thing.glow, grape::parse_color("#000000"));
    EXPECT_EQ(thing.heading, 2.0 * grape::pi - 3.0);
    EXPECT_EQ(thing.height, 0.0);
    EXPECT_EQ(thing.offset, (Vec2{16.0, -8.0}));
}

TEST(SceneValues, TheExampleSceneMatchesEngineTweensFrameByFrame) {
    // Ticks of 1/64 s and durations, delays, starts and timeline lengths that are sums of
    // powers of two: the engine's times and the scene's are the same doubles, so the values
    // agree bit for bit, from-current and relative starts included.
    compare_with_engine(1.0 / 64.0, 4 * 64, 0.0);
}

TEST(SceneValues, TheExampleSceneMatchesEngineTweensAt60Hz) {
    // 1/60 s ticks: the engine sums 240 of them (its time within 240 ulps of 4 s, 2e-13 s)
    // and the scene reads k/60; the fastest change here is under 400 units/s (height's spring
    // and bounce over 0.5 s; colour channels through the sRGB curve's slope of 12.92), so the
    // values agree within 400 · 2e-13 ≈ 1e-10.
    compare_with_engine(1.0 / 60.0, 240, 1e-10);
}

TEST(SceneValues, ARelativeTweenInATimelineAddsItsAmountToTheValueWhenItBegins) {
    // The engine reads a typed animation's start when placing it in a timeline too (its start
    // state is written then) and again when the timeline reaches it: the amount must be added
    // once, to the second reading. The member holds 5 when placed and 100 when the timeline
    // (delay 1) reaches the tween; the scene says 100 − 40.
    struct Y {
        double y = 5.0;
    };
    grape::Engine engine;
    Y thing;
    grape::Timeline line = engine.create_timeline({.delay = 1.0});
    line.add(engine.animate(thing, &Y::y, grape::by(-40.0), 0.5));
    thing.y = 100.0;
    const Scene scene = grape::load_scene(R"({"properties": [{"name": "y", "value": 100}],
      "tweens": [{"name": "drop", "property": "y", "by": -40, "duration": 0.5}],
      "timelines": [{"name": "line", "delay": 1, "children": [{"tween": "drop"}]}]})");
    const SceneProperties values(scene, SceneTiming(scene));
    for (int k = 1; k <= 16; ++k) {
        engine.tick(0.125);
        EXPECT_EQ(number_at(values, 0, 0.125 * k), thing.y) << k;
    }
    EXPECT_EQ(thing.y, 60.0);
}

TEST(SceneValues, AnOwnDelayAndTimeScaleInsideAYoyoTimelineMatchTheEngine) {
    // b has its own delay and time scale inside the timeline: the timeline reaches it at a's
    // end, it reads x there (8) and rests at its start through its delay; the timeline waits
    // 0.25 s, plays 0.75 s forwards, then backwards. Ticks of 1/64 s are exact, and a play of
    // 0.75 s (not a power of two) goes through the same divisions in the scene as in the engine.
    const Scene scene = grape::load_scene(R"({"properties": [{"name": "x", "value": 0}],
      "tweens": [{"name": "a", "property": "x", "to": 8, "duration": 0.5, "curve": "quad-out"},
                 {"name": "b", "property": "x", "by": 4, "duration": 0.25, "delay": 0.25, "time_scale": 2}],
      "timelines": [{"name": "t", "delay": 0.25, "repeat": 1, "yoyo": true,
                     "children": [{"tween": "a"}, {"tween": "b", "at": ">"}]}]})");
    const SceneProperties values(scene, SceneTiming(scene));
    struct X {
        double x = 0.0;
    };
    grape::Engine engine;
    X thing;
    grape::Timeline line = engine.create_timeline({.delay = 0.25, .repeat = 1, .yoyo = true});
    line.add(engine.animate(thing, &X::x, grape::to(8.0), 0.5, {.curve = grape::Curve::quad_out()}))
        .add(engine.animate(thing, &X::x, grape::by(4.0), 0.25, {.delay = 0.25, .time_scale = 2.0}), ">");
    EXPECT_EQ(line.duration(), 0.75);
    thing.x = 0.0;
    for (int k = 1; k <= 128; ++k) {
        engine.tick(1.0 / 64.0);
        EXPECT_EQ(number_at(values, 0, k / 64.0), thing.x) << "t = " << k / 64.0;
    }
    EXPECT_EQ(number_at(values, 0, 0.25 + 0.75), 12.0);  // the end of the first play: 8 + 4
    EXPECT_EQ(number_at(values, 0, 2.0), 0.0);           // back at the start
}

TEST(SceneValues, FromCurrentAndRelativeStartsAreWhereTheEarlierTweensLeft) {
    const Scene scene = typed_values();
    const SceneProperties values(scene, SceneTiming(scene));
    const auto tween = [&](const std::string& name) {
        for (std::size_t i = 0; i < scene.tweens.size(); ++i)
            if (scene.tweens[i].name == name) return i;
        ADD_FAILURE() << name;
        return std::size_t{0};
    };
    // to_blue begins at 1.5 s, after to_green ended on green; up by 40 from 0, down by −40 from 40.
    EXPECT_EQ(std::get<Color>(values.tween_from(tween("to_blue"))), grape::parse_color("#00ff00"));
    EXPECT_EQ(std::get<double>(values.tween_from(tween("up"))), 0.0);
    EXPECT_EQ(std::get<double>(values.tween_to(tween("up"))), 40.0);
    EXPECT_EQ(std::get<double>(values.tween_from(tween("down"))), 40.0);
    EXPECT_EQ(std::get<double>(values.tween_to(tween("down"))), 0.0);
    EXPECT_EQ(std::get<Vec2>(values.tween_to(tween("drift"))), (Vec2{16.0, -8.0}));
    EXPECT_EQ(std::get<Color>(values.tween_from(tween("fade"))), grape::parse_color("#ffcc00"));
}

TEST(SceneValues, ValuesDerivedByHand) {
    const Scene scene = typed_values();
    const SceneProperties values(scene, SceneTiming(scene));
    const std::size_t dial = property(scene, "dial"), height = property(scene, "height"), tint = property(scene, "tint");
    // dial: 350° to 10° the short way, linear over 1 s: 350 + 20·t, through 360 (not back by 340°).
    EXPECT_EQ(number_at(values, dial, 0.0), 350.0);
    EXPECT_EQ(number_at(values, dial, 0.25), 355.0);
    EXPECT_EQ(number_at(values, dial, 0.5), 360.0);
    EXPECT_EQ(number_at(values, dial, 1.0), 370.0);
    EXPECT_EQ(number_at(values, dial, 7.0), 370.0);
    // height in hop (delay 0.5, plays of 1 s, 0.25 s between): 0 before, 40 at the end of up
    // (1 s), 0 at the end of down (1.5 s) and through the repeat delay, 40 again at 2.25 s.
    EXPECT_EQ(number_at(values, height, 0.25), 0.0);
    EXPECT_EQ(number_at(values, height, 1.0), 40.0);
    EXPECT_EQ(number_at(values, height, 1.5), 0.0);
    EXPECT_EQ(number_at(values, height, 1.625), 0.0);
    EXPECT_EQ(number_at(values, height, 2.25), 40.0);
    EXPECT_EQ(number_at(values, height, 9.0), 0.0);
    // tint: red, green from 1 s to 1.5 s, blue from 2.5 s.
    EXPECT_EQ(color_at(values, tint, 0.0), grape::parse_color("#ff0000"));
    EXPECT_EQ(color_at(values, tint, 1.25), grape::parse_color("#00ff00"));
    EXPECT_EQ(color_at(values, tint, 3.0), grape::parse_color("#0000ff"));
}

TEST(SceneValues, EveryTurnAndLinearLightColours) {
    // An angle that keeps every turn goes the long way; colours mixed in linear light pass
    // the linear midpoint, encoded by the sRGB curve written out here (IEC 61966-2-1).
    const Scene scene = grape::load_scene(R"({
      "properties": [{"name": "a", "type": "angle", "value": 350, "unit": "degrees", "turn": "every"},
                     {"name": "r", "type": "angle", "value": 3},
                     {"name": "c", "type": "color", "value": "#000000"}],
      "tweens": [{"property": "a", "to": 10, "duration": 1},
                 {"property": "r", "by": 0.5, "duration": 1, "delay": 1},
                 {"property": "c", "to": "#ffffff", "duration": 2}]})");
    const SceneProperties values(scene, SceneTiming(scene));
    EXPECT_EQ(number_at(values, 0, 0.5), 180.0);
    EXPECT_EQ(number_at(values, 1, 0.5), 3.0);  // waiting: the value it had
    EXPECT_EQ(number_at(values, 1, 2.0), 3.5);  // by 0.5 from 3, within half a turn
    const double encoded = 1.055 * std::pow(0.5, 1.0 / 2.4) - 0.055;
    const Color mid = color_at(values, 2, 1.0);
    // 4e-16: a few ulps of a value below 1 through pow and the transfer curve.
    EXPECT_NEAR(mid.r, encoded, 4e-16);
    EXPECT_EQ(mid.r, mid.g);
    EXPECT_EQ(mid.g, mid.b);
    EXPECT_EQ(mid.a, 1.0);
}

TEST(SceneValues, OverlappingTweensTheLaterStartedWins) {
    // a runs 0–2 s, b 0.5–1 s: from 0.5 s b's value, also after b has ended (its end, 100).
    const Scene scene = grape::load_scene(R"({
      "properties": [{"name": "x", "value": 0}],
      "tweens": [{"property": "x", "to": 10, "duration": 2},
                 {"property": "x", "from": 50, "to": 100, "duration": 0.5, "delay": 0.5}]})");
    const SceneProperties values(scene, SceneTiming(scene));
    EXPECT_EQ(number_at(values, 0, 0.25), 1.25);
    EXPECT_EQ(number_at(values, 0, 0.75), 75.0);
    EXPECT_EQ(number_at(values, 0, 1.5), 100.0);
}

TEST(SceneValues, SaveLoadIsBitForBit) {
    Scene scene = typed_values();
    // A colour no hex text holds (0.3 is not k/255): saved as its numbers.
    scene.properties[0].value = Color{0.3, 0.1, 1.0 / 3.0, 0.75};
    scene.tweens[0].mode = grape::ValueMode::from_to;
    scene.tweens[0].from = Color{0.1, 0.2, 0.7, 1.0};
    const std::string text = grape::save_scene(scene);
    const Scene again = grape::load_scene(text);
    EXPECT_EQ(grape::save_scene(again), text);
    ASSERT_EQ(again.properties.size(), scene.properties.size());
    for (std::size_t k = 0; k < scene.properties.size(); ++k) {
        EXPECT_EQ(again.properties[k].value, scene.properties[k].value) << k;
        EXPECT_EQ(again.properties[k].type, scene.properties[k].type) << k;
        EXPECT_EQ(again.properties[k].space, scene.properties[k].space) << k;
        EXPECT_EQ(again.properties[k].shortest, scene.properties[k].shortest) << k;
        EXPECT_EQ(again.properties[k].degrees, scene.properties[k].degrees) << k;
    }
    ASSERT_EQ(again.tweens.size(), scene.tweens.size());
    for (std::size_t i = 0; i < scene.tweens.size(); ++i) {
        const grape::SceneTween &a = again.tweens[i], &b = scene.tweens[i];
        EXPECT_EQ(a.mode, b.mode) << i;
        if (a.mode == grape::ValueMode::from_to) {
            EXPECT_EQ(a.from, b.from) << i;
        }
        EXPECT_EQ(a.to, b.to) << i;
        EXPECT_TRUE(a.curve == b.curve) << i;
        EXPECT_EQ(a.duration, b.duration) << i;
        EXPECT_EQ(a.delay, b.delay) << i;
    }
    EXPECT_NE(text.find("\"#00ff00\""), std::string::npos);  // hex where it is exact
    // Not where it would round: the numbers (the round trip above has checked they read back).
    EXPECT_EQ(text.find(grape::to_hex(std::get<Color>(scene.properties[0].value))), std::string::npos);
}

TEST(SceneValues, AFunctionCurveCannotBeSaved) {
    Scene scene = typed_values();
    scene.tweens[2].curve = grape::Curve::from_function([](double t) { return t * t; });
    scene.tweens[2].curve_name.clear();
    expect_error([&] { (void)grape::save_scene(scene); }, {"scene: /tweens/2/curve: ", "from a function", "cannot be saved"});
    scene = typed_values();
    scene.curves[0].curve = grape::Curve::from_function([](double t) { return t; });
    expect_error([&] { (void)grape::save_scene(scene); }, {"scene: /curves/0/curve: "});
}

TEST(SceneValues, BadInputNamesItsPointer) {
    const std::string props = R"("properties": [{"name": "x", "value": 0}, {"name": "p", "type": "vec2", "value": [0, 0]},
                                                 {"name": "c", "type": "color", "value": "#000"}])";
    const auto scene = [&](const std::string& rest) { return "{" + props + ", " + rest + "}"; };
    const auto tween = [&](const std::string& fields) { return scene(R"("tweens": [{"duration": 1, )" + fields + "}]"); };
    struct Case {
        std::string json, pointer, why;
    };
    const std::vector<Case> cases = {
        {tween(R"("property": "y", "to": 1)"), "/tweens/0/property", "no property named \"y\""},
        {tween(R"("property": "x", "to": "#fff")"), "/tweens/0/to", "expected a number"},
        {tween(R"("property": "p", "to": 1)"), "/tweens/0/to", "expected a point [x, y]"},
        {tween(R"("property": "c", "to": "#ggg")"), "/tweens/0/to", "#ggg"},
        {tween(R"("property": "c", "to": [1, 0, 0])"), "/tweens/0/to", "expected a colour"},
        {tween(R"("property": "x", "to": 1, "by": 1)"), "/tweens/0", "\"to\" and \"by\" both given"},
        {tween(R"("property": "x")"), "/tweens/0", "missing field \"to\" or \"by\""},
        {tween(R"("property": "x", "from": 0, "by": 1)"), "/tweens/0/by", "give \"to\""},
        {tween(R"("property": "c", "by": "#111")"), "/tweens/0/by", "a colour cannot move by an amount"},
        {scene(R"("tweens": [{"property": "x", "to": 1, "duration": -1}])"), "/tweens/0/duration", "must be positive"},
        {tween(R"("property": "x", "to": 1, "delay": -1)"), "/tweens/0/delay", "must not be negative"},
        {tween(R"("property": "x", "to": 1, "time_scale": 0)"), "/tweens/0/time_scale", "must be positive"},
        {tween(R"("property": "x", "to": 1, "curve": "wobbly")"), "/tweens/0/curve", "nor is it a name in /curves"},
        {tween(R"j("property": "x", "to": 1, "curve": "svg(M0,0 A1,1 0 0 1 1,1)")j"), "/tweens/0/curve", ""},
        {tween(R"("property": "x", "to": 1, "speed": 2)"), "/tweens/0/speed", "unknown field"},
        // Values that overflow on the way: a start of 1e308 moved by 1e308, a colour whose
        // linear light is past the largest double, an elastic period whose 2π/p is infinite.
        {R"({"properties": [{"name": "x", "value": 1e308}], "tweens": [{"property": "x", "by": 1e308, "duration": 1}]})",
         "/tweens/0/by", "overflow the range of a double"},
        {tween(R"("property": "c", "to": [1e308, 0, 0, 1])"), "/tweens/0/to", "overflow the range of a double"},
        {tween(R"("property": "p", "from": [-1e308, 0], "to": [1.7e308, 0], "curve": "back-in-out")"), "/tweens/0/to",
         "overflow the range of a double"},
        {tween(R"j("property": "x", "to": 1, "curve": "elastic-out(1,1e-310)")j"), "/tweens/0/curve", "period must be >= 1e-15"},
        {R"({"properties": [{"name": "x", "type": "text", "value": 0}]})", "/properties/0/type", "unknown value \"text\""},
        {R"({"properties": [{"name": "x", "value": 0}, {"name": "x", "value": 1}]})", "/properties/1/name", "duplicate name"},
        {R"({"properties": [{"name": "x", "value": 0, "space": "oklab"}]})", "/properties/0/space", "only colours"},
        {R"({"properties": [{"name": "x", "value": 0, "turn": "every"}]})", "/properties/0/turn", "only angles"},
        {R"({"properties": [{"name": "x", "type": "angle", "value": 0, "unit": "turns"}]})", "/properties/0/unit", "unknown value"},
        {R"({"properties": [{"name": "x"}]})", "/properties/0", "missing field \"value\""},
        {R"j({"properties": [{"name": "c", "type": "color", "value": "rgb(1 2)"}]})j", "/properties/0/value", "rgb(1 2)"},
        {scene(R"("tweens": [{"name": "t", "property": "x", "to": 1, "duration": 1}],
                  "timelines": [{"name": "l", "children": [{"tween": "u"}]}])"),
         "/timelines/0/children/0/tween", "no tween named \"u\""},
        {scene(R"("tweens": [{"name": "t", "property": "x", "to": 1, "duration": 1}],
                  "timelines": [{"name": "l", "children": [{"tween": "t"}, {"tween": "t"}]}])"),
         "/timelines/0/children/1/tween", "already placed at /timelines/0/children/0"},
        {scene(R"("tweens": [{"name": "t", "property": "x", "to": 1, "duration": 1, "repeat": -1}],
                  "timelines": [{"name": "l", "children": [{"tween": "t"}]}])"),
         "/timelines/0/children/0/tween", "repeats forever"},
        {scene(R"("tweens": [{"name": "t", "property": "x", "to": 1, "duration": 1}],
                  "timelines": [{"name": "l", "children": [{"tween": "t", "animation": "t"}]}])"),
         "/timelines/0/children/0", "exactly one of"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.json);
        expect_error([&] { (void)grape::load_scene(c.json); }, {"scene: " + c.pointer + ": ", c.why});
    }
}

// Large values that stay finite all the way are kept: 0 by 1e308 is 5e307 half way.
TEST(SceneValues, LargeValuesThatStayFiniteAreKept) {
    const Scene scene = grape::load_scene(R"({"properties": [{"name": "x", "value": 0}],
        "tweens": [{"property": "x", "by": 1e308, "duration": 1}]})");
    const SceneProperties values(scene, SceneTiming(scene));
    EXPECT_EQ(std::get<double>(values.value(0, 0.5)), 5e307);
    EXPECT_EQ(std::get<double>(values.value(0, 1.0)), 1e308);
}

// 10⁵ properties, each with a tween: the names were compared pairwise and each tween's property
// found by a scan (2·10⁴ took 7.5 s, 10⁵ about three minutes); hashed, it is linear (10⁵ in
// about a second in a debug build). The bound is far from both.
TEST(SceneValues, ManyPropertiesAndTweensLoadInLinearTime) {
    constexpr int n = 100000;
    std::string json = R"({"properties": [)";
    for (int k = 0; k < n; ++k) json += (k ? ", " : "") + std::string(R"({"name": "p)") + std::to_string(k) + R"(", "value": 0})";
    json += R"(], "tweens": [)";
    for (int k = 0; k < n; ++k)
        json += (k ? ", " : "") + std::string(R"({"property": "p)") + std::to_string(k) + R"(", "to": )" + std::to_string(k) +
                R"(, "duration": 1})";
    json += "]}";
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = grape::load_scene(json);
    const SceneProperties values(scene, SceneTiming(scene));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 20.0);
    EXPECT_EQ(std::get<double>(values.value(n - 1, 0.5)), 0.5 * (n - 1));
}

TEST(SceneValues, ScenesBuiltInCodeAreChecked) {
    Scene scene;
    scene.properties.push_back({.name = "x", .type = grape::ScenePropertyType::vec2, .value = 1.0});
    expect_error([&] { SceneProperties(scene, SceneTiming(scene)); }, {"scene: /properties/0/value: ", "a vec2"});
    scene.properties[0].value = Vec2{0.0, 0.0};
    grape::SceneTween tw;
    tw.property = "x";
    tw.to = Color{};
    scene.tweens.push_back(tw);
    expect_error([&] { SceneProperties(scene, SceneTiming(scene)); }, {"scene: /tweens/0/to: ", "a vec2"});
    scene.tweens[0].property = "nothing";
    expect_error([&] { SceneProperties(scene, SceneTiming(scene)); }, {"scene: /tweens/0/property: "});
    scene.tweens[0].property = "x";
    scene.tweens[0].to = Vec2{1.0, 2.0};
    scene.tweens[0].duration = 0.0;
    expect_error([&] { SceneProperties(scene, SceneTiming(scene)); }, {"scene: /tweens/0/duration: "});
    scene.tweens[0].duration = 2.0;
    const SceneProperties values(scene, SceneTiming(scene));
    EXPECT_EQ(std::get<Vec2>(values.value(0, 1.0)), (Vec2{0.5, 1.0}));
    expect_error([&] { SceneProperties(scene, SceneTiming()); }, {"scene: /tweens: ", "another scene"});
}

}  // namespace
