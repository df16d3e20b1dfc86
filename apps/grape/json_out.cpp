#include "json_out.hpp"

#include <grape/error.hpp>

#include "math/number_text.hpp"

#include <cmath>
#include <string_view>

namespace grape::tool {

double parse_finite(std::string_view what, const std::string& text) {
    double value = 0.0;
    const std::string_view digits = !text.empty() && text.front() == '+' ? std::string_view(text).substr(1) : text;
    if (!detail::parse_finite(digits, value))
        throw Error(std::string(what) + " must be a finite number (got '" + text + "')");
    return value;
}

std::string json_number(double value) {
    return std::isfinite(value) ? detail::general_text(value, 17) : "null";
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
