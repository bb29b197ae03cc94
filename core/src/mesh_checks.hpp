// Argument checks shared by the edit primitives.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "small_vector.hpp"
#include "star_walk.hpp"
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

// True when some element of star(v) satisfies has(simplex), stopping at the first hit
// (for_each_in_star, star_walk.hpp: no allocation for stars of up to 128 elements). The flips'
// topological checks ("the new edge already exists") run on it.
template <class Has>
bool star_has(const Mesh& mesh, VertexId v, Has&& has) {
    StarList seen;
    return for_each_in_star(mesh, v, mesh.vertex_element(v), seen,
                            [&](std::size_t, ElementId, const Simplex& tau) { return has(tau); });
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
//
// The splits (ops/split_parents.hpp) and AMP's replay of a conforming refinement
// (ops/tet_bisection_amp.cpp, which checks the edges it bisects for two fans first) prove both
// from their new vertex or vertices, which no element had.
//
// `change` is change_elements on the same terms. Dissection (ops/dissect.cpp) proves both. (a)
// Every element it changes gets a copy of a split vertex, a vertex in no element before, so no
// changed element and no face holding a copy exists in an element that stays; a face without a
// copy keeps the vertices and orientation it had, and a valid mesh has it only there. (b) Two
// elements sharing a face that is not cut are in the same (x, C)-class of every vertex x of that
// face, so both get the same substitute for each of its vertices and stay mates: the classes,
// the new stars, are face-connected by construction, and the star of a vertex outside the cut
// (none of its faces is cut) keeps every adjacency it had.
class ProvenEdit {
public:
    static Outcome<Done> change(Mesh& mesh, std::span<const ElementSubstitution> substitution) {
        return mesh.change_elements(substitution, Mesh::StarChecksProof{});
    }
    static Outcome<std::vector<ElementId>> replace(Mesh& mesh, std::span<const ElementId> old_elements,
                                                   std::span<const Simplex> new_simplexes,
                                                   std::span<const int> labels,
                                                   std::span<const std::uint32_t> origins = {}) {
        return mesh.replace_elements(old_elements, new_simplexes, labels, origins, Mesh::StarChecksProof{});
    }
};

}  // namespace sxk
