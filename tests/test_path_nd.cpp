// path_nd: PathND's Catmull–Rom and Hermite kinds and its arc length against independent truth
// — keyframes and the known tangents, the 2-D and 3-D splines built by other code, d1 against
// differences of point, and lengths against exact sums (linear) and a Richardson-extrapolated
// dense polyline written here (splines).
#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/path3.hpp>

#include "count_allocations.hpp"
#include "error_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace grape;
using grape::testing::expect_error;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

std::vector<double> random_values(std::mt19937_64& rng, std::size_t count) {
    std::uniform_real_distribution<double> d(-5.0, 5.0);
    std::vector<double> v(count);
    for (double& x : v) x = d(rng);
    return v;
}

std::vector<double> at(const PathND& p, double u) {
    std::vector<double> out(p.dimension());
    p.point(u, out);
    return out;
}

std::vector<double> slope(const PathND& p, double u) {
    std::vector<double> out(p.dimension());
    p.d1(u, out);
    return out;
}

double gap(const std::vector<double>& a, const std::vector<double>& b) {
    double sum = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
    return std::sqrt(sum);
}

// The length of the polyline through point() at n even steps per segment, extrapolated
// (Romberg): a chord sum misses the arc by a·h² + b·h⁴ + c·h⁶ + …, so two Richardson levels
// over n, 2n and 4n steps leave O(h⁶).
double dense_length(const PathND& p, std::size_t per_segment) {
    const std::size_t segments = p.keyframe_count() - 1;
    auto chords = [&](std::size_t n) {
        double sum = 0.0;
        std::vector<double> prev = at(p, 0.0);
        const std::size_t steps = n * segments;
        for (std::size_t i = 1; i <= steps; ++i) {
            const std::vector<double> next = at(p, static_cast<double>(i) / static_cast<double>(steps));
            sum += gap(prev, next);
            prev = next;
        }
        return sum;
    };
    const double l1 = chords(per_segment), l2 = chords(2 * per_segment), l4 = chords(4 * per_segment);
    const double r1 = (4.0 * l2 - l1) / 3.0, r2 = (4.0 * l4 - l2) / 3.0;
    return (16.0 * r2 - r1) / 15.0;
}

}  // namespace

TEST(PathND, LinearLengthIsTheSumOfTheSegments) {
    std::mt19937_64 rng(5);
    for (std::size_t dim = 1; dim <= 5; ++dim) {
        const std::size_t count = 2 + dim;
        const std::vector<double> keys = random_values(rng, dim * count);
        const PathND p(dim, keys);
        std::vector<double> partial{0.0};
        for (std::size_t i = 0; i + 1 < count; ++i) {
            double sq = 0.0;
            for (std::size_t k = 0; k < dim; ++k) sq += std::pow(keys[(i + 1) * dim + k] - keys[i * dim + k], 2);
            partial.push_back(partial.back() + std::sqrt(sq));
        }
        EXPECT_NEAR(p.length(), partial.back(), 4 * eps * partial.back());
        for (std::size_t i = 0; i < count; ++i) {
            const double u = static_cast<double>(i) / static_cast<double>(count - 1);
            EXPECT_NEAR(p.length_at(u), partial[i], 4 * eps * partial.back());
            EXPECT_NEAR(p.u_at_length(partial[i]), u, 8 * eps);
        }
        // Halfway along a segment is half its length.
        const double mid = 0.5 / static_cast<double>(count - 1);
        EXPECT_NEAR(p.length_at(mid), 0.5 * partial[1], 4 * eps * partial.back());
        EXPECT_EQ(p.u_at_length(-1.0), 0.0);
        EXPECT_EQ(p.u_at_length(2.0 * p.length()), 1.0);
        EXPECT_EQ(p.kind(), PathNDKind::linear);
    }
}

TEST(PathND, CatmullRomPassesThroughItsKeysWithTheKnownTangents) {
    std::mt19937_64 rng(9);
    for (std::size_t dim = 1; dim <= 4; ++dim) {
        const std::size_t count = 3 + dim;
        const std::vector<double> keys = random_values(rng, dim * count);
        const PathND p = PathND::catmull_rom(dim, keys);
        EXPECT_EQ(p.kind(), PathNDKind::catmull_rom);
        const double n = static_cast<double>(count - 1);
        for (std::size_t i = 0; i < count; ++i) {
            const double u = static_cast<double>(i) / n;
            const std::vector<double> v = at(p, u);
            const std::vector<double> m = slope(p, u);
            for (std::size_t k = 0; k < dim; ++k) {
                EXPECT_EQ(v[k], keys[i * dim + k]) << i;
                // d/dt of the local t is d/du divided by the segments; uniform tangents are
                // (p[i+1] − p[i−1])/2 inside, p1 − p0 and pₙ − pₙ₋₁ at the ends (mirrored
                // phantoms). Values ≤ 5: a few roundings of 10.
                double want;
                if (i == 0) want = keys[dim + k] - keys[k];
                else if (i + 1 == count) want = keys[i * dim + k] - keys[(i - 1) * dim + k];
                else want = 0.5 * (keys[(i + 1) * dim + k] - keys[(i - 1) * dim + k]);
                EXPECT_NEAR(m[k] / n, want, 16 * eps * 10) << dim << " " << i;
            }
        }
    }
}

TEST(PathND, CatmullRomMatchesThe2DAnd3DSplines) {
    std::mt19937_64 rng(21);
    for (const CatmullRom type : {CatmullRom::uniform, CatmullRom::centripetal, CatmullRom::chordal}) {
        const std::vector<double> xy = random_values(rng, 12);
        const std::vector<double> xyz = random_values(rng, 18);
        const PathND p2 = PathND::catmull_rom(2, xy, type);
        const PathND p3 = PathND::catmull_rom(3, xyz, type);
        const CatmullRomSplinePath flat(xy, type);
        std::vector<Vec3> points;
        for (std::size_t i = 0; i < 6; ++i) points.push_back({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
        const Path3 space = Path3::catmull_rom(points, type);
        for (int i = 0; i <= 100; ++i) {
            const double u = i / 100.0;
            const Vec2 a = flat.point(u);
            const Vec3 b = space.point(u);
            const auto v2 = at(p2, u), v3 = at(p3, u);
            // The same cubic in another evaluation order: a few roundings of values ≤ ~10.
            EXPECT_NEAR(v2[0], a.x, 1e-13);
            EXPECT_NEAR(v2[1], a.y, 1e-13);
            EXPECT_NEAR(v3[0], b.x, 1e-13);
            EXPECT_NEAR(v3[1], b.y, 1e-13);
            EXPECT_NEAR(v3[2], b.z, 1e-13);
        }
        // Arc length agrees with Path3's (adaptive Gauss to ~1e-14 relative) within both tolerances.
        EXPECT_NEAR(p3.length(), space.length(), 1e-13 * space.length());
        for (int i = 0; i <= 20; ++i) EXPECT_NEAR(p3.length_at(i / 20.0), space.length_at(i / 20.0), 1e-13 * space.length());
    }
}

TEST(PathND, HermiteHitsItsKeysAndEndTangents) {
    std::mt19937_64 rng(33);
    const std::size_t dim = 4, count = 5;
    const std::vector<double> keys = random_values(rng, dim * count);
    const std::vector<double> tans = random_values(rng, dim * count);
    const PathND p = PathND::hermite(dim, keys, tans);
    const double n = static_cast<double>(count - 1);
    for (std::size_t i = 0; i < count; ++i) {
        const auto v = at(p, static_cast<double>(i) / n);
        for (std::size_t k = 0; k < dim; ++k) EXPECT_EQ(v[k], keys[i * dim + k]);
    }
    const auto m0 = slope(p, 0.0), m1 = slope(p, 1.0);
    for (std::size_t k = 0; k < dim; ++k) {
        EXPECT_NEAR(m0[k] / n, tans[k], 8 * eps * 5);
        // At t = 1: c1 + 2c2 + 3c3 of coefficients made from values ≤ 5 (~30 in size).
        EXPECT_NEAR(m1[k] / n, tans[(count - 1) * dim + k], 16 * eps * 30);
    }
    // Beyond the ends it goes on along the end tangents.
    const auto end = at(p, 1.0), past = at(p, 1.25), start = at(p, 0.0), before = at(p, -0.5);
    for (std::size_t k = 0; k < dim; ++k) {
        EXPECT_NEAR(past[k], end[k] + 0.25 * m1[k], 1e-13);
        EXPECT_NEAR(before[k], start[k] - 0.5 * m0[k], 1e-13);
    }
    // d1 against central differences of point: h = 1e-5 leaves h²·|P‴|/6 ≲ 1e-10·(n³·30) and
    // rounding eps·|P|/h ≲ 1e-10; 1e-7 covers both with margin.
    for (int i = 1; i < 100; ++i) {
        const double u = i / 100.0, h = 1e-5;
        if (std::abs(u * n - std::round(u * n)) < 2 * h * n) continue;  // not across a join
        const auto a = at(p, u + h), b = at(p, u - h), d = slope(p, u);
        for (std::size_t k = 0; k < dim; ++k) EXPECT_NEAR((a[k] - b[k]) / (2 * h), d[k], 1e-7) << u;
    }
    std::vector<double> short_tans(tans.begin(), tans.end() - 1);
    expect_error([&] { PathND::hermite(dim, keys, short_tans); }, {"PathND", "tangents must hold as many values"});
    std::vector<double> nan_tans = tans;
    nan_tans[3] = std::nan("");
    expect_error([&] { PathND::hermite(dim, keys, nan_tans); }, {"tangents[3] must be finite"});
}

TEST(PathND, SplineArcLengthMatchesADensePolylineOnASmoothSpline) {
    // A spline whose speed stays well away from 0 (a wide loop through 6 dimensions), where the
    // chord sums' error expansion holds.
    std::vector<double> keys;
    for (int i = 0; i < 6; ++i) {
        const double a = 0.9 * i;
        for (int k = 0; k < 6; ++k) keys.push_back(std::cos(a + k) * (1.0 + 0.1 * k));
    }
    for (const PathND& p : {PathND::catmull_rom(6, keys), PathND::catmull_rom(6, keys, CatmullRom::centripetal)}) {
        const double total = p.length();
        // 1024 to 4096 chords per segment: the extrapolation leaves O(h⁶) ≲ 1e-14 relative, and
        // summing ~2·10⁴ chords rounds by ≲ 1e-12 relative (Romberg amplifies each sum's
        // rounding by ≤ (16·5/3 + 5/3)/15 < 6): 1e-11 bounds the reference.
        EXPECT_NEAR(total, dense_length(p, 1024), 1e-11 * total);
    }
}

TEST(PathND, SplineArcLengthMatchesPath3OnIsometricImages) {
    // Path3 measures its splines by its own adaptive Gauss–Legendre (~1e-14 relative). A 3-D
    // spline's keys and tangents mapped into 6-D by the isometry (x, y, z) → (x·c, x·s, y·c,
    // y·s, z·c, z·s) give a PathND of the same length (every cubic maps with its coefficients).
    std::mt19937_64 rng(41);
    const double c = std::cos(0.7), s = std::sin(0.7);
    for (int trial = 0; trial < 10; ++trial) {
        const std::vector<double> xyz = random_values(rng, 15), txyz = random_values(rng, 15);
        std::vector<Vec3> points, tangents;
        std::vector<double> keys6, tans6;
        for (std::size_t i = 0; i < 5; ++i) {
            points.push_back({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
            tangents.push_back({txyz[3 * i], txyz[3 * i + 1], txyz[3 * i + 2]});
            for (std::size_t k = 0; k < 3; ++k) {
                keys6.insert(keys6.end(), {xyz[3 * i + k] * c, xyz[3 * i + k] * s});
                tans6.insert(tans6.end(), {txyz[3 * i + k] * c, txyz[3 * i + k] * s});
            }
        }
        const Path3 cr3 = Path3::catmull_rom(points, CatmullRom::centripetal);
        const Path3 h3 = Path3::hermite(points, tangents);
        const PathND cr3d = PathND::catmull_rom(3, xyz, CatmullRom::centripetal);
        const PathND h6 = PathND::hermite(6, keys6, tans6);
        // Both resolve to ~1e-14 relative; the isometry's rounding adds ~eps: 1e-13.
        EXPECT_NEAR(cr3d.length(), cr3.length(), 1e-13 * cr3.length()) << trial;
        EXPECT_NEAR(h6.length(), h3.length(), 1e-13 * h3.length()) << trial;
        for (int i = 0; i <= 20; ++i) {
            EXPECT_NEAR(cr3d.length_at(i / 20.0), cr3.length_at(i / 20.0), 1e-13 * cr3.length());
            EXPECT_NEAR(h6.length_at(i / 20.0), h3.length_at(i / 20.0), 1e-13 * h3.length());
        }
        // Round trips: s → u → s everywhere, and length_at increasing.
        for (const PathND* p : {&cr3d, &h6}) {
            const double total = p->length();
            for (int i = 0; i <= 64; ++i) {
                const double at_s = total * i / 64.0;
                EXPECT_NEAR(p->length_at(p->u_at_length(at_s)), at_s, 1e-14 * total) << trial << " " << i;
            }
            for (int i = 0; i < 64; ++i) {
                const double u = (i + 0.5) / 64.0;
                EXPECT_GE(p->length_at(u + 1e-9), p->length_at(u));
            }
        }
    }
}

TEST(PathND, OneDimensionalLengthIsTheTotalVariation) {
    // In 1-D the arc length is Σ|P(b) − P(a)| over the monotone pieces between the roots of
    // P′ (a quadratic per segment, solved here in closed form): exact truth where the speed
    // |P′| has kinks that a polyline's Richardson extrapolation cannot follow.
    std::mt19937_64 rng(43);
    for (int trial = 0; trial < 20; ++trial) {
        const std::vector<double> keys = random_values(rng, 6);
        const std::vector<double> tans = random_values(rng, 6);
        const PathND p = PathND::hermite(1, keys, tans);
        double total = 0.0;
        for (std::size_t i = 0; i < 5; ++i) {
            // P(t) = p0 + c1·t + c2·t² + c3·t³ on segment i (the Hermite cubic, written out).
            const double p0 = keys[i], p1 = keys[i + 1], t0 = tans[i], t1 = tans[i + 1];
            const double c1 = t0, c2 = 3 * (p1 - p0) - 2 * t0 - t1, c3 = 2 * (p0 - p1) + t0 + t1;
            std::vector<double> cuts{0.0};
            const double qa = 3 * c3, qb = 2 * c2, qc = c1, disc = qb * qb - 4 * qa * qc;
            if (qa != 0.0 && disc > 0.0) {
                const double r0 = (-qb - std::sqrt(disc)) / (2 * qa), r1 = (-qb + std::sqrt(disc)) / (2 * qa);
                for (const double r : {std::min(r0, r1), std::max(r0, r1)}) if (r > 0.0 && r < 1.0) cuts.push_back(r);
            }
            cuts.push_back(1.0);
            auto value = [&](double t) { return ((c3 * t + c2) * t + c1) * t + p0; };
            for (std::size_t k = 0; k + 1 < cuts.size(); ++k) total += std::abs(value(cuts[k + 1]) - value(cuts[k]));
        }
        // The quadrature is resolved to 1e-15 of each segment; rounding of the values ≤ ~10.
        EXPECT_NEAR(p.length(), total, 1e-13 * total) << trial;
    }
}

TEST(PathND, EvaluationAllocatesNothing) {
    const std::vector<double> keys{0, 0, 1, 2, 3, 1, 4, 4};
    const PathND p = PathND::catmull_rom(2, keys, CatmullRom::centripetal);
    const PathND l(2, keys);
    double out[2];
    const long before = g_allocations.load();
    double sum = 0.0;
    for (int i = 0; i <= 100; ++i) {
        p.point(i / 100.0, out);
        sum += out[0] + p.length_at(i / 100.0) + p.u_at_length(i / 10.0) + l.length_at(i / 100.0) + l.u_at_length(i / 10.0);
    }
    EXPECT_EQ(g_allocations.load(), before);
    EXPECT_TRUE(std::isfinite(sum));
}
