// `grape ease NAME T` and the demo's table of every easing at t = 0.25, 0.5, 0.75.
#include "commands.hpp"
#include "json_out.hpp"

#include <grape/curve.hpp>
#include <grape/error.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <ostream>
#include <string>

namespace grape::tool {

void register_ease_command(CLI::App& app) {
    auto* ease = app.add_subcommand(
        "ease", "Print an easing curve's progress at normalized time T: {\"progress\": p}");
    auto name = std::make_shared<std::string>();
    auto t_text = std::make_shared<std::string>();
    ease->add_option("NAME", *name,
                     "Curve name: linear, quad-in-out, back-out(2.5), cubic-bezier(0.25,0.1,0.25,1), "
                     "steps(4,jump-end), ...")
        ->required();
    ease->add_option("T", *t_text, "Normalized time (0 to 1; outside, the curve extends)")->required();
    ease->callback([name, t_text] {
        const Curve curve = parse_curve(*name);
        std::cout << json_object({{"progress", curve(parse_finite("ease: T", *t_text))}}) << '\n';
    });
}

void demo_curves(const DemoContext& context) {
    std::ostream& out = context.out;
    out << "\n== curves: progress at t = 0.25, 0.5, 0.75 ==\n";
    char line[128];
    std::snprintf(line, sizeof line, "%-32s %10s %10s %10s\n", "curve", "0.25", "0.5", "0.75");
    out << line;
    auto row = [&](const Curve& c) {
        std::snprintf(line, sizeof line, "%-32s %10.6f %10.6f %10.6f\n", to_string(c).c_str(), c(0.25), c(0.5),
                      c(0.75));
        out << line;
    };
    for (std::string_view n : curve_names()) row(parse_curve(n));
    for (const char* n : {"ease", "ease-in", "ease-out", "ease-in-out", "steps(4,jump-end)", "steps(4,jump-start)",
                          "steps(4,jump-none)", "steps(4,jump-both)", "monotone(0,0,0.3,0.7,1,1)"})
        row(parse_curve(n));
}

}  // namespace grape::tool
