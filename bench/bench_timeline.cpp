// Timelines against free animations, ticked at 60 Hz, contenders interleaved
// (--benchmark_enable_random_interleaving):
//   free/N          N free 2-D animations (linear paths, quad-in-out, 1–3 s plays, repeating
//                   with yoyo), as bench_anim's grape_linear
//   timelines/N     the same N animations as N/10 timelines of 10 sequential children
//                   (each child plays once, the timeline repeats forever): N/10 live updates
//                   per tick, one per timeline
//   one_active/K    one timeline of K sequential 0.5 s children (one active at a time): ns
//                   per tick, which should not grow with K
//   create_destroy  create a timeline of 10 fresh animations and kill it: ns each
//   timelines_shared/N  the same, with a timeline's 10 children moving one target
//   timelines_aligned/N the shared workload with durations in whole ticks (hand-overs on ticks)
//   free_floor/N, timelines_floor/N, timelines_shared_floor/N
//                   the memory traffic each workload cannot avoid, per live update
// Reports ns per live update (the children the tick moves) and per animation held, the
// allocations during the timed ticks (0 expected), and a summary with the ratios.
#include <grape/timeline.hpp>

#include "seed_animations.hpp"
#include "heap_hooks.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace {
std::atomic<long long> allocations{0};
}
// Every form of new is counted (aligned, array and nothrow ones included).
void heap_hooks::on_alloc(void*, std::size_t) noexcept { allocations.fetch_add(1, std::memory_order_relaxed); }
void heap_hooks::on_free(void*) noexcept {}

namespace {

constexpr double frame = 1.0 / 60.0;

struct Result {
    std::vector<double> ns;  // per live update (or per tick / per operation), one per repetition
    double median() const {
        std::vector<double> v = ns;
        std::sort(v.begin(), v.end());
        return v.empty() ? 0.0 : v[v.size() / 2];
    }
};
std::map<std::string, Result> results;

double cpu_now() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);  // the machine is shared: count our own time
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Times `step` and reports ns per `per` items; counts allocations inside the timed loop.
template <class Step>
void run(benchmark::State& state, const std::string& name, double per, Step&& step) {
    double seconds = 0;
    std::int64_t frames = 0;
    const long long before = allocations.load();
    for (auto _ : state) {
        const double t0 = cpu_now();
        step();
        seconds += cpu_now() - t0;
        ++frames;
    }
    const double ns = seconds * 1e9 / (static_cast<double>(frames) * per);
    state.counters["ns"] = ns;
    state.counters["allocs_per_iter"] = static_cast<double>(allocations.load() - before) / static_cast<double>(frames);
    results[name].ns.push_back(ns);
}

const std::vector<grape::Path>& linear_paths() {
    static const auto paths =
        grape::scenes::bench_paths(grape::scenes::BenchPathKind::linear, grape::scenes::bench_segments(1024));
    return paths;
}

void BM_free(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<grape::scenes::BenchTarget> targets(n);
    auto engine = std::make_unique<grape::Engine>();
    grape::scenes::create_bench_animations(*engine, targets, linear_paths(), grape::Curve::quad_in_out());
    engine->tick(frame);
    run(state, "free/" + std::to_string(n), static_cast<double>(n), [&] {
        engine->tick(frame);
        benchmark::ClobberMemory();
    });
    benchmark::DoNotOptimize(targets.data());
}

// shared: the 10 children of a timeline move one target (a sequence of moves of one object),
// so the live updates write N/10 targets side by side, as free animations write theirs.
// aligned (with shared): the children last whole ticks (60 to 180 of them, 1–3 s as above),
// as durations of 0.5 s or 30 frames do at 60 Hz: every hand-over lands on a tick, or
// within rounding of one.
void timelines_bench(benchmark::State& state, bool shared, bool aligned = false) {
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<grape::scenes::BenchTarget> targets(shared ? n / 10 : n);
    auto engine = std::make_unique<grape::Engine>();
    const auto& paths = linear_paths();
    const grape::AnimationDef def{.curve = grape::Curve::quad_in_out()};
    for (std::size_t t = 0; t < n / 10; ++t) {
        grape::Timeline tl = engine->create_timeline({.repeat = -1});
        for (std::size_t k = 0; k < 10; ++k) {
            const std::size_t i = t * 10 + k;
            const double duration =
                aligned ? static_cast<double>(60 + (i * 7) % 121) * frame : grape::scenes::bench_duration(i);
            tl.add(engine->create_2d_animation(targets[shared ? t : i], paths[i % paths.size()], duration, def));
        }
    }
    engine->tick(frame);
    const std::string name = aligned ? "timelines_aligned/" : shared ? "timelines_shared/" : "timelines/";
    run(state, name + std::to_string(n), static_cast<double>(n / 10), [&] {
        engine->tick(frame);
        benchmark::ClobberMemory();
    });
    benchmark::DoNotOptimize(targets.data());
}

// The memory-traffic floors of the two workloads, per live update: what a tick cannot avoid
// moving, with nothing computed. Free: each 32-byte record read, its first double written
// back and 16 bytes written to its target, in order (bench_anim's traffic_floor). Timelines:
// each timeline's 64-byte line read and its first double written back, and 16 bytes written
// to the target of its active child, which lies 10 targets (160 bytes) after the previous
// timeline's: a line of its own.
struct FreeRecord {
    double phase;
    double rate;
    grape::scenes::BenchTarget* target;
    std::uint64_t rest;
};
struct alignas(64) TimelineLine {
    double elapsed;
    double rate;
    grape::scenes::BenchTarget* target;
    std::uint64_t rest[5];
};

void BM_free_floor(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<grape::scenes::BenchTarget> targets(n);
    std::vector<FreeRecord> records(n);
    for (std::size_t i = 0; i < n; ++i) records[i] = {0.0, 1.0 / grape::scenes::bench_duration(i), &targets[i], i};
    run(state, "free_floor/" + std::to_string(n), static_cast<double>(n), [&] {
        for (FreeRecord& r : records) {
            r.phase += frame * r.rate;
            r.target->x = r.phase;
            r.target->y = r.rate;
        }
        benchmark::ClobberMemory();
    });
    benchmark::DoNotOptimize(targets.data());
}

void timelines_floor(benchmark::State& state, bool shared) {
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<grape::scenes::BenchTarget> targets(shared ? n / 10 : n);
    std::vector<TimelineLine> lines(n / 10);
    for (std::size_t t = 0; t < n / 10; ++t)
        lines[t] = {0.0, 1.0 / grape::scenes::bench_duration(t), &targets[shared ? t : t * 10 + t % 10], {t}};
    run(state, (shared ? "timelines_shared_floor/" : "timelines_floor/") + std::to_string(n), static_cast<double>(n / 10), [&] {
        for (TimelineLine& l : lines) {
            l.elapsed += frame;
            l.target->x = l.elapsed;
            l.target->y = l.rate;
        }
        benchmark::ClobberMemory();
    });
    benchmark::DoNotOptimize(targets.data());
}

void BM_timelines(benchmark::State& state) { timelines_bench(state, false); }
void BM_timelines_shared(benchmark::State& state) { timelines_bench(state, true); }
void BM_timelines_aligned(benchmark::State& state) { timelines_bench(state, true, true); }
void BM_timelines_floor(benchmark::State& state) { timelines_floor(state, false); }
void BM_timelines_shared_floor(benchmark::State& state) { timelines_floor(state, true); }

void BM_one_active(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<grape::scenes::BenchTarget> targets(n);
    auto engine = std::make_unique<grape::Engine>();
    const auto& paths = linear_paths();
    grape::Timeline tl = engine->create_timeline({.repeat = -1});
    for (std::size_t i = 0; i < n; ++i) tl.add(engine->create_2d_animation(targets[i], paths[i % paths.size()], 0.5));
    engine->tick(frame);
    // 100 ticks per timed block: the thread clock costs more than one small tick.
    run(state, "one_active/" + std::to_string(n), 100.0, [&] {
        for (int k = 0; k < 100; ++k) engine->tick(frame);
        benchmark::ClobberMemory();
    });
    benchmark::DoNotOptimize(targets.data());
}

void BM_create_destroy(benchmark::State& state) {
    std::vector<grape::scenes::BenchTarget> targets(10);
    auto engine = std::make_unique<grape::Engine>();
    const auto& paths = linear_paths();
    double seconds = 0;
    std::int64_t count = 0;
    for (auto _ : state) {
        const double t0 = cpu_now();
        for (int b = 0; b < 100; ++b) {  // 100 per timed block, as above
            grape::Timeline tl = engine->create_timeline();
            for (std::size_t k = 0; k < 10; ++k) tl.add(engine->create_2d_animation(targets[k], paths[k], 0.5));
            tl.kill();
        }
        seconds += cpu_now() - t0;
        count += 100;
    }
    const double ns = seconds * 1e9 / static_cast<double>(count);
    state.counters["ns"] = ns;
    results["create_destroy"].ns.push_back(ns);
}

// No MinTime here, so that --benchmark_min_time applies (0.5 s by default).
BENCHMARK(BM_free)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_timelines)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_free_floor)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_timelines_floor)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_timelines_shared)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_timelines_shared_floor)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_timelines_aligned)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_one_active)->Arg(10)->Arg(100000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_create_destroy)->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    auto median = [](const std::string& k) {
        const auto it = results.find(k);
        return it == results.end() ? 0.0 : it->second.median();
    };
    const double free_ns = median("free/1000000"), tl_ns = median("timelines/1000000");
    std::printf("\nmedians over repetitions\n");
    std::printf("free animations, ns per live update:          %8.2f\n", free_ns);
    std::printf("timelines, ns per live update (1 per timeline):%8.2f  (%.2fx free)\n", tl_ns,
                free_ns > 0 ? tl_ns / free_ns : 0.0);
    std::printf("timelines, ns per animation held per tick:     %8.2f  (%.2fx free)\n", tl_ns / 10,
                free_ns > 0 ? tl_ns / 10 / free_ns : 0.0);
    const double free_floor = median("free_floor/1000000"), tl_floor = median("timelines_floor/1000000");
    auto of = [](double a, double b) { return b > 0 ? a / b : 0.0; };
    std::printf("traffic floors, ns per live update: free %.2f, timelines %.2f (%.2fx free's)\n", free_floor, tl_floor,
                of(tl_floor, free_floor));
    std::printf("free / its floor %.2fx, timelines / their floor %.2fx\n", of(free_ns, free_floor), of(tl_ns, tl_floor));
    const double sh_ns = median("timelines_shared/1000000"), sh_floor = median("timelines_shared_floor/1000000");
    std::printf("shared targets: timelines %.2f ns per live update (%.2fx free), floor %.2f (%.2fx free's); %.2fx their floor\n",
                sh_ns, of(sh_ns, free_ns), sh_floor, of(sh_floor, free_floor), of(sh_ns, sh_floor));
    const double al_ns = median("timelines_aligned/1000000");
    std::printf("shared targets, durations in whole ticks: timelines %.2f ns per live update (%.2fx free, %.2fx shared)\n",
                al_ns, of(al_ns, free_ns), of(al_ns, sh_ns));
    std::printf("one active of 10, ns per tick:                 %8.1f\n", median("one_active/10"));
    std::printf("one active of 100000, ns per tick:             %8.1f  (%.2fx of 10)\n", median("one_active/100000"),
                median("one_active/10") > 0 ? median("one_active/100000") / median("one_active/10") : 0.0);
    std::printf("create + destroy a 10-child timeline, ns:      %8.0f\n", median("create_destroy"));
    return 0;
}
