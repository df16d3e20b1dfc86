// grape — the command-line tool. `grape demo` is the main job; `grape --help` lists the rest.
#include "commands.hpp"

#include <grape/error.hpp>

#include "atomic_file.hpp"

#include <iostream>
#include <new>

std::string& grape::tool::current_activity() {
    static std::string activity;
    return activity;
}

int main(int argc, char** argv) {
    grape::detail::remove_files_on_interrupt();
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
#ifdef GRAPE_TOOL_SAMPLE
    grape::tool::register_sample_command(app);
#endif
    grape::tool::register_list_command(app);
    // CLI11 would only say "A subcommand is required": name the word it did not know.
    if (argc > 1 && argv[1][0] != '-') {
        std::string names;
        bool known = false;
        for (const CLI::App* c : app.get_subcommands([](const CLI::App*) { return true; })) {
            known = known || c->check_name(argv[1]);
            names += (names.empty() ? "" : ", ") + c->get_name();
        }
        if (!known) {
            std::cerr << "grape: unknown command '" << argv[1] << "' (expected " << names << "; see grape --help)\n";
            return 2;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;
    } catch (const std::bad_alloc&) {
        const std::string& activity = grape::tool::current_activity();
        std::cerr << "grape: out of memory" << (activity.empty() ? std::string() : " while " + activity) << '\n';
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
