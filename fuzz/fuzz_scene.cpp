// libFuzzer target for grape::load_scene: any byte string either loads or throws grape::Error
// whose message starts "scene: " (a JSON pointer or a syntax error follows). A loaded scene
// must save, load again and save to the same text (the round trip), and its animations must
// evaluate without trapping. Anything else (a crash, a sanitizer report, another exception,
// a broken round trip) is a finding.
#include <grape/error.hpp>
#include <grape/scene.hpp>

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
    return 0;
}
