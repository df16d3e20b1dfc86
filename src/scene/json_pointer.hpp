// JSON pointers for error messages (RFC 6901), shared by the scene and sprite-sheet readers:
// every read knows where its value is, so an error names it.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace grape::detail {

/// `pointer` extended by an object key ('~' and '/' escaped as ~0 and ~1).
inline std::string child(const std::string& pointer, std::string_view key) {
    std::string out = pointer + "/";
    for (char c : key) {
        if (c == '~') out += "~0";
        else if (c == '/') out += "~1";
        else out += c;
    }
    return out;
}

/// `pointer` extended by an array index.
inline std::string child(const std::string& pointer, std::size_t index) { return pointer + "/" + std::to_string(index); }

/// "a number", "an object", … for "expected X, got Y" messages.
template <class Json>
std::string type_of(const Json& j) {
    if (j.is_number()) return "a number";
    if (j.is_string()) return "a string";
    if (j.is_boolean()) return "a boolean";
    if (j.is_array()) return "an array";
    if (j.is_object()) return "an object";
    return "null";
}

/// The member `key` of `obj` as true or false, `fallback` when absent; otherwise
/// `fail(pointer of the member, why)` (the scene and sprite-sheet readers differ only in it).
template <class Json, class Fail>
bool bool_member(const Json& obj, const std::string& pointer, std::string_view key, bool fallback, Fail fail) {
    const auto it = obj.find(key);
    if (it == obj.end()) return fallback;
    if (!it->is_boolean()) fail(child(pointer, key), "expected true or false, got " + type_of(*it));
    return it->template get<bool>();
}

/// `j` as a string; otherwise `fail(pointer, why)`.
template <class Json, class Fail>
std::string string_of(const Json& j, const std::string& pointer, Fail fail) {
    if (!j.is_string()) fail(pointer, "expected a string, got " + type_of(j));
    return j.template get<std::string>();
}

}  // namespace grape::detail
