#include "json_out.hpp"

#include <grape/error.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>

namespace grape::tool {

double parse_finite(std::string_view what, const std::string& text) {
    double value = 0.0;
    const char* first = text.data();
    const char* last = text.data() + text.size();
    if (first != last && *first == '+') ++first;
    const auto [end, ec] = std::from_chars(first, last, value);
    if (ec != std::errc() || end != last || first == last || !std::isfinite(value))
        throw Error(std::string(what) + " must be a finite number (got '" + text + "')");
    return value;
}

std::string json_number(double value) {
    if (!std::isfinite(value)) return "null";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

std::string json_object(std::initializer_list<std::pair<std::string_view, double>> fields) {
    std::string text = "{";
    bool first = true;
    for (const auto& [key, value] : fields) {
        if (!first) text += ", ";
        first = false;
        text += '"';
        text += key;
        text += "\": ";
        text += json_number(value);
    }
    return text + "}";
}

}  // namespace grape::tool
