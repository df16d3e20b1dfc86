// grape — equal arc-length sampling of 3-D paths.
#include <grape/error.hpp>
#include <grape/path3_sample.hpp>

#include <cmath>
#include <string>

namespace grape {

std::vector<double> equal_length_u(const Path3& path, std::size_t count) {
    if (count > max_samples3) {
        throw Error("equal_length_u: count: at most " + std::to_string(max_samples3) + ", got " + std::to_string(count));
    }
    std::vector<double> u;
    u.reserve(count);
    if (count == 1) u.push_back(0.0);
    if (count < 2) return u;
    const double total = path.length();
    for (std::size_t i = 0; i < count; ++i) {
        // The ends exactly; between, the share of the length.
        u.push_back(i == 0 ? 0.0 : i + 1 == count ? 1.0 : path.u_at_length(total * (static_cast<double>(i) / static_cast<double>(count - 1))));
    }
    return u;
}

std::vector<double> spaced_u(const Path3& path, double spacing) {
    if (!(std::isfinite(spacing) && spacing > 0.0)) {
        throw Error("spaced_u: spacing: must be finite and > 0, got " + detail::number_text(spacing));
    }
    const double total = path.length();
    // Multiples within a rounding of the length count as reaching it.
    const double n = std::floor(total / spacing * (1.0 + 1e-15));
    if (!(n < static_cast<double>(max_samples3))) {
        throw Error("spaced_u: spacing: " + detail::number_text(spacing) + " gives more than " +
                    std::to_string(max_samples3) + " points along a length of " + detail::number_text(total));
    }
    const auto count = static_cast<std::size_t>(n) + 1;
    std::vector<double> u;
    u.reserve(count);
    for (std::size_t i = 0; i < count; ++i) u.push_back(i == 0 ? 0.0 : path.u_at_length(spacing * static_cast<double>(i)));
    return u;
}

std::vector<Frame3> frames_at(const Frames3& frames, std::span<const double> u) {
    std::vector<Frame3> out;
    out.reserve(u.size());
    for (const double v : u) out.push_back(frames.frame(v));
    return out;
}

}  // namespace grape
