// The hot loop's inline evaluation: easing, the path point on copied coefficients, the write.
#pragma once

#include "engine_impl.hpp"

namespace grape::detail {

// The curve of a record: parameter-free kinds by curve.hpp's inline formula, the others
// through their Curve in the table.
inline double EngineImpl::ease(CurveKind kind, std::uint16_t curve, double x) const noexcept {
    return has_parameters(kind) ? curves_[curve].curve(x) : detail::ease_formula(kind, x);
}

// The kernel's formulas on copied coefficients (Path::point bit for bit for lines and cubics).
inline Vec2 EngineImpl::point(std::uint32_t path, double u) const noexcept {
    if (u >= 0.0 && u <= 1.0) {
        const PathFast& f = path_fast_[path];
        switch (f.fast) {
            case KernelKind::linear: return f.c[0] + f.c[1] * u;
            case KernelKind::cubic: return ((f.c[3] * u + f.c[2]) * u + f.c[1]) * u + f.c[0];
            case KernelKind::reparam_cubic: {
                const double v = ArcLengthTable::evaluate(f.table, f.steps, u);
                return ((f.c[3] * v + f.c[2]) * v + f.c[1]) * v + f.c[0];
            }
            case KernelKind::reparam_linear: return f.c[0] + f.c[1] * ArcLengthTable::evaluate(f.table, f.steps, u);
            case KernelKind::generic: break;
        }
    }
    return paths_[path].path.point(u);  // other kinds, and outside [0, 1] along the end tangents
}

inline void EngineImpl::write_2d(const Hot& h, Vec2 p) const noexcept {
    char* x = h.target;
    if (h.flags & flag_float) {
        *reinterpret_cast<float*>(x) = static_cast<float>(p.x);
        *reinterpret_cast<float*>(x + h.y_offset) = static_cast<float>(p.y);
    } else {
        *reinterpret_cast<double*>(x) = p.x;
        *reinterpret_cast<double*>(x + h.y_offset) = p.y;
    }
}

}  // namespace grape::detail
