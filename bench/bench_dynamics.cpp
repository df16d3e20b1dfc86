// Dynamics benchmarks. Steps per second of one bead (parametric) and one constrained
// particle (implicit), and 10 s of a chain of 10, 100 and 1,000 unit-mass particles 1 m
// apart, released horizontally from a pin, against the same chain in Box2D 2.4 (small
// circles joined by revolute joints at the previous body's centre, default 8 velocity and
// 3 position iterations, 60 Hz). Each chain run reports its speed (frames of 1/60 s per
// second) and its worst link-length error over the run; a summary prints the ratios.
#include <grape/dynamics.hpp>

#include <seed_dynamics.hpp>

#include <benchmark/benchmark.h>
#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace {

using namespace grape;

constexpr double frame = 1.0 / 60;
constexpr int frames = 600;  // 10 s
constexpr double link = 1.0;  // m
constexpr double g = 9.81;

void BM_bead_parametric(benchmark::State& state) {
    Bead bead(ParametricCurve(scenes::seed_parabola_frame), {.u = 100, .gravity = {0, 500}});
    for (auto _ : state) {
        bead.step(frame);
        benchmark::DoNotOptimize(bead.u());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_bead_parametric);

void particle_implicit(benchmark::State& state, DriftControl drift) {
    ParticleSystem system({.drift = {.method = drift}});
    const auto p = system.add_particle({.position = {100, -100}});
    system.add_gravity({0, 500});
    system.add_curve(p, scenes::seed_parabola_curve());
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

// Sub-steps per 1/60 s frame for explicit RK4 to stay stable: the chain's fastest mode
// grows like √(n·g/L) (≈ 99 rad/s at n = 1000); at 1/60 s the 1000-link chain blows up after
// ~7 s, at 1/120 s it holds its links at round-off for the whole run.
int substeps_for(std::int64_t links) { return links >= 1000 ? 2 : 1; }

void BM_grape_chain(benchmark::State& state) {
    const auto links = static_cast<std::size_t>(state.range(0));
    const int substeps = substeps_for(state.range(0));
    double worst = 0.0;
    for (auto _ : state) {
        state.PauseTiming();
        auto system = scenes::chain(links, link, g, {.drift = {.method = DriftControl::projection}});
        worst = 0.0;
        state.ResumeTiming();
        for (int f = 0; f < frames; ++f) {
            for (int s = 0; s < substeps; ++s) system.step(frame / substeps);
            worst = std::max(worst, scenes::chain_link_error(system, link));
        }
    }
    state.counters["frames/s"] = benchmark::Counter(static_cast<double>(frames * state.iterations()), benchmark::Counter::kIsRate);
    state.counters["link_error"] = worst;
    state.counters["substeps"] = substeps;
}
BENCHMARK(BM_grape_chain)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3);

void BM_box2d_chain(benchmark::State& state) {
    const int links = static_cast<int>(state.range(0));
    double worst = 0.0;
    for (auto _ : state) {
        state.PauseTiming();
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
        for (int k = 1; k <= links; ++k) {
            b2BodyDef def;
            def.type = b2_dynamicBody;
            def.position.Set(static_cast<float>(k * link), 0.0f);
            b2Body* body = world.CreateBody(&def);
            body->CreateFixture(&fixture);
            b2RevoluteJointDef joint;
            joint.Initialize(previous, body, previous->GetPosition());
            world.CreateJoint(&joint);
            bodies.push_back(body);
            previous = body;
        }
        worst = 0.0;
        state.ResumeTiming();
        for (int f = 0; f < frames; ++f) {
            world.Step(static_cast<float>(frame), 8, 3);
            for (int k = 1; k <= links; ++k) {
                const b2Vec2 d = bodies[k]->GetPosition() - bodies[k - 1]->GetPosition();
                worst = std::max(worst, std::abs(static_cast<double>(d.Length()) - link));
            }
        }
    }
    state.counters["frames/s"] = benchmark::Counter(static_cast<double>(frames * state.iterations()), benchmark::Counter::kIsRate);
    state.counters["link_error"] = worst;
}
BENCHMARK(BM_box2d_chain)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3);

// Prints the runs as usual and keeps the medians for the summary.
class Summary : public benchmark::ConsoleReporter {
public:
    std::map<std::string, std::map<std::string, double>> medians;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& run : runs) {
            if (run.aggregate_name != "median") continue;
            auto& m = medians[run.run_name.str()];
            for (const auto& [name, counter] : run.counters) m[name] = counter.value;
        }
        ConsoleReporter::ReportRuns(runs);
    }
};

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    Summary summary;
    benchmark::RunSpecifiedBenchmarks(&summary);
    std::printf("\nChains, 10 s at 60 Hz (medians): grape = RK4 + projection, Box2D = 8/3 iterations\n");
    std::printf("%8s %14s %14s %10s %14s %14s %12s\n", "links", "grape frames/s", "box2d frames/s", "speed x",
                "grape error m", "box2d error m", "error ratio");
    for (int links : {10, 100, 1000}) {
        auto find = [&](const std::string& prefix) {
            return std::find_if(summary.medians.begin(), summary.medians.end(),
                                [&](const auto& m) { return m.first.rfind(prefix, 0) == 0; });
        };
        const auto a = find("BM_grape_chain/" + std::to_string(links) + "/");
        const auto b = find("BM_box2d_chain/" + std::to_string(links) + "/");
        if (a == summary.medians.end() || b == summary.medians.end()) continue;
        const double fa = a->second["frames/s"], fb = b->second["frames/s"];
        const double ea = a->second["link_error"], eb = b->second["link_error"];
        std::printf("%8d %14.0f %14.0f %10.2f %14.3g %14.3g %12.3g\n", links, fa, fb, fa / fb, ea, eb,
                    eb / std::max(ea, 1e-300));
    }
    benchmark::Shutdown();
    return 0;
}
