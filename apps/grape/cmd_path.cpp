// `grape path length DATA`, `grape path point DATA U [--arc-length]` (DATA may come from a
// file or standard input, and is read by SVG's error rule unless --strict) and the demo's
// table of the seed's paths.
#include "commands.hpp"
#include "json_out.hpp"
#include "path_data.hpp"

#include <grape/error.hpp>
#include <grape/path.hpp>

#include <seed_paths.hpp>

#include "utf8_path.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <ostream>
#include <memory>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>

namespace grape::tool {
namespace {

// U in [0, 1], checked by grape's rules (CLI11's own conversion would not say which rule U broke).
double parse_parameter(const std::string& text) {
    const double value = parse_finite("path point: U", text);
    if (value < 0.0 || value > 1.0) throw Error("path point: U must lie in [0, 1] (got " + text + ")");
    return value;
}

// The whole of a stream (real path data reaches megabytes, past the argument limit).
std::string read_all(std::istream& in) {
    std::ostringstream text;
    text << in.rdbuf();
    return std::move(text).str();
}

}  // namespace

std::string read_data(const char* command, const DataSource& source) {
    const std::string who = std::string("path ") + command;
    if (!source.file.empty() && source.given) throw Error(who + ": give DATA or --data-file, not both");
    if (source.file.empty() && !source.given)
        throw Error(who + ": DATA is required (or --data-file FILE, or - for standard input)");
    if (source.file == "-" || (source.file.empty() && source.argument == "-")) {
        std::string text = read_all(std::cin);
        if (std::cin.bad()) throw Error(who + ": standard input could not be read");
        return text;
    }
    if (source.file.empty()) return source.argument;
    std::error_code ec;
    const std::filesystem::path file = detail::path_from_utf8(source.file);
    if (std::filesystem::is_directory(file, ec))
        throw Error(who + ": --data-file " + source.file + ": is a folder, not a file of SVG path data");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(who + ": --data-file " + source.file + ": cannot be opened (" + std::strerror(errno) + ")");
    std::string text = read_all(in);
    if (in.bad()) throw Error(who + ": --data-file " + source.file + ": cannot be read");
    return text;
}

void add_data_file_option(CLI::App& command, DataSource& source) {
    command.add_option("--data-file", source.file, "Read DATA from FILE (- for standard input)");
}

namespace {

// SVG's error rule (the path up to the command holding the first error, with a warning on
// stderr), or with --strict the error itself (exit status 2).
ComplexPath read_path(const char* command, const DataSource& source) {
    const std::string data = read_data(command, source);
    if (source.strict) return parse_svg_path(data);
    SvgPathParse parsed = parse_svg_path_prefix(data);
    if (parsed.error) {
        std::cerr << "grape: warning: " << parsed.error->message
                  << "; using the path before it, as SVG does (--strict makes this an error)\n";
    }
    return parsed.path;
}

void add_data_options(CLI::App& command, DataSource& source) {
    add_data_file_option(command, source);
    command.add_flag("--strict", source.strict,
                     "Refuse data with a syntax error (by default the path stops before it, as SVG draws it)");
}

}  // namespace

void register_path_commands(CLI::App& app) {
    auto* path = app.add_subcommand("path", "Queries on SVG path data (y down, as in SVG)");
    path->require_subcommand(1);

    auto* length = path->add_subcommand("length", "Print the arc length: {\"length\": L}");
    auto length_data = std::make_shared<DataSource>();
    auto* length_argument =
        length->add_option("DATA", length_data->argument, "SVG path data, e.g. \"M0 0 L3 4\" (- for standard input)");
    add_data_options(*length, *length_data);
    length->callback([length_data, length_argument] {
        length_data->given = length_argument->count() > 0;
        std::cout << json_object({{"length", read_path("length", *length_data).length()}}) << '\n';
    });

    auto* point = path->add_subcommand(
        "point", "Print the point at U and the derivative with respect to U: {\"x\", \"y\", \"dx\", \"dy\"}");
    auto point_data = std::make_shared<DataSource>();
    auto u_text = std::make_shared<std::string>();
    auto by_length = std::make_shared<bool>(false);
    auto* point_argument = point->add_option("DATA", point_data->argument, "SVG path data (- for standard input)");
    auto* u_argument = point->add_option("U", *u_text, "Parameter in [0, 1] (subpaths share it by length)");
    add_data_options(*point, *point_data);
    point->add_flag("--arc-length", *by_length,
                    "U is the fraction of the length travelled (the derivative's norm is then the length)");
    point->callback([point_data, u_text, by_length, point_argument, u_argument] {
        point_data->given = point_argument->count() > 0;
        // With --data-file the one positional argument is U.
        if (!point_data->file.empty() && point_data->given && u_argument->count() == 0) {
            std::swap(point_data->argument, *u_text);
            point_data->given = false;
        } else if (u_argument->count() == 0) {
            throw Error("path point: DATA and U are required (or --data-file FILE and U)");
        }
        const double u = parse_parameter(*u_text);
        const ComplexPath parsed = read_path("point", *point_data);
        // A path of length 0 stands at its point: reparametrizing it keeps it there.
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
    for (const NamedPath& named : scenes::seed_paths()) {
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
