// std::to_chars and std::from_chars for double, for standard libraries that lack them
// (emscripten 3.1.6's libc++ has only the integer overloads). Included before every source
// of the WebAssembly build; with a complete <charconv> it adds nothing.
//   to_chars(first, last, value): the shortest text that reads back as the same double, in
//     fixed or scientific form, whichever is shorter (fixed on a tie), as the standard says.
//   from_chars(first, last, value): the general format: [-]digits[.digits][e[±]digits], inf,
//     infinity, nan; no leading '+' or space; out of range leaves value unchanged.
#pragma once

#include <charconv>
#include <version>

#if !defined(__cpp_lib_to_chars)

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

namespace std {

inline to_chars_result to_chars(char* first, char* last, double value) {
    char text[64];
    std::size_t n = 0;
    auto put = [&](const char* s) { while (*s) text[n++] = *s++; };
    if (std::signbit(value) && !std::isnan(value)) text[n++] = '-';
    if (std::isnan(value)) put(std::signbit(value) ? "-nan" : "nan");
    else if (std::isinf(value)) put("inf");
    else if (value == 0.0) put("0");
    else {
        // The fewest significant digits that round-trip (17 always do).
        char sci[40];
        int precision = 1;
        for (; precision < 17; ++precision) {
            std::snprintf(sci, sizeof sci, "%.*e", precision - 1, value);
            if (std::strtod(sci, nullptr) == value) break;
        }
        std::snprintf(sci, sizeof sci, "%.*e", precision - 1, value);
        char digits[20];
        int count = 0;
        const char* p = sci + (sci[0] == '-' ? 1 : 0);
        for (; *p != 'e'; ++p)
            if (*p != '.') digits[count++] = *p;
        const int exponent = std::atoi(p + 1);
        while (count > 1 && digits[count - 1] == '0') --count;
        char scientific[32];
        int s = 0;
        scientific[s++] = digits[0];
        if (count > 1) {
            scientific[s++] = '.';
            for (int i = 1; i < count; ++i) scientific[s++] = digits[i];
        }
        s += std::snprintf(scientific + s, sizeof scientific - std::size_t(s), "e%c%02d", exponent < 0 ? '-' : '+',
                           exponent < 0 ? -exponent : exponent);
        std::string fixed;
        if (exponent >= 0) {
            for (int i = 0; i < count || i <= exponent; ++i) {
                if (i == exponent + 1) fixed += '.';
                fixed += i < count ? digits[i] : '0';
            }
        } else {
            fixed = "0.";
            fixed.append(std::size_t(-exponent - 1), '0');
            fixed.append(digits, std::size_t(count));
        }
        if (fixed.size() <= std::size_t(s)) put(fixed.c_str());
        else {
            scientific[s] = '\0';
            put(scientific);
        }
    }
    if (std::size_t(last - first) < n) return {last, errc::value_too_large};
    std::memcpy(first, text, n);
    return {first + n, errc()};
}

inline from_chars_result from_chars(const char* first, const char* last, double& value) {
    const char* p = first;
    if (p < last && *p == '-') ++p;
    auto word = [&](const char* w) {
        const std::size_t k = std::strlen(w);
        if (std::size_t(last - p) < k) return false;
        for (std::size_t i = 0; i < k; ++i)
            if ((p[i] | 0x20) != w[i]) return false;
        return true;
    };
    const char* end = p;
    if (word("infinity")) end = p + 8;
    else if (word("inf")) end = p + 3;
    else if (word("nan")) {
        end = p + 3;
        if (end < last && *end == '(') {
            const char* q = end + 1;
            while (q < last && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
            if (q < last && *q == ')') end = q + 1;
        }
    } else {
        int digits = 0;
        while (end < last && *end >= '0' && *end <= '9') { ++end; ++digits; }
        if (end < last && *end == '.') {
            ++end;
            while (end < last && *end >= '0' && *end <= '9') { ++end; ++digits; }
        }
        if (digits == 0) return {first, errc::invalid_argument};
        if (end < last && (*end == 'e' || *end == 'E')) {
            const char* q = end + 1;
            if (q < last && (*q == '+' || *q == '-')) ++q;
            if (q < last && *q >= '0' && *q <= '9') {
                while (q < last && *q >= '0' && *q <= '9') ++q;
                end = q;
            }
        }
    }
    if (end == p) return {first, errc::invalid_argument};
    const std::string lexeme(first, end);
    errno = 0;
    const double parsed = std::strtod(lexeme.c_str(), nullptr);
    if (errno == ERANGE && (std::isinf(parsed) || parsed == 0.0)) return {end, errc::result_out_of_range};
    value = parsed;
    return {end, errc()};
}

}  // namespace std

#endif
