// Whole-vector word loops for BitVector, with the machine's instructions chosen at run time.
// CI and packagers build without -march=native, so the popcnt and AVX2 versions are compiled
// as separate target clones and picked once from the CPU's feature bits.
#pragma once

#include <grape/export_bits.hpp>

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
    /// a &= b, returning the set bits of the result (one pass: the sparse vector's bitmap blocks).
    std::size_t (*and_count)(Word* a, const Word* b, std::size_t n) noexcept;
    /// words[0, n) as one 64n-bit number, shifted in place towards the high end by s bits
    /// (any s; zeros come in at the bottom, bits past the top are lost).
    void (*shift_up)(Word* words, std::size_t n, std::size_t s) noexcept;
    /// The same towards the low end (zeros come in at the top).
    void (*shift_down)(Word* words, std::size_t n, std::size_t s) noexcept;
    /// Index of the word holding the set bit with `rank` set bits before it, or n when
    /// words[0, n) hold `rank` set bits or fewer; `before` receives the set bits of the words
    /// ahead of the one returned (all of them when it is n).
    std::size_t (*find_rank)(const Word* words, std::size_t n, std::size_t rank, std::size_t& before) noexcept;
    const char* name;                                                  ///< "avx2+popcnt", "popcnt", "generic"
};

/// Words needed for `bits` bits.
constexpr std::size_t words_for(std::size_t bits) noexcept { return bits / 64 + (bits % 64 != 0 ? 1 : 0); }
/// The bits [0, b) of a word, b in [0, 64).
constexpr Word low_bits(std::size_t b) noexcept { return (Word{1} << b) - 1; }
/// The bits of the last word that lie inside `size` (all ones when the word is full).
constexpr Word tail_mask(std::size_t size) noexcept { return size % 64 == 0 ? ~Word{0} : low_bits(size % 64); }

/// The kernels for this machine, selected on first use.
GRAPE_BITS_API const WordKernels& word_kernels() noexcept;

/// The portable kernels (for tests that compare every version against each other; exported,
/// like runnable_word_kernels, so that they do so against a shared grape_bits too).
GRAPE_BITS_API const WordKernels& generic_word_kernels() noexcept;

/// Every version this machine can run, the generic one first; `count` receives how many.
GRAPE_BITS_API const WordKernels* const* runnable_word_kernels(std::size_t& count) noexcept;

}  // namespace grape::detail
