// `grape simulate parabola ...`: the seed's bead on x² + 100y = 0 by any method, integrator
// and drift control, as JSON (and optionally a CSV of every step); and the demo's drift
// table and seed-formula comparison.
#include "commands.hpp"
#include "json_out.hpp"
#include "progress.hpp"

#include <grape/dynamics.hpp>
#include <grape/error.hpp>

#include <seed_dynamics.hpp>

#include "atomic_file.hpp"
#include "utf8_path.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

namespace grape::tool {
namespace {

struct SimulateOptions {
    std::string method = "implicit";
    std::string integrator = "rk4";
    std::string dt = "0.016666666666666666";
    std::string seconds = "10";
    std::string x0 = "100";
    std::string g = "500";
    std::string force_x = "0";
    std::string stabilize = "none";
    std::string omega_dt = "0.05";
    std::string csv;
};

std::string quoted(std::string_view text) { return "\"" + std::string(text) + "\""; }

// Limits of the options (stated in --help).
constexpr double max_abs_x0 = 1e150;    // x0² stays far from overflow
constexpr double max_abs_g = 1e150;     // and so do g·x0 and the forces
constexpr double max_omega_dt = 1.0;    // Baumgarte gain per step

void run_simulate(const SimulateOptions& o) {
    scenes::ParabolaSetup setup;
    setup.method = scenes::parse_parabola_method(o.method);
    setup.integrator = parse_integrator(o.integrator);
    const double dt = parse_finite("simulate: --dt", o.dt);
    const double seconds = parse_finite("simulate: --seconds", o.seconds);
    setup.x0 = parse_finite("simulate: --x0", o.x0);
    setup.g = parse_finite("simulate: --g", o.g);
    setup.force_x = parse_finite("simulate: --force-x", o.force_x);
    setup.drift.method = parse_drift_control(o.stabilize);
    setup.drift.omega_dt = parse_finite("simulate: --omega-dt", o.omega_dt);
    if (!(dt > 0.0)) throw Error("simulate: --dt must be positive (got " + o.dt + ")");
    if (!(seconds >= 0.0)) throw Error("simulate: --seconds must be ≥ 0 (got " + o.seconds + ")");
    if (seconds / dt > 1e8) throw Error("simulate: --seconds/--dt must be at most 1e8 steps (got " + json_number(seconds / dt) + ")");
    if (!(setup.drift.omega_dt > 0.0)) throw Error("simulate: --omega-dt must be positive (got " + o.omega_dt + ")");
    if (setup.method != scenes::ParabolaMethod::implicit && setup.drift.method != DriftControl::none)
        throw Error("simulate: --stabilize applies to --method implicit only (got --method " + o.method + ")");

    // The release point (x0, −x0²/100) and its energy m·g·x0²/100 must stay finite.
    if (!(std::abs(setup.x0) <= max_abs_x0))
        throw Error("simulate: --x0 must lie in [-1e150, 1e150] (got " + o.x0 + ")");
    if (!(std::abs(setup.g) <= max_abs_g)) throw Error("simulate: --g must lie in [-1e150, 1e150] (got " + o.g + ")");
    if (!(std::abs(setup.force_x) <= max_abs_g))
        throw Error("simulate: --force-x must lie in [-1e150, 1e150] (got " + o.force_x + ")");
    if (setup.drift.omega_dt > max_omega_dt)
        throw Error("simulate: --omega-dt must be in (0, 1] (got " + o.omega_dt +
                    "): a larger gain overshoots the constraint within one step");
    const double steps = std::ceil(seconds / dt);

    std::optional<detail::AtomicFile> csv;
    if (!o.csv.empty()) {
        csv.emplace(detail::path_from_utf8(o.csv));
        csv->write("t,x,y,vx,vy,residual,energy\n");
    }
    auto write_row = [&csv](const scenes::ParabolaState& s) {
        csv->write(json_number(s.t) + ',' + json_number(s.x.x) + ',' + json_number(s.x.y) + ',' + json_number(s.v.x) + ',' +
                   json_number(s.v.y) + ',' + json_number(s.residual) + ',' + json_number(s.energy) + '\n');
    };
    // A state that leaves the finite range is refused at the step it happens: NaN would
    // otherwise print as null with a successful exit.
    auto check_finite = [&](const scenes::ParabolaState& s, double step) {
        if (!s.finite || !is_finite(s.x) || !is_finite(s.v) || !std::isfinite(s.energy))
            throw Error("simulate: the state left the finite range at step " + detail::number_text(step) + " (t = " +
                        detail::number_text(s.t) + " s, x = (" + detail::number_text(s.x.x) + ", " +
                        detail::number_text(s.x.y) + "), energy " + detail::number_text(s.energy) +
                        "); try a smaller --dt, --g or --force-x");
    };
    const scenes::ParabolaState start = scenes::ParabolaRun(setup).state();
    check_finite(start, 0);
    if (csv) write_row(start);
    Progress progress("simulate: step", steps);
    double step = 0;
    const auto summary = scenes::run_parabola(setup, dt, seconds, [&](const scenes::ParabolaState& s) {
        check_finite(s, ++step);
        if (csv) write_row(s);
        progress.update(step);
    });
    progress.done();
    if (csv) csv->commit();
    const auto& f = summary.final;
    std::cout << "{\"method\": " << quoted(to_string(setup.method)) << ", \"integrator\": " << quoted(to_string(setup.integrator))
              << ", \"stabilize\": " << quoted(to_string(setup.drift.method)) << ", \"dt\": " << json_number(dt)
              << ", \"seconds\": " << json_number(f.t) << ", \"x\": " << json_number(f.x.x) << ", \"y\": " << json_number(f.x.y)
              << ", \"vx\": " << json_number(f.v.x) << ", \"vy\": " << json_number(f.v.y)
              << ", \"max_residual\": " << json_number(summary.max_residual)
              << ", \"max_distance\": " << json_number(summary.max_distance)
              << ", \"initial_energy\": " << json_number(summary.initial.energy)
              << ", \"final_energy\": " << json_number(f.energy) << "}\n";
}

}  // namespace

void register_simulate_command(CLI::App& app) {
    auto* simulate = app.add_subcommand("simulate", "Constrained dynamics simulations");
    simulate->require_subcommand(1);
    auto* parabola = simulate->add_subcommand(
        "parabola",
        "The seed's bead on x² + 100y = 0 released from rest at x0 (y down, gravity m·g·(0, 1), m = 1). Prints "
        "the final state, max |C| and distance over the run, initial and final energy as JSON");
    auto o = std::make_shared<SimulateOptions>();
    parabola->add_option("--method", o->method, "implicit (Witkin solver), parametric (generalized coordinate) or seed (the seed's closed form as written)")
        ->capture_default_str();
    parabola->add_option("--integrator", o->integrator, "euler, symplectic, midpoint, rk4, verlet or rk45")->capture_default_str();
    parabola->add_option("--dt", o->dt, "Step in seconds; --seconds/--dt is at most 1e8 steps (progress on stderr when it is a terminal)")->capture_default_str();
    parabola->add_option("--seconds", o->seconds, "Simulated time")->capture_default_str();
    parabola->add_option("--x0", o->x0, "Release point x (px), |x0| ≤ 1e150")->capture_default_str();
    parabola->add_option("--g", o->g, "Gravity (px/s², along +y), |g| ≤ 1e150")->capture_default_str();
    parabola->add_option("--force-x", o->force_x, "Constant sideways force (potential −F·x), |F| ≤ 1e150")->capture_default_str();
    parabola->add_option("--stabilize", o->stabilize, "Drift control of the implicit method: none, baumgarte or projection")
        ->capture_default_str();
    parabola->add_option("--omega-dt", o->omega_dt, "Baumgarte gain ω·dt in (0, 1] (ks = ω², kd = 2ω)")->capture_default_str();
    parabola->add_option("--csv", o->csv, "Also write t, x, y, vx, vy, residual, energy per step to this file (written whole or not at all)");
    parabola->callback([o] { run_simulate(*o); });
}

void demo_dynamics(const DemoContext& context) {
    std::ostream& out = context.out;
    char line[200];
    out << "\nDynamics: the seed's parabola x² + 100y = 0, x0 = 100, g = 500, dt = 1/60 (drift over 60 s | 600 s)\n";
    std::snprintf(line, sizeof line, "  %-10s %-20s %-10s | %10s %10s %10s | %10s %10s %10s\n", "method", "integrator", "drift",
                  "max|C|", "max dist", "dE/E", "max|C|", "max dist", "dE/E");
    out << line;
    const double dt = 1.0 / 60;
    for (auto method : {scenes::ParabolaMethod::implicit, scenes::ParabolaMethod::parametric}) {
        for (Integrator integrator : {Integrator::euler, Integrator::semi_implicit_euler, Integrator::midpoint,
                                      Integrator::rk4, Integrator::velocity_verlet, Integrator::rk45}) {
            for (DriftControl drift : {DriftControl::none, DriftControl::baumgarte, DriftControl::projection}) {
                if (method == scenes::ParabolaMethod::parametric && drift != DriftControl::none) continue;
                scenes::ParabolaSetup setup{.method = method, .integrator = integrator};
                setup.drift.method = drift;
                const auto a = scenes::run_parabola(setup, dt, 60.0);
                const auto b = scenes::run_parabola(setup, dt, 600.0);
                auto rel = [](const scenes::ParabolaSummary& s) { return (s.final.energy - s.initial.energy) / s.initial.energy; };
                std::snprintf(line, sizeof line, "  %-10s %-20s %-10s | %10.3g %10.3g %10.3g | %10.3g %10.3g %10.3g\n",
                              std::string(to_string(method)).c_str(), std::string(to_string(integrator)).c_str(),
                              method == scenes::ParabolaMethod::parametric ? "-" : std::string(to_string(drift)).c_str(),
                              a.max_residual, a.max_distance, rel(a), b.max_residual, b.max_distance, rel(b));
                out << line;
            }
        }
    }
    out << "\nThe seed's closed-form force vs the solver under a sideways force of 100 (RK4, dt = 1/240, 5 s)\n";
    out << "  the seed's Fc.y has −100·x·Fext.x where Jᵀλ gives −50·x·Fext.x: it leaves C̈ = −2·x·Fext.x/m\n";
    for (auto method : {scenes::ParabolaMethod::seed, scenes::ParabolaMethod::implicit}) {
        for (DriftControl drift : {DriftControl::none, DriftControl::projection}) {
            if (method == scenes::ParabolaMethod::seed && drift != DriftControl::none) continue;
            scenes::ParabolaSetup setup{.method = method, .force_x = 100.0};
            setup.drift.method = drift;
            const auto s = scenes::run_parabola(setup, 1.0 / 240, 5.0);
            std::snprintf(line, sizeof line, "  %-28s max distance from the curve %10.3g px, dE/E %10.3g\n",
                          (std::string(method == scenes::ParabolaMethod::seed ? "seed's formula" : "Witkin solver") +
                           (method == scenes::ParabolaMethod::implicit ? " (" + std::string(to_string(drift)) + ")" : ""))
                              .c_str(),
                          s.max_distance, (s.final.energy - s.initial.energy) / s.initial.energy);
            out << line;
        }
    }
}

}  // namespace grape::tool
