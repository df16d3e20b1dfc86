// boost::dynamic_bitset::count() built with -mpopcnt (bench_bits_boost_popcnt.cpp).
#pragma once

#include <boost/dynamic_bitset.hpp>

#include <cstddef>
#include <cstdint>

namespace boost_popcnt {

/// bits.count(), compiled for the popcnt instruction.
std::size_t count(const boost::dynamic_bitset<std::uint64_t>& bits);

}  // namespace boost_popcnt
