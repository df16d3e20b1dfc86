// Orientation: ns per call of slerp (ends prepared per call, and prepared once as an animation
// does), of the C² spline's orientation and angular velocity at random t on 100 keys, of
// from_basis and to_euler; then the spline's build time at 10, 100 and 1,000 keys (linear in
// the keys is the claim: a few Newton steps of O(n) each).
//
//   build-bench/bench/bench_quat --benchmark_repetitions=7 --benchmark_enable_random_interleaving=true
//       --benchmark_min_time=0.05 --benchmark_report_aggregates_only=true      (one command line)
#include <grape/quat.hpp>
#include <grape/quat_spline.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using grape::Quat;

Quat random_rotation(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double u1 = u(rng), u2 = u(rng), u3 = u(rng), a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    return {a * std::sin(2 * grape::pi * u2), a * std::cos(2 * grape::pi * u2), b * std::sin(2 * grape::pi * u3),
            b * std::cos(2 * grape::pi * u3)};
}

const std::vector<Quat>& rotations() {
    static const std::vector<Quat> q = [] {
        std::mt19937_64 rng(5);
        std::vector<Quat> out(4096);
        for (Quat& x : out) x = random_rotation(rng);
        return out;
    }();
    return q;
}

const std::vector<double>& random_t() {
    static const std::vector<double> t = [] {
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::vector<double> out(4096);
        for (double& x : out) x = unit(rng);
        return out;
    }();
    return t;
}

// n keys one second apart, each a random turn of up to 1.5 rad from the one before.
grape::QuatSpline make_spline(int n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> nd;
    std::uniform_real_distribution<double> turn(0.0, 1.5);
    std::vector<double> t;
    std::vector<Quat> q;
    Quat k = random_rotation(rng);
    for (int i = 0; i < n; ++i) {
        t.push_back(i);
        q.push_back(k);
        k = grape::from_axis_angle({nd(rng), nd(rng), nd(rng)}, turn(rng)) * k;
    }
    return grape::QuatSpline(std::move(t), std::move(q));
}

const grape::QuatSpline& spline100() {
    static const grape::QuatSpline s = make_spline(100, 3);
    return s;
}

void BM_slerp(benchmark::State& state) {
    std::size_t i = 0;
    for (auto _ : state) {
        const std::size_t k = i++ & 4095;
        benchmark::DoNotOptimize(grape::slerp(rotations()[k], rotations()[(k + 1) & 4095], random_t()[k]));
    }
}
void BM_slerp_prepared(benchmark::State& state) {
    const grape::Slerp s(rotations()[0], rotations()[1]);
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(s(random_t()[i++ & 4095]));
}
void BM_spline_orientation(benchmark::State& state) {
    const grape::QuatSpline& s = spline100();
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(s.orientation(99.0 * random_t()[i++ & 4095]));
}
void BM_spline_angular_velocity(benchmark::State& state) {
    const grape::QuatSpline& s = spline100();
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(s.angular_velocity(99.0 * random_t()[i++ & 4095]));
}
void BM_from_basis(benchmark::State& state) {
    std::vector<grape::Basis> bases;
    for (std::size_t k = 0; k < 512; ++k) bases.push_back(grape::to_basis(rotations()[k]));
    std::size_t i = 0;
    for (auto _ : state) {
        const grape::Basis& b = bases[i++ & 511];
        benchmark::DoNotOptimize(grape::from_basis_unchecked(b.x, b.y, b.z));
    }
}
void BM_to_euler(benchmark::State& state) {
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(grape::to_euler(rotations()[i++ & 4095], grape::EulerOrder::zyx));
}
void BM_spline_build(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    int iterations = 0;
    for (auto _ : state) {
        const grape::QuatSpline s = make_spline(n, 7);
        iterations = s.iterations();
        benchmark::DoNotOptimize(s);
    }
    state.counters["newton_steps"] = iterations;
}

}  // namespace

BENCHMARK(BM_slerp);
BENCHMARK(BM_slerp_prepared);
BENCHMARK(BM_spline_orientation);
BENCHMARK(BM_spline_angular_velocity);
BENCHMARK(BM_from_basis);
BENCHMARK(BM_to_euler);
BENCHMARK(BM_spline_build)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
