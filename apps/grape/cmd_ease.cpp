#include "commands.hpp"
namespace grape::tool {
void register_ease_command(CLI::App&) {}
void demo_curves(const DemoContext&) {}
}  // namespace grape::tool
