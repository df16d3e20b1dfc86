// Minimal JSON output for the tool's answers: numbers with 17 significant digits, so a
// double printed and read back is the same double.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

namespace grape::tool {

/// A double as text with 17 significant digits ("null" for NaN or infinity, which JSON lacks).
std::string json_number(double value);

/// {"key": value, ...} on one line, values as numbers with 17 significant digits.
std::string json_object(std::initializer_list<std::pair<std::string_view, double>> fields);

}  // namespace grape::tool
