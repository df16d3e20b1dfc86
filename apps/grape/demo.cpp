// `grape demo`: the seed's examples, computed and summarized; each module adds a section.
#include "commands.hpp"

#include <grape/error.hpp>

#include "atomic_file.hpp"
#include "utf8_path.hpp"

#include <iostream>

namespace grape::tool {

void register_demo_command(CLI::App& app) {
    auto* demo = app.add_subcommand("demo", "Run the seed's demos: print the summary, write pictures to --out");
    auto dir = std::make_shared<std::string>("grape-demo");
    demo->add_option("--out", *dir, "Folder for the files the demo writes")->capture_default_str();
    demo->callback([dir] {
        if (dir->empty()) throw Error("demo: --out must name a folder (got an empty name)");
        const std::filesystem::path folder = detail::path_from_utf8(*dir);
        std::error_code ec;
        if (std::filesystem::exists(folder, ec) && !std::filesystem::is_directory(folder, ec))
            throw Error("demo: --out " + *dir + ": it exists and is not a folder");
        // The outermost folder this run creates, removed again if the run fails.
        std::filesystem::path created;
        for (std::filesystem::path p = folder; !p.empty() && !std::filesystem::exists(p, ec); p = p.parent_path()) {
            created = p;
            if (p == p.parent_path()) break;
        }
        std::filesystem::create_directories(folder, ec);
        if (ec)
            throw Error("demo: --out " + *dir + ": cannot create the folder (" +
                        detail::write_failure_reason(ec.default_error_condition().value(), folder) + ")");
        // The pictures go to a staging folder inside and move into place only when every
        // section has succeeded: a failure leaves the folder as it was (or gone, if created).
        detail::StagingFolder staging(folder, created);
        const DemoContext context{std::cout, staging.path(), folder};
        demo_paths(context);
        demo_curves(context);
#ifdef GRAPE_TOOL_DYNAMICS
        demo_dynamics(context);
#endif
#ifdef GRAPE_TOOL_RENDER
        demo_pictures(context);
#endif
        staging.commit();
    });
}

}  // namespace grape::tool
