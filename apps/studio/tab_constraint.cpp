// Constraint: the seed's parabola x² + 100y = 0, solved two ways side by side in real time:
// left the implicit form (a ParticleSystem with the curve as a Witkin constraint), right
// the parametric form (a Bead in its generalized coordinate). "If you watch long enough,
// you'll see the implicit form eventually leaves the parabola" — and the parametric one
// loses energy. Live plots of the implicit residual and of both energy errors; drag either
// particle to choose a new start point.
#include "studio.hpp"

#include <SDL.h>

#include <seed_dynamics.hpp>

#include <grape/dynamics.hpp>
#include <grape/error.hpp>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <optional>
#include <ostream>

namespace grape::studio {

namespace {

using scenes::ParabolaMethod;
using scenes::ParabolaRun;
using scenes::ParabolaSetup;
using scenes::ParabolaState;

constexpr std::array<Integrator, 6> integrators{Integrator::euler,    Integrator::semi_implicit_euler,
                                                Integrator::midpoint, Integrator::rk4,
                                                Integrator::velocity_verlet, Integrator::rk45};
constexpr std::size_t history = 600;  // plot samples (10 s at one per frame)
constexpr double half_width = 200.0;  // the seed's plot: x in [−200, 200]

// A fixed-size ring of samples, unrolled for ImGui::PlotLines.
struct Series {
    std::vector<float> values;
    void push(double v) {
        if (values.size() == history) values.erase(values.begin());
        values.push_back(std::isfinite(v) ? float(v) : 0.0f);
    }
};

class ConstraintTab final : public Tab {
public:
    ConstraintTab() { reset(); }

    const char* name() const noexcept override { return "constraint"; }
    const char* title() const noexcept override { return "Constraint"; }

    void advance(double dt) override {
        if (dragging_ >= 0) return;
        budget_ += dt * double(speed_);
        const double h = double(step_);
        // Bounded work per frame: a tiny dt at high speed slows down instead of freezing.
        for (int n = 0; budget_ >= h && n < 4000; ++n) {
            implicit_->step(h);
            parametric_->step(h);
            budget_ -= h;
        }
        budget_ = std::min(budget_, h);
        const ParabolaState a = implicit_->state();
        const ParabolaState b = parametric_->state();
        residual_.push(a.distance);
        energy_implicit_.push((a.energy - e0_implicit_) / std::abs(e0_implicit_));
        energy_parametric_.push((b.energy - e0_parametric_) / std::abs(e0_parametric_));
        trail_implicit_.push_back(a.x);
        trail_parametric_.push_back(b.x);
        if (trail_implicit_.size() > 90) trail_implicit_.erase(trail_implicit_.begin());
        if (trail_parametric_.size() > 90) trail_parametric_.erase(trail_parametric_.begin());
    }

    void controls() override {
        ImGui::TextWrapped("x^2 + 100y = 0, released from rest. Left: implicit (Witkin constraint force); "
                           "right: parametric (Lagrange, q'' from the curve's derivatives). Drag a particle "
                           "to a new start point.");
        ImGui::Separator();
        bool changed = false;
        static const char* names[] = {"euler", "semi-implicit euler", "midpoint", "rk4", "velocity verlet", "rk45"};
        changed |= ImGui::Combo("integrator", &integrator_, names, int(integrators.size()));
        ImGui::SliderFloat("dt (s)", &step_, 1.0f / 480.0f, 1.0f / 15.0f, "%.4f", ImGuiSliderFlags_Logarithmic);
        changed |= ImGui::SliderFloat("gravity (px/s^2)", &gravity_, 50.0f, 2000.0f, "%.0f");
        changed |= ImGui::SliderFloat("sideways force", &force_x_, -300.0f, 300.0f, "%.0f");
        static const char* lefts[] = {"implicit (Witkin solver)", "seed's formula as written"};
        changed |= ImGui::Combo("left side", &left_method_, lefts, 2);
        if (left_method_ == 1 && force_x_ != 0.0f)
            ImGui::TextWrapped("The seed's closed form has -100*x*Fx where J^T lambda gives -50*x*Fx: "
                               "with a sideways force it pushes the bead off the curve.");
        changed |= ImGui::Checkbox("feedback ks, kd (Baumgarte)", &feedback_);
        if (feedback_) changed |= ImGui::SliderFloat("omega*dt", &omega_dt_, 0.01f, 0.5f, "%.2f");
        ImGui::SliderFloat("speed (x real time)", &speed_, 0.25f, 60.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
        if (changed) reset();
        run_button();
        ImGui::SameLine();
        if (ImGui::Button("Reset")) reset();
        ImGui::SameLine();
        if (ImGui::Button("x0 = 100")) {
            x0_ = 100.0;
            reset();
        }
        const ParabolaState a = implicit_->state();
        const ParabolaState b = parametric_->state();
        ImGui::Text("t = %.2f s   x0 = %.1f px", a.t, x0_);
        ImGui::Text("implicit   x = %9.3f  off by %.2e px", a.x.x, a.distance);
        ImGui::Text("parametric x = %9.3f  off by %.2e px", b.x.x, b.distance);
        ImGui::Separator();
        plot("|C|/|grad C| implicit (px)", residual_, 0.0f);
        plot("dE/E implicit", energy_implicit_, FLT_MAX);
        plot("dE/E parametric", energy_parametric_, FLT_MAX);
    }

    void draw(ImDrawList* dl, ImVec2 min, ImVec2 max) override {
        const float mid = 0.5f * (min.x + max.x);
        side(dl, min, {mid - 4.0f, max.y}, *implicit_, trail_implicit_, 0,
             left_method_ == 0 ? "implicit (Witkin)" : "implicit (the seed's closed-form force)");
        side(dl, {mid + 4.0f, min.y}, max, *parametric_, trail_parametric_, 1, "parametric (Lagrange)");
        dl->AddLine({mid, min.y + 8.0f}, {mid, max.y - 8.0f}, color::grid, 2.0f);
    }

    void report(std::ostream& out) const override {
        const ParabolaState a = implicit_->state();
        const ParabolaState b = parametric_->state();
        out << "x0: " << x0_ << "\ntime: " << a.t << "\nimplicit: " << a.x.x << ' ' << a.x.y
            << "\nparametric: " << b.x.x << ' ' << b.x.y << "\nimplicit_distance: " << a.distance
            << "\nparametric_distance: " << b.distance << "\nimplicit_screen: " << screen_[0].x << ' '
            << screen_[0].y << "\nparametric_screen: " << screen_[1].x << ' ' << screen_[1].y << "\n";
    }

private:
    void reset() {
        ParabolaSetup setup;
        setup.integrator = integrators[std::size_t(integrator_)];
        setup.x0 = x0_;
        setup.g = gravity_;
        setup.drift = feedback_ ? DriftDef{.method = DriftControl::baumgarte, .omega_dt = omega_dt_}
                                : DriftDef{.method = DriftControl::none};
        setup.force_x = force_x_;
        setup.method = left_method_ == 0 ? ParabolaMethod::implicit : ParabolaMethod::seed;
        implicit_.emplace(setup);
        setup.method = ParabolaMethod::parametric;
        parametric_.emplace(setup);
        e0_implicit_ = implicit_->state().energy;
        e0_parametric_ = parametric_->state().energy;
        // Released from rest at the vertex there is no energy scale to compare against.
        if (e0_implicit_ == 0.0) e0_implicit_ = 1.0;
        if (e0_parametric_ == 0.0) e0_parametric_ = 1.0;
        budget_ = 0.0;
        residual_ = {};
        energy_implicit_ = {};
        energy_parametric_ = {};
        trail_implicit_.clear();
        trail_parametric_.clear();
    }

    static void plot(const char* label, const Series& s, float lo) {
        char overlay[64];
        std::snprintf(overlay, sizeof overlay, "%.3g", s.values.empty() ? 0.0 : double(s.values.back()));
        ImGui::TextUnformatted(label);
        ImGui::PlotLines((std::string("##") + label).c_str(), s.values.data(), int(s.values.size()), 0, overlay,
                         lo, FLT_MAX, {ImGui::GetContentRegionAvail().x, 70.0f});
    }

    void side(ImDrawList* dl, ImVec2 min, ImVec2 max, const ParabolaRun& run, const std::vector<Vec2>& trail, int id,
              const char* label) {
        dl->PushClipRect(min, max, true);
        ViewCanvas canvas(dl, min, max, {-half_width - 20.0, -half_width * half_width / 100.0 - 20.0}, {half_width + 20.0, 40.0});
        canvas.grid(50.0, color::grid);
        std::vector<Vec2> curve;
        for (int i = 0; i <= 200; ++i) {
            const double x = -half_width + 2.0 * half_width * i / 200.0;
            curve.push_back({x, -x * x / 100.0});
        }
        canvas.polyline(curve, color::path, 2.0f);
        canvas.polyline(trail, color::faint, 1.5f);
        Vec2 p = run.state().x;
        screen_[id] = canvas.to_screen(p);
        // Where the particle should be: the curve point below it, joined when it has drifted.
        const Vec2 on_curve{p.x, -p.x * p.x / 100.0};
        if (distance(on_curve, p) * canvas.scale() > 1.0) canvas.line(on_curve, p, color::marker, 1.5f);
        if (canvas.drag_handle(id, p, color::marker, 9.0)) {
            dragging_ = id;
            x0_ = std::clamp(p.x, -half_width, half_width);
        }
        if (dragging_ == id && ViewCanvas::active_handle() != id) {
            dragging_ = -1;  // released: start again from the new point
            reset();
        }
        if (dragging_ == id) canvas.ring({x0_, -x0_ * x0_ / 100.0}, 12.0f, color::handle, 2.0f);
        dl->AddText({min.x + 10.0f, min.y + 8.0f}, color::ink, label);
        dl->PopClipRect();
    }

    int integrator_ = 3;  // rk4, as in the seed's demo
    float step_ = 1.0f / 60.0f;
    float gravity_ = 500.0f;
    float force_x_ = 0.0f;  // a constant sideways force (wind), px/s² on the unit mass
    int left_method_ = 0;
    bool feedback_ = false;
    float omega_dt_ = 0.05f;
    float speed_ = 1.0f;
    double x0_ = 100.0;
    int dragging_ = -1;
    ImVec2 screen_[2];  // where the particles were drawn last frame, for reports
    double budget_ = 0.0;
    std::optional<ParabolaRun> implicit_;
    std::optional<ParabolaRun> parametric_;
    double e0_implicit_ = 1.0;
    double e0_parametric_ = 1.0;
    Series residual_;
    Series energy_implicit_;
    Series energy_parametric_;
    std::vector<Vec2> trail_implicit_;
    std::vector<Vec2> trail_parametric_;
};

}  // namespace

std::unique_ptr<Tab> make_constraint_tab() { return std::make_unique<ConstraintTab>(); }

}  // namespace grape::studio
