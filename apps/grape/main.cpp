// grape — the command-line tool. `grape demo` is the main job; `grape --help` lists the rest.
#include "commands.hpp"

#include <grape/error.hpp>

#include <iostream>

int main(int argc, char** argv) {
    CLI::App app{"grape: paths, curves, animation and constrained dynamics"};
    app.require_subcommand(1);
    grape::tool::register_demo_command(app);
    grape::tool::register_path_commands(app);
    grape::tool::register_ease_command(app);
    grape::tool::register_sprite_commands(app);
#ifdef GRAPE_TOOL_DYNAMICS
    grape::tool::register_simulate_command(app);
#endif
#ifdef GRAPE_TOOL_RENDER
    grape::tool::register_render_command(app);
#endif
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;
    } catch (const grape::Error& e) {
        std::cerr << "grape: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "grape: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
