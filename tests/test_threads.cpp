// The thread-safety contract of path.hpp, curve.hpp, anim.hpp and dynamics.hpp: shared Paths
// and Curves read from several threads at once, separate engines, particle systems and
// beads stepping on separate threads, and an engine's parallel tick. Every thread must get exactly (bit for bit) what one
// thread gets alone: the same code on the same immutable inputs. Built with
// -fsanitize=thread by scripts/run-tsan, which fails on any data race the runs expose.
#include <grape/anim.hpp>
#include <grape/curve.hpp>
#include <grape/path.hpp>
#ifdef GRAPE_TEST_DYNAMICS
#include <grape/dynamics.hpp>
#endif

#include "seed_paths.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace {

constexpr int thread_count = 4;

// Runs job(i) on thread_count threads at once and returns each thread's answer.
template <class Result>
std::vector<Result> on_threads(const std::function<Result(int)>& job) {
    std::vector<Result> results(thread_count);
    std::vector<std::thread> threads;
    for (int i = 0; i < thread_count; ++i) threads.emplace_back([&results, &job, i] { results[i] = job(i); });
    for (std::thread& t : threads) t.join();
    return results;
}

// Every kind of path, its arc-length version, SVG data (lines, arcs, curves) and one complex
// path holding them all: the shapes several threads read at once.
std::vector<grape::Path> shared_paths() {
    std::vector<grape::Path> paths;
    for (const auto& named : grape::scenes::path_gallery()) {
        paths.push_back(named.path);
        paths.push_back(named.path.reparametrized());
    }
    paths.push_back(grape::parse_svg_path("M10 10 h40 a20 20 0 0 1 0 40 q-20 30 -40 0 c-10 -10 10 -20 0 -40 z"));
    paths.push_back(grape::scenes::seed_nested_complex());
    std::vector<double> cues;
    for (std::size_t i = 0; i < paths.size(); ++i) cues.push_back(static_cast<double>(i) / static_cast<double>(paths.size()));
    paths.push_back(grape::ComplexPath(paths, cues));
    return paths;
}

// Everything a reader may ask of a path, as numbers (u beyond [0, 1] too: end tangents).
std::vector<double> read_path(const grape::Path& shared) {
    const grape::Path path = shared;  // copying the handle is a read of the shared count
    std::vector<double> out;
    for (int k = -8; k <= 264; ++k) {
        const double u = k / 256.0;
        const grape::Vec2 p = path.point(u), d1 = path.d1(u), d2 = path.d2(u);
        out.insert(out.end(), {p.x, p.y, d1.x, d1.y, d2.x, d2.y, path.heading(u)});
        if (k % 16 == 0) out.insert(out.end(), {path.length_at(u), path.u_at_length(u * path.length())});
    }
    const grape::Bounds b = path.bounds();
    out.insert(out.end(), {path.length(), b.min.x, b.min.y, b.max.x, b.max.y});
    for (const grape::Vec2 q : path.flatten(0.5)) out.insert(out.end(), {q.x, q.y});
    return out;
}

TEST(Threads, SharedPathsOfEveryKindReadFromFourThreads) {
    const std::vector<grape::Path> paths = shared_paths();
    ASSERT_GT(paths.size(), 30u);  // every kind twice, and the SVG and complex ones
    std::vector<std::vector<double>> reference;
    for (const grape::Path& p : paths) reference.push_back(read_path(p));
    const auto results = on_threads<std::vector<std::vector<double>>>([&](int i) {
        std::vector<std::vector<double>> mine(paths.size());
        // Each thread walks the paths in a different order, so different threads read the
        // same path at the same moment.
        for (std::size_t n = 0; n < paths.size(); ++n) {
            const std::size_t k = (n + static_cast<std::size_t>(i) * 7) % paths.size();
            mine[k] = read_path(paths[k]);
        }
        return mine;
    });
    for (int i = 0; i < thread_count; ++i)
        for (std::size_t k = 0; k < paths.size(); ++k) EXPECT_EQ(results[i][k], reference[k]) << "thread " << i << ", path " << k;
}

TEST(Threads, SharedCurvesOfEveryKindReadFromFourThreads) {
    std::vector<grape::Curve> curves;
    for (std::string_view name : grape::curve_names()) curves.push_back(grape::parse_curve(name));
    curves.push_back(grape::Curve::cubic_bezier(0.25, 0.1, 0.25, 1.0));
    curves.push_back(grape::Curve::steps(4, grape::StepPosition::jump_both));
    curves.push_back(grape::Curve::back(grape::EaseDirection::in_out, 2.5));
    curves.push_back(grape::Curve::elastic(grape::EaseDirection::out, 1.5, 0.4));
    const double x[] = {0.0, 0.3, 0.5, 1.0};
    const double y[] = {0.0, 0.6, 0.65, 1.0};
    curves.push_back(grape::Curve::monotone(x, y));  // its knots are shared on the heap
    const auto read = [&curves] {
        std::vector<double> out;
        for (const grape::Curve& shared : curves) {
            const grape::Curve c = shared;
            for (int k = -16; k <= 1040; ++k) out.push_back(c(k / 1024.0));
            const std::string name = grape::to_string(c);
            out.push_back(static_cast<double>(name.size()));
        }
        return out;
    };
    const std::vector<double> reference = read();
    const auto results = on_threads<std::vector<double>>([&](int) { return read(); });
    for (int i = 0; i < thread_count; ++i) EXPECT_EQ(results[i], reference) << "thread " << i;
}

struct Sprite {
    double x = 0.0, y = 0.0, rotation = 0.0;
};

// One engine per thread, all playing the same shared paths and curves.
std::vector<double> run_engine(const std::vector<grape::Path>& paths, const grape::Curve& curve) {
    grape::Engine engine;
    std::vector<Sprite> sprites(paths.size());
    int loops = 0;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        auto a = engine.create_2d_animation(sprites[i], paths[i], 0.5 + 0.01 * static_cast<double>(i),
                                            {.curve = curve, .repeat = 3, .yoyo = true, .heading = true});
        a.on_loop([&loops](int) { ++loops; });
    }
    for (int frame = 0; frame < 300; ++frame) engine.tick(1.0 / 120.0);
    std::vector<double> out;
    for (const Sprite& s : sprites) out.insert(out.end(), {s.x, s.y, s.rotation});
    out.push_back(loops);
    return out;
}

TEST(Threads, SeparateEnginesOnSeparateThreadsShareTheirPaths) {
    const std::vector<grape::Path> paths = shared_paths();
    const grape::Curve curve = grape::Curve::cubic_bezier(0.42, 0.0, 0.58, 1.0);
    const std::vector<double> reference = run_engine(paths, curve);
    const auto results = on_threads<std::vector<double>>([&](int) { return run_engine(paths, curve); });
    for (int i = 0; i < thread_count; ++i) EXPECT_EQ(results[i], reference) << "thread " << i;
}

// One engine whose ticks are shared among `threads` threads (Engine::set_parallel): 6,000
// animations over the shared paths and curves, so phase 1 splits into many blocks, with loop
// handlers that read every target the workers wrote (phase 2 runs after them) and seek
// other animations.
// awake 0: the workers sleep after every tick, so each tick wakes them (the other path of the
// pool's hand-over); the default keeps them awake between these back-to-back ticks. gap > 0:
// the ticks that far apart, as once a frame (workers asleep wake before the next is due).
std::vector<double> run_parallel_engine(const std::vector<grape::Path>& paths, const grape::Curve& curve, int threads,
                                        double awake = grape::ParallelDef{}.awake,
                                        std::chrono::microseconds gap = std::chrono::microseconds(0)) {
    grape::Engine engine;
    engine.set_parallel({.threads = threads, .min_animations = 0, .awake = awake});
    constexpr std::size_t count = 6000;
    std::vector<Sprite> sprites(count);
    std::vector<grape::Animation> anims;
    double seen = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const grape::AnimationDef def{.curve = i % 3 ? curve : grape::Curve::quad_in_out(),
                                      .delay = i % 5 == 0 ? 0.1 : 0.0, .repeat = -1, .yoyo = i % 2 == 0,
                                      .heading = i % 50 == 0};
        anims.push_back(engine.create_2d_animation(sprites[i], paths[i % paths.size()],
                                                   0.25 + 0.001 * static_cast<double>(i % 700), def));
    }
    for (std::size_t i = 0; i < count; i += 97) {
        anims[i].on_loop([&, i](int play) {
            for (const Sprite& s : sprites) seen += s.x;  // written by the workers in phase 1
            anims[(i * 31 + static_cast<std::size_t>(play)) % count].seek(0.05);
        });
    }
    for (int frame = 0; frame < 120; ++frame) {
        if (gap.count() > 0) std::this_thread::sleep_for(gap);
        engine.tick(1.0 / 60.0);
    }
    std::vector<double> out;
    for (const Sprite& s : sprites) out.insert(out.end(), {s.x, s.y, s.rotation});
    out.push_back(seen);
    return out;
}

TEST(Threads, ParallelTickOnFourThreadsMatchesOne) {
    const std::vector<grape::Path> paths = shared_paths();
    const grape::Curve curve = grape::Curve::cubic_bezier(0.42, 0.0, 0.58, 1.0);
    const std::vector<double> reference = run_parallel_engine(paths, curve, 1);
    EXPECT_EQ(run_parallel_engine(paths, curve, thread_count), reference);
    EXPECT_EQ(run_parallel_engine(paths, curve, thread_count, 0.0), reference);
    EXPECT_EQ(run_parallel_engine(paths, curve, thread_count, 100e-6, std::chrono::microseconds(1000)), reference);
    // and two such engines at once, each with its own workers
    const auto results = on_threads<std::vector<double>>([&](int) { return run_parallel_engine(paths, curve, 2); });
    for (const std::vector<double>& r : results) EXPECT_EQ(r, reference);
}

#ifdef GRAPE_TEST_DYNAMICS
// A chain of pendulums under Baumgarte drift control and a bead on a shared path, per thread.
std::vector<double> run_dynamics(const grape::Path& wire) {
    grape::ParticleSystem system({.integrator = grape::Integrator::rk4});
    auto previous = system.create_particle({.position = {0, 0}, .mass = HUGE_VAL});
    for (int i = 1; i <= 8; ++i) {
        const auto p = system.create_particle({.position = {20.0 * i, 0}});
        system.create_distance(previous, p, 20.0);
        previous = p;
    }
    system.add_gravity({0, 500});
    grape::Bead bead(wire, {.u = 0.25, .gravity = {0, 500}});
    for (int step = 0; step < 240; ++step) {
        system.step(1.0 / 120.0);
        bead.step(1.0 / 120.0);
    }
    std::vector<double> out;
    for (const grape::Vec2 p : system.positions()) out.insert(out.end(), {p.x, p.y});
    out.insert(out.end(), {bead.position().x, bead.position().y, system.energy()});
    return out;
}

TEST(Threads, SeparateParticleSystemsAndBeadsOnSeparateThreads) {
    const grape::Path wire = grape::scenes::seed_nested_complex();
    const std::vector<double> reference = run_dynamics(wire);
    const auto results = on_threads<std::vector<double>>([&](int) { return run_dynamics(wire); });
    for (int i = 0; i < thread_count; ++i) EXPECT_EQ(results[i], reference) << "thread " << i;
}
#endif

}  // namespace
