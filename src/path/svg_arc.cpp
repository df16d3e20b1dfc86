// The endpoint-to-center conversion of an SVG arc (SVG implementation notes F.6.5, with the
// radius correction of F.6.6).
#include "svg_parser.hpp"

#include <grape/math.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace grape::detail {
namespace {

// cos and sin of an angle in degrees, exact at multiples of 90° so that axis-aligned arcs
// (the usual case) carry no rounding from the rotation.
void cos_sin_degrees(double degrees, double& c, double& s) noexcept {
    if (degrees == 0.0) { c = 1.0; s = 0.0; return; }
    if (degrees == 90.0) { c = 0.0; s = 1.0; return; }
    if (degrees == 180.0) { c = -1.0; s = 0.0; return; }
    if (degrees == 270.0) { c = 0.0; s = -1.0; return; }
    const double radians = degrees * (pi / 180.0);
    c = std::cos(radians);
    s = std::sin(radians);
}

// hi + lo carried as an unevaluated sum: twice a double's precision where the radii only just
// reach and 1 − Λ cancels. Built on Knuth's two-sum and Dekker's two-product with Veltkamp's
// split, which are exact with plain IEEE double operations (no contraction: grape builds with
// -ffp-contract=off), rather than on std::fma, which some runtimes emulate slowly or round
// twice where the processor has no fused multiply-add.
struct Twice {
    double hi = 0.0;
    double lo = 0.0;
};

Twice two_sum(double a, double b) noexcept {
    const double sum = a + b;
    const double b_part = sum - a;
    return {sum, (a - (sum - b_part)) + (b - b_part)};
}

// Exact while |a|, |b| < 2⁹⁹⁶ (the split's product must not overflow) and the product's low
// part is no subnormal; callers scale their operands near 1.
Twice two_product(double a, double b) noexcept {
    constexpr double splitter = 134217729.0;  // 2²⁷ + 1: the high half keeps 26 bits
    const double ca = splitter * a;
    const double a_hi = ca - (ca - a);
    const double a_lo = a - a_hi;
    const double cb = splitter * b;
    const double b_hi = cb - (cb - b);
    const double b_lo = b - b_hi;
    const double product = a * b;
    return {product, ((a_hi * b_hi - product) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo};
}

Twice plus(Twice a, Twice b) noexcept {
    const Twice sum = two_sum(a.hi, b.hi);
    return two_sum(sum.hi, sum.lo + (a.lo + b.lo));
}

Twice times(Twice a, double b) noexcept {
    const Twice product = two_product(a.hi, b);
    return two_sum(product.hi, product.lo + a.lo * b);
}

// a / b: the quotient's remainder a − q·b is exact in the double-double.
Twice divided(Twice a, double b) noexcept {
    const double q = a.hi / b;
    const Twice qb = two_product(q, b);
    return {q, (((a.hi - qb.hi) - qb.lo) + a.lo) / b};
}

Twice squared(Twice a) noexcept {
    const Twice square = two_product(a.hi, a.hi);
    return two_sum(square.hi, square.lo + 2.0 * a.hi * a.lo);
}

Twice times(Twice a, Twice b) noexcept {
    const Twice product = two_product(a.hi, b.hi);
    return two_sum(product.hi, product.lo + (a.hi * b.lo + a.lo * b.hi));
}

Twice negated(Twice a) noexcept { return {-a.hi, -a.lo}; }

// cos and sin of `degrees` in [0, 360) to about 2⁻¹⁰⁰: an ellipse turned by another angle than a
// multiple of 90° has Λ through the rotation, and the double cosine's rounding, amplified by
// the axis ratio, would be all that is left of 1 − Λ. Reduced in degrees (exactly: each
// difference below is of numbers within a factor 2) to [0°, 45°], where Taylor's series in
// radians is below 2⁻¹¹⁰ of its sum after 15 terms each.
void cos_sin_degrees_twice(double degrees, Twice& c, Twice& s) noexcept {
    int quadrant = static_cast<int>(degrees / 90.0);
    double r = degrees - 90.0 * quadrant;
    if (r < 0.0) r = degrees - 90.0 * --quadrant;  // the division rounded up to the next quadrant
    const bool complement = r > 45.0;
    if (complement) r = 90.0 - r;
    constexpr Twice radians_per_degree{0.017453292519943295, 2.9486522708701687e-19};  // π/180
    const Twice theta = times(radians_per_degree, r);
    const Twice theta2 = squared(theta);
    Twice sine = theta;
    Twice cosine{1.0, 0.0};
    Twice odd = theta;         // θ^(2k+1)/(2k+1)!, signed
    Twice even{1.0, 0.0};      // θ^(2k)/(2k)!, signed
    for (int k = 1; k <= 14 && odd.hi != 0.0; ++k) {
        even = negated(divided(times(even, theta2), double((2 * k - 1) * (2 * k))));
        odd = negated(divided(times(odd, theta2), double((2 * k) * (2 * k + 1))));
        cosine = plus(cosine, even);
        sine = plus(sine, odd);
    }
    if (complement) std::swap(sine, cosine);
    switch (quadrant & 3) {
    case 0: c = cosine; s = sine; break;
    case 1: c = negated(sine); s = cosine; break;
    case 2: c = negated(cosine); s = negated(sine); break;
    default: c = sine; s = negated(cosine); break;
    }
}

// 1 − Λ = 1 − (x1/rx)² − (y1/ry)² for radii that nearly reach (Λ within [¼, 4]), to a few
// ulps of itself however close to 0: half the chord is exact as a double-double, and so is
// the rest but for roundings of order 2⁻¹⁰⁰. A circle's Λ is |chord|²/(2r)², free of the
// rotation; an ellipse's takes the rotation's cosine and sine in twice the precision too.
double reach_gap(Vec2 from, Vec2 to, double rx, double ry, double degrees) noexcept {
    // Scaled so that the larger radius lies in [½, 1): the products below neither overflow
    // nor (but for axes 2¹⁰⁰⁰ apart) underflow. Powers of two keep every value exact.
    int exponent = 0;
    (void)std::frexp(std::max(rx, ry), &exponent);
    const auto scaled = [exponent](double v) noexcept { return std::ldexp(v, -exponent); };
    // (from − to)/2, halved first as the caller does so that no value overflows.
    const Twice hx = two_sum(scaled(from.x * 0.5), -scaled(to.x * 0.5));
    const Twice hy = two_sum(scaled(from.y * 0.5), -scaled(to.y * 0.5));
    rx = scaled(rx);
    ry = scaled(ry);
    Twice lambda;
    if (rx == ry) {
        lambda = divided(divided(plus(squared(hx), squared(hy)), rx), rx);
    } else {
        Twice c;
        Twice s;
        cos_sin_degrees_twice(degrees, c, s);
        const Twice x1 = plus(times(hx, c), times(hy, s));
        const Twice y1 = plus(times(hx, negated(s)), times(hy, c));
        lambda = plus(squared(divided(x1, rx)), squared(divided(y1, ry)));
    }
    const Twice gap = two_sum(1.0, -lambda.hi);
    return gap.hi + (gap.lo - lambda.lo);
}

}  // namespace

bool svg_arc_to_center(Vec2 from, Vec2 to, double rx, double ry, double rotation_degrees, bool large_arc,
                       bool sweep, SvgSegment& out) noexcept {
    rx = std::abs(rx);
    ry = std::abs(ry);
    if (rx == 0.0 || ry == 0.0 || !std::isfinite(rotation_degrees)) return false;
    double degrees = std::fmod(rotation_degrees, 360.0);
    if (degrees < 0.0) degrees += 360.0;
    if (degrees >= 360.0) degrees = 0.0;  // fmod of a tiny negative angle rounds up to 360
    double c = 1.0;
    double s = 0.0;
    cos_sin_degrees(degrees, c, s);

    // Half the chord in the ellipse's own axes (F.6.5.1), halved before subtracting so that
    // endpoints near ±DBL_MAX do not overflow.
    const Vec2 half = from * 0.5 - to * 0.5;
    const double x1 = c * half.x + s * half.y;
    const double y1 = -s * half.x + c * half.y;
    const double h = std::hypot(x1, y1);
    if (!(h > 0.0) || !std::isfinite(h)) return false;
    // Everything below is written with the unit chord direction (xu, yu) and the axis ratio q,
    // so radii many orders of magnitude from the chord neither overflow nor underflow.
    const double xu = x1 / h;
    const double yu = y1 / h;
    const double q = rx / ry;
    if (!(q > 0.0) || !std::isfinite(q)) return false;  // an ellipse flatter than a double holds
    // n² is the SVG notes' Λ: above 1 the radii are too small to reach and are scaled up (F.6.6).
    // An overflow gives n = inf: scaled up; an underflow gives n ≈ 0, where the offset is
    // √(1 − n²) ≈ 1 anyway.
    const double n = std::hypot(x1 / rx, y1 / ry);
    // The center sits √(1 − Λ) radii off the chord: where the radii nearly reach, 1 − Λ in
    // doubles would keep only the rounding of Λ (2⁻⁵³ of 1 − Λ = 1e-12 moves the center by
    // 1e-10 radii), so it is taken in twice the precision there.
    const double gap = n > 0.5 && n < 2.0 ? reach_gap(from, to, rx, ry, degrees) : (1.0 - n) * (1.0 + n);
    // Radii that reach to within a few ulps (decimal data that only rounds to just-reaching:
    // icons draw circles as two half-arcs) reach exactly: the center is the chord's midpoint.
    constexpr double reach_tolerance = 8.0 * std::numeric_limits<double>::epsilon();
    const bool just_reaching = std::abs(gap) <= reach_tolerance;
    double cx = 0.0;
    double cy = 0.0;
    if (just_reaching) {
        // cx = cy = 0 and the radii as given.
    } else if (!(gap > 0.0)) {
        rx = h * std::hypot(xu, yu * q);
        ry = h * std::hypot(xu / q, yu);
        if (!std::isfinite(rx) || !std::isfinite(ry)) return false;
    } else {
        // F.6.5.2 divided through by rx²·ry²: the center sits sqrt(1/Λ − 1) half-chords off.
        const double k = std::sqrt(gap) * (large_arc == sweep ? -1.0 : 1.0);
        cx = k * rx * (yu / std::hypot(xu / q, yu));
        cy = -k * ry * (xu / std::hypot(xu, yu * q));
    }
    // F.6.5.5–6: start angle and sweep, measured on the unit circle the ellipse maps to.
    const double theta1 = std::atan2((y1 - cy) / ry, (x1 - cx) / rx);
    const double theta2 = std::atan2((-y1 - cy) / ry, (-x1 - cx) / rx);
    double delta = theta2 - theta1;
    if (sweep && delta < 0.0) delta += 2.0 * pi;
    if (!sweep && delta > 0.0) delta -= 2.0 * pi;
    if (delta == 0.0) {
        // The chord vanished against the radii: the small arc is the chord itself, the large
        // one the whole ellipse.
        if (!large_arc) return false;
        delta = sweep ? 2.0 * pi : -2.0 * pi;
    }
    const Vec2 mid = from * 0.5 + to * 0.5;
    out.kind = SvgSegment::Kind::arc;
    out.p[0] = from;
    out.p[1] = to;
    out.center = Vec2{c * cx - s * cy, s * cx + c * cy} + mid;
    out.rx = rx;
    out.ry = ry;
    out.rotation = degrees * (pi / 180.0);
    out.start_angle = theta1;
    out.end_angle = theta1 + delta;
    return is_finite(out.center);
}

}  // namespace grape::detail
