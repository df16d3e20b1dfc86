// The seed's spiral and Bézier: points, lengths, constant speed by arc length.
#include <grape/path.hpp>

#include <cstdio>

int main() {
    const grape::SpiralPath spiral({100, 100}, 200, 0);  // center, radius 200 → 0
    const grape::CubicBezierPath bez({20, 20}, {400, 200}, {400, 600}, {600, 600});
    const grape::Path even = bez.reparametrized();        // same shape, constant speed
    const grape::ComplexPath both = grape::ComplexPath::by_length({spiral, grape::LinearPath({100, 100}, {20, 20}), bez});

    std::printf("spiral %.3f px, bezier %.3f px, both %.3f px\n", spiral.length(), bez.length(), both.length());
    for (double u : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        const grape::Vec2 a = bez.point(u), b = even.point(u);
        std::printf("u=%.2f  bezier (%6.1f, %6.1f)  by length (%6.1f, %6.1f)\n", u, a.x, a.y, b.x, b.y);
    }
    return both.point(1.0) == bez.point(1.0) ? 0 : 1;
}
