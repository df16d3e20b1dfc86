// Numbers as text, the same in every locale (internal: not installed). Everything grape reads
// or writes as data — SVG path data, curve names, colours, timeline positions, the tool's
// JSON — goes through here, never through printf, strtod or a stream, which all follow the
// process's locale ("0,5" under de_DE). <charconv> does the work where the standard library
// has it for double; elsewhere (libc++ reads no double before LLVM 20, and Apple's writes
// none before macOS 13.3) strtod and printf run with a "C" locale object of their own.
// number_text, the shortest form, is declared in grape/error.hpp. Exported (GRAPE_MATH_API):
// the other modules, the tool and the tests call these across the shared libraries' boundary.
#pragma once

#include <grape/export_math.hpp>

#include <string>
#include <string_view>
#include <system_error>

namespace grape::detail {

/// Where a read stopped and why, as std::from_chars_result.
struct NumberRead {
    const char* ptr;
    std::errc ec;
};

/// std::from_chars(first, last, value) for double in the general format: [-]digits[.digits]
/// [(e|E)[+|-]digits], inf, infinity, nan, nan(chars); no '+' or white space in front.
/// Correctly rounded. Out of range (past the largest double, or a nonzero number that rounds
/// to zero) is result_out_of_range with ptr past the number and value left as it was.
GRAPE_MATH_API NumberRead parse_double(const char* first, const char* last, double& value) noexcept;

/// The whole of text as one finite number of parse_double's format; false (value unchanged)
/// for anything else: "", " 1", "+1", "1x", "inf", "1e999".
GRAPE_MATH_API bool parse_finite(std::string_view text, double& value) noexcept;

/// printf("%.*g", precision, value) in the "C" locale: precision 17 keeps every double apart.
GRAPE_MATH_API std::string general_text(double value, int precision);

/// printf("%.*f", digits, value) in the "C" locale.
GRAPE_MATH_API std::string fixed_text(double value, int digits);

/// The strtod/printf paths alone, whatever <charconv> has: what the functions above do where
/// <charconv> lacks double, callable everywhere so that tests hold them to <charconv>.
namespace portable {
GRAPE_MATH_API NumberRead parse_double(const char* first, const char* last, double& value) noexcept;
GRAPE_MATH_API std::string shortest_text(double value);  // number_text
GRAPE_MATH_API std::string general_text(double value, int precision);
GRAPE_MATH_API std::string fixed_text(double value, int digits);
}  // namespace portable

}  // namespace grape::detail
