// png-check: facts about screenshots for scripts/run-studio-checks, read with cairo.
//   png-check stats A.png                 size, distinct colours, share of the most common colour
//   png-check diff A.png B.png [x0 y0 x1 y1]  share of pixels that differ (in the box), and their bounding box
//   png-check pixel A.png X Y             the pixel's colour as RRGGBB
//   png-check count A.png RRGGBB [x0 y0 x1 y1]  share of pixels of exactly that colour (in the box)
// Exit status 0, or 2 with a message naming the file and the reason.
#include <cairo.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unordered_map>

namespace {

struct Png {
    cairo_surface_t* surface = nullptr;
    int width = 0;
    int height = 0;
    int stride = 0;
    const unsigned char* data = nullptr;

    explicit Png(const char* path) {
        surface = cairo_image_surface_create_from_png(path);
        if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
            std::fprintf(stderr, "png-check: cannot read '%s': %s\n", path,
                         cairo_status_to_string(cairo_surface_status(surface)));
            std::exit(2);
        }
        cairo_surface_flush(surface);
        width = cairo_image_surface_get_width(surface);
        height = cairo_image_surface_get_height(surface);
        stride = cairo_image_surface_get_stride(surface);
        data = cairo_image_surface_get_data(surface);
    }
    ~Png() { cairo_surface_destroy(surface); }
    Png(const Png&) = delete;
    Png& operator=(const Png&) = delete;
    // RGB only: screenshots are opaque.
    std::uint32_t at(int x, int y) const {
        std::uint32_t v;
        std::copy_n(data + std::size_t(y) * std::size_t(stride) + std::size_t(x) * 4, 4, reinterpret_cast<unsigned char*>(&v));
        return v & 0xFFFFFFu;
    }
};

int number(const char* s, const char* what) {
    char* end = nullptr;
    const long v = std::strtol(s, &end, 10);
    if (end == s || *end != '\0') {
        std::fprintf(stderr, "png-check: %s must be an integer (got '%s')\n", what, s);
        std::exit(2);
    }
    return int(v);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string command = argc > 1 ? argv[1] : "";
    if (command == "stats" && argc == 3) {
        const Png a(argv[2]);
        std::unordered_map<std::uint32_t, long> counts;
        for (int y = 0; y < a.height; ++y)
            for (int x = 0; x < a.width; ++x) ++counts[a.at(x, y)];
        long most = 0;
        for (const auto& [colour, n] : counts) most = std::max(most, n);
        std::printf("width %d height %d colours %zu dominant %.6f\n", a.width, a.height, counts.size(),
                    double(most) / (double(a.width) * a.height));
        return 0;
    }
    if (command == "diff" && (argc == 4 || argc == 8)) {
        const Png a(argv[2]);
        const Png b(argv[3]);
        if (a.width != b.width || a.height != b.height) {
            std::fprintf(stderr, "png-check: sizes differ (%dx%d vs %dx%d)\n", a.width, a.height, b.width, b.height);
            return 2;
        }
        int x0 = 0, y0 = 0, x1 = a.width, y1 = a.height;
        if (argc == 8) {
            x0 = std::clamp(number(argv[4], "x0"), 0, a.width);
            y0 = std::clamp(number(argv[5], "y0"), 0, a.height);
            x1 = std::clamp(number(argv[6], "x1"), x0, a.width);
            y1 = std::clamp(number(argv[7], "y1"), y0, a.height);
        }
        long differ = 0;
        int bx0 = x1, by0 = y1, bx1 = -1, by1 = -1;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                if (a.at(x, y) != b.at(x, y)) {
                    ++differ;
                    bx0 = std::min(bx0, x); by0 = std::min(by0, y);
                    bx1 = std::max(bx1, x); by1 = std::max(by1, y);
                }
        const double area = std::max(1.0, double(x1 - x0) * double(y1 - y0));
        if (differ == 0) std::printf("differ 0.000000 box none\n");
        else std::printf("differ %.6f box %d %d %d %d\n", double(differ) / area, bx0, by0, bx1, by1);
        return 0;
    }
    if (command == "pixel" && argc == 5) {
        const Png a(argv[2]);
        const int x = number(argv[3], "X");
        const int y = number(argv[4], "Y");
        if (x < 0 || y < 0 || x >= a.width || y >= a.height) {
            std::fprintf(stderr, "png-check: pixel (%d, %d) is outside the %dx%d image\n", x, y, a.width, a.height);
            return 2;
        }
        std::printf("%06X\n", unsigned(a.at(x, y)));
        return 0;
    }
    if (command == "count" && (argc == 4 || argc == 8)) {
        const Png a(argv[2]);
        char* end = nullptr;
        const unsigned long colour = std::strtoul(argv[3], &end, 16);
        if (std::string(argv[3]).size() != 6 || *end != '\0') {
            std::fprintf(stderr, "png-check: colour must be RRGGBB in hexadecimal (got '%s')\n", argv[3]);
            return 2;
        }
        int x0 = 0, y0 = 0, x1 = a.width, y1 = a.height;
        if (argc == 8) {
            x0 = std::clamp(number(argv[4], "x0"), 0, a.width);
            y0 = std::clamp(number(argv[5], "y0"), 0, a.height);
            x1 = std::clamp(number(argv[6], "x1"), x0, a.width);
            y1 = std::clamp(number(argv[7], "y1"), y0, a.height);
        }
        long n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) n += a.at(x, y) == colour ? 1 : 0;
        std::printf("share %.6f pixels %ld\n", double(n) / std::max(1.0, double(x1 - x0) * double(y1 - y0)), n);
        return 0;
    }
    std::fprintf(stderr, "usage: png-check stats A.png | diff A.png B.png [x0 y0 x1 y1] | pixel A.png X Y | "
                         "count A.png RRGGBB [x0 y0 x1 y1]\n");
    return 2;
}
