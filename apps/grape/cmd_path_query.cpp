// `grape path closest DATA X Y`, `grape path curvature DATA U` and `grape path slice DATA U0 U1`
// (with --arc-length, U and the answer's u are fractions of the length, as `grape path point`
// takes them).
#include "commands.hpp"
#include "json_out.hpp"
#include "path_data.hpp"

#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/path_query.hpp>

#include "utf8_path.hpp"

#include <array>
#include <fstream>
#include <initializer_list>
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

// What the queries take: SVG path DATA (the argument, - for standard input, or --data-file),
// one or two numbers (as text) and --arc-length.
struct QueryArgs {
    DataSource source;
    std::array<std::string, 3> positional;  // as given: DATA and the numbers, or the numbers alone with --data-file
    std::array<CLI::Option*, 3> options{};
    std::size_t numbers = 0;
    std::array<std::string, 2> values;      // the numbers, once resolved
    bool by_length = false;
    std::string usage;                      // "DATA, X and Y", for the message when some are missing
};

std::shared_ptr<QueryArgs> query_args(CLI::App* command, std::initializer_list<std::pair<const char*, const char*>> values,
                                      const char* by_length_help) {
    auto args = std::make_shared<QueryArgs>();
    // Not required one by one: with --data-file the first positional is the first number.
    args->options[0] = command->add_option("DATA", args->positional[0], "SVG path data (- for standard input)");
    args->usage = "DATA";
    for (const auto& [name, help] : values) {
        ++args->numbers;
        args->options[args->numbers] = command->add_option(name, args->positional[args->numbers], help);
        args->usage += std::string(args->numbers == values.size() ? " and " : ", ") + name;
    }
    add_data_file_option(*command, args->source);
    command->add_flag("--arc-length", args->by_length, by_length_help);
    return args;
}

// The path and the numbers of a query, from DATA or --data-file.
ComplexPath query_path(const char* command, QueryArgs& args) {
    std::size_t given = 0;
    for (std::size_t i = 0; i <= args.numbers; ++i) given += args.options[i]->count() > 0 ? 1 : 0;
    const bool from_file = !args.source.file.empty();
    const std::size_t needed = args.numbers + (from_file ? 0 : 1);
    if (given != needed) {
        const std::string who = std::string("path ") + command;
        if (from_file && given == needed + 1) throw Error(who + ": give DATA or --data-file, not both");
        throw Error(who + ": " + args.usage + " are required (or --data-file FILE and the numbers)");
    }
    const std::size_t first = from_file ? 0 : 1;
    for (std::size_t i = 0; i < args.numbers; ++i) args.values[i] = args.positional[first + i];
    args.source.argument = args.positional[0];
    args.source.given = !from_file;
    return parse_svg_path(read_data(command, args.source));
}

}  // namespace

void register_path_query_commands(CLI::App& path) {
    auto* closest = path.add_subcommand(
        "closest", "Print the nearest point of the path to (X, Y): {\"u\", \"x\", \"y\", \"distance\"}");
    const auto to_point = query_args(closest, {{"X", "Query point x"}, {"Y", "Query point y"}},
                                 "Print u as the fraction of the length travelled");
    closest->callback([to_point] {
        const ComplexPath parsed = query_path("closest", *to_point);
        const Vec2 q{parse_finite("path closest: X", to_point->values[0]), parse_finite("path closest: Y", to_point->values[1])};
        const ClosestPoint c = closest_point(parsed, q);
        const double u = to_point->by_length ? length_fraction(parsed, c.u) : c.u;
        std::cout << json_object({{"u", u}, {"x", c.point.x}, {"y", c.point.y}, {"distance", c.distance}}) << '\n';
    });

    auto* bend = path.add_subcommand(
        "curvature", "Print the signed curvature, unit tangent and normal at U: {\"curvature\", \"tx\", \"ty\", \"nx\", \"ny\"}");
    const auto at = query_args(bend, {{"U", "Parameter in [0, 1]"}}, "U is the fraction of the length travelled");
    bend->callback([at] {
        const ComplexPath parsed = query_path("curvature", *at);
        const double fraction = parse_fraction("path curvature", at->values[0]);
        // Curvature and frame are geometric: the same at the same point, whatever the parameter.
        const double u = at->by_length ? parsed.u_at_length(fraction * parsed.length()) : fraction;
        const PathFrame f = frame(parsed, u);
        std::cout << json_object({{"curvature", f.curvature},
                                  {"tx", f.tangent.x},
                                  {"ty", f.tangent.y},
                                  {"nx", f.normal.x},
                                  {"ny", f.normal.y}})
                  << '\n';
    });

    auto* cut = path.add_subcommand("slice", "Print the SVG path data of the part between U0 and U1");
    const auto span = query_args(cut, {{"U0", "Where the slice starts, in [0, 1)"}, {"U1", "Where it ends, in (U0, 1]"}},
                                 "U0 and U1 are fractions of the length travelled");
    cut->callback([span] {
        const ComplexPath parsed = query_path("slice", *span);
        const std::string& u0_text = span->values[0];
        const std::string& u1_text = span->values[1];
        const double u0 = parse_fraction("path slice", u0_text);
        const double u1 = parse_fraction("path slice", u1_text);
        if (!(u1 > u0)) throw Error("path slice: U1 must exceed U0 (got " + u0_text + " and " + u1_text + ")");
        const Path part = span->by_length ? slice_by_length(parsed, u0 * parsed.length(), u1 * parsed.length())
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
            std::ifstream in(detail::path_from_utf8(*fit_file));  // text: CRLF lines read as LF on Windows
            if (!in) throw Error("path fit: cannot read " + *fit_file);
            points = read_points(in, *fit_file);
        }
        std::cout << svg_path_data(fit_path(points, def)) << '\n';
    });
}

}  // namespace grape::tool
