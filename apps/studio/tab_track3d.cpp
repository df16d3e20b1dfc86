// 3-D track: a helix climbing into an S-bend, seen by an orbiting perspective camera (View3::
// orbit: drag to orbit, wheel to zoom), with its ribbon (the frame's binormal across, its
// normal as the face normal; quads painter-sorted by depth, the normal side orange and the
// other blue) and a follower played by the engine's 3-D animation with its three frame axes.
// Keys 1, 2 and 3 (or the panel's buttons) switch the frame between Frenet, rotation-minimizing
// and reference-up: the Frenet frame turns over at the bend's inflection, the others do not.
#include "studio.hpp"

#include <grape/anim.hpp>
#include <grape/anim3.hpp>
#include <grape/frames3.hpp>
#include <grape/path3.hpp>
#include <grape/quat.hpp>
#include <grape/view3.hpp>

#include <SDL.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <vector>

namespace grape::studio {

namespace {

constexpr int track_samples = 400;      // ribbon quads: the bend's flip falls between two of them
constexpr double ribbon_half_width = 0.7;
constexpr double axis_length = 2.0;     // world units of the follower's drawn axes
constexpr double follower_speed = 6.0;  // world units per second: about 8 s per run
constexpr double orbit_rate = 0.01;     // radians per pixel dragged
constexpr double zoom_step = 0.85;      // distance factor per wheel step toward the track
// Elevation stays 0.07 rad short of the vertical, where the orbit's up would be the view.
constexpr double elevation_limit = 1.5;
// Distance in radii of the track's bounding sphere: beyond 1.2 the eye stays outside it, so
// every point is in front of the camera; beyond 8 the track is a few dozen pixels.
constexpr double distance_min = 1.2;
constexpr double distance_max = 8.0;
constexpr double distance_default = 2.6;
constexpr double azimuth_default = -1.1;
constexpr double elevation_default = 0.45;
constexpr double field_of_view = 0.8;   // radians, vertical

constexpr ImU32 face_front = IM_COL32(242, 140, 38, 255);  // the normal's side
constexpr ImU32 face_back = IM_COL32(51, 102, 217, 255);
constexpr ImU32 ribbon_edge = IM_COL32(70, 60, 50, 255);
constexpr ImU32 axis_tangent = IM_COL32(220, 20, 20, 255);
constexpr ImU32 axis_normal = IM_COL32(20, 160, 40, 255);
constexpr ImU32 axis_binormal = IM_COL32(140, 40, 200, 255);

constexpr FrameMode track_modes[] = {FrameMode::frenet, FrameMode::rotation_minimizing, FrameMode::reference_up};
constexpr const char* track_mode_names[] = {"Frenet", "rotation-minimizing", "reference-up"};

// One and a quarter turns up a helix about z, then a planar S-bend in the plane of its end
// tangent and the y axis: its curvature passes through zero halfway, where Frenet turns over.
Path3 helix_into_s_bend() {
    const Path3 helix = Path3::helix({.center = {0, 0, 0}, .axis = {0, 0, 1}, .start = {1, 0, 0}, .radius = 4,
                                      .rise = 3, .turns = 1.25});
    const Vec3 p0 = helix.point(1.0);
    const Vec3 t = helix.tangent(1.0);
    const Vec3 side{0, -1, 0};
    const Path3 bend = Path3::cubic_bezier(p0, p0 + t * 5.0, p0 + t * 10.0 + side * 7.0, p0 + t * 15.0 + side * 7.0);
    return Path3::complex_by_length({helix, bend});
}

// The rotation between two orientations, radians in [0, π].
double turn_between(const Frame3& a, const Frame3& b) noexcept {
    return axis_angle(conjugate(from_frame(a)) * from_frame(b)).angle;
}

// What the animation writes: position and the frame.
struct Follower {
    double x = 0.0, y = 0.0, z = 0.0;
    Frame3 orientation{};
};

struct RibbonQuad {
    std::array<ImVec2, 4> corners;
    double depth;
    bool front;
};

class Track3dTab final : public Tab {
public:
    Track3dTab() : track_(helix_into_s_bend()) {
        const Bounds3& b = track_.bounds();
        center_ = (b.min + b.max) * 0.5;
        radius_ = 0.5 * length(b.size()) + ribbon_half_width;
        ground_ = b.min.z - 1.0;
        distance_ = distance_default * radius_;
        set_mode(1);
    }

    const char* name() const noexcept override { return "track3d"; }
    const char* title() const noexcept override { return "3-D track"; }

    void advance(double dt) override {
        engine_.tick(dt);
        const double turn = turn_between(last_orientation_, follower_.orientation);
        follower_turn_ = turn;
        follower_max_turn_ = std::max(follower_max_turn_, turn);
        last_orientation_ = follower_.orientation;
    }

    void on_event(const SDL_Event& e) override {
        if (e.type == SDL_KEYDOWN && !e.key.repeat) {
            if (e.key.keysym.scancode == SDL_SCANCODE_1) set_mode(0);
            if (e.key.keysym.scancode == SDL_SCANCODE_2) set_mode(1);
            if (e.key.keysym.scancode == SDL_SCANCODE_3) set_mode(2);
        }
        // Whole wheel steps from the event (the ImGui backend counts any step as one).
        if (e.type == SDL_MOUSEWHEEL && hovered_ && e.wheel.y != 0) {
            const double steps = e.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -e.wheel.y : e.wheel.y;
            distance_ = std::clamp(distance_ * std::pow(zoom_step, steps), distance_min * radius_, distance_max * radius_);
        }
    }

    void controls() override {
        ImGui::TextWrapped("A helix climbing into an S-bend, framed three ways. The ribbon spans the frame's binormal; "
                           "orange is the side its normal points to, blue the other. Drag to orbit, wheel to zoom.");
        ImGui::Separator();
        ImGui::TextUnformatted("frame (keys 1, 2, 3)");
        for (int i = 0; i < 3; ++i)
            if (ImGui::RadioButton(track_mode_names[i], mode_ == i)) set_mode(i);
        run_button(true);
        ImGui::SameLine();
        if (ImGui::Button("Reset view")) {
            azimuth_ = azimuth_default;
            elevation_ = elevation_default;
            distance_ = distance_default * radius_;
        }
        ImGui::Separator();
        ImGui::Text("largest turn between samples: %.1f deg", max_turn_ * 180.0 / pi);
        ImGui::Text("  at u = %.3f (%d samples)", max_turn_u_, track_samples);
        ImGui::Text("follower: %.2f deg this step, %.1f deg at most", follower_turn_ * 180.0 / pi,
                    follower_max_turn_ * 180.0 / pi);
        ImGui::Text("u = %.3f   length %.2f", anim_.progress(), track_.length());
        ImGui::Separator();
        ImGui::Text("azimuth %.2f  elevation %.2f rad", azimuth_, elevation_);
        ImGui::Text("distance %.1f (%.1f to %.1f)", distance_, distance_min * radius_, distance_max * radius_);
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(axis_tangent), "tangent");
        ImGui::SameLine();
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(axis_normal), "normal");
        ImGui::SameLine();
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(axis_binormal), "binormal");
    }

    void draw(ImDrawList* dl, ImVec2 min, ImVec2 max) override {
        // The picture's half height is 1 (View3's perspective), mapped to half the canvas height.
        const double aspect = double(max.x - min.x) / std::max(1.0, double(max.y - min.y));
        ViewCanvas canvas(dl, min, max, {-aspect, -1.0}, {aspect, 1.0}, 0.0);
        hovered_ = canvas.hovered();
        orbit(canvas);
        view_ = View3::orbit(center_, distance_, azimuth_, elevation_, field_of_view);
        const auto at = [&](Vec3 p) { return canvas.to_screen(view_.project(p).point); };

        // The ground: a grid under the track and the track's shadow on it.
        const Bounds3& b = track_.bounds();
        const double step = 2.0;
        const double x0 = std::floor(b.min.x / step - 1) * step, x1 = std::ceil(b.max.x / step + 1) * step;
        const double y0 = std::floor(b.min.y / step - 1) * step, y1 = std::ceil(b.max.y / step + 1) * step;
        for (double x = x0; x <= x1; x += step) dl->AddLine(at({x, y0, ground_}), at({x, y1, ground_}), color::grid);
        for (double y = y0; y <= y1; y += step) dl->AddLine(at({x0, y, ground_}), at({x1, y, ground_}), color::grid);
        shadow_.clear();
        for (int i = 0; i <= track_samples; ++i) {
            const Vec3 p = frames_[std::size_t(i)].point;
            shadow_.push_back(at({p.x, p.y, ground_}));
        }
        dl->AddPolyline(shadow_.data(), int(shadow_.size()), color::faint, ImDrawFlags_None, 2.0f);

        // The ribbon, farthest quads first.
        quads_.clear();
        for (int i = 1; i <= track_samples; ++i) {
            const Frame3& f0 = frames_[std::size_t(i - 1)];
            const Frame3& f1 = frames_[std::size_t(i)];
            const Vec3 middle = (f0.point + f1.point) * 0.5;
            const Vec3 normal = normalized(f0.normal + f1.normal);
            quads_.push_back({{at(f0.point + f0.binormal * ribbon_half_width), at(f1.point + f1.binormal * ribbon_half_width),
                               at(f1.point - f1.binormal * ribbon_half_width), at(f0.point - f0.binormal * ribbon_half_width)},
                              view_.project(middle).depth,
                              dot(normal, view_.view_direction(middle)) < 0.0});
        }
        std::stable_sort(quads_.begin(), quads_.end(), [](const RibbonQuad& a, const RibbonQuad& b) { return a.depth > b.depth; });
        // Without anti-aliased fill: its fringes would draw seams between neighbouring quads.
        const ImDrawListFlags flags = dl->Flags;
        dl->Flags &= ~ImDrawListFlags_AntiAliasedFill;
        front_quads_ = 0;
        for (const RibbonQuad& q : quads_) {
            dl->AddQuadFilled(q.corners[0], q.corners[1], q.corners[2], q.corners[3], q.front ? face_front : face_back);
            dl->AddLine(q.corners[0], q.corners[1], ribbon_edge, 1.0f);
            dl->AddLine(q.corners[2], q.corners[3], ribbon_edge, 1.0f);
            front_quads_ += q.front ? 1 : 0;
        }
        dl->Flags = flags;

        // Where the sampled frame turns most, when that is a flip rather than the bend's turning.
        if (max_turn_ > 0.25 * pi) {
            flip_screen_ = at(track_.point(max_turn_u_));
            dl->AddCircle(flip_screen_, 9.0f, color::marker, 0, 2.5f);
        }

        // The follower on top, with its frame.
        const Vec3 p{follower_.x, follower_.y, follower_.z};
        const Frame3& f = follower_.orientation;
        follower_screen_ = at(p);
        dl->AddLine(follower_screen_, at(p + f.tangent * axis_length), axis_tangent, 3.0f);
        dl->AddLine(follower_screen_, at(p + f.normal * axis_length), axis_normal, 3.0f);
        dl->AddLine(follower_screen_, at(p + f.binormal * axis_length), axis_binormal, 3.0f);
        dl->AddCircleFilled(follower_screen_, 5.0f, color::ink);

        char label[128];
        std::snprintf(label, sizeof label, "%s frame: largest turn per step %.1f deg", track_mode_names[mode_],
                      max_turn_ * 180.0 / pi);
        dl->AddText({min.x + 10.0f, min.y + 8.0f}, color::ink, label);
    }

    void report(std::ostream& out) const override {
        out << "mode: " << track_mode_names[mode_] << "\nazimuth: " << azimuth_ << "\nelevation: " << elevation_
            << "\ndistance: " << distance_ << "\ndistance_min: " << distance_min * radius_
            << "\ndistance_max: " << distance_max * radius_ << "\nmax_turn_deg: " << max_turn_ * 180.0 / pi
            << "\nmax_turn_u: " << max_turn_u_ << "\nfollower_turn_deg: " << follower_turn_ * 180.0 / pi
            << "\nfollower_max_turn_deg: " << follower_max_turn_ * 180.0 / pi << "\nprogress: " << anim_.progress()
            << "\nfollower: " << follower_.x << ' ' << follower_.y << ' ' << follower_.z
            << "\nfollower_screen: " << follower_screen_.x << ' ' << follower_screen_.y
            << "\nflip_screen: " << flip_screen_.x << ' ' << flip_screen_.y << "\nquads: " << quads_.size()
            << "\nfront_quads: " << front_quads_ << "\n";
    }

private:
    // Drag anywhere on the canvas to orbit: right turns the scene with the mouse, down looks
    // from higher up.
    void orbit(const ViewCanvas& canvas) {
        const ImGuiIO& io = ImGui::GetIO();
        if (!dragging_ && canvas.hovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            dragging_ = true;
            drag_last_ = io.MousePos;
        }
        if (!dragging_) return;
        azimuth_ -= orbit_rate * double(io.MousePos.x - drag_last_.x);
        elevation_ = std::clamp(elevation_ + orbit_rate * double(io.MousePos.y - drag_last_.y), -elevation_limit,
                                elevation_limit);
        drag_last_ = io.MousePos;
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragging_ = false;
    }

    // Rebuilds the ribbon's frames and the follower's animation in mode i, where the follower was.
    void set_mode(int i) {
        mode_ = i;
        const FramesDef def{.mode = track_modes[i]};
        const Frames3 frames(track_, def);
        frames_.clear();
        max_turn_ = 0.0;
        max_turn_u_ = 0.0;
        for (int k = 0; k <= track_samples; ++k) {
            const double u = double(k) / track_samples;
            frames_.push_back(frames.frame(u));
            if (k == 0) continue;
            const double turn = turn_between(frames_[std::size_t(k - 1)], frames_.back());
            if (turn > max_turn_) {
                max_turn_ = turn;
                max_turn_u_ = (double(k) - 0.5) / track_samples;
            }
        }
        const double time = anim_.alive() ? anim_.time() : 0.0;
        engine_.kill_all();
        anim_ = engine_.create_3d_animation(follower_, track_, Speed{follower_speed}, {.repeat = -1},
                                            {.align = Align3::frame, .frames = def});
        anim_.seek(time);
        last_orientation_ = follower_.orientation;
        follower_turn_ = 0.0;
        follower_max_turn_ = 0.0;
    }

    Path3 track_;
    Vec3 center_{};
    double radius_ = 1.0;  // of the track's bounding sphere, ribbon included
    double ground_ = 0.0;
    int mode_ = 1;
    std::vector<Frame3> frames_;  // at u = k / track_samples
    double max_turn_ = 0.0;       // radians, between neighbouring samples
    double max_turn_u_ = 0.0;
    Engine engine_;
    Animation anim_;
    Follower follower_;
    Frame3 last_orientation_{};
    double follower_turn_ = 0.0;      // radians, over the last step
    double follower_max_turn_ = 0.0;  // since the mode was set
    double azimuth_ = azimuth_default;
    double elevation_ = elevation_default;
    double distance_ = 1.0;
    View3 view_;
    bool hovered_ = false;
    bool dragging_ = false;
    ImVec2 drag_last_{};
    std::vector<ImVec2> shadow_;
    std::vector<RibbonQuad> quads_;
    int front_quads_ = 0;
    ImVec2 follower_screen_{};  // for reports
    ImVec2 flip_screen_{};
};

}  // namespace

std::unique_ptr<Tab> make_track3d_tab() { return std::make_unique<Track3dTab>(); }

}  // namespace grape::studio
