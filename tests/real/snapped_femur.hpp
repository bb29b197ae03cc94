// The snapped femur of the degeneracy tests (issue 4): every vertex within h/3 (h = mean edge
// length) of the plane through the centre of the femur's bounding box with normal
// (0.3, 1, 0.12) (along the bone, not axis aligned) snapped onto it, as a snap cut does (thesis
// §3.2.2). tools/bench/degeneracies.cpp snaps its femurs the same way.
#pragma once

#include "snap_to_plane.hpp"
#include "sxk/mesh.hpp"
#include "sxk/quality.hpp"

namespace sxk::test {

inline degeneracy::SnapReport snap_femur(Mesh& mesh) {
    return degeneracy::snap_to_plane(mesh, degeneracy::plane_through_centre(mesh, {0.3, 1, 0.12}),
                                     sxk::mean_edge_length(mesh) / 3);
}

}  // namespace sxk::test
