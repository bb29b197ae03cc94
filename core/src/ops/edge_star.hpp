// The elements around an edge, and whether an edge exists, on the star walks of star_walk.hpp:
// on a triangle mesh round the fan of one end (an edge has at most two triangles), otherwise
// breadth first. Used by the splits, the 2D bisections, flip_edge.cpp and the tetrahedron
// bisection's plan.
#pragma once

#include <algorithm>
#include <vector>

#include "mesh_checks.hpp"
#include "small_vector.hpp"
#include "star_walk.hpp"
#include "sxk/mesh.hpp"

namespace sxk::detail {

// True when c-d is an edge of a triangle mesh; t0 is a triangle containing c. On a valid
// triangle mesh the star of c is a fan (a path or a cycle of triangles, each joined to the next
// by an edge containing c: faces lie in at most two triangles and stars are face-connected), so
// it is walked from t0 both ways round at once (walk_fan_from), stopping at the first triangle
// holding d: each triangle once, no list of the ones seen (edge_exists' breadth-first walk keeps
// one), and two independent chains of loads instead of one (the walk is bound by cache misses
// on the triangles). A star that is not a fan (only on an invalid mesh) falls back to
// edge_exists.
inline bool fan_has_edge(const Mesh& mesh, ElementId t0, VertexId c, VertexId d) {
    bool found = false;
    const bool fan = walk_fan_from(mesh, c, t0, [&](ElementId t) {
        return found = mesh.simplex(t).contains(d);
    });
    return found || (!fan && edge_exists(mesh, c, d));
}

// elements_with_edge (below) into `out`, without allocation. In a triangle mesh an edge has at
// most two triangles: the walk of a's fan (walk_fan: star(a) order) stops at the first one met,
// and the other is its neighbour across the edge, which that order meets later.
template <std::size_t N>
void edge_elements_into(const Mesh& mesh, VertexId a, VertexId b, SmallVector<ElementId, N>& out) {
    if (mesh.topological_dimension() != 2 || a == b) {  // a == b: the whole star, as before
        SmallVector<ElementId, N> around;
        star_into(mesh, a, around);
        for (const ElementId t : around)
            if (mesh.simplex(t).contains(b)) out.push_back(t);
        return;
    }
    ElementId found = invalid_id;
    const bool fan = walk_fan(mesh, a, [&](ElementId t) {
        if (!mesh.simplex(t).contains(b)) return false;
        found = t;
        return true;
    });
    if (!fan) {  // not a fan (an invalid mesh): breadth first
        SmallVector<ElementId, N> around;
        star_into(mesh, a, around);
        for (const ElementId t : around)
            if (mesh.simplex(t).contains(b)) out.push_back(t);
        return;
    }
    if (found == invalid_id) return;
    out.push_back(found);
    // the third vertex's face is the edge ab
    const Simplex& tau = mesh.simplex(found);
    for (int i = 0; i < 3; ++i)
        if (tau.vertex(i) != a && tau.vertex(i) != b) {
            const ElementId other = mesh.neighbor(found, i);
            if (other != invalid_id) out.push_back(other);
        }
}

// The elements containing both a and b (the star of the edge ab), in star(a) order.
inline std::vector<ElementId> elements_with_edge(const Mesh& mesh, VertexId a, VertexId b) {
    SmallVector<ElementId, 64> around;
    edge_elements_into(mesh, a, b, around);
    return {around.begin(), around.end()};
}

// The number of fans the elements `around` the edge ab fall into: chains of elements, each
// joined to the next by a face containing a and b. A valid mesh may have several (two
// tetrahedra touching only along an edge, each vertex star joined through other elements); a
// split of the edge would then pinch the new vertex's star.
template <class Elements>
int edge_fans(const Mesh& mesh, const Elements& around, VertexId a, VertexId b) {
    SmallVector<ElementId, 64> reached;
    int fans = 0;
    for (const ElementId start : around) {
        if (std::find(reached.begin(), reached.end(), start) != reached.end()) continue;
        ++fans;
        reached.push_back(start);
        for (std::size_t next = reached.size() - 1; next < reached.size(); ++next) {
            const ElementId t = reached[next];
            const Simplex& tau = mesh.simplex(t);
            for (int i = 0; i < tau.count(); ++i) {
                if (tau.vertex(i) == a || tau.vertex(i) == b) continue;  // that face lacks a or b
                const ElementId n = mesh.neighbor(t, i);
                if (n != invalid_id && std::find(reached.begin(), reached.end(), n) == reached.end())
                    reached.push_back(n);
            }
        }
    }
    return fans;
}

}  // namespace sxk::detail
