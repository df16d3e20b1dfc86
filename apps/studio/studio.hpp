// grape-studio: shared pieces of the window: the options, the canvas a tab draws into and
// the interface every tab implements. Tabs use grape's public API and the scene catalogue;
// the studio only adds drawing and mouse handling.
#pragma once

#include <grape/math.hpp>
#include <grape/path.hpp>

#include <imgui.h>

#include <iosfwd>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

union SDL_Event;
struct SDL_Renderer;

namespace grape::studio {

/// The fixed simulation and animation step of one frame, in seconds: every frame advances
/// by exactly this much, so a run of N frames is deterministic whatever the wall clock does.
inline constexpr double frame_dt = 1.0 / 60.0;

/// Command-line options.
struct Options {
    std::string tab = "paths";      ///< tab shown at start
    std::string screenshot;         ///< PNG written after `frames` frames, then exit
    int frames = 0;                 ///< frames to run before exiting (0: run until closed)
    std::string script;             ///< file of timed mouse and key events
    std::string report;             ///< text file of the tabs' state written at exit
    int particles = 0;              ///< chain tab: particle count (0: the tab's default)
    std::string path;               ///< paths tab: the path selected at start ("" : the default)
    std::string sheet;              ///< sprites tab: the sheet JSON opened at start ("": grape's own)
    bool fps = false;               ///< no frame cap; print frames per second at exit
    int width = 1200;               ///< window width, pixels
    int height = 760;               ///< window height, pixels
};

/// The drawing area of a tab: a rectangle of the window with a world → screen transform
/// (uniform scale, y down in both) and the mouse state in world units.
class ViewCanvas {
public:
    /// Maps the world box [world_min, world_max] into the screen rectangle, centered, with a margin.
    ViewCanvas(ImDrawList* draw_list, ImVec2 screen_min, ImVec2 screen_max, Vec2 world_min, Vec2 world_max,
               double margin_px = 24.0);

    ImDrawList* draw_list() const noexcept { return draw_list_; }
    ImVec2 screen_min() const noexcept { return screen_min_; }
    ImVec2 screen_max() const noexcept { return screen_max_; }
    /// Pixels per world unit.
    double scale() const noexcept { return scale_; }
    /// Screen position of the world origin: screen = offset + world·scale.
    Vec2 offset() const noexcept { return offset_; }
    ImVec2 to_screen(Vec2 p) const noexcept;
    Vec2 to_world(ImVec2 p) const noexcept;

    /// The mouse is over the canvas (and not over a widget).
    bool hovered() const noexcept { return hovered_; }
    /// Mouse position in world units.
    Vec2 mouse() const noexcept { return to_world(ImGui::GetIO().MousePos); }

    /// A draggable point: grabbed by a left click within `radius_px`, follows the mouse while
    /// the button is held. Returns true when `p` changed this frame. `id` must be unique
    /// among the handles of one canvas.
    bool drag_handle(int id, Vec2& p, ImU32 color, double radius_px = 6.0);
    /// The handle being dragged (−1: none).
    static int active_handle() noexcept;
    static void release_handle() noexcept;

    // Drawing in world units (widths and radii in pixels).
    void polyline(const std::vector<Vec2>& points, ImU32 color, float width = 2.0f) const;
    void line(Vec2 a, Vec2 b, ImU32 color, float width = 1.0f) const;
    void disc(Vec2 p, float radius_px, ImU32 color) const;
    void ring(Vec2 p, float radius_px, ImU32 color, float width = 1.5f) const;
    void text(Vec2 p, ImU32 color, std::string_view s) const;
    /// Light grid lines every `step` world units.
    void grid(double step, ImU32 color) const;

private:
    ImDrawList* draw_list_;
    ImVec2 screen_min_;
    ImVec2 screen_max_;
    double scale_ = 1.0;
    Vec2 offset_;  // screen = offset + world·scale
    bool hovered_ = false;
    inline static int held_ = -1;  // the handle being dragged: one mouse, so one at a time
};

/// One tab of the window.
class Tab {
public:
    virtual ~Tab() = default;
    /// Name on the command line ("paths").
    virtual const char* name() const noexcept = 0;
    /// Label on the tab bar.
    virtual const char* title() const noexcept = 0;
    /// Advances the tab's simulation or animations by dt seconds: called by step() while the
    /// tab runs (only the visible tab runs).
    virtual void advance(double dt) = 0;
    /// The widgets of the left-hand panel.
    virtual void controls() = 0;
    /// Draws into the canvas and handles the mouse there. `min`/`max`: the canvas rectangle.
    virtual void draw(ImDrawList* draw_list, ImVec2 min, ImVec2 max) = 0;
    /// Sees every SDL event (keys for the keys tab) before ImGui does, after handle_event.
    virtual void on_event(const SDL_Event&) {}
    /// Tabs that run and pause (Space, the Run/Pause button); the Keys tab takes Space as a key.
    virtual bool pausable() const noexcept { return true; }

    /// One frame of the fixed step: advance(dt) while running.
    void step(double dt) {
        if (running_ || !pausable()) advance(dt);
    }
    /// Space runs and pauses a pausable tab, unless a text field has the keyboard; then on_event.
    void handle_event(const SDL_Event& e);
    bool running() const noexcept { return running_; }
    void set_running(bool running) noexcept { running_ = running; }
    /// The Run/Pause button ("Play"/"Pause" with play = true) on the tab's panel.
    void run_button(bool play = false);
    /// Called once after the window's renderer exists (textures).
    virtual void attach(SDL_Renderer*) {}
    /// Called before the renderer goes away.
    virtual void detach() {}
    /// The tab's state as `key: value` lines, for scripted checks.
    virtual void report(std::ostream&) const {}

private:
    bool running_ = true;
};

std::unique_ptr<Tab> make_paths_tab(const std::string& initial_path);
std::unique_ptr<Tab> make_sprites_tab(const std::string& sheet_file);
std::unique_ptr<Tab> make_keys_tab();
std::unique_ptr<Tab> make_draw_tab();
std::unique_ptr<Tab> make_track3d_tab();
#ifdef GRAPE_STUDIO_DYNAMICS
std::unique_ptr<Tab> make_constraint_tab();
std::unique_ptr<Tab> make_chain_tab(int particles);
#endif

/// Paths one tab hands to another (the Draw tab's "Animate in Paths"): the Paths tab takes
/// them into its list, selecting the last, the next time it is shown.
std::vector<std::pair<std::string, Path>>& handed_paths();

/// Colours shared by the tabs (ImGui's ABGR packing).
namespace color {
inline constexpr ImU32 background = IM_COL32(250, 248, 244, 255);
inline constexpr ImU32 grid = IM_COL32(228, 224, 216, 255);
inline constexpr ImU32 ink = IM_COL32(40, 40, 48, 255);
inline constexpr ImU32 path = IM_COL32(60, 90, 200, 255);
inline constexpr ImU32 faint = IM_COL32(150, 150, 160, 255);
inline constexpr ImU32 handle = IM_COL32(230, 120, 20, 255);
inline constexpr ImU32 marker = IM_COL32(200, 30, 60, 255);
inline constexpr ImU32 good = IM_COL32(30, 150, 80, 255);
}  // namespace color

}  // namespace grape::studio
