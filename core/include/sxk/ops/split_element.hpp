// Element split (stellar subdivision) of a triangle or tetrahedral mesh: a new vertex m inside
// element T and T replaced by the d+1 elements joining m to T's faces (thesis §3.2
// subdivision; connectivity edit by §7.3 replace-elements).
//
//            c                        c
//           / \                      /|\            <a,b,c> becomes <m,b,c>, <a,m,c>, <a,b,m>
//          /   \     split_element  / | \           (vertex j -> m for j = 0..d, canonical
//         /  T  \   -------------> /  m  \          order): one vertex substituted, so each
//        /       \                / /   \ \         child keeps T's orientation. In 3D the
//       a ------- b              a ------- b        four children join m to T's four faces.
//
// Contract.
//   Before: t is an element; weights is empty (centroid) or has d+1 entries, all > 0, for the
//   canonical vertices of simplex(t); they are divided by their sum.
//   After (on success): one new vertex m = vertex_count()-1 at the weighted point in both
//   position sets; t is gone; result.elements holds the d+1 children in the order above, all
//   with t's label. ONE replace_elements call; the d+1 faces of t keep their FaceIds (they are
//   the outer faces of the children) and so their mates and boundary status.
//   Inverse: collapse_edge(mesh, m, v) for any vertex v of t restores the element (m stays, in
//   no element).
//   Vertex attributes: m gets every attribute interpolated with the same weights as its
//   position (Mesh::add_interpolated_vertex).
//   Transaction: a refusal by replace_elements after m was added (impossible on a valid mesh)
//   removes m again (Mesh::remove_last_vertex), so no refusal leaves a vertex behind.
// Refusals (mesh untouched, no vertex added), reasons begin with "split_element: ":
//   t not an element; wrong number of weights; a weight not > 0; a child flat or of the other
//   orientation than t in either position set (rounding of m only).
#pragma once

#include <span>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/split_result.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

SXK_API Outcome<SplitResult> split_element(Mesh& mesh, ElementId t,
                                           std::span<const double> weights = {});

}  // namespace sxk
