// File names as UTF-8 text (internal: not installed). Command lines, JSON and messages carry
// UTF-8; std::filesystem::path's std::string constructor and string() use the native narrow
// encoding instead, which on Windows is the ANSI code page and cannot hold every name.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace grape::detail {

/// The path named by UTF-8 TEXT.
inline std::filesystem::path path_from_utf8(std::string_view text) {
    return std::filesystem::path(std::u8string(text.begin(), text.end()));
}

/// PATH as UTF-8, with its own separators (for messages).
inline std::string utf8_string(const std::filesystem::path& path) {
    const std::u8string s = path.u8string();
    return std::string(s.begin(), s.end());
}

/// PATH as UTF-8 with '/' separators (for files that must read the same on every system).
inline std::string generic_utf8_string(const std::filesystem::path& path) {
    const std::u8string s = path.generic_u8string();
    return std::string(s.begin(), s.end());
}

}  // namespace grape::detail
