// The lean runs on lines, compiled once (see engine_lean_table.hpp).
#include "engine_lean_runs.hpp"

namespace grape::detail {
constinit const LeanKernelRuns lean_line_runs = lean_table<LeanPath::line>();
}  // namespace grape::detail
