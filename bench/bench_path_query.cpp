// Path queries: ns per closest-point query on a 100-segment SVG path (cubic, quadratic, arc and
// line segments), exact (closest_point, and closest_point_from for a dragged point) against
// what engines do instead: bake the path into points and project onto that polyline. Three
// peers: the plain projection loop (hypot and a division per segment), the loop a careful
// engineer writes (squared distances over arrays of the segments' starts, directions and
// reciprocal squared lengths made at bake time, one square root per query), and Godot's way
// (Curve2D bakes at equal arc length, 5 px apart by default, and get_closest_point scans every
// baked segment), with the careful loop. In the same run, each peer's distance error against
// the exact answer, worst and median over the queries.
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

// Points every `spacing` of arc length (and the end), as Godot's Curve2D bakes them.
std::vector<Vec2> bake_by_length(double spacing) {
    const grape::Path arc = svg().reparametrized();
    const double length = svg().length();
    const auto n = static_cast<int>(std::ceil(length / spacing));
    std::vector<Vec2> out;
    for (int i = 0; i <= n; ++i) out.push_back(arc.point(std::min(1.0, i * spacing / length)));
    return out;
}

std::vector<Vec2> bake_by_u(int n) {
    std::vector<Vec2> out;
    for (int i = 0; i <= n; ++i) out.push_back(svg().point(static_cast<double>(i) / n));
    return out;
}

struct Baked {
    std::vector<Vec2> points;
    explicit Baked(int n) : points(bake_by_u(n)) {}
    std::size_t segments() const { return points.size() - 1; }
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

// The careful scan: the segments as arrays (start, direction, 1/|direction|², 0 for a repeated
// point), so the loop is multiplies, adds and a clamp the compiler can vectorize; the squared
// distance is compared and one square root taken at the end.
struct BakedArrays {
    std::vector<double> x, y, dx, dy, inv;
    std::size_t segments() const { return x.size(); }
    explicit BakedArrays(const std::vector<Vec2>& p) {
        for (std::size_t i = 0; i + 1 < p.size(); ++i) {
            const Vec2 d = p[i + 1] - p[i];
            const double l2 = grape::length_squared(d);
            x.push_back(p[i].x);
            y.push_back(p[i].y);
            dx.push_back(d.x);
            dy.push_back(d.y);
            inv.push_back(l2 > 0.0 ? 1.0 / l2 : 0.0);
        }
    }
    double distance(Vec2 q) const {
        double best = std::numeric_limits<double>::infinity();
        const std::size_t n = x.size();
        for (std::size_t i = 0; i < n; ++i) {
            const double qx = q.x - x[i], qy = q.y - y[i];
            const double t = std::clamp((qx * dx[i] + qy * dy[i]) * inv[i], 0.0, 1.0);
            const double ex = qx - t * dx[i], ey = qy - t * dy[i];
            best = std::min(best, ex * ex + ey * ey);
        }
        return std::sqrt(best);
    }
};

// The worst and median distance error of a peer over the queries, as counters.
template <class Table>
void error_counters(benchmark::State& state, const Table& table) {
    std::vector<double> error;
    for (const Vec2 p : queries()) error.push_back(table.distance(p) - grape::closest_point(svg(), p).distance);
    std::sort(error.begin(), error.end());
    state.counters["max_err_px"] = std::max(std::abs(error.front()), std::abs(error.back()));
    state.counters["median_err_px"] = error[error.size() / 2];
    state.counters["segments"] = static_cast<double>(table.segments());
}

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
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(table.distance(q[i++ & 1023]));
    error_counters(state, table);
}

void baked_careful(benchmark::State& state) {
    const BakedArrays table(bake_by_u(static_cast<int>(state.range(0))));
    const auto& q = queries();
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(table.distance(q[i++ & 1023]));
    error_counters(state, table);
}

// Godot's default bake interval, 5 px (Curve2D.bake_interval), and a finer 1 px.
void godot_bake(benchmark::State& state) {
    const BakedArrays table(bake_by_length(static_cast<double>(state.range(0))));
    const auto& q = queries();
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(table.distance(q[i++ & 1023]));
    error_counters(state, table);
}

}  // namespace

BENCHMARK(exact);
BENCHMARK(baked)->Arg(1000)->Arg(10000);
BENCHMARK(baked_careful)->Arg(1000)->Arg(10000);
BENCHMARK(godot_bake)->Arg(5)->Arg(1);
BENCHMARK(exact_dragged);
BENCHMARK(exact_cold_dragged);
BENCHMARK_MAIN();
