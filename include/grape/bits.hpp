// grape — bits: a packed bit vector (PairBits, one bit per unordered pair, in pair_bits.hpp;
// KeyState, key state as bits, in key_state.hpp; both included here).
//
//   grape::BitVector seen(10'000'000);          // 1.25 MB instead of 10 MB of bool
//   seen.set(42);
//   for (std::size_t i : seen.set_bits()) { ... }
//
//   grape::PairBits tested(objects.size());     // n(n−1)/2 bits (Ericson, RTCD)
//   if (!tested.test_and_set(a, b)) { collide(a, b); }
//
// Whole-vector operations (count, &=, |=, ^=, ~, set_all, shifts, range counts, rank, select)
// run over 64-bit words and pick the machine's instructions at run time (popcnt, AVX2), so a
// plain -O2 build is fast. Bits past size() are always zero: they never show in count(),
// all(), ~, ==, <, hash or the saved bytes.
#pragma once

#include <grape/export_bits.hpp>

#include <bit>
#include <bitset>
#include <cassert>
#include <compare>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <iosfwd>
#include <iterator>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace grape {

/// \addtogroup bits
/// @{

/// A resizable sequence of bits packed into 64-bit words; bit i lives in word i/64 at bit i%64.
/// Element access is noexcept and checked by assert in debug builds; at() is always checked.
/// Operations combining two vectors throw grape::Error when their sizes differ.
class GRAPE_BITS_API BitVector {
public:
    using Word = std::uint64_t;  ///< a storage word: bits i·64 to i·64 + 63, bit 0 lowest
    /// Bits per storage word.
    static constexpr std::size_t word_bits = 64;
    /// Returned by find_first()/find_next() when there is no further set bit.
    static constexpr std::size_t npos = static_cast<std::size_t>(-1);

    /// Iterates the indices of the set bits in increasing order (a countr_zero walk).
    class SetBitIterator {
    public:
        using iterator_concept = std::forward_iterator_tag;  ///< a forward iterator
        using iterator_category = std::forward_iterator_tag;  ///< a forward iterator
        using value_type = std::size_t;  ///< the index of a set bit
        using difference_type = std::ptrdiff_t;  ///< as iterators need

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

    /// The set bits of a vector that outlives the range: `for (std::size_t i : bits.set_bits())`.
    class SetBits {
    public:
        SetBitIterator begin() const noexcept { return {words_, words_ + word_count_}; }  ///< the lowest set bit
        std::default_sentinel_t end() const noexcept { return {}; }  ///< past the highest set bit

    private:
        friend class BitVector;
        SetBits(const Word* words, std::size_t word_count) noexcept : words_(words), word_count_(word_count) {}
        const Word* words_;
        std::size_t word_count_;
    };
    /// The set bits of a temporary, which the range keeps alive: `for (i : (a & b).set_bits())`.
    class OwnedSetBits;

    /// Bit i of a vector as an assignable value (`bits[i] = true`), like std::bitset::reference.
    /// Valid while the vector lives and is not resized.
    class Reference {
    public:
        Reference(const Reference&) noexcept = default;  ///< refers to the same bit
        /// The bit's value.
        operator bool() const noexcept { return (*word_ & mask_) != 0; }
        /// The bit's value, inverted.
        bool operator~() const noexcept { return (*word_ & mask_) == 0; }
        /// Sets the bit to `value`.
        Reference& operator=(bool value) noexcept {
            *word_ = value ? (*word_ | mask_) : (*word_ & ~mask_);
            return *this;
        }
        /// Sets the bit to the other bit's value (not a rebinding).
        Reference& operator=(const Reference& other) noexcept { return *this = static_cast<bool>(other); }
        /// bit = bit | value.
        Reference& operator|=(bool value) noexcept {
            if (value) *word_ |= mask_;
            return *this;
        }
        /// bit = bit & value.
        Reference& operator&=(bool value) noexcept {
            if (!value) *word_ &= ~mask_;
            return *this;
        }
        /// bit = bit ^ value.
        Reference& operator^=(bool value) noexcept {
            if (value) *word_ ^= mask_;
            return *this;
        }
        /// Inverts the bit.
        Reference& flip() noexcept {
            *word_ ^= mask_;
            return *this;
        }

    private:
        friend class BitVector;
        Reference(Word* word, Word mask) noexcept : word_(word), mask_(mask) {}
        Word* word_;
        Word mask_;
    };

    /// An empty vector (size 0).
    BitVector() noexcept = default;
    BitVector(const BitVector&) = default;  ///< a copy of the bits
    BitVector& operator=(const BitVector&) = default;  ///< copies the bits and the size
    /// Takes the bits over; `other` is left empty (size 0).
    BitVector(BitVector&& other) noexcept : words_(std::move(other.words_)), size_(std::exchange(other.size_, 0)) {
        other.words_.clear();
    }
    /// Takes the bits over; `other` is left empty (size 0).
    BitVector& operator=(BitVector&& other) noexcept {
        if (this != &other) {
            words_ = std::move(other.words_);
            size_ = std::exchange(other.size_, 0);
            other.words_.clear();
        }
        return *this;
    }
    /// `size` bits, all equal to `value`.
    explicit BitVector(std::size_t size, bool value = false);
    /// Parses the string form: '0'/'1' characters, bit 0 first (throws grape::Error on any
    /// other character, naming its position).
    static BitVector from_string(std::string_view bits);
    /// The same bits as a std::vector<bool> (bit i = bools[i]).
    static BitVector from_bools(const std::vector<bool>& bools);
    /// The same bits as a std::bitset (bit i = bitset[i], so size() == N).
    template <std::size_t N>
    static BitVector from_bitset(const std::bitset<N>& bitset) {
        BitVector result(N);
        for (std::size_t i = 0; i < N; ++i)
            if (bitset[i]) result.set(i);
        return result;
    }
    /// The bits as a std::vector<bool> of size(), bit i at [i].
    std::vector<bool> to_bools() const;
    /// The bits as a std::bitset<N>, bit i at [i]; throws grape::Error when size() != N.
    template <std::size_t N>
    std::bitset<N> to_bitset() const {
        check_bitset_size(N);
        std::bitset<N> result;
        for_each_set([&result](std::size_t i) { result.set(i); });
        return result;
    }

    /// Binary form, all integers little-endian (the same bytes on every machine):
    ///   offset 0   4 bytes   "GRBV"
    ///   offset 4   uint32    format version, 1
    ///   offset 8   uint64    n, the number of bits
    ///   offset 16  uint64 × ⌈n/64⌉  the words: word k holds bits 64k … 64k+63, bit i at
    ///              position i mod 64 (value 2^(i mod 64)); bits of the last word past n are 0.
    /// 16 + 8·⌈n/64⌉ bytes in all.
    std::vector<std::byte> to_bytes() const;
    /// Reads the binary form; throws grape::Error naming the problem when the magic or version
    /// is wrong, n is too large, the length is not exactly 16 + 8·⌈n/64⌉ bytes, or a bit past
    /// n is set.
    static BitVector from_bytes(std::span<const std::byte> bytes);
    /// Writes the binary form to a binary stream (throws grape::Error when the write fails).
    void save(std::ostream& out) const;
    /// Reads one binary form from a binary stream, leaving the stream just after it; checks as
    /// from_bytes (a stream that ends early is named with the bytes read). Memory grows with
    /// the bytes actually read, so a corrupt n cannot allocate more than the stream holds.
    static BitVector load(std::istream& in);

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
    /// Bit i as an assignable reference: `bits[i] = true`, `bits[i] ^= x` (i < size();
    /// asserted in debug builds).
    Reference operator[](std::size_t i) noexcept {
        assert(i < size_ && "BitVector: index out of range");
        return {&words_[i / word_bits], Word{1} << (i % word_bits)};
    }
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

    /// Sets the bits [first, last) to `value`; throws grape::Error unless first <= last <= size().
    void set_range(std::size_t first, std::size_t last, bool value = true);
    /// Clears the bits [first, last); errors as set_range().
    void reset_range(std::size_t first, std::size_t last) { set_range(first, last, false); }
    /// Inverts the bits [first, last); errors as set_range().
    void flip_range(std::size_t first, std::size_t last);
    /// Number of set bits in [first, last); errors as set_range().
    std::size_t count_range(std::size_t first, std::size_t last) const;
    /// Number of set bits before i, in [0, i); throws grape::Error when i > size().
    std::size_t rank(std::size_t i) const;
    /// Index of the set bit with `k` set bits before it (k = 0: the first), or npos when
    /// k >= count(). rank(select(k)) == k.
    std::size_t select(std::size_t k) const noexcept;

    /// Moves every bit up by n (bit i goes to i + n, as in std::bitset and
    /// boost::dynamic_bitset): the bits shifted past size() are lost, bits [0, n) become 0.
    /// In the string form (bit 0 first) the characters move right.
    BitVector& operator<<=(std::size_t n) noexcept;
    /// Moves every bit down by n (bit i goes to i − n): bits [0, n) are lost, the top n become 0.
    BitVector& operator>>=(std::size_t n) noexcept;
    friend BitVector operator<<(BitVector a, std::size_t n) noexcept { return a <<= n; }  ///< a copy of `a` moved up by n
    friend BitVector operator>>(BitVector a, std::size_t n) noexcept { return a >>= n; }  ///< a copy of `a` moved down by n

    /// Appends a bit (amortized constant time).
    void push_back(bool value) {
        if (size_ % word_bits == 0) return push_back_in_new_word(value);
        words_.back() |= static_cast<Word>(value) << (size_ % word_bits);
        ++size_;
    }
    /// Removes the last bit; throws grape::Error on an empty vector.
    void pop_back();
    /// Inserts `count` bits equal to `value` before bit `pos` (pos == size() appends); bits
    /// from pos on move up by count. Throws grape::Error when pos > size().
    void insert(std::size_t pos, std::size_t count, bool value);
    /// Inserts one bit before bit `pos`; errors as insert(pos, count, value).
    void insert(std::size_t pos, bool value) { insert(pos, 1, value); }
    /// insert(pos, 5) would insert one bit: give the count and the value.
    template <class T>
        requires(!std::same_as<T, bool>)
    void insert(std::size_t pos, T value) = delete;
    /// Removes the bits [first, last); the bits above move down. Errors as set_range().
    void erase(std::size_t first, std::size_t last);
    /// Removes bit `pos`; throws grape::Error when pos >= size().
    void erase(std::size_t pos);

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
    friend BitVector operator&(BitVector a, const BitVector& b) { return a &= b; }  ///< bitwise and; throws grape::Error when sizes differ
    friend BitVector operator|(BitVector a, const BitVector& b) { return a |= b; }  ///< bitwise or; throws grape::Error when sizes differ
    friend BitVector operator^(BitVector a, const BitVector& b) { return a ^= b; }  ///< bitwise exclusive or; throws grape::Error when sizes differ

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
    /// Index of the highest set bit, or npos.
    std::size_t find_last() const noexcept { return find_before(size_); }
    /// Index of the highest set bit below i, or npos (any i is allowed; i > size() acts as size()).
    std::size_t find_prev(std::size_t i) const noexcept { return find_before(i < size_ ? i : size_); }
    /// The set bits, in increasing order, as a range over this vector (which must outlive it).
    SetBits set_bits() const& noexcept { return {words_.data(), words_.size()}; }
    /// The set bits of a temporary: the range takes the vector over, so
    /// `for (auto i : (a & b).set_bits())` reads live memory.
    OwnedSetBits set_bits() && noexcept;
    /// The set bits of a const temporary: the range holds a copy.
    OwnedSetBits set_bits() const&&;
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
    /// A total order consistent with ==, so vectors can key std::map and sort: the shorter
    /// vector first; at equal sizes the vector read as an unsigned number, bit i worth 2^i
    /// (the highest bit where they differ decides: the one with that bit clear comes first).
    /// Note that this is not the order of the strings of to_string().
    friend GRAPE_BITS_API std::strong_ordering operator<=>(const BitVector& a, const BitVector& b) noexcept;
    /// A hash of the size and the bits (std::hash<BitVector> uses it).
    std::size_t hash() const noexcept;
    /// The string form: one '0'/'1' per bit, bit 0 first (reads like an array; note that
    /// std::bitset::to_string puts the highest bit first).
    std::string to_string() const;

private:
    std::size_t find_from(std::size_t i) const noexcept;
    std::size_t find_before(std::size_t i) const noexcept;
    void push_back_in_new_word(bool value);
    void clear_tail() noexcept;
    void check_same_size(const BitVector& other, const char* operation) const;
    void check_range(std::size_t first, std::size_t last, const char* operation) const;
    void check_bitset_size(std::size_t n) const;

    std::vector<Word> words_;
    std::size_t size_ = 0;
};

/// The set bits of a temporary vector, which the range holds (from `std::move(bits).set_bits()`).
class BitVector::OwnedSetBits {
public:
    /// The lowest set bit.
    SetBitIterator begin() const noexcept {
        const Word* words = bits_.words_.data();
        return {words, words + bits_.words_.size()};
    }
    std::default_sentinel_t end() const noexcept { return {}; }  ///< past the highest set bit

private:
    friend class BitVector;
    explicit OwnedSetBits(BitVector&& bits) noexcept : bits_(std::move(bits)) {}
    BitVector bits_;
};

inline BitVector::OwnedSetBits BitVector::set_bits() && noexcept { return OwnedSetBits(std::move(*this)); }
inline BitVector::OwnedSetBits BitVector::set_bits() const&& { return OwnedSetBits(BitVector(*this)); }

/// Writes to_string().
GRAPE_BITS_API std::ostream& operator<<(std::ostream& out, const BitVector& bits);


/// @}

}  // namespace grape

/// Hashes a BitVector by its size and bits, so it can key unordered containers.
template <>
struct std::hash<grape::BitVector> {
    std::size_t operator()(const grape::BitVector& bits) const noexcept { return bits.hash(); }  ///< BitVector::hash()
};

// PairBits and KeyState are built on BitVector; this header keeps offering them.
#include <grape/key_state.hpp>
#include <grape/pair_bits.hpp>
