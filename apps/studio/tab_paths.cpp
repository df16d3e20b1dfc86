// Paths: the seed's Grape demo. Pick a path (the seed's examples, complex and nested ones
// included, or one of every kind from the gallery), a curve (every easing, or any curve
// name such as "cubic-bezier(0.3,0,0.2,1)" or "steps(5)"), duration, repeat, reverse, yoyo
// and arc length; the path is drawn with its debug rendering and a marker plays along it.
// Bézier and spline control points can be dragged; the animation follows.
#include "studio.hpp"

#include <seed_paths.hpp>

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
#endif

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace grape::studio {

namespace {

// How an entry's control points rebuild its path. `scene`: through the path's scene JSON,
// whose "points" are the control points for every kind that has them.
enum class Edit { none, quadratic, cubic, linear_spline, cosine_spline, catmull_rom, scene };

struct Entry {
    std::string name;
    Path path;
    Edit edit = Edit::none;
    std::vector<Vec2> controls;   // Bézier control points or spline points
    bool reparametrize = false;   // Bézier built by arc length (the seed's flag)
    CatmullRom type = CatmullRom::uniform;
    std::string json;             // Edit::scene: the path as scene JSON
};

// A Bézier's control points from its end derivatives (exact: x′(0) = n(p1 − p0),
// x′(1) = n(pn − pn−1) for degree n), so any Bézier from the catalogue can be edited.
Entry entry_from_path(std::string name, const Path& path) {
    Entry e;
    e.name = std::move(name);
    e.path = path;
    const Vec2 p0 = path.point(0.0);
    const Vec2 pn = path.point(1.0);
    if (path.kind() == PathKind::quadratic_bezier) {
        e.edit = Edit::quadratic;
        e.controls = {p0, p0 + path.d1(0.0) / 2.0, pn};
    } else if (path.kind() == PathKind::cubic_bezier) {
        e.edit = Edit::cubic;
        e.controls = {p0, p0 + path.d1(0.0) / 3.0, pn - path.d1(1.0) / 3.0, pn};
    }
#ifdef GRAPE_STUDIO_SCENE
    else {
        // Splines (and anything else with points) through the scene format.
        const nlohmann::json j = nlohmann::json::parse(path_to_json(path));
        if (j.contains("points") && j["points"].is_array()) {
            e.edit = Edit::scene;
            e.json = j.dump();
            for (const auto& point : j["points"]) e.controls.push_back({point.at(0).get<double>(), point.at(1).get<double>()});
        }
    }
#endif
    return e;
}

std::vector<Entry> catalogue() {
    std::vector<Entry> entries;
    // The seed's examples; the typed factories give the Bézier and spline points to edit.
    for (auto& [name, path] : scenes::seed_paths()) entries.push_back(entry_from_path("seed_" + name, path));
    for (Entry& e : entries) {
        if (e.name == "seed_bezier" || e.name == "seed_bezier_reparametrized") {
            const CubicBezierPath b = scenes::seed_bezier(e.name == "seed_bezier_reparametrized");
            e.edit = Edit::cubic;
            e.reparametrize = e.name == "seed_bezier_reparametrized";
            e.controls = {b.control(0), b.control(1), b.control(2), b.control(3)};
        } else if (e.name == "seed_linear_spline_p1") {
            const auto s = scenes::seed_linear_spline();
            e.edit = Edit::linear_spline;
            e.controls.assign(s.points().begin(), s.points().end());
        } else if (e.name == "seed_cosine_spline_p2") {
            const auto s = scenes::seed_cosine_spline();
            e.edit = Edit::cosine_spline;
            e.controls.assign(s.points().begin(), s.points().end());
        } else if (e.name == "seed_catmull_rom_spline_p3") {
            const auto s = scenes::seed_catmull_rom_spline();
            e.edit = Edit::catmull_rom;
            e.type = s.type();
            e.controls.assign(s.points().begin(), s.points().end());
        }
    }
    for (auto& [name, path] : scenes::path_gallery()) entries.push_back(entry_from_path("gallery_" + name, path));
    return entries;
}

// The path through an entry's control points (throws grape::Error for a degenerate set).
Path rebuild(const Entry& e) {
    switch (e.edit) {
        case Edit::quadratic: return QuadraticBezierPath(e.controls[0], e.controls[1], e.controls[2], e.reparametrize);
        case Edit::cubic:
            return CubicBezierPath(e.controls[0], e.controls[1], e.controls[2], e.controls[3], e.reparametrize);
        case Edit::linear_spline: return LinearSplinePath(e.controls);
        case Edit::cosine_spline: return CosineSplinePath(e.controls);
        case Edit::catmull_rom: return CatmullRomSplinePath(e.controls, e.type);
        case Edit::scene: {
#ifdef GRAPE_STUDIO_SCENE
            nlohmann::json j = nlohmann::json::parse(e.json);
            j["points"] = nlohmann::json::array();
            for (Vec2 p : e.controls) j["points"].push_back({p.x, p.y});
            return path_from_json(j.dump());
#else
            break;
#endif
        }
        case Edit::none: break;
    }
    return e.path;
}

class PathsTab final : public Tab {
public:
    explicit PathsTab(const std::string& initial) : entries_(catalogue()) {
        for (const auto& n : curve_names()) curve_names_.emplace_back(n);
        std::size_t pick = 0;
        for (std::size_t i = 0; i < entries_.size(); ++i)
            if (entries_[i].name == (initial.empty() ? "seed_nested_complex" : initial)) pick = i + 1;
        if (pick == 0) {
            if (!initial.empty()) {
                std::string list;
                for (const Entry& e : entries_) list += (list.empty() ? "" : ", ") + e.name;
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

    void on_event(const SDL_Event& e) override {
        // Space runs and pauses, unless a text field has the keyboard.
        if (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_SPACE && !e.key.repeat && !ImGui::GetIO().WantTextInput)
            playing_ = !playing_;
    }

    void advance(double dt) override {
        if (playing_) engine_.tick(dt);
    }

    void controls() override {
        ImGui::TextUnformatted("Path");
        if (ImGui::BeginListBox("##paths", {-1.0f, 170.0f})) {
            for (std::size_t i = 0; i < entries_.size(); ++i) {
                const bool editable = entries_[i].edit != Edit::none;
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
        if (ImGui::Button(playing_ ? "Pause" : "Play")) playing_ = !playing_;
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
    }

    void draw(ImDrawList* dl, ImVec2 min, ImVec2 max) override {
        Canvas canvas(dl, min, max, view_min_, view_max_);
        screen_offset_ = canvas.offset();
        screen_scale_ = canvas.scale();
        canvas.grid(grid_step(), colour::grid);
        Entry& e = entries_[current_];
        draw_path(canvas, min, max);

        // Control polygon and handles.
        if (e.edit != Edit::none) {
            const bool bezier = e.edit == Edit::quadratic || e.edit == Edit::cubic;
            if (bezier)
                for (std::size_t i = 0; i + 1 < e.controls.size(); ++i)
                    canvas.line(e.controls[i], e.controls[i + 1], colour::faint, 1.0f);
            bool moved = false;
            for (std::size_t i = 0; i < e.controls.size(); ++i)
                moved |= canvas.drag_handle(int(i), e.controls[i], colour::handle);
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
            canvas.ring(ghost_.value(), 7.0f, colour::ink, 2.0f);
        }
        const Vec2 p = anim_.value();
        const double h = anim_.heading();
        canvas.line(p, p + Vec2{std::cos(h), std::sin(h)} * (22.0 / canvas.scale()), colour::marker, 2.0f);
        canvas.disc(p, 7.0f, colour::marker);
        char label[96];
        std::snprintf(label, sizeof label, "%s  |  %s  |  %s", e.name.c_str(), curve_text_.c_str(),
                      arc_length_ ? "by arc length" : "by u");
        dl->AddText({min.x + 10.0f, min.y + 8.0f}, colour::ink, label);
        if (compare_)
            dl->AddText({min.x + 10.0f, min.y + 24.0f}, colour::ink,
                        "filled: this parametrization   ring: the other one");
    }

    void report(std::ostream& out) const override {
        const Entry& e = entries_[current_];
        out << "path: " << e.name << "\nkind: " << to_string(e.path.kind()) << "\nlength: " << e.path.length()
            << "\ncurve: " << curve_text_ << "\narc_length: " << arc_length_ << "\n";
        for (std::size_t i = 0; i < e.controls.size(); ++i)
            out << "control_" << i << ": " << e.controls[i].x << ' ' << e.controls[i].y << "\ncontrol_" << i
                << "_screen: " << screen_offset_.x + e.controls[i].x * screen_scale_ << ' '
                << screen_offset_.y + e.controls[i].y * screen_scale_ << "\n";
        out << "midpoint: " << e.path.point(0.5).x << ' ' << e.path.point(0.5).y << "\n";
        out << "marker: " << anim_.value().x << ' ' << anim_.value().y << "\nprogress: " << anim_.progress() << "\n";
    }

private:
    void select(std::size_t i) {
        current_ = i;
        edit_error_.clear();
        Canvas::release_handle();
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
        const AnimationDef def{.curve = curve_, .repeat = repeat_, .reversed = reversed_, .yoyo = yoyo_};
        anim_ = engine_.create_animation(shown_, duration_, def);
        ghost_ = engine_.create_animation(other_, duration_, def);
        if (t > 0.0) {
            anim_.seek(t);
            ghost_.seek(t);
        }
    }

    void fit_view() {
        const Entry& e = entries_[current_];
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
    void draw_path(const Canvas& canvas, ImVec2 min, ImVec2 max) {
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
        canvas.polyline(shown_.flatten(tolerance), colour::path, 2.5f);
        if (debug_)
            for (int i = 0; i <= 20; ++i) canvas.disc(shown_.point(i / 20.0), 2.5f, colour::faint);
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
        dl->AddLine(to_screen(0, 0), to_screen(1, 0), colour::grid);
        dl->AddLine(to_screen(0, 1), to_screen(1, 1), colour::grid);
        ImVec2 pts[101];
        for (int i = 0; i <= 100; ++i) pts[i] = to_screen(i / 100.0, curve_(i / 100.0));
        dl->AddPolyline(pts, 101, colour::path, ImDrawFlags_None, 2.0f);
        const double d = double(duration_);
        const double t = anim_.time();
        double tau = t <= 0.0 ? 0.0 : std::fmod(t, d) / d;
        if (!anim_) tau = 1.0;
        dl->AddCircleFilled(to_screen(tau, curve_(tau)), 4.0f, colour::marker);
        dl->AddText({a.x + 6, a.y + 2}, colour::faint, "progress over each play");
    }

#ifdef GRAPE_STUDIO_SCENE
    void save() {
        try {
            const Entry& e = entries_[current_];
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
            }
            arc_length_ = false;
            select(first);
            scene_message_ = std::string("loaded ") + scene_file_;
        } catch (const Error& err) {
            scene_message_ = err.what();
        }
    }

    char scene_file_[256] = "studio-scene.json";
    std::string scene_message_;
#endif

    std::vector<Entry> entries_;
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
    bool arc_length_ = false;
    bool compare_ = false;
    bool playing_ = true;
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
