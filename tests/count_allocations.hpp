// Replaces the global operator new of a test program to count heap allocations, so a test can
// prove that evaluation allocates nothing (read g_allocations before and after). Include it
// in exactly one file of a test program. Every replaceable form is counted: plain, array,
// nothrow and the std::align_val_t forms that types declared alignas(N) beyond
// __STDCPP_DEFAULT_NEW_ALIGNMENT__ go through; a form left out would go to the library's own
// and allocate unseen. (GCC cannot see that the replaced new and delete pair up through
// malloc/free, hence the pragma.)
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>

#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
inline std::atomic<long> g_allocations{0};

namespace count_allocations {
inline void* plain(std::size_t size) noexcept {
    ++g_allocations;
    return std::malloc(size == 0 ? 1 : size);
}
// Over-allocates with malloc and keeps the block's own address just below the aligned one:
// portable (MinGW's C library has no aligned_alloc whose blocks free() accepts).
inline void* aligned(std::size_t size, std::align_val_t al) noexcept {
    ++g_allocations;
    const std::size_t a = static_cast<std::size_t>(al) < alignof(void*)
                              ? alignof(void*)
                              : static_cast<std::size_t>(al);
    if (size > SIZE_MAX - a - sizeof(void*)) return nullptr;
    void* raw = std::malloc(size + a + sizeof(void*));
    if (!raw) return nullptr;
    const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(raw) + sizeof(void*);
    const std::uintptr_t p = (start + a - 1) & ~(static_cast<std::uintptr_t>(a) - 1);
    std::memcpy(reinterpret_cast<void*>(p - sizeof(void*)), &raw, sizeof raw);
    return reinterpret_cast<void*>(p);
}
inline void release_aligned(void* p) noexcept {
    if (!p) return;
    void* raw = nullptr;
    std::memcpy(&raw, reinterpret_cast<void*>(reinterpret_cast<std::uintptr_t>(p) - sizeof(void*)), sizeof raw);
    std::free(raw);
}
}  // namespace count_allocations

void* operator new(std::size_t size) {
    if (void* p = count_allocations::plain(size)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
    if (void* p = count_allocations::plain(size)) return p;
    throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {  // std::stable_sort's buffer
    return count_allocations::plain(size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    return count_allocations::plain(size);
}
void* operator new(std::size_t size, std::align_val_t al) {
    if (void* p = count_allocations::aligned(size, al)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size, std::align_val_t al) {
    if (void* p = count_allocations::aligned(size, al)) return p;
    throw std::bad_alloc();
}
void* operator new(std::size_t size, std::align_val_t al, const std::nothrow_t&) noexcept {
    return count_allocations::aligned(size, al);
}
void* operator new[](std::size_t size, std::align_val_t al, const std::nothrow_t&) noexcept {
    return count_allocations::aligned(size, al);
}

void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { count_allocations::release_aligned(p); }
void operator delete[](void* p, std::align_val_t) noexcept {
    count_allocations::release_aligned(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    count_allocations::release_aligned(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    count_allocations::release_aligned(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    count_allocations::release_aligned(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    count_allocations::release_aligned(p);
}
