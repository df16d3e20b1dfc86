// The lean runs on cubics, compiled once (see engine_lean_table.hpp).
#include "engine_lean_runs.hpp"

namespace grape::detail {
constinit const LeanKernelRuns lean_cubic_runs = lean_table<LeanPath::cubic>();
}  // namespace grape::detail
