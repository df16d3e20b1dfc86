// Curve evaluation, ns per call over 4096 fixed t in [0, 1]: cubic-bezier as solved before
// (Newton to |x − t| ≤ 1e-12 in power form, bisection fallback; copied here as it was) and
// now (to round-off from the nearer end), on ease, ease-in and a curve with an interior flat
// point, run alternately in one process; the custom kinds (svg, spring, function, out-in);
// and the engine's tick with cubic-bezier curves (ns per 2-D update, 100,000 animations).
#include <grape/anim.hpp>
#include <grape/curve.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

// The solver before round-off solving (src/curve/curve.cpp until then), for comparison.
double cubic_bezier_before(double x1, double y1, double x2, double y2, double t) noexcept {
    if (!(t > 0.0)) return t;
    if (t >= 1.0) return 1.0;
    const double cx = 3.0 * x1;
    const double bx = 3.0 * (x2 - x1) - cx;
    const double ax = 1.0 - cx - bx;
    const double cy = 3.0 * y1;
    const double by = 3.0 * (y2 - y1) - cy;
    const double ay = 1.0 - cy - by;
    constexpr double tolerance = 1e-12;
    auto x_of = [&](double u) { return ((ax * u + bx) * u + cx) * u; };
    double u = t;
    bool solved = false;
    for (int i = 0; i < 8; ++i) {
        const double f = x_of(u) - t;
        if (std::abs(f) <= tolerance) { solved = true; break; }
        const double slope = (3.0 * ax * u + 2.0 * bx) * u + cx;
        if (std::abs(slope) < 1e-9) break;
        u -= f / slope;
        if (!(u >= 0.0 && u <= 1.0)) break;
    }
    if (!solved) {
        double lo = 0.0;
        double hi = 1.0;
        u = t;
        for (int i = 0; i < 200; ++i) {
            const double f = x_of(u) - t;
            if (std::abs(f) <= tolerance) break;
            if (f > 0.0) hi = u; else lo = u;
            u = 0.5 * (lo + hi);
        }
    }
    return ((ay * u + by) * u + cy) * u;
}

const std::vector<double>& ts() {
    static const std::vector<double> t = [] {
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::vector<double> v(4096);
        for (double& x : v) x = unit(rng);
        return v;
    }();
    return t;
}

struct Controls { double x1, y1, x2, y2; };
constexpr Controls ease{0.25, 0.1, 0.25, 1.0};
constexpr Controls ease_in{0.42, 0.0, 1.0, 1.0};
constexpr Controls flat{1.0, 0.0, 0.0, 1.0};

void before(benchmark::State& state, Controls k) {
    double sum = 0;
    for (auto _ : state) {
        for (double t : ts()) sum += cubic_bezier_before(k.x1, k.y1, k.x2, k.y2, t);
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long>(ts().size()));
}

void curve(benchmark::State& state, const grape::Curve& c) {
    double sum = 0;
    for (auto _ : state) {
        for (double t : ts()) sum += c(t);
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long>(ts().size()));
}

void after(benchmark::State& state, Controls k) { curve(state, grape::Curve::cubic_bezier(k.x1, k.y1, k.x2, k.y2)); }

void engine_bezier(benchmark::State& state) {
    struct Sprite { double x = 0, y = 0; };
    constexpr int n = 100000;
    std::vector<Sprite> sprites(n);
    grape::Engine engine;
    const grape::CubicBezierPath path({0, 0}, {30, 100}, {70, -50}, {100, 0});
    const grape::Curve c = grape::parse_curve("ease");
    for (Sprite& s : sprites) engine.create_2d_animation(s, path, 2.0, {.curve = c, .repeat = -1, .yoyo = true});
    for (auto _ : state) engine.tick(1.0 / 60.0);
    state.SetItemsProcessed(state.iterations() * n);
}

}  // namespace

// Alternating before/after on each curve, so drift on a shared machine hits both alike.
BENCHMARK_CAPTURE(before, ease, ease);
BENCHMARK_CAPTURE(after, ease, ease);
BENCHMARK_CAPTURE(before, ease_in, ease_in);
BENCHMARK_CAPTURE(after, ease_in, ease_in);
BENCHMARK_CAPTURE(before, flat_point, flat);
BENCHMARK_CAPTURE(after, flat_point, flat);
BENCHMARK_CAPTURE(curve, svg_two_segments, grape::Curve::svg("M0,0 C0.1,0.8 0.3,1.1 0.6,1 S0.9,1 1,1"));
BENCHMARK_CAPTURE(curve, spring_under, grape::Curve::spring({.stiffness = 100, .damping = 4}));
BENCHMARK_CAPTURE(curve, spring_over, grape::Curve::spring({.stiffness = 100, .damping = 50}));
BENCHMARK_CAPTURE(curve, function, grape::Curve::from_function([](double t) { return t * t * (3 - 2 * t); }));
BENCHMARK_CAPTURE(curve, quad_in_out, grape::Curve::quad_in_out());
BENCHMARK_CAPTURE(curve, quad_out_in, grape::Curve::quad_out_in());
BENCHMARK(engine_bezier);

BENCHMARK_MAIN();
