// Progress of a long run on stderr, shown only when stderr is a terminal (so pipes, logs and
// the tests see nothing) and only once the run has taken more than a second.
#pragma once

#ifdef _WIN32
#include "internal/windows.hpp"
#else
#include <unistd.h>
#endif

#include <chrono>
#include <cstdio>
#include <string>
#include <utility>

namespace grape::tool {

class Progress {
public:
    /// WHAT names the run and its unit ("simulate: step"); TOTAL is the number of units (steps, frames) it will do;
    /// the clock is read every STRIDE updates (a power of two: 1 for slow units such as frames).
    Progress(std::string what, double total, unsigned stride = 1024)
        : what_(std::move(what)), total_(total), mask_(stride - 1), shown_(stderr_is_terminal()) {}
    ~Progress() { done(); }
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// DONE units finished; cheap per step (the clock is read every STRIDE calls).
    void update(double done) {
        if (!shown_ || (++calls_ & mask_) != 0) return;
        const auto now = std::chrono::steady_clock::now();
        if (now - last_ < std::chrono::seconds(1)) return;
        last_ = now;
        std::fprintf(stderr, "\r%s %.0f of %.0f (%.0f%%)   ", what_.c_str(), done, total_, total_ > 0 ? 100.0 * done / total_ : 100.0);
        std::fflush(stderr);
        printed_ = true;
    }
    /// Clears the line once the run ends.
    void done() {
        if (printed_) std::fprintf(stderr, "\r%*s\r", static_cast<int>(what_.size()) + 48, "");
        printed_ = false;
    }

private:
    static bool stderr_is_terminal() noexcept {
#ifdef _WIN32
        // A console, not merely a character device: _isatty is true for NUL too.
        DWORD mode = 0;
        return ::GetConsoleMode(::GetStdHandle(STD_ERROR_HANDLE), &mode) != 0;
#else
        return isatty(STDERR_FILENO) == 1;
#endif
    }

    std::string what_;
    double total_;
    unsigned mask_;
    bool shown_;
    bool printed_ = false;
    unsigned calls_ = 0;
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace grape::tool
