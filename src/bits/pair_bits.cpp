#include <grape/bits.hpp>
#include <grape/error.hpp>

#include "pair_math.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace grape {
namespace detail {

std::size_t pair_count_for(std::size_t n, const char* who) {
    if (n < 2) return 0;
    // n(n−1)/2 computed as (even factor / 2) × other factor, checked against overflow.
    const std::size_t a = n % 2 == 0 ? n / 2 : n;
    const std::size_t b = n % 2 == 0 ? n - 1 : (n - 1) / 2;
    if (a > (std::numeric_limits<std::size_t>::max() - BitVector::word_bits) / b) {
        throw Error(std::string(who) + ": object_count " + std::to_string(n) + " is too large (n(n-1)/2 bits overflow)");
    }
    return a * b;
}

std::size_t pair_index(std::size_t n, std::size_t i, std::size_t j, const char* who) {
    if (i >= n || j >= n) {
        throw Error(std::string(who) + ": index " + std::to_string(i >= n ? i : j) + " is out of range (object_count " +
                    std::to_string(n) + ")");
    }
    if (i == j) throw Error(std::string(who) + ": i and j are both " + std::to_string(i) + "; a pair needs two objects");
    if (i > j) std::swap(i, j);
    // i(2n − i − 3) is even (i odd makes 2n − i − 3 even), so the halving is exact; both
    // factors are below 2n and the product is below 2·pair_count, which the constructor bounded.
    return i * (2 * n - i - 3) / 2 + j - 1;
}

std::pair<std::size_t, std::size_t> pair_at(std::size_t n, std::size_t index, const char* who) {
    const std::size_t count = n < 2 ? 0 : pair_count_for(n, who);
    if (index >= count) {
        throw Error(std::string(who) + "::pair: index " + std::to_string(index) + " is out of range (pair_count " +
                    std::to_string(count) + ")");
    }
    // Row i starts at s(i) = i(2n − i − 1)/2; the i with s(i) <= index < s(i + 1) solves a
    // quadratic. The double estimate is off by at most a few rows for any n whose pairs fit
    // in std::size_t, and the integer loops make it exact.
    const auto start = [n](std::size_t i) { return i % 2 == 0 ? i / 2 * (2 * n - i - 1) : (2 * n - i - 1) / 2 * i; };
    const double b = 2.0 * static_cast<double>(n) - 1.0;
    const double disc = std::max(0.0, b * b - 8.0 * static_cast<double>(index));
    const double estimate = std::floor((b - std::sqrt(disc)) / 2.0);
    std::size_t i = estimate <= 0 ? 0 : std::min(static_cast<std::size_t>(estimate), n - 2);
    while (i > 0 && start(i) > index) --i;
    while (i + 2 < n && start(i + 1) <= index) ++i;
    return {i, i + 1 + (index - start(i))};
}

}  // namespace detail

PairBits::PairBits(std::size_t object_count)
    : n_(object_count), bits_(detail::pair_count_for(object_count, "PairBits")) {}

std::size_t PairBits::index(std::size_t i, std::size_t j) const { return detail::pair_index(n_, i, j, "PairBits"); }

std::pair<std::size_t, std::size_t> PairBits::pair(std::size_t index) const {
    return detail::pair_at(n_, index, "PairBits");
}

}  // namespace grape
