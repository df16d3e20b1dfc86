// grape — the seed's paths (see seed_paths.hpp).
#include "seed_paths.hpp"

#include <cstdio>
#include <random>
#include <span>

namespace grape::scenes {

SpiralPath seed_spiral() { return SpiralPath({100, 100}, 200, 0); }

ComplexPath seed_complex() {
    return ComplexPath({seed_spiral(), LinearPath({100, 100}, {200, 200}), LinearPath({200, 200}, {200, 100}),
                        LinearPath({200, 100}, {100, 100})},
                       {0, 0.25, 0.5, 0.6});
}

ComplexPath seed_circles() {
    return ComplexPath({CirclePath({150, 200}, 50, 2 * pi, 0), CirclePath({250, 200}, 50, pi, 3 * pi),
                        CirclePath({300, 200}, 100, pi, 3 * pi)},
                       {0, 0.25, 0.5});
}

ComplexPath seed_nested_complex() {
    return ComplexPath({seed_circles(), CubicBezierPath({200, 200}, {350, 0}, {350, 500}, {350, 200}),
                        SineWavePath({350, 200}, {200, 200}, 3, 50)},
                       {0, 0.5, 0.75});
}

CubicBezierPath seed_bezier(bool reparametrize) {
    return CubicBezierPath({20, 20}, {400, 200}, {400, 600}, {600, 600}, reparametrize);
}

LinearSplinePath seed_linear_spline() { return LinearSplinePath(std::span<const double>(seed_p1)); }
CosineSplinePath seed_cosine_spline() { return CosineSplinePath(std::span<const double>(seed_p2)); }
CatmullRomSplinePath seed_catmull_rom_spline(CatmullRom type) {
    return CatmullRomSplinePath(std::span<const double>(seed_p3), type);
}

std::vector<NamedPath> seed_paths() {
    return {
        {"spiral", seed_spiral()},
        {"complex", seed_complex()},
        {"bezier", seed_bezier()},
        {"bezier_reparametrized", seed_bezier(true)},
        {"linear_spline_p1", seed_linear_spline()},
        {"cosine_spline_p2", seed_cosine_spline()},
        {"catmull_rom_spline_p3", seed_catmull_rom_spline()},
        {"circles", seed_circles()},
        {"nested_complex", seed_nested_complex()},
    };
}

std::vector<NamedPath> path_gallery() {
    const std::vector<Vec2> wave{{40, 500}, {120, 440}, {200, 520}, {280, 450}, {360, 560}};
    const std::vector<Vec2> wave_tangents{{80, -120}, {80, 0}, {80, 40}, {80, 0}, {80, 120}};
    return {
        {"linear", LinearPath({40, 40}, {200, 120})},
        {"circle", CirclePath({300, 80}, 50, 0, 1.5 * pi)},
        {"elliptical_arc", EllipticalArcPath({480, 80}, 80, 40, pi / 6, 0, 1.75 * pi)},
        {"spiral", SpiralPath({100, 230}, 70, 10, 0, 4 * pi)},
        {"sine_wave", SineWavePath({220, 230}, {560, 230}, 4, 30)},
        {"quadratic_bezier", QuadraticBezierPath({40, 330}, {140, 260}, {240, 380})},
        {"cubic_bezier", CubicBezierPath({280, 380}, {320, 260}, {500, 420}, {560, 300})},
        {"linear_spline", LinearSplinePath({40, 400, 100, 460, 160, 410, 220, 470})},
        {"cosine_spline", CosineSplinePath({300, 400, 360, 460, 420, 410, 480, 470})},
        {"hermite_spline", HermiteSplinePath(wave, wave_tangents)},
        {"catmull_rom_uniform", CatmullRomSplinePath({400, 500, 430, 590, 440, 520, 480, 505, 560, 590})},
        {"catmull_rom_centripetal",
         CatmullRomSplinePath({400, 500, 430, 590, 440, 520, 480, 505, 560, 590}, CatmullRom::centripetal)},
        {"catmull_rom_chordal",
         CatmullRomSplinePath({400, 500, 430, 590, 440, 520, 480, 505, 560, 590}, CatmullRom::chordal)},
        {"physics", PhysicsPath({40, 590}, {120, -200}, {0, 250}, 1.6)},
        {"complex", ComplexPath::by_length({LinearPath({240, 590}, {300, 540}),
                                            CirclePath({330, 540}, 30, pi, 2 * pi),
                                            CubicBezierPath({360, 540}, {380, 600}, {240, 600}, {260, 580})})},
        {"reparametrized", CubicBezierPath({40, 130}, {60, 200}, {200, 130}, {210, 190}).reparametrized()},
    };
}

std::string hundred_segments_svg() { return segments_svg(100, 100); }

std::string segments_svg(int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> c(0.0, 1000.0);
    std::string d = "M500 500";
    char buf[160];
    for (int i = 0; i < count; ++i) {
        // Drawn in sequence first: the order in which a call's arguments are evaluated is
        // unspecified, and the path must be the same whatever the compiler.
        double v[6];
        for (double& x : v) x = c(rng);
        switch (i % 4) {
            case 0: std::snprintf(buf, sizeof buf, " C%.1f %.1f %.1f %.1f %.1f %.1f", v[0], v[1], v[2], v[3], v[4], v[5]); break;
            case 1: std::snprintf(buf, sizeof buf, " Q%.1f %.1f %.1f %.1f", v[0], v[1], v[2], v[3]); break;
            case 2: std::snprintf(buf, sizeof buf, " A%.1f %.1f %.1f 0 1 %.1f %.1f", 50 + 0.3 * v[0], 50 + 0.2 * v[1], 0.36 * v[2], v[3], v[4]); break;
            default: std::snprintf(buf, sizeof buf, " L%.1f %.1f", v[0], v[1]);
        }
        d += buf;
    }
    return d;
}

}  // namespace grape::scenes
