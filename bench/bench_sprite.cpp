// 1,000,000 sprite players advanced once per game frame: ns per player, grape against the
// plain compare-and-subtract accumulator a game would write doing the same work (the same
// frames, and the same show_frame call when the frame changes), in one run with ratios.
//
//   build-bench/bench/bench_sprite [--rounds R] [--players N]
//
// Contenders run round-robin, R rounds (default 7) of one timed pass over the players each
// (passes repeated up to 10^6 player steps when N is smaller), after a warm-up pass; each row
// reports the median and the min–max over the rounds, in thread CPU time. 10^6 players (48 MB of SpritePlayers)
// stream from memory; 10^4 stay in the cache and measure the step's own work. Rates are random in
// (−15.5, 15.5) for the uniform players (16-frame loop) and in (−4, 4) for the clip players
// (a 16-frame clip with durations 40–200 ms, 1/60 s per game frame).
#include <grape/sprite.hpp>

#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {

std::size_t players = 1'000'000;  // --players
constexpr std::size_t frames = 16;
constexpr double dt = 1.0 / 60.0;

std::vector<double> random_rates(double limit, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> rate(-limit, limit);
    std::vector<double> r(players);
    for (double& x : r) x = rate(rng);
    return r;
}

template <class T>
void keep(const T& value) {
    asm volatile("" : : "r,m"(value) : "memory");
}

// ------------------------------------------------------------ uniform: frames per step

// The peer: the frame is trunc of a double accumulator kept in (−n, n) by one compare and
// subtract each way, exactly SpritePlayer's frames (start + trunc(rate·k), wrapped).
struct Accumulator {
    double position = 0.0;
    double rate = 0.0;
    std::int32_t count = static_cast<std::int32_t>(frames);
    std::int32_t frame = 0;
    grape::Playable* playable = nullptr;

    void advance() noexcept {
        double p = position + rate;
        const double n = count;
        p -= p >= n ? n : 0.0;
        p += p <= -n ? n : 0.0;
        position = p;
        std::int32_t f = static_cast<std::int32_t>(p);
        f += f < 0 ? count : 0;
        if (playable && f != frame) playable->show_frame(static_cast<std::size_t>(f));
        frame = f;
    }
};

// A Playable that only records the frame (the cheapest real show_frame).
struct Counter final : grape::Playable {
    std::size_t shown = 0;
    std::size_t frame_count() const noexcept override { return frames; }
    void show_frame(std::size_t k) noexcept override { shown = k; }
};

// ------------------------------------------------------------ clips: per-frame durations

std::vector<double> random_durations() {
    std::mt19937_64 rng(11);
    std::vector<double> d(frames);
    for (double& x : d) x = static_cast<double>(std::uniform_int_distribution<int>(40, 200)(rng));
    return d;
}

grape::SpriteSheet clip_sheet() {
    const auto durations = random_durations();
    grape::SpriteSheetDef def{.width = 16 * static_cast<int>(frames), .height = 16};
    for (std::size_t k = 0; k < frames; ++k) {
        def.frames.push_back({.rect = {16 * static_cast<int>(k), 0, 16, 16}, .duration_ms = durations[k]});
    }
    def.clips = {{.name = "loop", .from = 0, .to = frames - 1}};
    return grape::SpriteSheet(std::move(def));
}

// The peer with durations: time into the frame, compare and subtract the frame's duration
// (several frames per step at high rates), wrapping the index at both ends.
struct DurationAccumulator {
    double time = 0.0;
    double rate = 0.0;
    const double* durations = nullptr;
    std::int32_t count = static_cast<std::int32_t>(frames);
    std::int32_t frame = 0;

    void advance(double step) noexcept {
        double t = time + rate * step * 1000.0;
        double d = durations[frame];
        if (t >= 0.0 && t < d) {
            time = t;
            return;
        }
        while (t >= d) {
            t -= d;
            frame = frame + 1 == count ? 0 : frame + 1;
            d = durations[frame];
        }
        while (t < 0.0) {
            frame = frame == 0 ? count - 1 : frame - 1;
            t += durations[frame];
        }
        time = t;
    }
};

// ------------------------------------------------------------------------ the contenders

struct Contender {
    const char* name;
    const char* peer_of;  // the row this one is the peer of ("" for grape's rows)
    std::function<void()> pass;
    std::vector<double> ns;
};

// This thread's CPU time: on a shared machine, time spent descheduled is not counted.
double cpu_ns() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    int rounds = 7;
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::strcmp(argv[i], "--rounds") == 0) rounds = std::max(1, std::atoi(argv[i + 1]));
        if (std::strcmp(argv[i], "--players") == 0) players = static_cast<std::size_t>(std::max(1, std::atoi(argv[i + 1])));
    }
    const auto rates = random_rates(static_cast<double>(frames) - 0.5, 7);
    const auto clip_rates = random_rates(4.0, 9);

    std::vector<grape::SpritePlayer> counters;
    std::vector<Accumulator> counter_peers(players);
    std::vector<Counter> shown(players), shown_peer(players);
    std::vector<grape::SpritePlayer> sheets;
    std::vector<Accumulator> sheet_peers(players);
    std::vector<grape::SpritePlayer> timed;
    counters.reserve(players);
    sheets.reserve(players);
    timed.reserve(players);
    for (std::size_t i = 0; i < players; ++i) {
        counters.emplace_back(frames, grape::SpritePlayerDef{.rate = rates[i]});
        counter_peers[i].rate = rates[i];
        sheets.emplace_back(shown[i], grape::SpritePlayerDef{.rate = rates[i]});
        sheet_peers[i].rate = rates[i];
        sheet_peers[i].playable = &shown_peer[i];
        timed.emplace_back(frames, grape::SpritePlayerDef{.rate = clip_rates[i] * 24.0 / 60.0});
    }
    const grape::SpriteSheet sheet = clip_sheet();
    const auto durations = random_durations();
    std::vector<grape::ClipPlayer> clips;
    std::vector<DurationAccumulator> clip_peers(players);
    clips.reserve(players);
    for (std::size_t i = 0; i < players; ++i) {
        clips.emplace_back(sheet, std::size_t{0}, grape::ClipPlayerDef{.rate = clip_rates[i]});
        clip_peers[i].rate = clip_rates[i];
        clip_peers[i].durations = durations.data();
        clip_peers[i].time = clip_rates[i] < 0 ? durations[0] * 0.5 : 0.0;
    }

    std::vector<Contender> all = {
        {"grape SpritePlayer::advance(), frame counter", "", [&] { for (auto& p : counters) p.advance(); keep(counters.back()); }, {}},
        {"peer: compare-and-subtract accumulator", "grape SpritePlayer::advance(), frame counter",
         [&] { for (auto& p : counter_peers) p.advance(); keep(counter_peers.back()); }, {}},
        {"grape SpritePlayer::advance() + Playable", "", [&] { for (auto& p : sheets) p.advance(); keep(shown.back()); }, {}},
        {"peer: accumulator + show_frame on change", "grape SpritePlayer::advance() + Playable",
         [&] { for (auto& p : sheet_peers) p.advance(); keep(shown_peer.back()); }, {}},
        {"grape SpritePlayer::advance(dt, fps), uniform 24 fps", "", [&] { for (auto& p : timed) p.advance(dt, 24); keep(timed.back()); }, {}},
        {"grape ClipPlayer::advance(dt), per-frame durations", "", [&] { for (auto& p : clips) p.advance(dt); keep(clips.back()); }, {}},
        {"peer: duration accumulator (compare and subtract)", "grape ClipPlayer::advance(dt), per-frame durations",
         [&] { for (auto& p : clip_peers) p.advance(dt); keep(clip_peers.back()); }, {}},
    };
    for (auto& c : all) c.pass();  // warm-up: pages touched, branch history
    const std::size_t repeats = std::max<std::size_t>(1, 1'000'000 / players);
    for (int r = 0; r < rounds; ++r) {
        for (auto& c : all) {
            const double t0 = cpu_ns();
            for (std::size_t k = 0; k < repeats; ++k) c.pass();
            c.ns.push_back((cpu_ns() - t0) / double(players * repeats));
        }
    }
    std::printf("%zu players, %d rounds round-robin; sizeof SpritePlayer %zu, ClipPlayer %zu, peers %zu and %zu bytes\n",
                players, rounds, sizeof(grape::SpritePlayer), sizeof(grape::ClipPlayer), sizeof(Accumulator),
                sizeof(DurationAccumulator));
    std::printf("%-55s %9s %17s %s\n", "contender", "ns/player", "min-max", "ratio");
    for (const auto& c : all) {
        const double m = median(c.ns);
        const auto [lo, hi] = std::minmax_element(c.ns.begin(), c.ns.end());
        std::string ratio;
        for (const auto& other : all) {
            if (std::strcmp(c.peer_of, other.name) == 0) {
                char text[96];
                std::snprintf(text, sizeof text, "grape / peer = %.2f", median(other.ns) / m);
                ratio = text;
            }
        }
        std::printf("%-55s %9.3f %8.3f-%-8.3f %s\n", c.name, m, *lo, *hi, ratio.c_str());
    }
    return 0;
}
