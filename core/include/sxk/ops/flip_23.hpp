// The 2-3 flip (face flip) of a tetrahedral mesh: two tetrahedra sharing an interior triangle
// become three around a new edge (thesis §5.2.2: the 3D counterpart of the edge flip; §5.3 notes
// that in 3D not every face can be flipped, so every failure case is checked here).
//
//              p                                   p
//             /|\                                 /|\      apexes above and below
//            / | \                               / | \      the plane of the ring
//           /  |  \                             /  |  \      (ring in cyclic order)
//          a---|---c          flip_23          a---|---c       the shared triangle abc is
//           \  b  /          -------->          \  |  /        replaced by the edge pq: three
//            \ | /           <--------           \ b /         tetrahedra pq+ab, pq+bc, pq+ca
//             \|/             flip_32             \|/          (the new edge pierces abc)
//              q                                   q
//       <abc,p> and <abc,q>                 <pq,ab>, <pq,bc>, <pq,ca>
//
// Contract.
//   Before: mesh is tetrahedral; `face` is an interior face (it has a mate). Let t0 (apex p) be
//   the element of `face` and t1 (apex q) the element of its mate.
//   After (on success): t0 and t1 are gone; three new elements simplex(t0) with one vertex of
//   abc replaced by q each (in the order a, b, c of face_simplex(face)'s canonical vertices),
//   all with the label of t0; ONE Mesh::replace_elements call, so the edit is a transaction.
//   Identities: the six hull faces of the pair (the faces of t0, t1 other than abc) keep their
//   FaceIds and mates (face reuse); the three new faces containing pq are created as matched
//   pairs; the boundary map and the boundary watcher events are untouched.
//   Inverse: flip_32 on the new edge pq restores the vertex sets (and orientations) of t0 and
//   t1 and, again, the hull FaceIds: flip_32(flip_23(f)) == identity up to element ids.
// Refusals (mesh, ids and watchers untouched), reasons begin with "flip_23: ":
//   not a tetrahedral mesh; `face` not a face; face on the boundary; t0 and t1 have different
//   labels ("elements have different labels (a material interface)"); edge pq already exists
//   (topologically impossible, thesis Fig. 5.9: the new edge would be represented twice; not
//   searched when options.reference_is_embedding, whose guarantee makes it impossible);
//   unless options.topology_only, a new tetrahedron that is not strictly positive by exact
//   orient3d in the reference or the deformed positions (equivalently: segment pq does not
//   cross the interior of triangle abc, i.e. the union of t0 and t1 is not strictly convex).
#pragma once

#include <array>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/flip_options.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

SXK_API Outcome<std::array<ElementId, 3>> flip_23(Mesh& mesh, FaceId face,
                                                  const TetFlipOptions& options = {});

}  // namespace sxk
