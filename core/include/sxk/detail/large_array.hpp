// Storage for the arrays that grow with the mesh: the element, face and vertex pools, the
// boundary map's slots, and the scratch of the readers and of assign_elements.
//
// Why: on Linux every 4 KiB page of a fresh allocation costs a page fault when it is first
// touched, and reading the femur-1226k touches about 400 MB of fresh arrays. Under a hypervisor
// those faults measured 22% of read_mesh, plus 6% in the zeroing they imply (perf,
// docs/performance.md "io": huge pages). Allocations of 2 MiB and more are therefore aligned to
// 2 MiB and offered to the kernel as transparent huge pages (madvise MADV_HUGEPAGE), one fault
// per 2 MiB instead of 512; smaller ones go to operator new as usual, so a small mesh costs no
// more memory than before. Where the kernel has no huge pages (THP "never", other systems) the
// advice is ignored and nothing else changes. A mesh's random accesses (flips, walks) also miss
// the TLB less.
#pragma once

#include <cstddef>
#include <new>
#include <string>
#include <vector>

#include "sxk/config.hpp"

namespace sxk::detail {

// Allocations of at least this many bytes are huge-page aligned and advised.
inline constexpr std::size_t large_allocation_bytes = std::size_t{2} << 20;

// operator new(bytes), or for large sizes a 2 MiB aligned block of a whole number of huge
// pages with the advice given; throws std::bad_alloc. Release with the same byte count.
SXK_API void* allocate_large(std::size_t bytes);
SXK_API void deallocate_large(void* block, std::size_t bytes) noexcept;

// Asks the kernel to back [block, block + bytes) with memory now (Linux MADV_POPULATE_WRITE;
// elsewhere, or when refused, nothing happens). Contents are unchanged. For filling a fresh pool
// in parallel: the first touch of each page (the kernel zeroing it) is then shared by the
// threads instead of falling on the one thread that constructs the vector.
SXK_API void populate(void* block, std::size_t bytes) noexcept;

// A stateless standard allocator over allocate_large (every instance equal).
template <class T>
struct LargeArrayAllocator {
    static_assert(alignof(T) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__,
                  "over-aligned types need an aligned small path");
    using value_type = T;

    LargeArrayAllocator() noexcept = default;
    template <class U>
    LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
        return static_cast<T*>(allocate_large(n * sizeof(T)));
    }
    void deallocate(T* block, std::size_t n) noexcept { deallocate_large(block, n * sizeof(T)); }

    template <class U>
    bool operator==(const LargeArrayAllocator<U>&) const noexcept {
        return true;
    }
};

template <class T>
using LargeVector = std::vector<T, LargeArrayAllocator<T>>;

// Grows v to at least n entries (the new ones `fill`), making room for it to double when it has
// none: scratch kept per vertex or element id that follows a growing mesh (marks, slots) is then
// copied once per doubling of the mesh, not each time the mesh grows a little. Inside a tool's
// step such a copy, with the fresh pages it touches, took 36-47 ms on a million triangles
// (docs/performance.md "needle").
template <class Vector>
void grow_doubling(Vector& v, std::size_t n, const typename Vector::value_type& fill) {
    if (v.size() >= n) return;
    if (v.capacity() < n) v.reserve(2 * n);
    v.resize(n, fill);
}

// A file's bytes as the readers hold them.
using TextBuffer = std::basic_string<char, std::char_traits<char>, LargeArrayAllocator<char>>;

}  // namespace sxk::detail
