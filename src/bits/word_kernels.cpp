// The word loops are written once as templates over a vector type (GCC/Clang vector
// extensions: 2 words in an SSE2 register for the baseline and popcnt versions, 4 words in an
// AVX2 register for the avx2 version) and instantiated inside functions carrying target
// attributes. -O2's very-cheap vectorizer will not vectorize an unknown-length loop by itself
// (it would need an epilogue and an aliasing check), hence the explicit vectors.
#include "word_kernels.hpp"

#include <bit>
#include <cstring>

namespace grape::detail {
namespace {

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define GRAPE_BITS_X86_DISPATCH 1
#define GRAPE_TARGET(features) __attribute__((target(features)))
#else
#define GRAPE_BITS_X86_DISPATCH 0
#define GRAPE_TARGET(features)
#endif

#if defined(__GNUC__)
#define GRAPE_INLINE inline __attribute__((always_inline))
#else
#define GRAPE_INLINE inline
#endif

enum class Op { and_, or_, xor_, and_not };

// x = x op y. By reference, so no vector is ever passed by value (see below).
template <Op op, class T>
GRAPE_INLINE void apply(T& x, const T& y) noexcept {
    if constexpr (op == Op::and_) x &= y;
    if constexpr (op == Op::or_) x |= y;
    if constexpr (op == Op::xor_) x ^= y;
    if constexpr (op == Op::and_not) x &= ~y;
}

#if defined(__GNUC__)
// Vectors never cross a function boundary by value: passing a 32-byte vector to a function
// compiled without AVX uses a different ABI, which at -O0 (no inlining) corrupts the operands.
using Word2 = Word __attribute__((vector_size(16)));  // one SSE2 register
using Word4 = Word __attribute__((vector_size(32)));  // one AVX2 register

// Two vectors per iteration so the loads of the next pair overlap the stores of this one.
template <class V, Op op>
GRAPE_INLINE void binary_loop(Word* a, const Word* b, std::size_t n) noexcept {
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
GRAPE_INLINE void flip_loop(Word* a, std::size_t n) noexcept {
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
#endif

// Four accumulators keep the popcnt units busy (one chain would be latency bound).
GRAPE_INLINE std::size_t count_loop(const Word* w, std::size_t n) noexcept {
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

// One set of kernels per instruction set; the macro stamps out identical bodies so that each
// is compiled (and inlined into) with its own target features.
#define GRAPE_DEFINE_KERNELS(ns, features, V)                                                                     \
    namespace ns {                                                                                            \
    GRAPE_TARGET(features) std::size_t count(const Word* w, std::size_t n) noexcept { return count_loop(w, n); } \
    GRAPE_TARGET(features) void and_with(Word* a, const Word* b, std::size_t n) noexcept {                    \
        binary_loop<V, Op::and_>(a, b, n);                                                                         \
    }                                                                                                         \
    GRAPE_TARGET(features) void or_with(Word* a, const Word* b, std::size_t n) noexcept {                     \
        binary_loop<V, Op::or_>(a, b, n);                                                                          \
    }                                                                                                         \
    GRAPE_TARGET(features) void xor_with(Word* a, const Word* b, std::size_t n) noexcept {                    \
        binary_loop<V, Op::xor_>(a, b, n);                                                                         \
    }                                                                                                         \
    GRAPE_TARGET(features) void and_not(Word* a, const Word* b, std::size_t n) noexcept {                     \
        binary_loop<V, Op::and_not>(a, b, n);                                                                     \
    }                                                                                                         \
    GRAPE_TARGET(features) void flip(Word* a, std::size_t n) noexcept { flip_loop<V>(a, n); }                    \
    }

namespace generic {
std::size_t count(const Word* w, std::size_t n) noexcept { return count_loop(w, n); }
void and_with(Word* a, const Word* b, std::size_t n) noexcept { binary_loop<Word2, Op::and_>(a, b, n); }
void or_with(Word* a, const Word* b, std::size_t n) noexcept { binary_loop<Word2, Op::or_>(a, b, n); }
void xor_with(Word* a, const Word* b, std::size_t n) noexcept { binary_loop<Word2, Op::xor_>(a, b, n); }
void and_not(Word* a, const Word* b, std::size_t n) noexcept { binary_loop<Word2, Op::and_not>(a, b, n); }
void flip(Word* a, std::size_t n) noexcept { flip_loop<Word2>(a, n); }
}  // namespace generic

constexpr WordKernels generic_kernels{generic::count,   generic::and_with, generic::or_with, generic::xor_with,
                                      generic::and_not, generic::flip,     "generic"};

#if GRAPE_BITS_X86_DISPATCH
GRAPE_DEFINE_KERNELS(popcnt, "popcnt", Word2)
GRAPE_DEFINE_KERNELS(avx2, "avx2,popcnt", Word4)

constexpr WordKernels popcnt_kernels{popcnt::count,   popcnt::and_with, popcnt::or_with, popcnt::xor_with,
                                     popcnt::and_not, popcnt::flip,     "popcnt"};
constexpr WordKernels avx2_kernels{avx2::count,   avx2::and_with, avx2::or_with, avx2::xor_with,
                                   avx2::and_not, avx2::flip,     "avx2+popcnt"};

bool has_popcnt() noexcept {
    __builtin_cpu_init();  // safe to call early (e.g. from a static initializer)
    return __builtin_cpu_supports("popcnt");
}
bool has_avx2() noexcept {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2");
}

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
#if GRAPE_BITS_X86_DISPATCH
        if (has_popcnt()) list[k++] = &popcnt_kernels;
        if (has_popcnt() && has_avx2()) list[k++] = &avx2_kernels;
#endif
        return k;
    }();
    count = n;
    return list;
}

}  // namespace grape::detail
