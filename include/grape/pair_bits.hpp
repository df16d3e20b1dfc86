// grape — one bit per unordered pair of n objects, on a BitVector.
//
//   grape::PairBits tested(objects.size());     // n(n−1)/2 bits (Ericson, RTCD)
//   if (!tested.test_and_set(a, b)) { collide(a, b); }
#pragma once

#include <grape/bits.hpp>
#include <grape/export_bits.hpp>

#include <cstddef>

namespace grape {

/// \addtogroup bits
/// @{

/// One bit per unordered pair {i, j} of n objects: n(n−1)/2 bits, with the pair at
/// index i(2n − i − 3)/2 + j − 1 for i < j (Ericson, Real-Time Collision Detection).
/// Typical use: test each pair of colliding objects once per frame.
class GRAPE_BITS_API PairBits {
public:
    /// Room for the pairs of `object_count` objects, all clear. Throws grape::Error when
    /// n(n−1)/2 does not fit in std::size_t.
    explicit PairBits(std::size_t object_count);

    /// n, the number of objects.
    std::size_t object_count() const noexcept { return n_; }
    /// n(n−1)/2, the number of pairs (and of bits).
    std::size_t pair_count() const noexcept { return bits_.size(); }
    /// The bit index of the pair {i, j}, in either order; throws grape::Error when
    /// i == j or an index is >= n.
    std::size_t index(std::size_t i, std::size_t j) const;
    /// The pair's bit (either order; errors as index()).
    bool test(std::size_t i, std::size_t j) const { return bits_.get(index(i, j)); }
    /// Sets the pair's bit to `value` (either order; errors as index()).
    void set(std::size_t i, std::size_t j, bool value = true) { bits_.set(index(i, j), value); }
    /// Sets the pair's bit and returns its previous value (either order; errors as index()).
    bool test_and_set(std::size_t i, std::size_t j) { return bits_.test_and_set(index(i, j)); }
    /// Clears every pair (e.g. at the start of a frame).
    void clear_all() noexcept { bits_.clear_all(); }
    /// The underlying bits.
    const BitVector& bits() const noexcept { return bits_; }
    /// The pair (i, j), i < j, at a bit index: the inverse of index(). Throws grape::Error
    /// when index >= pair_count().
    std::pair<std::size_t, std::size_t> pair(std::size_t index) const;

    /// Walks the set pairs (i, j), i < j, in index order (i, then j, increasing), keeping the
    /// row so each step is O(1) amortized (no square root per pair).
    class SetPairIterator {
    public:
        using iterator_concept = std::forward_iterator_tag;  ///< a forward iterator
        using iterator_category = std::forward_iterator_tag;  ///< a forward iterator
        using value_type = std::pair<std::size_t, std::size_t>;  ///< a set pair (i, j), i < j
        using difference_type = std::ptrdiff_t;  ///< as iterators need

        SetPairIterator() noexcept = default;
        /// The current pair (i, j), i < j.
        value_type operator*() const noexcept { return {i_, i_ + 1 + (*bit_ - row_start_)}; }
        /// Moves to the next set pair.
        SetPairIterator& operator++() noexcept {
            ++bit_;
            find_row();
            return *this;
        }
        /// Moves to the next set pair, returning the old position.
        SetPairIterator operator++(int) noexcept {
            SetPairIterator old = *this;
            ++*this;
            return old;
        }
        /// Same position.
        friend bool operator==(const SetPairIterator& a, const SetPairIterator& b) noexcept { return a.bit_ == b.bit_; }
        /// Past the last set pair.
        friend bool operator==(const SetPairIterator& it, std::default_sentinel_t) noexcept {
            return it.bit_ == std::default_sentinel;
        }

    private:
        friend class PairBits;
        SetPairIterator(BitVector::SetBitIterator bit, std::size_t n) noexcept : bit_(bit), n_(n), row_end_(n - 1) {
            find_row();
        }
        void find_row() noexcept {
            if (bit_ == std::default_sentinel) return;
            while (*bit_ >= row_end_) {  // row i holds the n − 1 − i pairs (i, i+1 … n−1)
                ++i_;
                row_start_ = row_end_;
                row_end_ += n_ - 1 - i_;
            }
        }
        BitVector::SetBitIterator bit_;
        std::size_t n_ = 0;
        std::size_t i_ = 0;          // row of the current pair
        std::size_t row_start_ = 0;  // index of (i, i+1)
        std::size_t row_end_ = 0;    // index of (i+1, i+2): one past the row
    };
    /// The set pairs as a range: `for (auto [i, j] : pairs.set_pairs())`.
    class SetPairs {
    public:
        SetPairIterator begin() const noexcept { return {bits_->set_bits().begin(), n_}; }  ///< the first set pair
        std::default_sentinel_t end() const noexcept { return {}; }  ///< past the last set pair

    private:
        friend class PairBits;
        SetPairs(const BitVector* bits, std::size_t n) noexcept : bits_(bits), n_(n) {}
        const BitVector* bits_;
        std::size_t n_;
    };
    /// The set pairs (i, j), i < j, in index order, as a range over this object.
    SetPairs set_pairs() const& noexcept { return {&bits_, n_}; }
    /// Not on a temporary: the range would outlive the bits.
    void set_pairs() const&& = delete;
    /// Calls f(i, j), i < j, for every set pair in index order.
    template <class F>
    void for_each_set(F&& f) const {
        for (auto it = set_pairs().begin(); it != std::default_sentinel; ++it) {
            const auto [i, j] = *it;
            f(i, j);
        }
    }

private:
    std::size_t n_;
    BitVector bits_;
};

/// @}

}  // namespace grape
