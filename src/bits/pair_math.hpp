// The pair index shared by PairBits and SparsePairBits: pair {i, j}, i < j, of n objects at
// i(2n − i − 3)/2 + j − 1 (Ericson, Real-Time Collision Detection), and its inverse.
#pragma once

#include <cstddef>
#include <utility>

namespace grape::detail {

/// n(n−1)/2; throws grape::Error naming `who` when it does not fit in a bit count.
std::size_t pair_count_for(std::size_t n, const char* who);
/// The index of {i, j} (either order) among n objects; throws grape::Error naming `who` when
/// i == j or an index is >= n.
std::size_t pair_index(std::size_t n, std::size_t i, std::size_t j, const char* who);
/// The pair (i, j), i < j, at an index below n(n−1)/2 (checked, naming `who`).
std::pair<std::size_t, std::size_t> pair_at(std::size_t n, std::size_t index, const char* who);

}  // namespace grape::detail
