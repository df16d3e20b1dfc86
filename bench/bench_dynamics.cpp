// Dynamics benchmarks. Steps per second of one bead (parametric) and one constrained
// particle (implicit) (Google Benchmark), then 10 s of a chain of 10, 100 and 1,000
// unit-mass particles 1 m apart, released horizontally from a pin, against the same chain
// in Box2D 2.4 (small circles joined by revolute joints at the previous body's center,
// default 8 velocity and 3 position iterations, 60 Hz) and, built with
// -DGRAPE_BOX2D3_DIR=<source tree>, Box2D v3 (point masses joined by rigid distance joints,
// its soft step with 4 sub-steps). The chains run round-robin, `--rounds R` (default 5)
// fresh runs of each contender at each size; each row gives the median speed (frames of
// 1/60 s per CPU second), its min–max, the worst link-length error over every run and the
// ratio to the last peer.
//
//   bench_dynamics [--rounds R] [--benchmark_filter=...]   (--rounds 0: no chains)
#include <grape/dynamics.hpp>

#include <catalogue.hpp>
#include <seed_dynamics.hpp>

#include <benchmark/benchmark.h>
#include <box2d/box2d.h>

#if GRAPE_BENCH_BOX2D3
#include "bench_dynamics_box2d3.hpp"
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace grape;

constexpr double frame = 1.0 / 60;
constexpr int frames = 600;  // 10 s
constexpr double link = 1.0;  // m
constexpr double g = 9.81;

void BM_bead_parametric(benchmark::State& state) {
    Bead bead(ParametricFunction(scenes::seed_parabola_frame), {.u = 100, .gravity = {0, 500}});
    for (auto _ : state) {
        bead.step(frame);
        benchmark::DoNotOptimize(bead.u());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_bead_parametric);

void particle_implicit(benchmark::State& state, DriftControl drift) {
    ParticleSystem system({.drift = {.method = drift}});
    const auto p = system.create_particle({.position = {100, -100}});
    system.add_gravity({0, 500});
    system.create_implicit(p, scenes::seed_parabola_curve());
    for (auto _ : state) {
        system.step(frame);
        benchmark::DoNotOptimize(system.positions()[0]);
    }
    state.SetItemsProcessed(state.iterations());
}
void BM_particle_implicit_baumgarte(benchmark::State& state) { particle_implicit(state, DriftControl::baumgarte); }
void BM_particle_implicit_projection(benchmark::State& state) { particle_implicit(state, DriftControl::projection); }
BENCHMARK(BM_particle_implicit_baumgarte);
BENCHMARK(BM_particle_implicit_projection);

// ---- chains: contenders round-robin, a fresh chain per run ----

double thread_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct ChainRun {
    double seconds = 0.0;     // thread CPU time of the steps only
    double link_error = 0.0;  // worst over the run, m
};

// Sub-steps per 1/60 s frame that explicit RK4 needs on the old path: the chain's fastest mode
// grows like √(n·g/L) (≈ 99 rad/s at n = 1000); at 1/60 s the 1000-link chain blows up after
// ~7 s, at 1/120 s it holds its links at round-off for the whole run.
int rk4_substeps_for(std::size_t links) { return links >= 1000 ? 2 : 1; }

// The catalogue's chain_N (1 m links, g = 9.81 m/s², as `grape list` shows and the studio
// plays), set to the contender's integrator, drift control and sub-step rule.
ChainRun grape_chain(std::size_t links, const ParticleSystemDef& def, int substeps) {
    const scenes::Entry* entry = scenes::find_entry("chain_" + std::to_string(links));
    if (!entry) throw Error("bench_dynamics: the catalogue has no chain_" + std::to_string(links));
    ParticleSystem system = entry->system();
    system.set_integrator(def.integrator);
    system.set_drift(def.drift);
    system.set_substeps(def.substeps);
    ChainRun run;
    for (int f = 0; f < frames; ++f) {
        const double start = thread_seconds();
        for (int s = 0; s < substeps; ++s) system.step(frame / substeps);
        run.seconds += thread_seconds() - start;
        run.link_error = std::max(run.link_error, scenes::chain_link_error(system, link));
    }
    return run;
}

ChainRun box2d24_chain(std::size_t links) {
    b2World world(b2Vec2(0.0f, static_cast<float>(-g)));
    b2BodyDef ground_def;
    b2Body* previous = world.CreateBody(&ground_def);
    std::vector<b2Body*> bodies{previous};
    const float radius = 0.05f;
    b2CircleShape circle;
    circle.m_radius = radius;
    b2FixtureDef fixture;
    fixture.shape = &circle;
    fixture.density = 1.0f / (b2_pi * radius * radius);  // mass 1 like the particles
    fixture.filter.groupIndex = -1;                       // links do not collide: joints only
    for (std::size_t k = 1; k <= links; ++k) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(static_cast<float>(static_cast<double>(k) * link), 0.0f);
        b2Body* body = world.CreateBody(&def);
        body->CreateFixture(&fixture);
        b2RevoluteJointDef joint;
        joint.Initialize(previous, body, previous->GetPosition());
        world.CreateJoint(&joint);
        bodies.push_back(body);
        previous = body;
    }
    ChainRun run;
    for (int f = 0; f < frames; ++f) {
        const double start = thread_seconds();
        world.Step(static_cast<float>(frame), 8, 3);
        run.seconds += thread_seconds() - start;
        for (std::size_t k = 1; k <= links; ++k) {
            const b2Vec2 d = bodies[k]->GetPosition() - bodies[k - 1]->GetPosition();
            run.link_error = std::max(run.link_error, std::abs(static_cast<double>(d.Length()) - link));
        }
    }
    return run;
}

struct Contender {
    std::string name;
    std::function<ChainRun(std::size_t links)> run;
    std::map<std::size_t, std::vector<ChainRun>> runs{};
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

void run_chains(int rounds) {
    constexpr std::size_t sizes[] = {10, 100, 1000};
    std::vector<Contender> all;
    all.push_back({"grape rk4 + projection", [](std::size_t n) {
                       return grape_chain(n, {.drift = {.method = DriftControl::projection}}, rk4_substeps_for(n));
                   }});
    all.push_back({"grape rattle, automatic sub-steps", [](std::size_t n) {
                       return grape_chain(n, {.integrator = Integrator::rattle, .substeps = {.automatic = true}}, 1);
                   }});
    all.push_back({"box2d 2.4 (8/3 iterations)", box2d24_chain});
#if GRAPE_BENCH_BOX2D3
    const std::string v3 = std::string("box2d ") + bench::box2d3_version() + " (4 sub-steps)";
    all.push_back({v3, [](std::size_t n) {
                       const auto r = bench::box2d3_chain(n, link, g, frame, frames, 4);
                       return ChainRun{r.seconds, r.link_error};
                   }});
#endif
    for (int r = 0; r < rounds; ++r)
        for (std::size_t n : sizes)
            for (auto& c : all) c.runs[n].push_back(c.run(n));
    const Contender& peer = all.back();
    std::printf("\nChains, 10 s at 60 Hz from horizontal, %d rounds round-robin (CPU time of the steps):\n", rounds);
    std::printf("%6s  %-34s %12s %21s %13s %10s\n", "links", "contender", "frames/s", "min-max", "worst err m",
                ("/ " + peer.name.substr(0, 9)).c_str());
    for (std::size_t n : sizes) {
        std::vector<double> peer_rates;
        for (const auto& run : peer.runs.at(n)) peer_rates.push_back(frames / run.seconds);
        const double peer_median = median(peer_rates);
        for (const auto& c : all) {
            std::vector<double> rates;
            double worst = 0.0;
            for (const auto& run : c.runs.at(n)) {
                rates.push_back(frames / run.seconds);
                worst = std::max(worst, run.link_error);
            }
            const auto [lo, hi] = std::minmax_element(rates.begin(), rates.end());
            std::printf("%6zu  %-34s %12.0f %10.0f-%-10.0f %13.3g %10.2f\n", n, c.name.c_str(), median(rates), *lo, *hi,
                        worst, median(rates) / peer_median);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    int rounds = 5;
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], "--rounds") == 0) rounds = std::max(0, std::atoi(argv[i + 1]));
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    if (rounds > 0) run_chains(rounds);
    benchmark::Shutdown();
    return 0;
}
