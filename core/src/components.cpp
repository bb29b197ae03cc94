// connected_components with Boost's disjoint sets (a library's, not a hand-written union-find):
// one set per live element, joined across every pair of neighbours.
#include "sxk/components.hpp"

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>

namespace sxk {

Components connected_components(const Mesh& mesh) {
    Components result;
    const std::size_t capacity = mesh.element_capacity();
    result.element_component.assign(capacity, invalid_id);
    if (mesh.element_count() == 0) return result;

    // Union-find over the mated faces (Boost's disjoint_sets, the structure behind Boost.Graph's
    // incremental_components): no graph to build. The adjacency_list this replaces spent most of
    // its time constructing the graph: 40% of `sxk info` on the femur-1226k went to it. The sets
    // are indexed by element id: a dead id (a hole in the pools) stays a set of its own and is
    // never read, which costs less than renumbering the live elements densely (two more arrays
    // as long as the mesh, each page of them zeroed by the kernel on first touch).
    std::vector<std::uint32_t> rank(capacity, 0), parent(capacity);
    boost::disjoint_sets<std::uint32_t*, std::uint32_t*> sets(rank.data(), parent.data());
    for (std::uint32_t i = 0; i < capacity; ++i) sets.make_set(i);
    // the neighbour cache (Mesh::neighbor) sits in the element record: no visit to the face pool
    const int k = mesh.element_vertex_count();
    for (ElementId t : elements(mesh)) {
        for (int i = 0; i < k; ++i) {
            const ElementId neighbour = mesh.neighbor(t, i);
            if (neighbour != invalid_id && neighbour < t) sets.union_set(t.value(), neighbour.value());  // each pair once
        }
    }
    // components numbered by their smallest element id: the first element met of each set; the
    // ranks are done with, so their array holds each root's number
    std::vector<std::uint32_t>& number = rank;
    std::fill(number.begin(), number.end(), invalid_id);
    for (ElementId t : elements(mesh)) {
        const std::uint32_t root = sets.find_set(t.value());
        if (number[root] == invalid_id) number[root] = static_cast<std::uint32_t>(result.count++);
        result.element_component[t] = number[root];
    }
    return result;
}

}  // namespace sxk
