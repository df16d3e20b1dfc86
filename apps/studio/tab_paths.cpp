// Paths: the seed's Grape demo. Pick a path (the seed's examples, complex and nested ones
// included, or one of every kind from the gallery), a curve (every easing, or any curve
// name such as "cubic-bezier(0.3,0,0.2,1)" or "steps(5)"), duration, repeat, reverse, yoyo
// and arc length; the path is drawn with its debug rendering and a marker plays along it.
// Bézier and spline control points can be dragged (the path's spec is edited and rebuilt);
// the animation follows. A loaded scene with timelines gets a timeline view under the canvas:
// its animations then play by the scene's time, which the view's playhead seeks.
// Over 500 lines: one tab class whose panels share its state (pick, curve, drag, timeline);
// its list helpers are in path_entries.*, and a split of the class would only pass that state on.
#include "studio.hpp"
#include "path_entries.hpp"


#include <grape/anim.hpp>
#include <grape/curve.hpp>
#include <grape/error.hpp>
#include <grape/path.hpp>
#ifdef GRAPE_STUDIO_RENDER
#include <grape/render.hpp>
#endif
#ifdef GRAPE_STUDIO_SCENE
#include <grape/scene.hpp>

#include <nlohmann/json.hpp>

#include "timeline_view.hpp"
#endif

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <ostream>

namespace grape::studio {

namespace {

class PathsTab final : public Tab {
public:
    explicit PathsTab(const std::string& initial) : entries_(path_catalogue()) {
        for (const auto& n : curve_names()) curve_names_.emplace_back(n);
        std::size_t pick = 0;
        for (std::size_t i = 0; i < entries_.size(); ++i)
            if (entries_[i].name == (initial.empty() ? "seed_nested_complex" : initial)) pick = i + 1;
        if (pick == 0) {
            if (!initial.empty()) {
                std::string list;
                for (const PathEntry& e : entries_) list += (list.empty() ? "" : ", ") + e.name;
                throw Error("--path: unknown path '" + initial + "' (expected one of " + list + ")");
            }
            pick = 1;
        }
        select(pick - 1);
    }

    const char* name() const noexcept override { return "paths"; }
    const char* title() const noexcept override { return "Paths"; }

#ifdef GRAPE_STUDIO_RENDER
    void attach(SDL_Renderer* renderer) override { renderer_ = renderer; }
    void detach() override {
        if (texture_) SDL_DestroyTexture(texture_);
        texture_ = nullptr;
        renderer_ = nullptr;
    }
#endif

    void advance(double dt) override {
        engine_.tick(dt);
#ifdef GRAPE_STUDIO_SCENE
        // The scene's time runs round the view's axis (unless the playhead is held).
        if (!timeline_.empty() && !seeking_) {
            scene_time_ += dt;
            if (scene_time_ > timeline_.span()) scene_time_ = 0.0;
        }
#endif
    }

    void controls() override {
        if (!handed_paths().empty()) {  // drawn in the Draw tab: played here
            for (auto& [name, path] : handed_paths()) entries_.push_back(entry_from_path(name, path));
            handed_paths().clear();
            select(entries_.size() - 1);
        }
        ImGui::TextUnformatted("Path");
        if (ImGui::BeginListBox("##paths", {-1.0f, 170.0f})) {
            for (std::size_t i = 0; i < entries_.size(); ++i) {
                const bool editable = !entries_[i].controls.empty();
                std::string label = entries_[i].name + (editable ? "  (drag points)" : "");
                if (ImGui::Selectable(label.c_str(), i == current_)) select(i);
            }
            ImGui::EndListBox();
        }
        ImGui::Text("kind: %s   length: %.1f", std::string(to_string(entries_[current_].path.kind())).c_str(),
                    entries_[current_].path.length());
        // Paths drawn in any vector editor: SVG path data becomes a complex path.
        // Both widgets are submitted every frame, so no short-circuit between them.
        const bool entered =
            ImGui::InputText("SVG path", svg_edit_, sizeof svg_edit_, ImGuiInputTextFlags_EnterReturnsTrue);
        const bool clicked = ImGui::SmallButton("Add SVG path");
        if (entered || clicked) {
            try {
                entries_.push_back(entry_from_path("svg_" + std::to_string(++svg_count_), parse_svg_path(svg_edit_)));
                svg_error_.clear();
                select(entries_.size() - 1);
            } catch (const Error& err) {
                svg_error_ = err.what();
            }
        }
        if (!svg_error_.empty()) ImGui::TextColored({0.8f, 0.1f, 0.1f, 1.0f}, "%s", svg_error_.c_str());

        ImGui::Separator();
        ImGui::TextUnformatted("Curve");
        if (ImGui::BeginCombo("easing", curve_text_.c_str())) {
            for (const std::string& n : curve_names_)
                if (ImGui::Selectable(n.c_str(), n == curve_text_)) set_curve(n);
            ImGui::EndCombo();
        }
        if (ImGui::InputText("any curve", curve_edit_, sizeof curve_edit_, ImGuiInputTextFlags_EnterReturnsTrue))
            set_curve(curve_edit_);
        if (!curve_error_.empty()) ImGui::TextColored({0.8f, 0.1f, 0.1f, 1.0f}, "%s", curve_error_.c_str());
        curve_plot();

        ImGui::Separator();
        ImGui::TextUnformatted("Animation");
        bool changed = false;
        changed |= ImGui::SliderFloat("duration (s)", &duration_, 0.2f, 10.0f, "%.1f");
        changed |= ImGui::SliderInt("repeat (-1 forever)", &repeat_, -1, 10);
        changed |= ImGui::Checkbox("reverse", &reversed_);
        ImGui::SameLine();
        changed |= ImGui::Checkbox("yoyo", &yoyo_);
        if (ImGui::Checkbox("arc length (constant speed)", &arc_length_)) {
            shape_changed();
            changed = true;
        }
        changed |= ImGui::Checkbox("compare with the other parametrization", &compare_);
        if (changed) restart(true);
        run_button(true);
        ImGui::SameLine();
        if (ImGui::Button("Restart")) restart(false);
        ImGui::SameLine();
        if (ImGui::Button("Fit view")) fit_view();
        ImGui::Text("t = %.2f s  play %d  u = %.3f", anim_.time(), anim_.repetition(), anim_.progress());
        ImGui::Checkbox("debug: ticks every 0.05 u, tangents", &debug_);
#ifdef GRAPE_STUDIO_SCENE
        ImGui::Separator();
        ImGui::TextUnformatted("Scene file");
        ImGui::InputText("file", scene_file_, sizeof scene_file_);
        if (ImGui::Button("Save")) save();
        ImGui::SameLine();
        if (ImGui::Button("Load")) load();
        if (!scene_message_.empty()) ImGui::TextWrapped("%s", scene_message_.c_str());
#endif
        if (!edit_error_.empty()) ImGui::TextColored({0.8f, 0.1f, 0.1f, 1.0f}, "%s", edit_error_.c_str());
        // Last in the panel, so the controls above keep their places.
        ImGui::Separator();
        ImGui::TextUnformatted("Part of the path and a lane beside it");
        bool placed = ImGui::SliderFloat2("range (u)", range_, 0.0f, 1.0f, "%.2f");
        placed |= ImGui::SliderFloat("offset (sideways)", &offset_, -60.0f, 60.0f, "%.1f");
        if (placed) restart(true);
    }

    void draw(ImDrawList* dl, ImVec2 min, ImVec2 max) override {
        ImVec2 canvas_max = max;  // the timeline view, when shown, takes the bottom of the canvas
#ifdef GRAPE_STUDIO_SCENE
        if (!timeline_.empty()) canvas_max.y = std::max(min.y + 40.0f, max.y - timeline_.height());
#endif
        ViewCanvas canvas(dl, min, canvas_max, view_min_, view_max_);
        screen_offset_ = canvas.offset();
        screen_scale_ = canvas.scale();
        canvas.grid(grid_step(), color::grid);
        PathEntry& e = entries_[current_];
        draw_path(canvas, min, canvas_max);

        // Control polygon and handles.
        if (!e.controls.empty()) {
            const bool bezier = e.bezier;
            if (bezier)
                for (std::size_t i = 0; i + 1 < e.controls.size(); ++i)
                    canvas.line(e.controls[i], e.controls[i + 1], color::faint, 1.0f);
            bool moved = false;
            for (std::size_t i = 0; i < e.controls.size(); ++i)
                moved |= canvas.drag_handle(int(i), e.controls[i], color::handle);
            if (moved) {
                try {
                    e.path = rebuild(e);
                    edit_error_.clear();
                } catch (const Error& err) {
                    edit_error_ = err.what();
                }
                shape_changed();
                restart(true);
            }
        }

        // The marker, its heading, and the other parametrization's ghost.
        if (compare_ && ghost_) {
            canvas.ring(ghost_.value(), 7.0f, color::ink, 2.0f);
        }
        Vec2 p = anim_.value();
        double h = anim_.heading();
#ifdef GRAPE_STUDIO_SCENE
        if (const auto i = timeline_animation()) {  // played by the scene's timelines
            const SceneAnimation& a = scene_.animations[*i];
            const double progress = timing_.progress(*i, scene_time_);
            const Vec2 d = shown_.d1(a.range_start + progress * (a.range_end - a.range_start));
            p = a.position_at(progress);
            h = std::atan2(d.y, d.x) + (a.range_end < a.range_start ? pi : 0.0);
        }
        marker_ = p;
        if (!timeline_.empty()) seeking_ = timeline_.draw(dl, {min.x, canvas_max.y}, max, scene_time_);
#endif
        canvas.line(p, p + Vec2{std::cos(h), std::sin(h)} * (22.0 / canvas.scale()), color::marker, 2.0f);
        canvas.disc(p, 7.0f, color::marker);
        char label[96];
        std::snprintf(label, sizeof label, "%s  |  %s  |  %s", e.name.c_str(), curve_text_.c_str(),
                      arc_length_ ? "by arc length" : "by u");
        dl->AddText({min.x + 10.0f, min.y + 8.0f}, color::ink, label);
        if (compare_)
            dl->AddText({min.x + 10.0f, min.y + 24.0f}, color::ink,
                        "filled: this parametrization   ring: the other one");
    }

    void report(std::ostream& out) const override {
        const PathEntry& e = entries_[current_];
        out << "path: " << e.name << "\nkind: " << to_string(e.path.kind()) << "\nlength: " << e.path.length()
            << "\ncurve: " << curve_text_ << "\narc_length: " << arc_length_ << "\n";
        for (std::size_t i = 0; i < e.controls.size(); ++i)
            out << "control_" << i << ": " << e.controls[i].x << ' ' << e.controls[i].y << "\ncontrol_" << i
                << "_screen: " << screen_offset_.x + e.controls[i].x * screen_scale_ << ' '
                << screen_offset_.y + e.controls[i].y * screen_scale_ << "\n";
        out << "midpoint: " << e.path.point(0.5).x << ' ' << e.path.point(0.5).y << "\n";
        out << "marker: " << anim_.value().x << ' ' << anim_.value().y << "\nprogress: " << anim_.progress() << "\n";
#ifdef GRAPE_STUDIO_SCENE
        if (!timeline_.empty()) {
            out << "timelines: " << scene_.timelines.size() << "\nscene_time: " << scene_time_ << "\ntimeline_axis: "
                << timeline_.axis_start() << ' ' << timeline_.axis_end() << ' ' << timeline_.span() << "\n";
            if (const auto i = timeline_animation())
                out << "timeline_animation: " << scene_.animations[*i].name << "\ntimeline_marker: " << marker_.x << ' ' << marker_.y
                    << "\n";
        }
#endif
    }

private:
    void select(std::size_t i) {
        current_ = i;
        edit_error_.clear();
        ViewCanvas::release_handle();
        shape_changed();
        fit_view();
        restart(false);
    }

    void set_curve(const std::string& text) {
        try {
            curve_ = parse_curve(text);
            curve_text_ = to_string(curve_);
            curve_error_.clear();
            restart(true);
        } catch (const Error& err) {
            curve_error_ = err.what();
        }
    }

    // The path as played (by u or by arc length) and the other one for comparison.
    void shape_changed() {
        const Path& base = entries_[current_].path;
        const Path by_length = base.reparametrized();
        shown_ = arc_length_ ? by_length : base;
        other_ = arc_length_ ? base : by_length;
        picture_dirty_ = true;
    }

    void restart(bool keep_time) {
        const double t = keep_time && anim_ ? anim_.time() : 0.0;
        engine_.kill_all();
        const AnimationDef def{.curve = curve_,
                               .repeat = repeat_,
                               .reversed = reversed_,
                               .yoyo = yoyo_,
                               .range_start = range_[0],
                               .range_end = range_[1],
                               .offset = offset_};
        anim_ = engine_.create_animation(shown_, duration_, def);
        ghost_ = engine_.create_animation(other_, duration_, def);
        if (t > 0.0) {
            anim_.seek(t);
            ghost_.seek(t);
        }
    }

    void fit_view() {
        const PathEntry& e = entries_[current_];
        Bounds b = e.path.bounds();
        for (Vec2 c : e.controls) b.add(c);
        const Vec2 size = b.size();
        const double pad = 0.08 * std::max({size.x, size.y, 1.0});
        view_min_ = b.min - Vec2{pad, pad};
        view_max_ = b.max + Vec2{pad, pad};
        picture_dirty_ = true;
    }

    double grid_step() const {
        const Vec2 size = view_max_ - view_min_;
        const double span = std::max(size.x, size.y);
        double step = std::pow(10.0, std::floor(std::log10(std::max(span, 1e-9) / 4.0)));
        if (span / step > 20.0) step *= 5.0;
        return step;
    }

    // The path with the render module's debug drawing (ticks every 0.05 of u, complex-path
    // cues, tangents, ends), rasterized with cairo into a texture when anything changes.
    void draw_path(const ViewCanvas& canvas, ImVec2 min, ImVec2 max) {
#ifdef GRAPE_STUDIO_RENDER
        const int w = int(max.x - min.x);
        const int h = int(max.y - min.y);
        if (renderer_ && w > 0 && h > 0) {
            if (w != texture_w_ || h != texture_h_ || canvas.scale() != picture_scale_) picture_dirty_ = true;
            if (picture_dirty_) {
                grape::Canvas picture(w, h, colors::transparent);
                const Vec2 o = canvas.offset();
                picture.set_transform(Affine{canvas.scale(), 0.0, 0.0, canvas.scale(), o.x - min.x, o.y - min.y});
                PathStyle style{.stroke = {.color = {0.24, 0.35, 0.78}, .width = 2.5}};
                if (debug_) {
                    style.ticks = 0.05;
                    style.tangents = 8;
                }
                grape::draw_path(picture, shown_, style);
                const Image image = picture.to_image();
                if (!texture_ || w != texture_w_ || h != texture_h_) {
                    if (texture_) SDL_DestroyTexture(texture_);
                    texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_ARGB8888, SDL_TEXTUREACCESS_STREAMING, w, h);
                    if (texture_) SDL_SetTextureBlendMode(texture_, SDL_BLENDMODE_BLEND);
                    texture_w_ = w;
                    texture_h_ = h;
                }
                if (texture_) {
                    // cairo's pixels are premultiplied; SDL's software blending wants straight alpha.
                    straight_.assign(image.argb().begin(), image.argb().end());
                    for (std::uint32_t& px : straight_) {
                        const std::uint32_t alpha = px >> 24;
                        if (alpha == 0 || alpha == 255) continue;
                        auto channel = [&](int shift) { return std::min(255u, (((px >> shift) & 255u) * 255u + alpha / 2) / alpha); };
                        px = (alpha << 24) | (channel(16) << 16) | (channel(8) << 8) | channel(0);
                    }
                    SDL_UpdateTexture(texture_, nullptr, straight_.data(), image.width() * 4);
                }
                picture_scale_ = canvas.scale();
                picture_dirty_ = false;
            }
            if (texture_) {
                canvas.draw_list()->AddImage(ImTextureID(texture_), min, {min.x + float(w), min.y + float(h)});
                return;
            }
        }
#else
        (void)min;
        (void)max;
#endif
        const double tolerance = 0.25 / canvas.scale();  // a quarter pixel
        canvas.polyline(shown_.flatten(tolerance), color::path, 2.5f);
        if (debug_)
            for (int i = 0; i <= 20; ++i) canvas.disc(shown_.point(i / 20.0), 2.5f, color::faint);
    }

    void curve_plot() {
        const ImVec2 size{ImGui::GetContentRegionAvail().x, 110.0f};
        const ImVec2 a = ImGui::GetCursorScreenPos();
        ImGui::Dummy(size);
        ImDrawList* dl = ImGui::GetWindowDrawList();
        const ImVec2 b{a.x + size.x, a.y + size.y};
        dl->AddRectFilled(a, b, IM_COL32(255, 255, 255, 255));
        // Progress from −0.4 to 1.4 fits back and elastic overshoot.
        auto to_screen = [&](double t, double p) {
            return ImVec2{float(a.x + 6 + t * (size.x - 12)), float(b.y - (p + 0.4) / 1.8 * size.y)};
        };
        dl->AddLine(to_screen(0, 0), to_screen(1, 0), color::grid);
        dl->AddLine(to_screen(0, 1), to_screen(1, 1), color::grid);
        ImVec2 pts[101];
        for (int i = 0; i <= 100; ++i) pts[i] = to_screen(i / 100.0, curve_(i / 100.0));
        dl->AddPolyline(pts, 101, color::path, ImDrawFlags_None, 2.0f);
        const double d = double(duration_);
        const double t = anim_.time();
        double tau = t <= 0.0 ? 0.0 : std::fmod(t, d) / d;
        if (!anim_) tau = 1.0;
        dl->AddCircleFilled(to_screen(tau, curve_(tau)), 4.0f, color::marker);
        dl->AddText({a.x + 6, a.y + 2}, color::faint, "progress over each play");
    }

#ifdef GRAPE_STUDIO_SCENE
    void save() {
        try {
            const PathEntry& e = entries_[current_];
            Scene scene;
            scene.name = "grape studio: " + e.name;
            scene.view.ticks = 0.05;
            scene.paths.push_back({e.name, shown_});
            SceneAnimation a;
            a.name = e.name;
            a.path = shown_;
            a.path_name = e.name;
            a.curve = curve_;
            a.duration = duration_;
            a.repeat = repeat_;
            a.yoyo = yoyo_;
            a.reversed = reversed_;
            a.range_start = range_[0];
            a.range_end = range_[1];
            a.offset = offset_;
            scene.animations.push_back(a);
            save_scene_file(scene, scene_file_);
            scene_message_ = std::string("saved ") + scene_file_;
        } catch (const Error& err) {
            scene_message_ = err.what();
        }
    }

    void load() {
        try {
            const Scene scene = load_scene_file(scene_file_);
            std::size_t first = entries_.size();
            for (const SceneAnimation& a : scene.animations)
                entries_.push_back(entry_from_path("file_" + (a.name.empty() ? std::string("animation") : a.name), a.path));
            if (scene.animations.empty())
                for (const NamedPath& p : scene.paths) entries_.push_back(entry_from_path("file_" + p.name, p.path));
            if (first == entries_.size()) {
                scene_message_ = std::string(scene_file_) + ": no paths or animations";
                return;
            }
            if (!scene.animations.empty()) {
                const SceneAnimation& a = scene.animations.front();
                curve_ = a.curve;
                curve_text_ = to_string(curve_);
                duration_ = float(a.duration);
                repeat_ = a.repeat;
                yoyo_ = a.yoyo;
                reversed_ = a.reversed;
                range_[0] = float(a.range_start);
                range_[1] = float(a.range_end);
                offset_ = float(a.offset);
            }
            arc_length_ = false;
            scene_ = scene;
            timing_ = SceneTiming(scene);
            timeline_.set_scene(scene);
            scene_time_ = 0.0;
            seeking_ = false;
            file_first_ = scene.animations.empty() ? entries_.size() : first;
            select(first);
            scene_message_ = std::string("loaded ") + scene_file_;
        } catch (const Error& err) {
            scene_message_ = err.what();
        }
    }

    // The scene animation entry `current_` shows, when the loaded scene's timelines play it.
    std::optional<std::size_t> timeline_animation() const {
        if (timeline_.empty() || current_ < file_first_ || current_ - file_first_ >= scene_.animations.size()) return {};
        return current_ - file_first_;
    }

    char scene_file_[256] = "studio-scene.json";
    std::string scene_message_;
    Scene scene_;                 // the last scene loaded
    SceneTiming timing_;          // its animations and timelines in time
    TimelineView timeline_;       // its timelines under the canvas
    double scene_time_ = 0.0;     // seconds, seeked by the view's playhead
    bool seeking_ = false;        // the playhead is held
    std::size_t file_first_ = SIZE_MAX;  // the entry of the scene's first animation
    Vec2 marker_;                 // where the marker was drawn, for reports
#endif

    std::vector<PathEntry> entries_;
    std::size_t current_ = 0;
    std::vector<std::string> curve_names_;
    Curve curve_ = Curve::quad_in_out();
    std::string curve_text_ = to_string(Curve::quad_in_out());
    char curve_edit_[128] = "cubic-bezier(0.3,0,0.2,1)";
    std::string curve_error_;
    std::string edit_error_;
    char svg_edit_[512] = "M 20 80 C 60 0 140 0 180 80 S 300 160 340 80 A 40 40 0 0 1 420 80";
    std::string svg_error_;
    int svg_count_ = 0;
    float duration_ = 3.0f;
    int repeat_ = -1;
    bool reversed_ = false;
    bool yoyo_ = true;
    float range_[2] = {0.0f, 1.0f};  // the part of the path a play covers (AnimationDef::range_*)
    float offset_ = 0.0f;            // sideways from the path (AnimationDef::offset)
    bool arc_length_ = false;
    bool compare_ = false;
    bool debug_ = true;
    Path shown_;
    Path other_;
    Engine engine_;
    Animation anim_;
    Animation ghost_;
    Vec2 view_min_;
    Vec2 view_max_{1, 1};
    Vec2 screen_offset_;  // the last frame's world → window mapping, for reports
    double screen_scale_ = 1.0;
    bool picture_dirty_ = true;
#ifdef GRAPE_STUDIO_RENDER
    SDL_Renderer* renderer_ = nullptr;
    SDL_Texture* texture_ = nullptr;
    int texture_w_ = 0;
    int texture_h_ = 0;
    double picture_scale_ = 0.0;
    std::vector<std::uint32_t> straight_;
#endif
};

}  // namespace

std::unique_ptr<Tab> make_paths_tab(const std::string& initial_path) { return std::make_unique<PathsTab>(initial_path); }

}  // namespace grape::studio
