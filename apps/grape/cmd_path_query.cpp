// `grape path closest DATA X Y`, `grape path curvature DATA U` and `grape path slice DATA U0 U1`
// (with --arc-length, U and the answer's u are fractions of the length, as `grape path point`
// takes them).
#include "commands.hpp"
#include "json_out.hpp"

#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/path_query.hpp>

#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace grape::tool {
namespace {

double parse_fraction(const char* command, const std::string& text) {
    const double value = parse_finite(std::string(command) + ": U", text);
    if (value < 0.0 || value > 1.0) throw Error(std::string(command) + ": U must lie in [0, 1] (got " + text + ")");
    return value;
}

// `x y` per line (blank lines and # comments skipped); a bad line is an error naming it.
std::vector<Vec2> read_points(std::istream& in, const std::string& source) {
    std::vector<Vec2> points;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.erase(hash);
        std::istringstream fields(line);
        std::string x, y, extra;
        if (!(fields >> x)) continue;
        const std::string where = "path fit: " + source + " line " + std::to_string(number);
        if (!(fields >> y) || (fields >> extra)) throw Error(where + " must hold two numbers, x and y (got '" + line + "')");
        points.push_back({parse_finite(where + ": x", x), parse_finite(where + ": y", y)});
    }
    return points;
}

// The fraction of the length travelled at u (exact quadrature, not the arc-length table).
double length_fraction(const Path& path, double u) {
    return path.length() > 0.0 ? path.length_at(u) / path.length() : u;
}

}  // namespace

void register_path_query_commands(CLI::App& path) {
    auto* closest = path.add_subcommand(
        "closest", "Print the nearest point of the path to (X, Y): {\"u\", \"x\", \"y\", \"distance\"}");
    auto closest_data = std::make_shared<std::string>();
    auto x_text = std::make_shared<std::string>();
    auto y_text = std::make_shared<std::string>();
    auto closest_by_length = std::make_shared<bool>(false);
    closest->add_option("DATA", *closest_data, "SVG path data")->required();
    closest->add_option("X", *x_text, "Query point x")->required();
    closest->add_option("Y", *y_text, "Query point y")->required();
    closest->add_flag("--arc-length", *closest_by_length, "Print u as the fraction of the length travelled");
    closest->callback([closest_data, x_text, y_text, closest_by_length] {
        const Vec2 q{parse_finite("path closest: X", *x_text), parse_finite("path closest: Y", *y_text)};
        const ComplexPath parsed = parse_svg_path(*closest_data);
        const ClosestPoint c = closest_point(parsed, q);
        const double u = *closest_by_length ? length_fraction(parsed, c.u) : c.u;
        std::cout << json_object({{"u", u}, {"x", c.point.x}, {"y", c.point.y}, {"distance", c.distance}}) << '\n';
    });

    auto* bend = path.add_subcommand(
        "curvature", "Print the signed curvature, unit tangent and normal at U: {\"curvature\", \"tx\", \"ty\", \"nx\", \"ny\"}");
    auto bend_data = std::make_shared<std::string>();
    auto u_text = std::make_shared<std::string>();
    auto bend_by_length = std::make_shared<bool>(false);
    bend->add_option("DATA", *bend_data, "SVG path data")->required();
    bend->add_option("U", *u_text, "Parameter in [0, 1]")->required();
    bend->add_flag("--arc-length", *bend_by_length, "U is the fraction of the length travelled");
    bend->callback([bend_data, u_text, bend_by_length] {
        const double fraction = parse_fraction("path curvature", *u_text);
        const ComplexPath parsed = parse_svg_path(*bend_data);
        // Curvature and frame are geometric: the same at the same point, whatever the parameter.
        const double u = *bend_by_length ? parsed.u_at_length(fraction * parsed.length()) : fraction;
        const PathFrame f = frame(parsed, u);
        std::cout << json_object({{"curvature", f.curvature},
                                  {"tx", f.tangent.x},
                                  {"ty", f.tangent.y},
                                  {"nx", f.normal.x},
                                  {"ny", f.normal.y}})
                  << '\n';
    });

    auto* cut = path.add_subcommand("slice", "Print the SVG path data of the part between U0 and U1");
    auto cut_data = std::make_shared<std::string>();
    auto u0_text = std::make_shared<std::string>();
    auto u1_text = std::make_shared<std::string>();
    auto cut_by_length = std::make_shared<bool>(false);
    cut->add_option("DATA", *cut_data, "SVG path data")->required();
    cut->add_option("U0", *u0_text, "Where the slice starts, in [0, 1)")->required();
    cut->add_option("U1", *u1_text, "Where it ends, in (U0, 1]")->required();
    cut->add_flag("--arc-length", *cut_by_length, "U0 and U1 are fractions of the length travelled");
    cut->callback([cut_data, u0_text, u1_text, cut_by_length] {
        const double u0 = parse_fraction("path slice", *u0_text);
        const double u1 = parse_fraction("path slice", *u1_text);
        if (!(u1 > u0)) throw Error("path slice: U1 must exceed U0 (got " + *u0_text + " and " + *u1_text + ")");
        const ComplexPath parsed = parse_svg_path(*cut_data);
        const Path part = *cut_by_length ? slice_by_length(parsed, u0 * parsed.length(), u1 * parsed.length())
                                         : slice(parsed, u0, u1);
        std::cout << svg_path_data(part) << '\n';
    });

    auto* fit = path.add_subcommand(
        "fit", "Fit cubic Béziers to `x y` lines (a file, or stdin) and print the SVG path data");
    auto fit_file = std::make_shared<std::string>();
    auto fit_tolerance = std::make_shared<std::string>("1");
    auto fit_corner = std::make_shared<std::string>("60");
    fit->add_option("FILE", *fit_file, "Points, one `x y` per line (default: stdin)");
    fit->add_option("--tolerance", *fit_tolerance, "Largest distance of a point from the path (default 1)");
    fit->add_option("--corner-angle", *fit_corner, "Turns sharper than this many degrees stay corners (default 60)");
    fit->callback([fit_file, fit_tolerance, fit_corner] {
        FitPathDef def;
        def.tolerance = parse_finite("path fit: --tolerance", *fit_tolerance);
        def.corner_angle = parse_finite("path fit: --corner-angle", *fit_corner) * pi / 180.0;
        std::vector<Vec2> points;
        if (fit_file->empty() || *fit_file == "-") {
            points = read_points(std::cin, "stdin");
        } else {
            std::ifstream in(*fit_file);
            if (!in) throw Error("path fit: cannot read " + *fit_file);
            points = read_points(in, *fit_file);
        }
        std::cout << svg_path_data(fit_path(points, def)) << '\n';
    });
}

}  // namespace grape::tool
