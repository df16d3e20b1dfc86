// The lean lane of the tick: runs of records in the middle of a play, sharing one formula
// curve kind on lines or cubics, each run in a loop compiled for its (curve, path) pair.
#pragma once

#include "engine_eval.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

namespace grape::detail {

// The shared path tables the lean lane reads.
struct LeanTables {
    const KernelKind* kind;  // per path
    const LineFast* line;
    const PathFast* fast;
};

// A record's curve kind and flags as one 16-bit word (kind in the low byte), so that one
// compare checks the kind and every flag a run depends on.
static_assert(offsetof(Hot, flags) == offsetof(Hot, kind) + 1 && sizeof(CurveKind) == 1);
inline std::uint16_t kind_and_flags(const Hot& h) noexcept {
    std::uint16_t word;
    std::memcpy(&word, &h.kind, sizeof word);
    return static_cast<std::uint16_t>(std::endian::native == std::endian::little ? word : (word >> 8) | (word << 8));
}
// The flags a run needs as it started: not paused, dead or custom, and the target's type.
inline constexpr std::uint16_t lean_mask = 0xFF | (flag_paused | flag_dead | flag_custom | flag_float) << 8;

// Records from i on while they share curve kind K (no parameters), path kernel P (lines or
// cubics) and target type F (float or double), stay inside the current play, are not
// paused, dead or custom, have a target and started before this tick; returns the first
// record that does not (or n), unchanged. What it writes is plain_step's, bit for bit: the
// same formulas on the same values. The easing and path formula are inline and nothing
// else is tested, so a record costs a few instructions more than a hand-written loop.
template <CurveKind K, KernelKind P, bool F>
GRAPE_FLATTEN std::size_t lean_run(Hot* hot, const LeanTables& t, std::size_t i, std::size_t n, double dt) noexcept {
    static_assert(!has_parameters(K) && (P == KernelKind::linear || P == KernelKind::cubic));
    constexpr std::uint16_t want = static_cast<std::uint16_t>(static_cast<unsigned>(K) | (F ? flag_float << 8 : 0));
    const KernelKind* const kinds = t.kind;  // locals: the target writes cannot alias them
    const LineFast* const lines = t.line;
    const PathFast* const fast = t.fast;
    for (; i < n; ++i) {
        Hot& h = hot[i];
        const double phase = h.phase + dt * h.rate;
        // started before this tick and still inside the play (either way: the rate is < 0
        // when reversed at run time)
        if ((kind_and_flags(h) & lean_mask) != want || !(std::min(h.phase, phase) >= 0.0) || !(phase < play_end) ||
            !h.target || kinds[h.path] != P)
            break;
        const double u = detail::ease_formula(K, (h.flags & flag_backward) ? 1.0 - phase : phase);
        if (!(u >= 0.0 && u <= 1.0)) break;  // outside the path's ends: Path::point's tangents
        h.phase = phase;
        Vec2 p;
        if constexpr (P == KernelKind::linear) {
            const LineFast& f = lines[h.path];
            p = f.c[0] + f.c[1] * u;
        } else {
            const PathFast& f = fast[h.path];
            p = ((f.c[3] * u + f.c[2]) * u + f.c[1]) * u + f.c[0];
        }
        using T = std::conditional_t<F, float, double>;
        *reinterpret_cast<T*>(h.target) = static_cast<T>(p.x);
        *reinterpret_cast<T*>(h.target + h.y_offset) = static_cast<T>(p.y);
    }
    return i;
}

using LeanRun = std::size_t (*)(Hot*, const LeanTables&, std::size_t, std::size_t, double) noexcept;

// lean_run for every formula kind, path kernel and target type: [kind][line, cubic][double,
// float]; null for the kinds with parameters.
template <std::size_t... k>
constexpr auto lean_table(std::index_sequence<k...>) noexcept {
    constexpr auto row = [](auto kind) {
        constexpr auto K = static_cast<CurveKind>(decltype(kind)::value);
        using Row = std::array<std::array<LeanRun, 2>, 2>;
        if constexpr (has_parameters(K)) return Row{};
        else
            return Row{{{&lean_run<K, KernelKind::linear, false>, &lean_run<K, KernelKind::linear, true>},
                        {&lean_run<K, KernelKind::cubic, false>, &lean_run<K, KernelKind::cubic, true>}}};
    };
    return std::array{row(std::integral_constant<std::size_t, k>{})...};
}
inline constexpr std::size_t lean_kinds = static_cast<std::size_t>(CurveKind::bounce_out_in) + 1;
inline constexpr auto lean_runs = lean_table(std::make_index_sequence<lean_kinds>{});

// The lean run that record i would start, or null.
inline LeanRun lean_for(const Hot& h, const LeanTables& t) noexcept {
    const auto kind = static_cast<std::size_t>(h.kind);
    if (kind >= lean_kinds) return nullptr;
    const KernelKind p = t.kind[h.path];
    const std::size_t type = (h.flags & flag_float) ? 1 : 0;
    if (p == KernelKind::linear) return lean_runs[kind][0][type];
    if (p == KernelKind::cubic) return lean_runs[kind][1][type];
    return nullptr;
}

}  // namespace grape::detail
