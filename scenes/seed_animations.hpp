// grape — the seed's animation examples and the animation benchmark set-ups as named scenes,
// shared by the tests, the benchmarks, the tool's demo and the examples.
#pragma once

#include <grape/anim.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace grape::scenes {

/// A display object as the seed's examples move it: position and rotation (radians).
struct Sprite {
    double x = 0.0;
    double y = 0.0;
    double rotation = 0.0;
};

/// The seed's first example: `view` along seed_spiral() for 2 seconds, linear.
Animation seed_spiral_animation(Engine& engine, Sprite& view, const AnimationDef& def = {});

/// The seed's complex path (spiral, then three segments, cues 0, 0.25, 0.5, 0.6) for 4 s.
Animation seed_complex_animation(Engine& engine, Sprite& view, const AnimationDef& def = {});

/// The benchmark's path kinds: (a) linear, (b) cubic Bézier, (c) cubic Bézier by arc length;
/// then cubics with all four points random in the box (loops, cusps and near-cusps: arc-length
/// tables of up to thousands of pieces), and SVG path data of 8 segments (C Q A L, as
/// segments_svg), each by u and by arc length.
enum class BenchPathKind {
    linear,
    cubic_bezier,
    reparametrized_cubic_bezier,
    random_cubic_bezier,
    reparametrized_random_cubic_bezier,
    svg,
    reparametrized_svg
};

/// The enumerator's name, e.g. "reparametrized_cubic_bezier".
std::string_view to_string(BenchPathKind kind) noexcept;

/// A segment of the benchmark: where path i starts and ends (random in a 1000 × 1000 box,
/// fixed seed), so a peer tweening two numbers can do the same journey.
struct BenchSegment {
    Vec2 from;
    Vec2 to;
};

/// `count` segments from a fixed seed.
std::vector<BenchSegment> bench_segments(std::size_t count, std::uint64_t seed = 1);

/// One shared path per segment: the segment itself, or a cubic Bézier through its ends
/// with control points bent off the chord (reparametrized by arc length for kind (c)).
std::vector<Path> bench_paths(BenchPathKind kind, std::span<const BenchSegment> segments);

/// Seconds per play of animation i: spread over [1, 3) so plays end on different ticks.
double bench_duration(std::size_t i) noexcept;

/// The 2-D target of the benchmark: a plain struct.
struct BenchTarget {
    double x = 0.0;
    double y = 0.0;
};

/// Animation i moves targets[i] along paths[i % paths.size()] with `curve`, repeating
/// forever with yoyo, for bench_duration(i) per play.
void create_bench_animations(Engine& engine, std::span<BenchTarget> targets, std::span<const Path> paths,
                             const Curve& curve);

}  // namespace grape::scenes
