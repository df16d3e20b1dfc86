// grape — error type shared by every module.
#pragma once

#include <grape/export_math.hpp>

#include <stdexcept>
#include <string>

// Every library throws Error and its users catch it: on ELF its type_info must be one object
// for all of them (hidden, each shared library would keep a copy of its own, which catch tells
// apart where it compares type_info by address, as libc++ does). Windows compares the type's
// name, so there the class needs neither dllexport nor dllimport.
#if defined(_WIN32) || defined(__CYGWIN__)
#define GRAPE_VISIBLE_TYPE
#else
#define GRAPE_VISIBLE_TYPE __attribute__((visibility("default")))
#endif

namespace grape {

/// \addtogroup core
/// @{

/// Thrown by constructors and parsers for invalid input. The message names the offending
/// argument (or the character offset / JSON pointer for parsers) and the reason.
/// Evaluation on valid objects never throws.
class GRAPE_VISIBLE_TYPE Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

namespace detail {
/// A number as error messages and names quote it: the shortest text that reads back as the
/// same double ("0.1", "1e+100"), in every locale. Compiled (grape::math), as <charconv> cannot
/// write a double with every standard library grape supports.
GRAPE_MATH_API std::string number_text(double value);
}  // namespace detail

/// @}

}  // namespace grape
