// Stagger offsets: GSAP's distribution of start times over items in a row or a grid.
#include <grape/stagger.hpp>

#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace grape {
namespace {

/// SplitMix64 (Steele, Lea, Flood 2014): fully specified, so a seed orders items the same
/// way on every platform, unlike the standard library's distributions.
struct SplitMix64 {
    std::uint64_t state;
    std::uint64_t next() noexcept {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, range) without modulo bias: draws below 2⁶⁴ mod range are rejected.
    std::uint64_t below(std::uint64_t range) noexcept {
        const std::uint64_t threshold = (0 - range) % range;
        for (;;) {
            const std::uint64_t x = next();
            if (x >= threshold) return x % range;
        }
    }
};

void check_finite(const std::optional<double>& value, const char* name) {
    if (value && !std::isfinite(*value))
        throw Error(std::string("stagger: ") + name + " must be finite (got " + detail::number_text(*value) + ")");
}

}  // namespace

void stagger_offsets(const StaggerDef& def, std::span<double> out) {
    if (def.each && def.amount) throw Error("stagger: give each or amount, not both");
    check_finite(def.each, "each");
    check_finite(def.amount, "amount");
    const std::size_t n = out.size();
    const bool grid = def.grid.columns > 0;
    if (!grid && def.grid.rows > 0) throw Error("stagger: grid.rows needs grid.columns > 0");
    if (n == 0) return;
    if (def.from == StaggerFrom::index && def.index >= n)
        throw Error("stagger: index must be < count (got index " + std::to_string(def.index) + " of " + std::to_string(n) + ")");
    const std::size_t columns = grid ? def.grid.columns : n;
    const std::size_t needed = n / columns + (n % columns != 0 ? 1 : 0);
    if (grid && def.grid.rows > 0 && def.grid.rows < needed)
        throw Error("stagger: grid " + std::to_string(columns) + " x " + std::to_string(def.grid.rows) + " holds fewer than " +
                    std::to_string(n) + " items");
    const double rows = !grid ? 1.0 : def.grid.rows > 0 ? static_cast<double>(def.grid.rows) : static_cast<double>(n) / static_cast<double>(columns);

    // The origin, in cells (column, row).
    double ox = 0.0;
    double oy = 0.0;
    if (def.from == StaggerFrom::index) {
        ox = static_cast<double>(def.index % columns);
        oy = grid ? static_cast<double>(def.index / columns) : 0.0;
    } else {
        const double r = def.from == StaggerFrom::end ? 1.0
                         : (def.from == StaggerFrom::center || def.from == StaggerFrom::edges) ? 0.5
                                                                                                 : 0.0;
        ox = static_cast<double>(std::min(columns, n)) * r - 0.5;
        oy = grid ? rows * r - 0.5 : 0.0;
    }
    double lo = std::numeric_limits<double>::infinity();
    double hi = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
        const double x = static_cast<double>(j % columns) - ox;
        const double y = oy - static_cast<double>(j / columns);
        const double d = def.axis == StaggerAxis::x ? std::abs(x) : def.axis == StaggerAxis::y ? std::abs(y) : std::hypot(x, y);
        out[j] = d;
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
    if (def.from == StaggerFrom::random) {  // Fisher–Yates, from the end
        SplitMix64 rng{def.seed};
        for (std::size_t j = n - 1; j > 0; --j) std::swap(out[j], out[rng.below(j + 1)]);
    }

    // The total spread V.
    double spread = 0.0;
    if (def.amount) {
        spread = *def.amount;
    } else if (def.each) {
        const double count = static_cast<double>(n);
        const double c = static_cast<double>(columns);
        double span = 0.0;
        if (!grid || columns > n) span = count - 1.0;
        else if (def.axis == StaggerAxis::both) span = std::max(c, count / c);
        else if (def.axis == StaggerAxis::y) span = count / c;
        else span = c;
        spread = *def.each * span;
    }
    if (def.from == StaggerFrom::edges) spread = -spread;

    // Backwards spreads start at |V| and count down along the mirrored curve, so the farthest
    // items start first at 0 (GSAP inverts the ease the same way).
    const double range = hi - lo;
    const bool linear = def.curve.kind() == CurveKind::linear;
    for (std::size_t j = 0; j < n; ++j) {
        const double t = range > 0.0 ? (out[j] - lo) / range : 0.0;
        if (spread >= 0.0) out[j] = spread * (linear ? t : def.curve(t));
        else out[j] = -spread * (linear ? 1.0 - t : def.curve(1.0 - t));
    }
}

std::vector<double> stagger_offsets(std::size_t count, const StaggerDef& def) {
    std::vector<double> offsets(count);
    stagger_offsets(def, offsets);
    return offsets;
}

}  // namespace grape
