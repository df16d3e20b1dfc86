// Replaces every form of the global operator new and delete of a test or benchmark program (plain,
// array, nothrow and the std::align_val_t forms that alignas(64) storage goes through) so
// that its heap accounting sees them all. Include it in exactly one file and define there
//   void heap_hooks::on_alloc(void* block, std::size_t size) noexcept;  // after malloc
//   void heap_hooks::on_free(void* block) noexcept;                     // before free
// where `block` is what malloc returned (malloc_usable_size works on it) and `size` the
// bytes the program asked for.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>

#if defined(__GNUC__) && !defined(__clang__)
// GCC's -O3 inlines the standard allocator's new/delete pair and, seeing malloc meet a
// delete, warns that they do not match; both sides are replaced here, so they do.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

namespace heap_hooks {
void on_alloc(void* block, std::size_t size) noexcept;
void on_free(void* block) noexcept;

inline void* plain(std::size_t size) noexcept {
    void* p = std::malloc(size == 0 ? 1 : size);
    if (p) on_alloc(p, size);
    return p;
}
inline void release(void* p) noexcept {
    if (!p) return;
    on_free(p);
    std::free(p);
}
// Over-allocates and keeps malloc's block address just below the aligned one.
inline void* aligned(std::size_t size, std::align_val_t al) noexcept {
    const std::size_t a = static_cast<std::size_t>(al) < alignof(void*)
                              ? alignof(void*)
                              : static_cast<std::size_t>(al);
    if (size > SIZE_MAX - a - sizeof(void*)) return nullptr;
    void* raw = std::malloc(size + a + sizeof(void*));
    if (!raw) return nullptr;
    on_alloc(raw, size);
    const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(raw) + sizeof(void*);
    const std::uintptr_t p = (start + a - 1) & ~(static_cast<std::uintptr_t>(a) - 1);
    std::memcpy(reinterpret_cast<void*>(p - sizeof(void*)), &raw, sizeof raw);
    return reinterpret_cast<void*>(p);
}
inline void release_aligned(void* p) noexcept {
    if (!p) return;
    void* raw = nullptr;
    std::memcpy(&raw, reinterpret_cast<void*>(reinterpret_cast<std::uintptr_t>(p) - sizeof(void*)), sizeof raw);
    release(raw);
}
}  // namespace heap_hooks

void* operator new(std::size_t size) {
    if (void* p = heap_hooks::plain(size)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
    if (void* p = heap_hooks::plain(size)) return p;
    throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return heap_hooks::plain(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return heap_hooks::plain(size); }
void* operator new(std::size_t size, std::align_val_t al) {
    if (void* p = heap_hooks::aligned(size, al)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size, std::align_val_t al) {
    if (void* p = heap_hooks::aligned(size, al)) return p;
    throw std::bad_alloc();
}
void* operator new(std::size_t size, std::align_val_t al, const std::nothrow_t&) noexcept {
    return heap_hooks::aligned(size, al);
}
void* operator new[](std::size_t size, std::align_val_t al, const std::nothrow_t&) noexcept {
    return heap_hooks::aligned(size, al);
}
void operator delete(void* p) noexcept { heap_hooks::release(p); }
void operator delete[](void* p) noexcept { heap_hooks::release(p); }
void operator delete(void* p, std::size_t) noexcept { heap_hooks::release(p); }
void operator delete[](void* p, std::size_t) noexcept { heap_hooks::release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { heap_hooks::release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { heap_hooks::release(p); }
void operator delete(void* p, std::align_val_t) noexcept { heap_hooks::release_aligned(p); }
void operator delete[](void* p, std::align_val_t) noexcept { heap_hooks::release_aligned(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { heap_hooks::release_aligned(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { heap_hooks::release_aligned(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    heap_hooks::release_aligned(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    heap_hooks::release_aligned(p);
}
