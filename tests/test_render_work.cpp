// The work of drawing a path is bounded by what the picture shows: a very dense sine wave and
// a huge-radius ellipse hand cairo a number of pieces proportional to their size on the
// picture, and ordinary paths are drawn exactly as before.
#include <grape/path.hpp>
#include <grape/render.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

using namespace grape;

namespace {

constexpr double tau = 6.283185307179586;

// The coverage mask (alpha above a quarter) of a picture.
std::vector<bool> mask(const Image& image) {
    std::vector<bool> out;
    for (std::uint32_t p : image.argb()) out.push_back((p >> 24) > 64);
    return out;
}

// Pixels of `a` with no pixel of `b` within one pixel (8-neighbourhood): what a 1 px
// dilation of b does not cover.
int uncovered(const std::vector<bool>& a, const std::vector<bool>& b, int w, int h) {
    int count = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!a[static_cast<std::size_t>(y * w + x)]) continue;
            bool near = false;
            for (int dy = -1; dy <= 1 && !near; ++dy)
                for (int dx = -1; dx <= 1 && !near; ++dx) {
                    const int u = x + dx, v = y + dy;
                    near = u >= 0 && v >= 0 && u < w && v < h && b[static_cast<std::size_t>(v * w + u)];
                }
            count += !near;
        }
    return count;
}

const StrokeStyle line{.color = {0, 0, 0, 1}, .width = 1.5};

}  // namespace

TEST(DrawingWork, AVeryDenseSineWaveTakesWorkProportionalToItsLengthOnThePicture) {
    // 10⁵ waves over 1000 units drawn ~580 px wide: before, 5·10⁵ points (0.7 s of
    // flattening, growing with the waves); now a zigzag every quarter pixel, ≤ 4 pieces a
    // pixel of axis, whatever the number of waves.
    const SineWavePath dense({0, 0}, {1000, 0}, 1e5, 10);
    Canvas canvas(640, 480);
    canvas.set_transform(fit(dense.bounds(), {0, 0, 640, 480}, 30));
    const double axis = 1000.0 * canvas.transform().max_stretch();
    EXPECT_LE(static_cast<double>(canvas.path_pieces(dense)), 4.0 * axis + 2.0);
    // An amplitude within a quarter pixel is drawn as the axis: one piece.
    EXPECT_EQ(canvas.path_pieces(SineWavePath({0, 0}, {1000, 0}, 1e5, 1e-4)), 1u);
}

TEST(DrawingWork, ADenseSineIsTheBandItFillsWithinAPixel) {
    // 10⁴ waves (0.06 px each, flattened as they are in ~0.1 s): the zigzag and the wave's
    // own flattening cover the same pixels up to a 1 px dilation of either.
    const SineWavePath dense({0, 0}, {1000, 0}, 1e4, 10);
    const Affine view = fit(dense.bounds(), {0, 0, 640, 480}, 30);
    Canvas zigzag(640, 480), exact(640, 480);
    zigzag.set_transform(view);
    exact.set_transform(view);
    zigzag.stroke_path(dense, line);
    exact.stroke_polyline(dense.flatten(0.25 / view.max_stretch()), line);
    const auto a = mask(zigzag.to_image()), b = mask(exact.to_image());
    EXPECT_EQ(uncovered(a, b, 640, 480), 0);
    EXPECT_EQ(uncovered(b, a, 640, 480), 0);
    EXPECT_LT(static_cast<double>(zigzag.path_pieces(dense)), 0.2 * static_cast<double>(dense.flatten(0.25 / view.max_stretch()).size()));
}

TEST(DrawingWork, AHugeRadiusEllipseIsAFewPiecesWhateverItsRadius) {
    // Before: cairo split a circle of radius 1e12 px into 150 Béziers, 1e20 into 3220 and
    // spent tens of seconds on 1e50. Beyond 1e6 px only the part near the picture is divided
    // (depth ≤ 64, two pieces a level near the picture): measured ≤ 58 pieces.
    for (double r : {1e3, 1e6, 1e9, 1e12, 1e20, 1e50, 1e100, 1e300}) {
        SCOPED_TRACE(r);
        Canvas canvas(640, 480);
        EXPECT_LE(canvas.path_pieces(CirclePath({320, 240 + r}, r, 0, tau)), 128u);
        EXPECT_LE(canvas.path_pieces(EllipticalArcPath({320, 240 + r}, 2 * r, r, 0.3, 0, tau)), 128u);
    }
}

TEST(DrawingWork, AHugeCircleLooksLikeTheLineItIsOnThePicture) {
    // Radius 1e12 touching y = 240 from below: over the picture's 640 px it strays from the
    // tangent by 320²/(2·1e12) ≈ 5e-8 px, so it covers the same pixels as the line (up to a
    // 1 px dilation either way, for antialiasing).
    for (double r : {1e7, 1e12, 1e100}) {
        SCOPED_TRACE(r);
        Canvas arc(640, 480), straight(640, 480);
        arc.stroke_path(CirclePath({320, 240 + r}, r, 0, tau), line);
        straight.stroke_line({-10, 240}, {650, 240}, line);
        const auto a = mask(arc.to_image()), b = mask(straight.to_image());
        EXPECT_EQ(uncovered(a, b, 640, 480), 0);
        EXPECT_EQ(uncovered(b, a, 640, 480), 0);
    }
}

TEST(DrawingWork, OrdinaryWavesAreDrawnExactlyAsBefore) {
    // Waves of several pixels take Path::flatten within a quarter pixel, as before: the same
    // pixels, bit for bit, as that polyline.
    for (const SineWavePath& wave : {SineWavePath({0, 0}, {600, 0}, 3, 50), SineWavePath({10, 10}, {300, 400}, 40, 8),
                                     SineWavePath({0, 0}, {600, 0}, 300, 20)}) {
        Canvas drawn(640, 480), before(640, 480);
        const Affine view = fit(wave.bounds(), {0, 0, 640, 480}, 30);
        drawn.set_transform(view);
        before.set_transform(view);
        drawn.stroke_path(wave, line);
        before.stroke_polyline(wave.flatten(0.25 / view.max_stretch()), line);
        const Image a = drawn.to_image(), b = before.to_image();
        EXPECT_TRUE(std::equal(a.argb().begin(), a.argb().end(), b.argb().begin(), b.argb().end()));
    }
}
