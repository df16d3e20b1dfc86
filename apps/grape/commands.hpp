// The commands of the `grape` tool. Each register_* adds a subcommand to the app; each
// demo_* adds its section to `grape demo`.
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iosfwd>
#include <string>

namespace grape::tool {

/// Where `grape demo` writes: the summary stream and the output folder.
struct DemoContext {
    std::ostream& out;
    std::filesystem::path dir;    ///< where the files go: created before the sections run
    std::filesystem::path shown;  ///< the folder the files end up in, as messages name it
};

void register_path_commands(CLI::App& app);
void register_path_query_commands(CLI::App& path);  ///< closest, curvature, slice, fit under `path`
void register_ease_command(CLI::App& app);
void demo_paths(const DemoContext& context);
void demo_curves(const DemoContext& context);

#ifdef GRAPE_TOOL_DYNAMICS
void register_simulate_command(CLI::App& app);
void demo_dynamics(const DemoContext& context);
#endif

#ifdef GRAPE_TOOL_RENDER
void register_render_command(CLI::App& app);
void demo_pictures(const DemoContext& context);
#endif

#ifdef GRAPE_TOOL_PATH3
void register_path3_commands(CLI::App& app);  ///< `grape path3 length|point|closest|frame|sweep JSON ...`
#endif

#ifdef GRAPE_TOOL_SAMPLE
void register_sample_command(CLI::App& app);  ///< `grape sample SCENE --at T,...`
#endif

void register_demo_command(CLI::App& app);
void register_list_command(CLI::App& app);  ///< `grape list`: the scene catalogue
void register_sprite_commands(CLI::App& app);  // empty without the scene module

/// What the running command is doing ("drawing out.png (1920×1080)"), for the message when
/// memory runs out.
std::string& current_activity();

}  // namespace grape::tool
