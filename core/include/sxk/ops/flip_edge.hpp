// The 2-2 edge flip of a triangle mesh, planar or a surface in 3D (thesis §5.2.1: "the two
// triangles incident with the edge ... form a quadrilateral, and the diagonal may be switched";
// §7.3 / Fig. 7.4: the flip is one replace-elements call).
//
// a-b is the flipped edge (t0 = <a,b,c> above it, t1 = <b,a,d> below):
//
//          c                       c        the quadrilateral a d b c (counter-
//        /   \                   / | \      clockwise) keeps its four hull edges;
//      /  t0   \               /   |   \    the diagonal a-b becomes c-d:
//     a ------- b    ---->    a  0 | 1  b   new[0] = <a,d,c>, new[1] = <d,b,c>
//      \  t1   /               \   |   /
//        \   /                   \ | /      flip_edge(new diagonal) turns it back
//          d                       d
//
// Contract.
//   Before: topological dimension 2 (ambient 2 or 3); `edge` is a face (an edge) with a mate.
//   Let face_simplex(edge) = <a,b> (oriented), t0 = <a,b,c> its element, t1 = <b,a,d> the
//   element of its mate.
//   After (on success): t0 and t1 are gone; two new elements <a,d,c> and <d,b,c> (returned in
//   that order), both with the label of t0, written by ONE Mesh::replace_elements call, so the
//   edit is a transaction. Identities: the four hull faces <a,d>, <d,b>, <b,c>, <c,a> keep their
//   FaceIds and mates (face reuse); the new diagonal <c,d> / <d,c> is a new matched pair; the
//   boundary map is untouched, so watchers see 2 elements removed and 2 added, no boundary event.
//   Orientation is preserved: the new triangles have the sign of the old ones.
//   Inverse: flipping the new diagonal (a face of either new element containing c and d)
//   restores the vertex sets of t0 and t1 and their hull FaceIds: flip(flip(e)) == e up to
//   element ids.
// Refusals (mesh, ids and watchers untouched); every reason begins with "flip_edge: ":
//   - not a triangle mesh, or `edge` is not a face;
//   - "edge {a,b} is on the boundary" (a < b);
//   - "elements have different labels (a material interface)": the flip would move the
//     interface between two materials;
//   - the new edge c-d already exists: "new edge {c,d} already exists (thesis Fig. 5.9)" —
//     a vertex of degree 3 in the plane, or e.g. any edge of a tetrahedron's surface;
//   - planar meshes, unless options.topology_only: a new triangle that would be flat or inverted
//     by exact orient2d in the reference OR the deformed positions (the quadrilateral is not
//     strictly convex): "new triangle {x,y,z} would be inverted in the reference positions";
//   - surfaces in 3D: a new triangle with exactly collinear vertices (always: such a triangle
//     has no normal) and, unless options.topology_only, a flip whose two new triangles have
//     opposite normals (negative dot product, decided exactly): the surface would fold over
//     the new edge.
#pragma once

#include <array>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

struct FlipOptions {
    // false: the geometric checks above apply. true: only topology is checked (meshes without
    // meaningful geometry, or callers that decided geometry themselves, e.g. Lawson's algorithm
    // on one set of positions). Collinear triangles on 3D surfaces are refused regardless.
    bool topology_only = false;
};

SXK_API Outcome<std::array<ElementId, 2>> flip_edge(Mesh& mesh, FaceId edge,
                                                    const FlipOptions& options = {});

}  // namespace sxk
