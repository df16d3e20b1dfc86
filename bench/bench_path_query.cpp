// Path queries: ns per closest-point query on a 100-segment SVG path (cubic, quadratic, arc and
// line segments), exact (closest_point, and closest_point_from for a dragged point) against
// what engines do instead: bake the path into N points evenly in u and project onto that
// polyline (Godot's Curve2D.get_closest_point works on its baked points). In the same run, the
// baked answers' distance error against the exact one, worst and median over the queries.
//
//   build-bench/bench/bench_path_query --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <grape/path.hpp>
#include <grape/path_query.hpp>

#include "seed_paths.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace {

using grape::ClosestPoint;
using grape::Path;
using grape::Vec2;

const Path& svg() {
    static const Path path = grape::parse_svg_path(grape::scenes::hundred_segments_svg());
    return path;
}

// Queries: random in the box with a margin, half of them within 20 px of the path.
const std::vector<Vec2>& queries() {
    static const std::vector<Vec2> q = [] {
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::vector<Vec2> out;
        for (int i = 0; i < 1024; ++i) {
            if (i % 2) {
                const Vec2 p = svg().point(unit(rng));
                out.push_back(p + Vec2{40 * unit(rng) - 20, 40 * unit(rng) - 20});
            } else {
                out.push_back({1200 * unit(rng) - 100, 1200 * unit(rng) - 100});
            }
        }
        return out;
    }();
    return q;
}

// A dragged point: small steps along a wandering line, so each answer is near the last.
const std::vector<Vec2>& drag() {
    static const std::vector<Vec2> q = [] {
        std::vector<Vec2> out;
        for (int i = 0; i < 1024; ++i) {
            const double t = i / 1023.0;
            out.push_back({100 + 800 * t, 500 + 300 * std::sin(6 * t)});
        }
        return out;
    }();
    return q;
}

struct Baked {
    std::vector<Vec2> points;
    explicit Baked(int n) {
        for (int i = 0; i <= n; ++i) points.push_back(svg().point(static_cast<double>(i) / n));
    }
    double distance(Vec2 q) const {
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            const Vec2 d = points[i + 1] - points[i];
            const double l2 = grape::length_squared(d);
            const double t = l2 > 0.0 ? std::clamp(grape::dot(q - points[i], d) / l2, 0.0, 1.0) : 0.0;
            best = std::min(best, grape::distance(q, points[i] + d * t));
        }
        return best;
    }
};

void exact(benchmark::State& state) {
    const auto& q = queries();
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(grape::closest_point(svg(), q[i++ & 1023]));
}

void exact_dragged(benchmark::State& state) {
    const auto& q = drag();
    std::size_t i = 0;
    double last = 0.0;
    for (auto _ : state) {
        const ClosestPoint c = grape::closest_point_from(svg(), q[i++ & 1023], last);
        last = c.u;
        benchmark::DoNotOptimize(c);
    }
}

void exact_cold_dragged(benchmark::State& state) {
    const auto& q = drag();
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(grape::closest_point(svg(), q[i++ & 1023]));
}

void baked(benchmark::State& state) {
    const Baked table(static_cast<int>(state.range(0)));
    const auto& q = queries();
    std::vector<double> error;
    for (const Vec2 p : q) error.push_back(table.distance(p) - grape::closest_point(svg(), p).distance);
    std::sort(error.begin(), error.end());
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(table.distance(q[i++ & 1023]));
    state.counters["max_err_px"] = std::max(std::abs(error.front()), std::abs(error.back()));
    state.counters["median_err_px"] = error[error.size() / 2];
}

}  // namespace

BENCHMARK(exact);
BENCHMARK(baked)->Arg(1000)->Arg(10000);
BENCHMARK(exact_dragged);
BENCHMARK(exact_cold_dragged);
BENCHMARK_MAIN();
