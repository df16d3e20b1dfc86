// BitMagic as a peer of grape::SparseBitVector in bench_bits: built only when
// -DGRAPE_BITMAGIC_DIR=<BitMagic source tree> is given, in its own translation unit so that
// BitMagic gets its AVX2 build (BMAVX2OPT) without changing how the other contenders compile.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace bitmagic_peer {

/// The same bits the grape contenders use, as lists of set-bit indices.
struct Patterns {
    std::size_t bits = 0;
    std::vector<std::uint32_t> sparse;  // density 1/1000
    std::vector<std::uint32_t> dense_a, dense_b;
};

/// Builds the bm::bvector<> copies (optimize()d, as BitMagic recommends) and registers the
/// rows "sparse count", "sparse toggle + count", "sparse iterate" (enumerator and
/// for_each_bit visitor), "dense &=" and "dense &= + count" for BitMagic.
void register_rows(const Patterns& patterns);
/// Heap bytes of the sparse vector (bvector::calc_stat's memory_used).
std::size_t sparse_memory_bytes();

}  // namespace bitmagic_peer
