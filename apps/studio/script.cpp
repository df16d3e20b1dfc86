// Scripted input: parsing the event file into SDL events.
#include "script.hpp"

#include <grape/error.hpp>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace grape::studio {

namespace {

std::vector<std::string_view> split_words(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

struct LineParser {
    std::string where;  // "file:line"

    [[noreturn]] void fail(const std::string& reason) const { throw Error(where + ": " + reason); }

    int integer(std::string_view word, const char* what) const {
        int value = 0;
        const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
        if (ec != std::errc{} || end != word.data() + word.size())
            fail(std::string(what) + " must be an integer (got '" + std::string(word) + "')");
        return value;
    }

    Uint8 button(std::string_view word) const {
        if (word == "left") return SDL_BUTTON_LEFT;
        if (word == "right") return SDL_BUTTON_RIGHT;
        if (word == "middle") return SDL_BUTTON_MIDDLE;
        fail("mouse button must be left, right or middle (got '" + std::string(word) + "')");
    }

    // Keys by SDL scancode name: the physical key, whatever the keyboard layout.
    SDL_Scancode key(std::string_view word) const {
        const std::string name(word);
        const SDL_Scancode k = SDL_GetScancodeFromName(name.c_str());
        if (k == SDL_SCANCODE_UNKNOWN)
            fail("unknown key name '" + name + "' (SDL scancode names: A, Left, Space, Return, Left Ctrl, ...)");
        return k;
    }

    void arity(const std::vector<std::string_view>& words, std::size_t n, const char* usage) const {
        if (words.size() != n) fail(std::string("expected '") + usage + "'");
    }
};

SDL_Event mouse_motion(int x, int y, Uint32 buttons) {
    SDL_Event e{};
    e.type = SDL_MOUSEMOTION;
    e.motion.x = x;
    e.motion.y = y;
    e.motion.state = buttons;
    return e;
}

SDL_Event mouse_button(bool down, Uint8 button, int x, int y) {
    SDL_Event e{};
    e.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
    e.button.button = button;
    e.button.state = down ? SDL_PRESSED : SDL_RELEASED;
    e.button.clicks = 1;
    e.button.x = x;
    e.button.y = y;
    return e;
}

SDL_Event key_event(bool down, SDL_Scancode key) {
    SDL_Event e{};
    e.type = down ? SDL_KEYDOWN : SDL_KEYUP;
    e.key.state = down ? SDL_PRESSED : SDL_RELEASED;
    e.key.keysym.scancode = key;
    e.key.keysym.sym = SDL_GetKeyFromScancode(key);  // the layout's key (needs SDL's video up)
    return e;
}

}  // namespace

std::vector<ScriptEvent> parse_script(std::string_view text, std::string_view source) {
    std::vector<ScriptEvent> events;
    int mouse_x = 0;
    int mouse_y = 0;
    Uint32 buttons = 0;  // pressed buttons, so motion events carry the state SDL would give
    int last_frame = 0;
    int line_number = 0;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t end = std::min(text.find('\n', pos), text.size());
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        ++line_number;
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        const auto words = split_words(line);
        if (words.empty()) continue;
        const LineParser p{std::string(source) + ":" + std::to_string(line_number)};
        if (words.size() < 2) p.fail("expected '<frame> <event> [arguments]'");
        const int frame = p.integer(words[0], "frame");
        if (frame < 0) p.fail("frame must not be negative (got " + std::to_string(frame) + ")");
        if (frame < last_frame)
            p.fail("frame " + std::to_string(frame) + " comes before the previous line's frame " +
                   std::to_string(last_frame) + " (events must be in time order)");
        last_frame = frame;
        const std::string_view verb = words[1];
        if (verb == "move") {
            p.arity(words, 4, "<frame> move <x> <y>");
            mouse_x = p.integer(words[2], "x");
            mouse_y = p.integer(words[3], "y");
            events.push_back({frame, mouse_motion(mouse_x, mouse_y, buttons)});
        } else if (verb == "down" || verb == "up") {
            p.arity(words, 3, "<frame> down|up left|right|middle");
            const Uint8 b = p.button(words[2]);
            if (verb == "down") buttons |= SDL_BUTTON(b); else buttons &= ~SDL_BUTTON(b);
            events.push_back({frame, mouse_button(verb == "down", b, mouse_x, mouse_y)});
        } else if (verb == "key_down" || verb == "key_up") {
            // Key names may hold spaces ("Left Ctrl"): the rest of the line is the name.
            if (words.size() < 3) p.fail("expected '<frame> key_down|key_up <SDL key name>'");
            const std::string_view name(words[2].data(), std::size_t(words.back().data() + words.back().size() - words[2].data()));
            events.push_back({frame, key_event(verb == "key_down", p.key(name))});
        } else if (verb == "wheel") {
            p.arity(words, 3, "<frame> wheel <steps>");
            SDL_Event e{};
            e.type = SDL_MOUSEWHEEL;
            e.wheel.y = p.integer(words[2], "steps");
            events.push_back({frame, e});
        } else if (verb == "drag") {
            p.arity(words, 7, "<frame> drag <x0> <y0> <x1> <y1> <frames>");
            const int x0 = p.integer(words[2], "x0");
            const int y0 = p.integer(words[3], "y0");
            const int x1 = p.integer(words[4], "x1");
            const int y1 = p.integer(words[5], "y1");
            const int n = p.integer(words[6], "frames");
            if (n < 1) p.fail("drag frames must be at least 1 (got " + std::to_string(n) + ")");
            // Move there, press a frame later (as a hand does), glide, release a frame after.
            events.push_back({frame, mouse_motion(x0, y0, buttons)});
            buttons |= SDL_BUTTON(SDL_BUTTON_LEFT);
            events.push_back({frame + 1, mouse_button(true, SDL_BUTTON_LEFT, x0, y0)});
            for (int i = 1; i <= n; ++i) {
                const double t = double(i) / n;
                const int x = int(std::lround(x0 + (x1 - x0) * t));
                const int y = int(std::lround(y0 + (y1 - y0) * t));
                events.push_back({frame + 1 + i, mouse_motion(x, y, buttons)});
            }
            buttons &= ~SDL_BUTTON(SDL_BUTTON_LEFT);
            events.push_back({frame + n + 2, mouse_button(false, SDL_BUTTON_LEFT, x1, y1)});
            mouse_x = x1;
            mouse_y = y1;
            last_frame = frame + n + 2;
        } else {
            p.fail("unknown event '" + std::string(verb) + "' (expected move, down, up, key_down, key_up, wheel or drag)");
        }
    }
    return events;
}

std::vector<ScriptEvent> load_script(const std::string& path) {
    std::error_code ec;
    // A folder opens as a stream that reads nothing: it would pass as an empty script.
    if (std::filesystem::is_directory(path, ec)) throw Error("--script: '" + path + "' is a folder, not a script file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("--script: cannot read '" + path + "'");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_script(text.str(), path);
}

}  // namespace grape::studio
