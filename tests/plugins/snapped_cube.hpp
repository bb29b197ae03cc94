// The thesis' snapped cube (§3.3, Figs. 3.14-3.16: 729 nodes, 3072 tetrahedra) as the tests of
// degeneracy removal and of relaxation after it make it.
#pragma once

#include "snap_to_plane.hpp"
#include "sxk/generators.hpp"
#include "sxk/quality.hpp"

namespace sxk::test {

// A diagonal plane with mixed-sign normal: Kuhn tetrahedra climb +x, +y, +z, so only a normal
// with components of both signs lets one tetrahedron have all four vertices within h/3 of the
// plane, the way snapping flattens elements (thesis §3.2.3, Fig. 3.7). Of 3000 random planes
// through the middle of the cube none gave more than about 50 degenerates at h/3 (the thesis'
// cut, made by a sweep of many triangles, gave 143); this one gives 45.
inline const degeneracy::Plane thesis_cube_plane{{3.85, 4.0, 3.5}, {1, -0.95, 0.97}};

// The 8^3 Kuhn cube of unit cells, one material, every vertex within h/3 of thesis_cube_plane
// snapped onto it (h the mean edge length).
inline Mesh snapped_thesis_cube(degeneracy::SnapReport& snap) {
    Mesh mesh = make_kuhn_cube(8).value();
    snap =
        degeneracy::snap_to_plane(mesh, thesis_cube_plane, sxk::mean_edge_length(mesh) / 3);
    return mesh;
}

}  // namespace sxk::test
