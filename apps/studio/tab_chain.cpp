// Chain: the general Witkin solver on many particles — a pendulum chain (the catalogue's
// scenes::chain) or a cloth strip hanging from its top row — that the mouse can grab. A
// grabbed particle is pulled by a critically damped spring to the mouse (an exerted force,
// so the constraints still decide how the rest follows).
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

namespace grape::studio {

namespace {

constexpr double chain_length = 4.0;  // metres: every chain spans the same width whatever its count
constexpr double gravity = 9.81;      // m/s²
// The mouse holds a particle like a hand as heavy as the whole chain: k = ω²·n, so the chain's
// weight hardly stretches the spring; critically damped for the particle itself.
constexpr double grab_omega = 25.0;   // rad/s
constexpr double air_drag = 0.5;      // N·s/m per particle: tames the whip of the free end
constexpr double release_angle = 0.5; // rad from the vertical: the chain starts straight, at rest

// Steps per frame for explicit integrators: n links of a hanging length under tension T have
// transverse modes up to ω ≈ 2·√(T·n/(m·length)). The weight gives T = n·m·g; the mouse may
// add up to one more chain weight (its force is capped at that), and a yank more still, so
// the estimate takes 3·n·m·g. RK4 with projection stays stable for ω·h ≤ 0.7 (measured:
// 60 to 400 particles, the free end grabbed and pulled up, 10 s).
int substeps_for(int n, double length, double frame_dt) {
    const double omega_max = 2.0 * std::sqrt(3.0) * n * std::sqrt(gravity / length);
    return std::clamp(int(std::ceil(omega_max * frame_dt / 0.7)), 1, 64);
}

constexpr std::array<Integrator, 6> integrators{Integrator::euler,    Integrator::semi_implicit_euler,
                                                Integrator::midpoint, Integrator::rk4,
                                                Integrator::velocity_verlet, Integrator::rk45};

// A strip of cloth: columns × rows unit masses, `spacing` apart, the top row pinned, held by
// distance constraints along rows and columns, released sheared to one side.
ParticleSystem cloth_strip(int columns, int rows, double spacing, const ParticleSystemDef& def) {
    ParticleSystem system(def);
    std::vector<ParticleId> ids;
    const double x0 = -0.5 * spacing * (columns - 1);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c)
            // Sheared by the release angle (every link keeps its length), so it starts swinging.
            ids.push_back(system.add_particle({.position = {x0 + (c + r * std::sin(release_angle)) * spacing,
                                                            r * std::cos(release_angle) * spacing},
                                               .mass = r == 0 ? std::numeric_limits<double>::infinity() : 1.0}));
    auto at = [&](int c, int r) { return ids[std::size_t(r * columns + c)]; };
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            if (c + 1 < columns && r > 0) system.add_distance(at(c, r), at(c + 1, r), spacing);
            if (r + 1 < rows) system.add_distance(at(c, r), at(c, r + 1), spacing);
        }
    system.add_gravity({0.0, gravity});
    return system;
}

class ChainTab final : public Tab {
public:
    explicit ChainTab(int particles) : particles_(particles > 0 ? particles : 60) { reset(); }

    const char* name() const noexcept override { return "chain"; }
    const char* title() const noexcept override { return "Chain"; }

    void on_event(const SDL_Event& e) override {
        // Space runs and pauses, unless a text field has the keyboard.
        if (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_SPACE && !e.key.repeat && !ImGui::GetIO().WantTextInput)
            running_ = !running_;
    }

    void advance(double dt) override {
        if (!running_) return;
        const auto start = std::chrono::steady_clock::now();
        const int substeps = kind_ == 0 ? substeps_for(particles_, chain_length, dt)
                                        : substeps_for(rows_, (rows_ - 1) * spacing_, dt);
        substeps_ = substeps;
        const double h = dt / substeps;
        for (int i = 0; i < substeps; ++i) {
            if (grabbed_ >= 0) {
                const ParticleId id{std::uint32_t(grabbed_)};
                const Vec2 x = system_->position(id);
                const Vec2 v = system_->velocity(id);
                // Stiff enough to hold the chain's weight, its own frequency kept at ω·h ≤ 0.3,
                // and never pulling harder than the chain weighs (see substeps_for).
                const double n = double(system_->size());
                const double omega = std::min(grab_omega * std::sqrt(n), 0.3 / h);
                Vec2 force = (mouse_ - x) * (omega * omega) - v * (2.0 * omega);
                const double cap = n * gravity;
                if (length(force) > cap) force = normalized(force) * cap;
                system_->exert_force(id, force);
            }
            const StepReport r = system_->step(h);
            status_ = r.status;
        }
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
        static const char* names[] = {"euler", "semi-implicit euler", "midpoint", "rk4", "velocity verlet", "rk45"};
        changed |= ImGui::Combo("integrator", &integrator_, names, int(integrators.size()));
        static const char* drifts[] = {"none", "feedback ks, kd (Baumgarte)", "projection"};
        changed |= ImGui::Combo("drift control", &drift_, drifts, 3);
        if (changed) reset();
        if (ImGui::Button(running_ ? "Pause" : "Run")) running_ = !running_;
        ImGui::SameLine();
        if (ImGui::Button("Reset")) reset();
        ImGui::Separator();
        ImGui::Text("particles %zu   constraints %zu", system_->size(), system_->constraint_count());
        ImGui::Text("t = %.2f s   solve: %s", system_->time(), std::string(to_string(status_)).c_str());
        ImGui::Text("worst link error: %.2e m", link_error_);
        ImGui::Text("steps per frame: %d (stiffest mode w*h <= 0.7)", substeps_);
        ImGui::Text("simulation: %.2f ms per frame", step_ms_);
        ImGui::Text("energy: %.3f J", system_->energy());
    }

    void draw(ImDrawList* dl, ImVec2 min, ImVec2 max) override {
        const double reach = chain_length * 1.08;
        Canvas canvas(dl, min, max, {-reach, -0.4}, {reach, reach});
        canvas.grid(0.5, colour::grid);
        const auto x = system_->positions();
        const auto w = system_->inverse_masses();
        // Links: consecutive particles of the chain, or the cloth's grid.
        if (kind_ == 0) {
            std::vector<Vec2> line(x.begin(), x.end());
            canvas.polyline(line, colour::path, 2.0f);
        } else {
            for (int r = 0; r < rows_; ++r)
                for (int c = 0; c < columns_; ++c) {
                    const std::size_t i = std::size_t(r * columns_ + c);
                    if (c + 1 < columns_ && r > 0) canvas.line(x[i], x[i + 1], colour::path, 1.5f);
                    if (r + 1 < rows_) canvas.line(x[i], x[i + std::size_t(columns_)], colour::path, 1.5f);
                }
        }
        const float radius = std::clamp(float(0.4 * canvas.scale() * chain_length / double(particles_)), 2.0f, 6.0f);
        for (std::size_t i = 0; i < x.size(); ++i)
            canvas.disc(x[i], w[i] == 0.0 ? radius + 2.0f : radius, w[i] == 0.0 ? colour::ink : colour::path);

        // Grab the nearest particle within 15 px; hold it until the button is released.
        const ImGuiIO& io = ImGui::GetIO();
        mouse_ = canvas.mouse();
        last_screen_ = canvas.to_screen(x.back());
        if (grabbed_ < 0 && canvas.hovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            double best = 15.0 / canvas.scale();
            for (std::size_t i = 0; i < x.size(); ++i)
                if (w[i] > 0.0 && distance(x[i], mouse_) < best) {
                    best = distance(x[i], mouse_);
                    grabbed_ = int(i);
                }
        }
        if (grabbed_ >= 0 && !io.MouseDown[0]) grabbed_ = -1;
        if (grabbed_ >= 0) {
            canvas.line(x[std::size_t(grabbed_)], mouse_, colour::marker, 1.5f);
            canvas.ring(x[std::size_t(grabbed_)], radius + 5.0f, colour::marker, 2.0f);
        }
        char label[96];
        std::snprintf(label, sizeof label, "%s: %zu particles, %zu constraints, %d steps per frame",
                      kind_ == 0 ? "chain" : "cloth strip", system_->size(), system_->constraint_count(), substeps_);
        dl->AddText({min.x + 10.0f, min.y + 8.0f}, colour::ink, label);
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
        const ParticleSystemDef def{
            .integrator = integrators[std::size_t(integrator_)],
            .drift = DriftDef{.method = drift_ == 0 ? DriftControl::none
                                      : drift_ == 1 ? DriftControl::baumgarte : DriftControl::projection}};
        grabbed_ = -1;
        if (kind_ == 0) {
            const std::size_t links = std::size_t(std::max(particles_ - 1, 1));
            const double link = chain_length / double(links);
            system_.emplace(scenes::chain(links, link, gravity, def));
            // The catalogue's chain starts horizontal; falling from there its free end
            // whips faster than any fixed step follows, so it starts straight at an angle.
            for (std::size_t i = 1; i <= links; ++i)
                system_->set_position(ParticleId{std::uint32_t(i)},
                                      Vec2{std::sin(release_angle), std::cos(release_angle)} * (double(i) * link));
        } else {
            columns_ = std::clamp(int(std::lround(std::sqrt(particles_ * 2.0))), 2, particles_);
            rows_ = std::max(2, particles_ / columns_);
            spacing_ = chain_length / double(columns_ - 1) * 0.8;
            system_.emplace(cloth_strip(columns_, rows_, spacing_, def));
        }
        system_->add_drag(air_drag);
        status_ = SolveStatus::ok;
        link_error_ = 0.0;
    }

    int particles_;
    int kind_ = 0;
    int integrator_ = 3;  // rk4
    int drift_ = 2;  // projection: long chains yanked by the mouse need it to stay stable
    double spacing_ = 0.0;
    int substeps_ = 1;
    bool running_ = true;
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
