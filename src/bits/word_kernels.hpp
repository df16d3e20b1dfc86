// Whole-vector word loops for BitVector, with the machine's instructions chosen at run time.
// CI and packagers build without -march=native, so the popcnt and AVX2 versions are compiled
// as separate target clones and picked once from the CPU's feature bits.
#pragma once

#include <cstddef>
#include <cstdint>

namespace grape::detail {

using Word = std::uint64_t;

/// The word loops of one instruction set.
struct WordKernels {
    std::size_t (*count)(const Word* words, std::size_t n) noexcept;  ///< set bits in words[0, n)
    void (*and_with)(Word* a, const Word* b, std::size_t n) noexcept;  ///< a &= b
    void (*or_with)(Word* a, const Word* b, std::size_t n) noexcept;   ///< a |= b
    void (*xor_with)(Word* a, const Word* b, std::size_t n) noexcept;  ///< a ^= b
    void (*and_not)(Word* a, const Word* b, std::size_t n) noexcept;   ///< a &= ~b
    void (*flip)(Word* a, std::size_t n) noexcept;                     ///< a = ~a
    const char* name;                                                  ///< "avx2+popcnt", "popcnt", "generic"
};

/// The kernels for this machine, selected on first use.
const WordKernels& word_kernels() noexcept;

/// The portable kernels (for tests that compare every version against each other).
const WordKernels& generic_word_kernels() noexcept;

/// Every version this machine can run, the generic one first; `count` receives how many.
const WordKernels* const* runnable_word_kernels(std::size_t& count) noexcept;

}  // namespace grape::detail
