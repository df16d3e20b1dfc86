// `grape list`: the scene catalogue, one entry a line (name, category, summary), optionally of
// one category. Everything listed is what the tests build and the benchmarks and studio use.
#include "commands.hpp"

#include "catalogue.hpp"

#include <grape/error.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

namespace grape::tool {

void register_list_command(CLI::App& app) {
    auto* list = app.add_subcommand("list", "List the scene catalogue: name, category, summary");
    auto category = std::make_shared<std::string>();
    list->add_option("--category", *category, "Only this category: path, animation, dynamics, scene_file or sprite_sheet");
    list->callback([category] {
        bool known = category->empty();
        for (const auto c : {scenes::Category::path, scenes::Category::animation, scenes::Category::dynamics,
                             scenes::Category::scene_file, scenes::Category::sprite_sheet})
            known = known || to_string(c) == *category;
        if (!known)
            throw Error("list: --category must be path, animation, dynamics, scene_file or sprite_sheet (got '" + *category + "')");
        char line[256];
        for (const scenes::Entry& e : scenes::catalogue()) {
            if (!category->empty() && to_string(e.category) != *category) continue;
            std::snprintf(line, sizeof line, "%-32s %-12s %s\n", e.name.c_str(), std::string(to_string(e.category)).c_str(),
                          e.summary.c_str());
            std::cout << line;
        }
    });
}

}  // namespace grape::tool
