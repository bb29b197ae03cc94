// Moves the vertices near a plane onto it, as a snap cut does before it dissects (thesis
// §3.2.2): the test meshes and benchmark of degeneracy removal ("snapped" meshes, §3.3).
//
//        before                           after: vertices within max_distance of the
//     .   .    .   .                       plane are projected onto it
//   ----.--.------.----  plane          ---.--.--.---.--.---
//     .      .  .   .                     .           .
//
// Each vertex within max_distance (in the reference positions) is projected orthogonally onto
// the plane, in both position sets, one vertex after the other in order of id. A move that
// would make an element of the vertex's star flat or inverted (exact orient3d / orient2d in
// either position set) is not made: the thesis (§3.4) names inverted elements as the artefact
// of snapping that "might be prevented by simply forbidding node relocations in those cases".
// So the result has flat-ish elements (tiny aspect ratios) but none flat or inverted. Boundary
// vertices move too: the boundary changes by at most max_distance near the plane.
#pragma once

#include <cstddef>
#include <vector>

#include "sxk/mesh.hpp"

namespace sxk::degeneracy {

struct Plane {
    Point point{};         // a point on the plane
    Point normal{0, 0, 1};  // need not be unit length, must not be zero
};

struct SnapReport {
    std::vector<VertexId> moved;    // vertices projected, by increasing id
    std::size_t refused = 0;        // within reach, not moved (an element would be flat/inverted)
    double mean_edge_length = 0;    // of the mesh before snapping (reference positions)
};

// The plane through the centre of the bounding box of the mesh's vertices (reference positions)
// with the given normal: how the tests and benchmarks place their snap planes on real meshes
// (the femur's: normal {0.3, 1, 0.12}, along the bone, not axis aligned).
Plane plane_through_centre(const Mesh& mesh, const Point& normal);

// Snaps the vertices within max_distance of the plane (reference positions) onto it. The
// thesis' snapped meshes use max_distance = mean_edge_length / 3 (sxk/quality.hpp). A test-mesh
// maker, not an edit of the kernel: throws std::invalid_argument (mesh untouched) for a zero or
// non-finite normal ("snap_to_plane: the plane's normal must be finite and not zero") or a
// negative or non-finite distance ("snap_to_plane: max_distance must be finite and >= 0, not -1").
// Vertices in no element, and vertices whose projection is their position already (bit for
// bit, both sets), are neither moved nor refused. A refused move is checked against the
// positions of the vertices moved before it (order of id) and leaves the vertex where it was.
SnapReport snap_to_plane(Mesh& mesh, const Plane& plane, double max_distance);

// The elements of the stars of `vertices` (sorted, no repeats): what a snap changed, the
// candidates to hand to remove_degeneracies after it.
std::vector<ElementId> elements_around(const Mesh& mesh, const std::vector<VertexId>& vertices);

}  // namespace sxk::degeneracy
