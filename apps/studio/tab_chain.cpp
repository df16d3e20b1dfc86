// Chain: the general Witkin solver on many particles — the catalogue's pendulum chain
// (scenes::chain) or cloth strip (scenes::cloth_strip) — that the mouse can grab with the
// library's grab spring (a force, so the constraints still decide how the rest follows).
// Sub-steps per frame follow the system's stiffest mode (SubstepDef::automatic).
#include "studio.hpp"

#include <SDL.h>

#include <seed_dynamics.hpp>

#include <grape/dynamics.hpp>
#include <grape/error.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <ostream>
#include <span>
#include <vector>

namespace grape::studio {

namespace {

constexpr double chain_length = 4.0;  // metres: every chain spans the same width whatever its count
constexpr double gravity = 9.81;      // m/s²
// The mouse holds a particle like a hand as heavy as the whole chain (the grab spring is
// tuned for the chain's mass, so its weight hardly stretches it), critically damped for the
// particle itself, and never pulling harder than the chain weighs.
constexpr double grab_hertz = 25.0 / (2.0 * 3.141592653589793);  // 25 rad/s for the chain's mass
constexpr double air_drag = 0.5;      // N·s/m per particle: tames the whip of the free end
constexpr double release_angle = 0.5; // rad from the vertical: the chain starts straight, at rest

// Menu names: the library's own, in its order.
template <class E>
std::vector<const char*> names(std::span<const E> all) {
    std::vector<const char*> out;
    for (E e : all) out.push_back(to_string(e).data());  // string literals: null-terminated
    return out;
}

class ChainTab final : public Tab {
public:
    explicit ChainTab(int particles) : particles_(particles > 0 ? particles : 60) { reset(); }

    const char* name() const noexcept override { return "chain"; }
    const char* title() const noexcept override { return "Chain"; }

    void advance(double dt) override {
        const auto start = std::chrono::steady_clock::now();
        if (system_->grabbed()) system_->move_grab(mouse_);
        const StepStats r = system_->step(dt);
        status_ = r.status;
        substeps_ = r.substeps;
        step_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        link_error_ = 0.0;
        for (const ConstraintResidual& c : system_->residuals()) link_error_ = std::max(link_error_, c.distance);
    }

    void controls() override {
        ImGui::TextWrapped("Every particle and constraint solved together by the Witkin solver (J W J^T lambda = ..., "
                           "sparse for large systems). Grab any particle with the mouse.");
        ImGui::Separator();
        bool changed = false;
        static const char* kinds[] = {"pendulum chain", "cloth strip"};
        changed |= ImGui::Combo("scene", &kind_, kinds, 2);
        changed |= ImGui::SliderInt("particles", &particles_, 2, 400);
        static const std::vector<const char*> integrator_names = names(all_integrators());
        changed |= ImGui::Combo("integrator", &integrator_, integrator_names.data(), int(integrator_names.size()));
        static const std::vector<const char*> drift_names = names(all_drift_controls());
        changed |= ImGui::Combo("drift control", &drift_, drift_names.data(), int(drift_names.size()));
        if (changed) reset();
        run_button();
        ImGui::SameLine();
        if (ImGui::Button("Reset")) reset();
        ImGui::Separator();
        ImGui::Text("particles %zu   constraints %zu", system_->size(), system_->constraint_count());
        ImGui::Text("t = %.2f s   solve: %s", system_->time(), std::string(to_string(status_)).c_str());
        ImGui::Text("worst link error: %.2e m", link_error_);
        ImGui::Text("steps per frame: %d (stiffest mode w*h <= 1, w = %.0f rad/s)", substeps_, system_->stiffest_mode());
        ImGui::Text("simulation: %.2f ms per frame", step_ms_);
        ImGui::Text("energy: %.3f J", system_->energy());
    }

    void draw(ImDrawList* dl, ImVec2 min, ImVec2 max) override {
        const double reach = chain_length * 1.08;
        ViewCanvas canvas(dl, min, max, {-reach, -0.4}, {reach, reach});
        canvas.grid(0.5, color::grid);
        const auto x = system_->positions();
        const auto w = system_->inverse_masses();
        // Links: consecutive particles of the chain, or the cloth's grid.
        if (kind_ == 0) {
            std::vector<Vec2> line(x.begin(), x.end());
            canvas.polyline(line, color::path, 2.0f);
        } else {
            for (int r = 0; r < rows_; ++r)
                for (int c = 0; c < columns_; ++c) {
                    const std::size_t i = std::size_t(r * columns_ + c);
                    if (c + 1 < columns_ && r > 0) canvas.line(x[i], x[i + 1], color::path, 1.5f);
                    if (r + 1 < rows_) canvas.line(x[i], x[i + std::size_t(columns_)], color::path, 1.5f);
                }
        }
        const float radius = std::clamp(float(0.4 * canvas.scale() * chain_length / double(particles_)), 2.0f, 6.0f);
        for (std::size_t i = 0; i < x.size(); ++i)
            canvas.disc(x[i], w[i] == 0.0 ? radius + 2.0f : radius, w[i] == 0.0 ? color::ink : color::path);

        // Grab the nearest particle within 15 px; hold it until the button is released.
        const ImGuiIO& io = ImGui::GetIO();
        mouse_ = canvas.mouse();
        last_screen_ = canvas.to_screen(x.back());
        if (grabbed_ < 0 && canvas.hovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            if (const auto id = system_->nearest_particle(mouse_, 15.0 / canvas.scale())) {
                const double n = double(system_->size());
                system_->grab(*id, mouse_, {.hertz = grab_hertz, .mass = n, .max_force = n * gravity});
                grabbed_ = int(id->index);
            }
        }
        if (grabbed_ >= 0 && !io.MouseDown[0]) {
            system_->release_grab();
            grabbed_ = -1;
        }
        if (grabbed_ >= 0) {
            canvas.line(x[std::size_t(grabbed_)], mouse_, color::marker, 1.5f);
            canvas.ring(x[std::size_t(grabbed_)], radius + 5.0f, color::marker, 2.0f);
        }
        char label[96];
        std::snprintf(label, sizeof label, "%s: %zu particles, %zu constraints, %d steps per frame",
                      kind_ == 0 ? "chain" : "cloth strip", system_->size(), system_->constraint_count(), substeps_);
        dl->AddText({min.x + 10.0f, min.y + 8.0f}, color::ink, label);
    }

    void report(std::ostream& out) const override {
        const auto x = system_->positions();
        out << "particles: " << x.size() << "\nconstraints: " << system_->constraint_count()
            << "\ntime: " << system_->time() << "\nlast: " << x.back().x << ' ' << x.back().y
            << "\nlast_screen: " << last_screen_.x << ' ' << last_screen_.y << "\nmouse: " << mouse_.x << ' '
            << mouse_.y << "\ngrabbed: " << grabbed_ << "\nlink_error: " << link_error_ << "\n";
    }

private:
    void reset() {
        ParticleSystemDef def = scenes::chain_def();
        def.integrator = all_integrators()[std::size_t(integrator_)];
        def.drift = DriftDef{.method = all_drift_controls()[std::size_t(drift_)]};
        def.substeps.max = 256;  // --particles 2000: 2 mm links need ~100 sub-steps per frame
        grabbed_ = -1;
        if (kind_ == 0) {
            const std::size_t links = std::size_t(std::max(particles_ - 1, 1));
            system_.emplace(scenes::chain(links, chain_length / double(links), gravity, def, release_angle));
        } else {
            columns_ = std::clamp(int(std::lround(std::sqrt(particles_ * 2.0))), 2, particles_);
            rows_ = std::max(2, particles_ / columns_);
            spacing_ = chain_length / double(columns_ - 1) * 0.8;
            system_.emplace(scenes::cloth_strip(columns_, rows_, spacing_, gravity, def, release_angle));
        }
        system_->add_drag(air_drag);
        status_ = SolveStatus::ok;
        link_error_ = 0.0;
    }

    int particles_;
    int kind_ = 0;
    int integrator_ = int(Integrator::rattle);  // the catalogue's: links held at every step
    int drift_ = int(DriftControl::projection);  // for the others: long chains yanked by the mouse need it
    double spacing_ = 0.0;
    int substeps_ = 1;
    int columns_ = 0;
    int rows_ = 0;
    std::optional<ParticleSystem> system_;
    int grabbed_ = -1;
    Vec2 mouse_;
    ImVec2 last_screen_;  // for reports
    SolveStatus status_ = SolveStatus::ok;
    double link_error_ = 0.0;
    double step_ms_ = 0.0;
};

}  // namespace

std::unique_ptr<Tab> make_chain_tab(int particles) { return std::make_unique<ChainTab>(particles); }

}  // namespace grape::studio
