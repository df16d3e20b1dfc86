#include "commands.hpp"
namespace grape::tool {
void register_path_commands(CLI::App&) {}
void demo_paths(const DemoContext&) {}
}  // namespace grape::tool
