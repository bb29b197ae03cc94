// The walk of a vertex star, for every part of the library that needs one: sxk::star and
// collect_star (traversal.cpp), the flips' "does this edge exist" (star_has, mesh_checks.hpp),
// the invariant 7.4 and star-connectivity checks of the edit primitives (replace_elements.cpp,
// star_pieces.cpp), validate's star connectivity, and the operations' scratch stars (star_into).
//
// star(v) is found from v's anchor by crossing faces that contain v: a valid mesh has
// face-connected stars (thesis §7.3, star(v) is (v, {})-connected), so the walk meets every
// element containing v. The walks are on the hot path of flips and splits (docs/performance.md
// "tet_flips", "What changed" 1-2): nothing here allocates for stars of up to 128 elements.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "small_vector.hpp"
#include "sxk/mesh.hpp"

namespace sxk::detail {

// The elements met by a star walk, in the order met, with the position of each: the walk's
// queue and its "seen already?" set at once. Short lists (2D stars) are scanned and never pay
// for clearing a table; from `scanned` elements on an open-addressing table of positions (in
// place, 256 slots: a 3D star has ~25 elements, each reached from up to three neighbours) costs
// one probe instead of a scan, and it moves to the heap, doubling, beyond half full, so that the
// stars of large edits (an AMP replay replaces thousands of elements around vertices with
// hundreds in their star) cost linear, not quadratic, time.
class StarList {
public:
    StarList() = default;
    StarList(const StarList&) = delete;
    StarList& operator=(const StarList&) = delete;

    std::size_t size() const { return m_elements.size(); }
    ElementId operator[](std::size_t i) const { return m_elements[i]; }
    const ElementId* begin() const { return m_elements.begin(); }
    const ElementId* end() const { return m_elements.end(); }
    operator std::span<const ElementId>() const { return m_elements; }

    // The position of t in the list; t is appended (at position size()) when it is not there.
    std::size_t insert(ElementId t) {
        const std::size_t n = m_elements.size();
        if (n < scanned) {
            const ElementId* found = std::find(m_elements.begin(), m_elements.end(), t);
            if (found != m_elements.end()) return static_cast<std::size_t>(found - m_elements.begin());
            m_elements.push_back(t);
            if (n + 1 == scanned) index(inline_slots);
            return n;
        }
        std::uint32_t& slot = slot_of(t);
        if (slot != empty) return slot;
        slot = static_cast<std::uint32_t>(n);
        m_elements.push_back(t);
        if (2 * m_elements.size() > m_slot_count) index(2 * m_slot_count);
        return n;
    }

private:
    static constexpr std::size_t scanned = 16;
    static constexpr std::size_t inline_slots = 256;
    static constexpr std::uint32_t empty = ~std::uint32_t{0};

    std::uint32_t* slots() { return m_heap_slots.empty() ? m_inline_slots : m_heap_slots.data(); }
    // The slot holding t's position, or the empty slot where it goes.
    std::uint32_t& slot_of(ElementId t) {
        std::uint32_t* table = slots();
        const std::size_t mask = m_slot_count - 1;
        for (std::size_t slot = (t * 2654435761u) & mask;; slot = (slot + 1) & mask)
            if (table[slot] == empty || m_elements[table[slot]] == t) return table[slot];
    }
    // A table of `count` slots (a power of two) holding every listed element.
    void index(std::size_t count) {
        if (count > inline_slots) m_heap_slots.assign(count, empty);
        else std::fill(std::begin(m_inline_slots), std::end(m_inline_slots), empty);
        m_slot_count = count;
        for (std::size_t i = 0; i < m_elements.size(); ++i)
            slot_of(m_elements[i]) = static_cast<std::uint32_t>(i);
    }

    SmallVector<ElementId, inline_slots> m_elements;
    std::uint32_t m_inline_slots[inline_slots];  // raw until the list reaches `scanned`
    std::vector<std::uint32_t> m_heap_slots;
    std::size_t m_slot_count = 0;
};

// Called for every face i of an element containing v that contains v too; nothing by default.
struct IgnoreCrossings {
    void operator()(std::size_t, const Simplex&, int, ElementId, std::size_t) const {}
};

// Walks star(v) breadth first from `start` (an element containing v; nothing when invalid_id)
// across the faces that contain v, in face index order: the order sxk::star lists. The elements
// go into `list`, a StarList (empty, or holding the walk's own elements only) or a list with the
// same size(), operator[] and insert (validate's, which marks the elements of the whole mesh).
//
// visit(position, t, tau) is called for each element t = list[position] (tau its simplex) as the
// walk reaches it, in list order; returning true stops the walk, and then for_each_in_star
// returns true. After visit(t), cross(position, tau, i, n, n_position) is called for every face
// i of t that contains v, with n = the neighbour across it (invalid_id on the boundary) and, when
// n is an element, its position in the list (it is listed by then).
template <class List, class Visit, class Cross = IgnoreCrossings>
bool for_each_in_star(const Mesh& mesh, VertexId v, ElementId start, List& list, Visit&& visit,
                      Cross&& cross = {}) {
    if (start == invalid_id) return false;
    list.insert(start);
    const int k = mesh.element_vertex_count();
    for (std::size_t next = 0; next < list.size(); ++next) {
        const ElementId t = list[next];
        const Simplex& tau = mesh.simplex(t);
        if (visit(next, t, tau)) return true;
        for (int i = 0; i < k; ++i) {
            if (tau.vertex(i) == v) continue;  // the face opposite v does not contain v
            const ElementId n = mesh.neighbor(t, i);
            cross(next, tau, i, n, n == invalid_id ? std::size_t{0} : list.insert(n));
        }
    }
    return false;
}

// star(v) of a valid mesh, walked from `start`, into `list`.
inline void list_star(const Mesh& mesh, VertexId v, ElementId start, StarList& list) {
    for_each_in_star(mesh, v, start, list, [](std::size_t, ElementId, const Simplex&) { return false; });
}

// ---- triangle meshes: round the fan ---------------------------------------------------------
// Triangle meshes: star(v) in exactly sxk::star's order, visited by two walks round v's fan
// instead of a breadth-first search. A breadth-first walk from the anchor over a fan (a path or
// a cycle of triangles joined by edges containing v, which every vertex of a valid triangle mesh
// has) meets the anchor, then one triangle per branch and level, the branch through the
// anchor's lower face index first; two walks, one per branch, advanced level by level, meet the
// triangles in that order without a list of the ones seen, and their loads are two independent
// chains (the walk is bound by cache misses). visit(t) returns true to stop. Returns false,
// having visited a prefix of star(v) only, when v's star is not a fan (an invalid mesh): the
// caller then walks it breadth first.
// walk_fan_from starts at any triangle `anchor` of star(v) instead of v's anchor (the order is
// then breadth first from that triangle).
template <class Visit>
bool walk_fan_from(const Mesh& mesh, VertexId v, ElementId anchor, Visit&& visit) {
    if (anchor == invalid_id) return true;
    if (visit(anchor)) return true;
    const Simplex& first = mesh.simplex(anchor);
    // one walk per face of the anchor containing v, in face index order: at triangle t it leaves
    // across the edge opposite x (x in t, x != v)
    struct Walk {
        ElementId t;
        VertexId x;
        ElementId next = invalid_id;
    };
    std::array<Walk, 2> walks{};
    for (int j = 0, w = 0; j < 3; ++j)
        if (first.vertex(j) != v && w < 2) walks[static_cast<std::size_t>(w++)] = {anchor, first.vertex(j)};
    for (std::size_t level = 0; walks[0].t != invalid_id || walks[1].t != invalid_id; ++level) {
        if (level > mesh.element_count()) return false;
        for (Walk& w : walks) {
            if (w.t == invalid_id) continue;
            const int i = mesh.simplex(w.t).index(w.x);
            if (i < 0) return false;
            w.next = mesh.neighbor(w.t, i);
        }
        const bool both = walks[0].t != invalid_id && walks[1].t != invalid_id;
        // a cycle of odd length closes when a walk steps onto the other's triangle, one of even
        // length on a triangle both step onto (met once, by the first walk)
        if (both && (walks[0].next == walks[1].t || walks[1].next == walks[0].t)) return true;
        if (both && walks[0].next == walks[1].next && walks[0].next != invalid_id) {
            (void)visit(walks[0].next);
            return true;
        }
        for (Walk& w : walks) {
            if (w.t == invalid_id) continue;
            if (w.next == invalid_id) {  // the boundary: this branch is done
                w.t = invalid_id;
                continue;
            }
            if (w.next == anchor) return false;  // a branch came round alone: not a fan
            if (visit(w.next)) return true;
            // next was entered across {v, y}, y the vertex of t other than v and x: leave it
            // across the edge opposite y
            const Simplex& tau = mesh.simplex(w.t);
            for (int j = 0; j < 3; ++j)
                if (tau.vertex(j) != v && tau.vertex(j) != w.x) {
                    w.x = tau.vertex(j);
                    break;
                }
            w.t = w.next;
        }
    }
    return true;
}

template <class Visit>
bool walk_fan(const Mesh& mesh, VertexId v, Visit&& visit) {
    return walk_fan_from(mesh, v, mesh.vertex_element(v), std::forward<Visit>(visit));
}

// star(v) in the order sxk::star lists it (breadth first from v's anchor, faces in index order),
// appended to `out`: round the fan on a triangle mesh, for_each_in_star otherwise (and on a
// triangle mesh whose star is not a fan). No allocation for stars of up to N elements.
template <std::size_t N>
void star_into(const Mesh& mesh, VertexId v, SmallVector<ElementId, N>& out) {
    const ElementId anchor = mesh.vertex_element(v);
    if (anchor == invalid_id) return;
    const std::size_t first = out.size();
    if (mesh.topological_dimension() == 2) {
        if (walk_fan(mesh, v, [&](ElementId t) {
                out.push_back(t);
                return false;
            }))
            return;
        out.resize(first);  // not a fan: breadth first below
    }
    StarList around;
    list_star(mesh, v, anchor, around);
    for (const ElementId t : around) out.push_back(t);
}

}  // namespace sxk::detail
