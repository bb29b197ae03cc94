// Local refinement of a tetrahedral mesh around a point by conforming bisection (thesis §6.5
// refine-around(x, h), in 3D as in the thesis' Figure 6.13):
//
//     t <- tetrahedron containing x
//     while |refinement edge of t| > h:  bisect_tetrahedron(t);  t <- tetrahedron containing x
//
//          +-----------+            +-----------+          the tetrahedra around x are bisected
//          |\         /|            |\    |    /|          until their refinement edges are at
//          |  \     /  |   refine   |  \--+--/  |          most h long; neighbours are bisected
//          |    \ /  x |  ------->  |--+-\|/-x+-|          as far as conformity needs (no
//          |    / \    |   around   |  /--+--\  |          hanging nodes ever: every split
//          |  /     \  |            |/    |    \|          halves all tetrahedra around its edge)
//          +-----------+            +-----------+
//
// Lengths and point location use the reference positions. Point location (sxk/locate.hpp): with
// a SpatialIndex, its locate (a bounded walk from the last bisection's children, then the rtree:
// O(log n)); without, locate_tetrahedron: a visibility walk through face neighbours with exact
// orient3d from the last bisection's children (the stateless entry point: from the first
// element, O(n^(1/3)) steps), and a test of every element when the walk reaches the boundary (x
// outside, or a non-convex domain in the way) or takes too many steps. The location runs once
// per call; after that x is followed into the children of the planned splits.
//
// Contract (refine_around_tetrahedra):
//   Before: a valid tetrahedral mesh; x in the mesh (on its boundary counts); h > 0.
//   After: the tetrahedron containing x has a refinement edge of length <= h; the mesh is valid,
//   conforming, and covers the same domain (same volume, same boundary surface); every new
//   element is a bisection child (positive when its parent was). Returns the number of edges
//   bisected (0 when nothing needed refining).
// Refusals (mesh and state untouched), reasons begin with "refine_around_tetrahedra: ":
//   "the mesh has triangles, not tetrahedra"; "h = <h> is not positive" (also NaN);
//   "point (x, y, z) is not in the mesh"; "the bisection state is stale: <why>"; with an index,
//   "the spatial index watches another mesh" and "the spatial index is over the deformed
//   positions; refinement locates in the reference positions"; a split refused
//   anywhere in the call (rounding, for absurdly small h or flat deformed elements: "...
//   bisect_tetrahedron: split_edge: new element ... would be flat in the deformed positions",
//   the state-less form without "bisect_tetrahedron: ").
// One transaction: every bisection of the call is first planned on a scratch overlay (point
// location follows x into the children of the planned splits), then the whole plan is replayed
// through split_edge, so a refusal leaves mesh, state and watchers as they were.
#pragma once

#include <cstddef>

#include "sxk/config.hpp"
#include "sxk/locate.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/tet_bisection.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

// locate_tetrahedron (closed elements, reference positions: a point on a shared face may get
// either; walking from `start`, a dead or invalid one starting at the first live element) is
// declared in sxk/locate.hpp.

// Refines with an existing bisection state (its marking carries over between calls). With the
// AMP rule (TetBisection::with_amp_marking) each bisection of the tetrahedron containing x is
// followed by AMP's closure to conformity (tetrahedra with a hanging node bisected at their own
// refinement edges) on the plan, and the whole call is replayed as one replace_elements; the
// refusal of a child then reads "refine_around_tetrahedra: bisect_tetrahedron: new element ...
// would be flat in the deformed positions" (no "split_edge: ").
SXK_API Outcome<std::size_t> refine_around_tetrahedra(TetBisection& state, const Point& x,
                                                      double h);

// For `sxk refine` and any mesh: longest-edge bisection, the rule of
// TetBisection::with_initial_marking, without a state: that rule's marks are a function of the
// reference positions, computed when needed, so a call costs what it refines (no pass over the
// mesh) and calls in a row give the same mesh as one TetBisection session would.
SXK_API Outcome<std::size_t> refine_around_tetrahedra(Mesh& mesh, const Point& x, double h);

// Both, locating x with `index` (which must watch the state's mesh, or `mesh`, over the
// reference positions) instead of the walk-then-scan.
SXK_API Outcome<std::size_t> refine_around_tetrahedra(TetBisection& state, const Point& x, double h,
                                                      const SpatialIndex& index);
SXK_API Outcome<std::size_t> refine_around_tetrahedra(Mesh& mesh, const Point& x, double h,
                                                      const SpatialIndex& index);

}  // namespace sxk
