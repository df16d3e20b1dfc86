// The lean runs on arc-length paths, compiled once (see engine_lean_table.hpp).
#include "engine_lean_runs.hpp"

namespace grape::detail {
constinit const LeanKernelRuns lean_arc_runs = lean_table<LeanPath::arc>();
}  // namespace grape::detail
