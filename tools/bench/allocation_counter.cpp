// Replacement global operator new/delete that count live and peak heap bytes (see the header).
// Process-wide counters are the point of a replaced operator new, so this benchmark-only file
// holds the one piece of global mutable state in the project; the library itself has none.
#include "allocation_counter.hpp"

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::atomic<std::size_t> g_live{0};
std::atomic<std::size_t> g_peak{0};
std::atomic<std::size_t> g_count{0};

void count_allocation(void* pointer) {
    const std::size_t bytes = malloc_usable_size(pointer);
    const std::size_t live = g_live.fetch_add(bytes, std::memory_order_relaxed) + bytes;
    g_count.fetch_add(1, std::memory_order_relaxed);
    std::size_t peak = g_peak.load(std::memory_order_relaxed);
    while (live > peak && !g_peak.compare_exchange_weak(peak, live, std::memory_order_relaxed)) {
    }
}

void count_release(void* pointer) {
    if (pointer != nullptr)
        g_live.fetch_sub(malloc_usable_size(pointer), std::memory_order_relaxed);
}

void* allocate(std::size_t size) {
    void* pointer = std::malloc(size == 0 ? 1 : size);
    if (pointer != nullptr)
        count_allocation(pointer);
    return pointer;
}

void* allocate_aligned(std::size_t size, std::align_val_t alignment) {
    const std::size_t align = static_cast<std::size_t>(alignment);
    // aligned_alloc wants a size that is a multiple of the alignment
    const std::size_t rounded = ((size == 0 ? 1 : size) + align - 1) / align * align;
    void* pointer = std::aligned_alloc(align, rounded);
    if (pointer != nullptr)
        count_allocation(pointer);
    return pointer;
}

void release(void* pointer) {
    count_release(pointer);
    std::free(pointer);
}

}  // namespace

namespace sxk_bench {

std::size_t live_bytes() {
    return g_live.load(std::memory_order_relaxed);
}
std::size_t peak_bytes() {
    return g_peak.load(std::memory_order_relaxed);
}
std::size_t allocation_count() {
    return g_count.load(std::memory_order_relaxed);
}
void reset_peak() {
    g_peak.store(g_live.load(std::memory_order_relaxed), std::memory_order_relaxed);
    g_count.store(0, std::memory_order_relaxed);
}

}  // namespace sxk_bench

// The replaceable forms ([new.delete]); default visibility so that the shared libraries bind to
// them even though the project compiles with -fvisibility=hidden.
#define SXK_BENCH_EXPORT __attribute__((visibility("default")))

SXK_BENCH_EXPORT void* operator new(std::size_t size) {
    if (void* pointer = allocate(size))
        return pointer;
    throw std::bad_alloc();
}
SXK_BENCH_EXPORT void* operator new[](std::size_t size) {
    if (void* pointer = allocate(size))
        return pointer;
    throw std::bad_alloc();
}
SXK_BENCH_EXPORT void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    return allocate(size);
}
SXK_BENCH_EXPORT void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    return allocate(size);
}
SXK_BENCH_EXPORT void* operator new(std::size_t size, std::align_val_t alignment) {
    if (void* pointer = allocate_aligned(size, alignment))
        return pointer;
    throw std::bad_alloc();
}
SXK_BENCH_EXPORT void* operator new[](std::size_t size, std::align_val_t alignment) {
    if (void* pointer = allocate_aligned(size, alignment))
        return pointer;
    throw std::bad_alloc();
}
SXK_BENCH_EXPORT void* operator new(std::size_t size, std::align_val_t alignment,
                                    const std::nothrow_t&) noexcept {
    return allocate_aligned(size, alignment);
}
SXK_BENCH_EXPORT void* operator new[](std::size_t size, std::align_val_t alignment,
                                      const std::nothrow_t&) noexcept {
    return allocate_aligned(size, alignment);
}

SXK_BENCH_EXPORT void operator delete(void* pointer) noexcept {
    release(pointer);
}
SXK_BENCH_EXPORT void operator delete[](void* pointer) noexcept {
    release(pointer);
}
SXK_BENCH_EXPORT void operator delete(void* pointer, std::size_t) noexcept {
    release(pointer);
}
SXK_BENCH_EXPORT void operator delete[](void* pointer, std::size_t) noexcept {
    release(pointer);
}
SXK_BENCH_EXPORT void operator delete(void* pointer, const std::nothrow_t&) noexcept {
    release(pointer);
}
SXK_BENCH_EXPORT void operator delete[](void* pointer, const std::nothrow_t&) noexcept {
    release(pointer);
}
SXK_BENCH_EXPORT void operator delete(void* pointer, std::align_val_t) noexcept {
    release(pointer);
}
SXK_BENCH_EXPORT void operator delete[](void* pointer, std::align_val_t) noexcept {
    release(pointer);
}
SXK_BENCH_EXPORT void operator delete(void* pointer, std::size_t, std::align_val_t) noexcept {
    release(pointer);
}
SXK_BENCH_EXPORT void operator delete[](void* pointer, std::size_t, std::align_val_t) noexcept {
    release(pointer);
}
SXK_BENCH_EXPORT void operator delete(void* pointer, std::align_val_t,
                                      const std::nothrow_t&) noexcept {
    release(pointer);
}
SXK_BENCH_EXPORT void operator delete[](void* pointer, std::align_val_t,
                                        const std::nothrow_t&) noexcept {
    release(pointer);
}
