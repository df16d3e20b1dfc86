// `grape path length DATA`, `grape path point DATA U [--arc-length]` and the demo's table of
// the seed's paths.
#include "commands.hpp"
#include "json_out.hpp"

#include <grape/error.hpp>
#include <grape/path.hpp>

#include <seed_paths.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <ostream>
#include <memory>
#include <string>

namespace grape::tool {
namespace {

// U in [0, 1], checked by grape's rules (CLI11's own conversion would not say which rule U broke).
double parse_parameter(const std::string& text) {
    const double value = parse_finite("path point: U", text);
    if (value < 0.0 || value > 1.0) throw Error("path point: U must lie in [0, 1] (got " + text + ")");
    return value;
}

}  // namespace

void register_path_commands(CLI::App& app) {
    auto* path = app.add_subcommand("path", "Queries on SVG path data (y down, as in SVG)");
    path->require_subcommand(1);

    auto* length = path->add_subcommand("length", "Print the arc length: {\"length\": L}");
    auto length_data = std::make_shared<std::string>();
    length->add_option("DATA", *length_data, "SVG path data, e.g. \"M0 0 L3 4\"")->required();
    length->callback([length_data] {
        std::cout << json_object({{"length", parse_svg_path(*length_data).length()}}) << '\n';
    });

    auto* point = path->add_subcommand(
        "point", "Print the point at U and the derivative with respect to U: {\"x\", \"y\", \"dx\", \"dy\"}");
    auto point_data = std::make_shared<std::string>();
    auto u_text = std::make_shared<std::string>();
    auto by_length = std::make_shared<bool>(false);
    point->add_option("DATA", *point_data, "SVG path data")->required();
    point->add_option("U", *u_text, "Parameter in [0, 1] (subpaths share it by length)")->required();
    point->add_flag("--arc-length", *by_length,
                    "U is the fraction of the length travelled (the derivative's norm is then the length)");
    point->callback([point_data, u_text, by_length] {
        const double u = parse_parameter(*u_text);
        const ComplexPath parsed = parse_svg_path(*point_data);
        const Path path = *by_length ? parsed.reparametrized() : Path(parsed);
        const Vec2 p = path.point(u);
        const Vec2 d = path.d1(u);
        std::cout << json_object({{"x", p.x}, {"y", p.y}, {"dx", d.x}, {"dy", d.y}}) << '\n';
    });
    register_path_query_commands(*path);
}

void demo_paths(const DemoContext& context) {
    std::ostream& out = context.out;
    out << "Paths (the seed's examples; lengths in pixels, y down)\n";
    char line[160];
    std::snprintf(line, sizeof line, "  %-24s %-18s %12s  %-22s  %-22s\n", "name", "kind", "length", "start",
                  "end");
    out << line;
    for (const scenes::NamedPath& named : scenes::seed_paths()) {
        const Path& path = named.path;
        const Vec2 a = path.point(0.0);
        const Vec2 b = path.point(1.0);
        const std::string kind(to_string(path.kind()));
        std::snprintf(line, sizeof line, "  %-24s %-18s %12.6f  (%9.3f, %9.3f)  (%9.3f, %9.3f)\n", named.name.c_str(),
                      kind.c_str(), path.length(), a.x, a.y, b.x, b.y);
        out << line;
    }
    out << '\n';
}

}  // namespace grape::tool
