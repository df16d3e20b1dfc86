// 3-D paths: ns per call of point(u), of a frame (rotation-minimizing and reference-up tables)
// and of the global closest point, on a 100-segment centripetal Catmull–Rom spline through
// random points, beside the same calls on the 2-D spline through the same points' (x, y), and
// beside the closest point an engine gives instead: Godot's Curve3D way, a bake of 1,000 points
// at equal arc length scanned segment by segment with squared distances (the careful loop:
// arrays of starts, directions and reciprocal squared lengths made at bake time, one square
// root per query), with its worst distance error against the exact answer printed beside.
// Then the frame tables' build time and size at 10, 100 and 1,000 segments (linear in the
// segments is the claim).
//
//   build-bench/bench/bench_path3 --benchmark_repetitions=7 --benchmark_enable_random_interleaving=true
//       --benchmark_min_time=0.05 --benchmark_report_aggregates_only=true      (one command line)
#include <grape/frames3.hpp>
#include <grape/path.hpp>
#include <grape/path3.hpp>
#include <grape/path_query.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {

using grape::Path3;
using grape::Vec2;
using grape::Vec3;

std::vector<Vec3> random_points(int n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> xy(0.0, 1000.0), z(0.0, 200.0);
    std::vector<Vec3> p;
    for (int i = 0; i < n; ++i) p.push_back({xy(rng), xy(rng), z(rng)});
    return p;
}

const std::vector<Vec3>& points() {
    static const std::vector<Vec3> p = random_points(101, 3);
    return p;
}
const Path3& track3() {
    static const Path3 path = Path3::catmull_rom(points(), grape::CatmullRom::centripetal);
    return path;
}
const grape::CatmullRomSplinePath& track2() {
    static const grape::CatmullRomSplinePath path = [] {
        std::vector<Vec2> flat;
        for (const Vec3& p : points()) flat.push_back({p.x, p.y});
        return grape::CatmullRomSplinePath(flat, grape::CatmullRom::centripetal);
    }();
    return path;
}
const grape::Frames3& rmf() {
    static const grape::Frames3 f(track3(), {.mode = grape::FrameMode::rotation_minimizing, .up = {0, 0, 1}});
    return f;
}
const grape::Frames3& world_up() {
    static const grape::Frames3 f(track3(), {.mode = grape::FrameMode::reference_up, .up = {0, 0, 1}});
    return f;
}

const std::vector<double>& random_u() {
    static const std::vector<double> u = [] {
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::vector<double> out(4096);
        for (double& x : out) x = unit(rng);
        return out;
    }();
    return u;
}

// Queries: half near the path (within 20 units), half anywhere in the box with a margin.
const std::vector<Vec3>& queries() {
    static const std::vector<Vec3> q = [] {
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::vector<Vec3> out;
        for (int i = 0; i < 512; ++i) {
            if (i % 2) {
                out.push_back(track3().point(unit(rng)) + Vec3{40 * unit(rng) - 20, 40 * unit(rng) - 20, 40 * unit(rng) - 20});
            } else {
                out.push_back({1200 * unit(rng) - 100, 1200 * unit(rng) - 100, 400 * unit(rng) - 100});
            }
        }
        return out;
    }();
    return q;
}

// Godot's Curve3D: points at equal arc length, then every baked segment scanned.
struct Bake {
    std::vector<Vec3> start, dir;
    std::vector<double> inv_len2;
    explicit Bake(const Path3& path, int n) {
        std::vector<Vec3> p;
        for (int i = 0; i < n; ++i) p.push_back(path.point_at_length(path.length() * i / (n - 1)));
        for (int i = 0; i + 1 < n; ++i) {
            const Vec3 d = p[i + 1] - p[i];
            start.push_back(p[i]);
            dir.push_back(d);
            const double l2 = dot(d, d);
            inv_len2.push_back(l2 > 0.0 ? 1.0 / l2 : 0.0);
        }
    }
    double distance(Vec3 q) const noexcept {
        double best = HUGE_VAL;
        for (std::size_t i = 0; i < start.size(); ++i) {
            const Vec3 w = q - start[i];
            const double t = std::clamp(dot(w, dir[i]) * inv_len2[i], 0.0, 1.0);
            const Vec3 e = w - dir[i] * t;
            best = std::min(best, dot(e, e));
        }
        return std::sqrt(best);
    }
};
const Bake& bake() {
    static const Bake b(track3(), 1000);
    return b;
}

void BM_point3(benchmark::State& state) {
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(track3().point(random_u()[i++ & 4095]));
    }
}
void BM_point2(benchmark::State& state) {
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(track2().point(random_u()[i++ & 4095]));
    }
}
void BM_frame_rmf(benchmark::State& state) {
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(rmf().frame(random_u()[i++ & 4095]));
    }
}
void BM_frame_world_up(benchmark::State& state) {
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(world_up().frame(random_u()[i++ & 4095]));
    }
}
void BM_closest3(benchmark::State& state) {
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(grape::closest_point(track3(), queries()[i++ & 511]));
    }
}
void BM_closest2(benchmark::State& state) {
    std::size_t i = 0;
    for (auto _ : state) {
        const Vec3 q = queries()[i++ & 511];
        benchmark::DoNotOptimize(grape::closest_point(track2(), Vec2{q.x, q.y}));
    }
}
void BM_closest3_godot_bake_1000(benchmark::State& state) {
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(bake().distance(queries()[i++ & 511]));
    }
}
// Frame table build: a spline of state.range(0) segments through random points.
void BM_frames_build(benchmark::State& state) {
    const auto n = static_cast<int>(state.range(0));
    const Path3 path = Path3::catmull_rom(random_points(n + 1, 5), grape::CatmullRom::centripetal);
    std::size_t knots = 0;
    for (auto _ : state) {
        const grape::RotationMinimizingFrames table(path, {0, 0, 1});
        knots = table.knot_count();
        benchmark::DoNotOptimize(knots);
    }
    state.counters["knots_per_segment"] = static_cast<double>(knots) / n;
    state.counters["bytes_per_segment"] = static_cast<double>(knots * (sizeof(double) + sizeof(Vec3))) / n;
}

BENCHMARK(BM_point3);
BENCHMARK(BM_point2);
BENCHMARK(BM_frame_rmf);
BENCHMARK(BM_frame_world_up);
BENCHMARK(BM_closest3);
BENCHMARK(BM_closest2);
BENCHMARK(BM_closest3_godot_bake_1000);
BENCHMARK(BM_frames_build)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

// The bake's accuracy, beside its time: worst and median distance error against the exact
// closest point, relative to the path's length.
void print_accuracy() {
    std::vector<double> err;
    for (const Vec3& q : queries()) err.push_back(bake().distance(q) - grape::closest_point(track3(), q).distance);
    std::sort(err.begin(), err.end());
    std::printf("bake of 1,000 points: distance error worst %.3g, median %.3g (path length %.6g, %zu queries)\n",
                err.back(), err[err.size() / 2], track3().length(), err.size());
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    print_accuracy();
    // The tables are built before any timing: a build inside the first timed run would set
    // that benchmark's iteration count to 1 for every repetition (one cold call each).
    (void)rmf();
    (void)world_up();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
