// The lean runs' dispatch: one loop per (curve kind, path kernel, target type), and the
// four-lane loops where the processor has them.
#pragma once

#include "engine_impl.hpp"
#include "engine_lean.hpp"

#include <array>
#include <cstddef>
#include <utility>

namespace grape::detail {

using LeanRun = std::size_t (*)(Hot*, const LeanTables&, std::size_t, std::size_t, double) noexcept;

// The lean runs for every formula kind and target type on one path kernel:
// [kind][one record at a time, four-lane][double, float]; null for the kinds with parameters.
// Each kernel's table is instantiated in a file of its own (engine_lean_line.cpp, _cubic,
// _arc): the runs are flattened loops, the heaviest code grape compiles, so they are built
// once and in parallel rather than in every file that dispatches to them.
inline constexpr std::size_t lean_kinds = static_cast<std::size_t>(CurveKind::bounce_out_in) + 1;
using LeanKernelRuns = std::array<std::array<std::array<LeanRun, 2>, 2>, lean_kinds>;
extern const LeanKernelRuns lean_line_runs;
extern const LeanKernelRuns lean_cubic_runs;
extern const LeanKernelRuns lean_arc_runs;

// The lean run that record i would start, or null.
inline LeanRun lean_for(const Hot& h, const LeanTables& t) noexcept {
    const auto kind = static_cast<std::size_t>(curve_kind(h));
    const LaneKernel p = lane_kind(h);
    if (kind >= lean_kinds || p == LaneKernel::other) return nullptr;
    const std::size_t type = (h.flags & flag_float) ? 1 : 0;
    const std::size_t wide = t.wide ? 1 : 0;
    const LeanKernelRuns& runs = p == LaneKernel::linear ? lean_line_runs : p == LaneKernel::cubic ? lean_cubic_runs : lean_arc_runs;
    return runs[kind][wide][type];
}

}  // namespace grape::detail
