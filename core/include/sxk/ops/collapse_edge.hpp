// Edge collapse of a triangle or tetrahedral mesh (thesis §3.2.3, Fig. 3.10): vertex `from` is
// merged into vertex `to`; the elements containing the edge disappear and the rest of
// star(from) is re-attached to `to`.
//
//         x ------- y                x ------- y
//        / \       / \              / \       / \       the two triangles around from-to
//       /   \     /   \            /   \     /   \      vanish; the other triangles of
//      w ---- from --- to   --->  w ------------ to     star(from) get `to` instead of
//       \   /     \   /            \   /     \   /      `from` (a substitution, so their
//        \ /       \ /              \ /       \ /       orientation follows)
//         v ------- u                v ------- u
//
//   Link condition (Fig. 3.10; Dey et al.): the result is a manifold only if
//   link(from) ∩ link(to) == link(from-to). Here two triangles (from,to,x) would fold onto
//   each other when from and to share a neighbour x that is not opposite the edge:
//
//        from ---- to        from and to both see x, but no triangle contains from, to
//          \      /          and x: collapsing makes the edges from-x and to-x one edge
//           \    /           with three (or more) triangles: refused.
//            \  /
//             x
//
// Contract.
//   Before: from-to is an edge; the link condition holds (checked on all simplexes of the links,
//   the boundary counting as a virtual vertex joined to every boundary face, so that a
//   collapse cannot glue two boundary pieces either).
//   After (on success): every element of star(from) is gone; each one not containing `to` is
//   replaced by its copy with from -> to, with its label (ONE Mesh::replace_elements call, old
//   = star(from), so the edit is a transaction); `from` remains as a vertex in no element;
//   returns `to`. The point overload also moves `to` to the given positions (after the edit).
//   Vertex attributes: the plain overload leaves every attribute of `to` (and of `from`) as it
//   was. The point overload treats the collapse as a split of the edge at parameter s, the
//   reference point projected onto the segment to-from (s = 0 at to, 1 at from, clamped to
//   [0,1]): each attribute of `to` becomes (1-s) value(to) + s value(from), so collapsing to
//   the midpoint averages them. `from` keeps its values.
//   Face labels: labels of faces containing from and to vanish with them; a labelled face with
//   `from` but not `to` passes its label to the face with `to` in its place, unless that face
//   is labelled already.
//   Inverse: collapse_edge(split_edge(a, b) = m, a) restores the element vertex sets.
//   No vertex is added, so a refusal by replace_elements leaves nothing behind.
// Refusals (mesh untouched), reasons begin with "collapse_edge: ":
//   from or to not a vertex; from == to; from-to not an edge; link condition violated; `from`
//   on the boundary and the edge interior ("would move the boundary"); a boundary face around
//   from (or, for the point overload, around to) whose plane (line in 2D) the surviving vertex
//   would leave ("would move the boundary"); a re-attached element (or, for the point
//   overload, an element of star(to)) that would be flat or inverted by exact orient2d /
//   orient3d in the reference or the deformed positions; on triangle surfaces in space, a
//   degenerate (collinear) triangle or one whose normal would turn over (exact
//   normal_alignment); any refusal of replace_elements (prefixed).
#pragma once

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

struct CollapseOptions {
    // 0: a boundary face whose vertex moves must keep its plane (line) exactly, so the boundary
    // keeps its shape bit for bit. > 0: it may leave it by this times its longest edge (a
    // relative distance): degeneracy removal collapses edges of flat elements at a snapped,
    // slightly bent boundary, and undoes a split whose rounded midpoint is off the plane.
    double boundary_tolerance = 0;
};

SXK_API Outcome<VertexId> collapse_edge(Mesh& mesh, VertexId from, VertexId to,
                                        const CollapseOptions& options = {});
// Collapses and moves the surviving vertex `to` to (reference, deformed).
SXK_API Outcome<VertexId> collapse_edge(Mesh& mesh, VertexId from, VertexId to,
                                        const Point& reference, const Point& deformed,
                                        const CollapseOptions& options = {});

}  // namespace sxk
