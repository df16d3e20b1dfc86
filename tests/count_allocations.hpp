// Counts the heap allocations of a test program, so a test can prove that evaluation allocates
// nothing (read g_allocations before and after). Include it in exactly one file of a test
// program. Every replaceable form of operator new is counted (heap_hooks.hpp, shared with the
// benchmarks' byte counters): a form left out would go to the library's own and allocate
// unseen.
#pragma once

#include "heap_hooks.hpp"

#include <atomic>
#include <cstddef>

inline std::atomic<long> g_allocations{0};

void heap_hooks::on_alloc(void*, std::size_t) noexcept { ++g_allocations; }
void heap_hooks::on_free(void*) noexcept {}
