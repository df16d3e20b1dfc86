#include "commands.hpp"
namespace grape::tool {
void register_render_command(CLI::App&) {}
void demo_pictures(const DemoContext&) {}
}  // namespace grape::tool
