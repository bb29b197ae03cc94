// Node removal in a triangle mesh, planar or a surface in space (thesis §5.3.1, Fig. 5.10): the
// interior vertex v and its n triangles are replaced by n-2 triangles on the polygon formed by v's
// link.
//
//        w3 ----- w2                 w3 ----- w2        The thesis flips "ears" (two triangles
//       /  \     /  \               /  `.      \        around v whose angles opposite v sum to
//      /    \   /    \             /     `.     \       less than pi) until v has degree 3,
//    w4 ---- v ----- w1    --->  w4        `.    w1     then replaces the last three triangles
//      \    /   \    /             \         `.  /      by one and flips back the edges that
//       \  /     \  /               \          `/       violate the empty-circle criterion.
//        w5 ----- w0                 w5 ----- w0
//                                   (v stays, in no element)
//
// Flipping the ear at w_i (edge v-w_i) cuts the triangle (w_{i-1}, w_i, w_{i+1}) off the link
// polygon; v keeps seeing the rest, so the polygon stays star-shaped from v. Here the flips are
// made on a scratch copy of the link, not in the mesh: the ears are clipped there, the result
// is made locally Delaunay there (Lawson flips restricted to the diagonals of the hole), and the
// mesh is edited by ONE replace_elements call of star(v) -> the new triangles. The operation is
// therefore exactly transactional and watchers see one edit.
//
// Ears are decided with exact orient2d in BOTH the reference and the deformed positions: the
// ear at w_i is cut when (w_{i-1}, w_i, w_{i+1}) turns strictly counter-clockwise (the angle at
// w_i of the quadrilateral v, w_{i-1}, w_i, w_{i+1} is below pi: alpha_{i+1} + beta_i < pi) and
// no other vertex of the remaining polygon lies in the closed ear triangle. Thesis ears (the
// chord w_{i-1}-w_{i+1} also passes strictly on the far side of v, so flip_edge of v-w_i would
// be valid) are preferred; when none is left — e.g. v at the crossing of the diagonals of a
// square link, where every flip of v-w_i would give a flat triangle — any ear of the polygon is
// cut (two-ears theorem: a simple polygon always has one). A polygon whose ears differ between
// the two position sets can leave no common ear: that is refused.
//
// Boundary vertices. A vertex on a STRAIGHT piece of boundary (v exactly on the open segment
// between its two boundary neighbours w_n and w_0, by exact orient2d, in both position sets) is
// removed the same way: its link is the path w_0..w_n, closed by the new boundary edge w_n-w_0
// that passes where v was, and the polygon is ear-clipped into n-1 triangles; the domain does
// not change. A face label carried by the two old boundary edges moves to the new one (they
// must agree). Any other boundary vertex is refused: removing it would change the domain.
//
// Contract.
//   Before: planar triangle mesh (topological and ambient dimension 2); v an interior vertex
//   (its link is a closed cycle) or a vertex on a straight piece of boundary, whose triangles
//   are strictly counter-clockwise in both position sets and all carry the same label.
//   After (on success): star(v) is gone; n-2 new triangles (n-1 on the boundary), strictly
//   counter-clockwise in both position sets, cover exactly the same region; every diagonal of
//   the hole is locally Delaunay (in `positions`) where a flip is valid in both position sets.
//   If the mesh was Delaunay (in `positions`, general position) and v interior, it is Delaunay
//   after: removing a vertex only changes the triangles of its star. v stays as a vertex in no
//   element (Mesh has no vertex deletion); vertex ids, positions, the boundary (but for
//   w_n-v-w_0 -> w_n-w_0) and every element and face outside star(v) are untouched; hull edges
//   of the hole keep their FaceIds (face reuse). The new triangles carry the label of the star.
//   Returns the new element ids.
//   Inverse: none exact (the hole's triangulation is chosen), but split_element of a new
//   triangle containing v's old position, followed by flips, can rebuild a star.
// Refusals (mesh untouched), every reason begins with "remove_node: ":
//   "needs a triangle mesh (topological dimension 2)";
//   "7 is not a vertex"; "vertex 7 is in no element";
//   "vertex 7 is on the boundary and the boundary is not straight there (its removal would
//   change the domain)";
//   "the boundary edges at vertex 7 carry different face labels (3 and none)";
//   "the edge +<7,9> at vertex 7 carries face label 6 (a constraint)" (an interior edge at v with
//   a label would vanish);
//   "element 4 of the star of vertex 7 is not counter-clockwise in the reference positions";
//   "the star of vertex 7 mixes element labels 1 and 2" (the lowest and the highest; removing
//   v would move a material interface);
//   "no ear of the link of vertex 7 is valid in both the reference and the deformed positions";
//   on a surface, "the triangles that would replace the star of vertex 7 fold over each other";
//   and a replace_elements refusal (a new triangle already elsewhere, as removing a vertex of a
//   tetrahedron's surface would make its fourth face twice: Fig. 5.9; only in meshes that are not
//   embedded in the plane).
//
// Surfaces in space. There is no counter-clockwise: a triangle is proper when its corners are not
// collinear (exactly, in both position sets). Ears are cut in the thesis' order of preference,
// least angle sum at w_i first (a choice, in doubles: the thesis calls the 3D scheme heuristic),
// among those that are proper, whose new edge w_{i-1}-w_{i+1} is not an edge of the mesh already
// (Fig. 5.9), and that face the way v's triangles on their link edges face (normals' dot product
// strictly positive, exactly); the new triangles on either side of a chord of the hole must face
// one way too. The hole's diagonals are made Delaunay by the unfolded criterion (unfolded_incircle:
// the two triangles of an edge unfolded about it), each flip only when it does not fold the
// surface, and at most 8 n^2 flips (the thesis does not know that the criterion terminates on a
// surface). A vertex on a straight piece of boundary (exactly collinear) is removed as in the plane.
#pragma once

#include <vector>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/predicates.hpp"

namespace sxk {

// `positions`: where the empty-circle criterion of the final Lawson flips is evaluated
// (validity of every triangle is always checked in both position sets).
SXK_API Outcome<std::vector<ElementId>> remove_node(Mesh& mesh, VertexId v,
                                                    Positions positions = Positions::deformed);

}  // namespace sxk
