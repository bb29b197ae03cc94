#include <gtest/gtest.h>

#include "ops/tet_flip_fixtures.hpp"
#include "sxk/ops/flip_23.hpp"
#include "sxk/ops/flip_32.hpp"

namespace sxk {
namespace {

using test::CountingWatcher;
using test::expect_same_state;

TEST(Flip32, ThreeTetsAroundAnEdgeBecomeTwoAndBack) {
    Mesh mesh = test::two_tets();
    ASSERT_TRUE(flip_23(mesh, test::shared_face(mesh)).ok());
    const std::vector<FaceId> hull = mesh.boundary_faces();
    const auto three_sets = test::vertex_sets(mesh);
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const auto [entry, j] = test::edge_entry(mesh, 0, 4);
    const auto two = flip_32(mesh, entry, j);
    ASSERT_TRUE(two.ok()) << two.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(watcher.removed, 3);
    EXPECT_EQ(watcher.added, 2);
    EXPECT_EQ(watcher.boundary_added_count + watcher.boundary_removed_count +
                  watcher.boundary_changed_count,
              0);
    EXPECT_EQ(mesh.boundary_faces(), hull);
    // and flip_23 on the restored triangle gives the three tetrahedra back
    const auto three = flip_23(mesh, mesh.opposite_face((*two)[0], 0));
    ASSERT_TRUE(three.ok()) << three.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(test::vertex_sets(mesh), three_sets);
    EXPECT_EQ(mesh.boundary_faces(), hull);
}

TEST(Flip32, RefusesABoundaryEdge) {
    Mesh mesh = test::two_tets();
    const Mesh before = mesh;
    const auto [entry, j] = test::edge_entry(mesh, 1, 2);
    const auto result = flip_32(mesh, entry, j);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "flip_32: edge +<1,2> is on the boundary");
    EXPECT_EQ(result.code(), RefusalCode::not_applicable);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

// In the Kuhn cube of 2 x 2 x 2 cells the centre vertex 13 is interior; its edge to the
// corners 0 and 26 along the shared diagonals, 0-13 and 13-26, have the six tetrahedra of a cube around it.
TEST(Flip32, RefusesDegreeOtherThanThree) {
    Mesh mesh = test::kuhn_cube(2);
    const Mesh before = mesh;
    const auto [entry, j] = test::edge_entry(mesh, 0, 13);
    ASSERT_NE(entry, invalid_id);
    const auto result = flip_32(mesh, entry, j);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "flip_32: edge +<0,13> has degree 6, not 3");
    EXPECT_EQ(result.code(), RefusalCode::not_applicable);
    const auto [inner, k] = test::edge_entry(mesh, 13, 26);
    const auto six = flip_32(mesh, inner, k);
    ASSERT_FALSE(six.ok());
    EXPECT_EQ(six.reason(), "flip_32: edge +<13,26> has degree 6, not 3");
    EXPECT_EQ(six.code(), RefusalCode::not_applicable);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

// A tetrahedron 0,1,2,3 split at an interior point 4 into four: the edge 4-0 has degree 3 with
// ring 1,2,3, but the triangle 1,2,3 is already a face (of <1,2,3,4>), so the 3-2 flip would
// represent it three times (thesis Fig. 5.9 in 3D).
//
//            3
//           /|\           <4,1,2,3> <0,4,2,3> <0,1,4,3> <0,1,2,4>
//          / 4 \ .
//         0--|--2
//          \ | /
//            1
TEST(Flip32, RefusesAnExistingTriangle) {
    Mesh mesh(3, 3);
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({1, 0, 0});
    mesh.add_vertex({0, 1, 0});
    mesh.add_vertex({0, 0, 1});
    mesh.add_vertex({0.2, 0.2, 0.2});
    const Simplex whole(+1, {0, 1, 2, 3});
    const std::array<Simplex, 4> four{whole.substituted(0, 4), whole.substituted(1, 4),
                                      whole.substituted(2, 4), whole.substituted(3, 4)};
    ASSERT_TRUE(mesh.assign_elements(four).ok());
    ASSERT_TRUE(test::all_positive(mesh));
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const Mesh before = mesh;
    const auto [entry, j] = test::edge_entry(mesh, 0, 4);
    const auto result = flip_32(mesh, entry, j, {.topology_only = true});
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "flip_32: triangle +<1,2,3> already exists");
    EXPECT_EQ(result.code(), RefusalCode::not_manifold);
    expect_same_state(mesh, before);
    EXPECT_EQ(watcher.removed + watcher.added, 0);
    ASSERT_TRUE(mesh.validate().ok());
}

// One of the three tetrahedra around 0-4 of another material: removing the edge would move
// the interface.
TEST(Flip32, RefusesAMaterialInterface) {
    Mesh mesh = test::two_tets();
    const auto three = flip_23(mesh, test::shared_face(mesh));
    ASSERT_TRUE(three.ok()) << three.reason();
    mesh.set_label((*three)[2], 3);
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const Mesh before = mesh;
    const auto [entry, j] = test::edge_entry(mesh, 0, 4);
    const auto result = flip_32(mesh, entry, j);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "flip_32: elements have different labels (a material interface)");
    EXPECT_EQ(result.code(), RefusalCode::label_conflict);
    expect_same_state(mesh, before);
    EXPECT_EQ(watcher.removed + watcher.added, 0);
    ASSERT_TRUE(mesh.validate().ok());

    for (ElementId t : *three) mesh.set_label(t, 3);
    const auto two = flip_32(mesh, entry, j);
    ASSERT_TRUE(two.ok()) << two.reason();
    for (ElementId t : *two) EXPECT_EQ(mesh.label(t), 3);
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

// Three tetrahedra around 0-4; in the deformed positions 0 is moved below triangle 1,2,3 (the
// three are then inverted too, which a flip does not check): the new <1,2,3,0> would be
// inverted there, so the flip is refused.
TEST(Flip32, RefusesANonConvexRing) {
    Mesh mesh = test::two_tets();
    ASSERT_TRUE(flip_23(mesh, test::shared_face(mesh)).ok());
    ASSERT_TRUE(mesh.validate().ok());
    mesh.set_deformed(0, {0, 0, -2});
    const Mesh before = mesh;
    const auto [entry, j] = test::edge_entry(mesh, 0, 4);
    const auto result = flip_32(mesh, entry, j);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(),
              "flip_32: new tetrahedron -<0,1,2,3> would be inverted in the deformed positions");
    EXPECT_EQ(result.code(), RefusalCode::would_invert);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

}  // namespace
}  // namespace sxk
