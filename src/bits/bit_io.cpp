// BitVector conversions: std::vector<bool>, std::bitset (size check), and the binary form
// documented in bits.hpp, written little-endian on every machine.
#include <grape/bits.hpp>
#include <grape/error.hpp>

#include "word_kernels.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <istream>
#include <limits>
#include <ostream>
#include <string>

namespace grape {
namespace {

using Word = BitVector::Word;

constexpr std::size_t header_bytes = 16;
constexpr unsigned char magic[4] = {'G', 'R', 'B', 'V'};
constexpr std::uint32_t format_version = 1;
// resize()'s bound (bit_edit.cpp): a stored size above it could not be read back.
constexpr std::uint64_t max_read_bits = std::numeric_limits<std::size_t>::max() - BitVector::word_bits;

void put_le(std::byte* p, std::uint64_t v, std::size_t bytes) noexcept {
    for (std::size_t b = 0; b < bytes; ++b) p[b] = static_cast<std::byte>((v >> (8 * b)) & 0xFF);
}
std::uint64_t get_le(const std::byte* p, std::size_t bytes) noexcept {
    std::uint64_t v = 0;
    for (std::size_t b = 0; b < bytes; ++b) v |= static_cast<std::uint64_t>(p[b]) << (8 * b);
    return v;
}

// Words to little-endian bytes and back (a copy on little-endian machines).
void words_to_bytes(const Word* w, std::size_t n, std::byte* out) noexcept {
    if constexpr (std::endian::native == std::endian::little) {
        if (n != 0) std::memcpy(out, w, n * sizeof(Word));
    } else {
        for (std::size_t k = 0; k < n; ++k) put_le(out + 8 * k, w[k], 8);
    }
}
void bytes_to_words(const std::byte* in, std::size_t n, Word* w) noexcept {
    if constexpr (std::endian::native == std::endian::little) {
        if (n != 0) std::memcpy(w, in, n * sizeof(Word));
    } else {
        for (std::size_t k = 0; k < n; ++k) w[k] = get_le(in + 8 * k, 8);
    }
}

std::array<std::byte, header_bytes> header_for(std::size_t size) noexcept {
    std::array<std::byte, header_bytes> h{};
    for (std::size_t b = 0; b < 4; ++b) h[b] = static_cast<std::byte>(magic[b]);
    put_le(h.data() + 4, format_version, 4);
    put_le(h.data() + 8, size, 8);
    return h;
}

// The bit count of a checked header.
std::size_t parse_header(const std::byte* h, const char* operation) {
    const std::string where = std::string("BitVector::") + operation + ": ";
    for (std::size_t b = 0; b < 4; ++b) {
        if (h[b] != static_cast<std::byte>(magic[b])) {
            throw Error(where + "not a bit vector (bytes 0-3 are not \"GRBV\")");
        }
    }
    const std::uint64_t version = get_le(h + 4, 4);
    if (version != format_version) {
        throw Error(where + "format version " + std::to_string(version) + " is not supported (expected 1)");
    }
    const std::uint64_t n = get_le(h + 8, 8);
    if (n > max_read_bits) throw Error(where + "size " + std::to_string(n) + " bits is too large");
    return static_cast<std::size_t>(n);
}

void check_tail(const std::vector<Word>& words, std::size_t size, const char* operation) {
    if (!words.empty() && (words.back() & ~detail::tail_mask(size)) != 0) {
        throw Error(std::string("BitVector::") + operation + ": bits past the size (" + std::to_string(size) +
                    ") are set in the last word");
    }
}

}  // namespace

BitVector BitVector::from_bools(const std::vector<bool>& bools) {
    BitVector result(bools.size());
    for (std::size_t i = 0; i < bools.size(); ++i)
        if (bools[i]) result.set(i);
    return result;
}

std::vector<bool> BitVector::to_bools() const {
    std::vector<bool> result(size_);
    for_each_set([&result](std::size_t i) { result[i] = true; });
    return result;
}

void BitVector::check_bitset_size(std::size_t n) const {
    if (n != size_) {
        throw Error("BitVector::to_bitset: std::bitset<" + std::to_string(n) + "> cannot hold " +
                    std::to_string(size_) + " bits (the sizes must be equal)");
    }
}

std::vector<std::byte> BitVector::to_bytes() const {
    std::vector<std::byte> out(header_bytes + words_.size() * sizeof(Word));
    const auto h = header_for(size_);
    std::copy(h.begin(), h.end(), out.begin());
    words_to_bytes(words_.data(), words_.size(), out.data() + header_bytes);
    return out;
}

BitVector BitVector::from_bytes(std::span<const std::byte> bytes) {
    if (bytes.size() < header_bytes) {
        throw Error("BitVector::from_bytes: " + std::to_string(bytes.size()) +
                    " bytes, shorter than the 16-byte header");
    }
    const std::size_t n = parse_header(bytes.data(), "from_bytes");
    const std::size_t words = detail::words_for(n);
    const std::size_t expected = header_bytes + words * sizeof(Word);
    if (bytes.size() != expected) {
        throw Error("BitVector::from_bytes: " + std::to_string(bytes.size()) + " bytes, expected " +
                    std::to_string(expected) + " for " + std::to_string(n) + " bits");
    }
    BitVector result;
    result.words_.resize(words);
    bytes_to_words(bytes.data() + header_bytes, words, result.words_.data());
    check_tail(result.words_, n, "from_bytes");
    result.size_ = n;
    return result;
}

void BitVector::save(std::ostream& out) const {
    const auto h = header_for(size_);
    out.write(reinterpret_cast<const char*>(h.data()), static_cast<std::streamsize>(h.size()));
    // In chunks, so a big-endian machine needs only a small buffer.
    constexpr std::size_t chunk = 4096;
    std::array<std::byte, chunk * sizeof(Word)> buffer;
    for (std::size_t k = 0; k < words_.size() && out; k += chunk) {
        const std::size_t m = std::min(chunk, words_.size() - k);
        words_to_bytes(words_.data() + k, m, buffer.data());
        out.write(reinterpret_cast<const char*>(buffer.data()), static_cast<std::streamsize>(m * sizeof(Word)));
    }
    if (!out) throw Error("BitVector::save: the stream failed while writing");
}

BitVector BitVector::load(std::istream& in) {
    std::array<std::byte, header_bytes> h;
    in.read(reinterpret_cast<char*>(h.data()), static_cast<std::streamsize>(h.size()));
    if (static_cast<std::size_t>(in.gcount()) != header_bytes) {
        throw Error("BitVector::load: the stream ends after " + std::to_string(in.gcount()) +
                    " bytes, inside the 16-byte header");
    }
    const std::size_t n = parse_header(h.data(), "load");
    const std::size_t words = detail::words_for(n);
    BitVector result;
    // Grow with what the stream actually holds: a corrupt n fails at the stream's end rather
    // than allocating n bits up front.
    constexpr std::size_t chunk = 1 << 16;
    std::array<std::byte, 4096 * sizeof(Word)> buffer;
    for (std::size_t k = 0; k < words;) {
        const std::size_t m = std::min<std::size_t>(4096, words - k);
        in.read(reinterpret_cast<char*>(buffer.data()), static_cast<std::streamsize>(m * sizeof(Word)));
        const std::size_t got = static_cast<std::size_t>(in.gcount());
        if (got != m * sizeof(Word)) {
            throw Error("BitVector::load: the stream ends after " + std::to_string(header_bytes + k * sizeof(Word) + got) +
                        " bytes, expected " + std::to_string(header_bytes + words * sizeof(Word)) + " for " +
                        std::to_string(n) + " bits");
        }
        if (result.words_.capacity() < k + m) result.words_.reserve(std::min(words, std::max(k + m, 2 * k + chunk)));
        result.words_.resize(k + m);
        bytes_to_words(buffer.data(), m, result.words_.data() + k);
        k += m;
    }
    check_tail(result.words_, n, "load");
    result.size_ = n;
    return result;
}

}  // namespace grape
