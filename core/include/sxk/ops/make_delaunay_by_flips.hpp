// Lawson's flip algorithm: turn any triangulation of a planar point set into the Delaunay
// triangulation by flipping illegal edges (thesis §5.2.1: "The Delaunay triangulation can be
// constructed by starting with an arbitrary triangulation and flipping illegal edges until none
// are left. The final result maximizes the minimum element angle.").
//
//          c                       c        edge a-b is illegal when d lies strictly inside
//        /   \                   / | \      the circle through a, b, c (exact incircle);
//      /       \               /   |   \    the two triangles then always form a convex
//     a ------- b    ---->    a    |    b   quadrilateral and the flipped diagonal c-d is
//      \       /               \   |   /    legal. The four hull edges a-d, d-b, b-c, c-a
//        \   /                   \ | /      may have become illegal and are checked again.
//          d                       d
//
#pragma once

#include <cstddef>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/predicates.hpp"

namespace sxk {

// True when `edge` is on the boundary, or when the vertex d opposite it in the mate's element
// does not lie strictly inside the circumcircle of the edge's element <a,b,c> (exact incircle in
// the chosen positions). Cocircular quadrilaterals are locally Delaunay both ways.
// Planar triangle meshes (topological and ambient dimension 2) whose two triangles at `edge` are
// counter-clockwise; on a triangle surface in space the two triangles are unfolded about the edge
// (exact unfolded_incircle, sxk/predicates.hpp: the angles opposite the edge sum to more than pi
// when it is not). Returns true for anything else (nothing to flip there).
SXK_API bool is_locally_delaunay(const Mesh& mesh, FaceId edge,
                                 Positions positions = Positions::deformed);

// Lawson's algorithm with a stack of edges: every interior edge is checked once, each
// non-locally-Delaunay edge is flipped (flip_edge) and the four hull edges of the flip are
// pushed again. Returns the number of flips.
//   Before: planar triangle mesh, every triangle strictly counter-clockwise in `positions`.
//   After: every interior edge is locally Delaunay in `positions`, hence (Delaunay's lemma) the
//   triangulation is Delaunay on its vertices when its domain is convex — except at
//   constraints flip_edge refuses to flip: edges between triangles of different labels
//   (material interfaces) and edges carrying a face label stay, and the result is constrained
//   Delaunay with respect to them; vertex positions,
//   labels of untouched elements and all hull FaceIds of each flip are kept. Flips happen only
//   when incircle is strictly positive, so cocircular input terminates (each flip strictly
//   lowers the lifted surface) and is left as it is.
//   Only `positions` decide what is Delaunay. A flip that would make a triangle inverted or
//   flat in the other set of positions (when the two differ) is not made: that edge stays, like
//   a constraint, so no triangle is ever inverted in either set.
// Refusals (mesh untouched): not planar; a triangle not strictly counter-clockwise in
// `positions` ("make_delaunay_by_flips: element 7 is not counter-clockwise ...").
SXK_API Outcome<std::size_t> make_delaunay_by_flips(Mesh& mesh,
                                                    Positions positions = Positions::deformed);

}  // namespace sxk
