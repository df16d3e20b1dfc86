#include <grape/error.hpp>
#include <grape/sparse_bits.hpp>

#include "word_kernels.hpp"

#include <algorithm>
#include <iterator>
#include <string>

namespace grape {
namespace {

constexpr std::size_t block_words = SparseBitVector::block_bits / 64;

}  // namespace

SparseBitVector::SparseBitVector(std::size_t size)
    : blocks_(size / block_bits + (size % block_bits != 0 ? 1 : 0)), size_(size) {}

SparseBitVector SparseBitVector::from_bits(const BitVector& bits) {
    SparseBitVector result(bits.size());
    const auto words = bits.words();
    for (std::size_t b = 0; b < result.blocks_.size(); ++b) {
        const std::size_t first = b * block_words, n = std::min(block_words, words.size() - first);
        Block& block = result.blocks_[b];
        block.count = static_cast<std::uint32_t>(detail::word_kernels().count(words.data() + first, n));
        if (block.count > array_limit) {
            block.bitmap.assign(block_words, 0);
            std::copy_n(words.data() + first, n, block.bitmap.begin());
        } else {
            block.array.reserve(block.count);
            for (std::size_t k = 0; k < n; ++k)
                for (Word w = words[first + k]; w != 0; w &= w - 1)
                    block.array.push_back(static_cast<std::uint16_t>(k * 64 + static_cast<std::size_t>(std::countr_zero(w))));
        }
    }
    return result;
}

BitVector SparseBitVector::to_bits() const {
    BitVector bits(size_);
    for_each_set([&bits](std::size_t i) { bits.set(i); });
    return bits;
}

std::size_t SparseBitVector::count() const noexcept {
    std::size_t c = 0;
    for (const Block& block : blocks_) c += count_of(block);
    return c;
}

std::size_t SparseBitVector::count_of(const Block& block) noexcept {
    if (block.count != uncounted) return block.count;
    return detail::word_kernels().count(block.bitmap.data(), block_words);
}

bool SparseBitVector::any() const noexcept {
    for (const Block& block : blocks_)
        if (count_of(block) != 0) return true;
    return false;
}

std::size_t SparseBitVector::memory_bytes() const noexcept {
    std::size_t bytes = blocks_.capacity() * sizeof(Block);
    for (const Block& block : blocks_)
        bytes += block.array.capacity() * sizeof(std::uint16_t) + block.bitmap.capacity() * sizeof(Word);
    return bytes;
}

std::size_t SparseBitVector::bitmap_blocks() const noexcept {
    return static_cast<std::size_t>(
        std::count_if(blocks_.begin(), blocks_.end(), [](const Block& block) { return !block.bitmap.empty(); }));
}

bool SparseBitVector::get(std::size_t i) const noexcept {
    assert(i < size_ && "SparseBitVector: index out of range");
    const Block& block = blocks_[i / block_bits];
    const std::size_t p = i % block_bits;
    if (!block.bitmap.empty()) return (block.bitmap[p / 64] >> (p % 64)) & 1u;
    return std::binary_search(block.array.begin(), block.array.end(), static_cast<std::uint16_t>(p));
}

void SparseBitVector::to_bitmap(Block& block) {
    Bitmap bitmap(block_words, 0);
    for (const std::uint16_t p : block.array) bitmap[p / 64] |= Word{1} << (p % 64);
    block.bitmap = std::move(bitmap);
    block.array = std::vector<std::uint16_t>();  // frees the array (`= {}` would keep its capacity)
}

void SparseBitVector::fit(Block& block) {
    block.count = static_cast<std::uint32_t>(count_of(block));
    if (block.bitmap.empty()) {
        if (block.count > array_limit) to_bitmap(block);
        if (block.count == 0) block.array = std::vector<std::uint16_t>();
        return;
    }
    if (block.count > array_limit) return;
    std::vector<std::uint16_t> array;
    array.reserve(block.count);
    for (std::size_t k = 0; k < block_words; ++k)
        for (Word w = block.bitmap[k]; w != 0; w &= w - 1)
            array.push_back(static_cast<std::uint16_t>(k * 64 + static_cast<std::size_t>(std::countr_zero(w))));
    block.array = std::move(array);
    block.bitmap = Bitmap();
}

void SparseBitVector::set(std::size_t i, bool value) {
    assert(i < size_ && "SparseBitVector: index out of range");
    Block& block = blocks_[i / block_bits];
    const std::size_t p = i % block_bits;
    if (!block.bitmap.empty()) {
        Word& w = block.bitmap[p / 64];
        const Word mask = Word{1} << (p % 64);
        if (((w & mask) != 0) == value) return;
        w ^= mask;
        if (block.count == uncounted) return;  // counted when next needed
        if (value) {
            ++block.count;
        } else {
            --block.count;
            fit(block);
        }
        return;
    }
    const auto offset = static_cast<std::uint16_t>(p);
    const auto it = std::lower_bound(block.array.begin(), block.array.end(), offset);
    const bool present = it != block.array.end() && *it == offset;
    if (present == value) return;
    if (!value) {
        block.array.erase(it);
        --block.count;
        fit(block);
        return;
    }
    if (block.count == array_limit) {
        to_bitmap(block);
        block.bitmap[p / 64] |= Word{1} << (p % 64);
    } else {
        block.array.insert(it, offset);
    }
    ++block.count;
}

bool SparseBitVector::test_and_set(std::size_t i) {
    const bool was = get(i);
    if (!was) set(i);
    return was;
}

void SparseBitVector::clear_all() noexcept {
    for (Block& block : blocks_) block = Block{};
}

void SparseBitVector::shrink_to_fit() {
    for (Block& block : blocks_) {
        fit(block);  // blocks `&=` left as uncounted bitmaps get their count and form back
        block.array.shrink_to_fit();
    }
    blocks_.shrink_to_fit();
}

void SparseBitVector::check_same_size(const SparseBitVector& other, const char* operation) const {
    if (other.size_ != size_) {
        throw Error(std::string("SparseBitVector::") + operation + ": other has size " + std::to_string(other.size_) +
                    ", expected the same size as this vector (" + std::to_string(size_) + ")");
    }
}

SparseBitVector& SparseBitVector::operator&=(const SparseBitVector& other) {
    if (this == &other) return *this;  // x & x is x
    check_same_size(other, "operator&=");
    const auto& kernels = detail::word_kernels();
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        Block& x = blocks_[b];
        const Block& y = other.blocks_[b];
        if (x.count == 0 || y.count == 0) {  // an empty side: an empty block
            x = Block{};
            continue;
        }
        const bool xb = !x.bitmap.empty(), yb = !y.bitmap.empty();
        if (xb && yb) {
            // A plain and at memory speed; counting in the same pass (a nibble-table popcount
            // per 32 bytes) made the loop compute-bound at 0.75× memcpy. The count, and the
            // array form if the result is sparse, wait until they are needed.
            kernels.and_with(x.bitmap.data(), y.bitmap.data(), block_words);
            x.count = uncounted;
            continue;
        } else if (xb) {  // the result is the array's offsets that the bitmap has
            std::vector<std::uint16_t> array;
            array.reserve(y.array.size());
            for (const std::uint16_t p : y.array)
                if ((x.bitmap[p / 64] >> (p % 64)) & 1u) array.push_back(p);
            x.bitmap = Bitmap();
            x.array = std::move(array);
            x.count = static_cast<std::uint32_t>(x.array.size());
        } else if (yb) {
            std::erase_if(x.array, [&y](std::uint16_t p) { return ((y.bitmap[p / 64] >> (p % 64)) & 1u) == 0; });
            x.count = static_cast<std::uint32_t>(x.array.size());
        } else {
            // In place: the write position never passes the read position in x.
            std::size_t out = 0, j = 0;
            for (std::size_t k = 0; k < x.array.size() && j < y.array.size(); ++k) {
                while (j < y.array.size() && y.array[j] < x.array[k]) ++j;
                if (j < y.array.size() && y.array[j] == x.array[k]) x.array[out++] = x.array[k];
            }
            x.array.resize(out);
            x.count = static_cast<std::uint32_t>(x.array.size());
        }
        fit(x);
    }
    return *this;
}

SparseBitVector& SparseBitVector::operator|=(const SparseBitVector& other) {
    check_same_size(other, "operator|=");
    if (this == &other) return *this;
    const auto& kernels = detail::word_kernels();
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        Block& x = blocks_[b];
        const Block& y = other.blocks_[b];
        if (y.count == 0) continue;
        if (x.count == 0) {
            x = y;
            continue;
        }
        if (!y.bitmap.empty()) {
            if (x.bitmap.empty()) {
                Bitmap bitmap = y.bitmap;
                for (const std::uint16_t p : x.array) bitmap[p / 64] |= Word{1} << (p % 64);
                x.bitmap = std::move(bitmap);
                x.array = std::vector<std::uint16_t>();
            } else {
                kernels.or_with(x.bitmap.data(), y.bitmap.data(), block_words);
            }
            x.count = static_cast<std::uint32_t>(kernels.count(x.bitmap.data(), block_words));
        } else if (!x.bitmap.empty()) {
            for (const std::uint16_t p : y.array) x.bitmap[p / 64] |= Word{1} << (p % 64);
            x.count = static_cast<std::uint32_t>(kernels.count(x.bitmap.data(), block_words));
        } else {
            std::vector<std::uint16_t> merged;
            merged.reserve(x.array.size() + y.array.size());
            std::set_union(x.array.begin(), x.array.end(), y.array.begin(), y.array.end(), std::back_inserter(merged));
            x.array = std::move(merged);
            x.count = static_cast<std::uint32_t>(x.array.size());
            fit(x);
        }
    }
    return *this;
}

bool SparseBitVector::same_bits(const Block& x, const Block& y) noexcept {
    const bool xb = !x.bitmap.empty(), yb = !y.bitmap.empty();
    if (xb && yb) return x.bitmap == y.bitmap;
    if (!xb && !yb) return x.array == y.array;
    // One bitmap (left uncounted by `&=`), one array: the same bits when the bitmap holds
    // every offset of the array and no other bit.
    const Block& bitmap = xb ? x : y;
    const Block& array = xb ? y : x;
    if (count_of(bitmap) != array.array.size()) return false;
    return std::all_of(array.array.begin(), array.array.end(),
                       [&bitmap](std::uint16_t p) { return ((bitmap.bitmap[p / 64] >> (p % 64)) & 1u) != 0; });
}

bool operator==(const SparseBitVector& a, const SparseBitVector& b) noexcept {
    if (a.size_ != b.size_) return false;
    for (std::size_t k = 0; k < a.blocks_.size(); ++k)
        if (!SparseBitVector::same_bits(a.blocks_[k], b.blocks_[k])) return false;
    return true;
}

}  // namespace grape
