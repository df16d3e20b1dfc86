// What a cut-scene script costs per tick, next to what it replaces. N = 10,000 of each, ticked
// at 60 Hz:
//  - engine_only: N animations alive for the whole run (the floor every row shares);
//  - listeners: the same plus N plain tick listeners, each checking its animation's alive()
//    (a hand-written state machine's polling);
//  - scripts_awaiting: the same animations plus N scripts, each suspended on its animation;
//  - scripts_resuming: N scripts resumed every tick (co_await wait(1/60) in a loop), no
//    animations;
//  - script_lifecycle: create, start (to its first wait) and destroy one script.
// Reported per tick in ns per script (per listener): subtract engine_only for the overhead.
#include <grape/script.hpp>

#include <benchmark/benchmark.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace {

constexpr double frame = 1.0 / 60.0;
constexpr std::size_t count = 10'000;
const grape::LinearPath line({0, 0}, {1, 0});

struct Dot {
    double x = 0, y = 0;
};

grape::Script await_one(grape::Animation a) { co_await a; }

grape::Script every_frame(long& resumptions) {
    for (;;) {
        co_await grape::wait(frame);
        ++resumptions;
    }
}

std::vector<grape::Animation> long_animations(grape::Engine& engine, std::vector<Dot>& dots) {
    std::vector<grape::Animation> made;
    for (Dot& d : dots) made.push_back(engine.create_2d_animation(d, line, 1e9));
    return made;
}

void engine_only(benchmark::State& state) {
    grape::Engine engine;
    std::vector<Dot> dots(count);
    const auto animations = long_animations(engine, dots);
    for (auto _ : state) engine.tick(frame);
    state.counters["ns_per_item"] =
        benchmark::Counter(static_cast<double>(count), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void listeners(benchmark::State& state) {
    grape::Engine engine;
    std::vector<Dot> dots(count);
    const auto animations = long_animations(engine, dots);
    long seen = 0;
    for (const grape::Animation& a : animations) {
        engine.on_tick([a, &seen](double) {
            if (!a.alive()) ++seen;
        });
    }
    for (auto _ : state) engine.tick(frame);
    benchmark::DoNotOptimize(seen);
    state.counters["ns_per_item"] =
        benchmark::Counter(static_cast<double>(count), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void scripts_awaiting(benchmark::State& state) {
    grape::Engine engine;
    std::vector<Dot> dots(count);
    const auto animations = long_animations(engine, dots);
    std::vector<grape::Script> scripts;
    for (const grape::Animation& a : animations) {
        scripts.push_back(await_one(a));
        scripts.back().start(engine);
    }
    for (auto _ : state) engine.tick(frame);
    state.counters["ns_per_item"] =
        benchmark::Counter(static_cast<double>(count), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void scripts_resuming(benchmark::State& state) {
    grape::Engine engine;
    long resumptions = 0;
    std::vector<grape::Script> scripts;
    for (std::size_t i = 0; i < count; ++i) {
        scripts.push_back(every_frame(resumptions));
        scripts.back().start(engine);
    }
    for (auto _ : state) engine.tick(frame);
    if (resumptions < static_cast<long>(count)) state.SkipWithError("the scripts did not resume");
    state.counters["ns_per_item"] =
        benchmark::Counter(static_cast<double>(count), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void script_lifecycle(benchmark::State& state) {
    grape::Engine engine;
    long resumptions = 0;
    for (auto _ : state) {
        grape::Script s = every_frame(resumptions);
        s.start(engine);
    }
}

}  // namespace

BENCHMARK(engine_only)->Unit(benchmark::kMicrosecond);
BENCHMARK(listeners)->Unit(benchmark::kMicrosecond);
BENCHMARK(scripts_awaiting)->Unit(benchmark::kMicrosecond);
BENCHMARK(scripts_resuming)->Unit(benchmark::kMicrosecond);
BENCHMARK(script_lifecycle)->Unit(benchmark::kNanosecond);
BENCHMARK_MAIN();
