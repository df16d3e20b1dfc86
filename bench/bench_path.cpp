// Paths: ns per point(u) for every kind; the arc-length table (reparametrized()): build time and
// ns per lookup; and, in the same run, what game engines usually do instead: bake the path into
// points every few pixels of length and interpolate linearly between them (Godot's Curve2D
// bake_interval, Unity/DOTween path tables, GSAP's sampled lengths). Both are measured for
// speed and for their worst position error against the true arc-length point.
//
//   build-bench/bench/bench_path --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// After the runs a summary prints the ratios (baked / exact) and the errors.
#include <grape/path.hpp>

#include <seed_paths.hpp>

#include "path/kernel.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

using grape::Path;
using grape::Vec2;

std::vector<double> random_parameters(std::size_t count, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<double> u(count);
    for (double& x : u) x = uniform(rng);
    return u;
}

struct NamedPath {
    std::string name;
    Path path;
};

const char* const svg_arcs = "M10 315 L 110 215 A 30 50 0 0 1 162.55 162.45 L 172.55 152.45 "
                             "A 30 50 -45 0 1 215.1 109.9 L 315 10";

// One path of every kind (the studio's gallery), plus SVG data and an arc-length path.
std::vector<NamedPath> every_kind() {
    std::vector<NamedPath> all;
    for (auto& [name, path] : grape::scenes::path_gallery()) all.push_back({name, path});
    all.push_back({"svg_arcs", grape::parse_svg_path(svg_arcs)});
    all.push_back({"bezier_reparametrized", grape::scenes::seed_bezier(true)});
    return all;
}

// Paths for the arc-length comparison: the seed's Bézier (its speed varies about 2:1), its
// spiral (speed falls to about a sixth), its nested complex path, and SVG data with ellipses.
std::vector<NamedPath> arc_length_paths() {
    return {{"bezier", grape::scenes::seed_bezier()},
            {"spiral", grape::scenes::seed_spiral()},
            {"nested_complex", grape::scenes::seed_nested_complex()},
            {"svg_arcs", grape::parse_svg_path(svg_arcs)},
            {"svg_10000", grape::parse_svg_path(grape::scenes::segments_svg(10000, 17))}};
}

// The engines' way: walk the path in small parameter steps, accumulate chord length, and keep
// a point every `spacing` pixels of it; a lookup at fraction f of the length interpolates
// linearly between the two neighbouring points.
class BakedTable {
public:
    BakedTable(const Path& path, double spacing) : spacing_(spacing) {
        // Eight sub-steps per spacing of the (exact) length, as engines oversample before
        // resampling; the table's own length is that of the fine polyline.
        const auto steps = static_cast<std::size_t>(std::ceil(8.0 * path.length() / spacing)) + 1;
        Vec2 previous = path.point(0.0);
        points_.push_back(previous);
        double travelled = 0.0;
        double next = spacing;
        for (std::size_t i = 1; i <= steps; ++i) {
            const Vec2 p = path.point(static_cast<double>(i) / static_cast<double>(steps));
            const double chord = grape::distance(previous, p);
            while (chord > 0.0 && travelled + chord >= next) {
                points_.push_back(grape::lerp(previous, p, (next - travelled) / chord));
                next += spacing;
            }
            travelled += chord;
            previous = p;
        }
        length_ = travelled;
        last_ = travelled - spacing * static_cast<double>(points_.size() - 1);
        points_.push_back(previous);
    }

    Vec2 at_fraction(double f) const noexcept {
        const double x = f * length_ / spacing_;
        const std::size_t last = points_.size() - 2;
        const auto i = std::min(static_cast<std::size_t>(std::max(x, 0.0)), last);
        double t = x - static_cast<double>(i);
        if (i == last) t = last_ > 0.0 ? t * spacing_ / last_ : 1.0;  // the shorter final interval
        return grape::lerp(points_[i], points_[i + 1], std::clamp(t, 0.0, 1.0));
    }

    std::size_t size() const noexcept { return points_.size(); }

private:
    double spacing_;
    double length_ = 0.0;
    double last_ = 0.0;
    std::vector<Vec2> points_;
};

// The true arc-length point at fractions f = k/n: u solving ∫₀ᵘ |x′| = f·L, the integral by
// adaptive Gauss–Legendre over each smooth piece (between the path's breaks) to 1e-13·L and
// the root to 1e-14 in u, independent of the path's own arc-length table.
std::vector<Vec2> true_arc_length_points(const Path& path, int n) {
    auto speed = [&](double u) noexcept { return grape::length(path.d1(u)); };
    const auto breaks = grape::detail::smooth_breaks(path);
    const double tol = 1e-13 * path.length() / static_cast<double>(breaks.size());
    std::vector<double> s_at(breaks.size(), 0.0);  // arc length at each break
    for (std::size_t b = 1; b < breaks.size(); ++b) s_at[b] = s_at[b - 1] + grape::integrate(speed, breaks[b - 1], breaks[b], tol);
    const double total = s_at.back();
    std::vector<Vec2> out;
    out.reserve(static_cast<std::size_t>(n) + 1);
    std::size_t piece = 0;
    for (int k = 0; k <= n; ++k) {
        const double target = total * k / n;
        while (piece + 2 < breaks.size() && s_at[piece + 1] < target) ++piece;
        const double a = breaks[piece], b = breaks[piece + 1];
        auto fd = [&](double u) noexcept {
            return std::pair{s_at[piece] + grape::integrate(speed, a, u, tol) - target, speed(u)};
        };
        out.push_back(path.point(grape::find_root(fd, a, b, 0.5 * (a + b), 1e-14).x));
    }
    return out;
}

template <class Lookup>
double worst_error(const std::vector<Vec2>& truth, Lookup&& lookup) {
    const int n = static_cast<int>(truth.size()) - 1;
    double worst = 0.0;
    for (int k = 0; k <= n; ++k) {
        worst = std::max(worst, grape::distance(lookup(static_cast<double>(k) / n), truth[static_cast<std::size_t>(k)]));
    }
    return worst;
}

constexpr std::size_t lookups = 4096;  // a power of two: the index wraps with a mask

void point_benchmark(benchmark::State& state, const Path& path) {
    const std::vector<double> u = random_parameters(lookups, 1);
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(path.point(u[i++ & (lookups - 1)]));
    }
}

void build_exact(benchmark::State& state, const Path& path) {
    for (auto _ : state) {
        Path r = path.reparametrized();
        benchmark::DoNotOptimize(r);
    }
}

void build_baked(benchmark::State& state, const Path& path, double spacing) {
    for (auto _ : state) {
        BakedTable table(path, spacing);
        benchmark::DoNotOptimize(table);
    }
}

void lookup_exact(benchmark::State& state, const Path& reparametrized, double error) {
    const std::vector<double> f = random_parameters(lookups, 2);
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(reparametrized.point(f[i++ & (lookups - 1)]));
    }
    state.counters["max_err_px"] = error;
}

void lookup_baked(benchmark::State& state, const BakedTable& table, double error) {
    const std::vector<double> f = random_parameters(lookups, 2);
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(table.at_fraction(f[i++ & (lookups - 1)]));
    }
    state.counters["max_err_px"] = error;
    state.counters["points"] = static_cast<double>(table.size());
}

// Keeps each run's CPU time (the median when repeated) for the ratio summary.
class SummaryReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            if (run.run_type == Run::RT_Aggregate && run.aggregate_name != "median") continue;
            std::string name = run.run_name.function_name;
            if (!run.run_name.args.empty()) name += "/" + run.run_name.args;
            ns_[name] = run.GetAdjustedCPUTime();  // CPU time: steadier than wall time on a shared machine
            const auto e = run.counters.find("max_err_px");
            if (e != run.counters.end()) error_[name] = e->second.value;
        }
    }
    double ns(const std::string& name) const {
        const auto it = ns_.find(name);
        return it == ns_.end() ? std::nan("") : it->second;
    }
    double error(const std::string& name) const {
        const auto it = error_.find(name);
        return it == error_.end() ? std::nan("") : it->second;
    }

private:
    std::map<std::string, double> ns_;
    std::map<std::string, double> error_;
};

constexpr double spacings[] = {1.0, 5.0, 20.0};  // pixels; 5 is Godot's default bake_interval

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

    const std::vector<NamedPath> kinds = every_kind();
    for (const NamedPath& k : kinds) {
        benchmark::RegisterBenchmark(("point/" + k.name).c_str(), point_benchmark, k.path);
    }

    struct Comparison {
        NamedPath path;
        Path exact;
        double exact_error;
        std::vector<double> spacings;
        std::vector<BakedTable> tables;
        std::vector<double> table_errors;
    };
    std::vector<Comparison> comparisons;
    for (const NamedPath& p : arc_length_paths()) {
        Comparison c{p, p.path.reparametrized(), 0.0, {}, {}, {}};
        const std::vector<Vec2> truth = true_arc_length_points(p.path, 2000);
        c.exact_error = worst_error(truth, [&](double f) { return c.exact.point(f); });
        for (const double spacing : spacings) {
            // A 1 px table of the 10,000-segment path would hold ~5 million points: left out.
            if (p.path.length() / spacing > 1e6) continue;
            c.spacings.push_back(spacing);
            c.tables.emplace_back(p.path, spacing);
            const BakedTable& table = c.tables.back();
            c.table_errors.push_back(worst_error(truth, [&](double f) { return table.at_fraction(f); }));
        }
        comparisons.push_back(std::move(c));
    }
    for (const Comparison& c : comparisons) {
        const std::string& name = c.path.name;
        benchmark::RegisterBenchmark(("build/exact/" + name).c_str(), build_exact, c.path.path)->Unit(benchmark::kMicrosecond);
        benchmark::RegisterBenchmark(("lookup/exact/" + name).c_str(), lookup_exact, c.exact, c.exact_error);
        for (std::size_t s = 0; s < c.spacings.size(); ++s) {
            const std::string tag = std::to_string(static_cast<int>(c.spacings[s])) + "px/" + name;
            benchmark::RegisterBenchmark(("build/baked_" + tag).c_str(), build_baked, c.path.path, c.spacings[s])
                ->Unit(benchmark::kMicrosecond);
            benchmark::RegisterBenchmark(("lookup/baked_" + tag).c_str(), lookup_baked, std::cref(c.tables[s]),
                                         c.table_errors[s]);
        }
    }

    SummaryReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);

    std::printf("\nArc-length lookup: exact table (reparametrized) vs baked points + lerp (same run)\n");
    std::printf("%-16s %-10s %12s %12s %14s %14s %10s\n", "path", "method", "build_us", "lookup_ns",
                "lookup_ratio", "max_err_px", "length_px");
    for (const Comparison& c : comparisons) {
        const std::string& name = c.path.name;
        const double exact_ns = reporter.ns("lookup/exact/" + name);
        std::printf("%-16s %-10s %12.2f %12.2f %14s %14.3g %10.2f\n", name.c_str(), "exact",
                    reporter.ns("build/exact/" + name), exact_ns, "1", c.exact_error, c.path.path.length());
        for (std::size_t s = 0; s < c.spacings.size(); ++s) {
            const std::string tag = std::to_string(static_cast<int>(c.spacings[s])) + "px/" + name;
            const double baked_ns = reporter.ns("lookup/baked_" + tag);
            char ratio[32];
            std::snprintf(ratio, sizeof ratio, "%.2f", baked_ns / exact_ns);
            const std::string method = "baked " + std::to_string(static_cast<int>(c.spacings[s])) + "px";
            std::printf("%-16s %-10s %12.2f %12.2f %14s %14.3g %10s\n", name.c_str(), method.c_str(),
                        reporter.ns("build/baked_" + tag), baked_ns, ratio, c.table_errors[s], "");
        }
    }
    benchmark::Shutdown();
    return 0;
}
