// The 3-2 flip (edge removal) of a tetrahedral mesh: the three tetrahedra around an interior
// edge of degree 3 become two sharing the triangle of the ring vertices. The inverse of flip_23
// (thesis §5.2.2; connectivity edit by §7.3 replace-elements).
//
//              a                                   a
//             /|\                                 /|\      apexes above and below
//            / | \                               / | \      the plane of the ring
//           /  |  \                             /  |  \      (ring in cyclic order)
//          c---|---e          flip_32          c-------e       the edge ab and its three
//           \  d  /          -------->          \  d  /        tetrahedra ab+cd, ab+de, ab+ec
//            \ | /           <--------           \ | /         become <cde,a> and <cde,b>
//             \|/             flip_23             \|/
//              b                                   b
//
// The edge is given as cycle_around gives it: sigma = face_simplex(entry).subn(j), j in 0..2.
//
// Contract.
//   Before: mesh is tetrahedral; sigma = ab is an interior edge (no boundary face contains it)
//   with exactly three tetrahedra around it; ring vertices c, d, e.
//   After (on success): the three are gone; two new elements, first the one containing a
//   (a = sigma's first canonical vertex) then the one containing b, both with the label of the
//   element of `entry`; ONE Mesh::replace_elements call. Identities: the six hull faces keep
//   their FaceIds and mates; the new triangle cde is a matched pair; no boundary events.
//   Inverse: flip_23 on the new triangle cde restores the three vertex sets around ab and the
//   hull FaceIds: flip_23(flip_32(e)) == identity up to element ids, and conversely.
// Refusals (mesh, ids and watchers untouched), reasons begin with "flip_32: ":
//   not tetrahedral; bad entry or j; edge on the boundary; degree != 3; the ring's elements
//   have different labels ("elements have different labels (a material interface)"); the
//   triangle cde
//   already exists as a face (topologically impossible, thesis Fig. 5.9; not searched when
//   options.reference_is_embedding); unless
//   options.topology_only, a new tetrahedron not strictly positive (exact orient3d) in the
//   reference or the deformed positions (equivalently: ab does not cross triangle cde).
#pragma once

#include <array>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/flip_options.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

SXK_API Outcome<std::array<ElementId, 2>> flip_32(Mesh& mesh, FaceId entry, int j,
                                                  const TetFlipOptions& options = {});

}  // namespace sxk
