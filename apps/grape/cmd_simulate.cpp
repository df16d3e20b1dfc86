#include "commands.hpp"
namespace grape::tool {
void register_simulate_command(CLI::App&) {}
void demo_dynamics(const DemoContext&) {}
}  // namespace grape::tool
