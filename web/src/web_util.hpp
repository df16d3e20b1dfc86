// Shared by the embind bindings: grape::Error as a JavaScript Error, options read from plain
// JavaScript objects, and JavaScript arrays of numbers.
#pragma once

#include <grape/error.hpp>
#include <grape/math.hpp>

#include <emscripten/val.h>

#include <exception>
#include <string>
#include <utility>
#include <vector>

namespace grape::web {

using emscripten::val;

/// Throws a JavaScript Error carrying `message` (a grape::Error's text, unchanged).
[[noreturn]] inline void throw_js(const std::string& message) {
    val::global("Error").new_(message).throw_();
}

/// Wraps a function so that a C++ exception leaves it as a JavaScript Error with the same
/// message (the C++ exception is finished before the JavaScript one is thrown).
template <auto F, class Sig = decltype(F)>
struct Guarded;
template <auto F, class R, class... A>
struct Guarded<F, R (*)(A...)> {
    static R call(A... args) {
        std::string message;
        try {
            return F(std::forward<A>(args)...);
        } catch (const std::exception& e) {
            message = e.what();
        }
        throw_js(message);
    }
};
/// `guarded<&f>`: f as a function pointer that throws JavaScript Errors.
template <auto F>
inline constexpr auto guarded = &Guarded<F>::call;

/// A member function as a free function of the object (this embind has no overloads for
/// noexcept member pointers): `method<&Path::point>`.
template <auto M, class Sig = decltype(M)>
struct Method;
template <auto M, class C, class R, class... A>
struct Method<M, R (C::*)(A...) const noexcept> {
    static R call(const C& c, A... args) { return (c.*M)(std::forward<A>(args)...); }
};
template <auto M, class C, class R, class... A>
struct Method<M, R (C::*)(A...) noexcept> {
    static R call(C& c, A... args) { return (c.*M)(std::forward<A>(args)...); }
};
template <auto M, class C, class R, class... A>
struct Method<M, R (C::*)(A...) const> {
    static R call(const C& c, A... args) { return (c.*M)(std::forward<A>(args)...); }
};
template <auto M, class C, class R, class... A>
struct Method<M, R (C::*)(A...)> {
    static R call(C& c, A... args) { return (c.*M)(std::forward<A>(args)...); }
};
template <auto M>
inline constexpr auto method = &Method<M>::call;

/// options[name] when it is present (not undefined or null).
inline bool has(const val& options, const char* name) {
    if (options.isUndefined() || options.isNull()) return false;
    const val v = options[name];
    return !v.isUndefined() && !v.isNull();
}
/// options[name] as a number, or `fallback` when absent; a non-number is an error naming it.
inline double number_or(const val& options, const char* name, double fallback, const char* where) {
    if (!has(options, name)) return fallback;
    const val v = options[name];
    if (!v.isNumber()) throw Error(std::string(where) + ": option '" + name + "' must be a number");
    return v.as<double>();
}
/// options[name] as a boolean, or `fallback` when absent.
inline bool bool_or(const val& options, const char* name, bool fallback) {
    if (!has(options, name)) return fallback;
    return options[name].as<bool>();
}
/// options[name] as a string, or `fallback` when absent.
inline std::string string_or(const val& options, const char* name, const std::string& fallback, const char* where) {
    if (!has(options, name)) return fallback;
    const val v = options[name];
    if (!v.isString()) throw Error(std::string(where) + ": option '" + name + "' must be a string");
    return v.as<std::string>();
}
/// A Vec2 from {x, y}.
inline Vec2 vec2_or(const val& options, const char* name, Vec2 fallback, const char* where) {
    if (!has(options, name)) return fallback;
    const val v = options[name];
    return {number_or(v, "x", 0.0, where), number_or(v, "y", 0.0, where)};
}
/// The numbers of a JavaScript array or typed array.
inline std::vector<double> numbers(const val& array) {
    return emscripten::convertJSArrayToNumberVector<double>(array);
}
/// A Float64Array copy of `values`.
inline val float64_array(const double* data, std::size_t count) {
    return val::global("Float64Array").new_(val(emscripten::typed_memory_view(count, data)));
}

}  // namespace grape::web
