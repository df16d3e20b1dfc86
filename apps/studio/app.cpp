// The window and its frame loop. Every frame advances the visible tab by the fixed step
// frame_dt, so screenshots and scripted runs are deterministic; interactive runs are
// additionally capped at 60 frames per second of wall time.
#include "app.hpp"

#include "script.hpp"

#include <grape/error.hpp>

#include <SDL.h>
#include <cairo.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace grape::studio {

void Tab::handle_event(const SDL_Event& e) {
    if (pausable() && e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_SPACE && !e.key.repeat &&
        !ImGui::GetIO().WantTextInput)
        running_ = !running_;
    on_event(e);
}

void Tab::run_button(bool play) {
    if (ImGui::Button(running_ ? "Pause" : (play ? "Play" : "Run"))) running_ = !running_;
}

std::vector<std::pair<std::string, Path>>& handed_paths() {
    static std::vector<std::pair<std::string, Path>> paths;
    return paths;
}

namespace {

constexpr float panel_width = 330.0f;

std::vector<std::unique_ptr<Tab>> make_tabs([[maybe_unused]] const Options& options) {
    std::vector<std::unique_ptr<Tab>> tabs;
#ifdef GRAPE_STUDIO_DYNAMICS
    tabs.push_back(make_constraint_tab());
#endif
    tabs.push_back(make_paths_tab(options.path));
#ifdef GRAPE_STUDIO_DYNAMICS
    tabs.push_back(make_chain_tab(options.particles));
#endif
    tabs.push_back(make_sprites_tab(options.sheet));
    tabs.push_back(make_keys_tab());
    tabs.push_back(make_draw_tab());
    tabs.push_back(make_track3d_tab());
    return tabs;
}

// The SDL objects, released in reverse order whatever happens.
struct Sdl {
    SDL_Window* window = nullptr;
    SDL_Renderer* renderer = nullptr;
    bool imgui = false;

    ~Sdl() {
        if (imgui) {
            ImGui_ImplSDLRenderer_Shutdown();
            ImGui_ImplSDL2_Shutdown();
            ImGui::DestroyContext();
        }
        if (renderer) SDL_DestroyRenderer(renderer);
        if (window) SDL_DestroyWindow(window);
        SDL_Quit();
    }
};

// Reads the frame back (call before SDL_RenderPresent) and writes it as a PNG with cairo.
void save_screenshot(SDL_Renderer* renderer, const std::string& path) {
    int w = 0;
    int h = 0;
    if (SDL_GetRendererOutputSize(renderer, &w, &h) != 0) throw Error(std::string("screenshot: ") + SDL_GetError());
    // SDL's ARGB8888 is a native-endian 0xAARRGGBB word, which is cairo's RGB24/ARGB32 layout.
    const int stride = cairo_format_stride_for_width(CAIRO_FORMAT_RGB24, w);
    std::vector<unsigned char> pixels(std::size_t(stride) * std::size_t(h));
    if (SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_ARGB8888, pixels.data(), stride) != 0)
        throw Error(std::string("screenshot: SDL_RenderReadPixels failed: ") + SDL_GetError());
    cairo_surface_t* surface = cairo_image_surface_create_for_data(pixels.data(), CAIRO_FORMAT_RGB24, w, h, stride);
    const cairo_status_t status = cairo_surface_write_to_png(surface, path.c_str());
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS)
        throw Error("--screenshot: cannot write '" + path + "': " + cairo_status_to_string(status));
}

// A pushed event carries the window it belongs to, as a real one would.
void address(SDL_Event& e, Uint32 window_id) {
    switch (e.type) {
        case SDL_MOUSEMOTION: e.motion.windowID = window_id; break;
        case SDL_MOUSEBUTTONDOWN:
        case SDL_MOUSEBUTTONUP: e.button.windowID = window_id; break;
        case SDL_MOUSEWHEEL: e.wheel.windowID = window_id; break;
        case SDL_KEYDOWN:
        case SDL_KEYUP: e.key.windowID = window_id; break;
        default: break;
    }
}

// The mouse as the event stream describes it. ImGui 1.86's SDL backend polls the pointer
// with SDL_GetMouseState, which pushed events do not move, so scripted runs hand ImGui this.
struct EventMouse {
    ImVec2 pos{-1.0f, -1.0f};
    bool down[3] = {false, false, false};
    bool pressed[3] = {false, false, false};  // pressed this frame, so a click shorter than a frame counts

    void see(const SDL_Event& e) {
        if (e.type == SDL_MOUSEMOTION) pos = {float(e.motion.x), float(e.motion.y)};
        if (e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP) {
            pos = {float(e.button.x), float(e.button.y)};
            const int i = e.button.button == SDL_BUTTON_LEFT ? 0 : e.button.button == SDL_BUTTON_RIGHT ? 1 : 2;
            down[i] = e.type == SDL_MOUSEBUTTONDOWN;
            if (down[i]) pressed[i] = true;
        }
    }
    void apply(ImGuiIO& io) {
        io.MousePos = pos;
        for (int i = 0; i < 3; ++i) {
            io.MouseDown[i] = down[i] || pressed[i];
            pressed[i] = false;
        }
    }
};

}  // namespace

std::vector<std::string> tab_names() {
    std::vector<std::string> names;
    for (const auto& tab : make_tabs(Options{})) names.emplace_back(tab->name());
    return names;
}

int run(const Options& options) {
    auto tabs = make_tabs(options);
    std::size_t current = tabs.size();
    for (std::size_t i = 0; i < tabs.size(); ++i)
        if (options.tab == tabs[i]->name()) current = i;
    if (current == tabs.size()) {
        std::string list;
        for (const auto& t : tabs) list += std::string(list.empty() ? "" : ", ") + t->name();
        throw Error("--tab: unknown tab '" + options.tab + "' (expected one of " + list + ")");
    }
    Sdl sdl;
    if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_TIMER) != 0) throw Error(std::string("SDL_Init failed: ") + SDL_GetError());
    const std::vector<ScriptEvent> script = options.script.empty() ? std::vector<ScriptEvent>{}
                                                                   : load_script(options.script);
    const bool scripted = !options.script.empty();
    sdl.window = SDL_CreateWindow("grape studio", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, options.width,
                                  options.height, SDL_WINDOW_RESIZABLE);
    if (!sdl.window) throw Error(std::string("SDL_CreateWindow failed: ") + SDL_GetError());
    // The software renderer: no GPU or OpenGL needed, the same pixels everywhere.
    sdl.renderer = SDL_CreateRenderer(sdl.window, -1, SDL_RENDERER_SOFTWARE);
    if (!sdl.renderer) throw Error(std::string("SDL_CreateRenderer failed: ") + SDL_GetError());

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // the layout is fixed; no imgui.ini next to the user's files
    ImGui::StyleColorsLight();
    ImGui::GetStyle().WindowRounding = 0.0f;
    ImGui_ImplSDL2_InitForSDLRenderer(sdl.window);
    ImGui_ImplSDLRenderer_Init(sdl.renderer);
    sdl.imgui = true;
    for (auto& t : tabs) t->attach(sdl.renderer);

    const Uint32 window_id = SDL_GetWindowID(sdl.window);
    EventMouse event_mouse;
    std::size_t next_event = 0;
    std::vector<double> frame_seconds;
    frame_seconds.reserve(std::size_t(std::max(options.frames, 0)));
    using clock = std::chrono::steady_clock;
    auto frame_start = clock::now();

    int frame = 0;
    bool running = true;
    double phase[4] = {0, 0, 0, 0};  // seconds: simulation, UI building, rasterizing, presenting
    while (running) {
        for (; next_event < script.size() && script[next_event].frame <= frame; ++next_event) {
            SDL_Event e = script[next_event].event;
            address(e, window_id);
            SDL_PushEvent(&e);
        }
        SDL_Event e;
        while (SDL_PollEvent(&e)) {
            if (e.type == SDL_QUIT) running = false;
            if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE && e.window.windowID == window_id)
                running = false;
            event_mouse.see(e);
            tabs[current]->handle_event(e);
            ImGui_ImplSDL2_ProcessEvent(&e);
        }

        ImGui_ImplSDLRenderer_NewFrame();
        ImGui_ImplSDL2_NewFrame();
        io.DeltaTime = float(frame_dt);  // fixed step: the same run gives the same pixels
        if (scripted) event_mouse.apply(io);
        ImGui::NewFrame();

        const auto t_advance = clock::now();
        tabs[current]->step(frame_dt);
        const auto t_ui = clock::now();

        ImGui::SetNextWindowPos({0.0f, 0.0f});
        ImGui::SetNextWindowSize(io.DisplaySize);
        ImGui::Begin("grape studio", nullptr,
                     ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                         ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoBackground);
        if (ImGui::BeginTabBar("tabs")) {
            for (std::size_t i = 0; i < tabs.size(); ++i) {
                const ImGuiTabItemFlags flags = (frame == 0 && i == current) ? ImGuiTabItemFlags_SetSelected : 0;
                if (!ImGui::BeginTabItem(tabs[i]->title(), nullptr, flags)) continue;
                if (i != current && frame > 0) {
                    ViewCanvas::release_handle();
                    current = i;
                }
                ImGui::PushStyleColor(ImGuiCol_ChildBg, ImGui::GetStyleColorVec4(ImGuiCol_WindowBg));
                ImGui::BeginChild("controls", {panel_width, 0.0f}, true);
                ImGui::PopStyleColor();
                ImGui::PushItemWidth(-140.0f);
                tabs[i]->controls();
                ImGui::PopItemWidth();
                ImGui::EndChild();
                ImGui::SameLine();
                ImGui::BeginChild("canvas", {0.0f, 0.0f}, true,
                                  ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoMove);
                const ImVec2 min = ImGui::GetCursorScreenPos();
                const ImVec2 avail = ImGui::GetContentRegionAvail();
                const ImVec2 max{min.x + std::max(avail.x, 1.0f), min.y + std::max(avail.y, 1.0f)};
                // An invisible button over the canvas keeps drags there from reaching the
                // window behind (and from being read as widget drags).
                ImGui::InvisibleButton("area", {max.x - min.x, max.y - min.y});
                ImDrawList* draw_list = ImGui::GetWindowDrawList();
                draw_list->PushClipRect(min, max, true);
                tabs[i]->draw(draw_list, min, max);
                draw_list->PopClipRect();
                ImGui::EndChild();
                ImGui::EndTabItem();
            }
            ImGui::EndTabBar();
        }
        ImGui::End();

        ImGui::Render();
        const auto t_raster = clock::now();
        // The clear is the only full-window fill: with the software renderer every ImGui
        // rectangle is a textured, blended triangle pair, so the window and the canvas draw
        // no background of their own (about a third of the frame time at 1200 × 760).
        SDL_SetRenderDrawColor(sdl.renderer, 250, 248, 244, 255);
        SDL_RenderClear(sdl.renderer);
        ImGui_ImplSDLRenderer_RenderDrawData(ImGui::GetDrawData());
        ++frame;
        const bool last = options.frames > 0 && frame >= options.frames;
        if (last && !options.screenshot.empty()) save_screenshot(sdl.renderer, options.screenshot);
        const auto t_present = clock::now();
        SDL_RenderPresent(sdl.renderer);
        const auto t_end = clock::now();
        phase[0] += std::chrono::duration<double>(t_ui - t_advance).count();
        phase[1] += std::chrono::duration<double>(t_raster - t_ui).count();
        phase[2] += std::chrono::duration<double>(t_present - t_raster).count();
        phase[3] += std::chrono::duration<double>(t_end - t_present).count();
        if (last) running = false;

        const auto now = clock::now();
        frame_seconds.push_back(std::chrono::duration<double>(now - frame_start).count());
        if (options.screenshot.empty() && !options.fps) {
            // Interactive: hold 60 frames per second of wall time.
            const double left = frame_dt - frame_seconds.back();
            if (left > 0.0) SDL_Delay(Uint32(left * 1000.0));
        }
        frame_start = clock::now();
    }

    for (auto& t : tabs) t->detach();

    if (options.fps && !frame_seconds.empty()) {
        // Skip the first frames (font texture upload, first allocations) when there are enough.
        const std::size_t skip = frame_seconds.size() > 60 ? 30 : 0;
        std::vector<double> s(frame_seconds.begin() + std::ptrdiff_t(skip), frame_seconds.end());
        double total = 0.0;
        for (double x : s) total += x;
        std::sort(s.begin(), s.end());
        const double median = s[s.size() / 2];
        const double p95 = s[std::min(s.size() - 1, s.size() * 95 / 100)];
        std::printf("fps: tab=%s frames=%zu mean_fps=%.1f median_frame_ms=%.2f p95_frame_ms=%.2f\n",
                    tabs[current]->name(), s.size(), double(s.size()) / total, median * 1e3, p95 * 1e3);
        const double n = double(frame_seconds.size());
        std::printf("fps: mean ms per frame: simulation %.2f, ui %.2f, rasterizing %.2f, presenting %.2f\n",
                    phase[0] / n * 1e3, phase[1] / n * 1e3, phase[2] / n * 1e3, phase[3] / n * 1e3);
    }
    if (!options.report.empty()) {
        std::ofstream out(options.report);
        if (!out) throw Error("--report: cannot write '" + options.report + "'");
        out.precision(17);  // full doubles, so checks can compare closely
        out << "tab: " << tabs[current]->name() << "\nframes: " << frame << "\n";
        tabs[current]->report(out);
    }
    return 0;
}

}  // namespace grape::studio
