// Progress of a long run on stderr, shown only when stderr is a terminal (so pipes, logs and
// the tests see nothing) and only once the run has taken more than a second.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace grape::tool {

class Progress {
public:
    /// WHAT names the run ("simulate"); TOTAL is the number of units (steps, frames) it will do.
    Progress(std::string what, double total) : what_(std::move(what)), total_(total), shown_(isatty(STDERR_FILENO) == 1) {}
    ~Progress() { done(); }
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// DONE units finished; reads the clock only every 1024 calls, so it is cheap per step.
    void update(double done) {
        if (!shown_ || (++calls_ & 1023u) != 0) return;
        const auto now = std::chrono::steady_clock::now();
        if (now - last_ < std::chrono::seconds(1)) return;
        last_ = now;
        std::fprintf(stderr, "\r%s: %.0f of %.0f (%.0f%%)   ", what_.c_str(), done, total_, total_ > 0 ? 100.0 * done / total_ : 100.0);
        std::fflush(stderr);
        printed_ = true;
    }
    /// Clears the line once the run ends.
    void done() {
        if (printed_) std::fprintf(stderr, "\r%*s\r", static_cast<int>(what_.size()) + 48, "");
        printed_ = false;
    }

private:
    std::string what_;
    double total_;
    bool shown_;
    bool printed_ = false;
    unsigned calls_ = 0;
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace grape::tool
