// grape — sparse bits: a bit vector that stores each 65,536-bit block as what it costs least.
//
//   grape::SparseBitVector hits(100'000'000);   // 100 M bits, a few thousand set: kilobytes
//   hits.set(31'337);
//   hits.for_each_set([](std::size_t i) { ... });
//
// A block with at most 4,096 set bits keeps their positions as a sorted array of 16-bit
// offsets (2 bytes per set bit); a fuller one is a plain bitmap of 1,024 words (8 KiB, the
// size of 4,096 offsets), combined with the same popcnt/AVX2 word loops as BitVector; a block
// with no set bit holds nothing. Each block keeps its count, so count() is O(blocks). The
// representation is canonical (it depends only on the bits), so == compares blocks directly.
// This is the layout of Roaring bitmaps (Chambi, Lemire et al., 2016), without run blocks.
#pragma once

#include <grape/bits.hpp>
#include <grape/detail/line_allocator.hpp>
#include <grape/export_bits.hpp>

#include <bit>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <new>
#include <utility>
#include <vector>

namespace grape {

/// \addtogroup bits
/// @{

/// A fixed-size bit vector for sparse or clustered bits; bit i lives in block i / 65,536.
/// Element access is checked by assert in debug builds; combining two vectors throws
/// grape::Error when their sizes differ.
class GRAPE_BITS_API SparseBitVector {
public:
    using Word = std::uint64_t;  ///< a word of a bitmap block, bit 0 lowest
    /// Bits per block.
    static constexpr std::size_t block_bits = 65536;
    /// Set bits a block may hold as an array; one more makes it a bitmap.
    static constexpr std::size_t array_limit = 4096;

    /// An empty vector (size 0).
    SparseBitVector() noexcept = default;
    /// `size` bits, all clear (no storage beyond one small record per block).
    explicit SparseBitVector(std::size_t size);
    /// The same bits as a BitVector.
    static SparseBitVector from_bits(const BitVector& bits);
    /// The bits as a BitVector.
    BitVector to_bits() const;

    /// Number of bits.
    std::size_t size() const noexcept { return size_; }
    /// Number of set bits (the sum of the blocks' counts; a bitmap block that `&=` left
    /// uncounted is counted here, at memory speed, without being changed).
    std::size_t count() const noexcept;
    /// At least one bit set.
    bool any() const noexcept;
    /// Heap bytes held (capacities of the block table, the arrays and the bitmaps).
    std::size_t memory_bytes() const noexcept;
    /// Blocks stored as bitmaps (the others are arrays or empty).
    std::size_t bitmap_blocks() const noexcept;

    /// Bit i (i < size(); asserted in debug builds). O(log 4096) in an array block.
    bool get(std::size_t i) const noexcept;
    /// Sets bit i to `value` (i < size()); may allocate, or change the block's form.
    void set(std::size_t i, bool value = true);
    /// Clears bit i (i < size()).
    void reset(std::size_t i) { set(i, false); }
    /// Sets bit i and returns its previous value (i < size()).
    bool test_and_set(std::size_t i);
    /// Every bit to 0 (frees the blocks' storage).
    void clear_all() noexcept;
    /// Gives back the arrays' spare capacity (growth by set() leaves up to half unused) and
    /// turns bitmap blocks that `&=` left sparse back into arrays, as BitMagic's optimize()
    /// does for its blocks.
    void shrink_to_fit();

    /// Bitwise and; throws grape::Error when sizes differ. Two bitmap blocks are anded in
    /// place at memory speed and left as a bitmap whose count is taken when next needed
    /// (count(), a clear by set(), shrink_to_fit()), even if few bits remain.
    SparseBitVector& operator&=(const SparseBitVector& other);
    /// Bitwise or; throws grape::Error when sizes differ.
    SparseBitVector& operator|=(const SparseBitVector& other);

    /// Calls f(i) for every set bit i in increasing order.
    template <class F>
    void for_each_set(F&& f) const {
        for (std::size_t b = 0; b < blocks_.size(); ++b) {
            const Block& block = blocks_[b];
            const std::size_t base = b * block_bits;
            if (!block.bitmap.empty()) {
                for (std::size_t k = 0; k < block.bitmap.size(); ++k)
                    for (Word w = block.bitmap[k]; w != 0; w &= w - 1)
                        f(base + k * 64 + static_cast<std::size_t>(std::countr_zero(w)));
            } else {
                for (const std::uint16_t p : block.array) f(base + p);
            }
        }
    }

    /// Same size and same bits (whatever form their blocks have).
    friend GRAPE_BITS_API bool operator==(const SparseBitVector& a, const SparseBitVector& b) noexcept;

private:
public:
    /// Block::count of a bitmap block that `&=` left uncounted (internal).
    static constexpr std::uint32_t uncounted = 0xFFFFFFFFu;

private:
    // Bitmaps on 64-byte boundaries, so that no 32-byte load of the word kernels straddles
    // two cache lines (malloc's 16-byte alignment split every other one).
    using Bitmap = std::vector<Word, detail::LineAllocator<Word>>;

    struct Block {
        std::uint32_t count = 0;  // set bits, or `uncounted` (bitmap blocks after `&=` only)
        std::vector<std::uint16_t> array;  // sorted offsets, when 0 < count <= array_limit
        Bitmap bitmap;                     // block_bits / 64 words, when count > array_limit
        friend bool operator==(const Block&, const Block&) = default;
    };
    static void to_bitmap(Block& block);
    static void fit(Block& block);  // counts the block and makes the form match the count
    static std::size_t count_of(const Block& block) noexcept;
    static bool same_bits(const Block& x, const Block& y) noexcept;
    void check_same_size(const SparseBitVector& other, const char* operation) const;

    std::vector<Block> blocks_;
    std::size_t size_ = 0;
};

/// PairBits over a SparseBitVector, for many objects of which few pairs are ever set: the
/// same index (pair {i, j}, i < j, at i(2n − i − 3)/2 + j − 1), the same errors. 100,000
/// objects have 4,999,950,000 pairs: 625 MB as a PairBits, a 4 MB block table plus 2 bytes per
/// set pair here.
class GRAPE_BITS_API SparsePairBits {
public:
    /// Room for the pairs of `object_count` objects, all clear. Throws grape::Error when
    /// n(n−1)/2 does not fit in std::size_t.
    explicit SparsePairBits(std::size_t object_count);

    /// n, the number of objects.
    std::size_t object_count() const noexcept { return n_; }
    /// n(n−1)/2, the number of pairs (and of bits).
    std::size_t pair_count() const noexcept { return bits_.size(); }
    /// The bit index of the pair {i, j}, in either order; throws grape::Error when i == j or
    /// an index is >= n.
    std::size_t index(std::size_t i, std::size_t j) const;
    /// The pair (i, j), i < j, at a bit index; throws grape::Error when index >= pair_count().
    std::pair<std::size_t, std::size_t> pair(std::size_t index) const;
    /// The pair's bit (either order; errors as index()).
    bool test(std::size_t i, std::size_t j) const { return bits_.get(index(i, j)); }
    /// Sets the pair's bit to `value` (either order; errors as index()).
    void set(std::size_t i, std::size_t j, bool value = true) { bits_.set(index(i, j), value); }
    /// Sets the pair's bit and returns its previous value (either order; errors as index()).
    bool test_and_set(std::size_t i, std::size_t j) { return bits_.test_and_set(index(i, j)); }
    /// Clears every pair, freeing the blocks' storage.
    void clear_all() noexcept { bits_.clear_all(); }
    /// The underlying bits.
    const SparseBitVector& bits() const noexcept { return bits_; }
    /// Calls f(i, j), i < j, for every set pair in index order, keeping the row as it goes
    /// (O(1) amortized per pair, no square root).
    template <class F>
    void for_each_set(F&& f) const {
        std::size_t i = 0, row_start = 0, row_end = n_ < 2 ? 0 : n_ - 1;
        bits_.for_each_set([&](std::size_t k) {
            while (k >= row_end) {  // row i holds the n − 1 − i pairs (i, i+1 … n−1)
                ++i;
                row_start = row_end;
                row_end += n_ - 1 - i;
            }
            f(i, i + 1 + (k - row_start));
        });
    }

private:
    std::size_t n_;
    SparseBitVector bits_;
};

/// @}

}  // namespace grape
