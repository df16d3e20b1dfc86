// scene: a structure-aware mutator over valid scenes. Each round takes a valid scene (the
// catalogue in scenes/, the scene fuzzer's seeds, one scene using every field) and changes its
// JSON tree a few times: a field or element dropped or duplicated, a value of another type,
// a number swapped for an extreme (±1e308, −0, the smallest denormal, a number past the
// doubles, huge integers), a huge array, deep nesting, a string from the format's own words,
// a key renamed to another field of the format. load_scene must then either load the scene
// or throw grape::Error whose message names the scene ("scene: ..."): never crash, hang or
// throw anything else (the sanitizer build runs the same rounds). What loads must save, load
// again to the same text, evaluate its animations, and start and step its simulations or
// refuse them with grape::Error.
//
// The rounds are drawn from a fixed seed and bounded in number and time; GRAPE_MUTATOR_SEED
// and GRAPE_MUTATOR_ROUNDS (environment) explore further. With GRAPE_MUTANT_DIR set, the
// scenes that loaded (the first 200) are written there, e.g. for `grape render` to draw.
#include <grape/config.hpp>
#include <grape/error.hpp>
#include <grape/scene.hpp>
#include <grape/scene_values.hpp>
#if GRAPE_HAS_DYNAMICS
#include <grape/dynamics.hpp>
#endif

#include <nlohmann/json.hpp>

#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using json = nlohmann::json;

const std::filesystem::path source_dir = GRAPE_SOURCE_DIR;

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// A scene with every kind of field, the newer ones included.
const char* const every_field = R"json({
  "grape_scene": 1, "name": "every field", "view": {"width": 320, "height": 240, "ticks": 0.1},
  "paths": [
    {"name": "loop", "path": {"kind": "catmull_rom_spline", "type": "chordal", "closed": true, "points": [[0, 0], [100, 0], [100, 100], [0, 80]]}},
    {"name": "herm", "path": {"kind": "hermite_spline", "closed": true, "points": [[0, 0], [50, 10], [20, 60]], "tangents": [[10, 0], [0, 10], [-10, 0]]}},
    {"name": "cos", "path": {"kind": "cosine_spline", "closed": true, "points": [[0, 0], [50, 10], [20, 60]]}},
    {"name": "cut", "path": {"kind": "cubic_bezier", "points": [[0, 0], [10, 50], [60, 50], [80, 0]], "slice": [0.25, 0.75], "reparametrize": true}},
    {"name": "arc", "path": {"kind": "elliptical_arc", "center": [0, 0], "rx": 40, "ry": 20, "rotation": 0.3, "slice": [0.1, 0.9]}},
    {"name": "svg", "path": {"kind": "svg", "data": "M0 0 C 10 20 30 20 40 0 A 20 20 0 1 1 0 0 Z"}},
    {"name": "all", "path": {"kind": "complex", "parts": ["loop", "cut", {"kind": "spiral", "center": [0, 0], "start_radius": 5, "end_radius": 50}], "cues": [0, 0.5, 0.75]}}
  ],
  "curves": [{"name": "soft", "curve": "cubic-bezier(0.25,0.1,0.25,1)"}],
  "animations": [
    {"name": "lane", "path": "loop", "curve": "soft", "duration": 2, "delay": 0.5, "repeat": -1, "yoyo": true, "offset": 12, "range": [0.9, 0.1]},
    {"name": "shot", "path": {"kind": "physics", "position": [0, 0], "velocity": [10, -20], "acceleration": [0, 40], "seconds": 1}, "duration": 1, "reversed": true}
  ],
  "sprites": [
    {"name": "hero", "sheet": "hero.json", "clip": "walk", "rate": -0.5, "scale": 2, "animation": "lane"},
    {"sheet": "hero.json", "frames": [0, 3], "at": [10, 20]}
  ],
  "simulations": [
    {"name": "chain", "integrator": "rk45", "drift": "projection", "dt": 0.01, "duration": 0.05,
     "particles": [{"position": [0, 0], "mass": "pinned"}, {"position": [10, 0]}, {"position": [20, 0], "velocity": [0, 1], "mass": 2}],
     "forces": [{"kind": "gravity", "acceleration": [0, 500]}, {"kind": "drag", "k": 0.1},
                {"kind": "spring", "a": 1, "b": 2, "rest_length": 10, "stiffness": 5, "damping": 0.5}],
     "constraints": [{"kind": "distance", "a": 0, "b": 1}, {"kind": "anchor", "a": 2, "point": [20, -30], "length": 30},
                     {"kind": "fixed_point", "a": 0, "point": [0, 0]}, {"kind": "conic", "a": 1, "coefficients": [1, 0, 1, 0, 0, -100]}]}
  ]
})json";

std::vector<json> seed_scenes() {
    std::vector<json> seeds{json::parse(every_field)};
    for (const auto& folder : {source_dir / "scenes", source_dir / "fuzz" / "corpus" / "scene"}) {
        for (const auto& entry : std::filesystem::directory_iterator(folder)) {
            if (!entry.is_regular_file()) continue;
            if (folder.filename() == "scenes" && entry.path().extension() != ".json") continue;
            const json j = json::parse(read_text(entry.path()), nullptr, false);
            if (!j.is_discarded()) seeds.push_back(j);  // the corpus holds broken JSON on purpose
        }
    }
    return seeds;
}

// Every value's pointer in the document (the root excluded); of a long array only the first
// and last 8 elements (after a huge-array mutation the places stay few).
void collect(const json& j, const json::json_pointer& at, std::vector<json::json_pointer>& out) {
    if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it) {
            out.push_back(at / it.key());
            collect(*it, at / it.key(), out);
        }
    } else if (j.is_array()) {
        for (std::size_t i = 0; i < j.size(); ++i) {
            if (i == 8 && j.size() > 16) i = j.size() - 8;
            out.push_back(at / i);
            collect(j[i], at / i, out);
        }
    }
}

// The format's own words: keys and strings a mutation may put anywhere.
const std::vector<std::string> words = {
    "kind", "name", "path", "paths", "points", "tangents", "type", "closed", "slice", "range", "offset", "cues",
    "parts", "reparametrize", "data", "curve", "duration", "delay", "repeat", "yoyo", "reversed", "sheet", "clip",
    "frames", "rate", "scale", "animation", "at", "particles", "forces", "constraints", "mass", "position", "velocity",
    "a", "b", "length", "point", "coefficients", "integrator", "drift", "dt", "view", "width", "height", "ticks",
    "linear", "circle", "elliptical_arc", "spiral", "sine_wave", "quadratic_bezier", "cubic_bezier", "linear_spline",
    "cosine_spline", "hermite_spline", "catmull_rom_spline", "physics", "svg", "complex", "by_length", "pinned",
    "gravity", "spring", "distance", "anchor", "fixed_point", "conic", "rk45", "projection", "baumgarte", "none",
    "back-out(2.5)", "steps(0,jump-none)", "monotone(0,0,1,1)", "cubic-bezier(0,9,1,-9)", "loop", "lane", "all", "",
    "M0 0", "M0 0 L", "M 98 0 A 49 49 0 1 1 0 0", "uniform", "centripetal", "chordal",
    "properties", "tweens", "tween", "property", "from", "to", "by", "space", "turn", "unit", "time_scale", "number",
    "angle", "vec2", "color", "oklab", "every", "degrees", "#ff000080", "rgb(0 0 255 / 50%)", "tint"};

// Placeholders for numbers JSON text can hold but a JSON library would not write.
const std::string beyond_doubles = "\"@@1e999@@\"";

json extreme(std::mt19937_64& rng) {
    static const std::vector<json> values = {
        1e308, -1e308, -0.0, 0, 5e-324, 1e-310, std::numeric_limits<double>::max(), 1e300, -1e300, 9e15, -1,
        9007199254740993ULL, 4294967296LL, -2147483649LL, 0.5, 1e-300, 1e150, 1e7, 100000001, "@@1e999@@"};
    return values[rng() % values.size()];
}

json other_type(std::mt19937_64& rng) {
    static const std::vector<json> values = {nullptr, true, false, "text", json::array(), json::object(), 0, 1,
                                             json::array({1, 2}), json::array({json::array({0, 0})}),
                                             json{{"kind", "linear"}}, json::array({json::array({0, 0}), json::array({1, 1}), json::array({2, 0})})};
    return values[rng() % values.size()];
}

json nested(json inner, int depth, bool as_paths) {
    for (int i = 0; i < depth; ++i)
        inner = as_paths ? json{{"kind", "complex"}, {"parts", json::array({inner})}} : json::array({inner});
    return inner;
}

// One structural change at a random place.
void mutate(json& doc, std::mt19937_64& rng) {
    std::vector<json::json_pointer> at;
    collect(doc, json::json_pointer(), at);
    if (at.empty()) {
        doc[words[rng() % words.size()]] = other_type(rng);
        return;
    }
    const json::json_pointer p = at[rng() % at.size()];
    json& value = doc[p];
    json& parent = doc[p.parent_pointer()];
    switch (rng() % 9) {
        case 0:  // drop it
            if (parent.is_object()) parent.erase(p.back());
            else parent.erase(parent.begin() + static_cast<std::ptrdiff_t>(std::stoull(p.back())));
            break;
        case 1:  // duplicate it (in an array), or copy it under another key
            if (parent.is_array()) parent.insert(parent.begin() + static_cast<std::ptrdiff_t>(std::stoull(p.back())), value);
            else parent[words[rng() % words.size()]] = value;
            break;
        case 2: value = other_type(rng); break;
        case 3: {  // a number swapped for an extreme (the nearest number below, if this is none)
            std::vector<json::json_pointer> numbers;
            for (const auto& q : at)
                if (doc[q].is_number()) numbers.push_back(q);
            if (numbers.empty()) value = extreme(rng);
            else doc[numbers[rng() % numbers.size()]] = extreme(rng);
            break;
        }
        case 4: {  // a huge array of what it holds
            const json element = value.is_array() && !value.empty() ? value[0] : value;
            value = json::array();
            // Up to 20000 copies, and at most ~2 MB of them (a huge array of huge arrays would
            // test only the JSON parser's memory).
            const std::size_t n = std::min<std::size_t>(rng() % 2 == 0 ? 20000 : 1000, 2000000 / (element.dump().size() + 1));
            for (std::size_t i = 0; i < n; ++i) value.push_back(element);
            break;
        }
        case 5: value = nested(value, 1 + static_cast<int>(rng() % 64), rng() % 2 == 0); break;
        case 6: value = words[rng() % words.size()]; break;
        case 7:  // a key renamed to another field of the format
            if (parent.is_object()) {
                json moved = value;
                const std::string key = p.back();
                parent.erase(key);
                parent[words[rng() % words.size()]] = std::move(moved);
            }
            break;
        default:  // a new field from the format's words
            if (value.is_object()) value[words[rng() % words.size()]] = rng() % 2 == 0 ? extreme(rng) : other_type(rng);
            else value = extreme(rng);
            break;
    }
}

std::string text_of(const json& doc) {
    std::string text = doc.dump();
    for (std::size_t at = text.find(beyond_doubles); at != std::string::npos; at = text.find(beyond_doubles, at))
        text.replace(at, beyond_doubles.size(), "1e999");
    return text;
}

std::uint64_t env_number(const char* name, std::uint64_t fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

// What a loaded scene must do without trapping.
void exercise(const grape::Scene& scene, const std::string& text) {
    const std::string saved = grape::save_scene(scene);
    grape::Scene again;
    try {
        again = grape::load_scene(saved);
    } catch (const grape::Error& e) {
        FAIL() << "the saved scene does not load: " << e.what() << "\nmutant: " << text.substr(0, 2000);
    }
    ASSERT_EQ(grape::save_scene(again), saved) << "mutant: " << text.substr(0, 2000);
    for (const grape::SceneAnimation& a : scene.animations)
        for (double t : {0.0, 0.5 * a.duration, a.delay + a.duration, 1e9, 1e300}) (void)a.position(t);
    if (!scene.properties.empty()) {
        const grape::SceneProperties values(scene, grape::SceneTiming(scene));
        for (std::size_t k = 0; k < values.property_count(); ++k)
            for (double t : {0.0, 0.75, 3.0, 1e9, 1e300}) (void)values.value(k, t);
    }
#if GRAPE_HAS_DYNAMICS
    for (const grape::SceneSimulation& s : scene.simulations) {
        try {
            grape::ParticleSystem system = grape::make_particle_system(s);
            // rk45's guard at 2,000 sub-steps per step instead of 10⁵: a stiff mutant (a spring
            // damped at 9e15) reaches either guard the same way, and at 10⁵ it took a second
            // here and a minute under the sanitizers.
            if (s.integrator == "rk45") system.set_rk45({.max_substeps = 2000});
            for (int k = 0; k < 3; ++k) {
                const grape::StepStats report = system.step(s.dt);
                // A step that reports ok leaves the state finite.
                if (report.status != grape::SolveStatus::ok) continue;
                for (grape::Vec2 p : system.positions()) {
                    ASSERT_TRUE(grape::is_finite(p)) << "mutant: " << text.substr(0, 2000);
                }
            }
        } catch (const grape::Error&) {
            // refused with a reason: fine
        }
    }
#endif
}

TEST(SceneMutator, LoadsOrRefusesEveryMutant) {
    const std::vector<json> seeds = seed_scenes();
    ASSERT_GE(seeds.size(), 10u);
    const std::uint64_t seed = env_number("GRAPE_MUTATOR_SEED", 18);
    const std::uint64_t rounds = env_number("GRAPE_MUTATOR_ROUNDS", 4000);
    // A bounded time as well as a bounded count: the sanitizer build is ~10x slower.
    const auto budget = std::chrono::seconds(env_number("GRAPE_MUTATOR_SECONDS", 60));
    const char* mutant_dir = std::getenv("GRAPE_MUTANT_DIR");
    const char* trace = std::getenv("GRAPE_MUTATOR_TRACE");  // "1": each round on stderr, "dump": also its text
    std::mt19937_64 rng(grape::testing::test_seed(seed));
    const auto start = std::chrono::steady_clock::now();
    std::uint64_t ran = 0, loaded = 0, refused = 0, written = 0;
    for (; ran < rounds && std::chrono::steady_clock::now() - start < budget; ++ran) {
        json doc = seeds[rng() % seeds.size()];
        // Mostly one change (so that many mutants still load and go on to be drawn and run),
        // sometimes up to four.
        const int changes = rng() % 4 == 0 ? 2 + static_cast<int>(rng() % 3) : 1;
        for (int c = 0; c < changes; ++c) mutate(doc, rng);
        const std::string text = text_of(doc);
        if (trace) std::fprintf(stderr, "round %llu: %zu bytes\n", static_cast<unsigned long long>(ran), text.size());
        if (trace && std::string(trace) == "dump") std::ofstream("mutant-last.json") << text;
        grape::Scene scene;
        try {
            scene = grape::load_scene(text);
        } catch (const grape::Error& e) {
            ++refused;
            // "scene: /pointer: reason": the pointer of the value at fault, never an internal name.
            EXPECT_EQ(std::string(e.what()).rfind("scene: /", 0), 0u) << e.what() << "\nmutant: " << text.substr(0, 2000);
            continue;
        } catch (const std::exception& e) {
            FAIL() << "not a grape::Error: " << e.what() << "\nround " << ran << " mutant: " << text.substr(0, 2000);
        }
        ++loaded;
        exercise(scene, text);
        if (::testing::Test::HasFatalFailure()) return;
        if (mutant_dir && written < 200) {
            std::ofstream(std::filesystem::path(mutant_dir) / ("mutant-" + std::to_string(written++) + ".json")) << text;
        }
    }
    std::printf("seed %llu: %llu mutants, %llu loaded, %llu refused\n", static_cast<unsigned long long>(seed),
                static_cast<unsigned long long>(ran), static_cast<unsigned long long>(loaded),
                static_cast<unsigned long long>(refused));
    // The rounds ran, and both outcomes occur (a mutator that breaks everything, or nothing,
    // tests little).
    EXPECT_GE(ran, 100u);
    EXPECT_GT(loaded, ran / 20);
    EXPECT_GT(refused, ran / 20);
}

}  // namespace
