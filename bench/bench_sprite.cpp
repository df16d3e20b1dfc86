// 1,000,000 SpritePlayers advanced once per frame: ns per player, against the two ways a
// game usually writes it (a float accumulator wrapped with fmod, and the frame recomputed
// from elapsed time with a multiply and fmod), in one run with ratios printed.
//
//   build-bench/bench/bench_sprite
#include <grape/sprite.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {

constexpr std::size_t players = 1'000'000;
constexpr std::size_t frames = 16;

// Rates across the whole allowed range, both directions, mostly fractional.
std::vector<double> random_rates() {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> rate(-static_cast<double>(frames) + 0.5, static_cast<double>(frames) - 0.5);
    std::vector<double> r(players);
    for (double& x : r) x = rate(rng);
    return r;
}

void bm_grape_counter(benchmark::State& state) {
    const auto rates = random_rates();
    std::vector<grape::SpritePlayer> all;
    all.reserve(players);
    for (std::size_t i = 0; i < players; ++i) all.emplace_back(frames, grape::SpritePlayerDef{.rate = rates[i]});
    for (auto _ : state) {
        for (auto& p : all) p.advance();
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(players));
}

void bm_grape_sheet(benchmark::State& state) {
    const grape::TileSheet sheet({.width = 512, .height = 64, .columns = 8, .rows = 2});
    const auto rates = random_rates();
    std::vector<grape::TileSheetSprite> sprites(players, grape::TileSheetSprite(sheet));
    std::vector<grape::SpritePlayer> all;
    all.reserve(players);
    for (std::size_t i = 0; i < players; ++i) all.emplace_back(sprites[i], grape::SpritePlayerDef{.rate = rates[i]});
    for (auto _ : state) {
        for (auto& p : all) p.advance();
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(players));
}

void bm_grape_timed(benchmark::State& state) {
    const auto rates = random_rates();
    std::vector<grape::SpritePlayer> all;
    all.reserve(players);
    for (std::size_t i = 0; i < players; ++i) all.emplace_back(frames, grape::SpritePlayerDef{.rate = rates[i]});
    for (auto _ : state) {
        for (auto& p : all) p.advance(1.0 / 60, 24);  // a 24 fps sheet in a 60 Hz game
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(players));
}

// Peer 1: a float position accumulated and wrapped with fmod, frame = floor(position).
struct Accumulator {
    double position = 0.0;
    double rate = 0.0;
    std::uint32_t frame = 0;
};
void bm_peer_accumulator(benchmark::State& state) {
    const auto rates = random_rates();
    std::vector<Accumulator> all(players);
    for (std::size_t i = 0; i < players; ++i) all[i].rate = rates[i];
    const double n = frames;
    for (auto _ : state) {
        for (auto& a : all) {
            a.position = std::fmod(a.position + a.rate, n);
            if (a.position < 0) a.position += n;
            a.frame = static_cast<std::uint32_t>(a.position);
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(players));
}

// Peer 2: the frame recomputed from the step count: floor(start + rate·k) mod n.
struct FromTime {
    double start = 0.0;
    double rate = 0.0;
    std::uint32_t frame = 0;
};
void bm_peer_from_time(benchmark::State& state) {
    const auto rates = random_rates();
    std::vector<FromTime> all(players);
    for (std::size_t i = 0; i < players; ++i) all[i].rate = rates[i];
    const double n = frames;
    double k = 0.0;
    for (auto _ : state) {
        k += 1.0;
        for (auto& a : all) {
            double x = std::fmod(a.start + a.rate * k, n);
            if (x < 0) x += n;
            a.frame = static_cast<std::uint32_t>(x);
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(players));
}

class SummaryReporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> ns_per_player;  // median CPU time / players
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& run : runs) {
            if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median") {
                ns_per_player[run.run_name.function_name] =
                    run.GetAdjustedCPUTime() * 1e9 / benchmark::GetTimeUnitMultiplier(run.time_unit) / players;
            }
        }
        ConsoleReporter::ReportRuns(runs);
    }
};

}  // namespace

int main(int argc, char** argv) {
    const char* names[] = {"grape::SpritePlayer advance() (frame counter)", "grape::SpritePlayer advance() + TileSheetSprite",
                           "grape::SpritePlayer advance(dt, fps)", "peer: float accumulator + fmod",
                           "peer: from time, multiply + fmod"};
    void (*fns[])(benchmark::State&) = {bm_grape_counter, bm_grape_sheet, bm_grape_timed, bm_peer_accumulator,
                                        bm_peer_from_time};
    for (int i = 0; i < 5; ++i) {
        benchmark::RegisterBenchmark(names[i], fns[i])->MinTime(0.2)->Repetitions(5)->ReportAggregatesOnly(true);
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    SummaryReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    std::printf("\nSummary: %zu players of %zu frames, median CPU time of 5 repetitions; sizeof(SpritePlayer) = %zu bytes\n",
                players, frames, sizeof(grape::SpritePlayer));
    const double base = reporter.ns_per_player[names[0]];
    for (const char* name : names) {
        const double ns = reporter.ns_per_player[name];
        std::printf("  %-50s %7.3f ns/player  (%.2fx the frame-counter player's time)\n", name, ns, base > 0 ? ns / base : 0.0);
    }
    benchmark::Shutdown();
    return 0;
}
