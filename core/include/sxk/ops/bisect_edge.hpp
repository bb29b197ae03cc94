// Thesis §6.5 bisect(e): bisect the edge pq, first bisecting the hypotenuses of its neighbours
// when pq is not their hypotenuse, so the mesh stays conforming (no hanging vertex) and, on a
// mesh of right-angled triangles, every triangle stays congruent to a starting one.
//
//     procedure bisect(e):
//       let f1, f2 be incident with e
//       if f1 != null and e != hypotenuse(f1): bisect(hypotenuse(f1))
//       if f2 != null and e != hypotenuse(f2): bisect(hypotenuse(f2))
//       simple-bisect(e)
//
//   Fig. 6.7 on a grid of right isosceles triangles, bisect(1-4):
//
//   3 ----- 4 ----- 5          3 ----- 4 ----- 5
//   |     / |     / |          | \   / | \   / |     1-4 is a leg of both its triangles, so
//   |   /   |   /   |   --->   |   x - m - y   |     their hypotenuses 0-4 and 1-5 are
//   | /     | /     |          | /   \ | /   \ |     bisected first (x, y), then 1-4 (m);
//   0 ----- 1 ----- 2          0 ----- 1 ----- 2     returns {x, y, m}, midpoint m
//
// The hypotenuse rule is simple_bisect's (longest edge in the reference positions, ties by
// vertex ids): on general meshes this is Rivara's longest-edge bisection. The recursion runs
// with an explicit stack (no call depth), and each hypotenuse pushed is strictly longer (in the
// rule's total order) than the edge below it, so the stack never cycles.
//
// Transaction. All splits are first PLANNED on a scratch overlay of the mesh (the triangles
// they create, their midpoints computed with split_edge's arithmetic, every child checked for
// flatness/inversion in both position sets as split_edge will); only when the whole plan
// stands is it replayed, one split_edge per planned bisection. split_edge refuses only what the
// plan already checked, so a replay never stops half-way; a refusal (a flat or inverted child,
// which needs a (nearly) flat triangle on the propagation path) leaves the mesh untouched.
//
// Contract.
//   Before: triangle mesh (planar, or a surface in 3D); pq an edge.
//   After (on success): pq and every edge split on the way are bisected; every new vertex sits
//   at the midpoint of its edge in both positions; children inherit labels; the mesh is
//   conforming (validate() holds). Returns the new vertices in creation order (ids
//   vertex_count() before the call, +1, ...) and the midpoint of pq (the last one).
// Refusals (mesh untouched), reasons begin with "bisect_edge: ":
//   "needs a triangle mesh (topological dimension 2)"; "7 is not a vertex"; "the two ends are
//   the same vertex"; "+<p,q> is not an edge"; "new element +<a,b,c> would be flat in the
//   deformed positions" (or inverted; as split_edge).
#pragma once

#include <vector>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

struct BisectEdgeResult {
    VertexId midpoint = invalid_id;  // the new vertex on pq
    std::vector<VertexId> vertices;  // all new vertices, in creation order; back() == midpoint
};

SXK_API Outcome<BisectEdgeResult> bisect_edge(Mesh& mesh, VertexId p, VertexId q);

}  // namespace sxk
