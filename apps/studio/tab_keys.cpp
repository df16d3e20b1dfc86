// Keys: the keyboard's grape::KeyState, live. Keys light up while down; the frame a key goes
// down or up it flashes (pressed/released edges last exactly one frame), and a log keeps the
// edges so they can be read. Two masks show combinations: Ctrl+S (all down) and the arrows
// (any down). A held key repeats on the state's clock (0.5 s after the press, then 30 times
// a second), which each frame moves on by the studio's fixed step.
#include "studio.hpp"

#include <grape/bits.hpp>

#include <SDL.h>

#include <deque>
#include <ostream>
#include <string>

namespace grape::studio {

namespace {

// One key cap: scancode, label and width in key units.
struct Cap {
    SDL_Scancode code;
    const char* label;
    double width = 1.0;
};

// A compact US layout: enough to see any key the tests or a person press.
const std::vector<std::vector<Cap>>& layout() {
    static const std::vector<std::vector<Cap>> rows = {
        {{SDL_SCANCODE_ESCAPE, "Esc"}, {SDL_SCANCODE_1, "1"}, {SDL_SCANCODE_2, "2"}, {SDL_SCANCODE_3, "3"},
         {SDL_SCANCODE_4, "4"}, {SDL_SCANCODE_5, "5"}, {SDL_SCANCODE_6, "6"}, {SDL_SCANCODE_7, "7"},
         {SDL_SCANCODE_8, "8"}, {SDL_SCANCODE_9, "9"}, {SDL_SCANCODE_0, "0"}, {SDL_SCANCODE_BACKSPACE, "Bksp", 2.0}},
        {{SDL_SCANCODE_TAB, "Tab", 1.5}, {SDL_SCANCODE_Q, "Q"}, {SDL_SCANCODE_W, "W"}, {SDL_SCANCODE_E, "E"},
         {SDL_SCANCODE_R, "R"}, {SDL_SCANCODE_T, "T"}, {SDL_SCANCODE_Y, "Y"}, {SDL_SCANCODE_U, "U"},
         {SDL_SCANCODE_I, "I"}, {SDL_SCANCODE_O, "O"}, {SDL_SCANCODE_P, "P"}, {SDL_SCANCODE_RETURN, "Enter", 1.5}},
        {{SDL_SCANCODE_CAPSLOCK, "Caps", 1.75}, {SDL_SCANCODE_A, "A"}, {SDL_SCANCODE_S, "S"}, {SDL_SCANCODE_D, "D"},
         {SDL_SCANCODE_F, "F"}, {SDL_SCANCODE_G, "G"}, {SDL_SCANCODE_H, "H"}, {SDL_SCANCODE_J, "J"},
         {SDL_SCANCODE_K, "K"}, {SDL_SCANCODE_L, "L"}, {SDL_SCANCODE_SEMICOLON, ";"}, {SDL_SCANCODE_APOSTROPHE, "'", 2.25}},
        {{SDL_SCANCODE_LSHIFT, "Shift", 2.25}, {SDL_SCANCODE_Z, "Z"}, {SDL_SCANCODE_X, "X"}, {SDL_SCANCODE_C, "C"},
         {SDL_SCANCODE_V, "V"}, {SDL_SCANCODE_B, "B"}, {SDL_SCANCODE_N, "N"}, {SDL_SCANCODE_M, "M"},
         {SDL_SCANCODE_COMMA, ","}, {SDL_SCANCODE_PERIOD, "."}, {SDL_SCANCODE_UP, "Up"}, {SDL_SCANCODE_RSHIFT, "Shift", 1.75}},
        {{SDL_SCANCODE_LCTRL, "Ctrl", 1.5}, {SDL_SCANCODE_LALT, "Alt", 1.5}, {SDL_SCANCODE_SPACE, "Space", 5.0},
         {SDL_SCANCODE_RALT, "Alt", 1.0}, {SDL_SCANCODE_LEFT, "Left"}, {SDL_SCANCODE_DOWN, "Down"},
         {SDL_SCANCODE_RIGHT, "Right"}, {SDL_SCANCODE_RCTRL, "Ctrl", 1.5}},
    };
    return rows;
}

class KeysTab final : public Tab {
public:
    KeysTab()
        : save_(keys_.mask({SDL_SCANCODE_LCTRL, SDL_SCANCODE_S})),
          arrows_(keys_.mask({SDL_SCANCODE_LEFT, SDL_SCANCODE_RIGHT, SDL_SCANCODE_UP, SDL_SCANCODE_DOWN})) {}

    const char* name() const noexcept override { return "keys"; }
    const char* title() const noexcept override { return "Keys"; }

    void on_event(const SDL_Event& e) override {
        if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_FOCUS_LOST) {
            keys_.release_all();  // keys released elsewhere would otherwise stay down forever
            return;
        }
        if (e.type != SDL_KEYDOWN && e.type != SDL_KEYUP) return;
        const auto code = std::size_t(e.key.keysym.scancode);
        if (code >= keys_.key_count()) return;
        const bool was_down = keys_.is_down(code);
        if (e.type == SDL_KEYDOWN) keys_.press(code); else keys_.release(code);
        if (was_down != keys_.is_down(code)) {
            const char* key_name = SDL_GetScancodeName(e.key.keysym.scancode);
            log_.push_front("frame " + std::to_string(frame_) + ": " + (*key_name ? key_name : "?") +
                            (e.type == SDL_KEYDOWN ? " pressed" : " released"));
            if (log_.size() > 14) log_.pop_back();
            (e.type == SDL_KEYDOWN ? presses_ : releases_) += 1;
        }
    }

    void advance(double) override { ++frame_; }
    bool pausable() const noexcept override { return false; }  // Space is a key here

    void controls() override {
        ImGui::TextWrapped("grape::KeyState holds the keys down as bits, one per SDL scancode, with "
                           "the keys pressed and released this frame. Type anywhere in the window.");
        ImGui::Separator();
        ImGui::Text("keys down: %zu", keys_.down().count());
        ImGui::Text("presses: %d   releases: %d   repeats: %ld", presses_, releases_, repeats_);
        ImGui::TextColored(keys_.all_down(save_) ? ImVec4(0.1f, 0.6f, 0.2f, 1) : ImVec4(0.5f, 0.5f, 0.5f, 1),
                           "mask Ctrl+S (all down): %s", keys_.all_down(save_) ? "yes" : "no");
        ImGui::TextColored(keys_.any_down(arrows_) ? ImVec4(0.1f, 0.6f, 0.2f, 1) : ImVec4(0.5f, 0.5f, 0.5f, 1),
                           "mask arrows (any down): %s", keys_.any_down(arrows_) ? "yes" : "no");
        if (ImGui::Button("Release all")) keys_.release_all();
        ImGui::Separator();
        ImGui::TextUnformatted("Edges (newest first):");
        for (const auto& line : log_) ImGui::TextUnformatted(line.c_str());
    }

    void draw(ImDrawList* dl, ImVec2 min, ImVec2 max) override {
        const float unit = std::min((max.x - min.x - 40.0f) / 15.5f, 56.0f);
        const float gap = unit * 0.08f;
        const float y0 = min.y + 40.0f;
        dl->AddText({min.x + 20.0f, min.y + 12.0f}, color::ink,
                    "down: green   pressed this frame: orange outline   released this frame: red outline   "
                    "repeated: a bar on top");
        for (std::size_t r = 0; r < layout().size(); ++r) {
            float x = min.x + 20.0f;
            const float y = y0 + float(r) * unit;
            for (const Cap& cap : layout()[r]) {
                const auto code = std::size_t(cap.code);
                const ImVec2 a{x + gap, y + gap};
                const ImVec2 b{x + float(cap.width) * unit - gap, y + unit - gap};
                const bool down = keys_.is_down(code);
                dl->AddRectFilled(a, b, down ? IM_COL32(60, 180, 90, 255) : IM_COL32(236, 234, 228, 255), 4.0f);
                dl->AddRect(a, b, color::faint, 4.0f);
                if (keys_.pressed_this_frame(code)) dl->AddRect(a, b, color::handle, 4.0f, 0, 4.0f);
                if (keys_.released_this_frame(code)) dl->AddRect(a, b, color::marker, 4.0f, 0, 4.0f);
                if (keys_.repeated_this_frame(code)) dl->AddRectFilled(a, {b.x, a.y + 4.0f}, color::path, 2.0f);
                dl->AddText({a.x + 5.0f, a.y + 4.0f}, down ? IM_COL32_WHITE : color::ink, cap.label);
                x += float(cap.width) * unit;
            }
        }
        // The bit vector itself: the first 128 scancodes as a strip of bits.
        const float by = y0 + 5.5f * unit + 10.0f;
        dl->AddText({min.x + 20.0f, by}, color::ink, "KeyState::down(), scancodes 0-255 (one cell per bit):");
        const float cell = std::min((max.x - min.x - 40.0f) / 64.0f, 14.0f);
        for (std::size_t i = 0; i < 256; ++i) {
            const float cx = min.x + 20.0f + float(i % 64) * cell;
            const float cy = by + 20.0f + float(i / 64) * cell;
            dl->AddRectFilled({cx, cy}, {cx + cell - 1.0f, cy + cell - 1.0f},
                              keys_.is_down(i) ? IM_COL32(60, 180, 90, 255) : IM_COL32(225, 222, 215, 255));
        }
        // The edges and repeats have been shown: the frame ends for the key state, whose
        // clock moves on by the frame's step (the repeats due in it are reported next frame).
        for (const std::size_t code : keys_.repeated_keys()) {
            repeats_ += static_cast<long>(keys_.repeat_count(code));
            last_repeated_ = SDL_GetScancodeName(SDL_Scancode(code));
        }
        keys_.end_frame(frame_dt);
    }

    void report(std::ostream& out) const override {
        out << "keys_down:";
        for (std::size_t i = 0; i < keys_.key_count(); ++i)
            if (keys_.is_down(i)) out << ' ' << SDL_GetScancodeName(SDL_Scancode(i));
        out << "\npresses: " << presses_ << "\nreleases: " << releases_ << "\nrepeats: " << repeats_
            << "\nlast_repeated: " << last_repeated_ << "\n";
    }

private:
    KeyState keys_;
    BitVector save_;
    BitVector arrows_;
    std::deque<std::string> log_;
    int presses_ = 0;
    int releases_ = 0;
    long repeats_ = 0;           // every repeat reported so far
    std::string last_repeated_;  // the key of the latest one
    long frame_ = 0;
};

}  // namespace

std::unique_ptr<Tab> make_keys_tab() { return std::make_unique<KeysTab>(); }

}  // namespace grape::studio
