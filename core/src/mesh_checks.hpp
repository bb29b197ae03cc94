// Argument checks shared by the edit primitives.
#pragma once

#include <algorithm>
#include <cstddef>
#include <new>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/predicates.hpp"
#include "sxk/simplex.hpp"

namespace sxk::detail {

// Why `s` cannot be an element of a mesh with `vertices` vertices and elements of
// `vertex_count_per_element` vertices; empty when it can.
inline std::string check_simplex(const Simplex& s, int vertex_count_per_element,
                                 std::size_t vertices) {
    if (s.count() != vertex_count_per_element)
        return "element has " + std::to_string(s.count()) + " vertices, expected " +
               std::to_string(vertex_count_per_element);
    for (int j = 0; j < s.count(); ++j)
        if (s.vertex(j) >= vertices)
            return "vertex " + std::to_string(s.vertex(j)) + " does not exist (the mesh has " +
                   std::to_string(vertices) + " vertices)";
    if (!s.has_distinct_vertices()) return "element " + to_text(s) + " repeats a vertex";
    return {};
}

// The code of a refusal for a new element whose orientation `s` is not the one it must have:
// would_flatten when it is zero, would_invert otherwise.
inline RefusalCode orientation_code(Sign s) {
    return s == Sign::zero ? RefusalCode::would_flatten : RefusalCode::would_invert;
}

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

// The elements met by a star walk, with a small open-addressing set beside the list so that
// "seen already?" costs one probe instead of a scan (a 3D star has ~25 elements, each reached
// from up to three neighbours). Short lists (2D stars) are scanned and never pay for clearing
// the set; beyond `hashed` elements the set is full and the scan takes over again.
class StarList {
public:
    const SmallVector<ElementId, 256>& elements() const { return m_elements; }
    // Appends t unless it is in the list already; true when appended.
    bool insert(ElementId t) {
        const std::size_t n = m_elements.size();
        if (n < scanned || n >= hashed) {
            if (std::find(m_elements.begin(), m_elements.end(), t) != m_elements.end()) return false;
            if (n + 1 == scanned) {
                std::fill(std::begin(m_slots), std::end(m_slots), invalid_id);
                for (const ElementId e : m_elements) probe(e);
                probe(t);
            }
        } else if (!probe(t)) {
            return false;
        }
        m_elements.push_back(t);
        return true;
    }

private:
    // Puts t into the set; false when it was there.
    bool probe(ElementId t) {
        std::size_t slot = (t * 2654435761u) & (slots - 1);
        while (m_slots[slot] != invalid_id) {
            if (m_slots[slot] == t) return false;
            slot = (slot + 1) & (slots - 1);
        }
        m_slots[slot] = t;
        return true;
    }

    static constexpr std::size_t scanned = 16;
    static constexpr std::size_t slots = 256;
    static constexpr std::size_t hashed = slots / 2;
    ElementId m_slots[slots];
    SmallVector<ElementId, 256> m_elements;
};

// True when some element of star(v) satisfies has(simplex): walks star(v) from v's anchor
// across faces containing v, as sxk::star does (complete on a valid mesh, whose vertex stars
// are face-connected), stopping at the first hit and allocating nothing for stars of up to 256
// elements. The flips' topological checks ("the new edge already exists") run on it.
template <class Has>
bool star_has(const Mesh& mesh, VertexId v, Has&& has) {
    const ElementId anchor = mesh.vertex_element(v);
    if (anchor == invalid_id) return false;
    StarList seen;
    seen.insert(anchor);
    const int k = mesh.element_vertex_count();
    for (std::size_t next = 0; next < seen.elements().size(); ++next) {
        const ElementId t = seen.elements()[next];
        const Simplex& tau = mesh.simplex(t);
        if (has(tau)) return true;
        for (int i = 0; i < k; ++i) {
            if (tau.vertex(i) == v) continue;  // the face opposite v does not contain v
            const ElementId n = mesh.neighbor(t, i);
            if (n != invalid_id) seen.insert(n);
        }
    }
    return false;
}

// True when the edge v-w is an edge of some element.
inline bool edge_exists(const Mesh& mesh, VertexId v, VertexId w) {
    return star_has(mesh, v, [&](const Simplex& tau) { return tau.contains(w); });
}

}  // namespace sxk::detail

namespace sxk {

// The operations' door to Mesh::replace_elements without its star walks: the only maker of
// Mesh::StarChecksProof (a private header: only the library's own operations in core/src/ops
// can use it).
//
// Mesh::replace_elements must refuse any edit that would represent a new face or element twice
// (invariant 7.4) or pinch a vertex star, and for an arbitrary edit that takes a walk of the
// star of every touched vertex. A local operation usually knows more. `replace` is
// replace_elements with every other check (ids, sizes, repeated and unknown vertices,
// duplicates among the new simplexes, faces twice among them) and all the bookkeeping (face
// reuse, matched pairs, boundary map, anchors, watchers); the caller guarantees instead:
//
//   (a) no new element and no new face that is not a face of an old element exists in an
//       element that stays, and
//   (b) no touched vertex star is pinched.
//
// The flips prove both from one check each. Their new elements and every new face that is not
// an old (hull) face contain the new edge or triangle (flip_23: edge pq; flip_32: triangle cde;
// flip_44: the new diagonal; flip_edge: edge cd), which they have checked is not in the mesh:
// that gives (a). Their old and new elements fill the same region with the same hull faces
// (every hull face is reused), and the new elements around each touched vertex are
// face-connected among themselves, so every path through star(v) across the old elements can be
// rerouted across the new ones: that gives (b).
class ProvenEdit {
public:
    static Outcome<std::vector<ElementId>> replace(Mesh& mesh, std::span<const ElementId> old_elements,
                                                   std::span<const Simplex> new_simplexes,
                                                   std::span<const int> labels,
                                                   std::span<const std::uint32_t> origins = {}) {
        return mesh.replace_elements(old_elements, new_simplexes, labels, origins, Mesh::StarChecksProof{});
    }
};

}  // namespace sxk
