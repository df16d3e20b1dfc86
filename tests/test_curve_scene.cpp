// Custom curves in scene files: read from their names, played, written back by save_scene
// and read again to the same curves.
#include <grape/curve.hpp>
#include <grape/scene.hpp>

#include "error_text.hpp"

#include <gtest/gtest.h>

#include <string>

using grape::Curve;

TEST(CurveScene, CustomCurvesRoundTripThroughSaveScene) {
    const grape::Scene s = grape::load_scene(R"json({
        "curves": [
            {"name": "custom", "curve": "svg(M0,0 C0.1,0.8 0.3,1.1 0.6,1 S0.9,1 1,1)"},
            {"name": "relative", "curve": "svg(m0,0 c0.2,0 0.3,1 1,1)"},
            {"name": "springy", "curve": "spring(170,26)"},
            {"name": "swift", "curve": "spring-duration(0.5,0.3)"},
            {"name": "outin", "curve": "quad-out-in"}
        ],
        "animations": [
            {"path": {"kind": "linear", "start": [0, 0], "end": [100, 0]}, "curve": "custom", "duration": 2},
            {"path": {"kind": "linear", "start": [0, 0], "end": [100, 0]}, "curve": "spring(100,10,1,2)", "duration": 1},
            {"path": {"kind": "linear", "start": [0, 0], "end": [100, 0]}, "curve": "back-out-in(2.5)", "duration": 1},
            {"path": {"kind": "linear", "start": [0, 0], "end": [100, 0]}, "curve": "swift", "duration": 1}
        ]})json");
    ASSERT_EQ(s.curves.size(), 5u);
    EXPECT_EQ(s.curves[0].curve, Curve::svg("M0,0 C0.1,0.8 0.3,1.1 0.6,1 S0.9,1 1,1"));
    EXPECT_EQ(s.curves[2].curve, Curve::spring({.stiffness = 170, .damping = 26}));
    EXPECT_EQ(s.curves[3].curve, Curve::spring_duration(0.5, 0.3));
    EXPECT_EQ(s.curves[4].curve, Curve::quad_out_in());
    EXPECT_EQ(s.animations[1].curve, Curve::spring({.stiffness = 100, .damping = 10, .velocity = 2}));
    EXPECT_EQ(s.animations[2].curve, Curve::back(grape::EaseDirection::out_in, 2.5));
    // Played as the curve gives it: half way through the 2 s play, y at x = ½.
    EXPECT_DOUBLE_EQ(s.animations[0].progress(1.0), s.curves[0].curve(0.5));

    const std::string saved = grape::save_scene(s);
    EXPECT_NE(saved.find("svg(M0,0 C0.1,0.8 0.3,1.1 0.6,1 C"), std::string::npos) << saved;  // S written as C
    EXPECT_NE(saved.find("spring(170,26,1,0)"), std::string::npos);
    EXPECT_NE(saved.find("spring-duration(0.5,0.3,0)"), std::string::npos);
    const grape::Scene again = grape::load_scene(saved);
    ASSERT_EQ(again.curves.size(), s.curves.size());
    for (std::size_t i = 0; i < s.curves.size(); ++i) {
        EXPECT_EQ(again.curves[i].curve, s.curves[i].curve) << s.curves[i].name;
        EXPECT_EQ(grape::to_string(again.curves[i].curve), grape::to_string(s.curves[i].curve));
    }
    for (std::size_t i = 0; i < s.animations.size(); ++i) {
        EXPECT_EQ(again.animations[i].curve, s.animations[i].curve) << i;
        EXPECT_EQ(again.animations[i].curve_name, s.animations[i].curve_name);
    }
    EXPECT_EQ(grape::save_scene(again), saved);
}

TEST(CurveScene, BadCustomCurvesPointAtTheField) {
    grape::testing::expect_error(
        [] { (void)grape::load_scene(R"json({"curves": [{"name": "bad", "curve": "svg(M0,0 C1.2,0 -0.2,1 1,1)"}]})json"); },
        {"/curves/0/curve", "segment 1 (C from 0,0) goes back in x"});
    grape::testing::expect_error(
        [] { (void)grape::load_scene(R"json({"curves": [{"name": "bad", "curve": "spring(100,0)"}]})json"); },
        {"/curves/0/curve", "damping must be finite and > 0"});
}
