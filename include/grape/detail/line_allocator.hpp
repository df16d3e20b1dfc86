// grape — an allocator of cache-line aligned storage (internal to the library's containers).
#pragma once

#include <cstddef>
#include <new>

namespace grape::detail {

/// Storage on 64-byte boundaries, so that no piece a loop loads (a 32-byte vector, a table
/// entry) straddles two cache lines; malloc's 16-byte alignment splits every other one.
template <class T>
struct LineAllocator {
    using value_type = T;
    LineAllocator() = default;
    template <class U>
    LineAllocator(const LineAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t{64})); }
    void deallocate(T* p, std::size_t) noexcept { ::operator delete(p, std::align_val_t{64}); }
    template <class U>
    bool operator==(const LineAllocator<U>&) const noexcept { return true; }
};

}  // namespace grape::detail
