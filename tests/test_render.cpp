// render: pictures are checked by reading pixels back against the geometry that made them.
#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/render.hpp>
#include <grape/sprite.hpp>

#include "error_text.hpp"
#include "polyline_distance.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using grape::Canvas;
using grape::Color;
using grape::Image;
using grape::Vec2;

std::filesystem::path temp_dir() {
    auto dir = std::filesystem::temp_directory_path() /
               ("grape_test_render_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(dir);
    return dir;
}

std::string read_file(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Ink of a black-on-white pixel: 0 for white, 1 for black (its coverage by black paint).
double ink(const Image& image, int x, int y) {
    const Color c = image.pixel(x, y);
    return 1.0 - (c.r + c.g + c.b) / 3.0;
}

// A small XML well-formedness check: balanced, properly nested tags; quoted attributes;
// known entity forms; comments, processing instructions, CDATA and a DOCTYPE.
bool well_formed_xml(const std::string& s, std::string& why) {
    std::vector<std::string> stack;
    std::size_t i = 0;
    bool root_seen = false;
    const auto name_char = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == ':' || c == '_' || c == '-' || c == '.';
    };
    while (i < s.size()) {
        if (s[i] == '<') {
            if (s.compare(i, 4, "<!--") == 0) {
                const auto e = s.find("-->", i + 4);
                if (e == std::string::npos) return why = "unterminated comment", false;
                i = e + 3;
            } else if (s.compare(i, 9, "<![CDATA[") == 0) {
                const auto e = s.find("]]>", i);
                if (e == std::string::npos) return why = "unterminated CDATA", false;
                i = e + 3;
            } else if (s.compare(i, 2, "<?") == 0) {
                const auto e = s.find("?>", i);
                if (e == std::string::npos) return why = "unterminated processing instruction", false;
                i = e + 2;
            } else if (s.compare(i, 2, "<!") == 0) {
                const auto e = s.find('>', i);
                if (e == std::string::npos) return why = "unterminated declaration", false;
                i = e + 1;
            } else if (s.compare(i, 2, "</") == 0) {
                std::size_t j = i + 2;
                while (j < s.size() && name_char(s[j])) ++j;
                const std::string name = s.substr(i + 2, j - i - 2);
                while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
                if (j >= s.size() || s[j] != '>') return why = "bad end tag " + name, false;
                if (stack.empty() || stack.back() != name) return why = "mismatched </" + name + ">", false;
                stack.pop_back();
                i = j + 1;
            } else {
                std::size_t j = i + 1;
                while (j < s.size() && name_char(s[j])) ++j;
                const std::string name = s.substr(i + 1, j - i - 1);
                if (name.empty()) return why = "empty tag name at " + std::to_string(i), false;
                if (stack.empty() && root_seen) return why = "second root element " + name, false;
                for (;;) {
                    while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
                    if (j >= s.size()) return why = "unterminated tag " + name, false;
                    if (s[j] == '>') {
                        stack.push_back(name);
                        root_seen = true;
                        break;
                    }
                    if (s.compare(j, 2, "/>") == 0) {
                        root_seen = true;
                        ++j;
                        break;
                    }
                    const std::size_t a = j;
                    while (j < s.size() && name_char(s[j])) ++j;
                    if (j == a) return why = "bad attribute in " + name, false;
                    while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
                    if (j >= s.size() || s[j] != '=') return why = "attribute without value in " + name, false;
                    ++j;
                    while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
                    if (j >= s.size() || (s[j] != '"' && s[j] != '\'')) return why = "unquoted attribute in " + name, false;
                    const auto e = s.find(s[j], j + 1);
                    if (e == std::string::npos) return why = "unterminated attribute in " + name, false;
                    if (s.substr(j + 1, e - j - 1).find('<') != std::string::npos)
                        return why = "'<' in attribute of " + name, false;
                    j = e + 1;
                }
                i = j + 1;
            }
        } else if (s[i] == '&') {
            const auto e = s.find(';', i);
            if (e == std::string::npos || e - i > 10) return why = "bad entity at " + std::to_string(i), false;
            const std::string ent = s.substr(i + 1, e - i - 1);
            if (ent != "amp" && ent != "lt" && ent != "gt" && ent != "quot" && ent != "apos" && ent.rfind('#', 0) != 0)
                return why = "unknown entity &" + ent + ";", false;
            i = e + 1;
        } else {
            if (stack.empty() && !std::isspace(static_cast<unsigned char>(s[i])))
                return why = "text outside the root element", false;
            ++i;
        }
    }
    if (!stack.empty()) return why = "unclosed <" + stack.back() + ">", false;
    if (!root_seen) return why = "no root element", false;
    return true;
}

using grape::testing::expect_error;

// ------------------------------------------------------------------------------- geometry

TEST(Affine, ComposeAppliesRightFirst) {
    const grape::Affine a = grape::Affine::translation({3, -2}) * grape::Affine::rotation(0.7);
    const grape::Affine b = grape::Affine::scaling(2, -0.5);
    std::mt19937 rng(static_cast<std::uint32_t>(grape::testing::test_seed(7)));
    std::uniform_real_distribution<double> d(-100, 100);
    for (int i = 0; i < 100; ++i) {
        const Vec2 p{d(rng), d(rng)};
        const Vec2 direct = a.apply(b.apply(p));
        const Vec2 composed = (a * b).apply(p);
        // A handful of roundings of numbers up to ~300: 1e-12 is hundreds of ulps of slack.
        EXPECT_NEAR(direct.x, composed.x, 1e-12);
        EXPECT_NEAR(direct.y, composed.y, 1e-12);
    }
}

TEST(Affine, MaxStretchIsLargestSingularValue) {
    // Rotation·diag(3, 0.5)·rotation: singular values 3 and 0.5 exactly.
    const grape::Affine m = grape::Affine::rotation(0.3) * grape::Affine::scaling(3, 0.5) * grape::Affine::rotation(-1.1);
    EXPECT_NEAR(m.max_stretch(), 3.0, 1e-14);  // a few ulps of 3
    EXPECT_NEAR(grape::Affine::rotation(2.0).max_stretch(), 1.0, 1e-15);
}

TEST(Fit, MapsBoundsIntoViewportKeepingAspect) {
    grape::Bounds b;
    b.add(Vec2{-200, -400});
    b.add(Vec2{200, 0});
    const grape::Affine t = grape::fit(b, {10, 20, 300, 500}, 25);
    // 400 wide, 400 tall into 250 × 450: scale 250/400 limited by width, centered vertically.
    const Vec2 lo = t.apply(b.min);
    const Vec2 hi = t.apply(b.max);
    EXPECT_NEAR(lo.x, 35.0, 1e-12);
    EXPECT_NEAR(hi.x, 285.0, 1e-12);
    EXPECT_NEAR(hi.y - lo.y, 250.0, 1e-12);
    EXPECT_NEAR(0.5 * (lo.y + hi.y), 270.0, 1e-12);
    // A single point maps to the center without NaN.
    grape::Bounds point;
    point.add(Vec2{5, 5});
    const Vec2 c = grape::fit(point, {0, 0, 100, 60}).apply({5, 5});
    EXPECT_EQ(c, (Vec2{50, 30}));
}

// ---------------------------------------------------------------------------------- image

TEST(Image, PixelRoundTripAndBounds) {
    Image image(3, 2, grape::colors::white);
    image.set_pixel(2, 1, {1.0, 0.0, 0.0, 1.0});
    EXPECT_EQ(image.pixel(2, 1), (Color{1, 0, 0, 1}));
    EXPECT_EQ(image.pixel(0, 0), (Color{1, 1, 1, 1}));
    EXPECT_EQ(image.pixel(-1, 0), grape::colors::transparent);
    EXPECT_EQ(image.pixel(3, 0), grape::colors::transparent);
    image.set_pixel(7, 7, grape::colors::black);  // ignored, no crash
    // Half-transparent colours come back within one 8-bit step of premultiplication (1/127).
    image.set_pixel(1, 1, {0.2, 0.4, 0.6, 0.5});
    const Color c = image.pixel(1, 1);
    EXPECT_NEAR(c.r, 0.2, 1.0 / 127);
    EXPECT_NEAR(c.g, 0.4, 1.0 / 127);
    EXPECT_NEAR(c.b, 0.6, 1.0 / 127);
    EXPECT_NEAR(c.a, 0.5, 1.0 / 255);
}

TEST(Image, PngRoundTripIsExact) {
    Image image(5, 4, grape::colors::transparent);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) image.set_pixel(x, y, {x / 4.0, y / 3.0, 0.5, 1.0});
    const auto file = temp_dir() / "round.png";
    image.write_png(file);
    const Image back = Image::load_png(file);
    ASSERT_EQ(back.width(), 5);
    ASSERT_EQ(back.height(), 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) EXPECT_EQ(back.pixel(x, y), image.pixel(x, y));
}

TEST(Image, BadArgumentsAreNamed) {
    expect_error([] { Image(0, 4); }, {"Image", "width", "got 0"});
    expect_error([] { Image(4, 40000); }, {"Image", "height", "40000"});
    expect_error([] { (void)Image::load_png("/nonexistent/none.png"); }, {"/nonexistent/none.png", "no such file"});
    const auto junk = temp_dir() / "junk.png";
    std::ofstream(junk) << "not a png";
    expect_error([&] { (void)Image::load_png(junk); }, {"junk.png", "not a readable PNG"});
}

// --------------------------------------------------------------------------------- canvas

TEST(Canvas, BadArgumentsAreNamed) {
    expect_error([] { Canvas(0, 10); }, {"Canvas", "width", "got 0"});
    expect_error([] { Canvas(10, std::nan("")); }, {"Canvas", "height", "nan"});
    Canvas canvas(10, 10);
    expect_error([&] { canvas.write(temp_dir() / "picture.bmp"); }, {"picture.bmp", "unknown format", ".png, .svg or .pdf"});
    expect_error([&] { canvas.write("/nonexistent/folder/picture.png"); }, {"/nonexistent/folder/picture.png", "does not exist"});
}

TEST(Canvas, BackgroundFillsEveryPixel) {
    const Image image = Canvas(7.5, 3, {0.0, 0.5, 1.0, 1.0}).to_image();
    EXPECT_EQ(image.width(), 8);  // rounded up
    EXPECT_EQ(image.height(), 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 7; ++x) {
            EXPECT_NEAR(image.pixel(x, y).g, 0.5, 1.0 / 255);
            EXPECT_EQ(image.pixel(x, y).b, 1.0);
        }
}

// A 1-unit stroke covers points within ½ of the circle; a pixel that is more than half
// covered has its center within ½ + ½ (its half-diagonal is 0.71 < 1) of the circle.
TEST(Canvas, StrokedCircleLiesWithinAPixel) {
    const Vec2 c{100.3, 99.6};
    const double r = 61.7;
    Canvas canvas(200, 200);
    canvas.stroke_circle(c, r, {.width = 1.0});
    const Image image = canvas.to_image();
    int dark = 0;
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 200; ++x) {
            if (ink(image, x, y) < 0.5) continue;
            ++dark;
            const double d = grape::distance({x + 0.5, y + 0.5}, c);
            EXPECT_LE(std::abs(d - r), 1.0) << x << "," << y;
        }
    // Completeness: every point of the circle has ink within a pixel (the ring is unbroken).
    for (int k = 0; k < 720; ++k) {
        const double a = 2.0 * grape::pi * k / 720.0;
        const Vec2 p = c + Vec2{std::cos(a), std::sin(a)} * r;
        double best = 0.0;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                best = std::max(best, ink(image, static_cast<int>(p.x) + dx, static_cast<int>(p.y) + dy));
        EXPECT_GT(best, 0.3) << "gap at angle " << a;
    }
    // The ring is about 2πr pixels long and 1 wide.
    EXPECT_GT(dark, 0.5 * 2 * grape::pi * r);
    EXPECT_LT(dark, 2.0 * 2 * grape::pi * r);
}

// Anti-aliased coverage sums to the area; cairo's 8-bit coverage rounding (±1/510 per edge
// pixel over ~2πr edge pixels) stays far below 1 %, the bound checked here.
TEST(Canvas, FilledShapesHaveTheirArea) {
    {
        Canvas canvas(200, 200);
        canvas.fill_circle({97.2, 103.9}, 70.0, {});
        const Image image = canvas.to_image();
        double area = 0.0;
        for (int y = 0; y < 200; ++y)
            for (int x = 0; x < 200; ++x) area += ink(image, x, y);
        EXPECT_NEAR(area, grape::pi * 70.0 * 70.0, 0.01 * grape::pi * 70.0 * 70.0);
    }
    {
        // A transformed triangle: world area × |det|.
        Canvas canvas(300, 300);
        canvas.set_transform(grape::Affine::translation({150, 150}) * grape::Affine::rotation(0.4) *
                             grape::Affine::scaling(2.0, 1.5));
        const Vec2 tri[] = {{-50, -40}, {60, -10}, {-5, 55}};
        canvas.fill_polygon(tri, {});
        const Image image = canvas.to_image();
        double area = 0.0;
        for (int y = 0; y < 300; ++y)
            for (int x = 0; x < 300; ++x) area += ink(image, x, y);
        const double exact = 0.5 * std::abs(grape::cross(tri[1] - tri[0], tri[2] - tri[0])) * 3.0;
        EXPECT_NEAR(area, exact, 0.01 * exact);
    }
}

TEST(Canvas, BlittedFrameLandsInPlace) {
    // A 4-frame tile sheet, 8×6 pixels per frame, each frame one colour with a marked corner.
    Image sheet(32, 6);
    const Color frame_colors[4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 0, 1}};
    for (int f = 0; f < 4; ++f)
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 8; ++x) sheet.set_pixel(8 * f + x, y, frame_colors[f]);
    sheet.set_pixel(8 * 2, 0, grape::colors::black);  // frame 2's top-left pixel
    Canvas canvas(100, 80);
    // Frame 2 at (37, 21), doubled.
    canvas.draw_image(sheet, {16, 0, 8, 6}, {37, 21, 16, 12});
    const Image image = canvas.to_image();
    for (int y = 15; y < 40; ++y)
        for (int x = 30; x < 60; ++x) {
            const bool inside = x >= 37 && x < 53 && y >= 21 && y < 33;
            const bool corner = x >= 37 && x < 39 && y >= 21 && y < 23;
            const Color expected = !inside ? grape::colors::white : corner ? grape::colors::black : frame_colors[2];
            EXPECT_EQ(image.pixel(x, y), expected) << x << "," << y;
        }
    // The whole-image overload puts pixel (0, 0) at the given point, one pixel per unit.
    Canvas plain(40, 10);
    plain.draw_image(sheet, Vec2{3, 2});
    const Image shown = plain.to_image();
    EXPECT_EQ(shown.pixel(3 + 16, 2), grape::colors::black);
    EXPECT_EQ(shown.pixel(3 + 17, 2), frame_colors[2]);
    EXPECT_EQ(shown.pixel(2, 2), grape::colors::white);
}

TEST(Canvas, StrokeWidthIgnoresTheTransform) {
    Canvas canvas(100, 100);
    canvas.set_transform(grape::Affine::scaling(10, 10));
    canvas.stroke_line({1, 5}, {9, 5}, {.width = 2.0, .cap = grape::LineCap::butt});
    const Image image = canvas.to_image();
    // The line sits at y = 50 in output units, 2 units thick: rows 49 and 50, nothing else.
    for (int y = 40; y < 60; ++y) EXPECT_NEAR(ink(image, 50, y), (y == 49 || y == 50) ? 1.0 : 0.0, 1.0 / 255) << y;
}

TEST(Canvas, TextLeavesInkNearItsAnchor) {
    Canvas canvas(200, 60);
    canvas.text({100, 40}, "grape", {.size = 20, .align = grape::TextAlign::center});
    const Image image = canvas.to_image();
    int left = 200, right = 0, ink_pixels = 0;
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 200; ++x)
            if (ink(image, x, y) > 0.5) {
                ++ink_pixels;
                left = std::min(left, x);
                right = std::max(right, x);
                EXPECT_LE(y, 46);  // the baseline is at 40; only descenders ("g", "p") go below
                EXPECT_GE(y, 15);  // 20-unit letters rise at most ~20 above the baseline
            }
    ASSERT_GT(ink_pixels, 20);
    // Centered: the ink's middle is within a few pixels of the anchor (glyph side bearings).
    EXPECT_NEAR(0.5 * (left + right), 100.0, 4.0);
}

TEST(Canvas, WritesSvgThatParsesAsXml) {
    Canvas canvas(120, 80);
    canvas.stroke_circle({60, 40}, 30, {.color = grape::colors::red, .width = 2});
    canvas.text({10, 70}, "a < b & c", {});
    Image sheet(4, 4, grape::colors::blue);
    canvas.draw_image(sheet, Vec2{1, 1});
    const auto file = temp_dir() / "picture.svg";
    canvas.write(file);
    const std::string svg = read_file(file);
    std::string why;
    EXPECT_TRUE(well_formed_xml(svg, why)) << why;
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    for (const auto& entry : std::filesystem::directory_iterator(file.parent_path()))  // no temporary left
        EXPECT_NE(entry.path().filename().string().rfind("picture.svg.partial", 0), 0u) << entry.path();
    // The checker itself rejects what it should.
    EXPECT_FALSE(well_formed_xml("<svg><g></svg></g>", why));
    EXPECT_FALSE(well_formed_xml("<svg a=b/>", why));
    EXPECT_FALSE(well_formed_xml("<svg>&bogus;</svg>", why));
    EXPECT_FALSE(well_formed_xml("<svg>", why));
}

TEST(Canvas, WritesPdfAndPngByExtension) {
    Canvas canvas(50, 40);
    canvas.fill_rect({10, 10, 20, 10}, {.color = grape::colors::green});
    const auto dir = temp_dir();
    canvas.write(dir / "picture.PDF");
    EXPECT_EQ(read_file(dir / "picture.PDF").substr(0, 5), "%PDF-");
    canvas.write(dir / "picture.png");
    const Image back = Image::load_png(dir / "picture.png");
    const Image direct = canvas.to_image();
    ASSERT_EQ(back.width(), direct.width());
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 50; ++x) ASSERT_EQ(back.pixel(x, y), direct.pixel(x, y));
    EXPECT_NEAR(back.pixel(15, 15).g, grape::colors::green.g, 1.0 / 255);
}

TEST(Canvas, PushAndPopRestoreTheTransform) {
    Canvas canvas(10, 10);
    canvas.set_transform(grape::Affine::scaling(2, 2));
    canvas.push();
    canvas.concat(grape::Affine::translation({1, 1}));
    EXPECT_EQ(canvas.transform().apply({0, 0}), (Vec2{2, 2}));
    canvas.pop();
    EXPECT_EQ(canvas.transform().apply({1, 0}), (Vec2{2, 0}));
    canvas.pop();  // unbalanced: resets instead of failing
    EXPECT_EQ(canvas.transform().apply({1, 0}), (Vec2{1, 0}));
    // Singular and non-finite transforms are refused; drawing still works afterwards.
    canvas.set_transform(grape::Affine::scaling(0, 3));
    canvas.set_transform(grape::Affine::translation({std::nan(""), 0}));
    EXPECT_EQ(canvas.transform().apply({1, 0}), (Vec2{1, 0}));
    canvas.fill_rect({0, 0, 10, 10}, {});
    EXPECT_EQ(ink(canvas.to_image(), 5, 5), 1.0);
}

TEST(Plot, DrawsSeriesInsideItsArea) {
    Canvas canvas(300, 200);
    std::vector<double> x, y;
    for (int i = 0; i <= 100; ++i) {
        x.push_back(i * 0.1);
        y.push_back(std::sin(i * 0.1));
    }
    y[50] = std::nan("");  // skipped, no crash
    const grape::StrokeStyle stroke{.color = grape::colors::red};
    const grape::PlotSeries s[] = {{x, y, stroke, "sin"}};
    grape::draw_plot(canvas, {50, 40, 200, 120}, s, "title");
    const Image image = canvas.to_image();
    int red = 0;
    for (int py = 0; py < 200; ++py)
        for (int px = 0; px < 300; ++px) {
            const Color c = image.pixel(px, py);
            if (c.r > 0.6 && c.g < 0.4) {
                ++red;
                EXPECT_TRUE(px >= 50 && px < 250 && py >= 40 && py < 160) << px << "," << py;
            }
        }
    EXPECT_GT(red, 100);
}

// ---------------------------------------------------------------------------------- paths

using grape::testing::distance_to_polyline;

// Every path kind, drawn 1 unit wide on a fitted canvas: ink lies within a pixel of the
// true shape (a 0.01-unit flattening of it, in output units), and the shape is inked all
// along (no missing piece). This is what catches a wrong Bézier, arc or spline rebuild.
void expect_drawn_faithfully(const grape::Path& path, const std::string& label) {
    Canvas canvas(240, 240);
    const grape::Affine t = grape::fit(path.bounds(), {0, 0, 240, 240}, 12);
    canvas.set_transform(t);
    canvas.stroke_path(path, {.width = 1.0});
    const Image image = canvas.to_image();
    std::vector<Vec2> truth;
    for (Vec2 p : path.flatten(0.01 / t.max_stretch())) truth.push_back(t.apply(p));
    int dark = 0;
    for (int y = 0; y < 240; ++y)
        for (int x = 0; x < 240; ++x) {
            if (ink(image, x, y) < 0.5) continue;
            ++dark;
            // ½ stroke + ½ pixel, plus the 0.01 flattening error and round caps/joins.
            ASSERT_LE(distance_to_polyline({x + 0.5, y + 0.5}, truth), 1.0 + 0.01) << label << " at " << x << "," << y;
        }
    EXPECT_GT(dark, 50) << label;
    for (int k = 0; k <= 400; ++k) {
        const Vec2 p = t.apply(path.point(k / 400.0));
        double best = 0.0;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                best = std::max(best, ink(image, static_cast<int>(std::floor(p.x)) + dx, static_cast<int>(std::floor(p.y)) + dy));
        EXPECT_GT(best, 0.3) << label << ": nothing drawn near u = " << k / 400.0;
    }
}

TEST(DrawPath, EveryKindIsDrawnWhereItIs) {
    using namespace grape;
    const std::vector<std::pair<std::string, Path>> paths = {
        {"linear", LinearPath({0, 0}, {100, 40})},
        {"circle ccw multi-turn", CirclePath({0, 0}, 50, 2.0 * pi, -1.5)},
        {"circle cw", CirclePath({10, 5}, 30, 0.3, 2.0)},
        {"ellipse", EllipticalArcPath({0, 0}, 80, 30, 0.6, 0.2, 4.0)},
        {"spiral", SpiralPath({100, 100}, 200, 0)},
        {"sine", SineWavePath({350, 200}, {200, 200}, 3, 50)},
        {"quadratic", QuadraticBezierPath({0, 0}, {50, 120}, {100, 0})},
        {"cubic", CubicBezierPath({20, 20}, {400, 200}, {400, 600}, {600, 600})},
        {"cubic reparametrized", CubicBezierPath({20, 20}, {400, 200}, {400, 600}, {600, 600}, true)},
        {"linear spline", LinearSplinePath({20, 20, 100, 100, 120, 50, 300, 300, 400, 50, 500, 200})},
        {"cosine spline", CosineSplinePath({20, 120, 100, 200, 120, 150, 300, 400, 400, 150, 500, 300})},
        {"catmull-rom", CatmullRomSplinePath({20, 220, 100, 300, 120, 250, 300, 500, 400, 250, 500, 400})},
        {"catmull-rom centripetal",
         CatmullRomSplinePath({20, 220, 100, 300, 120, 250, 300, 500, 400, 250, 500, 400}, CatmullRom::centripetal)},
        {"physics", PhysicsPath({0, 0}, {100, -200}, {0, 400}, 1.0)},
        {"svg", parse_svg_path("M10 10 C 20 80 90 80 100 10 S 150 -40 190 30 Q 220 90 250 30 A 40 20 30 1 0 300 60 Z")},
    };
    for (const auto& [label, path] : paths) expect_drawn_faithfully(path, label);
    const Vec2 h_points[] = {{0, 0}, {100, 50}, {200, 0}};
    const Vec2 h_tangents[] = {{100, 200}, {100, -100}, {0, -300}};
    expect_drawn_faithfully(HermiteSplinePath(h_points, h_tangents), "hermite");
}

TEST(DrawPath, NestedComplexPathAndItsCues) {
    using namespace grape;
    // The seed's "ComplexPath2D 2": three circles nested in a complex with a Bézier and a sine.
    const ComplexPath circles({CirclePath({150, 200}, 50, 2 * pi, 0), CirclePath({250, 200}, 50, pi, 3 * pi),
                               CirclePath({300, 200}, 100, pi, 3 * pi)},
                              {0, 0.25, 0.5});
    const ComplexPath path({circles, CubicBezierPath({200, 200}, {350, 0}, {350, 500}, {350, 200}),
                            SineWavePath({350, 200}, {200, 200}, 3, 50)},
                           {0, 0.5, 0.75});
    expect_drawn_faithfully(path, "nested complex");
    // Cue markers: orange discs where each part (nested ones too) begins.
    Canvas canvas(240, 240);
    const Affine t = fit(path.bounds(), {0, 0, 240, 240}, 12);
    canvas.set_transform(t);
    draw_path(canvas, path, {.stroke = {.color = colors::light_grey}, .cues = true, .ends = false});
    const Image image = canvas.to_image();
    for (double u : {0.0, 0.125, 0.25, 0.5, 0.75}) {
        const Vec2 p = t.apply(path.point(u));
        const Color c = image.pixel(static_cast<int>(p.x), static_cast<int>(p.y));
        EXPECT_NEAR(c.r, colors::orange.r, 0.05) << "cue at u = " << u;
        EXPECT_NEAR(c.g, colors::orange.g, 0.05) << "cue at u = " << u;
    }
}

TEST(DrawPath, TicksCrossThePathEveryDeltaU) {
    using namespace grape;
    const LinearPath line({10, 50}, {190, 50});
    Canvas canvas(200, 100);
    draw_path(canvas, line, {.stroke = {.color = colors::white}, .ticks = 0.25, .tick_length = 20, .tick_color = colors::black, .ends = false});
    const Image image = canvas.to_image();
    // Ticks at x = 10, 55, 100, 145, 190 reach 10 units above and below the line.
    int columns = 0;
    for (int x = 0; x < 200; ++x)
        if (ink(image, x, 42) > 0.4) ++columns;
    EXPECT_GE(columns, 5);
    EXPECT_LE(columns, 10);  // five 1-unit ticks cover at most two pixel columns each
    for (double x : {10.0, 55.0, 100.0, 145.0, 190.0}) {
        const double covered = ink(image, static_cast<int>(x) - 1, 42) + ink(image, static_cast<int>(x), 42);
        EXPECT_NEAR(covered, 1.0, 0.1) << x;
    }
}

TEST(DrawPath, FilledPathHasItsArea) {
    using namespace grape;
    // A closed circle path of radius 60 filled: π·60² within 1 %.
    Canvas canvas(200, 200);
    canvas.fill_path(CirclePath({100, 100}, 60, 0.5, 0.5 + 2 * pi), {});
    const Image image = canvas.to_image();
    double area = 0.0;
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 200; ++x) area += ink(image, x, y);
    EXPECT_NEAR(area, pi * 3600, 0.01 * pi * 3600);
    // The area under a quadratic Bézier arch closed by its chord: (2/3)·base·(height/2)... by
    // Green's theorem, ∮ x dy over the curve and chord = 2/3 · 200 · 60 for control height 120.
    Canvas arch(240, 120);
    arch.fill_path(QuadraticBezierPath({20, 100}, {120, -20}, {220, 100}), {});
    const Image a = arch.to_image();
    double inked = 0.0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 240; ++x) inked += ink(a, x, y);
    const double exact = 2.0 / 3.0 * 200.0 * 60.0;
    EXPECT_NEAR(inked, exact, 0.01 * exact);
}

TEST(DebugDraw, ImplicitCurveTracesItsZeroSet) {
    Canvas canvas(200, 200);
    const Vec2 c{100, 100};
    grape::Bounds region;
    region.add(Vec2{0, 0});
    region.add(Vec2{200, 200});
    grape::draw_implicit_curve(canvas, [&](Vec2 p) { return grape::length_squared(p - c) - 70.0 * 70.0; }, region,
                               {.width = 1.0}, 100);
    const Image image = canvas.to_image();
    int dark = 0;
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 200; ++x)
            if (ink(image, x, y) >= 0.5) {
                ++dark;
                // Chords of 2-unit cells sag at most h²/(8r) = 0.007 inside the circle.
                EXPECT_LE(std::abs(grape::distance({x + 0.5, y + 0.5}, c) - 70.0), 1.0 + 0.01);
            }
    EXPECT_GT(dark, 300);
}

TEST(DebugDraw, SpriteFrameIsBlittedFromItsRectangle) {
    const grape::TileSheet sheet({.width = 40, .height = 20, .columns = 4, .rows = 2});
    Image image(40, 20);
    for (int f = 0; f < 8; ++f)
        for (int y = 0; y < 10; ++y)
            for (int x = 0; x < 10; ++x)
                image.set_pixel((f % 4) * 10 + x, (f / 4) * 10 + y, {f / 8.0, 1.0 - f / 8.0, 0.5, 1.0});
    grape::TileSheetSprite sprite(sheet);
    sprite.show_frame(6);
    Canvas canvas(100, 100);
    grape::draw_sprite(canvas, image, sprite, {30, 40}, 3.0);
    const Image out = canvas.to_image();
    for (int y = 35; y < 75; ++y)
        for (int x = 25; x < 65; ++x) {
            const bool inside = x >= 30 && x < 60 && y >= 40 && y < 70;
            const Color expected = inside ? image.pixel(25, 15) : grape::colors::white;  // (25, 15) is in frame 6
            EXPECT_EQ(out.pixel(x, y), expected) << x << "," << y;
        }
}

TEST(DebugDraw, ParticlesAreDiscsAtTheirPositions) {
    Canvas canvas(100, 100);
    const Vec2 positions[] = {{20, 20}, {70, 60}};
    const double inverse_masses[] = {1.0, 0.0};
    grape::draw_particles(canvas, positions, {}, inverse_masses, {.color = grape::colors::red, .radius = 4});
    const Image image = canvas.to_image();
    EXPECT_NEAR(image.pixel(20, 20).r, grape::colors::red.r, 0.01);
    EXPECT_NEAR(image.pixel(20, 20).g, grape::colors::red.g, 0.01);
    EXPECT_EQ(image.pixel(70, 60), grape::colors::black);  // pinned
    EXPECT_EQ(image.pixel(45, 40), grape::colors::white);
}

// The animated SVG is well-formed XML with one circle per mover, whose discrete cx/cy values
// are the mover's positions mapped by the transform, frame by frame.
TEST(AnimatedSvg, MoversStepThroughTheirMappedPositions) {
    const grape::LinearPath line({0, 0}, {10, 5});
    const grape::Path paths[] = {line, grape::CirclePath({5, 5}, 3, 0, 2 * grape::pi)};
    const Color path_colors[] = {grape::colors::red};
    grape::SvgMover mover{.color = grape::colors::green, .label = "a <b> & \"c\""};
    for (int k = 0; k < 5; ++k) mover.positions.push_back(line.point(k / 4.0));
    grape::SvgMover stuck{.positions = {Vec2{std::nan(""), 1.0}}};
    const grape::SvgMover movers[] = {mover, stuck};
    const grape::Affine t = grape::Affine::translation({20, 10}) * grape::Affine::scaling(10, 10);
    const std::string svg = grape::animated_svg(200, 100, t, paths, path_colors, movers, 2.5, "title & more");
    std::string why;
    ASSERT_TRUE(well_formed_xml(svg, why)) << why;
    EXPECT_NE(svg.find("dur=\"2.5s\""), std::string::npos);
    EXPECT_NE(svg.find("values=\"20.00;45.00;70.00;95.00;120.00\""), std::string::npos) << svg;  // x = 20 + 10·(0 … 10)
    EXPECT_NE(svg.find("values=\"10.00;22.50;35.00;47.50;60.00\""), std::string::npos) << svg;  // y = 10 + 10·(0 … 5)
    EXPECT_EQ(svg.find("nan"), std::string::npos);  // a non-finite position is never written
    std::size_t circles = 0;
    for (auto at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
    EXPECT_EQ(circles, 2u);
    std::size_t drawn = 0;
    for (auto at = svg.find("<path"); at != std::string::npos; at = svg.find("<path", at + 1)) ++drawn;
    EXPECT_EQ(drawn, 2u);
}

TEST(Canvas, ClipLimitsDrawingUntilPop) {
    Canvas canvas(60, 60);
    canvas.push();
    canvas.clip({10, 20, 30, 15});
    canvas.fill_rect({0, 0, 60, 60}, {});
    canvas.pop();
    canvas.fill_rect({50, 50, 10, 10}, {});  // after pop: unclipped again
    const Image image = canvas.to_image();
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 60; ++x) {
            const bool inside = (x >= 10 && x < 40 && y >= 20 && y < 35) || (x >= 50 && y >= 50);
            EXPECT_EQ(ink(image, x, y), inside ? 1.0 : 0.0) << x << "," << y;
        }
}

TEST(DrawPath, TangentArrowsPointAlongTheDerivative) {
    // A straight line from (20, 50) to (180, 50): two arrows (u = 0 and 1) of 30 units to the right.
    Canvas canvas(240, 100);
    grape::draw_path(canvas, grape::LinearPath({20, 50}, {180, 50}),
                     {.stroke = {.color = grape::colors::white}, .tangents = 2, .tangent_length = 30,
                      .tangent_color = grape::colors::black, .ends = false});
    const Image image = canvas.to_image();
    EXPECT_GT(ink(image, 35, 50), 0.5);   // along the first arrow
    EXPECT_GT(ink(image, 205, 50), 0.5);  // along the second, past the end of the path
    EXPECT_LT(ink(image, 15, 50), 0.1);   // nothing behind the start
    EXPECT_LT(ink(image, 215, 50), 0.1);  // nor past the second tip (180 + 30 + 1.5 width)
}

// Non-finite input to any primitive is skipped, and the canvas keeps drawing afterwards
// (cairo would otherwise enter an error state and silently drop everything that follows).
TEST(Canvas, NonFiniteInputIsSkipped) {
    const double nan = std::nan("");
    Canvas canvas(40, 40);
    canvas.stroke_line({nan, 0}, {10, 10}, {});
    canvas.fill_polygon(std::vector<Vec2>{{0, 0}, {nan, 5}, {5, 0}}, {});
    canvas.stroke_circle({5, 5}, nan, {});
    canvas.fill_circle({nan, 5}, 3, {});
    canvas.dot({5, nan}, 3, grape::colors::black);
    canvas.stroke_rect({nan, 0, 5, 5}, {});
    canvas.fill_rect({0, 0, nan, 5}, {});
    canvas.clip({0, 0, nan, 1});
    canvas.text({nan, 3}, "x", {});
    canvas.draw_image(Image(2, 2, grape::colors::black), {0, 0, 2, 2}, {0, 0, nan, 4});
    canvas.stroke_line({0, 0}, {10, 10}, {.width = nan});  // falls back to width 1
    canvas.fill_rect({20, 20, 10, 10}, {});
    const Image image = canvas.to_image();
    EXPECT_EQ(ink(image, 25, 25), 1.0);
    EXPECT_GT(ink(image, 5, 5), 0.3);  // the fallback-width line
    EXPECT_EQ(ink(image, 35, 5), 0.0);
}

}  // namespace
