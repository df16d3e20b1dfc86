// A reference model of clip playback for the sprite tests, written apart from ClipPlayer: it
// unrolls a clip pass by pass as Aseprite describes its tags (a ping-pong pass is one
// direction; later passes leave out the frame they share with the previous one) and finds the
// step shown at an elapsed time by searching the cumulative durations in integer arithmetic.
// Times are N / scale milliseconds for an integer N.
#pragma once

#include <grape/sprite.hpp>

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <vector>

namespace grape::testing {

struct Shown {
    std::size_t frame;
    std::int64_t pass;
};

// Aseprite's playback of a tag, pass by pass.
inline std::vector<Shown> unroll(const SpriteClip& clip, std::int64_t passes) {
    std::vector<Shown> out;
    const bool bounce = clip.direction == ClipDirection::ping_pong || clip.direction == ClipDirection::ping_pong_reverse;
    for (std::int64_t p = 0; p < passes; ++p) {
        bool up = clip.direction == ClipDirection::forward || clip.direction == ClipDirection::ping_pong;
        if (bounce && p % 2 == 1) up = !up;
        std::vector<std::size_t> run;
        for (std::size_t f = clip.from; f <= clip.to; ++f) run.push_back(f);
        if (!up) std::reverse(run.begin(), run.end());
        if (bounce && p > 0 && run.size() > 1) run.erase(run.begin());
        for (std::size_t f : run) out.push_back({f, p});
    }
    return out;
}

struct RefEvent {
    ClipEventKind kind;
    std::size_t frame;
    std::int64_t pass;
    friend bool operator==(const RefEvent&, const RefEvent&) = default;
};

inline std::ostream& operator<<(std::ostream& os, const RefEvent& e) {
    const char* names[] = {"frame", "loop", "complete", "switched"};
    return os << names[static_cast<int>(e.kind)] << "(" << e.frame << ", pass " << e.pass << ")";
}

// Plays one clip from its start (its end, backwards): the step shown at elapsed time N / S ms
// is j with cum[j] <= t < cum[j+1] going forwards, cum[j] < t <= cum[j+1] going backwards.
struct Reference {
    std::vector<Shown> seq;
    std::vector<std::int64_t> cum;  // cum[j]: ms before step j
    bool finite = false;
    bool backward = false;
    std::size_t at = 0;  // the step shown
    bool done = false;

    // A clip forever is unrolled for `passes_if_forever` passes (enough for the run).
    Reference(const SpriteSheet& sheet, const SpriteClip& clip, std::int64_t passes_if_forever, bool backwards)
        : finite(clip.repeat > 0), backward(backwards) {
        seq = unroll(clip, finite ? clip.repeat : passes_if_forever);
        cum.push_back(0);
        for (const Shown& s : seq) cum.push_back(cum.back() + static_cast<std::int64_t>(sheet.frame(s.frame).duration_ms));
        at = backward ? seq.size() - 1 : 0;
    }
    std::int64_t total() const { return cum.back(); }
    std::size_t frame() const { return seq[at].frame; }

    // Moves to elapsed time n / s ms since the start and returns the events on the way.
    std::vector<RefEvent> play_to(std::int64_t n, std::int64_t s) {
        std::vector<RefEvent> want;
        if (done) return want;
        if (!backward) {
            const bool end = finite && n >= total() * s;
            std::size_t next = at;
            if (end) {
                next = seq.size() - 1;
            } else {
                while (next + 1 < seq.size() && cum[next + 1] * s <= n) ++next;
            }
            for (std::size_t j = at + 1; j <= next; ++j) {
                if (seq[j].pass != seq[j - 1].pass) want.push_back({ClipEventKind::loop, seq[j].frame, seq[j].pass});
                want.push_back({ClipEventKind::frame, seq[j].frame, seq[j].pass});
            }
            if (end) want.push_back({ClipEventKind::complete, seq[next].frame, seq[next].pass});
            at = next;
            done = end;
        } else {
            const std::int64_t t = total() * s - n;
            const bool end = t <= 0;
            std::size_t next = at;
            if (end) {
                next = 0;
            } else {
                while (next > 0 && cum[next] * s >= t) --next;
            }
            for (std::size_t j = at; j-- > next;) {
                if (seq[j].pass != seq[j + 1].pass) want.push_back({ClipEventKind::loop, seq[j].frame, seq[j].pass});
                want.push_back({ClipEventKind::frame, seq[j].frame, seq[j].pass});
            }
            if (end) want.push_back({ClipEventKind::complete, seq[next].frame, seq[next].pass});
            at = next;
            done = end;
        }
        return want;
    }
};

}  // namespace grape::testing
