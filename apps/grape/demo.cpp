// `grape demo`: the seed's examples, computed and summarized; each module adds a section.
#include "commands.hpp"

#include <iostream>

namespace grape::tool {

void register_demo_command(CLI::App& app) {
    auto* demo = app.add_subcommand("demo", "Run the seed's demos: print the summary, write pictures to --out");
    auto dir = std::make_shared<std::string>("grape-demo");
    demo->add_option("--out", *dir, "Folder for the files the demo writes")->capture_default_str();
    demo->callback([dir] {
        std::filesystem::create_directories(*dir);
        const DemoContext context{std::cout, *dir};
        demo_paths(context);
        demo_curves(context);
#ifdef GRAPE_TOOL_DYNAMICS
        demo_dynamics(context);
#endif
#ifdef GRAPE_TOOL_RENDER
        demo_pictures(context);
#endif
    });
}

}  // namespace grape::tool
