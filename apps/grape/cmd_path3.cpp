// `grape path3 length|point|closest|frame|sweep JSON ...`: queries on a 3-D path given as one
// JSON object (docs/scene-format.md, "3-D paths"). JSON is the object itself when it starts
// with '{', standard input when it is "-", and otherwise the name of a file holding the object.
#include "commands.hpp"
#include "json_out.hpp"

#include <grape/error.hpp>
#include <grape/frames3.hpp>
#include <grape/path3.hpp>
#include <grape/path3_closest.hpp>
#include <grape/scene_path3.hpp>
#include <grape/sweep3.hpp>

#include "atomic_file.hpp"
#include "scene/file_text.hpp"
#include "utf8_path.hpp"

#include <algorithm>
#include <cmath>
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
    // As `grape sample` bounds its times: the answer is one line per value.
    if (values.size() > 1000000)
        throw Error(who + ": --at: at most 1000000 values (got " + std::to_string(values.size()) + ")");
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
    std::vector<std::string> ray;
    std::string mode = "rmf";
    std::string up = "0,0,1";
    std::string end_up;
    bool closed = false;
    std::string profile;
    std::string tolerance = "0.001";
    std::string output;
    CLI::Option* up_option = nullptr;
    CLI::Option* end_up_option = nullptr;
};

CLI::Option* add_json(CLI::App* command, Path3Args& args) {
    return command->add_option("JSON", args.json, "The 3-D path: a JSON object, - for standard input, or a file holding it")
        ->required();
}

// --mode, --up, --end-up and --closed: how frames are chosen (frame and sweep).
void add_frame_options(CLI::App* command, Path3Args& args) {
    command->add_option("--mode", args.mode,
                        "rmf (default): rotation-minimizing from --up; up: --up kept as the world up (a camera); "
                        "frenet: the curve's own normal");
    args.up_option = command->add_option(
        "--up", args.up, "rmf: the normal at u = 0 is X,Y,Z without its part along the tangent; up: the world up (default 0,0,1)");
    args.end_up_option = command->add_option("--end-up", args.end_up,
                                             "rmf: the normal at u = 1 too (X,Y,Z without its part along the tangent), "
                                             "by the least twist spread evenly along the length");
    command->add_flag("--closed", args.closed, "rmf: the frame at u = 1 meets the frame at u = 0 (a closed path)");
}

// The frames the options choose; errors name the option.
Frames3 frames_of(const std::string& who, const Path3& path, const Path3Args& args) {
    const std::string& mode = args.mode;
    if (mode != "frenet" && mode != "rmf" && mode != "up")
        throw Error(who + ": --mode must be frenet, rmf or up (got '" + mode + "')");
    const bool end_up = args.end_up_option->count() > 0;
    if (mode != "rmf" && (end_up || args.closed))
        throw Error(who + ": " + (end_up ? "--end-up" : "--closed") + " applies to --mode rmf only");
    if (end_up && args.closed) throw Error(who + ": give --end-up or --closed, not both");
    if (mode == "frenet" && args.up_option->count() > 0)
        throw Error(who + ": --up applies to --mode rmf and up only (the Frenet normal is the curve's own)");
    FramesDef def;
    def.mode = mode == "frenet" ? FrameMode::frenet
               : mode == "up"   ? FrameMode::reference_up
               : end_up         ? FrameMode::ends
               : args.closed    ? FrameMode::closed
                                : FrameMode::rotation_minimizing;
    def.up = vec3_argument(who + ": --up", args.up);
    if (end_up) def.end_up = vec3_argument(who + ": --end-up", args.end_up);
    if (mode == "rmf") {
        // RotationMinimizingFrames' own bound: within ~1e-6 rad of the tangent the normal
        // would be mostly rounding.
        const Vec3 t0 = path.tangent(0.0);
        if (!(length(def.up - t0 * dot(def.up, t0)) > 1e-6 * length(def.up)))
            throw Error(who + ": --up " + args.up + " is zero or parallel to the tangent at u = 0 " + vec3_json(t0) +
                        " (give another --up)");
        const Vec3 t1 = path.tangent(1.0);
        if (end_up && !(length(def.end_up - t1 * dot(def.end_up, t1)) > 1e-6 * length(def.end_up)))
            throw Error(who + ": --end-up " + args.end_up + " is zero or parallel to the tangent at u = 1 " + vec3_json(t1) +
                        " (give another --end-up)");
    }
    try {
        return Frames3(path, def);
    } catch (const Error& e) {
        throw Error(who + ": " + e.what());
    }
}

// "circle:R:SIDES" as a profile.
std::vector<Vec2> profile_argument(const std::string& who, const std::string& text) {
    const std::string usage = who + ": --profile must be circle:RADIUS:SIDES (got '" + text + "')";
    if (text.rfind("circle:", 0) != 0) throw Error(usage);
    const std::size_t colon = text.find(':', 7);
    if (colon == std::string::npos) throw Error(usage);
    const double radius = parse_finite(who + ": --profile radius", text.substr(7, colon - 7));
    const double sides = parse_finite(who + ": --profile sides", text.substr(colon + 1));
    if (!(radius > 0.0)) throw Error(who + ": --profile radius must be positive (got " + json_number(radius) + ")");
    // A tube of more sides than this is a typo, not a mesh (each ring holds SIDES vertices).
    if (sides != std::floor(sides) || sides < 3 || sides > 4096)
        throw Error(who + ": --profile sides must be a whole number in [3, 4096] (got " + json_number(sides) + ")");
    return circle_profile(radius, static_cast<int>(sides));
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
        "closest", "Print the nearest point of the path to X,Y,Z: {\"u\", \"point\", \"distance\"}, or with --ray to a ray: "
                   "{\"u\", \"point\", \"distance\", \"t\"}");
    auto closest_args = std::make_shared<Path3Args>();
    add_json(closest, *closest_args);
    auto* point_option = closest->add_option("POINT", closest_args->point, "The query point X,Y,Z");
    auto* ray_option = closest->add_option("--ray", closest_args->ray,
                                           "The ray ORIGIN DIRECTION (X,Y,Z each): the nearest point to origin + t·direction, "
                                           "t ≥ 0 in units of |direction|");
    ray_option->expected(2);
    closest->callback([closest_args, point_option, ray_option] {
        const std::string who = "path3 closest";
        const bool ray = ray_option->count() > 0;
        if (ray == (point_option->count() > 0)) throw Error(who + ": give POINT (X,Y,Z) or --ray ORIGIN DIRECTION, one of them");
        const Path3 path = read_path3_argument(who, closest_args->json);
        if (ray) {
            const Vec3 origin = vec3_argument(who + ": --ray ORIGIN", closest_args->ray[0]);
            const Vec3 direction = vec3_argument(who + ": --ray DIRECTION", closest_args->ray[1]);
            if (!(length(direction) > 0.0)) throw Error(who + ": --ray DIRECTION must not be the zero vector");
            const RayClosest3 c = closest_point_to_ray(path, origin, direction);
            std::cout << "{\"u\": " << json_number(c.u) << ", \"point\": " << vec3_json(c.point)
                      << ", \"distance\": " << json_number(c.distance) << ", \"t\": " << json_number(c.t) << "}\n";
            return;
        }
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
    add_frame_options(frame, *frame_args);
    frame->callback([frame_args] {
        const std::string who = "path3 frame";
        const Path3 path = read_path3_argument(who, frame_args->json);
        const std::vector<double> at = parameters(who, frame_args->at, path, false);
        const Frames3 frames = frames_of(who, path, *frame_args);
        std::vector<std::string> items;
        for (double u : at) {
            const Frenet3 f = path.frenet(u);
            const Frame3 r = frames.frame(u);
            items.push_back("{\"u\": " + json_number(u) + ", \"point\": " + vec3_json(r.point) +
                            ", \"tangent\": " + vec3_json(r.tangent) + ", \"normal\": " + vec3_json(r.normal) +
                            ", \"binormal\": " + vec3_json(r.binormal) + ", \"curvature\": " + json_number(f.curvature) +
                            ", \"torsion\": " + json_number(f.torsion) + "}");
        }
        print_array(items);
    });

    auto* sweep_command = path3->add_subcommand(
        "sweep", "Sweep a profile along the path's frames and write the mesh as Wavefront OBJ (-o FILE)");
    auto sweep_args = std::make_shared<Path3Args>();
    add_json(sweep_command, *sweep_args);
    sweep_command->add_option("--profile", sweep_args->profile, "circle:RADIUS:SIDES, a tube")->required();
    sweep_command->add_option("--tolerance", sweep_args->tolerance,
                              "How far the faces may stray from the true surface, world units (default 0.001)");
    sweep_command->add_option("-o,--output", sweep_args->output, "The OBJ file to write")->required();
    add_frame_options(sweep_command, *sweep_args);
    sweep_command->callback([sweep_args] {
        const std::string who = "path3 sweep";
        const std::vector<Vec2> profile = profile_argument(who, sweep_args->profile);
        const double tolerance = parse_finite(who + ": --tolerance", sweep_args->tolerance);
        if (!(tolerance > 0.0)) throw Error(who + ": --tolerance must be positive (got " + sweep_args->tolerance + ")");
        const Path3 path = read_path3_argument(who, sweep_args->json);
        const Frames3 frames = frames_of(who, path, *sweep_args);
        Mesh3 mesh;
        try {
            mesh = sweep(frames, {.profile = profile, .tolerance = tolerance});
        } catch (const Error& e) {
            throw Error(who + ": " + e.what());
        }
        detail::write_file_atomically(detail::path_from_utf8(sweep_args->output), to_obj(mesh));
        std::cout << "wrote " << sweep_args->output << " (" << mesh.positions.size() << " vertices, "
                  << mesh.triangles.size() << " triangles, " << mesh.ring_u.size() << " rings)\n";
    });
}

}  // namespace grape::tool
