// The lean runs' table for one path kernel, instantiated by engine_lean_line.cpp,
// engine_lean_cubic.cpp and engine_lean_arc.cpp (declared in engine_lean_table.hpp).
#pragma once

#include "engine_lean.hpp"
#include "engine_lean_arc.hpp"
#include "engine_lean_table.hpp"
#include "engine_lean_wide.hpp"

#include <array>
#include <cstddef>
#include <utility>

namespace grape::detail {

// Which path the runs of a table are compiled for.
enum class LeanPath { line, cubic, arc };

// One kind's runs: [one record at a time, four-lane][double, float]. The four-lane loops take
// the polynomial easings on lines and cubics (the others: their one-at-a-time loop); on
// arc-length paths, the polynomial easings' clocks and easing and every formula kind's pieces.
template <CurveKind K, LeanPath P>
constexpr std::array<std::array<LeanRun, 2>, 2> lean_row() noexcept {
    if constexpr (has_parameters(K)) {
        return {};
    } else if constexpr (P == LeanPath::arc) {
        constexpr std::array<LeanRun, 2> one{&lean_arc_run<K, false>, &lean_arc_run<K, true>};
#if GRAPE_WIDE
        if constexpr (stays_on_path(K)) return {one, {&arc_run_lanes<K, false>, &arc_run_lanes<K, true>}};
#endif
        return {one, {&lean_arc_run_wide<K, false>, &lean_arc_run_wide<K, true>}};
    } else {
        constexpr KernelKind k = P == LeanPath::line ? KernelKind::linear : KernelKind::cubic;
        constexpr std::array<LeanRun, 2> one{&lean_run<K, k, false>, &lean_run<K, k, true>};
        if constexpr (stays_on_path(K)) return {one, {&lean_run_wide<K, k, false>, &lean_run_wide<K, k, true>}};
        else return {one, one};
    }
}

template <LeanPath P, std::size_t... k>
constexpr LeanKernelRuns lean_table(std::index_sequence<k...>) noexcept {
    return LeanKernelRuns{lean_row<static_cast<CurveKind>(k), P>()...};
}
template <LeanPath P>
constexpr LeanKernelRuns lean_table() noexcept {
    return lean_table<P>(std::make_index_sequence<lean_kinds>{});
}

}  // namespace grape::detail
