// allocate_large / deallocate_large (sxk/detail/large_array.hpp): why huge pages, and the
// figures, are there.
#include "sxk/detail/large_array.hpp"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace sxk::detail {

namespace {

constexpr std::align_val_t huge_alignment{large_allocation_bytes};

std::size_t whole_huge_pages(std::size_t bytes) {
    return (bytes + large_allocation_bytes - 1) / large_allocation_bytes * large_allocation_bytes;
}

}  // namespace

void* allocate_large(std::size_t bytes) {
    if (bytes < large_allocation_bytes) return ::operator new(bytes);
    const std::size_t rounded = whole_huge_pages(bytes);
    if (rounded < bytes) throw std::bad_alloc();  // wrapped around
    void* block = ::operator new(rounded, huge_alignment);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // advice only: where huge pages are off or exhausted the block simply stays in 4 KiB pages
    (void)::madvise(block, rounded, MADV_HUGEPAGE);
#endif
    return block;
}

void deallocate_large(void* block, std::size_t bytes) noexcept {
    if (bytes < large_allocation_bytes)
        ::operator delete(block);
    else
        ::operator delete(block, huge_alignment);
}

void populate(void* block, std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    // madvise wants a page-aligned start: round it down (the page is ours or our neighbour's in
    // the same allocation, and populating does not change contents)
    const auto start = reinterpret_cast<std::uintptr_t>(block) & ~std::uintptr_t{4095};
    const std::size_t length = bytes + (reinterpret_cast<std::uintptr_t>(block) - start);
    (void)::madvise(reinterpret_cast<void*>(start), length, MADV_POPULATE_WRITE);
#else
    (void)block;
    (void)bytes;
#endif
}

}  // namespace sxk::detail
