// `grape path3 length|point|closest|frame JSON ...`: queries on a 3-D path given as one JSON
// object (docs/scene-format.md, "3-D paths"). JSON is the object itself when it starts with
// '{', standard input when it is "-", and otherwise the name of a file holding the object.
#include "commands.hpp"
#include "json_out.hpp"

#include <grape/error.hpp>
#include <grape/path3.hpp>
#include <grape/scene_path3.hpp>

#include "scene/file_text.hpp"
#include "utf8_path.hpp"

#include <algorithm>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace grape::tool {
namespace {

// The path JSON names (see the file's comment); errors name the command and where the text came from.
Path3 read_path3_argument(const std::string& who, const std::string& argument) {
    const auto first = argument.find_first_not_of(" \t\r\n");
    std::string text;
    std::string from;
    if (first != std::string::npos && argument[first] == '{') {
        text = argument;
    } else if (argument == "-") {
        std::ostringstream all;
        all << std::cin.rdbuf();
        if (std::cin.bad()) throw Error(who + ": standard input could not be read");
        text = std::move(all).str();
        from = "standard input: ";
    } else if (first == std::string::npos) {
        throw Error(who + ": JSON must be a 3-D path object, - (standard input) or a file name (got '" + argument + "')");
    } else {
        try {
            text = detail::read_file_text(detail::path_from_utf8(argument), "a file of 3-D path JSON");
        } catch (const Error& e) {
            throw Error(who + ": " + e.what());
        }
        from = argument + ": ";
    }
    try {
        return parse_path3_json(text);
    } catch (const Error& e) {
        // "path3: /points/1: ..." after "path3 length: " would say path3 twice.
        std::string what = e.what();
        if (what.rfind("path3: ", 0) == 0) what.erase(0, 7);
        throw Error(who + ": " + from + what);
    }
}

// Numbers separated by commas ("0,0.5,1"), each finite; `what` names the argument.
std::vector<double> number_list(const std::string& what, const std::string& text) {
    std::vector<double> values;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string piece = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        values.push_back(parse_finite(what, piece));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return values;
}

// "X,Y,Z" as a point or direction.
Vec3 vec3_argument(const std::string& what, const std::string& text) {
    const std::size_t commas = static_cast<std::size_t>(std::count(text.begin(), text.end(), ','));
    if (commas != 2) throw Error(what + " must be three numbers X,Y,Z separated by commas (got '" + text + "')");
    const std::vector<double> v = number_list(what, text);
    return {v[0], v[1], v[2]};
}

std::string vec3_json(Vec3 v) {
    return "[" + json_number(v.x) + ", " + json_number(v.y) + ", " + json_number(v.z) + "]";
}

// One JSON object per line inside one array.
void print_array(const std::vector<std::string>& items) {
    std::string out = "[";
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ",\n " : "") + items[i];
    std::cout << out << "]\n";
}

// The values of --at: parameters u in [0, 1], or with `by_length` distances s in [0, length].
std::vector<double> parameters(const std::string& who, const std::string& text, const Path3& path, bool by_length) {
    const std::vector<double> values = number_list(who + ": --at", text);
    const double total = path.length();
    for (double v : values) {
        if (by_length && (v < 0.0 || v > total))
            throw Error(who + ": --at: a distance must lie in [0, " + json_number(total) + "], the path's length (got " +
                        json_number(v) + ")");
        if (!by_length && (v < 0.0 || v > 1.0))
            throw Error(who + ": --at: u must lie in [0, 1] (got " + json_number(v) + ")");
    }
    return values;
}

struct Path3Args {
    std::string json;
    std::string at;
    bool by_length = false;
    std::string point;
    std::string mode = "rmf";
    std::string up = "0,0,1";
};

CLI::Option* add_json(CLI::App* command, Path3Args& args) {
    return command->add_option("JSON", args.json, "The 3-D path: a JSON object, - for standard input, or a file holding it")
        ->required();
}

}  // namespace

void register_path3_commands(CLI::App& app) {
    auto* path3 = app.add_subcommand("path3", "Queries on a 3-D path given as JSON (docs/scene-format.md, \"3-D paths\")");
    path3->require_subcommand(1);

    auto* length_command = path3->add_subcommand("length", "Print the arc length: {\"length\": L}");
    auto length_args = std::make_shared<Path3Args>();
    add_json(length_command, *length_args);
    length_command->callback([length_args] {
        const Path3 path = read_path3_argument("path3 length", length_args->json);
        std::cout << json_object({{"length", path.length()}}) << '\n';
    });

    auto* point = path3->add_subcommand("point", "Print the points at u1,u2,...: [{\"u\", \"point\"}, ...]");
    auto point_args = std::make_shared<Path3Args>();
    add_json(point, *point_args);
    point->add_option("--at", point_args->at, "Parameters u in [0, 1], separated by commas")->required();
    point->add_flag("--arc-length", point_args->by_length,
                    "The --at values are distances s along the path, in [0, length]: [{\"s\", \"u\", \"point\"}, ...]");
    point->callback([point_args] {
        const std::string who = "path3 point";
        const Path3 path = read_path3_argument(who, point_args->json);
        std::vector<std::string> items;
        for (double v : parameters(who, point_args->at, path, point_args->by_length)) {
            const double u = point_args->by_length ? path.u_at_length(v) : v;
            const std::string s = point_args->by_length ? "\"s\": " + json_number(v) + ", " : "";
            items.push_back("{" + s + "\"u\": " + json_number(u) + ", \"point\": " + vec3_json(path.point(u)) + "}");
        }
        print_array(items);
    });

    auto* closest = path3->add_subcommand(
        "closest", "Print the nearest point of the path to X,Y,Z: {\"u\", \"point\", \"distance\"}");
    auto closest_args = std::make_shared<Path3Args>();
    add_json(closest, *closest_args);
    closest->add_option("POINT", closest_args->point, "The query point X,Y,Z")->required();
    closest->callback([closest_args] {
        const std::string who = "path3 closest";
        const Path3 path = read_path3_argument(who, closest_args->json);
        const Vec3 q = vec3_argument(who + ": POINT", closest_args->point);
        const Closest3 c = closest_point(path, q);
        std::cout << "{\"u\": " << json_number(c.u) << ", \"point\": " << vec3_json(c.point)
                  << ", \"distance\": " << json_number(c.distance) << "}\n";
    });

    auto* frame = path3->add_subcommand(
        "frame", "Print frames at u1,u2,...: [{\"u\", \"point\", \"tangent\", \"normal\", \"binormal\", \"curvature\", "
                 "\"torsion\"}, ...]");
    auto frame_args = std::make_shared<Path3Args>();
    add_json(frame, *frame_args);
    frame->add_option("--at", frame_args->at, "Parameters u in [0, 1], separated by commas")->required();
    frame->add_option("--mode", frame_args->mode,
                      "frenet: the curve's own normal; rmf (default): rotation-minimizing, the normal is --up "
                      "carried along without spin");
    auto* up_option = frame->add_option("--up", frame_args->up,
                                        "rmf: the normal at u = 0 is X,Y,Z without its part along the tangent (default 0,0,1)");
    frame->callback([frame_args, up_option] {
        const std::string who = "path3 frame";
        const std::string& mode = frame_args->mode;
        if (mode != "frenet" && mode != "rmf")
            throw Error(who + ": --mode must be frenet or rmf (got '" + mode + "')");
        if (mode == "frenet" && up_option->count() > 0)
            throw Error(who + ": --up applies to --mode rmf only (the Frenet normal is the curve's own)");
        const Path3 path = read_path3_argument(who, frame_args->json);
        const std::vector<double> at = parameters(who, frame_args->at, path, false);
        std::unique_ptr<RotationMinimizingFrames> rmf;
        if (mode == "rmf") {
            const Vec3 up = vec3_argument(who + ": --up", frame_args->up);
            // RotationMinimizingFrames' own bound: within ~1e-6 rad of the tangent the normal
            // would be mostly rounding.
            const Vec3 t0 = path.tangent(0.0);
            if (!(length(up - t0 * dot(up, t0)) > 1e-6 * length(up)))
                throw Error(who + ": --up " + frame_args->up + " is zero or parallel to the tangent at u = 0 " +
                            vec3_json(t0) + " (give another --up)");
            try {
                rmf = std::make_unique<RotationMinimizingFrames>(path, up);
            } catch (const Error& e) {
                throw Error(who + ": " + e.what());
            }
        }
        std::vector<std::string> items;
        for (double u : at) {
            const Frenet3 f = path.frenet(u);
            Vec3 tangent = f.tangent, normal = f.normal, binormal = f.binormal;
            if (rmf) {
                const Frame3 r = rmf->frame(u);
                tangent = r.tangent;
                normal = r.normal;
                binormal = r.binormal;
            }
            items.push_back("{\"u\": " + json_number(u) + ", \"point\": " + vec3_json(f.point) +
                            ", \"tangent\": " + vec3_json(tangent) + ", \"normal\": " + vec3_json(normal) +
                            ", \"binormal\": " + vec3_json(binormal) + ", \"curvature\": " + json_number(f.curvature) +
                            ", \"torsion\": " + json_number(f.torsion) + "}");
        }
        print_array(items);
    });
}

}  // namespace grape::tool
