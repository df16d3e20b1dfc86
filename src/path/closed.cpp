// grape — closed loops: splines whose seam wraps around, and the test for ends that meet.
#include <grape/error.hpp>
#include <grape/path_query.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace grape {

namespace {

[[noreturn]] void loop_fail(const char* who, const std::string& what) { throw Error(std::string(who) + ": " + what); }

std::vector<Vec2> loop_points(const char* who, std::span<const Vec2> points) {
    if (points.size() < 3) loop_fail(who, "points needs at least 3 points for a loop (got " + std::to_string(points.size()) + ")");
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!is_finite(points[i])) loop_fail(who, "points[" + std::to_string(i) + "] must be finite");
    }
    std::vector<Vec2> loop(points.begin(), points.end());
    loop.push_back(points.front());
    return loop;
}

}  // namespace

bool closed(const Path& path) noexcept {
    const Vec2 size = path.bounds().size();
    return distance(path.point(0.0), path.point(1.0)) <= 1e-12 * std::max(std::abs(size.x), std::abs(size.y));
}

Path closed_cosine_spline(std::span<const Vec2> points) {
    const std::vector<Vec2> loop = loop_points("closed_cosine_spline", points);
    return CosineSplinePath(std::span<const Vec2>(loop));
}

Path closed_hermite_spline(std::span<const Vec2> points, std::span<const Vec2> tangents) {
    const char* who = "closed_hermite_spline";
    const std::vector<Vec2> loop = loop_points(who, points);
    if (tangents.size() != points.size()) {
        loop_fail(who, "tangents needs one tangent per point (got " + std::to_string(tangents.size()) + " tangents for " +
                      std::to_string(points.size()) + " points)");
    }
    std::vector<Vec2> t(tangents.begin(), tangents.end());
    t.push_back(tangents.front());
    return HermiteSplinePath(std::span<const Vec2>(loop), std::span<const Vec2>(t));
}

Path closed_catmull_rom_spline(std::span<const Vec2> points, CatmullRom type) {
    const char* who = "closed_catmull_rom_spline";
    if (type != CatmullRom::uniform && type != CatmullRom::centripetal && type != CatmullRom::chordal) {
        loop_fail(who, "type must be uniform, centripetal or chordal (got " + std::to_string(static_cast<int>(type)) + ")");
    }
    const std::vector<Vec2> loop = loop_points(who, points);
    const std::size_t n = points.size();
    auto at = [&](std::size_t i) { return points[i % n]; };
    if (type == CatmullRom::uniform) {
        std::vector<Vec2> tangents(n + 1);
        for (std::size_t i = 0; i <= n; ++i) tangents[i] = 0.5 * (at(i + 1) - at(i + n - 1));
        return HermiteSplinePath(std::span<const Vec2>(loop), std::span<const Vec2>(tangents));
    }
    // Barry–Goldman tangents with knot spacing |Δp|^α (as CatmullRomSplinePath, neighbours
    // wrapped instead of mirrored), each segment scaled to its local t by its own spacing.
    const double alpha = type == CatmullRom::centripetal ? 0.5 : 1.0;
    auto spacing = [alpha](Vec2 a, Vec2 b) {
        const double d = std::pow(distance(a, b), alpha);
        return d > 0.0 ? d : 1.0;
    };
    std::vector<Path> parts;
    std::vector<double> cues;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 p0 = at(i + n - 1), p1 = at(i), p2 = at(i + 1), p3 = at(i + 2);
        const double d01 = spacing(p0, p1), d12 = spacing(p1, p2), d23 = spacing(p2, p3);
        const Vec2 m1 = ((p1 - p0) / d01 - (p2 - p0) / (d01 + d12) + (p2 - p1) / d12) * d12;
        const Vec2 m2 = ((p2 - p1) / d12 - (p3 - p1) / (d12 + d23) + (p3 - p2) / d23) * d12;
        parts.push_back(CubicBezierPath(p1, p1 + m1 / 3.0, p2 - m2 / 3.0, p2));  // Hermite as Bézier
        cues.push_back(static_cast<double>(i) / static_cast<double>(n));
    }
    return ComplexPath(std::move(parts), std::move(cues));
}

}  // namespace grape
