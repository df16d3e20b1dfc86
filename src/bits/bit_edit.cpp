// BitVector edits that move bits: shifts, push/pop at the end, insert and erase. A move of
// the bits above a position is one in-place word shift of the words from there on.
#include <grape/bits.hpp>
#include <grape/error.hpp>

#include "word_kernels.hpp"

#include <limits>
#include <string>

namespace grape {
namespace {

// The largest size resize() accepts: the word count must not overflow.
constexpr std::size_t max_bits = std::numeric_limits<std::size_t>::max() - BitVector::word_bits;

}  // namespace

BitVector& BitVector::operator<<=(std::size_t n) noexcept {
    if (n >= size_) {
        clear_all();
        return *this;
    }
    detail::word_kernels().shift_up(words_.data(), words_.size(), n);
    clear_tail();
    return *this;
}

BitVector& BitVector::operator>>=(std::size_t n) noexcept {
    if (n >= size_) {
        clear_all();
        return *this;
    }
    // The bits past size() are zero, so zeros come in at the top.
    detail::word_kernels().shift_down(words_.data(), words_.size(), n);
    return *this;
}

// push_back() when the last word is full (or there is none).
void BitVector::push_back_in_new_word(bool value) {
    if (size_ == max_bits) throw Error("BitVector::push_back: size " + std::to_string(size_) + " is the largest");
    words_.push_back(static_cast<Word>(value));
    ++size_;
}

void BitVector::pop_back() {
    if (size_ == 0) throw Error("BitVector::pop_back: the vector is empty");
    --size_;
    if (size_ % word_bits == 0) {
        words_.pop_back();
    } else {
        clear_tail();
    }
}

void BitVector::insert(std::size_t pos, std::size_t count, bool value) {
    if (pos > size_) {
        throw Error("BitVector::insert: position " + std::to_string(pos) + " is past the end (size " +
                    std::to_string(size_) + ")");
    }
    if (count > max_bits - size_) {
        throw Error("BitVector::insert: count " + std::to_string(count) + " makes the size too large");
    }
    if (count == 0) return;
    resize(size_ + count);
    // Shift the words from pos's word on, keeping the bits below pos where they are: they are
    // cleared first, so the shift leaves zeros in [word start, pos + count), then put back.
    const std::size_t k0 = pos / word_bits;
    const Word below = detail::low_bits(pos % word_bits);
    Word* w = words_.data() + k0;
    const Word kept = w[0] & below;
    w[0] &= ~below;
    detail::word_kernels().shift_up(w, words_.size() - k0, count);
    w[0] |= kept;
    if (value) set_range(pos, pos + count);
}

void BitVector::erase(std::size_t first, std::size_t last) {
    check_range(first, last, "erase");
    if (first == last) return;
    // After the shift, bit p >= first holds the old bit p + count (>= last); the bits of the
    // first word below `first` are put back.
    const std::size_t k0 = first / word_bits;
    const Word below = detail::low_bits(first % word_bits);
    Word* w = words_.data() + k0;
    const Word kept = w[0] & below;
    detail::word_kernels().shift_down(w, words_.size() - k0, last - first);
    w[0] = (w[0] & ~below) | kept;
    resize(size_ - (last - first));
}

void BitVector::erase(std::size_t pos) {
    if (pos >= size_) {
        throw Error("BitVector::erase: index " + std::to_string(pos) + " is out of range (size " +
                    std::to_string(size_) + ")");
    }
    erase(pos, pos + 1);
}

}  // namespace grape
