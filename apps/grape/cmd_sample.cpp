// `grape sample SCENE.json --at T1,T2,...` (or --at-file FILE): where every named animation of a scene stands at
// each scene time, as JSON with 17 significant digits (each number reads back as the same
// double), played as `grape render` plays it: free animations by their own timing, the others
// by the timelines that drive them. Named 3-D animations stand beside them as [x, y, z], or as
// {"position": [x, y, z], "orientation": [w, x, y, z]} when they turn their target (a unit
// quaternion, as SceneMotion3 gives it). A scene with properties also gets each property's value
// (numbers and angles as numbers, vec2 as [x, y], colours as [r, g, b, a]).
#include "commands.hpp"
#include "json_out.hpp"

#include <grape/error.hpp>
#include <grape/scene.hpp>
#include <grape/scene_values.hpp>

#include <nlohmann/json.hpp>

#include "utf8_path.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace grape::tool {

namespace {

struct SampleOptions {
    std::string scene;
    std::vector<std::string> at;
    std::string at_file;  // "" when absent, "-" for standard input
};

std::string vec3_text(Vec3 p) { return "[" + json_number(p.x) + ", " + json_number(p.y) + ", " + json_number(p.z) + "]"; }

std::string value_text(const SceneValue& v) {
    if (const double* d = std::get_if<double>(&v)) return json_number(*d);
    if (const Vec2* p = std::get_if<Vec2>(&v)) return "[" + json_number(p->x) + ", " + json_number(p->y) + "]";
    if (const Vec3* p = std::get_if<Vec3>(&v)) return vec3_text(*p);
    if (const Quat* q = std::get_if<Quat>(&v))
        return "[" + json_number(q->w) + ", " + json_number(q->x) + ", " + json_number(q->y) + ", " + json_number(q->z) + "]";
    const Color& c = std::get<Color>(v);
    return "[" + json_number(c.r) + ", " + json_number(c.g) + ", " + json_number(c.b) + ", " + json_number(c.a) + "]";
}

// More times than this is a typo or a script gone wrong: the answer would not fit a terminal.
constexpr std::size_t max_times = 1'000'000;

// The times of --at-file: numbers separated by white space (one a line, or several), read
// up to one past the limit so that a huge file is refused without reading it all.
std::vector<double> read_times(std::istream& in, const std::string& name) {
    std::vector<double> times;
    std::string token;
    while (in >> token) {
        if (times.size() == max_times)
            throw Error("sample: --at-file " + name + ": more than 1000000 times (the most one run takes)");
        times.push_back(parse_finite("sample: --at-file " + name + ": time " + std::to_string(times.size() + 1), token));
    }
    if (in.bad()) throw Error("sample: --at-file " + name + ": cannot be read");
    return times;
}

std::vector<double> sample_times(const SampleOptions& o) {
    if (!o.at.empty() && !o.at_file.empty()) throw Error("sample: give --at or --at-file, not both");
    if (o.at.empty() && o.at_file.empty()) throw Error("sample: --at T1,T2,... or --at-file FILE is required");
    std::vector<double> times;
    if (o.at_file == "-") {
        times = read_times(std::cin, "-");
    } else if (!o.at_file.empty()) {
        const std::filesystem::path file = detail::path_from_utf8(o.at_file);
        std::error_code ec;
        if (std::filesystem::is_directory(file, ec)) throw Error("sample: --at-file " + o.at_file + ": is a folder, not a file of times");
        std::ifstream in(file);
        if (!in) throw Error("sample: --at-file " + o.at_file + ": cannot be opened (" + std::strerror(errno) + ")");
        times = read_times(in, o.at_file);
    } else {
        for (const std::string& text : o.at) times.push_back(parse_finite("sample: --at", text));
    }
    if (times.empty()) throw Error(o.at_file.empty() ? "sample: --at needs at least one time" : "sample: --at-file " + o.at_file + " holds no time");
    if (times.size() > max_times) throw Error("sample: --at takes at most 1000000 times (got " + std::to_string(times.size()) + ")");
    return times;
}

void run_sample(const SampleOptions& o) {
    const std::vector<double> times = sample_times(o);
    const Scene scene = load_scene_file(detail::path_from_utf8(o.scene));
    // The named animations, each name once (a JSON object holds a key once).
    std::vector<std::size_t> named;
    for (std::size_t i = 0; i < scene.animations.size(); ++i) {
        const std::string& name = scene.animations[i].name;
        if (name.empty()) continue;
        for (std::size_t j : named)
            if (scene.animations[j].name == name)
                throw Error("sample: " + o.scene + ": /animations/" + std::to_string(j) + " and /animations/" + std::to_string(i) +
                            " are both named \"" + name + "\"; sampled animations need distinct names");
        named.push_back(i);
    }
    // The named 3-D animations: names distinct from each other and from the 2-D ones.
    std::vector<std::size_t> named3;
    for (std::size_t i = 0; i < scene.animations3.size(); ++i) {
        const std::string& name = scene.animations3[i].name;
        if (name.empty()) continue;
        for (std::size_t j : named)
            if (scene.animations[j].name == name)
                throw Error("sample: " + o.scene + ": /animations/" + std::to_string(j) + " and /animations3/" + std::to_string(i) +
                            " are both named \"" + name + "\"; sampled animations need distinct names");
        for (std::size_t j : named3)
            if (scene.animations3[j].name == name)
                throw Error("sample: " + o.scene + ": /animations3/" + std::to_string(j) + " and /animations3/" + std::to_string(i) +
                            " are both named \"" + name + "\"; sampled animations need distinct names");
        named3.push_back(i);
    }
    std::vector<SceneMotion3> motions;
    motions.reserve(named3.size());
    for (std::size_t i : named3) motions.emplace_back(scene.animations3[i]);  // validated by the loader
    const SceneTiming timing(scene);
    const SceneProperties values(scene, timing);
    std::string out = "[";
    for (std::size_t k = 0; k < times.size(); ++k) {
        out += k ? ",\n " : "";
        out += "{\"time\": " + json_number(times[k]) + ", \"animations\": {";
        for (std::size_t n = 0; n < named.size(); ++n) {
            const std::size_t i = named[n];
            const Vec2 p = scene.animations[i].position_at(timing.progress(i, times[k]));
            out += (n ? ", " : "") + nlohmann::json(scene.animations[i].name).dump() + ": [" + json_number(p.x) + ", " +
                   json_number(p.y) + "]";
        }
        for (std::size_t n = 0; n < named3.size(); ++n) {
            const std::size_t i = named3[n];
            const SceneMotion3& m = motions[n];
            const double progress = timing.animation3_progress(i, times[k]);
            out += (n || !named.empty() ? ", " : "") + nlohmann::json(scene.animations3[i].name).dump() + ": ";
            const std::string position = vec3_text(m.position_at(progress));
            if (!m.writes_orientation()) {
                out += position;
            } else {
                const Quat q = m.orientation_at(progress, timing.animation3_backward(i, times[k]));
                out += "{\"position\": " + position + ", \"orientation\": [" + json_number(q.w) + ", " + json_number(q.x) +
                       ", " + json_number(q.y) + ", " + json_number(q.z) + "]}";
            }
        }
        out += "}";
        if (!scene.properties.empty()) {
            out += ", \"properties\": {";
            for (std::size_t p = 0; p < scene.properties.size(); ++p)
                out += (p ? ", " : "") + nlohmann::json(scene.properties[p].name).dump() + ": " + value_text(values.value(p, times[k]));
            out += "}";
        }
        out += "}";
    }
    std::cout << out << "]\n";
}

}  // namespace

void register_sample_command(CLI::App& app) {
    auto options = std::make_shared<SampleOptions>();
    auto* cmd = app.add_subcommand("sample", "Print where every named animation of a scene is (3-D ones with their orientation), and its properties' values, at the given scene times (JSON)");
    cmd->add_option("scene", options->scene, "Scene file (JSON, see docs/scene-format.md)")->required();
    cmd->add_option("--at", options->at, "Scene times in seconds, comma-separated: --at 0,0.5,1.25")->delimiter(',');
    cmd->add_option("--at-file", options->at_file,
                    "Read the times from FILE (- for standard input): numbers separated by spaces or lines, at most 1000000");
    cmd->callback([options] { run_sample(*options); });
}

}  // namespace grape::tool
