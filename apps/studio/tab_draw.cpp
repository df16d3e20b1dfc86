// Draw: a path drawn with the mouse. Dragging on the canvas records the mouse's points; on
// release grape::fit_path turns them into a few cubic Béziers within the tolerance, corners
// kept where the drag turns sharply. Shown: the raw points, the fitted path with its joins
// and handles, the largest distance of any recorded point from the fitted path (measured by
// closest_point, not taken from the fitter), its SVG path data, and a marker running along
// it at constant speed.
#include "studio.hpp"

#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/path_query.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace grape::studio {

namespace {

// The world the canvas shows, in world units (y down).
constexpr Vec2 world_min{0, 0};
constexpr Vec2 world_max{800, 600};
// Seconds a marker takes along the fitted path.
constexpr double lap_seconds = 3.0;

class DrawTab final : public Tab {
public:
    const char* name() const noexcept override { return "draw"; }
    const char* title() const noexcept override { return "Draw"; }

    bool pausable() const noexcept override { return false; }  // the marker always runs

    void advance(double dt) override {
        if (!fitted_) return;
        time_ = std::fmod(time_ + dt, lap_seconds);
    }

    void controls() override {
        ImGui::TextWrapped("Drag on the canvas to draw. On release grape::fit_path fits cubic Béziers within "
                           "the tolerance (Schneider's algorithm), keeping corners where the drag turns "
                           "by more than the corner angle.");
        ImGui::Separator();
        const bool tolerance_moved =
            ImGui::SliderFloat("tolerance", &tolerance_, 0.25f, 20.0f, "%.2f units", ImGuiSliderFlags_Logarithmic);
        const bool angle_moved = ImGui::SliderFloat("corner angle", &corner_degrees_, 10.0f, 180.0f, "%.0f deg");
        if ((tolerance_moved || angle_moved) && !drawing_) fit();
        if (ImGui::Button("Clear")) clear();
        if (fitted_) {
            ImGui::SameLine();
            if (ImGui::Button("Animate in Paths")) {  // play it there with curves, ranges and offsets
                const std::string name = "drawn_" + std::to_string(++handed_);
                handed_paths().emplace_back(name, *fitted_);
                message_ = "sent to the Paths tab as " + name;
            }
        }
        ImGui::Separator();
        ImGui::Text("points recorded: %zu", points_.size());
        if (fitted_) {
            ImGui::Text("Bezier segments: %zu   corners: %zu", segments_, corners_);
            ImGui::Text("largest distance: %.3f units", max_deviation_);
            ImGui::Text("length: %.1f units%s", fitted_->length(), closed(*fitted_) ? ", closed" : "");
            ImGui::TextUnformatted("SVG path data:");
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextUnformatted(svg_.c_str());
            ImGui::PopTextWrapPos();
        }
        if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
    }

    void draw(ImDrawList* dl, ImVec2 min, ImVec2 max) override {
        ViewCanvas canvas(dl, min, max, world_min, world_max);
        canvas.grid(50.0, color::grid);
        record(canvas);
        if (points_.size() >= 2) canvas.polyline(points_, color::faint, 1.0f);
        for (Vec2 p : points_) canvas.disc(p, 1.5f, color::faint);
        if (fitted_ && !drawing_) {
            const auto spec = path_cast<ComplexSpec>(*fitted_);
            for (const Path& part : spec->parts) {
                if (const auto b = path_cast<CubicBezierSpec>(part)) {
                    canvas.line(b->control[0], b->control[1], color::handle);
                    canvas.line(b->control[3], b->control[2], color::handle);
                    canvas.disc(b->control[1], 3.0f, color::handle);
                    canvas.disc(b->control[2], 3.0f, color::handle);
                    canvas.disc(b->control[0], 4.0f, color::ink);
                    canvas.disc(b->control[3], 4.0f, color::ink);
                }
            }
            // Flattened within a quarter of a pixel.
            canvas.polyline(fitted_->flatten(0.25 / canvas.scale()), color::path, 2.5f);
            canvas.disc(even_->point(time_ / lap_seconds), 7.0f, color::marker);
        }
        canvas.text({world_min.x + 8, world_min.y + 8}, color::ink,
                    drawing_ ? "drawing..." : "drag to draw a path; it is fitted on release");
    }

    void report(std::ostream& out) const override {
        out << "handed: " << handed_ << "\npoints: " << points_.size() << "\nsegments: " << segments_ << "\ncorners: " << corners_
            << "\ntolerance: " << tolerance_ << "\nmax_deviation: " << max_deviation_
            << "\nfitted: " << (fitted_ ? 1 : 0) << "\nlength: " << (fitted_ ? fitted_->length() : 0.0) << "\nsvg: " << svg_ << "\n";
        if (fitted_) {
            const Vec2 a = fitted_->point(0.0), b = fitted_->point(1.0);
            out << "start: " << a.x << ' ' << a.y << "\nend: " << b.x << ' ' << b.y << "\n";
        }
    }

private:
    // Mouse down on the canvas starts a new drag; every move of half a pixel or more adds a
    // point; release fits.
    void record(const ViewCanvas& canvas) {
        if (!drawing_ && canvas.hovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            clear();
            drawing_ = true;
        }
        if (!drawing_) return;
        const Vec2 m = canvas.mouse();
        if (is_finite(m) && (points_.empty() || distance(points_.back(), m) * canvas.scale() >= 0.5)) points_.push_back(m);
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
            drawing_ = false;
            fit();
        }
    }

    void fit() {
        forget_fit();
        if (points_.empty()) return;
        try {
            const ComplexPath path = fit_path(points_, {.tolerance = tolerance_, .corner_angle = corner_degrees_ * pi / 180.0});
            const auto spec = path_cast<ComplexSpec>(path);
            segments_ = spec->parts.size();
            // A corner: a join where the tangents leaving and arriving differ in direction.
            for (std::size_t i = 1; i < spec->parts.size(); ++i) {
                const Vec2 in = spec->parts[i - 1].d1(1.0), out = spec->parts[i].d1(0.0);
                if (std::abs(cross(in, out)) > 1e-6 * length(in) * length(out) || dot(in, out) < 0.0) ++corners_;
            }
            for (Vec2 p : points_) max_deviation_ = std::max(max_deviation_, closest_point(path, p).distance);
            svg_ = svg_path_data(path);
            even_.emplace(path.reparametrized());
            fitted_.emplace(path);
            time_ = 0.0;
        } catch (const Error& e) {
            message_ = e.what();  // a click without a drag: fewer than 2 distinct points
        }
    }

    void forget_fit() {
        fitted_.reset();
        even_.reset();
        segments_ = corners_ = 0;
        max_deviation_ = 0.0;
        svg_.clear();
        message_.clear();
    }

    void clear() {
        points_.clear();
        forget_fit();
    }

    std::vector<Vec2> points_;      // the drag, world units
    bool drawing_ = false;          // the button is held since a press on the canvas
    float tolerance_ = 2.0f;        // world units
    float corner_degrees_ = 60.0f;  // FitPathDef's default, π/3
    std::optional<Path> fitted_;    // the fit of the last drag
    std::optional<Path> even_;      // the same at constant speed, for the marker
    std::size_t segments_ = 0;
    std::size_t corners_ = 0;
    double max_deviation_ = 0.0;    // over the recorded points, by closest_point
    std::string svg_;
    std::string message_;
    double time_ = 0.0;             // seconds into the marker's lap
    int handed_ = 0;                // fits sent to the Paths tab
};

}  // namespace

std::unique_ptr<Tab> make_draw_tab() { return std::make_unique<DrawTab>(); }

}  // namespace grape::studio
