// Face split of a tetrahedral mesh: a new vertex m inside the triangle abc, and each of the (one
// or two) tetrahedra sharing abc replaced by three around m (thesis §3.2 subdivision; the
// connectivity edit is §7.3 replace-elements). For triangle meshes a face is an edge: use
// split_edge.
//
//              p                              p
//             /|\                            /|\         <abc,p> becomes <mbc,p>, <amc,p>,
//            / | \                          / | \        <abm,p> (a -> m, b -> m, c -> m);
//           /  |  \       split_face       /  |  \       the same below with apex q. The
//          a---|---c     ----------->     a---m---c      children keep the parent's
//           \  b  /                        \  b  /       orientation (one vertex substituted).
//            \ | /                          \ | /
//             \|/                            \|/        m = wa a + wb b + wc c in both
//              q                              q         position sets (default: centroid)
//
// Contract.
//   Before: mesh is tetrahedral; f is a face; weights (for the canonical vertices a < b < c of
//   face_simplex(f)) are all > 0; they are divided by their sum.
//   After (on success): one new vertex m = vertex_count()-1; face_element(f) and, if f is
//   interior, face_element(mate(f)) are replaced by three children each (result.elements: first
//   the children of face_element(f) for a -> m, b -> m, c -> m, then those of the mate's
//   element), each with its parent's label. ONE replace_elements call; the hull faces of the
//   parents (those other than abc) keep their FaceIds.
//   Inverse: collapse_edge(mesh, m, a) restores the element vertex sets (m stays, in no element).
//   Vertex attributes: m gets every attribute interpolated with the same weights as its
//   position (Mesh::add_interpolated_vertex).
//   Face labels: a label on abc passes to its three pieces.
//   Transaction: a refusal by replace_elements after m was added (impossible on a valid mesh)
//   removes m again (Mesh::remove_last_vertex), so no refusal leaves a vertex behind.
// Refusals (mesh untouched, no vertex added), reasons begin with "split_face: ":
//   not a tetrahedral mesh; f not a face; a weight not > 0; a child flat or of the other
//   orientation than its parent in either position set (rounding of m only), except the
//   children of parents containing all of options.vanishing_with (split_result.hpp).
#pragma once

#include <array>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/split_result.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

SXK_API Outcome<SplitResult> split_face(Mesh& mesh, FaceId f,
                                        std::array<double, 3> weights = {1.0, 1.0, 1.0},
                                        const SplitOptions& options = {});

}  // namespace sxk
