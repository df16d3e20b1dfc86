#include "json_out.hpp"

#include <cmath>
#include <cstdio>

namespace grape::tool {

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
