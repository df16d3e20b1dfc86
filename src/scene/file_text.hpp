// Reading a whole JSON file for the scene module's loaders (scenes, sprite sheets), with the
// reasons a user can act on: a folder, a missing file, no permission, a read error.
#pragma once

#include <grape/error.hpp>

#include "utf8_path.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

namespace grape::detail {

/// The bytes of `file`; throws grape::Error "cannot read FILE: REASON". `what` names what the
/// file should be ("a scene file").
inline std::string read_file_text(const std::filesystem::path& file, const std::string& what) {
    std::error_code folder_ec;
    if (std::filesystem::is_directory(file, folder_ec))
        throw Error("cannot read " + utf8_string(file) + ": it is a folder, not " + what);
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        std::error_code ec;
        const bool exists = std::filesystem::exists(file, ec);
        throw Error("cannot read " + utf8_string(file) + ": " + (exists ? "permission denied or not a file" : "no such file"));
    }
    std::stringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw Error("cannot read " + utf8_string(file) + ": read error");
    return buffer.str();
}

}  // namespace grape::detail
