// The hot loop's inline evaluation: easing, the path point on copied coefficients, the write.
#pragma once

#include "engine_impl.hpp"

#include <algorithm>

// GRAPE_FLATTEN (internal/compiler.hpp) inlines every call in the hot loops (see plain_run).
#include "internal/compiler.hpp"

namespace grape::detail {

// The curve of a record: parameter-free kinds by curve.hpp's inline formula, the others
// through their Curve in the table.
inline double EngineImpl::ease(CurveKind kind, std::uint16_t curve, double x) const noexcept {
    return has_parameters(kind) ? curves_[curve].curve(x) : detail::ease_formula(kind, x);
}

// The kernel's formulas on copied coefficients (Path::point bit for bit for cubics, to rounding
// for lines), the arc-length table's points for reparametrized ones, from the engine's tables
// (passed in, so that a hot loop may hold them in locals): false for the other kinds and
// outside [0, 1], which EngineImpl::point takes to the path itself.
inline bool kernel_point(const KernelKind* kinds, const LineFast* lines, const PathFast* fast, std::uint32_t path,
                         double u, Vec2& p) noexcept {
    if (!(u >= 0.0 && u <= 1.0)) return false;
    const KernelKind kind = kinds[path];
    if (kind == KernelKind::linear) {  // from the dense table of lines
        const LineFast& l = lines[path];
        p = l.c[0] + l.c[1] * u;
        return true;
    }
    const PathFast& f = fast[path];
    switch (kind) {
        case KernelKind::cubic: p = ((f.c[3] * u + f.c[2]) * u + f.c[1]) * u + f.c[0]; return true;
        case KernelKind::reparam_cubic:
        case KernelKind::reparam_linear:  // the ends exact, as Path::point has them
            p = u >= 1.0 ? f.c[1] : u <= 0.0 ? f.c[0] : ArcLengthTable::evaluate(f.table, f.steps, u);
            return true;
        case KernelKind::linear:  // taken above
        case KernelKind::generic: break;
    }
    return false;
}

inline Vec2 EngineImpl::point(std::uint32_t path, double u) const noexcept {
    Vec2 p;
    if (kernel_point(path_kind_.data(), line_fast_.data(), path_fast_.data(), path, u, p)) return p;
    return paths_[path].path.point(u);  // other kinds, and outside [0, 1] along the end tangents
}

// A point into a 2-D target of members of type T (float or double): x at `x`, y at
// x + y_offset.
template <class T>
inline void write_pair(char* x, std::int16_t y_offset, Vec2 p) noexcept {
    *reinterpret_cast<T*>(x) = static_cast<T>(p.x);
    *reinterpret_cast<T*>(x + y_offset) = static_cast<T>(p.y);
}

// The point into a 2-D record's target, as its flags say.
inline void write_target(const Hot& h, Vec2 p) noexcept {
    if (h.flags & flag_float) write_pair<float>(h.target, h.y_offset, p);
    else write_pair<double>(h.target, h.y_offset, p);
}

inline void EngineImpl::write_2d(const Hot& h, Vec2 p) const noexcept { write_target(h, p); }

// A play that ends within a tick leads into the next one alone while the phase stays below
// next_play_end (beyond it the tick crosses a whole play: the timing model's work): the next
// play's phase, and its direction after the yoyo's turn. The tick's loops share it.
inline constexpr double next_play_end = 2.0 - play_snap;
struct NextPlay {
    double phase;
    std::uint8_t flags;
};
inline NextPlay next_play(const Hot& h, double phase) noexcept {
    return {std::max(phase - 1.0, 0.0), static_cast<std::uint8_t>((h.flags & flag_yoyo) ? h.flags ^ flag_backward : h.flags)};
}

// The common case of a tick: playing, not paused, dead or custom, a target to write, no play
// end that anybody listens for. Reads and writes record i alone (and its target), so records
// may run on separate threads; the general path takes everything else. In two stages, so
// that a loop can advance a batch of records before it writes any (see plain_run): advance
// moves the record's time and gives the eased progress u (false, with nothing changed, when
// the record needs the general path), write puts the point at u into the target.
template <bool phase1>
inline bool EngineImpl::plain_advance(Hot* hot, Cold* cold, std::size_t i, double dt, double& u) const noexcept {
    Hot& h = hot[i];
    double phase = h.phase + dt * h.rate;
    if ((h.flags & (flag_paused | flag_dead | flag_custom)) || !(phase >= 0.0) || !h.target ||
        (h.phase < 0.0 && (h.flags & flag_listens)) ||  // the first play begins: on_start
        (phase == 0.0 && h.rate < 0.0))  // back at the start: on_reverse_complete
        return false;
    if (phase1 && curve_kind(h) == CurveKind::function) return false;  // user code: the calling thread
    if (phase >= play_end) {
        // A new play that nobody listens for, reached within this tick: handled here.
        Cold& c = cold[i];
        if ((h.flags & flag_listens) || phase >= next_play_end || (c.plays() != 0 && c.play() + 1 >= c.plays())) return false;
        ++c.count;  // the next play (see Cold::count)
        const NextPlay next = next_play(h, phase);
        phase = next.phase;
        h.flags = with_more(next.flags, c);
    }
    h.phase = phase;
    const double x = (h.flags & flag_backward) ? 1.0 - phase : phase;
    u = has_parameters(curve_kind(h)) ? curves_[cold[i].curve].curve(x) : detail::ease_formula(curve_kind(h), x);
    return true;
}

inline void EngineImpl::plain_write(const Hot& h, const PathFast* fast, double u) const noexcept {
    const PathFast& f = fast[h.path];
    Vec2 p;
    if (f.fast == KernelKind::cubic && u >= 0.0 && u <= 1.0) p = ((f.c[3] * u + f.c[2]) * u + f.c[1]) * u + f.c[0];
    else p = point(h.path, u);
    write_2d(h, p);
}

// An arc-length path's piece at u, found before the write: where it starts (null for the
// other kinds and at the ends, which plain_write takes) and u's place x in it; its lines
// are asked for now (shared tables of many paths do not stay in L1), read by the write.
inline ArcLengthTable::Piece plain_piece(const Hot& h, const PathFast* fast, double u) noexcept {
    const PathFast& f = fast[h.path];
    const bool arc = f.fast == KernelKind::reparam_cubic || f.fast == KernelKind::reparam_linear;
    if (!arc || !(u > 0.0 && u < 1.0)) return {nullptr, 0.0};
    const ArcLengthTable::Piece p = ArcLengthTable::piece_at(f.table, f.steps, u);
    ArcLengthTable::prefetch_piece(p.c);
    return p;
}

template <bool phase1>
inline bool EngineImpl::plain_step(Hot* hot, Cold* cold, const PathFast* fast, std::size_t i, double dt) const noexcept {
    double u;
    if (!plain_advance<phase1>(hot, cold, i, dt, u)) return false;
    plain_write(hot[i], fast, u);
    return true;
}

}  // namespace grape::detail
