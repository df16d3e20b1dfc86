// CSS cubic-bezier(x1, y1, x2, y2), solved to round-off from the nearer end.
#include "curve_data.hpp"

#include <grape/curve.hpp>

#include <algorithm>
#include <memory>

namespace grape::detail {

double cubic_bezier_eval(const CurveData& table, double x1, double y1, double x2, double y2, double t) noexcept {
    if (!(t > 0.0)) {
        if (!(t < 0.0)) return t;  // 0 (exact) or NaN (passed through, never invented)
        // CSS: a straight line through the start with the start tangent.
        const double slope = x1 > 0.0 ? y1 / x1 : (x2 > 0.0 ? y2 / x2 : 0.0);
        return slope * t;
    }
    if (t >= 1.0) {
        if (t == 1.0) return 1.0;
        const double slope = x2 < 1.0 ? (y2 - 1.0) / (x2 - 1.0) : (x1 < 1.0 ? (y1 - 1.0) / (x1 - 1.0) : 0.0);
        return 1.0 + slope * (t - 1.0);
    }
    // Above ½ the curve is solved mirrored through (½, ½): 1 − t is exact there (Sterbenz),
    // so a t next to 1 keeps all its digits as a small distance from the end, and x(s) is a
    // sum of non-negative Bernstein terms (x1, x2 ∈ [0, 1]) accurate to a few ulp of itself.
    const auto& tab = static_cast<const BezierTable&>(table);
    constexpr int n = BezierTable::n;
    const bool upper = t > 0.5;
    const double v = upper ? 1.0 - t : t;
    const double at = v * n;  // exact: n is a power of 2
    const int k = std::min(static_cast<int>(at), n / 2 - 1);
    const double* nodes = upper ? tab.w : tab.s;
    const double lo = nodes[k];
    const double hi = nodes[k + 1];
    const double s0 = lo + (hi - lo) * (at - k);
    if (!upper) return bernstein(y1, y2, 1.0, bernstein_solve(x1, x2, 1.0, v, lo, hi, s0));
    const double s = bernstein_solve(1.0 - x2, 1.0 - x1, 1.0, v, lo, hi, s0);
    return 1.0 - bernstein(1.0 - y2, 1.0 - y1, 1.0, s);
}

std::shared_ptr<const CurveData> cubic_bezier_table(double x1, double x2) {
    auto tab = std::make_shared<BezierTable>();
    constexpr int n = BezierTable::n;
    tab->s[0] = 0.0;
    tab->w[0] = 0.0;
    for (int k = 1; k <= n / 2; ++k) {
        tab->s[k] = bernstein_solve(x1, x2, 1.0, static_cast<double>(k) / n);
        tab->w[k] = bernstein_solve(1.0 - x2, 1.0 - x1, 1.0, static_cast<double>(k) / n);
    }
    return tab;
}

}  // namespace grape::detail
