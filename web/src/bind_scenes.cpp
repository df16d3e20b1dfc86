// The catalogue's parabola for JavaScript: the seed's bead on x² + 100y = 0 by the same code
// as `grape simulate parabola`, so the page's figures can be checked against the tool's.
#include "web_util.hpp"

#include <seed_dynamics.hpp>

#include <emscripten/bind.h>

#include <string>

namespace grape::web {
namespace {

scenes::ParabolaSetup parabola_setup(const val& o) {
    const char* where = "parabola";
    scenes::ParabolaSetup setup;
    if (has(o, "method")) setup.method = scenes::parse_parabola_method(string_or(o, "method", "", where));
    if (has(o, "integrator")) setup.integrator = parse_integrator(string_or(o, "integrator", "", where));
    setup.x0 = number_or(o, "x0", setup.x0, where);
    setup.g = number_or(o, "g", setup.g, where);
    setup.mass = number_or(o, "mass", setup.mass, where);
    setup.force_x = number_or(o, "forceX", setup.force_x, where);
    if (has(o, "stabilize")) setup.drift.method = parse_drift_control(string_or(o, "stabilize", "", where));
    setup.drift.omega_dt = number_or(o, "omegaDt", setup.drift.omega_dt, where);
    return setup;
}

val state_object(const scenes::ParabolaState& s) {
    val out = val::object();
    out.set("t", s.t);
    out.set("x", s.x.x);
    out.set("y", s.x.y);
    out.set("vx", s.v.x);
    out.set("vy", s.v.y);
    out.set("residual", s.residual);
    out.set("distance", s.distance);
    out.set("energy", s.energy);
    return out;
}

scenes::ParabolaRun* make_run(val options) {
    std::string message;
    try {
        return new scenes::ParabolaRun(parabola_setup(options));
    } catch (const std::exception& e) {
        message = e.what();
    }
    throw_js(message);
}
scenes::ParabolaRun* make_default_run() { return make_run(val::undefined()); }
void step(scenes::ParabolaRun& r, double dt) { r.step(dt); }
val state(const scenes::ParabolaRun& r) { return state_object(r.state()); }

// The tool's JSON fields for the same run (`grape simulate parabola`), plus max_energy_error.
val run(val options, double dt, double seconds) {
    const scenes::ParabolaSetup setup = parabola_setup(options);
    const scenes::ParabolaSummary s = scenes::run_parabola(setup, dt, seconds);
    val out = val::object();
    out.set("method", std::string(to_string(setup.method)));
    out.set("integrator", std::string(to_string(setup.integrator)));
    out.set("stabilize", std::string(to_string(setup.drift.method)));
    out.set("dt", dt);
    out.set("seconds", s.final.t);
    out.set("x", s.final.x.x);
    out.set("y", s.final.x.y);
    out.set("vx", s.final.v.x);
    out.set("vy", s.final.v.y);
    out.set("max_residual", s.max_residual);
    out.set("max_distance", s.max_distance);
    out.set("initial_energy", s.initial.energy);
    out.set("final_energy", s.final.energy);
    out.set("max_energy_error", s.max_energy_error);
    return out;
}

}  // namespace

EMSCRIPTEN_BINDINGS(grape_scenes) {
    using namespace emscripten;
    class_<scenes::ParabolaRun>("ParabolaRun")
        .constructor(&make_run, allow_raw_pointers())
        .constructor(&make_default_run, allow_raw_pointers())
        .function("step", guarded<&step>)
        .function("state", guarded<&state>);
    function("runParabola", guarded<&run>);
}

}  // namespace grape::web
