// grape — sweeping a 2-D profile along framed 3-D paths, rings placed by the chord error.
#include <grape/error.hpp>
#include <grape/sweep3.hpp>

#include "math/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace grape {
namespace {

// The profile point p placed in the frame f.
Vec3 place_sw3(const Frame3& f, Vec2 p) noexcept { return f.point + f.normal * p.x + f.binormal * p.y; }

double segment_gap_sw3(Vec3 q, Vec3 a, Vec3 b) noexcept {
    const Vec3 d = b - a;
    const double dd = dot(d, d);
    const double t = dd > 0.0 ? std::clamp(dot(q - a, d) / dd, 0.0, 1.0) : 0.0;
    return distance(q, a + d * t);
}

struct Sweeper3 {
    const Frames3& frames;
    const SweepDef& def;
    std::size_t edges;  // profile edges: n for a closed profile, n − 1 for an open one

    std::size_t next(std::size_t j) const noexcept { return (j + 1) % def.profile.size(); }

    // Does the step [a, b] keep the faces within tolerance of the true surface? Each column's
    // chord is checked against the true ring vertex at a quarter, half and three quarters of
    // the step (the true edge between two columns is within the worse of the two of the
    // bilinear patch through the four corners), and each face's two triangles are checked
    // against that patch: they part at its centre by the quad's twist, the part of
    // ¼(A_j + B_j+1 − A_j+1 − B_j) along the face's normal.
    bool fits(double a, double b) const noexcept {
        const Frame3 fa = frames.frame(a), fb = frames.frame(b);
        const Frame3 fm[3] = {frames.frame(a + (b - a) * 0.25), frames.frame(0.5 * (a + b)), frames.frame(a + (b - a) * 0.75)};
        auto column_error = [&](std::size_t j) noexcept {
            const Vec2 p = def.profile[j];
            const Vec3 pa = place_sw3(fa, p), pb = place_sw3(fb, p);
            double worst = 0.0;
            for (const Frame3& f : fm) worst = std::max(worst, segment_gap_sw3(place_sw3(f, p), pa, pb));
            return worst;
        };
        double first = column_error(0), previous = first;
        if (first > def.tolerance) return false;
        for (std::size_t j = 0; j < edges; ++j) {
            const std::size_t k = next(j);
            const double here = k == 0 ? first : column_error(k);
            const Vec3 a0 = place_sw3(fa, def.profile[j]), a1 = place_sw3(fa, def.profile[k]);
            const Vec3 b0 = place_sw3(fb, def.profile[j]), b1 = place_sw3(fb, def.profile[k]);
            const Vec3 face = normalized(cross(b1 - a0, b0 - a1));  // across the diagonals
            const double twist = std::abs(dot((a0 + b1 - a1 - b0) * 0.25, face));
            if (std::max(previous, here) + twist > def.tolerance) return false;
            previous = here;
        }
        return true;
    }
};

}  // namespace

std::vector<Vec2> circle_profile(double radius, int sides) {
    if (!(std::isfinite(radius) && radius > 0.0)) {
        throw Error("circle_profile: radius: must be finite and > 0, got " + detail::number_text(radius));
    }
    if (sides < 3 || sides > (1 << 20)) throw Error("circle_profile: sides: must be in [3, 2^20], got " + std::to_string(sides));
    std::vector<Vec2> out;
    out.reserve(static_cast<std::size_t>(sides));
    for (int k = 0; k < sides; ++k) {
        const double a = 2.0 * pi * k / sides;
        out.push_back({radius * std::cos(a), radius * std::sin(a)});
    }
    return out;
}

Mesh3 sweep(const Frames3& frames, const SweepDef& def) {
    const std::string where = "sweep: ";
    const std::size_t n = def.profile.size();
    if (n < (def.closed_profile ? 3u : 2u)) {
        throw Error(where + "profile: needs at least " + (def.closed_profile ? "3 points (closed)" : "2 points") + ", got " +
                    std::to_string(n));
    }
    for (std::size_t j = 0; j < n; ++j) {
        if (!std::isfinite(def.profile[j].x) || !std::isfinite(def.profile[j].y)) {
            throw Error(where + "profile[" + std::to_string(j) + "]: not finite");
        }
    }
    if (!(std::isfinite(def.tolerance) && def.tolerance > 0.0)) {
        throw Error(where + "tolerance: must be finite and > 0, got " + detail::number_text(def.tolerance));
    }
    if (def.max_rings < 2) throw Error(where + "max_rings: must be at least 2");
    if (n > (std::size_t{1} << 20)) throw Error(where + "profile: at most 2^20 points");
    const Sweeper3 sw{frames, def, def.closed_profile ? n : n - 1};
    const Path3& path = frames.path();

    // Rings: every break, each piece first cut in 8, then steps bisected until they fit.
    std::vector<double> rings{0.0};
    const auto breaks = path.breaks();
    struct Step {
        double a, b;
        int depth;
    };
    std::vector<Step> stack;
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
        for (int c = 7; c >= 0; --c) {
            stack.push_back({breaks[k] + (breaks[k + 1] - breaks[k]) * c / 8.0,
                             c == 7 ? breaks[k + 1] : breaks[k] + (breaks[k + 1] - breaks[k]) * (c + 1) / 8.0, 0});
        }
        while (!stack.empty()) {
            const Step st = stack.back();
            stack.pop_back();
            const double m = 0.5 * (st.a + st.b);
            // 48 halvings: a step of 2⁻⁴⁸ of a piece is beyond any tolerance's reach.
            if (st.depth >= 48 || m <= st.a || m >= st.b || sw.fits(st.a, st.b)) {
                if (rings.size() >= def.max_rings) {
                    throw Error(where + "tolerance: " + detail::number_text(def.tolerance) + " needs more than max_rings = " +
                                std::to_string(def.max_rings) + " rings (near u = " + detail::number_text(st.a) + ")");
                }
                rings.push_back(st.b);
                continue;
            }
            stack.push_back({m, st.b, st.depth + 1});
            stack.push_back({st.a, m, st.depth + 1});
        }
    }

    // A closed seam: the path's ends meet and the frames there agree.
    const Frame3 f0 = frames.frame(0.0), f1 = frames.frame(1.0);
    const bool seam = rings.size() > 2 && distance(f0.point, f1.point) <= 1e-9 * std::max(path.length(), 1e-300) &&
                      distance(f0.normal, f1.normal) <= 1e-9 && distance(f0.tangent, f1.tangent) <= 1e-9;
    if (seam) rings.pop_back();

    // The profile's vertex normals (edges' outward normals (e.y, −e.x), averaged) and its u.
    std::vector<Vec2> normal2(n);
    std::vector<double> along(n, 0.0);
    double perimeter = 0.0;
    for (std::size_t j = 0; j < sw.edges; ++j) {
        const Vec2 e = def.profile[sw.next(j)] - def.profile[j];
        const Vec2 en = normalized(Vec2{e.y, -e.x});
        normal2[j] += en;
        normal2[sw.next(j)] += en;
        perimeter += length(e);
        if (j + 1 < n) along[j + 1] = perimeter;
    }
    for (auto& v : normal2) v = normalized(v);

    Mesh3 mesh;
    mesh.ring_u = rings;
    mesh.ring_size = n;
    const std::size_t count = rings.size();
    mesh.positions.reserve(count * n);
    for (const double u : rings) {
        const Frame3 f = frames.frame(u);
        const double s = path.length_at(u);
        for (std::size_t j = 0; j < n; ++j) {
            mesh.positions.push_back(place_sw3(f, def.profile[j]));
            mesh.normals.push_back(normalized(f.normal * normal2[j].x + f.binormal * normal2[j].y));
            mesh.uv.push_back({perimeter > 0.0 ? along[j] / perimeter : 0.0, s});
        }
    }
    const std::size_t bands = seam ? count : count - 1;
    auto index = [&](std::size_t i, std::size_t j) { return static_cast<std::uint32_t>((i % count) * n + j); };
    for (std::size_t i = 0; i < bands; ++i) {
        for (std::size_t j = 0; j < sw.edges; ++j) {
            const std::uint32_t a = index(i, j), b = index(i, sw.next(j)), c = index(i + 1, j), d = index(i + 1, sw.next(j));
            // Profile direction × path direction is the outward normal of a counter-clockwise profile.
            mesh.triangles.push_back({a, b, c});
            mesh.triangles.push_back({b, d, c});
        }
    }
    if (def.caps && def.closed_profile && !seam) {
        for (const bool end : {false, true}) {
            const Frame3 f = frames.frame(end ? 1.0 : 0.0);
            const Vec3 normal = end ? f.tangent : -f.tangent;
            const auto centre = static_cast<std::uint32_t>(mesh.positions.size());
            mesh.positions.push_back(f.point);
            mesh.normals.push_back(normal);
            mesh.uv.push_back({0.0, 0.0});
            for (std::size_t j = 0; j < n; ++j) {
                mesh.positions.push_back(place_sw3(f, def.profile[j]));
                mesh.normals.push_back(normal);
                mesh.uv.push_back(def.profile[j]);
            }
            for (std::size_t j = 0; j < n; ++j) {
                const auto p = static_cast<std::uint32_t>(centre + 1 + j), q = static_cast<std::uint32_t>(centre + 1 + sw.next(j));
                // A counter-clockwise profile seen from +T: the end cap faces +T, the start −T.
                mesh.triangles.push_back(end ? std::array<std::uint32_t, 3>{centre, p, q} : std::array<std::uint32_t, 3>{centre, q, p});
            }
        }
    }
    return mesh;
}

std::string to_obj(const Mesh3& mesh) {
    auto num = [](double v) { return detail::general_text(v, 17); };
    std::string out = "# grape mesh: " + std::to_string(mesh.positions.size()) + " vertices, " +
                      std::to_string(mesh.triangles.size()) + " triangles\n";
    for (const Vec3 p : mesh.positions) out += "v " + num(p.x) + ' ' + num(p.y) + ' ' + num(p.z) + '\n';
    for (const Vec3 v : mesh.normals) out += "vn " + num(v.x) + ' ' + num(v.y) + ' ' + num(v.z) + '\n';
    for (const Vec2 t : mesh.uv) out += "vt " + num(t.x) + ' ' + num(t.y) + '\n';
    for (const auto& t : mesh.triangles) {
        out += 'f';
        for (const std::uint32_t i : t) {
            const std::string k = std::to_string(i + 1);
            out += ' ' + k + '/' + k + '/' + k;
        }
        out += '\n';
    }
    return out;
}

}  // namespace grape
