// grape — every compiler extension grape's sources use, each with a portable fallback, so
// that a compiler without it (MSVC, or any other) builds the same code without them.
//
//   GRAPE_FLATTEN          inline every call in the function's body (the hot loops)
//   GRAPE_ALWAYS_INLINE    inline this function wherever it is called
//   GRAPE_X86_TARGETS      1 where one function may be compiled for an instruction set the
//                          build's baseline lacks (x86 GCC and clang): GRAPE_TARGET("avx2")
//                          on the function, <immintrin.h> included, chosen at run time by
//                          cpu_has_avx2() / cpu_has_popcnt(); 0 elsewhere (baseline code only)
//   GRAPE_VECTOR_EXTENSIONS 1 where `T __attribute__((vector_size(N)))` works (GCC, clang)
//   prefetch_read(p), prefetch_write(p)  hints, no effect on results
//   cpu_relax()            a spin-wait's pause
//   GRAPE_DEFAULT_VISIBILITY a symbol a runtime looks up by name (sanitizer hooks), seen
//                          from outside although grape builds with hidden visibility
//   GRAPE_ADDRESS_SANITIZER 1 in an AddressSanitizer build (GCC defines __SANITIZE_ADDRESS__,
//                          clang answers __has_feature), else 0
// Not used anywhere: __int128, GNU statement expressions, #pragma GCC, builtins outside this
// header. Public headers use none of these.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define GRAPE_FLATTEN __attribute__((flatten))
#define GRAPE_ALWAYS_INLINE inline __attribute__((always_inline))
#define GRAPE_VECTOR_EXTENSIONS 1
#elif defined(_MSC_VER)
#define GRAPE_FLATTEN
#define GRAPE_ALWAYS_INLINE __forceinline
#define GRAPE_VECTOR_EXTENSIONS 0
#else
#define GRAPE_FLATTEN
#define GRAPE_ALWAYS_INLINE inline
#define GRAPE_VECTOR_EXTENSIONS 0
#endif

#if defined(__GNUC__) || defined(__clang__)
#define GRAPE_DEFAULT_VISIBILITY __attribute__((visibility("default")))
#else
#define GRAPE_DEFAULT_VISIBILITY
#endif

#if defined(__SANITIZE_ADDRESS__)
#define GRAPE_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GRAPE_ADDRESS_SANITIZER 1
#endif
#endif
#ifndef GRAPE_ADDRESS_SANITIZER
#define GRAPE_ADDRESS_SANITIZER 0
#endif

#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__))
#define GRAPE_X86_TARGETS 1
#define GRAPE_TARGET(features) __attribute__((target(features)))
#include <immintrin.h>
#else
#define GRAPE_X86_TARGETS 0
#define GRAPE_TARGET(features)
#endif

#if defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
#include <intrin.h>
#elif defined(_MSC_VER) && defined(_M_ARM64)
#include <intrin.h>
#endif

namespace grape::detail {

/// Asks for the cache line at p, to be read.
inline void prefetch_read(const void* p) noexcept {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(p, 0);
#elif defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
    _mm_prefetch(static_cast<const char*>(p), _MM_HINT_T0);
#else
    (void)p;
#endif
}

/// Asks for the cache line at p, to be written.
inline void prefetch_write(const void* p) noexcept {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(p, 1);
#else
    prefetch_read(p);  // MSVC has no write hint for x86; a read hint still brings the line
#endif
}

/// One pause of a spin wait: lets the other hyper-thread run and saves power.
inline void cpu_relax() noexcept {
#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__))
    __builtin_ia32_pause();
#elif (defined(__GNUC__) || defined(__clang__)) && defined(__aarch64__)
    __asm__ __volatile__("yield");
#elif defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
    _mm_pause();
#elif defined(_MSC_VER) && defined(_M_ARM64)
    __yield();
#endif
}

/// Whether this processor (and its operating system) runs AVX2 / POPCNT code. Always false
/// where GRAPE_X86_TARGETS is 0, so only baseline code is ever chosen there.
inline bool cpu_has_avx2() noexcept {
#if GRAPE_X86_TARGETS
    __builtin_cpu_init();  // safe to call early (e.g. from a static initializer)
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}
inline bool cpu_has_popcnt() noexcept {
#if GRAPE_X86_TARGETS
    __builtin_cpu_init();
    return __builtin_cpu_supports("popcnt");
#else
    return false;
#endif
}

}  // namespace grape::detail
