// grape — the seed's paths as named scenes, shared by the tests, the benchmarks, the tool's
// demo and the pictures. Coordinates are the seed's (pixels, y down).
#pragma once

#include <grape/path.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace grape::scenes {

/// The seed's spiral: center (100, 100), radius 200 → 0 over one turn.
SpiralPath seed_spiral();

/// The seed's four-part complex path: the spiral, then segments (100,100)→(200,200)→(200,100)
/// →(100,100), cues [0, 0.25, 0.5, 0.6] (shares 25%, 25%, 10%, 40%).
ComplexPath seed_complex();

/// The three circles of the seed's nested example, as one complex path (cues [0, 0.25, 0.5]).
ComplexPath seed_circles();

/// The seed's nested example: seed_circles(), a cubic Bézier and a sine wave, cues [0, 0.5, 0.75].
ComplexPath seed_nested_complex();

/// The seed's cubic Bézier (20,20), (400,200), (400,600), (600,600), optionally by arc length.
CubicBezierPath seed_bezier(bool reparametrize = false);

/// The seed's spline point sets p1, p2, p3 as flat x, y pairs (6 points each).
inline constexpr std::array<double, 12> seed_p1{20, 20, 100, 100, 120, 50, 300, 300, 400, 50, 500, 200};
inline constexpr std::array<double, 12> seed_p2{20, 120, 100, 200, 120, 150, 300, 400, 400, 150, 500, 300};
inline constexpr std::array<double, 12> seed_p3{20, 220, 100, 300, 120, 250, 300, 500, 400, 250, 500, 400};

/// p1 through a linear spline, p2 through a cosine spline, p3 through a Catmull–Rom spline.
LinearSplinePath seed_linear_spline();
CosineSplinePath seed_cosine_spline();
CatmullRomSplinePath seed_catmull_rom_spline(CatmullRom type = CatmullRom::uniform);

/// Every path the seed names, in the seed's order.
std::vector<NamedPath> seed_paths();

/// One path of every kind (and every Catmull–Rom type), laid out on a 600 × 600 canvas.
std::vector<NamedPath> path_gallery();

/// SVG path data of 100 drawn segments cycling C, Q, A, L over pseudo-random coordinates in a
/// 1000 × 1000 box (a fixed seed): the path-query tests' and benchmarks' long path.
std::string hundred_segments_svg();

/// SVG path data of `count` segments drawn the same way from `seed` (hundred_segments_svg is
/// segments_svg(100, 100)): long paths for the arc-length tests and benchmarks.
std::string segments_svg(int count, std::uint64_t seed);

}  // namespace grape::scenes
