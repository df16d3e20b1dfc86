// Scripted input: a small text file of timed mouse and key events, fed into SDL's event
// queue at the frames they name, so a headless run can drag, click and type like a person.
//
//   # frame  event     arguments          (window pixels; '#' starts a comment)
//   10       move      400 300            mouse moves to (400, 300)
//   11       down      left               button pressed where the mouse is (left|right|middle)
//   20       up        left
//   30       key_down  Space              SDL scancode names: A, Left, Space, Return, Left Ctrl, ...
//   31       key_up    Space
//   40       wheel     -1                 wheel steps (positive: away from the user)
//   50       drag      400 300 600 200 20 press at the first point, move over 20 frames, release
//
// Lines must come in non-decreasing frame order.
#pragma once

#include <SDL.h>

#include <string>
#include <string_view>
#include <vector>

namespace grape::studio {

/// One event of a script, due at the start of `frame` (0-based).
struct ScriptEvent {
    int frame = 0;
    SDL_Event event{};
};

/// Parses a script (after SDL_Init, so key codes follow the keyboard layout); throws grape::Error naming `source:line` and the reason.
std::vector<ScriptEvent> parse_script(std::string_view text, std::string_view source = "script");
/// Reads and parses a script file; throws grape::Error if it cannot be read or parsed.
std::vector<ScriptEvent> load_script(const std::string& path);

}  // namespace grape::studio
