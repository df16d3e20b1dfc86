#include "seed_animations.hpp"

#include "seed_paths.hpp"

#include <random>

namespace grape::scenes {

Animation seed_spiral_animation(Engine& engine, Sprite& view, const AnimationDef& def) {
    return engine.create_2d_animation(view, seed_spiral(), 2.0, def);
}

Animation seed_complex_animation(Engine& engine, Sprite& view, const AnimationDef& def) {
    return engine.create_2d_animation(view, seed_complex(), 4.0, def);
}

std::string_view to_string(BenchPathKind kind) noexcept {
    switch (kind) {
        case BenchPathKind::linear: return "linear";
        case BenchPathKind::cubic_bezier: return "cubic_bezier";
        case BenchPathKind::reparametrized_cubic_bezier: return "reparametrized_cubic_bezier";
        case BenchPathKind::random_cubic_bezier: return "random_cubic_bezier";
        case BenchPathKind::reparametrized_random_cubic_bezier: return "reparametrized_random_cubic_bezier";
        case BenchPathKind::svg: return "svg";
        case BenchPathKind::reparametrized_svg: return "reparametrized_svg";
    }
    return "unknown";
}

std::vector<BenchSegment> bench_segments(std::size_t count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> coordinate(0.0, 1000.0);
    std::vector<BenchSegment> segments(count);
    for (BenchSegment& s : segments) {
        s.from = {coordinate(rng), coordinate(rng)};
        s.to = {coordinate(rng), coordinate(rng)};
    }
    return segments;
}

std::vector<Path> bench_paths(BenchPathKind kind, std::span<const BenchSegment> segments) {
    std::vector<Path> paths;
    paths.reserve(segments.size());
    const std::size_t n = segments.size();
    for (std::size_t i = 0; i < n; ++i) {
        const BenchSegment& s = segments[i];
        if (kind == BenchPathKind::linear) {
            paths.push_back(LinearPath(s.from, s.to));
            continue;
        }
        if (kind == BenchPathKind::random_cubic_bezier || kind == BenchPathKind::reparametrized_random_cubic_bezier) {
            // The controls are the next segment's ends: anywhere in the box.
            const BenchSegment& next = segments[(i + 1) % n];
            paths.push_back(CubicBezierPath(s.from, next.from, next.to, s.to,
                                            kind == BenchPathKind::reparametrized_random_cubic_bezier));
            continue;
        }
        if (kind == BenchPathKind::svg || kind == BenchPathKind::reparametrized_svg) {
            const Path path = parse_svg_path(segments_svg(8, 1000 + i));
            paths.push_back(kind == BenchPathKind::reparametrized_svg ? path.reparametrized() : path);
            continue;
        }
        // Controls at a third and two thirds of the chord, pushed to either side, so the
        // speed along u varies (what reparametrization is for).
        const Vec2 chord = s.to - s.from;
        const Vec2 side = perpendicular(chord) * 0.4;
        const Vec2 c1 = s.from + chord / 3.0 + side;
        const Vec2 c2 = s.from + chord * (2.0 / 3.0) - side;
        paths.push_back(CubicBezierPath(s.from, c1, c2, s.to, kind == BenchPathKind::reparametrized_cubic_bezier));
    }
    return paths;
}

double bench_duration(std::size_t i) noexcept { return 1.0 + 2.0 * static_cast<double>(i % 1000) / 1000.0; }

void create_bench_animations(Engine& engine, std::span<BenchTarget> targets, std::span<const Path> paths,
                             const Curve& curve) {
    const AnimationDef def{.curve = curve, .repeat = -1, .yoyo = true};
    for (std::size_t i = 0; i < targets.size(); ++i)
        engine.create_2d_animation(targets[i], paths[i % paths.size()], bench_duration(i), def);
}

}  // namespace grape::scenes
