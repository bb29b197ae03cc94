// SmallVector, the scratch list of the edit primitives, the star walks and the operations
// (mesh_checks.hpp, star_walk.hpp, core/src/ops): the flips' checks allocated a list per star
// walk before it (docs/performance.md "tet_flips", "What changed" 2).
#pragma once

#include <cstddef>
#include <new>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace sxk::detail {

// A vector that keeps its first N elements in place (on the stack, as a local) and moves to the
// heap only beyond N: the edit primitives' scratch lists (a few faces, one vertex star) fit in
// place, so a flip allocates nothing but its result. Only for trivially copyable T. The in-place
// slots are raw storage, not N constructed T: types with default member initialisers would
// otherwise be written N times on every construction (64 NewFace records, 2.5 KB of stores per
// replace_elements call, before any work).
template <class T, std::size_t N>
class SmallVector {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

public:
    SmallVector() = default;
    SmallVector(const SmallVector&) = delete;
    SmallVector& operator=(const SmallVector&) = delete;

    std::size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    T* data() { return m_heap.empty() ? inline_data() : m_heap.data(); }
    const T* data() const { return m_heap.empty() ? inline_data() : m_heap.data(); }
    T* begin() { return data(); }
    T* end() { return data() + m_size; }
    const T* begin() const { return data(); }
    const T* end() const { return data() + m_size; }
    T& operator[](std::size_t i) { return data()[i]; }
    const T& operator[](std::size_t i) const { return data()[i]; }
    T& back() { return data()[m_size - 1]; }
    operator std::span<const T>() const { return {data(), m_size}; }

    void push_back(const T& value) {
        if (m_heap.empty()) {
            if (m_size < N) {
                ::new (static_cast<void*>(inline_data() + m_size)) T(value);
                ++m_size;
                return;
            }
            m_heap.reserve(2 * N);
            m_heap.assign(inline_data(), inline_data() + m_size);
        }
        m_heap.push_back(value);
        ++m_size;
    }
    template <class... Arguments>
    void emplace_back(Arguments&&... arguments) {
        push_back(T(std::forward<Arguments>(arguments)...));
    }
    // Grows with value-initialised elements or shrinks.
    void resize(std::size_t size) {
        while (m_size < size) push_back(T{});
        if (!m_heap.empty()) m_heap.resize(size);  // heap mode iff m_heap is not empty
        m_size = size;
    }
    void clear() {
        m_size = 0;
        m_heap.clear();
    }

private:
    T* inline_data() { return std::launder(reinterpret_cast<T*>(m_inline)); }
    const T* inline_data() const { return std::launder(reinterpret_cast<const T*>(m_inline)); }

    alignas(T) std::byte m_inline[N * sizeof(T)];
    std::vector<T> m_heap;
    std::size_t m_size = 0;
};

}  // namespace sxk::detail
