// sweep3: swept meshes against independent truth — a tube about a helix checked with the
// helix's closed form (every vertex at distance r from the centre line, chords between rings
// within the tolerance of the true tube, by a nearest-point search on the closed form written
// here), the topology of closed seams (vertex and triangle counts, every edge shared by two
// triangles), normals, an OBJ round trip, and the rings uniform spacing needs for the same error.
#include <grape/error.hpp>
#include <grape/frames3.hpp>
#include <grape/path3.hpp>
#include <grape/sweep3.hpp>

#include "error_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <locale>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace grape;
using grape::testing::expect_error;

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

// The test's helix, closed form: p(θ) = (R cos θ, R sin θ, cθ), θ = 2π·turns·u.
constexpr double HR = 2.0, Hc = 0.3, Hturns = 3.0;
Vec3 helix_at(double th) { return {HR * std::cos(th), HR * std::sin(th), Hc * th}; }
Vec3 helix_d1(double th) { return {-HR * std::sin(th), HR * std::cos(th), Hc}; }
Vec3 helix_d2(double th) { return {-HR * std::cos(th), -HR * std::sin(th), 0.0}; }

// Distance from q to the helix by Newton on (p − q)·p′ = 0 from θ0 (the nearest point is
// near the chord's rings, well inside a convex valley as r ≪ the radius of curvature).
double helix_distance(Vec3 q, double th) {
    for (int i = 0; i < 50; ++i) {
        const Vec3 e = helix_at(th) - q, d1 = helix_d1(th);
        const double g = dot(e, d1), dg = dot(d1, d1) + dot(e, helix_d2(th));
        const double step = g / dg;
        th -= step;
        if (std::abs(step) < 1e-16) break;
    }
    return distance(helix_at(th), q);
}

// Each undirected edge's count of triangles: a closed (watertight) mesh has 2 for every edge.
std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_uses(const Mesh3& m) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const auto& t : m.triangles) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[k], b = t[(k + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    return uses;
}

// The worst distance from the chords between rings (at a quarter, half, three quarters) to the
// true swept surface, for a tube: |distance to the centre line − r|.
double tube_chord_error(const Mesh3& m, double r) {
    double worst = 0.0;
    for (std::size_t i = 0; i + 1 < m.ring_u.size(); ++i) {
        const double th = two_pi * Hturns * 0.5 * (m.ring_u[i] + m.ring_u[i + 1]);
        for (std::size_t j = 0; j < m.ring_size; ++j) {
            const Vec3 a = m.positions[i * m.ring_size + j], b = m.positions[(i + 1) * m.ring_size + j];
            for (const double w : {0.25, 0.5, 0.75}) worst = std::max(worst, std::abs(helix_distance(lerp(a, b, w), th) - r));
        }
    }
    return worst;
}

}  // namespace

// A tube of r = 0.25 (16 sides) about the 3-turn helix. Each vertex is p(u) + r·(cos·N +
// sin·B): its distance from p(u) is r to the rounding of coordinates ≲ 4 (a few ulp of 4 ≈
// 1e-15) and of the unit frame (1e-16·r), so 1e-13 leaves room; it lies in the normal plane
// (its offset ⟂ T) to the same. The chords between rings stay within the tolerance of the
// tube (|distance to the centre line − r|, found here on the closed form). Normals are unit
// and radial: the mean of two edge normals of a regular polygon points at its vertex.
TEST(Sweep3, HelixTube) {
    const Path3 h = Path3::helix({.radius = HR, .rise = two_pi * Hc, .turns = Hturns});
    const double r = 0.25;
    for (const double tol : {1e-2, 1e-3, 1e-4}) {
        const Frames3 fr(h, {.up = {-1, 0, 0}});
        const Mesh3 m = sweep(fr, {.profile = circle_profile(r, 16), .tolerance = tol});
        ASSERT_EQ(m.ring_size, 16u);
        ASSERT_EQ(m.positions.size(), m.ring_u.size() * 16);
        double worst_radius = 0.0, worst_plane = 0.0, worst_normal = 0.0;
        for (std::size_t i = 0; i < m.ring_u.size(); ++i) {
            const double th = two_pi * Hturns * m.ring_u[i];
            const Vec3 c = helix_at(th), t = normalized(helix_d1(th));
            for (std::size_t j = 0; j < 16; ++j) {
                const Vec3 v = m.positions[i * 16 + j], n = m.normals[i * 16 + j];
                worst_radius = std::max(worst_radius, std::abs(distance(v, c) - r));
                worst_plane = std::max(worst_plane, std::abs(dot(v - c, t)));
                worst_normal = std::max({worst_normal, std::abs(length(n) - 1.0), distance(n, (v - c) / r)});
            }
        }
        EXPECT_LE(worst_radius, 1e-13);
        EXPECT_LE(worst_plane, 1e-13);
        EXPECT_LE(worst_normal, 1e-13);
        const double chord = tube_chord_error(m, r);
        EXPECT_LE(chord, tol);
        EXPECT_GT(chord, tol / 16);  // not wastefully fine either: the error is h²-like, so ¼ of h would do
        EXPECT_EQ(m.triangles.size(), 2 * 16 * (m.ring_u.size() - 1));
        std::printf("helix tube, tolerance %g: %zu rings, chord error %.3g, radius within %.2g, normals within %.2g\n", tol,
                    m.ring_u.size(), chord, worst_radius, worst_normal);
    }
}

// A closed path with frames that close (mode closed) and a closed profile: the last ring is
// the first and the last column the first, so V = rings·sides, T = 2·rings·sides, and every
// edge is shared by exactly two triangles (no seam anywhere). Open with caps: watertight too.
TEST(Sweep3, ClosedSeamsShareVertices) {
    const Vec3 pts[] = {{0, 0, 0}, {4, 0, 1}, {5, 3, -1}, {1, 4, 0.5}, {-1, 2, 2}};
    const Path3 loop = Path3::catmull_rom(pts, CatmullRom::centripetal, true);
    const Frames3 fr(loop, {.mode = FrameMode::closed, .up = {0, 0, 1}});
    const int sides = 12;
    const Mesh3 m = sweep(fr, {.profile = circle_profile(0.3, sides), .tolerance = 1e-3});
    const std::size_t rings = m.ring_u.size();
    EXPECT_EQ(m.positions.size(), rings * sides);
    EXPECT_EQ(m.triangles.size(), 2 * rings * sides);
    EXPECT_LT(m.ring_u.back(), 1.0);
    for (const auto& [edge, n] : edge_uses(m)) ASSERT_EQ(n, 2) << edge.first << '-' << edge.second;
    // Euler characteristic of a torus: V − E + F = 0.
    EXPECT_EQ(static_cast<long>(m.positions.size()) - static_cast<long>(edge_uses(m).size()) +
                  static_cast<long>(m.triangles.size()),
              0);
    // An RMF on the same loop does not close (holonomy): the seam is open, one more ring.
    const Mesh3 open = sweep(Frames3(loop, {.up = {0, 0, 1}}), {.profile = circle_profile(0.3, sides), .tolerance = 1e-3});
    EXPECT_EQ(open.ring_u.back(), 1.0);
    EXPECT_EQ(open.triangles.size(), 2 * (open.ring_u.size() - 1) * sides);
    // An open path with caps: a sphere's topology (V − E + F = 2), every edge used twice.
    const Path3 arc = Path3::cubic_bezier({0, 0, 0}, {2, 0, 0}, {2, 2, 1}, {0, 2, 2});
    const Mesh3 capped = sweep(Frames3(arc, {.up = {0, 0, 1}}), {.profile = circle_profile(0.2, 8), .caps = true});
    const auto uses = edge_uses(capped);
    int boundary = 0;
    for (const auto& [edge, n] : uses) boundary += n == 1;
    // Caps have their own vertices (their normals differ), so the rims are seams: 2·8 edges
    // once on the tube and once on a cap. Everything else twice.
    EXPECT_EQ(boundary, 4 * 8);
    for (std::size_t i = 0; i < capped.normals.size(); ++i) EXPECT_NEAR(length(capped.normals[i]), 1.0, 1e-15);
    // Cap normals face away from the tube: −T at the start, +T at the end.
    const Vec3 t0 = arc.tangent(0.0), t1 = arc.tangent(1.0);
    const std::size_t cap0 = capped.ring_u.size() * 8;
    EXPECT_NEAR(dot(capped.normals[cap0], t0), -1.0, 1e-15);
    EXPECT_NEAR(dot(capped.normals[cap0 + 9], t1), 1.0, 1e-15);
    // Every triangle's winding agrees with its vertices' normals (counter-clockwise outside).
    for (const auto& t : capped.triangles) {
        const Vec3 a = capped.positions[t[0]], b = capped.positions[t[1]], c = capped.positions[t[2]];
        const Vec3 face = cross(b - a, c - a);
        const Vec3 mean = capped.normals[t[0]] + capped.normals[t[1]] + capped.normals[t[2]];
        ASSERT_GT(dot(face, mean), 0.0);
    }
}

// Rings are placed by the error, so a path with long straight runs and one tight bend (C¹ at
// its joins, so that uniform rings need not land on a corner) needs far fewer than uniform
// spacing (as Unity's SplineExtrude places them) for the same error. The error of a set of
// rings is measured here, on the columns only (what uniform spacing is judged by), as the
// largest distance from the true column at 3 points per step to its chord.
TEST(Sweep3, AdaptiveAgainstUniform) {
    const Path3 p = Path3::complex_by_length({Path3::line({0, 0, 0}, {20, 0, 0}),
                                              Path3::cubic_bezier({20, 0, 0}, {22, 0, 0}, {22, 2, 1}, {20, 2, 1}),
                                              Path3::line({20, 2, 1}, {0, 2, 1})});
    const Frames3 fr(p, {.up = {0, 0, 1}});
    const std::vector<Vec2> profile = circle_profile(0.3, 16);
    const double tol = 1e-3;
    const Mesh3 m = sweep(fr, {.profile = profile, .tolerance = tol});
    auto error = [&](const std::vector<double>& us) {
        double worst = 0.0;
        for (std::size_t i = 0; i + 1 < us.size(); ++i) {
            const Frame3 fa = fr.frame(us[i]), fb = fr.frame(us[i + 1]);
            for (const double w : {0.25, 0.5, 0.75}) {
                const Frame3 fm = fr.frame(us[i] + (us[i + 1] - us[i]) * w);
                for (const Vec2 p : profile) {
                    const Vec3 a = fa.point + fa.normal * p.x + fa.binormal * p.y;
                    const Vec3 b = fb.point + fb.normal * p.x + fb.binormal * p.y;
                    const Vec3 q = fm.point + fm.normal * p.x + fm.binormal * p.y;
                    const Vec3 d = b - a;
                    const double t = std::clamp(dot(q - a, d) / dot(d, d), 0.0, 1.0);
                    worst = std::max(worst, distance(q, a + d * t));
                }
            }
        }
        return worst;
    };
    EXPECT_LE(error(m.ring_u), tol);
    // The least uniform ring count within tol (bisection on n; the error falls with n).
    auto uniform = [](std::size_t n) {
        std::vector<double> us;
        for (std::size_t i = 0; i < n; ++i) us.push_back(static_cast<double>(i) / static_cast<double>(n - 1));
        return us;
    };
    std::size_t lo = 2, hi = 2;
    while (error(uniform(hi)) > tol) lo = hi, hi *= 2;
    while (hi - lo > 1) {
        const std::size_t mid = (lo + hi) / 2;
        (error(uniform(mid)) > tol ? lo : hi) = mid;
    }
    EXPECT_LT(m.ring_u.size() * 3, hi);
    std::printf("rail with a hairpin, tolerance %g: adaptive %zu rings, uniform needs %zu\n", tol, m.ring_u.size(), hi);
}

// The OBJ text reads back (in the classic locale) to the very same doubles and indices.
TEST(Sweep3, ObjRoundTrip) {
    const Path3 h = Path3::helix({.radius = 1, .rise = 0.7, .turns = 0.5});
    const Mesh3 m = sweep(Frames3(h, {.mode = FrameMode::frenet}), {.profile = circle_profile(0.1, 5), .tolerance = 1e-2});
    std::istringstream in(to_obj(m));
    in.imbue(std::locale::classic());
    std::vector<Vec3> v, vn;
    std::vector<Vec2> vt;
    std::vector<std::array<std::uint32_t, 3>> f;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        ls.imbue(std::locale::classic());
        std::string tag;
        ls >> tag;
        if (tag == "v" || tag == "vn") {
            Vec3 p;
            ls >> p.x >> p.y >> p.z;
            (tag == "v" ? v : vn).push_back(p);
        } else if (tag == "vt") {
            Vec2 t;
            ls >> t.x >> t.y;
            vt.push_back(t);
        } else if (tag == "f") {
            std::array<std::uint32_t, 3> t{};
            for (auto& i : t) {
                std::string corner;
                ls >> corner;
                const auto k = static_cast<std::uint32_t>(std::stoul(corner));
                ASSERT_EQ(corner, std::to_string(k) + '/' + std::to_string(k) + '/' + std::to_string(k));
                i = k - 1;
            }
            f.push_back(t);
        }
    }
    EXPECT_EQ(v, m.positions);
    EXPECT_EQ(vn, m.normals);
    EXPECT_EQ(vt, m.uv);
    EXPECT_EQ(f, m.triangles);
}

// uv: u runs along the profile (0 at its first vertex), v is the arc length at the ring.
TEST(Sweep3, TextureCoordinates) {
    const Path3 h = Path3::helix({.radius = 1, .rise = 0.7, .turns = 1});
    const Mesh3 m = sweep(Frames3(h, {.up = {-1, 0, 0}}), {.profile = circle_profile(0.1, 4), .tolerance = 1e-3});
    for (std::size_t i = 0; i < m.ring_u.size(); ++i) {
        for (std::size_t j = 0; j < 4; ++j) {
            EXPECT_EQ(m.uv[i * 4 + j].x, j / 4.0);
            EXPECT_NEAR(m.uv[i * 4 + j].y, h.length() * m.ring_u[i], 1e-13);  // u ∝ arc length on a helix
        }
    }
}

TEST(Sweep3, BadInputs) {
    const Frames3 fr(Path3::line({0, 0, 0}, {1, 0, 0}), {.up = {0, 0, 1}});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expect_error([&] { sweep(fr, {.profile = {{0, 0}, {1, 0}}}); }, {"sweep", "profile", "3 points"});
    expect_error([&] { sweep(fr, {.profile = {{0, 0}}, .closed_profile = false}); }, {"sweep", "profile", "2 points"});
    expect_error([&] { sweep(fr, {.profile = {{0, 0}, {nan, 0}}, .closed_profile = false}); }, {"profile[1]", "not finite"});
    expect_error([&] { sweep(fr, {.profile = circle_profile(1, 3), .tolerance = 0}); }, {"tolerance", "> 0"});
    const Frames3 helix(Path3::helix({.radius = 1, .turns = 5}), {.up = {1, 0, 0}});
    expect_error([&] { sweep(helix, {.profile = circle_profile(1, 8), .tolerance = 1e-9, .max_rings = 100}); },
                 {"tolerance", "max_rings = 100"});
    expect_error([&] { circle_profile(0, 8); }, {"circle_profile", "radius"});
    expect_error([&] { circle_profile(1, 2); }, {"circle_profile", "sides"});
}
