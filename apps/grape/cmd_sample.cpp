// `grape sample SCENE.json --at T1,T2,...`: where every named animation of a scene stands at
// each scene time, as JSON with 17 significant digits (each number reads back as the same
// double), played as `grape render` plays it: free animations by their own timing, the others
// by the timelines that drive them. A scene with properties also gets each property's value
// (numbers and angles as numbers, vec2 as [x, y], colours as [r, g, b, a]).
#include "commands.hpp"
#include "json_out.hpp"

#include <grape/error.hpp>
#include <grape/scene.hpp>
#include <grape/scene_values.hpp>

#include <nlohmann/json.hpp>

#include "utf8_path.hpp"

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
};

std::string value_text(const SceneValue& v) {
    if (const double* d = std::get_if<double>(&v)) return json_number(*d);
    if (const Vec2* p = std::get_if<Vec2>(&v)) return "[" + json_number(p->x) + ", " + json_number(p->y) + "]";
    const Color& c = std::get<Color>(v);
    return "[" + json_number(c.r) + ", " + json_number(c.g) + ", " + json_number(c.b) + ", " + json_number(c.a) + "]";
}

// More times than this is a typo or a script gone wrong: the answer would not fit a terminal.
constexpr std::size_t max_times = 1'000'000;

void run_sample(const SampleOptions& o) {
    std::vector<double> times;
    for (const std::string& text : o.at) times.push_back(parse_finite("sample: --at", text));
    if (times.empty()) throw Error("sample: --at needs at least one time");
    if (times.size() > max_times) throw Error("sample: --at takes at most 1000000 times (got " + std::to_string(times.size()) + ")");
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
    auto* cmd = app.add_subcommand("sample", "Print where every named animation of a scene is, and its properties' values, at the given scene times (JSON)");
    cmd->add_option("scene", options->scene, "Scene file (JSON, see docs/scene-format.md)")->required();
    cmd->add_option("--at", options->at, "Scene times in seconds, comma-separated: --at 0,0.5,1.25")
        ->required()
        ->delimiter(',');
    cmd->callback([options] { run_sample(*options); });
}

}  // namespace grape::tool
