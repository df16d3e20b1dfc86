// The word loops are written once as templates over a vector type (GCC/Clang vector
// extensions: 2 words in an SSE2 register for the baseline and popcnt versions, 4 words in an
// AVX2 register for the avx2 version) and instantiated inside functions carrying target
// attributes. -O2's very-cheap vectorizer will not vectorize an unknown-length loop by itself
// (it would need an epilogue and an aliasing check), hence the explicit vectors.
#include "word_kernels.hpp"

#include <bit>
#include <cstring>

#include "internal/compiler.hpp"

namespace grape::detail {
namespace {


enum class Op { and_, or_, xor_, and_not };

// x = x op y. By reference, so no vector is ever passed by value (see below).
template <Op op, class T>
GRAPE_ALWAYS_INLINE void apply(T& x, const T& y) noexcept {
    if constexpr (op == Op::and_) x &= y;
    if constexpr (op == Op::or_) x |= y;
    if constexpr (op == Op::xor_) x ^= y;
    if constexpr (op == Op::and_not) x &= ~y;
}

#if GRAPE_VECTOR_EXTENSIONS
// Vectors never cross a function boundary by value: passing a 32-byte vector to a function
// compiled without AVX uses a different ABI, which at -O0 (no inlining) corrupts the operands.
using Word2 = Word __attribute__((vector_size(16)));  // one SSE2 register
using Word4 = Word __attribute__((vector_size(32)));  // one AVX2 register

// Two vectors per iteration so the loads of the next pair overlap the stores of this one.
template <class V, Op op>
GRAPE_ALWAYS_INLINE void binary_loop(Word* a, const Word* b, std::size_t n) noexcept {
    constexpr std::size_t lanes = sizeof(V) / sizeof(Word);
    std::size_t i = 0;
    for (; i + 2 * lanes <= n; i += 2 * lanes) {
        V a0, a1, b0, b1;
        std::memcpy(&a0, a + i, sizeof(V));  // unaligned loads: one vector move each
        std::memcpy(&a1, a + i + lanes, sizeof(V));
        std::memcpy(&b0, b + i, sizeof(V));
        std::memcpy(&b1, b + i + lanes, sizeof(V));
        apply<op>(a0, b0);
        apply<op>(a1, b1);
        std::memcpy(a + i, &a0, sizeof(V));
        std::memcpy(a + i + lanes, &a1, sizeof(V));
    }
    for (; i < n; ++i) apply<op>(a[i], b[i]);
}

template <class V>
GRAPE_ALWAYS_INLINE void flip_loop(Word* a, std::size_t n) noexcept {
    constexpr std::size_t lanes = sizeof(V) / sizeof(Word);
    std::size_t i = 0;
    for (; i + lanes <= n; i += lanes) {
        V x;
        std::memcpy(&x, a + i, sizeof(V));
        x = ~x;
        std::memcpy(a + i, &x, sizeof(V));
    }
    for (; i < n; ++i) a[i] = ~a[i];
}

// Shifts by s = 64·ws + bs with 0 < bs < 64 (bs == 0 is a memmove): word k of the result
// takes the high bits of source word k − ws − 1 and the low bits of word k − ws. Towards the
// high end the words are written from the top down, so every load reads a word not yet
// written; each step loads all of its vectors before storing any.
template <class V>
GRAPE_ALWAYS_INLINE void shift_up_loop(Word* w, std::size_t n, std::size_t ws, unsigned bs) noexcept {
    constexpr std::size_t lanes = sizeof(V) / sizeof(Word);
    const unsigned back = 64 - bs;
    std::size_t top = n;  // words [top, n) are done
    while (top >= ws + 1 + 2 * lanes) {
        const std::size_t d0 = top - lanes, d1 = top - 2 * lanes;
        V h0, l0, h1, l1;
        std::memcpy(&h0, w + d0 - ws, sizeof(V));
        std::memcpy(&l0, w + d0 - ws - 1, sizeof(V));
        std::memcpy(&h1, w + d1 - ws, sizeof(V));
        std::memcpy(&l1, w + d1 - ws - 1, sizeof(V));
        h0 = (h0 << bs) | (l0 >> back);
        h1 = (h1 << bs) | (l1 >> back);
        std::memcpy(w + d0, &h0, sizeof(V));
        std::memcpy(w + d1, &h1, sizeof(V));
        top = d1;
    }
    for (std::size_t k = top; k-- > ws + 1;) w[k] = (w[k - ws] << bs) | (w[k - ws - 1] >> back);
    w[ws] = w[0] << bs;
}

template <class V>
GRAPE_ALWAYS_INLINE void shift_down_loop(Word* w, std::size_t n, std::size_t ws, unsigned bs) noexcept {
    constexpr std::size_t lanes = sizeof(V) / sizeof(Word);
    const unsigned back = 64 - bs;
    const std::size_t last = n - ws - 1;  // the top word of the result with source bits
    std::size_t k = 0;
    for (; k + 2 * lanes <= last; k += 2 * lanes) {
        V l0, h0, l1, h1;
        std::memcpy(&l0, w + k + ws, sizeof(V));
        std::memcpy(&h0, w + k + ws + 1, sizeof(V));
        std::memcpy(&l1, w + k + lanes + ws, sizeof(V));
        std::memcpy(&h1, w + k + lanes + ws + 1, sizeof(V));
        l0 = (l0 >> bs) | (h0 << back);
        l1 = (l1 >> bs) | (h1 << back);
        std::memcpy(w + k, &l0, sizeof(V));
        std::memcpy(w + k + lanes, &l1, sizeof(V));
    }
    for (; k < last; ++k) w[k] = (w[k + ws] >> bs) | (w[k + ws + 1] << back);
    w[last] = w[n - 1] >> bs;
}
#else
using Word2 = Word;  // no vector extensions: plain word loops
using Word4 = Word;

template <class V, Op op>
inline void binary_loop(Word* a, const Word* b, std::size_t n) noexcept {
    for (std::size_t i = 0; i < n; ++i) apply<op>(a[i], b[i]);
}
template <class V>
inline void flip_loop(Word* a, std::size_t n) noexcept {
    for (std::size_t i = 0; i < n; ++i) a[i] = ~a[i];
}
template <class V>
inline void shift_up_loop(Word* w, std::size_t n, std::size_t ws, unsigned bs) noexcept {
    for (std::size_t k = n; k-- > ws + 1;) w[k] = (w[k - ws] << bs) | (w[k - ws - 1] >> (64 - bs));
    w[ws] = w[0] << bs;
}
template <class V>
inline void shift_down_loop(Word* w, std::size_t n, std::size_t ws, unsigned bs) noexcept {
    const std::size_t last = n - ws - 1;
    for (std::size_t k = 0; k < last; ++k) w[k] = (w[k + ws] >> bs) | (w[k + ws + 1] << (64 - bs));
    w[last] = w[n - 1] >> bs;
}
#endif

// The whole-word part of a shift is a memmove, the rest a vector loop; `up` moves bit i to
// i + s (towards the end of the array), else to i − s.
template <class V, bool up>
GRAPE_ALWAYS_INLINE void shift_words(Word* w, std::size_t n, std::size_t s) noexcept {
    if (n == 0) return;  // (w may be null: no memset on it)
    const std::size_t ws = s / 64;
    const unsigned bs = static_cast<unsigned>(s % 64);
    if (ws >= n) {
        std::memset(w, 0, n * sizeof(Word));
        return;
    }
    if (bs == 0) std::memmove(up ? w + ws : w, up ? w : w + ws, (n - ws) * sizeof(Word));
    else if constexpr (up) shift_up_loop<V>(w, n, ws, bs);
    else shift_down_loop<V>(w, n, ws, bs);
    std::memset(up ? w : w + (n - ws), 0, ws * sizeof(Word));  // the words shifted in
}
template <class V>
GRAPE_ALWAYS_INLINE void shift_up_words(Word* w, std::size_t n, std::size_t s) noexcept { shift_words<V, true>(w, n, s); }
template <class V>
GRAPE_ALWAYS_INLINE void shift_down_words(Word* w, std::size_t n, std::size_t s) noexcept { shift_words<V, false>(w, n, s); }

// Four accumulators keep the popcnt units busy (one chain would be latency bound).
GRAPE_ALWAYS_INLINE std::size_t count_loop(const Word* w, std::size_t n) noexcept {
    std::size_t c0 = 0, c1 = 0, c2 = 0, c3 = 0, i = 0;
    for (; i + 4 <= n; i += 4) {
        c0 += static_cast<std::size_t>(std::popcount(w[i]));
        c1 += static_cast<std::size_t>(std::popcount(w[i + 1]));
        c2 += static_cast<std::size_t>(std::popcount(w[i + 2]));
        c3 += static_cast<std::size_t>(std::popcount(w[i + 3]));
    }
    for (; i < n; ++i) c0 += static_cast<std::size_t>(std::popcount(w[i]));
    return c0 + c1 + c2 + c3;
}

// Blocks of 32 words (256 bytes) are counted by the four-accumulator loop and skipped whole
// while their set bits do not reach the rank, so the scan runs at count() speed.
GRAPE_ALWAYS_INLINE std::size_t find_rank_loop(const Word* w, std::size_t n, std::size_t rank, std::size_t& before) noexcept {
    constexpr std::size_t block = 32;
    std::size_t seen = 0, k = 0;
    for (; k + block <= n; k += block) {
        const std::size_t c = count_loop(w + k, block);
        if (seen + c > rank) break;
        seen += c;
    }
    for (; k < n; ++k) {
        const std::size_t c = static_cast<std::size_t>(std::popcount(w[k]));
        if (seen + c > rank) break;
        seen += c;
    }
    before = seen;
    return k;
}

// a &= b and the count of the result in one pass, four popcount accumulators.
GRAPE_ALWAYS_INLINE std::size_t and_count_loop(Word* a, const Word* b, std::size_t n) noexcept {
    std::size_t c0 = 0, c1 = 0, c2 = 0, c3 = 0, i = 0;
    for (; i + 4 <= n; i += 4) {
        c0 += static_cast<std::size_t>(std::popcount(a[i] &= b[i]));
        c1 += static_cast<std::size_t>(std::popcount(a[i + 1] &= b[i + 1]));
        c2 += static_cast<std::size_t>(std::popcount(a[i + 2] &= b[i + 2]));
        c3 += static_cast<std::size_t>(std::popcount(a[i + 3] &= b[i + 3]));
    }
    for (; i < n; ++i) c0 += static_cast<std::size_t>(std::popcount(a[i] &= b[i]));
    return c0 + c1 + c2 + c3;
}

#if GRAPE_X86_TARGETS
// The AVX2 version counts with a nibble table in a byte shuffle (Muła, Kurz and Lemire,
// "Faster population counts using AVX2 instructions", 2018): 32 bytes per step, where popcnt
// takes four steps of 8. The byte counts (at most 8 each) add up over 31 steps before they are
// summed into 64-bit lanes, so no byte overflows.
GRAPE_TARGET("avx2,popcnt") std::size_t and_count_avx2(Word* a, const Word* b, std::size_t n) noexcept {
    const __m256i table = _mm256_setr_epi8(0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4,  //
                                           0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4);
    const __m256i low = _mm256_set1_epi8(0x0F);
    __m256i total = _mm256_setzero_si256();
    std::size_t i = 0;
    while (i + 4 <= n) {
        __m256i bytes = _mm256_setzero_si256();
        for (int step = 0; step < 31 && i + 4 <= n; ++step, i += 4) {
            const __m256i x = _mm256_and_si256(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(a + i)),
                                               _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b + i)));
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(a + i), x);
            const __m256i lo = _mm256_shuffle_epi8(table, _mm256_and_si256(x, low));
            const __m256i hi = _mm256_shuffle_epi8(table, _mm256_and_si256(_mm256_srli_epi16(x, 4), low));
            bytes = _mm256_add_epi8(bytes, _mm256_add_epi8(lo, hi));
        }
        total = _mm256_add_epi64(total, _mm256_sad_epu8(bytes, _mm256_setzero_si256()));
    }
    alignas(32) std::uint64_t lanes[4];
    _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), total);
    std::size_t c = static_cast<std::size_t>(lanes[0] + lanes[1] + lanes[2] + lanes[3]);
    for (; i < n; ++i) c += static_cast<std::size_t>(std::popcount(a[i] &= b[i]));
    return c;
}
#endif

// One binary kernel a = a op b, compiled with `features`.
#define GRAPE_BINARY_KERNEL(features, V, name, op) \
    GRAPE_TARGET(features) void name(Word* a, const Word* b, std::size_t n) noexcept { binary_loop<V, Op::op>(a, b, n); }

// One set of kernels per instruction set; the macro stamps out identical bodies so that each
// is compiled (and inlined into) with its own target features.
#define GRAPE_DEFINE_KERNELS(ns, features, V)                                                                     \
    namespace ns {                                                                                            \
    GRAPE_TARGET(features) std::size_t count(const Word* w, std::size_t n) noexcept { return count_loop(w, n); } \
    GRAPE_BINARY_KERNEL(features, V, and_with, and_)                                                          \
    GRAPE_BINARY_KERNEL(features, V, or_with, or_)                                                            \
    GRAPE_BINARY_KERNEL(features, V, xor_with, xor_)                                                          \
    GRAPE_BINARY_KERNEL(features, V, and_not, and_not)                                                        \
    GRAPE_TARGET(features) void flip(Word* a, std::size_t n) noexcept { flip_loop<V>(a, n); }                    \
    GRAPE_TARGET(features) void shift_up(Word* a, std::size_t n, std::size_t s) noexcept {                    \
        shift_up_words<V>(a, n, s);                                                                           \
    }                                                                                                         \
    GRAPE_TARGET(features) void shift_down(Word* a, std::size_t n, std::size_t s) noexcept {                  \
        shift_down_words<V>(a, n, s);                                                                         \
    }                                                                                                         \
    GRAPE_TARGET(features) std::size_t find_rank(const Word* w, std::size_t n, std::size_t r, std::size_t& b) noexcept { \
        return find_rank_loop(w, n, r, b);                                                                    \
    }                                                                                                         \
    }

namespace generic {
std::size_t count(const Word* w, std::size_t n) noexcept { return count_loop(w, n); }
void and_with(Word* a, const Word* b, std::size_t n) noexcept { binary_loop<Word2, Op::and_>(a, b, n); }
void or_with(Word* a, const Word* b, std::size_t n) noexcept { binary_loop<Word2, Op::or_>(a, b, n); }
void xor_with(Word* a, const Word* b, std::size_t n) noexcept { binary_loop<Word2, Op::xor_>(a, b, n); }
void and_not(Word* a, const Word* b, std::size_t n) noexcept { binary_loop<Word2, Op::and_not>(a, b, n); }
void flip(Word* a, std::size_t n) noexcept { flip_loop<Word2>(a, n); }
std::size_t and_count(Word* a, const Word* b, std::size_t n) noexcept { return and_count_loop(a, b, n); }
void shift_up(Word* a, std::size_t n, std::size_t s) noexcept { shift_up_words<Word2>(a, n, s); }
void shift_down(Word* a, std::size_t n, std::size_t s) noexcept { shift_down_words<Word2>(a, n, s); }
std::size_t find_rank(const Word* w, std::size_t n, std::size_t r, std::size_t& b) noexcept {
    return find_rank_loop(w, n, r, b);
}
}  // namespace generic

#define GRAPE_KERNEL_TABLE(ns, and_count_fn, name)                                                                       \
    WordKernels {                                                                                          \
        ns::count, ns::and_with, ns::or_with, ns::xor_with, ns::and_not, ns::flip, and_count_fn, ns::shift_up, \
            ns::shift_down, ns::find_rank, name                                                            \
    }

constexpr WordKernels generic_kernels = GRAPE_KERNEL_TABLE(generic, generic::and_count, "generic");

#if GRAPE_X86_TARGETS
GRAPE_DEFINE_KERNELS(popcnt, "popcnt", Word2)
namespace popcnt {
GRAPE_TARGET("popcnt") std::size_t and_count(Word* a, const Word* b, std::size_t n) noexcept {
    return and_count_loop(a, b, n);
}
}  // namespace popcnt
GRAPE_DEFINE_KERNELS(avx2, "avx2,popcnt", Word4)

constexpr WordKernels popcnt_kernels = GRAPE_KERNEL_TABLE(popcnt, popcnt::and_count, "popcnt");
constexpr WordKernels avx2_kernels = GRAPE_KERNEL_TABLE(avx2, and_count_avx2, "avx2+popcnt");

bool has_popcnt() noexcept { return cpu_has_popcnt(); }
bool has_avx2() noexcept { return cpu_has_avx2(); }

const WordKernels& select() noexcept {
    if (has_popcnt() && has_avx2()) return avx2_kernels;
    if (has_popcnt()) return popcnt_kernels;
    return generic_kernels;
}
#else
const WordKernels& select() noexcept { return generic_kernels; }
#endif

}  // namespace

const WordKernels& word_kernels() noexcept {
    static const WordKernels& chosen = select();
    return chosen;
}

const WordKernels& generic_word_kernels() noexcept { return generic_kernels; }

const WordKernels* const* runnable_word_kernels(std::size_t& count) noexcept {
    static const WordKernels* list[3] = {&generic_kernels, nullptr, nullptr};
    static const std::size_t n = [] {
        std::size_t k = 1;
#if GRAPE_X86_TARGETS
        if (has_popcnt()) list[k++] = &popcnt_kernels;
        if (has_popcnt() && has_avx2()) list[k++] = &avx2_kernels;
#endif
        return k;
    }();
    count = n;
    return list;
}

}  // namespace grape::detail
