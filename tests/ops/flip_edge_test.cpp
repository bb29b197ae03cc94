// Tests of the 2-2 edge flip (sxk/ops/flip_edge.hpp).
//
//   planar fixture (unit_square):            the flip of diagonal 0-2:
//
//   3 ------- 2                              3 ------- 2
//   |       / |                              | \       |
//   |  B  /   |          flip_edge           |   \  1  |
//   |   /  A  |          -------->           | 0   \   |
//   | /       |                              |       \ |
//   0 ------- 1                              0 ------- 1
//
//   A = <0,1,2>, B = <0,2,3>                 new: {0,1,3}, {1,2,3}; hull edges keep FaceIds
#include "sxk/ops/flip_edge.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <vector>

#include "core/fixtures.hpp"
#include "sxk/predicates.hpp"

namespace sxk {
namespace {

using test::CountingWatcher;
using test::expect_same_state;
using test::unit_square;

// Some face representing the edge {u,v}.
FaceId find_edge(const Mesh& mesh, VertexId u, VertexId v) {
    const Simplex wanted(+1, {u, v});
    for (ElementId t : elements(mesh))
        for (FaceId f : mesh.faces(t))
            if (mesh.face_simplex(f).same_vertices(wanted)) return f;
    return invalid_id;
}

std::set<std::vector<VertexId>> vertex_sets(const Mesh& mesh) {
    std::set<std::vector<VertexId>> sets;
    for (ElementId t : elements(mesh)) {
        const auto v = mesh.simplex(t).vertices();
        sets.insert(std::vector<VertexId>(v.begin(), v.end()));
    }
    return sets;
}

Mesh mesh_from(int ambient, const std::vector<Point>& points, const std::vector<Simplex>& triangles) {
    Mesh mesh(2, ambient);
    for (const Point& p : points) mesh.add_vertex(p);
    EXPECT_TRUE(mesh.assign_elements(triangles).ok());
    return mesh;
}

// a = 0 at the origin, b = 1, c = 2 the corners of a big triangle, vertex 3 inside: every
// interior edge 3-x has the degree-3 vertex 3 as an end, so its flip would create an edge
// between two corners that already exists (the planar case of thesis Fig. 5.9).
Mesh degree_three_vertex() {
    return mesh_from(2, {{0, 0, 0}, {4, 0, 0}, {2, 4, 0}, {2, 1, 0}},
                     {Simplex(+1, {0, 1, 3}), Simplex(+1, {1, 2, 3}), Simplex(+1, {2, 0, 3})});
}

// A non-convex quadrilateral 0 1 2 3 with the reflex corner at 2 (or a flat one when 2 lies
// on the segment 1-3): flipping 0-2 would give an inverted (or flat) triangle {1,2,3}.
Mesh dart(double corner) {
    return mesh_from(2, {{0, 0, 0}, {4, 0, 0}, {corner, corner, 0}, {0, 4, 0}},
                     {Simplex(+1, {0, 1, 2}), Simplex(+1, {0, 2, 3})});
}

TEST(FlipEdge, KeepsHullFaceIdsOnUnitSquare) {
    Mesh mesh = unit_square();
    const std::vector<FaceId> hull = mesh.boundary_faces();
    ASSERT_EQ(hull.size(), 4u);
    auto flipped = flip_edge(mesh, find_edge(mesh, 0, 2));
    ASSERT_TRUE(flipped.ok()) << flipped.reason();
    EXPECT_EQ(mesh.boundary_faces(), hull);
    EXPECT_EQ(vertex_sets(mesh), (std::set<std::vector<VertexId>>{{0, 1, 3}, {1, 2, 3}}));
    std::vector<FaceId> faces_after;
    for (ElementId t : flipped.value()) {
        EXPECT_EQ(element_orientation(mesh, t), Sign::positive);
        for (FaceId f : mesh.faces(t)) faces_after.push_back(f);
    }
    for (FaceId f : hull) EXPECT_NE(std::find(faces_after.begin(), faces_after.end(), f), faces_after.end());
    // the new diagonal is a matched pair between the two new elements
    const FaceId diagonal = find_edge(mesh, 1, 3);
    ASSERT_NE(diagonal, invalid_id);
    ASSERT_NE(mesh.mate(diagonal), invalid_id);
    EXPECT_NE(mesh.face_element(diagonal), mesh.face_element(mesh.mate(diagonal)));
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(FlipEdge, FlipTwiceRestoresVertexSets) {
    Mesh mesh = unit_square();
    const auto before = vertex_sets(mesh);
    const std::vector<FaceId> hull = mesh.boundary_faces();
    ASSERT_TRUE(flip_edge(mesh, find_edge(mesh, 0, 2)).ok());
    auto back = flip_edge(mesh, find_edge(mesh, 1, 3));
    ASSERT_TRUE(back.ok()) << back.reason();
    EXPECT_EQ(vertex_sets(mesh), before);
    EXPECT_EQ(mesh.boundary_faces(), hull);
    for (ElementId t : elements(mesh)) EXPECT_EQ(element_orientation(mesh, t), Sign::positive);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(FlipEdge, WatchersSeeTwoRemovedTwoAddedAndNoBoundaryEvent) {
    Mesh mesh = unit_square();
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    ASSERT_TRUE(flip_edge(mesh, find_edge(mesh, 0, 2)).ok());
    EXPECT_EQ(watcher.removed, 2);
    EXPECT_EQ(watcher.added, 2);
    EXPECT_EQ(watcher.changed, 0);
    EXPECT_EQ(watcher.boundary_removed_count, 0);
    EXPECT_EQ(watcher.boundary_added_count, 0);
    EXPECT_EQ(watcher.boundary_changed_count, 0);
    watcher.expect_in_step_with(mesh);
    mesh.remove_watcher(watcher);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(FlipEdge, RefusesBoundaryEdge) {
    Mesh mesh = unit_square();
    const Mesh copy = mesh;
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    watcher.reset_counts();
    auto flipped = flip_edge(mesh, find_edge(mesh, 0, 1));
    ASSERT_FALSE(flipped.ok());
    EXPECT_EQ(flipped.reason(), "flip_edge: edge {0,1} is on the boundary");
    EXPECT_EQ(flipped.code(), RefusalCode::not_applicable);
    EXPECT_EQ(watcher.removed + watcher.added + watcher.changed, 0);
    mesh.remove_watcher(watcher);
    expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());
}

// A and B of different materials: flipping 0-2 would move the interface between them.
TEST(FlipEdge, RefusesAMaterialInterface) {
    Mesh mesh = unit_square();
    mesh.set_label(1, 2);
    const Mesh copy = mesh;
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    watcher.reset_counts();
    auto flipped = flip_edge(mesh, find_edge(mesh, 0, 2));
    ASSERT_FALSE(flipped.ok());
    EXPECT_EQ(flipped.reason(), "flip_edge: elements have different labels (a material interface)");
    EXPECT_EQ(flipped.code(), RefusalCode::label_conflict);
    EXPECT_EQ(watcher.removed + watcher.added + watcher.changed, 0);
    mesh.remove_watcher(watcher);
    expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());

    // one material again: the same flip goes through and both triangles keep the label
    mesh.set_label(0, 2);
    auto again = flip_edge(mesh, find_edge(mesh, 0, 2));
    ASSERT_TRUE(again.ok()) << again.reason();
    EXPECT_EQ(mesh.label((*again)[0]), 2);
    EXPECT_EQ(mesh.label((*again)[1]), 2);
    ASSERT_TRUE(mesh.validate().ok());
}

// The diagonal 0-2 carries a face label (a constraint, e.g. a drawn interface): flipping it
// would drop the label, so the flip is refused; make_delaunay_by_flips leaves it too.
TEST(FlipEdge, RefusesALabelledEdge) {
    Mesh mesh = unit_square();
    mesh.face_labels()[Simplex(+1, {0, 2})] = 9;
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    const Mesh copy = mesh;
    auto flipped = flip_edge(mesh, find_edge(mesh, 0, 2));
    ASSERT_FALSE(flipped.ok());
    EXPECT_EQ(flipped.reason(),
              "flip_edge: face +<0,2> carries label 9 (a constraint: an interface or a boundary "
              "patch)");
    EXPECT_EQ(flipped.code(), RefusalCode::label_conflict);
    expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());

    mesh.face_labels().clear();
    ASSERT_TRUE(flip_edge(mesh, find_edge(mesh, 0, 2)).ok());
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(FlipEdge, RefusesTopologicallyImpossibleFlipAtDegreeThreeVertex) {
    Mesh mesh = degree_three_vertex();
    const Mesh copy = mesh;
    auto flipped = flip_edge(mesh, find_edge(mesh, 0, 3));
    ASSERT_FALSE(flipped.ok());
    EXPECT_EQ(flipped.reason(),
              "flip_edge: new edge {1,2} already exists (thesis Fig. 5.9), flipping edge {0,3} is "
              "topologically impossible");
    EXPECT_EQ(flipped.code(), RefusalCode::not_manifold);
    // even when the caller waives geometry
    auto waived = flip_edge(mesh, find_edge(mesh, 0, 3), FlipOptions{.topology_only = true});
    ASSERT_FALSE(waived.ok());
    EXPECT_EQ(waived.reason(), flipped.reason());
    EXPECT_EQ(waived.code(), flipped.code());
    expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(FlipEdge, RefusesNonConvexQuadrilateral) {
    Mesh mesh = dart(1.0);
    const Mesh copy = mesh;
    auto flipped = flip_edge(mesh, find_edge(mesh, 0, 2));
    ASSERT_FALSE(flipped.ok());
    EXPECT_EQ(flipped.reason(), "flip_edge: new triangle {1,2,3} would be inverted in the reference positions");
    EXPECT_EQ(flipped.code(), RefusalCode::would_invert);
    expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(FlipEdge, TopologyOnlyFlipsNonConvexQuadrilateral) {
    Mesh mesh = dart(1.0);
    auto flipped = flip_edge(mesh, find_edge(mesh, 0, 2), FlipOptions{.topology_only = true});
    ASSERT_TRUE(flipped.ok()) << flipped.reason();
    EXPECT_EQ(vertex_sets(mesh), (std::set<std::vector<VertexId>>{{0, 1, 3}, {1, 2, 3}}));
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(FlipEdge, RefusesFlatTriangle) {
    Mesh mesh = dart(2.0);  // corner 2 on the segment 1-3
    const Mesh copy = mesh;
    auto flipped = flip_edge(mesh, find_edge(mesh, 0, 2));
    ASSERT_FALSE(flipped.ok());
    EXPECT_EQ(flipped.reason(), "flip_edge: new triangle {1,2,3} would be flat in the reference positions");
    EXPECT_EQ(flipped.code(), RefusalCode::would_flatten);
    expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(FlipEdge, ChecksDeformedPositionsToo) {
    Mesh mesh = unit_square();
    mesh.set_deformed(2, {0.4, 0.4, 0});  // still a valid deformed mesh, but no longer convex
    const Mesh copy = mesh;
    auto flipped = flip_edge(mesh, find_edge(mesh, 0, 2));
    ASSERT_FALSE(flipped.ok());
    EXPECT_EQ(flipped.reason(), "flip_edge: new triangle {1,2,3} would be inverted in the deformed positions");
    EXPECT_EQ(flipped.code(), RefusalCode::would_invert);
    expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(FlipEdge, RefusesTetrahedralMesh) {
    Mesh mesh = test::kuhn_cube(1);
    const Mesh copy = mesh;
    auto flipped = flip_edge(mesh, 0);
    ASSERT_FALSE(flipped.ok());
    EXPECT_EQ(flipped.reason(), "flip_edge: needs a triangle mesh (topological dimension 2), this one has dimension 3");
    EXPECT_EQ(flipped.code(), RefusalCode::wrong_dimension);
    expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());
}

// ---- triangle surfaces in 3D ------------------------------------------------------------------

TEST(FlipEdgeSurface, FlipsBentSquareAndBack) {
    // the unit square with corner 1 lifted: a gently bent surface
    Mesh mesh = mesh_from(3, {{0, 0, 0}, {1, 0, 0.3}, {1, 1, 0}, {0, 1, 0}},
                          {Simplex(+1, {0, 1, 2}), Simplex(+1, {0, 2, 3})});
    const auto before = vertex_sets(mesh);
    const std::vector<FaceId> hull = mesh.boundary_faces();
    auto flipped = flip_edge(mesh, find_edge(mesh, 0, 2));
    ASSERT_TRUE(flipped.ok()) << flipped.reason();
    EXPECT_EQ(vertex_sets(mesh), (std::set<std::vector<VertexId>>{{0, 1, 3}, {1, 2, 3}}));
    EXPECT_EQ(mesh.boundary_faces(), hull);
    ASSERT_TRUE(mesh.validate().ok());
    ASSERT_TRUE(flip_edge(mesh, find_edge(mesh, 1, 3)).ok());
    EXPECT_EQ(vertex_sets(mesh), before);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(FlipEdgeSurface, RefusesEveryEdgeOfTetrahedronSurface) {
    // the boundary of the positive tetrahedron <0,1,2,3>: every pair of vertices is an edge
    const Simplex tet(+1, {0, 1, 2, 3});
    Mesh mesh = mesh_from(3, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                          {tet.subn(0), tet.subn(1), tet.subn(2), tet.subn(3)});
    ASSERT_EQ(mesh.boundary_face_count(), 0u);
    const Mesh copy = mesh;
    auto flipped = flip_edge(mesh, find_edge(mesh, 0, 1));
    ASSERT_FALSE(flipped.ok());
    EXPECT_EQ(flipped.reason(),
              "flip_edge: new edge {2,3} already exists (thesis Fig. 5.9), flipping edge {0,1} is "
              "topologically impossible");
    EXPECT_EQ(flipped.code(), RefusalCode::not_manifold);
    expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());
}

// Two triangles hinged at a right angle on the short edge 0-1; flipping to 2-3 would put the
// new triangles back to back (normals (0,0,-2) and (-2,0,2)).
Mesh hinge() {
    return mesh_from(3, {{1, 0, 0}, {1, 0, 1}, {0, 1, 0}, {0, -1, 0}},
                     {Simplex(+1, {0, 1, 2}), Simplex(+1, {1, 0, 3})});
}

TEST(FlipEdgeSurface, RefusesFolding) {
    Mesh mesh = hinge();
    const Mesh copy = mesh;
    auto flipped = flip_edge(mesh, find_edge(mesh, 0, 1));
    ASSERT_FALSE(flipped.ok());
    EXPECT_EQ(flipped.reason(),
              "flip_edge: flipping edge {0,1} to {2,3} would fold the surface (the new triangles' "
              "normals are opposite) in the reference positions");
    EXPECT_EQ(flipped.code(), RefusalCode::would_invert);
    expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(FlipEdgeSurface, TopologyOnlyAllowsFolding) {
    Mesh mesh = hinge();
    auto flipped = flip_edge(mesh, find_edge(mesh, 0, 1), FlipOptions{.topology_only = true});
    ASSERT_TRUE(flipped.ok()) << flipped.reason();
    EXPECT_EQ(vertex_sets(mesh), (std::set<std::vector<VertexId>>{{0, 2, 3}, {1, 2, 3}}));
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(FlipEdgeSurface, RefusesCollinearTriangleEvenWithTopologyOnly) {
    // 0, 2, 3 lie on one line, so the new triangle {0,2,3} would have no normal
    Mesh mesh = mesh_from(3, {{1, 0, 0}, {1, 0, 1}, {0, 1, 0}, {2, -1, 0}},
                          {Simplex(+1, {0, 1, 2}), Simplex(+1, {1, 0, 3})});
    const Mesh copy = mesh;
    for (bool topology_only : {false, true}) {
        auto flipped = flip_edge(mesh, find_edge(mesh, 0, 1), FlipOptions{.topology_only = topology_only});
        ASSERT_FALSE(flipped.ok());
        EXPECT_EQ(flipped.reason(),
                  "flip_edge: new triangle {0,2,3} would be degenerate (collinear vertices) in the "
                  "reference positions");
        EXPECT_EQ(flipped.code(), RefusalCode::would_flatten);
    }
    expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());
}

}  // namespace
}  // namespace sxk
