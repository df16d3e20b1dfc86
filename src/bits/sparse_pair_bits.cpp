#include <grape/sparse_bits.hpp>

#include "pair_math.hpp"

namespace grape {

SparsePairBits::SparsePairBits(std::size_t object_count)
    : n_(object_count), bits_(detail::pair_count_for(object_count, "SparsePairBits")) {}

std::size_t SparsePairBits::index(std::size_t i, std::size_t j) const {
    return detail::pair_index(n_, i, j, "SparsePairBits");
}

std::pair<std::size_t, std::size_t> SparsePairBits::pair(std::size_t index) const {
    return detail::pair_at(n_, index, "SparsePairBits");
}

}  // namespace grape
