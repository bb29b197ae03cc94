// The 4-4 flip of a tetrahedral mesh: the four tetrahedra around an interior edge ab of degree 4
// become the four around a diagonal of the ring (thesis §5.2.2; it is a flip_23 followed by a
// flip_32, done here as ONE transaction so the intermediate, often flat, state never exists).
//
//            a                                  a
//           /|\                               / | \      (apexes a, b)
//     v3 --/-|-\-- v2       ring v0 v1 v2 v3 v3 ---|--- v2
//       \ /  |  \ /         (cycle_around     |\   |   /|       the edge ab becomes the
//        /\  |  /\           order)           | \  |  / |       diagonal v0-v2 (diagonal 0)
//     v0 --\-|-/-- v1          -------->      v0 ---------- v1   or v1-v3 (diagonal 1)
//           \|/                                 \  |  /
//            b                                    b
//   <ab,v3v0> <ab,v0v1> <ab,v1v2> <ab,v2v3>     <v0v2, a v1> <v0v2, b v1> <v0v2, a v3> <v0v2, b v3>
//
// The ring v0..v3 is numbered by cycle_around(mesh, entry, j): v_k is the vertex the k-th and
// (k+1)-th tetrahedra of the ring share besides a and b.
//
// Contract.
//   Before: mesh is tetrahedral; ab = face_simplex(entry).subn(j) is an interior edge with
//   exactly four tetrahedra around it; `diagonal` is 0 (new edge v0-v2) or 1 (new edge v1-v3).
//   After (on success): the four are gone; four new elements around the new edge, all with the
//   label of the element of `entry`; ONE Mesh::replace_elements call. Identities: the eight
//   hull faces keep their FaceIds and mates; no boundary events.
//   Inverse: flip_44 on the new edge with the diagonal that recreates ab restores the four
//   vertex sets and the hull FaceIds.
// Refusals (mesh, ids and watchers untouched), reasons begin with "flip_44: ":
//   not tetrahedral; bad entry, j or diagonal; edge on the boundary (the 2-2 boundary flip is
//   not provided); degree != 4; the ring's elements have different labels ("elements have
//   different labels (a material interface)"); the new edge already exists (thesis Fig. 5.9; not searched when
//   options.reference_is_embedding); unless
//   options.topology_only, a new tetrahedron not strictly positive (exact orient3d) in the
//   reference or the deformed positions. The classic 4-4 flip has a, b and the ring coplanar
//   pairs; no such coplanarity is required here, only positivity of the result.
#pragma once

#include <array>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/flip_options.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

SXK_API Outcome<std::array<ElementId, 4>> flip_44(Mesh& mesh, FaceId entry, int j, int diagonal,
                                                  const TetFlipOptions& options = {});

}  // namespace sxk
