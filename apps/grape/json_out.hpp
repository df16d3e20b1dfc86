// The tool's numbers in and out: arguments read as checked doubles, answers written as JSON
// with 17 significant digits, so a double printed and read back is the same double.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

namespace grape::tool {

/// `text` as a finite double (an optional leading '+' allowed); otherwise a grape::Error
/// "WHAT must be a finite number (got 'TEXT')", so the message names the argument.
double parse_finite(std::string_view what, const std::string& text);

/// A double as text with 17 significant digits ("null" for NaN or infinity, which JSON lacks).
std::string json_number(double value);

/// {"key": value, ...} on one line, values as numbers with 17 significant digits.
std::string json_object(std::initializer_list<std::pair<std::string_view, double>> fields);

}  // namespace grape::tool
