// Numbers as text: <charconv> where it has double, the portable paths (number_text_portable.cpp)
// where it has not. Decided per direction, since libc++ writes doubles long before it reads them.
#include "number_text.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <version>

// libstdc++ 11+ and MSVC announce both directions with __cpp_lib_to_chars. libc++ 17+ says
// whether the running system's library has them (_LIBCPP_AVAILABILITY_HAS_*: Apple's writes
// from macOS 13.3 on); libc++ 14–16 write everywhere but on Apple systems, and read nowhere.
// Emscripten's libc++ (web/compat/charconv_double.hpp stands in) takes the portable paths.
#if defined(__cpp_lib_to_chars)
#define GRAPE_CHARCONV_READS_DOUBLE 1
#define GRAPE_CHARCONV_WRITES_DOUBLE 1
#elif defined(_LIBCPP_VERSION) && !defined(__EMSCRIPTEN__)
#if defined(_LIBCPP_AVAILABILITY_HAS_FROM_CHARS_FLOATING_POINT)
#define GRAPE_CHARCONV_READS_DOUBLE _LIBCPP_AVAILABILITY_HAS_FROM_CHARS_FLOATING_POINT
#else
#define GRAPE_CHARCONV_READS_DOUBLE 0
#endif
#if defined(_LIBCPP_AVAILABILITY_HAS_TO_CHARS_FLOATING_POINT)
#define GRAPE_CHARCONV_WRITES_DOUBLE _LIBCPP_AVAILABILITY_HAS_TO_CHARS_FLOATING_POINT
#elif _LIBCPP_VERSION >= 14000 && !defined(__APPLE__)
#define GRAPE_CHARCONV_WRITES_DOUBLE 1
#else
#define GRAPE_CHARCONV_WRITES_DOUBLE 0
#endif
#else
#define GRAPE_CHARCONV_READS_DOUBLE 0
#define GRAPE_CHARCONV_WRITES_DOUBLE 0
#endif

namespace grape::detail {

NumberRead parse_double(const char* first, const char* last, double& value) noexcept {
#if GRAPE_CHARCONV_READS_DOUBLE
    const auto [ptr, ec] = std::from_chars(first, last, value);
    return {ptr, ec};
#else
    return portable::parse_double(first, last, value);
#endif
}

bool parse_finite(std::string_view text, double& value) noexcept {
    const char* const last = text.data() + text.size();
    double read = 0.0;
    const auto [ptr, ec] = parse_double(text.data(), last, read);
    if (text.empty() || ec != std::errc() || ptr != last || !std::isfinite(read)) return false;
    value = read;
    return true;
}

std::string number_text(double value) {
#if GRAPE_CHARCONV_WRITES_DOUBLE
    char buffer[32];  // the longest: "-2.2250738585072014e-308"
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
#else
    return portable::shortest_text(value);
#endif
}

std::string general_text(double value, int precision) {
#if GRAPE_CHARCONV_WRITES_DOUBLE
    // %g is fixed only below 10^precision, so precision digits, a sign, a point and e-308 fit.
    std::string buffer(static_cast<std::size_t>(std::max(precision, 1)) + 16, '\0');
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, std::chars_format::general, precision);
    buffer.resize(static_cast<std::size_t>(result.ptr - buffer.data()));
    return buffer;
#else
    return portable::general_text(value, precision);
#endif
}

std::string fixed_text(double value, int digits) {
#if GRAPE_CHARCONV_WRITES_DOUBLE
    // 309 digits before the point at most (DBL_MAX), a sign, the point and the digits after.
    std::string buffer(static_cast<std::size_t>(std::max(digits, 0)) + 320, '\0');
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, std::chars_format::fixed, digits);
    buffer.resize(static_cast<std::size_t>(result.ptr - buffer.data()));
    return buffer;
#else
    return portable::fixed_text(value, digits);
#endif
}

}  // namespace grape::detail
