// Thesis §6.5 simple-bisect(p, q): the edge pq, the hypotenuse of each of its (one or two)
// triangles, is split at its midpoint n; each triangle f becomes f[p := n] and f[q := n].
//
//          c                          c
//         /|\                        /|\          the hypotenuse pq of <p,q,c> and <q,p,d>
//       /  |  \                    / 1|0 \        (a right angle at c and at d on the
//     /    |    \                /    |    \      thesis' meshes) gets n; the four halves
//    p     |     q   ---->     p ---- n ---- q    are congruent to each other
//     \    |    /                \    |    /
//       \  |  /                    \ 3|2 /
//         \|/                        \|/
//          d                          d
//
// The hypotenuse of a triangle is its longest edge in the REFERENCE positions, ties broken by
// vertex ids (the smaller id pair wins), so it is a property of the edge that both triangles
// sharing it agree on. On meshes of right-angled triangles it is the hypotenuse, opposite the
// newest vertex (newest-vertex bisection); on general meshes it is the longest edge (Rivara).
//
// Contract.
//   Before: triangle mesh (planar, or a surface in 3D); pq an edge that is the hypotenuse of
//   every triangle containing it.
//   After (on success): exactly split_edge(mesh, p, q, 0.5): one new vertex, both positions at
//   the midpoint (every attribute the split interpolates follows), children with their
//   parent's label, one replace_elements call. Returns split_edge's result.
//   Inverse: collapse_edge(mesh, n, p) restores the element vertex sets.
// Refusals (mesh untouched), reasons begin with "simple_bisect: ":
//   "needs a triangle mesh (topological dimension 2)"; "7 is not a vertex"; "the two ends are
//   the same vertex"; "+<p,q> is not an edge"; "+<p,q> is not the hypotenuse of element 4 (its
//   hypotenuse is +<a,b>)" — bisect_edge bisects such an edge; and split_edge's refusals (a
//   flat or inverted child, only for nearly flat triangles) as "simple_bisect: split_edge: ...".
#pragma once

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/split_result.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

SXK_API Outcome<SplitResult> simple_bisect(Mesh& mesh, VertexId p, VertexId q);

}  // namespace sxk
