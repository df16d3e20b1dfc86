// BitVector over a range of bits: set/reset/flip/count of [first, last), rank, select and the
// backward searches. Whole words in the middle go through the word kernels; only the two end
// words are masked.
#include <grape/bits.hpp>
#include <grape/error.hpp>

#include "word_kernels.hpp"

#include <cstring>

namespace grape {
namespace {

using detail::low_bits;
using Word = BitVector::Word;

// The word index and the mask of the bits of [first, last) in the first and last word they
// touch (first < last).
struct Span {
    std::size_t k0, k1;  // first and last word touched
    Word m0, m1;         // the range's bits in word k0 and in word k1 (m0 == m1 when k0 == k1)
};

Span span_of(std::size_t first, std::size_t last) noexcept {
    const std::size_t k0 = first / 64, k1 = (last - 1) / 64;
    const Word head = ~low_bits(first % 64);
    const Word tail = detail::tail_mask(last);
    if (k0 == k1) return {k0, k1, head & tail, head & tail};
    return {k0, k1, head, tail};
}

// The index of the set bit with `rank` set bits before it, inside one word that holds more
// than `rank` set bits: bytes first (at most 8 steps), then bits (at most 8).
std::size_t select_in_word(Word w, std::size_t rank) noexcept {
    std::size_t base = 0;
    for (;;) {
        const std::size_t c = static_cast<std::size_t>(std::popcount(w & 0xFF));
        if (c > rank) break;
        rank -= c;
        w >>= 8;
        base += 8;
    }
    for (;; w &= w - 1) {
        if (rank-- == 0) return base + static_cast<std::size_t>(std::countr_zero(w));
    }
}

}  // namespace

void BitVector::set_range(std::size_t first, std::size_t last, bool value) {
    check_range(first, last, "set_range");
    if (first == last) return;
    const Span s = span_of(first, last);
    auto apply = [value](Word& w, Word m) { w = value ? (w | m) : (w & ~m); };
    apply(words_[s.k0], s.m0);
    if (s.k1 == s.k0) return;
    // memset, not std::fill: the fill value is not a constant, so the compiler would not make
    // the loop a memset by itself.
    std::memset(words_.data() + s.k0 + 1, value ? 0xFF : 0, (s.k1 - s.k0 - 1) * sizeof(Word));
    apply(words_[s.k1], s.m1);
}

void BitVector::flip_range(std::size_t first, std::size_t last) {
    check_range(first, last, "flip_range");
    if (first == last) return;
    const Span s = span_of(first, last);
    words_[s.k0] ^= s.m0;
    if (s.k1 == s.k0) return;
    detail::word_kernels().flip(words_.data() + s.k0 + 1, s.k1 - s.k0 - 1);
    words_[s.k1] ^= s.m1;
}

std::size_t BitVector::count_range(std::size_t first, std::size_t last) const {
    check_range(first, last, "count_range");
    if (first == last) return 0;
    const Span s = span_of(first, last);
    if (s.k1 == s.k0) return static_cast<std::size_t>(std::popcount(words_[s.k0] & s.m0));
    return static_cast<std::size_t>(std::popcount(words_[s.k0] & s.m0)) +
           detail::word_kernels().count(words_.data() + s.k0 + 1, s.k1 - s.k0 - 1) +
           static_cast<std::size_t>(std::popcount(words_[s.k1] & s.m1));
}

std::size_t BitVector::rank(std::size_t i) const {
    if (i > size_) {
        throw Error("BitVector::rank: index " + std::to_string(i) + " is past the end (size " + std::to_string(size_) +
                    ")");
    }
    const std::size_t k = i / 64;
    std::size_t r = detail::word_kernels().count(words_.data(), k);
    if (i % 64 != 0) r += static_cast<std::size_t>(std::popcount(words_[k] & low_bits(i % 64)));
    return r;
}

std::size_t BitVector::select(std::size_t k) const noexcept {
    std::size_t before = 0;
    const std::size_t word = detail::word_kernels().find_rank(words_.data(), words_.size(), k, before);
    if (word == words_.size()) return npos;
    return word * 64 + select_in_word(words_[word], k - before);
}

// The highest set bit below i (i <= size_).
std::size_t BitVector::find_before(std::size_t i) const noexcept {
    if (i == 0) return npos;
    std::size_t k = (i - 1) / 64;
    Word w = words_[k] & detail::tail_mask(i);
    while (w == 0) {
        // Four words per test while the scan is long (a sparse vector's top is mostly zeros).
        while (k >= 4 && (words_[k - 1] | words_[k - 2] | words_[k - 3] | words_[k - 4]) == 0) k -= 4;
        if (k == 0) return npos;
        w = words_[--k];
    }
    return k * 64 + 63 - static_cast<std::size_t>(std::countl_zero(w));
}

}  // namespace grape
