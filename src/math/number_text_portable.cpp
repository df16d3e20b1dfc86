// Numbers as text without <charconv>: strtod and printf given a "C" locale object of their own
// (strtod_l, snprintf_l, or uselocale for this thread alone), so setlocale and
// std::locale::global elsewhere in the process never change a digit. Both are correctly
// rounded in glibc, musl, Apple's libc and the UCRT. A file of its own: a static link takes
// it only where number_text.cpp needs it (or a test calls it).
#include "number_text.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <locale.h>
#include <string>
#if defined(__APPLE__) || defined(__FreeBSD__)
#include <xlocale.h>
#endif

namespace grape::detail::portable {
namespace {

#if defined(_WIN32)
using CLocale = _locale_t;
CLocale c_locale() {
    static const CLocale c = _create_locale(LC_ALL, "C");
    return c;
}
#else
using CLocale = locale_t;
CLocale c_locale() {
    static const CLocale c = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(0));
    return c;
}

// This thread in the "C" locale while it lives (where no *_l function exists).
class InCLocale {
public:
    InCLocale() : before_(uselocale(c_locale())) {}
    ~InCLocale() { uselocale(before_); }
    InCLocale(const InCLocale&) = delete;
    InCLocale& operator=(const InCLocale&) = delete;

private:
    locale_t before_;
};
#endif

double strtod_c(const char* text, char** end) {
#if defined(_WIN32)
    return _strtod_l(text, end, c_locale());
#elif defined(__GLIBC__) || defined(__APPLE__) || defined(__FreeBSD__)
    return strtod_l(text, end, c_locale());
#else
    const InCLocale in_c;
    return std::strtod(text, end);
#endif
}

// snprintf(buffer, size, "%.*e" (or g, f), precision, value) in the "C" locale.
int print_c(char* buffer, std::size_t size, char conversion, int precision, double value) {
    const char* format = conversion == 'e' ? "%.*e" : conversion == 'g' ? "%.*g" : "%.*f";
#if defined(_WIN32)
    return _snprintf_l(buffer, size, format, c_locale(), precision, value);
#elif defined(__APPLE__) || defined(__FreeBSD__)
    return snprintf_l(buffer, size, c_locale(), format, precision, value);
#else
    const InCLocale in_c;
    return std::snprintf(buffer, size, format, precision, value);
#endif
}

// The text printed, in a buffer of size bytes (enough for the conversion: never cut).
std::string print(char conversion, int precision, double value, std::size_t size) {
    std::string text(size, '\0');
    const int n = print_c(text.data(), text.size(), conversion, precision, value);
    text.resize(n > 0 ? std::min(static_cast<std::size_t>(n), size - 1) : 0);
    return text;
}

bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }

// ASCII alone: std::isalnum would ask the locale.
bool is_nan_char(char c) noexcept {
    return is_digit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

// The text at p starts with word (lower case), ignoring case.
bool starts_with_word(const char* p, const char* last, const char* word) noexcept {
    for (; *word; ++p, ++word) {
        if (p == last || (*p | 0x20) != *word) return false;
    }
    return true;
}

// A decimal number: its significant digits and the decimal exponent of the first.
struct Decimal {
    std::string digits;
    int exponent = 0;
};

// "d.ddde±XX" (printf's %e) as a Decimal; the sign is dropped.
Decimal decimal_of(const std::string& e_text) {
    Decimal d;
    std::size_t i = e_text[0] == '-' ? 1 : 0;
    for (; i < e_text.size() && e_text[i] != 'e'; ++i)
        if (e_text[i] != '.') d.digits += e_text[i];
    d.exponent = std::atoi(e_text.c_str() + i + 1);
    return d;
}

Decimal trimmed(Decimal d) {
    while (d.digits.size() > 1 && d.digits.back() == '0') d.digits.pop_back();
    return d;
}

// The same number of digits, one unit in the last place larger in magnitude.
Decimal next_up(Decimal d) {
    std::size_t i = d.digits.size();
    while (i > 0 && d.digits[i - 1] == '9') d.digits[--i] = '0';
    if (i == 0) {
        d.digits.insert(d.digits.begin(), '1');
        d.digits.pop_back();
        ++d.exponent;
    } else {
        ++d.digits[i - 1];
    }
    return d;
}

std::string scientific(const Decimal& d) {
    std::string out(1, d.digits[0]);
    if (d.digits.size() > 1) out += '.' + d.digits.substr(1);
    const int e = d.exponent < 0 ? -d.exponent : d.exponent;
    out += d.exponent < 0 ? "e-" : "e+";
    if (e < 10) out += '0';
    out += std::to_string(e);
    return out;
}

// d in fixed notation, when it has digits after the point.
std::string fixed(const Decimal& d) {
    if (d.exponent < 0) return "0." + std::string(static_cast<std::size_t>(-d.exponent - 1), '0') + d.digits;
    const auto point = static_cast<std::size_t>(d.exponent + 1);
    return d.digits.substr(0, point) + '.' + d.digits.substr(point);
}

double read_c(const std::string& text) { return strtod_c(text.c_str(), nullptr); }

}  // namespace

NumberRead parse_double(const char* first, const char* last, double& value) noexcept {
    // The lexeme is found here, by from_chars' grammar: strtod alone would also take white
    // space, '+' and hexadecimal in front, and read past last.
    const char* p = first;
    if (p != last && *p == '-') ++p;
    const char* end = p;
    bool word = false;
    bool nonzero = false;
    if (starts_with_word(p, last, "infinity")) {
        end = p + 8;
        word = true;
    } else if (starts_with_word(p, last, "inf")) {
        end = p + 3;
        word = true;
    } else if (starts_with_word(p, last, "nan")) {
        end = p + 3;
        word = true;
        if (end != last && *end == '(') {
            const char* q = end + 1;
            while (q != last && is_nan_char(*q)) ++q;
            if (q != last && *q == ')') end = q + 1;
        }
    } else {
        std::size_t digits = 0;
        for (; end != last && is_digit(*end); ++end, ++digits) nonzero = nonzero || *end != '0';
        if (end != last && *end == '.') {
            ++end;
            for (; end != last && is_digit(*end); ++end, ++digits) nonzero = nonzero || *end != '0';
        }
        if (digits == 0) return {first, std::errc::invalid_argument};
        if (end != last && (*end == 'e' || *end == 'E')) {
            const char* q = end + 1;
            if (q != last && (*q == '+' || *q == '-')) ++q;
            if (q != last && is_digit(*q)) {
                while (q != last && is_digit(*q)) ++q;
                end = q;
            }
        }
    }
    try {
        const std::string lexeme(first, end);
        const int saved_errno = errno;
        const double read = read_c(lexeme);
        errno = saved_errno;
        if (!word && (std::isinf(read) || (read == 0.0 && nonzero))) return {end, std::errc::result_out_of_range};
        value = read;
        return {end, std::errc()};
    } catch (...) {  // std::bad_alloc for a lexeme of many megabytes
        return {first, std::errc::not_enough_memory};
    }
}

std::string shortest_text(double value) {
    if (std::isnan(value)) return std::signbit(value) ? "-nan" : "nan";
    const std::string sign = std::signbit(value) ? "-" : "";
    if (std::isinf(value)) return sign + "inf";
    if (value == 0.0) return sign + "0";
    // The fewest significant digits that read back as value (17 always do), the nearest such
    // decimal; to_chars then writes it fixed or scientific, whichever is shorter (fixed on a tie).
    Decimal d;
    for (int precision = 1; precision <= 17; ++precision) {
        const std::string e_text = print('e', precision - 1, value, 40);
        const double read = read_c(e_text);
        if (read == value) {
            d = decimal_of(e_text);
            break;
        }
        // Just above a power of two the doubles below are twice as dense as those above, so the
        // nearest decimal can miss on the near side while the next one up reads back.
        if (std::abs(read) < std::abs(value)) {
            const Decimal up = next_up(decimal_of(e_text));
            if (read_c(sign + scientific(up)) == value) {
                d = up;
                break;
            }
        }
    }
    d = trimmed(d);
    // Fixed without a point means value is a whole number (below 2^53 a double near a whole
    // number N that reads back from N's digits is N), and to_chars then writes all its digits
    // exactly, as %.0f does: 2^55 is "36028797018963968", not "36028797018963970".
    const bool whole = d.exponent + 1 >= static_cast<int>(d.digits.size());
    const std::string f = whole ? print('f', 0, std::abs(value), 320) : fixed(d);
    const std::string s = scientific(d);
    return sign + (f.size() <= s.size() ? f : s);
}

std::string general_text(double value, int precision) {
    const int p = precision < 1 ? 1 : precision;
    return print('g', precision, value, static_cast<std::size_t>(p) + 16);
}

std::string fixed_text(double value, int digits) {
    const int d = digits < 0 ? 0 : digits;
    return print('f', digits, value, static_cast<std::size_t>(d) + 320);
}

}  // namespace grape::detail::portable
