// Test helpers: checks of grape::Error messages for bad input, and the build mode.
#pragma once

#include <grape/error.hpp>

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <utility>

namespace grape::testing {

/// The message of the grape::Error that f() throws, or "(no grape::Error thrown)".
template <class F>
std::string error_text(F&& f) {
    try {
        f();
    } catch (const grape::Error& e) {
        return e.what();
    }
    return "(no grape::Error thrown)";
}

/// True in optimized builds; Debug and sanitizer builds run shortened variants of long runs.
#ifdef NDEBUG
inline constexpr bool fast_build = true;
#else
inline constexpr bool fast_build = false;
#endif

/// Expects f() to throw a grape::Error whose message contains every fragment.
template <class F>
void expect_error(F&& f, std::initializer_list<std::string> fragments) {
    const std::string message = error_text(f);
    for (const auto& fragment : fragments)
        EXPECT_NE(message.find(fragment), std::string::npos) << "message: " << message << "\nmissing: " << fragment;
}

/// Expects f() to throw a grape::Error whose message contains `fragment`.
template <class F>
void expect_error(F&& f, const std::string& fragment) {
    expect_error(std::forward<F>(f), {fragment});
}

}  // namespace grape::testing
