// The four-lane runs' dispatch for lean timeline entries: one loop per (curve kind, path
// kernel, target type).
#include "timeline_lanes.hpp"

#include <array>
#include <utility>

namespace grape::detail {

#if GRAPE_WIDE

namespace {

inline constexpr std::size_t lane_kinds = static_cast<std::size_t>(CurveKind::quint_out_in) + 1;
static_assert(stays_on_path(CurveKind::quint_out_in) && !stays_on_path(static_cast<CurveKind>(lane_kinds)));

using Row = std::array<std::array<TimelineLanes, 2>, 2>;  // [line, cubic][double, float]
template <std::size_t... k>
constexpr auto lanes_table(std::index_sequence<k...>) noexcept {
    constexpr auto row = [](auto kind) {
        constexpr auto K = static_cast<CurveKind>(decltype(kind)::value);
        return Row{{{&timeline_lanes<K, KernelKind::linear, false>, &timeline_lanes<K, KernelKind::linear, true>},
                    {&timeline_lanes<K, KernelKind::cubic, false>, &timeline_lanes<K, KernelKind::cubic, true>}}};
    };
    return std::array{row(std::integral_constant<std::size_t, k>{})...};
}
constexpr auto runs = lanes_table(std::make_index_sequence<lane_kinds>{});

}  // namespace

TimelineLanes timeline_lanes_for(const RootLine& l) noexcept {
    const auto kind = static_cast<std::size_t>(l.kind);
    const auto kernel = static_cast<LaneKernel>((l.bits & root_kernel) >> root_kernel_shift);
    if ((l.bits & (unsigned{root_mode} | root_lean)) != (unsigned{root_one} | root_lean) || kind >= lane_kinds ||
        (kernel != LaneKernel::linear && kernel != LaneKernel::cubic))
        return nullptr;
    return runs[kind][kernel == LaneKernel::cubic ? 1 : 0][(l.bits & root_float) ? 1 : 0];
}

#else

TimelineLanes timeline_lanes_for(const RootLine&) noexcept { return nullptr; }

#endif

}  // namespace grape::detail
