#include <gtest/gtest.h>

#include "fixtures.hpp"
#include "sxk/mesh.hpp"

namespace sxk {
namespace {

using test::CountingWatcher;
using test::expect_same_state;
using test::unit_square;

// Thesis Fig. 7.5 in miniature: cut the square along its diagonal by giving triangle <0,2,3>
// its own copies 4 (of 0) and 5 (of 2). Element and face identities survive; the diagonal
// faces become two boundary faces.
//
//   3 ------- 2          3 ---- 5   2
//   |       / |          |    /   / |
//   |  B  /   |   --->   | B /   /  |
//   |   /  A  |          |  /   / A |
//   | /       |          | /   /    |
//   0 ------- 1          4   0 ---- 1
TEST(ChangeElements, CutAlongTheDiagonalKeepsIdentities) {
    Mesh mesh = unit_square();
    const VertexId copy0 = mesh.add_vertex(mesh.reference(0), mesh.deformed(0));
    const VertexId copy2 = mesh.add_vertex(mesh.reference(2), mesh.deformed(2));
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const FaceId diagonal_b = mesh.face(1, 2);  // +<0,2> in <0,2,3>
    const FaceId edge_23 = mesh.find_boundary_face(Simplex(+1, {2, 3}));
    ASSERT_EQ(mesh.face_simplex(diagonal_b), Simplex(+1, {0, 2}));

    const std::array<ElementSubstitution, 1> cut{ElementSubstitution{1, {copy0, copy2, 3, invalid_id}}};
    ASSERT_TRUE(mesh.change_elements(cut).ok());
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.simplex(1), Simplex(+1, {4, 5, 3}));
    EXPECT_EQ(mesh.element_count(), 2u);
    EXPECT_EQ(mesh.boundary_face_count(), 6u);
    // the same Face objects, now with substituted simplexes
    EXPECT_EQ(mesh.face_simplex(diagonal_b), Simplex(+1, {4, 5}));
    EXPECT_EQ(mesh.mate(diagonal_b), invalid_id);
    EXPECT_EQ(mesh.face_simplex(edge_23), Simplex(+1, {5, 3}));
    EXPECT_EQ(mesh.vertex_element(0), 0u);
    EXPECT_EQ(mesh.vertex_element(copy0), 1u);
    // watchers: one element changed; the two diagonal faces joined the boundary; B's two other
    // edges stayed on the boundary under new simplexes (3-0 became 3-4, 2-3 became 5-3)
    EXPECT_EQ(watcher.changed, 1);
    EXPECT_EQ(watcher.removed + watcher.added, 0);
    EXPECT_EQ(watcher.boundary_added_count, 2);
    EXPECT_EQ(watcher.boundary_removed_count, 0);
    EXPECT_EQ(watcher.boundary_changed_count, 2);
    watcher.expect_in_step_with(mesh);

    // stitching back is the inverse substitution
    // canonical order of <4,5,3> is (3,4,5): 3 stays, 4 -> 0, 5 -> 2
    const std::array<ElementSubstitution, 1> inverse{ElementSubstitution{1, {3, 0, 2, invalid_id}}};
    ASSERT_TRUE(mesh.change_elements(inverse).ok());
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.boundary_face_count(), 4u);
    EXPECT_EQ(mesh.mate(diagonal_b), mesh.face(0, 1));
    watcher.expect_in_step_with(mesh);
}

TEST(ChangeElements, RefusesCollisionsAndLeavesTheMeshAlone) {
    Mesh mesh = unit_square();
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const Mesh before = mesh;
    {
        // <0,2,3> -> <0,2,1> would be the mirror of element <0,1,2>
        const std::array<ElementSubstitution, 1> s{ElementSubstitution{1, {0, 2, 1, invalid_id}}};
        EXPECT_EQ(mesh.change_elements(s).reason(),
                  "element -<0,1,2> already exists as an unchanged element (invariant 7.4)");
        EXPECT_EQ(mesh.change_elements(s).code(), RefusalCode::not_manifold);
    }
    {
        const std::array<ElementSubstitution, 1> s{ElementSubstitution{1, {0, 2, 2, invalid_id}}};
        EXPECT_EQ(mesh.change_elements(s).reason(),
                  "substitution of element 1: element +<0,2,2> repeats a vertex");
        EXPECT_EQ(mesh.change_elements(s).code(), RefusalCode::bad_argument);
    }
    {
        const std::array<ElementSubstitution, 1> s{ElementSubstitution{5, {0, 1, 2, invalid_id}}};
        EXPECT_EQ(mesh.change_elements(s).reason(), "element 5 does not exist");
        EXPECT_EQ(mesh.change_elements(s).code(), RefusalCode::not_found);
    }
    {
        const std::array<ElementSubstitution, 2> s{ElementSubstitution{0, {0, 1, 2, invalid_id}},
                                                   ElementSubstitution{0, {0, 1, 2, invalid_id}}};
        EXPECT_EQ(mesh.change_elements(s).reason(), "element 0 is listed twice");
        EXPECT_EQ(mesh.change_elements(s).code(), RefusalCode::bad_argument);
    }
    expect_same_state(mesh, before);
    EXPECT_EQ(watcher.changed + watcher.boundary_added_count + watcher.boundary_removed_count, 0);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(ChangeElements, IdentitySubstitutionChangesNothingVisible) {
    Mesh mesh = test::kuhn_cube(2);
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const Mesh before = mesh;
    std::vector<ElementSubstitution> all;
    for (ElementId t : elements(mesh)) {
        ElementSubstitution s{t, {}};
        for (int j = 0; j < 4; ++j) s.new_vertices[static_cast<std::size_t>(j)] = mesh.simplex(t).vertex(j);
        all.push_back(s);
    }
    ASSERT_TRUE(mesh.change_elements(all).ok());
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    expect_same_state(mesh, before);
    EXPECT_EQ(watcher.changed, 48);
    EXPECT_EQ(watcher.boundary_added_count + watcher.boundary_removed_count +
                  watcher.boundary_changed_count,
              0);
}

}  // namespace
}  // namespace sxk
