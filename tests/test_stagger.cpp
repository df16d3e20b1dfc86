// Stagger offsets against values worked out by hand from GSAP's documented rule (see
// stagger.hpp), plus symmetry, each ≡ amount, random = a permutation, and grid distances.
#include <grape/stagger.hpp>

#include <grape/anim.hpp>
#include <grape/error.hpp>

#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using grape::StaggerAxis;
using grape::StaggerDef;
using grape::StaggerFrom;
using grape::stagger_offsets;

namespace {

// Offsets are a few products and quotients of numbers below 10: within 4 ulp of 1.
constexpr double tight = 1e-15;

void expect_offsets(const std::vector<double>& got, const std::vector<double>& want, const std::string& what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], tight) << what << ", item " << i;
}

}  // namespace

// In a row, the distances are |j − origin|: start 0.5 cells before item 0, end 0.5 past the
// last, center at the middle; normalized by their range and scaled by each × (n − 1).
TEST(Stagger, RowsFollowGsapsRule) {
    expect_offsets(stagger_offsets(5, {.each = 0.1}), {0.0, 0.1, 0.2, 0.3, 0.4}, "start");
    expect_offsets(stagger_offsets(5, {.each = 0.1, .from = StaggerFrom::end}), {0.4, 0.3, 0.2, 0.1, 0.0}, "end");
    // Center of 5 at item 2: distances 2 1 0 1 2, spread 0.4.
    expect_offsets(stagger_offsets(5, {.each = 0.1, .from = StaggerFrom::center}), {0.4, 0.2, 0.0, 0.2, 0.4}, "center 5");
    // Center of 4 at 1.5: distances 1.5 .5 .5 1.5 (range 1), spread 0.3.
    expect_offsets(stagger_offsets(4, {.each = 0.1, .from = StaggerFrom::center}), {0.3, 0.0, 0.0, 0.3}, "center 4");
    // Edges: the same distances, the outermost first.
    expect_offsets(stagger_offsets(5, {.each = 0.1, .from = StaggerFrom::edges}), {0.0, 0.2, 0.4, 0.2, 0.0}, "edges");
    // From item 1: distances 1 0 1 2 3 (range 3), spread 0.4.
    expect_offsets(stagger_offsets(5, {.each = 0.1, .from = StaggerFrom::index, .index = 1}),
                   {0.4 / 3, 0.0, 0.4 / 3, 0.8 / 3, 0.4}, "index 1");
    expect_offsets(stagger_offsets(5, {.amount = 1.0}), {0.0, 0.25, 0.5, 0.75, 1.0}, "amount");
    // A negative spread runs backwards from |V|.
    expect_offsets(stagger_offsets(4, {.each = -0.5}), {1.5, 1.0, 0.5, 0.0}, "negative each");
}

// A grid of C columns: item j at (j % C, j / C). GSAP's each-spread is each × max(C, n / C).
TEST(Stagger, GridsMeasureDistanceInTwoDimensions) {
    // 3 × 3 from the center (1, 1): corners √2 away, edges 1, the middle 0; spread 0.3.
    const double corner = 0.3;
    const double edge = 0.3 / std::sqrt(2.0);
    expect_offsets(stagger_offsets(9, {.each = 0.1, .from = StaggerFrom::center, .grid = {.columns = 3, .rows = 3}}),
                   {corner, edge, corner, edge, 0.0, edge, corner, edge, corner}, "3x3 center");
    // 4 × 2 from the start: the origin (−0.5, −0.5), so item (c, r) is at √((c + ½)² + (r + ½)²);
    // min √0.5, max √14.5, spread 0.1 × max(4, 2) = 0.4.
    {
        const std::vector<double> got = stagger_offsets(8, {.each = 0.1, .grid = {.columns = 4}});
        const double lo = std::sqrt(0.5);
        const double range = std::sqrt(14.5) - lo;
        expect_offsets(got,
                       {0.0, 0.4 * (std::sqrt(2.5) - lo) / range, 0.4 * (std::sqrt(6.5) - lo) / range,
                        0.4 * (std::sqrt(12.5) - lo) / range, 0.4 * (std::sqrt(2.5) - lo) / range,
                        0.4 * (std::sqrt(4.5) - lo) / range, 0.4 * (std::sqrt(8.5) - lo) / range, 0.4},
                       "4x2 start");
    }
    // Along x: columns start together, 0.4 over 3 column steps; along y: rows, spread 0.1 × 8/4.
    expect_offsets(stagger_offsets(8, {.each = 0.1, .grid = {.columns = 4}, .axis = StaggerAxis::x}),
                   {0.0, 0.4 / 3, 0.8 / 3, 0.4, 0.0, 0.4 / 3, 0.8 / 3, 0.4}, "axis x");
    expect_offsets(stagger_offsets(8, {.each = 0.1, .grid = {.columns = 4}, .axis = StaggerAxis::y}),
                   {0.0, 0.0, 0.0, 0.0, 0.2, 0.2, 0.2, 0.2}, "axis y");
    // From item 5 of a 3 × 3 grid, (2, 1): distance √((c − 2)² + (r − 1)²), max √5.
    {
        const std::vector<double> got =
            stagger_offsets(9, {.amount = 1.0, .from = StaggerFrom::index, .index = 5, .grid = {.columns = 3}});
        const double r5 = std::sqrt(5.0);
        expect_offsets(got, {1.0, std::sqrt(2.0) / r5, 1.0 / r5, 2.0 / r5, 1.0 / r5, 0.0, 1.0, std::sqrt(2.0) / r5, 1.0 / r5},
                       "index in grid");
    }
}

// The curve maps the normalized distance t: quad-in gives (j/4)²; backwards spreads use
// curve(1 − t), so edges with quad-in give 1 − ... : |V|·curve(1 − t) = (1 − t)².
TEST(Stagger, TheCurveDistributesTheOffsets) {
    const grape::Curve quad = grape::Curve::quad_in();
    expect_offsets(stagger_offsets(5, {.amount = 1.0, .curve = quad}), {0.0, 0.0625, 0.25, 0.5625, 1.0}, "quad start");
    expect_offsets(stagger_offsets(5, {.amount = 1.0, .from = StaggerFrom::edges, .curve = quad}), {0.0, 0.25, 1.0, 0.25, 0.0},
                   "quad edges");
}

// From the center (and edges) the offsets mirror exactly: the distances are |j − (n−1)/2|,
// equal in floating point for j and n − 1 − j; on a full grid, the point mirror.
TEST(Stagger, CenterAndEdgesAreMirrorSymmetric) {
    for (std::size_t n = 1; n <= 40; ++n) {
        for (StaggerFrom from : {StaggerFrom::center, StaggerFrom::edges}) {
            const std::vector<double> row = stagger_offsets(n, {.each = 0.07, .from = from, .curve = grape::Curve::cubic_in_out()});
            for (std::size_t j = 0; j < n; ++j) EXPECT_EQ(row[j], row[n - 1 - j]) << n << " " << j;
            const std::size_t columns = 1 + n % 6;
            const std::size_t rows = (n + columns - 1) / columns;
            const std::vector<double> grid = stagger_offsets(columns * rows, {.each = 0.07, .from = from, .grid = {.columns = columns}});
            for (std::size_t j = 0; j < grid.size(); ++j) EXPECT_EQ(grid[j], grid[grid.size() - 1 - j]) << n << " " << j;
        }
    }
}

// `amount` is the spread each × (n − 1) implies (each × max(C, n / C) on a grid), whatever
// the origin: the same numbers, bit for bit.
TEST(Stagger, AmountAndEachAgree) {
    std::mt19937_64 rng(grape::testing::test_seed(5));
    for (int k = 0; k < 200; ++k) {
        const std::size_t n = 1 + rng() % 30;
        const double each = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
        const StaggerFrom from = static_cast<StaggerFrom>(rng() % 5);  // start … index
        const std::size_t index = rng() % n;
        const std::vector<double> a = stagger_offsets(n, {.each = each, .from = from, .index = index});
        const std::vector<double> b = stagger_offsets(n, {.amount = each * static_cast<double>(n - 1), .from = from, .index = index});
        EXPECT_EQ(a, b) << k;
        const std::size_t columns = 1 + rng() % n;
        const double span = std::max(static_cast<double>(columns), static_cast<double>(n) / static_cast<double>(columns));
        const std::vector<double> c = stagger_offsets(n, {.each = each, .from = from, .index = index, .grid = {.columns = columns}});
        const std::vector<double> d =
            stagger_offsets(n, {.amount = each * span, .from = from, .index = index, .grid = {.columns = columns}});
        EXPECT_EQ(c, d) << k;
    }
}

// Random orders the start offsets: the same multiset, in an order fixed by the seed.
TEST(Stagger, RandomIsASeededPermutationOfStart) {
    for (std::size_t n : {1u, 2u, 7u, 20u, 100u}) {
        for (std::size_t columns : {std::size_t{0}, std::size_t{3}}) {
            const StaggerDef linear{.amount = 2.0, .grid = {.columns = columns}};
            StaggerDef random = linear;
            random.from = StaggerFrom::random;
            random.seed = 99;
            std::vector<double> a = stagger_offsets(n, linear);
            std::vector<double> b = stagger_offsets(n, random);
            EXPECT_EQ(b, stagger_offsets(n, random)) << "the same seed, the same order";
            if (n >= 7 && columns == 0) {
                EXPECT_NE(a, b) << n;
                random.seed = 100;
                EXPECT_NE(stagger_offsets(n, random), b) << n;
            }
            std::sort(a.begin(), a.end());
            std::sort(b.begin(), b.end());
            EXPECT_EQ(a, b) << n;
        }
    }
    // The order for seed 1 on every platform (SplitMix64, Fisher–Yates from the end), as an
    // independent 12-line Python model of the two computes it: pinned.
    const std::vector<double> order = stagger_offsets(8, {.each = 1.0, .from = StaggerFrom::random, .seed = 1});
    EXPECT_EQ(order, (std::vector<double>{4, 3, 2, 7, 5, 6, 0, 1}));
}

TEST(Stagger, EdgeCountsAndDefaults) {
    EXPECT_TRUE(stagger_offsets(0, {.each = 0.1}).empty());
    EXPECT_EQ(stagger_offsets(1, {.each = 0.1}), std::vector<double>{0.0});
    EXPECT_EQ(stagger_offsets(1, {.each = 0.1, .from = StaggerFrom::center}), std::vector<double>{0.0});
    EXPECT_EQ(stagger_offsets(4, {}), std::vector<double>(4, 0.0));  // neither each nor amount
}

TEST(Stagger, BadDefsAreNamed) {
    auto message = [](std::size_t n, const StaggerDef& def) {
        try {
            stagger_offsets(n, def);
        } catch (const grape::Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message(3, {.each = 0.1, .amount = 1.0}), "stagger: give each or amount, not both");
    EXPECT_EQ(message(3, {.each = std::numeric_limits<double>::quiet_NaN()}), "stagger: each must be finite (got nan)");
    EXPECT_EQ(message(3, {.amount = std::numeric_limits<double>::infinity()}), "stagger: amount must be finite (got inf)");
    EXPECT_EQ(message(3, {.from = StaggerFrom::index, .index = 3}), "stagger: index must be < count (got index 3 of 3)");
    EXPECT_EQ(message(7, {.grid = {.columns = 3, .rows = 2}}), "stagger: grid 3 x 2 holds fewer than 7 items");
    EXPECT_EQ(message(7, {.grid = {.rows = 2}}), "stagger: grid.rows needs grid.columns > 0");
}

// One call, N animations: each waits its offset (time() is −delay before its first play).
TEST(Stagger, OneCallCreatesTheAnimations) {
    grape::Engine engine;
    const grape::LinearPath line({0, 0}, {1, 0});
    const StaggerDef def{.each = 0.25, .from = StaggerFrom::center};
    std::vector<std::size_t> order;
    const std::vector<grape::Animation> made = grape::stagger(5, def, [&](std::size_t i, double delay) {
        order.push_back(i);
        return engine.create_animation(line, 1.0, {.delay = delay});
    });
    ASSERT_EQ(made.size(), 5u);
    EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
    const std::vector<double> offsets = stagger_offsets(5, def);
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_TRUE(made[i].alive());
        EXPECT_DOUBLE_EQ(made[i].time(), -offsets[i]) << i;
    }
    EXPECT_EQ(engine.size(), 5u);
}

// Over random defs: every offset lies in [0, |V|] and, with distinct distances and a curve
// from 0 to 1, the first start is 0 and the last |V| (to rounding: 1e-15 relative).
TEST(Stagger, OffsetsSpanExactlyTheSpread) {
    std::mt19937_64 rng(grape::testing::test_seed(8));
    for (int k = 0; k < 500; ++k) {
        const std::size_t n = 2 + rng() % 40;
        const double amount = std::uniform_real_distribution<double>(-3.0, 3.0)(rng);
        const StaggerFrom from = static_cast<StaggerFrom>(rng() % 6);
        const std::size_t columns = rng() % 2 ? 0 : 1 + rng() % n;
        const StaggerAxis axis = static_cast<StaggerAxis>(rng() % 3);
        const grape::Curve curve = rng() % 2 ? grape::Curve::linear() : grape::Curve::sine_in_out();
        const StaggerDef def{.amount = amount, .from = from, .index = rng() % n, .seed = rng(), .grid = {.columns = columns},
                             .axis = axis, .curve = curve};
        const std::vector<double> got = stagger_offsets(n, def);
        const double spread = std::abs(amount);
        const auto [lo, hi] = std::minmax_element(got.begin(), got.end());
        EXPECT_GE(*lo, 0.0) << k;
        EXPECT_LE(*hi, spread * (1 + 1e-15)) << k;
        if (*hi - *lo > 0.0) {  // not all distances equal (e.g. axis y on one row)
            EXPECT_EQ(*lo, 0.0) << k;
            EXPECT_NEAR(*hi, spread, 1e-15 * spread) << k;
        }
    }
}
