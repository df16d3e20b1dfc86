// N live 2-D animations, quad-in-out, repeating with yoyo, bound to plain structs, ticked at
// 60 Hz: grape's engine along (a) linear paths, (b) cubic Béziers, (c) arc-length
// reparametrized cubic Béziers; tweeny doing the same journeys on two floats (linear and
// quad-in-out); and a hand-written loop over plain structs with the same arithmetic (the
// floor). Paths are shared: K = 1024 distinct shapes (scenes::bench_paths; GRAPE_BENCH_PATHS
// sets fewer), animation i takes shape i % K. 3-D rows (grape3_*) do the same along 3-D cubics,
// plain and with the frame's orientation. Reports ns per animation update and bytes per
// animation, then a summary with the ratios.
#include <grape/anim.hpp>
#include <grape/color.hpp>

#include "seed_animations.hpp"
#include "heap_hooks.hpp"

#include <benchmark/benchmark.h>

// tweeny 3's headers are not self-contained under g++ 12.
#include <array>
#include <cmath>
#include <cstdint>
#include <tweeny/tweeny.h>

#include <algorithm>
#include <atomic>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <malloc.h>
#include <map>
#include <memory>
#include <new>
#include <string>
#include <vector>

// Live heap bytes, to measure bytes per animation the same way for every contender.
namespace {
std::atomic<long long> live_bytes{0};
}
// Counts what malloc really hands out (malloc_usable_size), so both sides of new/delete agree;
// every form of new is counted (the engine's alignas(64) storage goes through the aligned ones).
void heap_hooks::on_alloc(void* block, std::size_t) noexcept {
    live_bytes.fetch_add(static_cast<long long>(malloc_usable_size(block)), std::memory_order_relaxed);
}
void heap_hooks::on_free(void* block) noexcept {
    live_bytes.fetch_sub(static_cast<long long>(malloc_usable_size(block)), std::memory_order_relaxed);
}

namespace {

using grape::scenes::BenchPathKind;
// GRAPE_BENCH_PATHS=K (1 … 1024) shares K shapes instead: with few, the arc-length tables
// stay in cache, which splits that row's cost into the tables' traffic and the arithmetic.
std::size_t shared_paths() {
    const char* text = std::getenv("GRAPE_BENCH_PATHS");
    if (!text) return 1024;
    char* end = nullptr;
    const unsigned long k = std::strtoul(text, &end, 10);
    if (end == text || *end != '\0' || k < 1 || k > 1024) {
        std::fprintf(stderr, "GRAPE_BENCH_PATHS must be 1 ... 1024 (got '%s')\n", text);
        std::exit(2);
    }
    return k;
}
const std::size_t distinct_paths = shared_paths();
constexpr double frame = 1.0 / 60.0;

struct Result {
    std::vector<double> ns_per_update;  // one per repetition
    double bytes_per_animation = 0;
    double median() const {
        std::vector<double> v = ns_per_update;
        std::sort(v.begin(), v.end());
        return v.empty() ? 0.0 : v[v.size() / 2];
    }
};
std::map<std::string, Result> results;  // "name/N"

std::string key(const char* name, std::int64_t n) { return std::string(name) + "/" + std::to_string(n); }

// Times the loop body ourselves too (steady clock), so the summary can print ratios.
// wall: wall-clock time instead (a parallel tick's work is on several threads).
// frame_work > 0: before each timed step the calling thread stays busy, untimed, until
// `frame_work` seconds have passed since the previous step began (a game's own work in a
// frame), so that the step runs once a frame as in a game, not back to back.
template <class Step>
void run(benchmark::State& state, const char* name, double bytes, Step&& step, bool wall = false,
         double frame_work = 0.0) {
    const auto n = state.range(0);
    double seconds = 0;
    std::int64_t frames = 0;
    // Thread CPU time: the machine is shared, and wall time counts the other jobs' turns.
    auto now = [wall] {
        timespec ts{};
        clock_gettime(wall ? CLOCK_MONOTONIC : CLOCK_THREAD_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    };
    auto cpu = [] {
        timespec ts{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    };
    double cpu_seconds = 0;  // the calling thread's CPU time, beside wall time
    double begun = now();
    for (auto _ : state) {
        if (frame_work > 0.0) {
            while (now() < begun + frame_work) benchmark::ClobberMemory();
            begun = now();
        }
        const double c0 = wall ? cpu() : 0.0, t0 = now();
        step();
        seconds += now() - t0;
        if (wall) cpu_seconds += cpu() - c0;
        ++frames;
    }
    const double ns = seconds * 1e9 / static_cast<double>(frames * n);
    if (wall) results[key((std::string(name) + "_cpu").c_str(), n)].ns_per_update.push_back(cpu_seconds * 1e9 / static_cast<double>(frames * n));
    state.counters["ns_per_update"] = ns;
    state.counters["bytes_per_anim"] = bytes;
    state.SetItemsProcessed(frames * n);
    Result& r = results[key(name, n)];
    r.ns_per_update.push_back(ns);
    r.bytes_per_animation = bytes;
}

// spread > 0: one tick of `spread` seconds before timing, so that the animations sharing a
// path sit at different phases (plays last 1–3 s: phase i = frac(spread / duration i)).
void grape_engine(benchmark::State& state, BenchPathKind kind, const char* name, double spread = 0.0) {
    const auto n = static_cast<std::size_t>(state.range(0));
    const auto segments = grape::scenes::bench_segments(distinct_paths);
    const auto paths = grape::scenes::bench_paths(kind, segments);  // shared shapes: not counted
    std::vector<grape::scenes::BenchTarget> targets(n);
    const long long before = live_bytes.load();
    auto engine = std::make_unique<grape::Engine>();
    grape::scenes::create_bench_animations(*engine, targets, paths, grape::Curve::quad_in_out());
    const double bytes = static_cast<double>(live_bytes.load() - before) / static_cast<double>(n);
    engine->tick(spread > 0.0 ? spread : frame);
    run(state, name, bytes, [&] {
        engine->tick(frame);
        benchmark::ClobberMemory();
    });
    benchmark::DoNotOptimize(targets.data());
}

// The parallel tick against the one-pass tick, both in wall-clock time, on the linear kind.
// threads 0: one-pass; else Engine::set_parallel({.threads, .min_animations = 0}).
// once_a_frame: one tick per 60 Hz frame, the calling thread busy between ticks (run's
// frame_work), so that the workers have gone to sleep when a tick opens (awake: 200 µs).
void grape_engine_wall(benchmark::State& state, BenchPathKind kind, const char* name, int threads,
                       bool once_a_frame = false) {
    const auto n = static_cast<std::size_t>(state.range(0));
    const auto segments = grape::scenes::bench_segments(distinct_paths);
    const auto paths = grape::scenes::bench_paths(kind, segments);
    std::vector<grape::scenes::BenchTarget> targets(n);
    const long long before = live_bytes.load();
    auto engine = std::make_unique<grape::Engine>();
    grape::scenes::create_bench_animations(*engine, targets, paths, grape::Curve::quad_in_out());
    const double bytes = static_cast<double>(live_bytes.load() - before) / static_cast<double>(n);
    if (threads > 0) engine->set_parallel({.threads = threads, .min_animations = 0});  // 10⁵ too: below the default
    engine->tick(frame);
    run(
        state, name, bytes,
        [&] {
            engine->tick(frame);
            benchmark::ClobberMemory();
        },
        true, once_a_frame ? frame : 0.0);
    benchmark::DoNotOptimize(targets.data());
}
void BM_wall_one_pass(benchmark::State& s) { grape_engine_wall(s, BenchPathKind::linear, "wall_one_pass", 0); }
void BM_wall_two_phase_1(benchmark::State& s) { grape_engine_wall(s, BenchPathKind::linear, "wall_two_phase_1", 1); }
void BM_wall_parallel_2(benchmark::State& s) { grape_engine_wall(s, BenchPathKind::linear, "wall_parallel_2", 2); }
void BM_wall_frame_one_pass(benchmark::State& s) {
    grape_engine_wall(s, BenchPathKind::linear, "wall_frame_one_pass", 0, true);
}
void BM_wall_frame_parallel_2(benchmark::State& s) {
    grape_engine_wall(s, BenchPathKind::linear, "wall_frame_parallel_2", 2, true);
}

void BM_grape_linear(benchmark::State& s) { grape_engine(s, BenchPathKind::linear, "grape_linear"); }
void BM_grape_cubic(benchmark::State& s) { grape_engine(s, BenchPathKind::cubic_bezier, "grape_cubic"); }
void BM_grape_reparam_cubic(benchmark::State& s) {
    grape_engine(s, BenchPathKind::reparametrized_cubic_bezier, "grape_reparam_cubic");
}
// The same two kinds with the phases spread out (1000.37 s into the run).
void BM_grape_cubic_spread(benchmark::State& s) {
    grape_engine(s, BenchPathKind::cubic_bezier, "grape_cubic_spread", 1000.37);
}
void BM_grape_reparam_cubic_spread(benchmark::State& s) {
    grape_engine(s, BenchPathKind::reparametrized_cubic_bezier, "grape_reparam_cubic_spread", 1000.37);
}

// Arc length where the tables are large: random cubics and 8-segment SVG paths, by u and by
// arc length, phases spread.
void BM_grape_random_cubic_spread(benchmark::State& s) {
    grape_engine(s, BenchPathKind::random_cubic_bezier, "grape_random_cubic_spread", 1000.37);
}
void BM_grape_reparam_random_cubic_spread(benchmark::State& s) {
    grape_engine(s, BenchPathKind::reparametrized_random_cubic_bezier, "grape_reparam_random_cubic_spread", 1000.37);
}
void BM_grape_svg_spread(benchmark::State& s) { grape_engine(s, BenchPathKind::svg, "grape_svg_spread", 1000.37); }
void BM_grape_reparam_svg_spread(benchmark::State& s) {
    grape_engine(s, BenchPathKind::reparametrized_svg, "grape_reparam_svg_spread", 1000.37);
}

// tweeny: each tween owns its two start and two end floats; integer duration in ms
// (during(1000·d)), stepped by the fraction of its duration, yoyo by hand (tweeny 3 has no
// loops): the sign flips at either end.
struct FloatTarget {
    float x = 0, y = 0;
};

template <class Easing>
void tweeny_bench(benchmark::State& state, Easing easing, const char* name) {
    const auto n = static_cast<std::size_t>(state.range(0));
    const auto segments = grape::scenes::bench_segments(distinct_paths);
    std::vector<FloatTarget> targets(n);
    const long long before = live_bytes.load();
    using Tween = tweeny::tween<float, float>;
    auto tweens = std::make_unique<std::vector<Tween>>();
    auto step_of = std::make_unique<std::vector<float>>(n);  // signed fraction per frame
    tweens->reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto& s = segments[i % distinct_paths];
        const double d = grape::scenes::bench_duration(i);
        tweens->push_back(tweeny::from(static_cast<float>(s.from.x), static_cast<float>(s.from.y))
                              .to(static_cast<float>(s.to.x), static_cast<float>(s.to.y))
                              .during(static_cast<std::uint16_t>(1000.0 * d))
                              .via(easing, easing));
        (*step_of)[i] = static_cast<float>(frame / d);
    }
    const double bytes = static_cast<double>(live_bytes.load() - before) / static_cast<double>(n);
    run(state, name, bytes, [&] {
        for (std::size_t i = 0; i < n; ++i) {
            Tween& t = (*tweens)[i];
            float& dp = (*step_of)[i];
            const auto& v = t.step(dp);
            targets[i].x = v[0];
            targets[i].y = v[1];
            const float p = t.progress();
            if ((dp > 0 && p >= 1.0f) || (dp < 0 && p <= 0.0f)) dp = -dp;
        }
        benchmark::ClobberMemory();
    });
    benchmark::DoNotOptimize(targets.data());
}

void BM_tweeny_linear(benchmark::State& s) { tweeny_bench(s, tweeny::easing::linear, "tweeny_linear"); }
void BM_tweeny_quad(benchmark::State& s) { tweeny_bench(s, tweeny::easing::quadraticInOut, "tweeny_quad"); }

// The floor: plain structs, the shared segments, quad-in-out, yoyo; nothing else.
struct Plain {
    double phase;
    double rate;
    std::uint32_t segment;
    bool backward;
};

void BM_floor(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    const auto segments = grape::scenes::bench_segments(distinct_paths);
    std::vector<grape::Vec2> a(distinct_paths), delta(distinct_paths);
    for (std::size_t k = 0; k < distinct_paths; ++k) {
        a[k] = segments[k].from;
        delta[k] = segments[k].to - segments[k].from;
    }
    std::vector<grape::scenes::BenchTarget> targets(n);
    const long long before = live_bytes.load();
    auto anims = std::make_unique<std::vector<Plain>>(n);
    for (std::size_t i = 0; i < n; ++i)
        (*anims)[i] = {0.0, 1.0 / grape::scenes::bench_duration(i), static_cast<std::uint32_t>(i % distinct_paths), false};
    const double bytes = static_cast<double>(live_bytes.load() - before) / static_cast<double>(n);
    run(state, "floor", bytes, [&] {
        Plain* p = anims->data();
        for (std::size_t i = 0; i < n; ++i) {
            double phase = p[i].phase + frame * p[i].rate;
            if (phase >= 1.0) {
                phase -= 1.0;
                p[i].backward = !p[i].backward;
            }
            p[i].phase = phase;
            const double x = p[i].backward ? 1.0 - phase : phase;
            const double e = grape::ease::quad_in_out(x);
            const grape::Vec2 v = a[p[i].segment] + delta[p[i].segment] * e;
            targets[i].x = v.x;
            targets[i].y = v.y;
        }
        benchmark::ClobberMemory();
    });
    benchmark::DoNotOptimize(targets.data());
}

// The memory-traffic floor of a tick: each 32-byte record read, its first double written
// back, 16 bytes written to its target (the engine's hot record and write, nothing computed).
struct Record {
    double phase;
    double rate;
    grape::scenes::BenchTarget* target;
    std::uint64_t rest;
};
static_assert(sizeof(Record) == 32);

void BM_traffic_floor(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<grape::scenes::BenchTarget> targets(n);
    const long long before = live_bytes.load();
    auto records = std::make_unique<std::vector<Record>>(n);
    for (std::size_t i = 0; i < n; ++i) (*records)[i] = {0.0, 1.0 / grape::scenes::bench_duration(i), &targets[i], i};
    const double bytes = static_cast<double>(live_bytes.load() - before) / static_cast<double>(n);
    run(state, "traffic_floor", bytes, [&] {
        Record* r = records->data();
        for (std::size_t i = 0; i < n; ++i) {
            const double phase = r[i].phase + frame * r[i].rate;
            r[i].phase = phase;
            r[i].target->x = phase;
            r[i].target->y = r[i].rate;
        }
        benchmark::ClobberMemory();
    });
    benchmark::DoNotOptimize(targets.data());
}

// Typed values: N animations of one member of a plain struct, same durations, curve and
// yoyo, through Engine::animate: a colour (linear light), a colour in OKLab, a user type with
// its own lerp (three doubles), and a double.
namespace user {
struct Hsv {
    double h = 0, s = 0, v = 0;
};
Hsv lerp(const Hsv& a, const Hsv& b, double t) noexcept {
    return {a.h + (b.h - a.h) * t, a.s + (b.s - a.s) * t, a.v + (b.v - a.v) * t};
}
}  // namespace user

struct TypedTarget {
    grape::Color tint{};
    user::Hsv hsv{};
    double value = 0;
};

enum class TypedKind { color, color_oklab, user, scalar };

void typed_bench(benchmark::State& state, TypedKind kind, const char* name) {
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<TypedTarget> targets(n);
    const long long before = live_bytes.load();
    auto engine = std::make_unique<grape::Engine>();
    const grape::AnimationDef def{.curve = grape::Curve::quad_in_out(), .repeat = -1, .yoyo = true};
    for (std::size_t i = 0; i < n; ++i) {
        const double d = grape::scenes::bench_duration(i);
        const double k = static_cast<double>(i % 1024) / 1024.0;
        switch (kind) {
            case TypedKind::color:
                engine->animate(targets[i], &TypedTarget::tint, grape::from_to(grape::Color{k, 0.2, 0.9, 1}, grape::Color{0.1, k, 0.3, 0.5}), d, def);
                break;
            case TypedKind::color_oklab:
                engine->animate(targets[i], &TypedTarget::tint, grape::from_to(grape::Color{k, 0.2, 0.9, 1}, grape::Color{0.1, k, 0.3, 0.5}), d, def,
                                grape::ColorLerp{grape::ColorSpace::oklab});
                break;
            case TypedKind::user:
                engine->animate(targets[i], &TypedTarget::hsv, grape::from_to(user::Hsv{k, 1, 1}, user::Hsv{360 * k, 0.5, 0}), d, def);
                break;
            case TypedKind::scalar:
                engine->animate(targets[i], &TypedTarget::value, grape::from_to(k, 1000 * k), d, def);
                break;
        }
    }
    const double bytes = static_cast<double>(live_bytes.load() - before) / static_cast<double>(n);
    engine->tick(frame);
    run(state, name, bytes, [&] {
        engine->tick(frame);
        benchmark::ClobberMemory();
    });
    benchmark::DoNotOptimize(targets.data());
}

void BM_grape_color(benchmark::State& s) { typed_bench(s, TypedKind::color, "grape_color"); }
void BM_grape_color_oklab(benchmark::State& s) { typed_bench(s, TypedKind::color_oklab, "grape_color_oklab"); }
void BM_grape_user_type(benchmark::State& s) { typed_bench(s, TypedKind::user, "grape_user_type"); }
void BM_grape_typed_double(benchmark::State& s) { typed_bench(s, TypedKind::scalar, "grape_typed_double"); }

// The property animation of one double (create_property_animation), for the typed double.
void BM_grape_property_double(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<TypedTarget> targets(n);
    const long long before = live_bytes.load();
    auto engine = std::make_unique<grape::Engine>();
    const grape::AnimationDef def{.curve = grape::Curve::quad_in_out(), .repeat = -1, .yoyo = true};
    for (std::size_t i = 0; i < n; ++i) {
        const double k = static_cast<double>(i % 1024) / 1024.0;
        engine->create_property_animation(targets[i], {&TypedTarget::value}, {k}, {1000 * k},
                                          grape::scenes::bench_duration(i), def);
    }
    const double bytes = static_cast<double>(live_bytes.load() - before) / static_cast<double>(n);
    engine->tick(frame);
    run(state, "grape_property_double", bytes, [&] {
        engine->tick(frame);
        benchmark::ClobberMemory();
    });
    benchmark::DoNotOptimize(targets.data());
}

// 3-D: N animations along K shared 3-D cubic Béziers (the same timing as grape_cubic: quad-in-out,
// repeating, yoyo, 1–3 s plays), writing x, y, z (plain) and also a Basis from each path's
// rotation-minimizing frame, its table built once per shape and shared (oriented).
struct Body3 {
    double x = 0, y = 0, z = 0;
    grape::Basis orientation;
};

void grape3_engine(benchmark::State& state, bool oriented, const char* name) {
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<grape::Path3> paths;
    std::vector<std::shared_ptr<const grape::Frames3>> frames;
    for (std::size_t k = 0; k < distinct_paths; ++k) {
        const double a = static_cast<double>(k) / static_cast<double>(distinct_paths);
        paths.push_back(grape::Path3::cubic_bezier({0, 0, 0}, {100 * a, 200, 50}, {300, 200 * a, 100 - 50 * a},
                                                   {400, 100 * a, 200}));
        if (oriented) frames.push_back(std::make_shared<const grape::Frames3>(paths.back(), grape::FramesDef{.up = {0, 0, 1}}));
    }
    std::vector<Body3> targets(n);
    const long long before = live_bytes.load();
    auto engine = std::make_unique<grape::Engine>();
    const grape::AnimationDef def{.curve = grape::Curve::quad_in_out(), .repeat = -1, .yoyo = true};
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t k = i % paths.size();
        grape::Motion3Def motion;
        if (oriented) {
            motion.align = grape::Align3::frame;
            motion.shared_frames = frames[k];
        }
        engine->create_3d_animation(targets[i], paths[k], grape::scenes::bench_duration(i), def, motion);
    }
    const double bytes = static_cast<double>(live_bytes.load() - before) / static_cast<double>(n);
    engine->tick(frame);
    run(state, name, bytes, [&] {
        engine->tick(frame);
        benchmark::ClobberMemory();
    });
    benchmark::DoNotOptimize(targets.data());
}
void BM_grape3_cubic(benchmark::State& s) { grape3_engine(s, false, "grape3_cubic"); }
void BM_grape3_cubic_frame(benchmark::State& s) { grape3_engine(s, true, "grape3_cubic_frame"); }

void sizes(benchmark::internal::Benchmark* b) {
    b->Arg(1000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);  // --benchmark_min_time applies (0.5 s by default)
}

BENCHMARK(BM_floor)->Apply(sizes);
BENCHMARK(BM_traffic_floor)->Apply(sizes);
BENCHMARK(BM_wall_one_pass)->Apply(sizes);
BENCHMARK(BM_wall_two_phase_1)->Apply(sizes);
BENCHMARK(BM_wall_parallel_2)->Apply(sizes);
// 16.7 ms a repetition's iteration: the large sizes only, where a parallel tick may pay.
BENCHMARK(BM_wall_frame_one_pass)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_wall_frame_parallel_2)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_grape_linear)->Apply(sizes);
BENCHMARK(BM_grape_cubic)->Apply(sizes);
BENCHMARK(BM_grape_reparam_cubic)->Apply(sizes);
BENCHMARK(BM_grape_cubic_spread)->Apply(sizes);
BENCHMARK(BM_grape_reparam_cubic_spread)->Apply(sizes);
BENCHMARK(BM_grape_random_cubic_spread)->Apply(sizes);
BENCHMARK(BM_grape_reparam_random_cubic_spread)->Apply(sizes);
BENCHMARK(BM_grape_svg_spread)->Apply(sizes);
BENCHMARK(BM_grape_reparam_svg_spread)->Apply(sizes);
BENCHMARK(BM_tweeny_linear)->Apply(sizes);
BENCHMARK(BM_tweeny_quad)->Apply(sizes);
BENCHMARK(BM_grape_color)->Apply(sizes);
BENCHMARK(BM_grape_color_oklab)->Apply(sizes);
BENCHMARK(BM_grape_user_type)->Apply(sizes);
BENCHMARK(BM_grape_typed_double)->Apply(sizes);
BENCHMARK(BM_grape_property_double)->Apply(sizes);
BENCHMARK(BM_grape3_cubic)->Apply(sizes);
BENCHMARK(BM_grape3_cubic_frame)->Apply(sizes);

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    // Summary: updates per second relative to tweeny quad-in-out (higher is better) and to
    // the floor (1 = as fast as the hand-written loop); medians over repetitions.
    std::printf("\nengine storage per 2-D animation: %zu bytes (hot + cold + handle slot)\n",
                grape::Engine::bytes_per_animation());
    // A ratio to a contender that was not run (filtered out) prints as "-", not as 0.
    std::printf("%-26s %9s %12s %12s %14s %12s %14s\n", "contender", "N", "ns/update", "bytes/anim",
                "x tweeny_quad", "floor/this", "traffic/this");
    auto ratio_text = [](const std::map<std::string, Result>::const_iterator& ref, double r) {
        if (ref == results.end() || !(r > 0.0)) return std::string("-");
        char text[32];
        std::snprintf(text, sizeof text, "%.2f", ref->second.median() / r);
        return std::string(text);
    };
    for (std::int64_t n : {1000, 100000, 1000000}) {
        const auto tw = results.find(key("tweeny_quad", n));
        const auto fl = results.find(key("floor", n));
        const auto tf = results.find(key("traffic_floor", n));
        for (const char* name : {"floor", "traffic_floor", "grape_linear", "grape_cubic", "grape_reparam_cubic", "grape_cubic_spread",
                                 "grape_reparam_cubic_spread", "grape_random_cubic_spread",
                                 "grape_reparam_random_cubic_spread", "grape_svg_spread", "grape_reparam_svg_spread",
                                 "tweeny_linear", "tweeny_quad", "grape_color",
                                 "grape_color_oklab", "grape_user_type", "grape_typed_double",
                                 "grape_property_double", "grape3_cubic", "grape3_cubic_frame", "wall_one_pass", "wall_two_phase_1", "wall_parallel_2",
                                 "wall_frame_one_pass", "wall_frame_parallel_2"}) {
            const auto it = results.find(key(name, n));
            if (it == results.end()) continue;
            const double r = it->second.median();
            std::printf("%-26s %9lld %12.2f %12.1f %14s %12s %14s\n", name, static_cast<long long>(n), r,
                        it->second.bytes_per_animation, ratio_text(tw, r).c_str(), ratio_text(fl, r).c_str(),
                        ratio_text(tf, r).c_str());
        }
    }
    // Arc length against the plain cubic kind, per repetition and size: median and min–max of
    // the ratios (the two were interleaved when run with --benchmark_enable_random_interleaving).
    std::printf("\narc-length / plain cubic (ns ratio; median [min, max] over repetitions)\n");
    for (std::int64_t n : {1000, 100000, 1000000}) {
        for (const char* tag : {"", "_spread", "random_spread", "svg_spread"}) {
            const std::string t = tag;
            // "random_spread": random cubics against the plain cubic of the same random shapes;
            // "svg_spread": SVG paths by arc length against the same paths by u.
            const std::string by_length = t == "random_spread" ? "grape_reparam_random_cubic_spread"
                                          : t == "svg_spread"   ? "grape_reparam_svg_spread"
                                                                : "grape_reparam_cubic" + t;
            const std::string by_u = t == "random_spread" ? "grape_random_cubic_spread"
                                     : t == "svg_spread"   ? "grape_svg_spread"
                                                           : "grape_cubic" + t;
            const auto a = results.find(key(by_length.c_str(), n));
            const auto b = results.find(key(by_u.c_str(), n));
            if (a == results.end() || b == results.end()) continue;
            std::vector<double> r;
            for (std::size_t i = 0; i < std::min(a->second.ns_per_update.size(), b->second.ns_per_update.size()); ++i)
                r.push_back(a->second.ns_per_update[i] / b->second.ns_per_update[i]);
            std::sort(r.begin(), r.end());
            std::printf("%-14s N=%-8lld %6.2f [%.2f, %.2f]  (%.2f / %.2f ns)\n",
                        t.empty() ? "phase 0" : t == "_spread" ? "spread" : tag,
                        static_cast<long long>(n), r[r.size() / 2], r.front(), r.back(), a->second.median(),
                        b->second.median());
        }
    }
    // Ratios per repetition (median [min, max]): the linear kind to the memory-traffic floor
    // (thread CPU time), and the one-pass tick to the parallel one (wall time).
    auto ratios = [](const char* over, const char* under, std::int64_t n, const char* label) {
        const auto a = results.find(key(over, n));
        const auto b = results.find(key(under, n));
        if (a == results.end() || b == results.end()) return;
        std::vector<double> r;
        for (std::size_t i = 0; i < std::min(a->second.ns_per_update.size(), b->second.ns_per_update.size()); ++i)
            r.push_back(a->second.ns_per_update[i] / b->second.ns_per_update[i]);
        std::sort(r.begin(), r.end());
        std::printf("%-34s N=%-8lld %6.2f [%.2f, %.2f]  (%.2f / %.2f ns)\n", label, static_cast<long long>(n),
                    r[r.size() / 2], r.front(), r.back(), a->second.median(), b->second.median());
    };
    std::printf("\nratios (median [min, max] over repetitions)\n");
    for (std::int64_t n : {1000, 100000, 1000000}) {
        ratios("grape_linear", "traffic_floor", n, "linear / memory-traffic floor");
        ratios("tweeny_quad", "grape_linear", n, "tweeny quad / linear");
        ratios("grape3_cubic", "grape_cubic", n, "3-D cubic / 2-D cubic");
        ratios("grape3_cubic_frame", "grape_cubic", n, "3-D cubic + frame / 2-D cubic");
        ratios("wall_one_pass", "wall_parallel_2", n, "one-pass / parallel 2 threads");
        ratios("wall_one_pass", "wall_two_phase_1", n, "one-pass / two-phase 1 thread");
        ratios("wall_frame_one_pass", "wall_frame_parallel_2", n, "frame: one-pass / parallel 2");
        // what the calling thread itself spends: the share of the work it kept
        ratios("wall_one_pass_cpu", "wall_parallel_2_cpu", n, "one-pass / parallel 2, caller's CPU");
    }
    return 0;
}
