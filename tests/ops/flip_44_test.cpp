#include <gtest/gtest.h>

#include "ops/tet_flip_fixtures.hpp"
#include "sxk/ops/flip_44.hpp"

namespace sxk {
namespace {

using test::CountingWatcher;
using test::expect_same_state;

// An octahedron: the square 1,2,3,4 in z = 0 and apexes 0 = a (above, shifted to x = -0.5)
// and 5 = b (below); four tetrahedra around the axis a-b.
//
//            0 a
//          / | `
//   4 ----/--|--`--- 3        square ring 1 (1,0) 2 (0,1) 3 (-1,0) 4 (0,-1)
//     `  /   |   ` /
//      1 ----|--- 2
//            5 b
inline Mesh octahedron() {
    Mesh mesh(3, 3);
    mesh.add_vertex({-0.5, 0, 1});
    mesh.add_vertex({1, 0, 0});
    mesh.add_vertex({0, 1, 0});
    mesh.add_vertex({-1, 0, 0});
    mesh.add_vertex({0, -1, 0});
    mesh.add_vertex({-0.5, 0, -1});
    std::vector<Simplex> tets;
    for (VertexId k = 1; k <= 4; ++k) {
        const VertexId next = k % 4 + 1;
        // ring k -> next counter-clockwise seen from above: <k, next, 0-apex> positive with a
        const Simplex tau(+1, {k, next, 0, 5});
        tets.push_back(tau);
    }
    // fix orientations by geometry (each must be positive)
    Mesh probe(3, 3);
    for (VertexId v = 0; v < 6; ++v) probe.add_vertex(mesh.reference(v));
    EXPECT_TRUE(probe.assign_elements_unchecked(tets).ok());
    for (std::size_t i = 0; i < tets.size(); ++i)
        if (element_orientation(probe, static_cast<ElementId>(i)) != Sign::positive)
            tets[i] = tets[i].mate();
    EXPECT_TRUE(mesh.assign_elements(tets).ok());
    return mesh;
}

TEST(Flip44, OctahedronSwapsItsAxisAndBack) {
    Mesh mesh = octahedron();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    ASSERT_TRUE(test::all_positive(mesh));
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const std::vector<FaceId> hull = mesh.boundary_faces();
    const auto before_sets = test::vertex_sets(mesh);
    const auto [entry, j] = test::edge_entry(mesh, 0, 5);
    const auto four = flip_44(mesh, entry, j, 0);
    ASSERT_TRUE(four.ok()) << four.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_TRUE(test::all_positive(mesh));
    EXPECT_EQ(mesh.boundary_faces(), hull);
    EXPECT_EQ(watcher.removed, 4);
    EXPECT_EQ(watcher.added, 4);
    EXPECT_EQ(watcher.boundary_added_count + watcher.boundary_removed_count +
                  watcher.boundary_changed_count,
              0);
    // the new edge is a diagonal of the square: 1-3 or 2-4
    const Simplex& first = mesh.simplex((*four)[0]);
    const bool diagonal_13 = first.contains(1) && first.contains(3);
    const VertexId u = diagonal_13 ? 1 : 2, w = diagonal_13 ? 3 : 4;
    for (ElementId t : *four) {
        EXPECT_TRUE(mesh.simplex(t).contains(u));
        EXPECT_TRUE(mesh.simplex(t).contains(w));
    }
    // back: one of the two diagonals of the ring around u-w recreates 0-5
    const auto [back_entry, back_j] = test::edge_entry(mesh, u, w);
    bool restored = false;
    for (int diagonal = 0; diagonal < 2 && !restored; ++diagonal) {
        Mesh trial = mesh;
        const auto back = flip_44(trial, back_entry, back_j, diagonal);
        ASSERT_TRUE(back.ok()) << back.reason();
        ASSERT_TRUE(trial.validate().ok()) << trial.validate().reason();
        if (test::vertex_sets(trial) == before_sets) {
            restored = true;
            EXPECT_EQ(trial.boundary_faces(), hull);
        }
    }
    EXPECT_TRUE(restored);
}

TEST(Flip44, RefusesBoundaryEdgesAndOtherDegrees) {
    Mesh mesh = octahedron();
    const Mesh before = mesh;
    const auto [hull_entry, hull_j] = test::edge_entry(mesh, 1, 2);
    const auto boundary = flip_44(mesh, hull_entry, hull_j, 0);
    ASSERT_FALSE(boundary.ok());
    EXPECT_EQ(boundary.reason(), "flip_44: edge +<1,2> is on the boundary");
    EXPECT_EQ(boundary.code(), RefusalCode::not_applicable);
    const auto [entry, j] = test::edge_entry(mesh, 0, 5);
    const auto bad = flip_44(mesh, entry, j, 2);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.reason(), "flip_44: diagonal 2 is not 0 or 1");
    EXPECT_EQ(bad.code(), RefusalCode::bad_argument);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());

    Mesh cube = test::kuhn_cube(2);
    const Mesh cube_before = cube;
    const auto [e, k] = test::edge_entry(cube, 0, 13);
    const auto six = flip_44(cube, e, k, 0);
    ASSERT_FALSE(six.ok());
    EXPECT_EQ(six.reason(), "flip_44: edge +<0,13> has degree 6, not 4");
    EXPECT_EQ(six.code(), RefusalCode::not_applicable);
    expect_same_state(cube, cube_before);
    ASSERT_TRUE(cube.validate().ok());
}

// One tetrahedron of the octahedron of another material: swapping the axis would move the
// interface.
TEST(Flip44, RefusesAMaterialInterface) {
    Mesh mesh = octahedron();
    mesh.set_label(2, 9);
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const Mesh before = mesh;
    const auto [entry, j] = test::edge_entry(mesh, 0, 5);
    for (const int diagonal : {0, 1}) {
        const auto result = flip_44(mesh, entry, j, diagonal);
        ASSERT_FALSE(result.ok());
        EXPECT_EQ(result.reason(), "flip_44: elements have different labels (a material interface)");
        EXPECT_EQ(result.code(), RefusalCode::label_conflict);
    }
    expect_same_state(mesh, before);
    EXPECT_EQ(watcher.removed + watcher.added, 0);
    ASSERT_TRUE(mesh.validate().ok());

    for (ElementId t : elements(mesh)) mesh.set_label(t, 9);
    const auto four = flip_44(mesh, entry, j, 0);
    ASSERT_TRUE(four.ok()) << four.reason();
    for (ElementId t : *four) EXPECT_EQ(mesh.label(t), 9);
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

// Vertex 1 pulled in to (-0.2,0,0) makes the square reflex at 1: the diagonal 2-4 (x = 0) then
// leaves the ring polygon and its tetrahedra would be inverted; 1-3 still works.
TEST(Flip44, RefusesTheDiagonalOutsideANonConvexRing) {
    Mesh mesh = octahedron();
    mesh.set_reference(1, {-0.2, 0, 0});
    mesh.set_deformed(1, {-0.2, 0, 0});
    ASSERT_TRUE(test::all_positive(mesh));
    const auto [entry, j] = test::edge_entry(mesh, 0, 5);
    int accepted = 0;
    for (int diagonal = 0; diagonal < 2; ++diagonal) {
        Mesh trial = mesh;
        const auto result = flip_44(trial, entry, j, diagonal);
        if (result.ok()) {
            ++accepted;
            ASSERT_TRUE(trial.validate().ok());
            EXPECT_TRUE(test::all_positive(trial));
            EXPECT_TRUE(trial.simplex((*result)[0]).contains(1));
        } else {
            EXPECT_EQ(result.reason().rfind("flip_44: new tetrahedron ", 0), 0u) << result.reason();
            EXPECT_TRUE(result.code() == RefusalCode::would_invert ||
                        result.code() == RefusalCode::would_flatten)
                << to_string(result.code());
            expect_same_state(trial, mesh);
            ASSERT_TRUE(trial.validate().ok());
        }
    }
    EXPECT_EQ(accepted, 1);
}

}  // namespace
}  // namespace sxk
