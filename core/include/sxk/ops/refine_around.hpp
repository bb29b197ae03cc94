// Thesis §6.5 refine-around(x, h): bisect until the triangle containing x has a hypotenuse no
// longer than h (Fig. 6.8).
//
//     procedure refine-around(x, h)            +-----------+        +-----+-----+
//       t <- triangle containing x             |         / |        |\    |   / |
//       if |hypotenuse(t)| > h:                |       /   |  --->  |  \  | /   |
//         bisect(hypotenuse(t))                |     /     |        +----+*+----+
//         refine-around(x, h)                  |   /    *  |        |   / |\    |
//                                              | /         |        | /   |  \  |
//                                              +-----------+        +-----+-----+
//                                            (* = x; bisections propagate to keep conformity)
//
// Triangle meshes in the plane only (topological and ambient dimension 2); tetrahedral meshes
// have their own newest-vertex bisection, refine_around_tetrahedra. Lengths, the hypotenuse
// rule (see simple_bisect.hpp) and x are in the REFERENCE positions; x's z is ignored.
//
// Point location (sxk/locate.hpp): with a SpatialIndex (reference positions) a walk from `hint`,
// then the index's rtree: O(log n) whatever the hint. Without one, locate_triangle: the
// stochastic visibility walk from `hint` when it is an element, else from the nearest (by first
// vertex) of about cbrt(n) sampled elements (jump-and-walk, O(n^(1/3)) on a 1M-element mesh,
// docs/performance.md "refine_latency"), and a linear scan when the walk meets the boundary (x
// outside, or a non-convex domain in between). Pass the previous result's `element` as the hint
// when refining along a path. After the first location, x is followed down the planned
// bisections without searching.
//
// Transaction: every bisection of the whole refinement is planned on a scratch overlay first
// (as bisect_edge does) and replayed only when the plan stands, so a refusal leaves the mesh
// untouched, even after many planned bisections.
//
// Contract.
//   Before: planar triangle mesh, counter-clockwise triangles in the reference positions;
//   h > 0.
//   After (on success): the triangle containing x (the `element` returned; for x on an edge,
//   one of the triangles containing it) has a hypotenuse of reference length <= h; the mesh is
//   conforming; on a mesh of right-angled isosceles triangles every triangle is congruent (up
//   to scale: same angles) to a starting one. Returns the number of bisections (= new
//   vertices, ids vertex_count() before the call onwards).
// Refusals (mesh untouched), reasons begin with "refine_around: ":
//   "tetrahedral meshes use refine_around_tetrahedra";
//   "needs a planar triangle mesh (ambient dimension 2)";
//   "size h = -1 is not a positive number" (also 0 and nan);
//   "point (2, 3) is not in the mesh";
//   with an index: "the spatial index watches another mesh", "the spatial index is over the
//   deformed positions; refinement locates in the reference positions";
//   "new element +<a,b,c> would be flat in the deformed positions" (as bisect_edge).
#pragma once

#include <cstddef>

#include "sxk/config.hpp"
#include "sxk/locate.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

struct RefineAroundResult {
    std::size_t bisections = 0;
    ElementId element = invalid_id;  // the triangle containing x afterwards (a good next hint)
};

SXK_API Outcome<RefineAroundResult> refine_around(Mesh& mesh, const Point& x, double h,
                                                  ElementId hint = invalid_id);

// The same, locating x with `index` (which must watch `mesh` over the reference positions): no
// walk longer than the index's bounded one, no scan. The result may name the other triangle
// than the index-less call for an x on an edge (both contain it; the refinement then differs).
SXK_API Outcome<RefineAroundResult> refine_around(Mesh& mesh, const Point& x, double h, const SpatialIndex& index,
                                                  ElementId hint = invalid_id);

// locate_triangle (the walk then scan described above) is declared in sxk/locate.hpp.

}  // namespace sxk
