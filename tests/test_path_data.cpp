// path_data: values along a path keyed by arc length or by u — keys come back exactly, the
// lookup by u agrees with Path3::u_at_length, easing per interval written out, and the
// conversion works on 2-D, 3-D and N-D paths.
#include <grape/color.hpp>
#include <grape/curve.hpp>
#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/path3.hpp>
#include <grape/path_data.hpp>
#include <grape/vec3.hpp>

#include "error_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace grape;
using grape::testing::expect_error;

namespace {
constexpr double eps = std::numeric_limits<double>::epsilon();
}

TEST(PathData, ArcLengthKeysReadByUAgreeWithUAtLength) {
    const Path3 path = Path3::catmull_rom(std::vector<Vec3>{{0, 0, 0}, {3, 1, 0}, {5, 4, 2}, {4, 8, 3}, {0, 9, 1}},
                                          CatmullRom::centripetal);
    const double total = path.length();
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> value(1.0, 2.0);
    std::vector<PathDataPoint<double>> keys;
    for (int i = 0; i <= 8; ++i) keys.push_back({total * i / 8.0, value(rng)});
    const PathData<double> data(PathDataKey::arc_length, keys);
    // Path3::u_at_length gives u within ~1e-15 (taken as 2e-15), so length_at(u) is s within
    // 2e-15·max|d1| (max|d1| sampled here); values in [1, 2] change by < 1 over L/8, so the
    // value read moves from the key's by < (8/L)·2e-15·max|d1|. The bound is that plus 1e-15
    // relative of the value.
    double fastest = 0.0;
    for (int i = 0; i <= 4000; ++i) fastest = std::max(fastest, length(path.d1(i / 4000.0)));
    const double slack = 8.0 / total * 2e-15 * fastest * 1.01;  // 1 % for the sampled maximum
    for (const auto& k : keys) {
        EXPECT_EQ(data.at_key(k.at), k.value);
        EXPECT_EQ(data.at_length(path, k.at), k.value);
        const double got = data.at_u(path, path.u_at_length(k.at));
        EXPECT_NEAR(got, k.value, 1e-15 * k.value + slack) << k.at;
    }
    // Between keys: linear in arc length.
    for (int i = 0; i < 8; ++i) {
        const double s = total * (i + 0.25) / 8.0;
        EXPECT_NEAR(data.at_length(path, s), keys[i].value + 0.25 * (keys[i + 1].value - keys[i].value), 4 * eps * 2);
    }
}

TEST(PathData, UKeysAndEasedIntervals) {
    const Path3 path = Path3::line({0, 0, 0}, {0, 0, 10});
    const PathData<Vec3> data(PathDataKey::u, {{0.0, {0, 0, 0}}, {0.5, {1, 2, 3}}, {1.0, {1, 0, 0}}},
                              {Curve::quad_in(), Curve::linear()});
    // On a constant-speed line, s = 10·u exactly for these dyadic u.
    EXPECT_EQ(data.at_length(path, 2.5), data.at_key(0.25));
    const Vec3 q = data.at_key(0.25);  // quad in at t = ½: ¼ of the way
    EXPECT_NEAR(q.x, 0.25, eps);
    EXPECT_NEAR(q.y, 0.5, eps);
    EXPECT_NEAR(q.z, 0.75, eps);
    EXPECT_EQ(data.at_u(path, 0.5), (Vec3{1, 2, 3}));
    EXPECT_EQ(data.at_u(path, -1.0), (Vec3{0, 0, 0}));
    EXPECT_EQ(data.at_u(path, 2.0), (Vec3{1, 0, 0}));
    // Colours go through their own lerp, keys exactly.
    const PathData<Color> tint(PathDataKey::u, {{0.0, Color{1, 0, 0, 1}}, {1.0, Color{0, 0, 1, 1}}});
    EXPECT_EQ(tint.at_key(0.0), (Color{1, 0, 0, 1}));
    EXPECT_EQ(tint.at_key(1.0), (Color{0, 0, 1, 1}));
}

TEST(PathData, WorksOn2DAndNDPaths) {
    const Path flat = LinearPath({0, 0}, {3, 4});  // length 5
    const PathData<double> d(PathDataKey::arc_length, {{0.0, 0.0}, {5.0, 10.0}});
    EXPECT_NEAR(d.at_u(flat, 0.5), 5.0, 4 * eps * 10);
    const PathND nd(std::vector<double>{0, 0, 0}, std::vector<double>{2, 3, 6});  // length 7
    EXPECT_NEAR(d.at_u(nd, 0.5), 10.0 * 3.5 / 5.0, 4 * eps * 10);
    EXPECT_EQ(d.at_length(nd, 5.0), 10.0);
}

TEST(PathData, RefusesBadKeys) {
    using P = PathDataPoint<double>;
    expect_error([] { PathData<double> d(PathDataKey::u, {}); }, {"PathData", "at least 1"});
    expect_error([] { PathData<double> d(PathDataKey::u, {P{0.0, 1.0}, P{1.5, 2.0}}); }, {"points[1].at", "[0, 1]"});
    expect_error([] { PathData<double> d(PathDataKey::arc_length, {P{3.0, 1.0}, P{3.0, 2.0}}); }, {"points[1].at", "greater"});
    expect_error([] { PathData<double> d(PathDataKey::arc_length, {P{-1.0, 1.0}}); }, {"points[0].at", ">= 0"});
    expect_error([] { PathData<double> d(PathDataKey::arc_length, {P{0.0, 1.0}, P{1.0, 2.0}}, {Curve(), Curve()}); },
                 {"curves", "one curve per interval"});
}
