// SVG path data drawn by draw_path against rsvg-convert (librsvg, the SVG renderer of GNOME):
// closed subpaths, miter limits, zero-length dots, arcs and curves must cover the same pixels
// up to antialiasing, i.e. agree after a 1 px dilation.
#include <grape/path.hpp>
#include <grape/render.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using grape::Vec2;

struct Case {
    const char* data;
    const char* cap;   // SVG stroke-linecap
    const char* join;  // SVG stroke-linejoin
};

// Every case is drawn in a 20 × 20 world scaled 8× into a 160 × 160 image.
constexpr int size = 160;
constexpr double scale = 8.0;
constexpr double width = 12.0;  // stroke width in pixels

bool have_rsvg() { return std::system("rsvg-convert --version > /dev/null 2>&1") == 0; }

grape::LineCap cap_of(const std::string& cap) {
    return cap == "butt" ? grape::LineCap::butt : cap == "round" ? grape::LineCap::round : grape::LineCap::square;
}

grape::LineJoin join_of(const std::string& join) {
    return join == "miter" ? grape::LineJoin::miter : join == "round" ? grape::LineJoin::round : grape::LineJoin::bevel;
}

// Dark pixels (ink) of an image on white.
std::vector<bool> ink(const grape::Image& image) {
    std::vector<bool> out(static_cast<std::size_t>(image.width() * image.height()));
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const grape::Color c = image.pixel(x, y);
            // Composited over white: dark when the grey level is below one half.
            const double grey = (c.r + c.g + c.b) / 3.0 * c.a + (1.0 - c.a);
            out[static_cast<std::size_t>(y * image.width() + x)] = grey < 0.5;
        }
    return out;
}

// Pixels inked in `a` with no inked pixel of `b` within one pixel (8-neighbourhood).
int uncovered(const std::vector<bool>& a, const std::vector<bool>& b) {
    int count = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            if (!a[static_cast<std::size_t>(y * size + x)]) continue;
            bool near = false;
            for (int dy = -1; dy <= 1 && !near; ++dy)
                for (int dx = -1; dx <= 1 && !near; ++dx) {
                    const int u = x + dx, v = y + dy;
                    near = u >= 0 && v >= 0 && u < size && v < size && b[static_cast<std::size_t>(v * size + u)];
                }
            if (!near) ++count;
        }
    return count;
}

TEST(SvgRender, DrawPathMatchesRsvgAfterADilationOf1px) {
    if (!have_rsvg()) GTEST_SKIP() << "rsvg-convert not installed (Debian package librsvg2-bin, scripts/install-deps)";
    const Case cases[] = {
        {"m15 12h4v4h-4z", "butt", "miter"},             // Z joins at (15, 12): no caps there
        {"m 8,14 4,-4.9 -4,2 -4,-2 z", "butt", "miter"},  // sharp corners beyond SVG's limit 4: bevels
        {"M2 2 h6 v6 z M10 10 h6 l-3 5", "butt", "miter"},  // a closed and an open subpath
        {"M 5 5 L 5 5 M 12 5 z", "round", "round"},      // zero-length subpaths: round dots
        {"M 3 10 A 5 5 0 1 1 13 10 A 5 5 0 0 1 3 10 z", "butt", "miter"},
        {"M2 8 A 6 3 30 0 1 16 10", "round", "round"},
        {"M2 16 C 2 2 10 2 10 10 S 18 18 18 4", "square", "bevel"},
        {"M2 10 Q 6 2 10 10 T 18 10", "butt", "round"},
        {"M 13,9 3,19 h 3 v -3 l 1,-1 v -8 z", "butt", "miter"},
    };
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("grape-svg-render-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    for (const Case& c : cases) {
        SCOPED_TRACE(c.data);
        const std::filesystem::path svg = dir / "case.svg", png = dir / "case.png";
        {
            std::ofstream out(svg);
            out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size << "\" height=\"" << size << "\">"
                << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>"
                << "<g transform=\"scale(" << scale << ")\"><path d=\"" << c.data << "\" fill=\"none\" stroke=\"black\""
                << " stroke-width=\"" << width / scale << "\" stroke-linecap=\"" << c.cap << "\" stroke-linejoin=\""
                << c.join << "\"/></g></svg>";
        }
        const std::string command = "rsvg-convert -o '" + png.string() + "' '" + svg.string() + "'";
        ASSERT_EQ(std::system(command.c_str()), 0);
        const grape::Image reference = grape::Image::load_png(png);
        ASSERT_EQ(reference.width(), size);
        ASSERT_EQ(reference.height(), size);

        grape::Canvas canvas(size, size, grape::colors::white);
        canvas.set_transform(grape::Affine::scaling(scale, scale));
        grape::draw_path(canvas, grape::parse_svg_path(c.data),
                         {.stroke = {.color = grape::colors::black, .width = width, .cap = cap_of(c.cap), .join = join_of(c.join)},
                          .cues = false,
                          .ends = false});
        const std::vector<bool> ours = ink(canvas.to_image());
        const std::vector<bool> theirs = ink(reference);
        int inked = 0;
        for (bool b : theirs) inked += b;
        EXPECT_GT(inked, 50);  // the case draws something
        EXPECT_EQ(uncovered(ours, theirs), 0);
        EXPECT_EQ(uncovered(theirs, ours), 0);
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
