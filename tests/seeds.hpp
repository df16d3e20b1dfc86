// Seeds of the randomized tests. The ordinary run uses the fixed seed each test names, so every
// run explores the same cases and a failure reproduces; GRAPE_TEST_SEED=K (a whole number)
// moves every one of them to other seeds for a longer look (a soak before a release). A
// failure prints the seed its test names: rerun with the same GRAPE_TEST_SEED to reproduce it.
#pragma once

#include <cstdint>
#include <cstdlib>

namespace grape::testing {

inline std::uint64_t seed_shift() {
    static const std::uint64_t shift = [] {
        const char* v = std::getenv("GRAPE_TEST_SEED");
        return v && *v ? std::strtoull(v, nullptr, 10) * 0x9E3779B97F4A7C15ull : 0ull;  // 2⁶⁴/φ: spreads K
    }();
    return shift;
}

/// The seed a randomized test draws from: `fixed`, or another one under GRAPE_TEST_SEED.
inline std::uint64_t test_seed(std::uint64_t fixed) { return fixed + seed_shift(); }

}  // namespace grape::testing
