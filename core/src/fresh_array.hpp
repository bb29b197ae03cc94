// Large arrays filled by parallel loops (the bulk build behind every reader): their memory is
// backed by all threads before the first store, so that the first touch of each page (the kernel
// zeroing it, which measured as much as filling the array; docs/performance.md "io") is shared
// instead of falling on the one thread that constructs the vector.
#pragma once

#include <algorithm>
#include <cstddef>

#include <tbb/parallel_for.h>

#include "sxk/detail/large_array.hpp"

namespace sxk::detail {

// Backs [block, block + bytes) with memory, 2 MiB per task (see populate).
inline void populate_in_parallel(void* block, std::size_t bytes) {
    constexpr std::size_t chunk = large_allocation_bytes;
    if (bytes < chunk) return;
    tbb::parallel_for(std::size_t{0}, (bytes + chunk - 1) / chunk, [&](std::size_t c) {
        populate(static_cast<char*>(block) + c * chunk, std::min(chunk, bytes - c * chunk));
    });
}

// reserve(count), the memory backed in parallel (for the readers' arrays, filled by push_back).
template <class Vector>
void reserve_fresh(Vector& vector, std::size_t count) {
    vector.reserve(count);
    populate_in_parallel(vector.data(), vector.capacity() * sizeof(typename Vector::value_type));
}

// Makes `pool` hold `count` copies of `value`, its memory backed in parallel first.
template <class T>
void assign_fresh(LargeVector<T>& pool, std::size_t count, const T& value) {
    pool.clear();
    pool.reserve(count);
    populate_in_parallel(pool.data(), count * sizeof(T));
    pool.assign(count, value);
}

// A vector of `count` copies of `value`, its memory backed in parallel first.
template <class T>
LargeVector<T> fresh_vector(std::size_t count, const T& value = T{}) {
    LargeVector<T> fresh;
    assign_fresh(fresh, count, value);
    return fresh;
}

}  // namespace sxk::detail
