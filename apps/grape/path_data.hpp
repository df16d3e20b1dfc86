// Where a `grape path` command's SVG path DATA comes from: the argument itself, standard
// input ("-" as DATA or as --data-file), or a file (--data-file FILE): real data reaches
// megabytes, past the argument limit.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace grape::tool {

struct DataSource {
    std::string argument;  ///< DATA as given (empty data is valid SVG: it draws nothing)
    bool given = false;    ///< DATA was on the command line
    std::string file;      ///< --data-file ("" when absent, "-" for standard input)
    bool strict = false;   ///< --strict
};

/// The data; throws grape::Error naming `path COMMAND` when it is missing, given twice or
/// cannot be read.
std::string read_data(const char* command, const DataSource& source);

/// Adds --data-file FILE.
void add_data_file_option(CLI::App& command, DataSource& source);

}  // namespace grape::tool
