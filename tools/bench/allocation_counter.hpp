// Heap accounting for the benchmark programs: this program's replacement of the global operator
// new/delete (allocation_counter.cpp) counts the bytes every allocation really occupies
// (malloc_usable_size, so allocator rounding is included) and keeps the high-water mark.
//
// It sees every allocation made through operator new anywhere in the process, including the
// simplexkit shared library and CGAL's containers (std::allocator), because the executable's
// definitions interpose on libstdc++'s. Memory obtained from malloc directly is not counted;
// neither simplexkit nor the CGAL code measured here does that.
//
// Usage around a build:
//
//     sxk_bench::reset_peak();                         // peak := live
//     const std::size_t before = sxk_bench::live_bytes();
//     build();
//     const std::size_t peak = sxk_bench::peak_bytes() - before;   // excludes the inputs
#pragma once

#include <cstddef>

namespace sxk_bench {

// Bytes currently allocated through operator new.
std::size_t live_bytes();
// Highest live_bytes() since the last reset_peak().
std::size_t peak_bytes();
// Number of operator new calls since the last reset_peak().
std::size_t allocation_count();
// Sets the peak to the current live bytes and the allocation count to zero.
void reset_peak();

}  // namespace sxk_bench
