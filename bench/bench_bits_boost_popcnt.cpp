// boost::dynamic_bitset's count() compiled for the popcnt instruction (-mpopcnt, this file
// only): what a user who builds with -mpopcnt or -march=native gets, beside the default build
// of the other contenders (x86-64 baseline, where boost counts through __builtin_popcountl's
// library fallback). The wrapper is flattened so boost's inline count() is compiled here and
// not shared with the default build's copy at link time.
#include "bench_bits_boost_popcnt.hpp"

namespace boost_popcnt {

__attribute__((flatten)) std::size_t count(const boost::dynamic_bitset<std::uint64_t>& bits) { return bits.count(); }

}  // namespace boost_popcnt
