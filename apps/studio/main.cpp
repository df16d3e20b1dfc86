// grape-studio: the seed's interactive demos in a window.
//   grape-studio [--tab NAME]
//   grape-studio --screenshot OUT.png --tab NAME --frames N [--script FILE] [--report FILE]
#include "app.hpp"

#include <grape/error.hpp>

#include <charconv>
#include <cstdio>
#include <iostream>
#include <string>
#include <string_view>

namespace {

void usage(std::FILE* to) {
    std::string tabs;
    for (const auto& name : grape::studio::tab_names()) tabs += (tabs.empty() ? "" : "|") + name;
    std::fprintf(to,
                 "usage: grape-studio [options]\n"
                 "  --tab %s   tab shown at start (default paths)\n"
                 "  --frames N          run N frames (fixed 1/60 s steps), then exit\n"
                 "  --screenshot FILE   after the last frame, save the window as PNG (needs --frames)\n"
                 "  --script FILE       feed timed mouse/key events from FILE (see tests/studio/*.script)\n"
                 "  --report FILE       write the visible tab's state at exit (key: value lines)\n"
                 "  --path NAME         paths tab: the path selected at start (e.g. seed_bezier)\n"
                 "  --particles N       chain tab: number of particles (2..2000)\n"
                 "  --sheet FILE        sprites tab: the sheet JSON opened at start (default: grape's own)\n"
                 "  --size WxH          window size in pixels (default 1200x760)\n"
                 "  --fps               no frame cap; print frames per second at exit\n"
                 "  --help              this text\n",
                 tabs.c_str());
}

int integer_option(std::string_view name, std::string_view value, int lo, int hi) {
    int v = 0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
    if (ec != std::errc{} || end != value.data() + value.size() || v < lo || v > hi)
        throw grape::Error(std::string(name) + ": must be an integer in [" + std::to_string(lo) + ", " +
                           std::to_string(hi) + "] (got '" + std::string(value) + "')");
    return v;
}

grape::studio::Options parse(int argc, char** argv) {
    grape::studio::Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--help" || arg == "-h") {
            usage(stdout);
            std::exit(0);
        }
        if (arg == "--fps") {
            o.fps = true;
            continue;
        }
        if (i + 1 >= argc) throw grape::Error(std::string(arg) + ": missing value (or unknown option; see --help)");
        const std::string_view value = argv[++i];
        if (arg == "--tab") o.tab = value;
        else if (arg == "--frames") o.frames = integer_option(arg, value, 1, 100000000);
        else if (arg == "--screenshot") o.screenshot = value;
        else if (arg == "--script") o.script = value;
        else if (arg == "--report") o.report = value;
        else if (arg == "--path") o.path = value;
        else if (arg == "--sheet") o.sheet = value;
        else if (arg == "--particles") o.particles = integer_option(arg, value, 2, 2000);
        else if (arg == "--size") {
            const std::size_t x = value.find('x');
            if (x == std::string_view::npos) throw grape::Error("--size: expected WxH, e.g. 1200x760 (got '" + std::string(value) + "')");
            o.width = integer_option("--size width", value.substr(0, x), 320, 8192);
            o.height = integer_option("--size height", value.substr(x + 1), 240, 8192);
        } else {
            throw grape::Error("unknown option '" + std::string(arg) + "' (see --help)");
        }
    }
    if (!o.screenshot.empty() && o.frames == 0)
        throw grape::Error("--screenshot: needs --frames N (how many frames to run before the picture)");
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return grape::studio::run(parse(argc, argv));
    } catch (const grape::Error& e) {
        std::fprintf(stderr, "grape-studio: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "grape-studio: %s\n", e.what());
        return 1;
    }
}
