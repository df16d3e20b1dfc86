// grape — error type shared by every module.
#pragma once

#include <charconv>
#include <stdexcept>
#include <string>

namespace grape {

/// Thrown by constructors and parsers for invalid input. The message names the offending
/// argument (or the character offset / JSON pointer for parsers) and the reason.
/// Evaluation on valid objects never throws.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

namespace detail {
/// A number as error messages quote it: the shortest text that reads back as the same double.
inline std::string number_text(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}
}  // namespace detail

}  // namespace grape
