// Test helpers for grape::Error: every module's tests check the messages of bad input.
#pragma once

#include <grape/error.hpp>

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

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

/// Expects f() to throw a grape::Error whose message contains every fragment.
template <class F>
void expect_error(F&& f, std::initializer_list<std::string> fragments) {
    const std::string message = error_text(f);
    for (const auto& fragment : fragments)
        EXPECT_NE(message.find(fragment), std::string::npos) << "message: " << message << "\nmissing: " << fragment;
}

}  // namespace grape::testing
