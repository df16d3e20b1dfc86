// grape — bits: a packed bit vector, one bit per unordered pair, and key state.
//
//   grape::BitVector seen(10'000'000);          // 1.25 MB instead of 10 MB of bool
//   seen.set(42);
//   for (std::size_t i : seen.set_bits()) { ... }
//
//   grape::PairBits tested(objects.size());     // n(n−1)/2 bits (Ericson, RTCD)
//   if (!tested.test_and_set(a, b)) { collide(a, b); }
//
// Whole-vector operations (count, &=, |=, ^=, ~, set_all) run over 64-bit words and pick
// the machine's instructions at run time (popcnt, AVX2), so a plain -O2 build is fast.
// Bits past size() are always zero: they never show in count(), all(), ~, ==, or hash.
#pragma once

#include <bit>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <iosfwd>
#include <iterator>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grape {

/// A resizable sequence of bits packed into 64-bit words; bit i lives in word i/64 at bit i%64.
/// Element access is noexcept and checked by assert in debug builds; at() is always checked.
/// Operations combining two vectors throw grape::Error when their sizes differ.
class BitVector {
public:
    using Word = std::uint64_t;
    /// Bits per storage word.
    static constexpr std::size_t word_bits = 64;
    /// Returned by find_first()/find_next() when there is no further set bit.
    static constexpr std::size_t npos = static_cast<std::size_t>(-1);

    /// Iterates the indices of the set bits in increasing order (a countr_zero walk).
    class SetBitIterator {
    public:
        using iterator_concept = std::forward_iterator_tag;
        using iterator_category = std::forward_iterator_tag;
        using value_type = std::size_t;
        using difference_type = std::ptrdiff_t;

        SetBitIterator() noexcept = default;
        /// Index of the current set bit.
        std::size_t operator*() const noexcept { return base_ + static_cast<std::size_t>(std::countr_zero(current_)); }
        /// Moves to the next set bit (or to the end).
        SetBitIterator& operator++() noexcept {
            current_ &= current_ - 1;  // drop the lowest set bit
            if (current_ == 0) next_word();
            return *this;
        }
        /// Moves to the next set bit, returning the old position.
        SetBitIterator operator++(int) noexcept {
            SetBitIterator old = *this;
            ++*this;
            return old;
        }
        /// Same position.
        friend bool operator==(const SetBitIterator& a, const SetBitIterator& b) noexcept {
            return a.word_ == b.word_ && a.current_ == b.current_;
        }
        /// Past the last set bit.
        friend bool operator==(const SetBitIterator& it, std::default_sentinel_t) noexcept {
            return it.word_ == it.end_;
        }

    private:
        friend class BitVector;
        SetBitIterator(const Word* begin, const Word* end) noexcept : word_(begin), end_(end) {
            if (word_ != end_) {
                current_ = *word_;
                if (current_ == 0) next_word();
            }
        }
        void next_word() noexcept {
            while (++word_ != end_) {
                base_ += word_bits;
                if ((current_ = *word_) != 0) return;
            }
        }
        const Word* word_ = nullptr;  // the word holding the current bit; end_ when done
        const Word* end_ = nullptr;
        Word current_ = 0;            // the bits of *word_ not yet visited
        std::size_t base_ = 0;        // index of bit 0 of *word_
    };

    /// The set bits as a range: `for (std::size_t i : bits.set_bits())`.
    class SetBits {
    public:
        SetBitIterator begin() const noexcept { return {words_, words_ + word_count_}; }
        std::default_sentinel_t end() const noexcept { return {}; }

    private:
        friend class BitVector;
        SetBits(const Word* words, std::size_t word_count) noexcept : words_(words), word_count_(word_count) {}
        const Word* words_;
        std::size_t word_count_;
    };

    /// An empty vector (size 0).
    BitVector() noexcept = default;
    /// `size` bits, all equal to `value`.
    explicit BitVector(std::size_t size, bool value = false);
    /// Parses the string form: '0'/'1' characters, bit 0 first (throws grape::Error on any
    /// other character, naming its position).
    static BitVector from_string(std::string_view bits);

    /// Number of bits.
    std::size_t size() const noexcept { return size_; }
    /// size() == 0.
    bool empty() const noexcept { return size_ == 0; }
    /// The storage words; bits past size() in the last word are zero.
    std::span<const Word> words() const noexcept { return {words_.data(), words_.size()}; }
    /// Heap bytes held (capacity of the word storage).
    std::size_t memory_bytes() const noexcept { return words_.capacity() * sizeof(Word); }

    /// Bit i (i < size(); asserted in debug builds).
    bool get(std::size_t i) const noexcept {
        assert(i < size_ && "BitVector: index out of range");
        return (words_[i / word_bits] >> (i % word_bits)) & 1u;
    }
    /// Bit i, like get().
    bool operator[](std::size_t i) const noexcept { return get(i); }
    /// Bit i, checked: throws grape::Error when i >= size().
    bool at(std::size_t i) const;
    /// Sets bit i to `value` (i < size(); asserted in debug builds).
    void set(std::size_t i, bool value = true) noexcept {
        assert(i < size_ && "BitVector: index out of range");
        const Word mask = Word{1} << (i % word_bits);
        Word& w = words_[i / word_bits];
        w = value ? (w | mask) : (w & ~mask);
    }
    /// Clears bit i (i < size()).
    void reset(std::size_t i) noexcept { set(i, false); }
    /// Inverts bit i (i < size()).
    void flip(std::size_t i) noexcept {
        assert(i < size_ && "BitVector: index out of range");
        words_[i / word_bits] ^= Word{1} << (i % word_bits);
    }
    /// Sets bit i and returns its previous value (i < size()).
    bool test_and_set(std::size_t i) noexcept {
        assert(i < size_ && "BitVector: index out of range");
        const Word mask = Word{1} << (i % word_bits);
        Word& w = words_[i / word_bits];
        const bool was = (w & mask) != 0;
        w |= mask;
        return was;
    }

    /// Every bit to 1.
    void set_all() noexcept;
    /// Every bit to 0.
    void clear_all() noexcept;
    /// Inverts every bit (in place ~).
    void flip_all() noexcept;

    /// Bitwise and; throws grape::Error when sizes differ.
    BitVector& operator&=(const BitVector& other);
    /// Bitwise or; throws grape::Error when sizes differ.
    BitVector& operator|=(const BitVector& other);
    /// Bitwise exclusive or; throws grape::Error when sizes differ.
    BitVector& operator^=(const BitVector& other);
    /// Clears the bits set in `other` (this & ~other); throws grape::Error when sizes differ.
    BitVector& subtract(const BitVector& other);
    /// A copy with every bit inverted (bits past size() stay zero).
    BitVector operator~() const;
    friend BitVector operator&(BitVector a, const BitVector& b) { return a &= b; }
    friend BitVector operator|(BitVector a, const BitVector& b) { return a |= b; }
    friend BitVector operator^(BitVector a, const BitVector& b) { return a ^= b; }

    /// Number of set bits.
    std::size_t count() const noexcept;
    /// At least one bit set.
    bool any() const noexcept;
    /// No bit set (true for an empty vector).
    bool none() const noexcept { return !any(); }
    /// Every bit set (true for an empty vector).
    bool all() const noexcept;
    /// Every bit set here is set in `other`; throws grape::Error when sizes differ.
    bool is_subset_of(const BitVector& other) const;
    /// Some bit is set in both; throws grape::Error when sizes differ.
    bool intersects(const BitVector& other) const;

    /// Index of the lowest set bit, or npos.
    std::size_t find_first() const noexcept { return find_from(0); }
    /// Index of the lowest set bit above i, or npos (any i, including npos, is allowed).
    std::size_t find_next(std::size_t i) const noexcept { return i >= size_ ? npos : find_from(i + 1); }
    /// The set bits, in increasing order, as a range.
    SetBits set_bits() const noexcept { return {words_.data(), words_.size()}; }
    /// Calls f(i) for every set bit i in increasing order (the fastest walk).
    template <class F>
    void for_each_set(F&& f) const {
        const std::size_t n = words_.size();
        for (std::size_t k = 0; k < n; ++k) {
            for (Word w = words_[k]; w != 0; w &= w - 1) {
                f(k * word_bits + static_cast<std::size_t>(std::countr_zero(w)));
            }
        }
    }

    /// Changes the size; bits added at the end take `value`, bits cut off are dropped.
    void resize(std::size_t size, bool value = false);
    /// Reserves storage for `size` bits without changing size().
    void reserve(std::size_t size);

    /// Same size and same bits.
    friend bool operator==(const BitVector& a, const BitVector& b) noexcept {
        return a.size_ == b.size_ && a.words_ == b.words_;
    }
    /// A hash of the size and the bits (std::hash<BitVector> uses it).
    std::size_t hash() const noexcept;
    /// The string form: one '0'/'1' per bit, bit 0 first (reads like an array; note that
    /// std::bitset::to_string puts the highest bit first).
    std::string to_string() const;

private:
    std::size_t find_from(std::size_t i) const noexcept;
    void clear_tail() noexcept;
    void check_same_size(const BitVector& other, const char* operation) const;

    std::vector<Word> words_;
    std::size_t size_ = 0;
};

/// Writes to_string().
std::ostream& operator<<(std::ostream& out, const BitVector& bits);

/// One bit per unordered pair {i, j} of n objects: n(n−1)/2 bits, with the pair at
/// index i(2n − i − 3)/2 + j − 1 for i < j (Ericson, Real-Time Collision Detection).
/// Typical use: test each pair of colliding objects once per frame.
class PairBits {
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

private:
    std::size_t n_;
    BitVector bits_;
};

/// Which keys are down, as bits indexed by key code, with the edges since the last
/// end_frame(). Feed it from the event loop (press/release), query it from game logic,
/// and call end_frame() once per frame after the logic ran. A tap that presses and releases
/// within one frame still reports pressed_this_frame and released_this_frame.
class KeyState {
public:
    /// Codes 0 … key_count − 1 are tracked; 512 fits every SDL scancode (SDL_NUM_SCANCODES).
    static constexpr std::size_t default_key_count = 512;

    /// Tracks key codes below `key_count` (throws grape::Error when key_count is 0).
    explicit KeyState(std::size_t key_count = default_key_count);

    /// One more than the largest key code tracked.
    std::size_t key_count() const noexcept { return down_.size(); }
    /// Marks the key down (a repeat of a held key is not a new press); throws
    /// grape::Error when key >= key_count().
    void press(std::size_t key);
    /// Marks the key up; throws grape::Error when key >= key_count().
    void release(std::size_t key);
    /// Releases every key (e.g. when the window loses focus), recording the edges.
    void release_all() noexcept;
    /// The key is down now (false for codes beyond key_count()).
    bool is_down(std::size_t key) const noexcept { return key < down_.size() && down_.get(key); }
    /// The key went down since the last end_frame() (false for codes beyond key_count()).
    bool pressed_this_frame(std::size_t key) const noexcept { return key < pressed_.size() && pressed_.get(key); }
    /// The key went up since the last end_frame() (false for codes beyond key_count()).
    bool released_this_frame(std::size_t key) const noexcept {
        return key < released_.size() && released_.get(key);
    }
    /// Forgets this frame's edges; the keys held stay down.
    void end_frame() noexcept;

    /// A mask for a key combination, sized for this state; throws grape::Error for a code
    /// >= key_count().
    BitVector mask(std::initializer_list<std::size_t> keys) const;
    /// Every key of the mask is down (true for an empty mask); throws grape::Error when the
    /// mask's size is not key_count().
    bool all_down(const BitVector& mask) const { return mask.is_subset_of(down_); }
    /// Some key of the mask is down; throws grape::Error when the mask's size is not key_count().
    bool any_down(const BitVector& mask) const { return mask.intersects(down_); }
    /// The keys down now.
    const BitVector& down() const noexcept { return down_; }

private:
    void check_key(std::size_t key, const char* operation) const;

    BitVector down_;
    BitVector pressed_;
    BitVector released_;
};

}  // namespace grape

/// Hashes a BitVector by its size and bits, so it can key unordered containers.
template <>
struct std::hash<grape::BitVector> {
    std::size_t operator()(const grape::BitVector& bits) const noexcept { return bits.hash(); }
};
