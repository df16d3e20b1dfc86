#include <grape/bits.hpp>
#include <grape/error.hpp>

#include "word_kernels.hpp"

#include <algorithm>
#include <limits>
#include <ostream>

namespace grape {

using detail::tail_mask;
using detail::words_for;

BitVector::BitVector(std::size_t size, bool value)
    : words_(words_for(size), value ? ~Word{0} : Word{0}), size_(size) {
    clear_tail();
}

BitVector BitVector::from_string(std::string_view bits) {
    BitVector result(bits.size());
    for (std::size_t i = 0; i < bits.size(); ++i) {
        const char c = bits[i];
        if (c == '1') {
            result.set(i);
        } else if (c != '0') {
            throw Error("BitVector::from_string: bits[" + std::to_string(i) + "] is '" + std::string(1, c) +
                        "', expected '0' or '1'");
        }
    }
    return result;
}

bool BitVector::at(std::size_t i) const {
    if (i >= size_) {
        throw Error("BitVector::at: index " + std::to_string(i) + " is out of range (size " +
                    std::to_string(size_) + ")");
    }
    return get(i);
}

void BitVector::clear_tail() noexcept {
    if (!words_.empty()) words_.back() &= tail_mask(size_);
}

void BitVector::check_range(std::size_t first, std::size_t last, const char* operation) const {
    if (first > last || last > size_) {
        throw Error(std::string("BitVector::") + operation + ": range [" + std::to_string(first) + ", " +
                    std::to_string(last) + ") is not within [0, size " + std::to_string(size_) + ")" +
                    (first > last ? " (first > last)" : ""));
    }
}

void BitVector::check_same_size(const BitVector& other, const char* operation) const {
    if (other.size_ != size_) {
        throw Error(std::string("BitVector::") + operation + ": other has size " + std::to_string(other.size_) +
                    ", expected the same size as this vector (" + std::to_string(size_) + ")");
    }
}

void BitVector::set_all() noexcept {
    std::fill(words_.begin(), words_.end(), ~Word{0});
    clear_tail();
}

void BitVector::clear_all() noexcept { std::fill(words_.begin(), words_.end(), Word{0}); }

void BitVector::flip_all() noexcept {
    detail::word_kernels().flip(words_.data(), words_.size());
    clear_tail();
}

BitVector& BitVector::operator&=(const BitVector& other) {
    check_same_size(other, "operator&=");
    detail::word_kernels().and_with(words_.data(), other.words_.data(), words_.size());
    return *this;
}

BitVector& BitVector::operator|=(const BitVector& other) {
    check_same_size(other, "operator|=");
    detail::word_kernels().or_with(words_.data(), other.words_.data(), words_.size());
    return *this;
}

BitVector& BitVector::operator^=(const BitVector& other) {
    check_same_size(other, "operator^=");
    detail::word_kernels().xor_with(words_.data(), other.words_.data(), words_.size());
    return *this;
}

BitVector& BitVector::subtract(const BitVector& other) {
    check_same_size(other, "subtract");
    detail::word_kernels().and_not(words_.data(), other.words_.data(), words_.size());
    return *this;
}

BitVector BitVector::operator~() const {
    BitVector result(*this);
    result.flip_all();
    return result;
}

std::size_t BitVector::count() const noexcept { return detail::word_kernels().count(words_.data(), words_.size()); }

bool BitVector::any() const noexcept {
    return std::any_of(words_.begin(), words_.end(), [](Word w) { return w != 0; });
}

bool BitVector::all() const noexcept {
    if (words_.empty()) return true;
    const std::size_t full = words_.size() - 1;
    for (std::size_t k = 0; k < full; ++k) {
        if (words_[k] != ~Word{0}) return false;
    }
    return words_.back() == tail_mask(size_);
}

bool BitVector::is_subset_of(const BitVector& other) const {
    check_same_size(other, "is_subset_of");
    for (std::size_t k = 0; k < words_.size(); ++k) {
        if ((words_[k] & ~other.words_[k]) != 0) return false;
    }
    return true;
}

bool BitVector::intersects(const BitVector& other) const {
    check_same_size(other, "intersects");
    for (std::size_t k = 0; k < words_.size(); ++k) {
        if ((words_[k] & other.words_[k]) != 0) return true;
    }
    return false;
}

std::size_t BitVector::find_from(std::size_t i) const noexcept {
    if (i >= size_) return npos;
    std::size_t k = i / word_bits;
    Word w = words_[k] & (~Word{0} << (i % word_bits));
    while (w == 0) {
        if (++k == words_.size()) return npos;
        w = words_[k];
    }
    return k * word_bits + static_cast<std::size_t>(std::countr_zero(w));
}

void BitVector::resize(std::size_t size, bool value) {
    if (size > std::numeric_limits<std::size_t>::max() - word_bits) {
        throw Error("BitVector::resize: size " + std::to_string(size) + " is too large");
    }
    if (size > size_ && value && !words_.empty()) {
        words_.back() |= ~tail_mask(size_);  // the old last word's unused bits become new bits
    }
    words_.resize(words_for(size), value ? ~Word{0} : Word{0});
    size_ = size;
    clear_tail();
}

void BitVector::reserve(std::size_t size) {
    if (size > std::numeric_limits<std::size_t>::max() - word_bits) {
        throw Error("BitVector::reserve: size " + std::to_string(size) + " is too large");
    }
    words_.reserve(words_for(size));
}

std::strong_ordering operator<=>(const BitVector& a, const BitVector& b) noexcept {
    if (a.size_ != b.size_) return a.size_ <=> b.size_;
    const BitVector::Word* x = a.words_.data();
    const BitVector::Word* y = b.words_.data();
    for (std::size_t k = a.words_.size(); k > 0;) {
        // Four words per test while they are equal: equal keys are compared in full.
        if (k >= 4 && ((x[k - 1] ^ y[k - 1]) | (x[k - 2] ^ y[k - 2]) | (x[k - 3] ^ y[k - 3]) | (x[k - 4] ^ y[k - 4])) == 0) {
            k -= 4;
            continue;
        }
        --k;
        if (x[k] != y[k]) return x[k] <=> y[k];
    }
    return std::strong_ordering::equal;
}

std::size_t BitVector::hash() const noexcept {
    // Each word goes through the splitmix64 finalizer together with the running state, so a
    // change in any bit reaches every bit of the result (a plain multiply only carries
    // upwards and lets single-bit changes in different words collide).
    auto mix = [](std::uint64_t z) {
        z ^= z >> 30;
        z *= 0xBF58476D1CE4E5B9ull;
        z ^= z >> 27;
        z *= 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    };
    std::uint64_t h = mix(0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(size_));
    for (const Word w : words_) h = mix(h + 0x9E3779B97F4A7C15ull + w);
    return static_cast<std::size_t>(h);
}

std::string BitVector::to_string() const {
    std::string s(size_, '0');
    for_each_set([&s](std::size_t i) { s[i] = '1'; });
    return s;
}

std::ostream& operator<<(std::ostream& out, const BitVector& bits) { return out << bits.to_string(); }

}  // namespace grape
