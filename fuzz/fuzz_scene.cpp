// libFuzzer target for grape::load_scene: any byte string either loads or throws grape::Error
// whose message starts "scene: " (a JSON pointer or a syntax error follows). A loaded scene
// must save, load again and save to the same text (the round trip), its animations must
// evaluate without trapping, and its simulations must step or be refused. Anything else (a
// crash, a sanitizer report, another exception, a broken round trip) is a finding.
#include <grape/config.hpp>
#include <grape/error.hpp>
#include <grape/scene.hpp>
#include <grape/scene_values.hpp>
#if GRAPE_HAS_DYNAMICS
#include <grape/dynamics.hpp>
#endif

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

void require(bool condition) {
    if (!condition) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    grape::Scene scene;
    try {
        scene = grape::load_scene(text);
    } catch (const grape::Error& e) {
        require(std::string_view(e.what()).substr(0, 7) == "scene: ");
        return 0;
    }
    const std::string saved = grape::save_scene(scene);
    const grape::Scene again = grape::load_scene(saved);  // must not throw
    require(grape::save_scene(again) == saved);
    for (const grape::SceneAnimation& a : scene.animations)
        for (double t : {0.0, 0.5 * a.duration, a.delay + a.duration, 1e9}) (void)a.position(t);
    if (!scene.properties.empty()) {  // properties evaluate at any time, NaN included
        const grape::SceneProperties values(scene, grape::SceneTiming(scene));
        for (std::size_t k = 0; k < values.property_count(); ++k)
            for (double t : {-1.0, 0.0, 0.3, 1.7, 1e9, std::nan("")}) (void)values.value(k, t);
    }
#if GRAPE_HAS_DYNAMICS
    // Simulations start and take a few steps, or are refused with grape::Error; a step that
    // reports ok leaves every particle finite (degenerate starts were flung to 1e152 before).
    for (const grape::SceneSimulation& s : scene.simulations) {
        try {
            grape::ParticleSystem system = grape::make_particle_system(s);
            for (int k = 0; k < 3; ++k) {
                if (system.step(s.dt).status != grape::SolveStatus::ok) continue;
                for (grape::Vec2 p : system.positions()) require(grape::is_finite(p));
            }
        } catch (const grape::Error&) {
        }
    }
#endif
    return 0;
}
