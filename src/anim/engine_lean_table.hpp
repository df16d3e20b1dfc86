// The lean runs' dispatch: one loop per (curve kind, path kernel, target type), and the
// four-lane loops where the processor has them.
#pragma once

#include "engine_lean.hpp"
#include "engine_lean_arc.hpp"
#include "engine_lean_wide.hpp"

#include <array>
#include <cstddef>
#include <utility>

namespace grape::detail {

using LeanRun = std::size_t (*)(Hot*, const LeanTables&, std::size_t, std::size_t, double) noexcept;

// The lean runs for every formula kind, path kernel and target type: [kind][line, cubic,
// arc length][one record at a time, four-lane][double, float]; null for the kinds with
// parameters. The four-lane loops take the polynomial easings on lines and cubics (the
// others: their one-at-a-time loop); on arc-length paths, the polynomial easings' clocks and
// easing and every formula kind's pieces.
template <CurveKind K, KernelKind P>
constexpr std::array<LeanRun, 2> lanes_or_one() noexcept {
    if constexpr (stays_on_path(K)) return {&lean_run_wide<K, P, false>, &lean_run_wide<K, P, true>};
    else return {&lean_run<K, P, false>, &lean_run<K, P, true>};
}
// On arc-length paths: the polynomial easings wholly in lanes, the others' pieces only.
template <CurveKind K>
constexpr std::array<LeanRun, 2> arc_lanes_or_batch() noexcept {
#if GRAPE_WIDE
    if constexpr (stays_on_path(K)) return {&arc_run_lanes<K, false>, &arc_run_lanes<K, true>};
    else
#endif
        return {&lean_arc_run_wide<K, false>, &lean_arc_run_wide<K, true>};
}
template <std::size_t... k>
constexpr auto lean_table(std::index_sequence<k...>) noexcept {
    constexpr auto row = [](auto kind) {
        constexpr auto K = static_cast<CurveKind>(decltype(kind)::value);
        using Row = std::array<std::array<std::array<LeanRun, 2>, 2>, 3>;
        if constexpr (has_parameters(K)) return Row{};
        else
            return Row{{{{{&lean_run<K, KernelKind::linear, false>, &lean_run<K, KernelKind::linear, true>},
                          lanes_or_one<K, KernelKind::linear>()}},
                        {{{&lean_run<K, KernelKind::cubic, false>, &lean_run<K, KernelKind::cubic, true>},
                          lanes_or_one<K, KernelKind::cubic>()}},
                        {{{&lean_arc_run<K, false>, &lean_arc_run<K, true>},
                          arc_lanes_or_batch<K>()}}}};
    };
    return std::array{row(std::integral_constant<std::size_t, k>{})...};
}
inline constexpr std::size_t lean_kinds = static_cast<std::size_t>(CurveKind::bounce_out_in) + 1;
inline constexpr auto lean_runs = lean_table(std::make_index_sequence<lean_kinds>{});

// The lean run that record i would start, or null.
inline LeanRun lean_for(const Hot& h, const LeanTables& t) noexcept {
    const auto kind = static_cast<std::size_t>(curve_kind(h));
    const LaneKernel p = lane_kind(h);
    if (kind >= lean_kinds || p == LaneKernel::other) return nullptr;
    const std::size_t type = (h.flags & flag_float) ? 1 : 0;
    const std::size_t wide = t.wide ? 1 : 0;
    return lean_runs[kind][static_cast<std::size_t>(p) - 1][wide][type];
}

}  // namespace grape::detail
