// grape — error type shared by every module.
#pragma once

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

}  // namespace grape
