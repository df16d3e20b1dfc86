// CSS cubic-bezier(x1, y1, x2, y2), solved to round-off from the nearer end.
#include "curve_data.hpp"

#include <grape/curve.hpp>

namespace grape::detail {

double cubic_bezier_eval(double x1, double y1, double x2, double y2, double t) noexcept {
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
    if (t <= 0.5) return bernstein(y1, y2, 1.0, bernstein_solve(x1, x2, 1.0, t));
    const double s = bernstein_solve(1.0 - x2, 1.0 - x1, 1.0, 1.0 - t);
    return 1.0 - bernstein(1.0 - y2, 1.0 - y1, 1.0, s);
}

}  // namespace grape::detail
