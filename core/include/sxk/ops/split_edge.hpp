// Edge split (bisection when t = 1/2) of a triangle or tetrahedral mesh: a new vertex m on the
// edge ab, and every element containing ab replaced by its two halves (thesis §3.2: subdivision
// before cutting; the connectivity edit is §7.3 replace-elements).
//
//            c                           c
//           / \                         /|\          2D: each triangle <a,b,c> around ab
//          /   \                       / | \         becomes <m,b,c> (a -> m) and <a,m,c>
//         /  T  \        split_edge   / T1|T0\       (b -> m); in 3D each tetrahedron around
//        a ------ b     ---------->  a----m----b     ab becomes its two halves the same way.
//         \  U  /                     \ U1|U0/       Substituting one vertex of the parent
//          \   /                       \ | /         simplex keeps its orientation, so the
//           \ /                         \|/          children are positive when it is.
//            d                           d
//                    m = (1-t) a + t b, in the reference and in the deformed positions
//
// Contract.
//   Before: a and b are the ends of an edge of some element; 0 < t < 1.
//   After (on success): one new vertex m = vertex_count()-1 at (1-t)a + tb in both position
//   sets; each element T containing ab is gone and replaced by T[a->m] and T[b->m] (result
//   .elements lists, per parent in star(a) order, first T[a->m] then T[b->m]), both with T's
//   label. ONE Mesh::replace_elements call (a transaction); faces not containing ab keep their
//   FaceIds (face reuse). Boundary edges split too (the boundary keeps its shape: m lies on ab).
//   Inverse: collapse_edge(mesh, m, a) (or onto b) restores the element vertex sets and
//   orientations: collapse_edge(split_edge(e)) == e up to element and face ids; m stays as a
//   vertex in no element.
//   Vertex attributes: m gets every attribute interpolated with the weights 1-t, t of a, b,
//   like its position (Mesh::add_interpolated_vertex).
//   Face labels: a labelled face containing ab passes its label to its two halves.
//   Transaction: a refusal by replace_elements after m was added (impossible on a valid mesh)
//   removes m again (Mesh::remove_last_vertex), so no refusal leaves a vertex behind.
// Refusals (mesh untouched, no vertex added), reasons begin with "split_edge: ":
//   a or b is not a vertex; a == b; ab is not an edge; t not in the open interval (0,1); the
//   elements around ab fall into fans that share only the edge ("the tetrahedra around {a,b}
//   are 2 fans joined only at the edge: the new vertex's star would be pinched", pinched_star:
//   a valid mesh may have such an edge, as a mesh pinched at a vertex may not); a child
//   that would be flat or of the other orientation than its parent in either position set
//   (possible only by rounding of m for nearly flat parents), except the children of parents
//   containing all of options.vanishing_with (split_result.hpp), which the caller removes next.
#pragma once

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/split_result.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

SXK_API Outcome<SplitResult> split_edge(Mesh& mesh, VertexId a, VertexId b, double t = 0.5,
                                        const SplitOptions& options = {});

}  // namespace sxk
