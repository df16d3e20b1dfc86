// The hot loop's inline evaluation: easing, the path point on copied coefficients, the write.
#pragma once

#include "engine_impl.hpp"

#include <algorithm>

// Inlines every call in the function's body (the hot loops: see plain_run).
#if defined(__GNUC__) || defined(__clang__)
#define GRAPE_FLATTEN __attribute__((flatten))
#else
#define GRAPE_FLATTEN
#endif

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

// The common case of a tick: playing, not paused, dead or custom, a target to write, no play
// end that anybody listens for. Reads and writes record i alone (and its target), so records
// may run on separate threads; the general path takes everything else.
template <bool phase1>
inline bool EngineImpl::plain_step(Hot* hot, Cold* cold, const PathFast* fast, std::size_t i, double dt) const noexcept {
    Hot& h = hot[i];
    double phase = h.phase + dt * h.rate;
    if ((h.flags & (flag_paused | flag_dead | flag_custom)) || !(phase >= 0.0) || !h.target ||
        (h.phase < 0.0 && (h.flags & flag_listens)))  // the first play begins: on_start
        return false;
    if (phase1 && h.kind == CurveKind::function) return false;  // user code: the calling thread
    if (phase >= play_end) {
        // A new play that nobody listens for, reached within this tick: handled here.
        Cold& c = cold[i];
        if ((h.flags & flag_listens) || phase >= 2.0 - play_snap || (c.plays != 0 && c.play + 1 >= c.plays)) return false;
        ++c.play;
        phase = std::max(phase - 1.0, 0.0);
        if (h.flags & flag_yoyo) h.flags ^= flag_backward;
    }
    h.phase = phase;
    const double x = (h.flags & flag_backward) ? 1.0 - phase : phase;
    const double u = has_parameters(h.kind) ? curves_[cold[i].curve].curve(x) : detail::ease_formula(h.kind, x);
    const PathFast& f = fast[h.path];
    Vec2 p;
    if (f.fast == KernelKind::linear && u >= 0.0 && u <= 1.0) p = f.c[0] + f.c[1] * u;
    else if (f.fast == KernelKind::cubic && u >= 0.0 && u <= 1.0) p = ((f.c[3] * u + f.c[2]) * u + f.c[1]) * u + f.c[0];
    else p = point(h.path, u);
    write_2d(h, p);
    return true;
}

}  // namespace grape::detail
