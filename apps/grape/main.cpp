// grape — the command-line tool. `grape demo` is the main job; `grape --help` lists the rest.
#include "commands.hpp"

#include <grape/error.hpp>

#include "atomic_file.hpp"

#include <iostream>
#include <new>
#include <string>
#include <vector>

#ifdef _WIN32
#include "internal/windows.hpp"
#include <shellapi.h>
#include <fcntl.h>
#include <io.h>
#include <cstdio>
#endif

std::string& grape::tool::current_activity() {
    static std::string activity;
    return activity;
}

#ifdef _WIN32
namespace {

// main's argv is in the ANSI code page, which cannot hold every file name; the commands read
// UTF-8 (and make paths with path_from_utf8), so the UTF-16 command line is converted.
std::vector<std::string> utf8_arguments() {
    std::vector<std::string> out;
    int count = 0;
    wchar_t** wide = ::CommandLineToArgvW(::GetCommandLineW(), &count);
    if (!wide) return out;
    for (int i = 0; i < count; ++i) {
        const int size = ::WideCharToMultiByte(CP_UTF8, 0, wide[i], -1, nullptr, 0, nullptr, nullptr);
        std::string s(size > 0 ? static_cast<std::size_t>(size) : 1, '\0');
        if (size > 0) ::WideCharToMultiByte(CP_UTF8, 0, wide[i], -1, s.data(), size, nullptr, nullptr);
        s.pop_back();  // the terminating null
        out.push_back(std::move(s));
    }
    ::LocalFree(wide);
    return out;
}

}  // namespace
#endif

int main(int argc, char** argv) {
#ifdef _WIN32
    // Output is the same bytes as on POSIX ("\n", not "\r\n": JSON and path data compare
    // byte for byte), and UTF-8 text shows as such in a console.
    ::_setmode(::_fileno(stdout), _O_BINARY);
    ::_setmode(::_fileno(stderr), _O_BINARY);
    ::SetConsoleOutputCP(CP_UTF8);
    std::vector<std::string> arguments = utf8_arguments();
    std::vector<char*> pointers;
    if (!arguments.empty()) {
        for (std::string& a : arguments) pointers.push_back(a.data());
        pointers.push_back(nullptr);
        argc = static_cast<int>(arguments.size());
        argv = pointers.data();
    }
#endif
    grape::detail::remove_files_on_interrupt();
    CLI::App app{"grape: paths, curves, animation and constrained dynamics"};
    // Arguments are Unix-style everywhere: a path such as /tmp/x.json is not an option /tmp
    // (CLI11's default on Windows), and subcommands inherit this when created.
    app.allow_windows_style_options(false);
    app.require_subcommand(1);
    grape::tool::register_demo_command(app);
    grape::tool::register_path_commands(app);
#ifdef GRAPE_TOOL_PATH3
    grape::tool::register_path3_commands(app);
#endif
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
