#include <gtest/gtest.h>

#include <array>
#include <initializer_list>
#include <span>
#include <sstream>

#include "fixtures.hpp"
#include "sxk/mesh.hpp"

namespace sxk {
namespace {

using test::CountingWatcher;
using test::expect_same_state;
using test::kuhn_cube;
using test::unit_square;

// Thesis Fig. 7.4: the edge flip replaces {<0,1,2>, <0,2,3>} by {<0,1,3>, <1,2,3>}:
//
//   3 ------- 2          3 ------- 2
//   |       / |          | \       |
//   |     /   |   --->   |   \     |
//   |   /     |          |     \   |
//   | /       |          |       \ |
//   0 ------- 1          0 ------- 1
TEST(ReplaceElements, EdgeFlipReusesHullFacesAndLeavesBoundaryAlone) {
    Mesh mesh = unit_square();
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const FaceId edge01 = mesh.find_boundary_face(Simplex(+1, {0, 1}));
    const FaceId edge23 = mesh.find_boundary_face(Simplex(+1, {2, 3}));
    const std::array<ElementId, 2> old{0, 1};
    const std::array<Simplex, 2> flipped{Simplex(+1, {0, 1, 3}), Simplex(+1, {1, 2, 3})};
    const auto created = mesh.replace_elements(old, flipped);
    ASSERT_TRUE(created.ok()) << created.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(created->size(), 2u);
    // hull edges keep their Face objects
    EXPECT_EQ(mesh.find_boundary_face(Simplex(+1, {0, 1})), edge01);
    EXPECT_EQ(mesh.find_boundary_face(Simplex(+1, {2, 3})), edge23);
    EXPECT_EQ(mesh.face_element(edge01), (*created)[0]);
    // the new diagonal 1-3 is an internal matched pair
    const FaceId diagonal = mesh.face((*created)[0], 0);  // <0,1,3>.subn(0) = +<1,3>
    EXPECT_EQ(mesh.face_simplex(diagonal), Simplex(+1, {1, 3}));
    EXPECT_EQ(mesh.face_element(mesh.mate(diagonal)), (*created)[1]);
    // watchers: two removed, two added, no boundary change at all
    EXPECT_EQ(watcher.removed, 2);
    EXPECT_EQ(watcher.added, 2);
    EXPECT_EQ(watcher.boundary_added_count + watcher.boundary_removed_count +
                  watcher.boundary_changed_count,
              0);
    watcher.expect_in_step_with(mesh);
}

TEST(ReplaceElements, RemovingAndAddingBackRestoresTheMesh) {
    Mesh mesh = kuhn_cube(2);
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const std::size_t boundary = mesh.boundary_face_count();
    const ElementId victim = 20;
    const Simplex tau = mesh.simplex(victim);
    const int label = mesh.label(victim);
    const std::array<ElementId, 1> old{victim};
    ASSERT_TRUE(mesh.replace_elements(old, {}).ok());
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.element_count(), 47u);
    // each interior face of the victim exposed its mate; each boundary face of it vanished
    EXPECT_EQ(watcher.removed, 1);
    EXPECT_EQ(static_cast<std::size_t>(watcher.boundary_added_count) -
                  static_cast<std::size_t>(watcher.boundary_removed_count),
              mesh.boundary_face_count() - boundary);
    watcher.expect_in_step_with(mesh);

    const std::array<Simplex, 1> back{tau};
    const std::array<int, 1> labels{label};
    const auto created = mesh.replace_elements({}, back, labels);
    ASSERT_TRUE(created.ok()) << created.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.boundary_face_count(), boundary);
    EXPECT_EQ(mesh.label((*created)[0]), label);
    watcher.expect_in_step_with(mesh);
}

// Two tetrahedra sharing face 123 become three around the new edge 0-4 (the 2-3 flip), and
// back (3-2): faces on the hull keep their identity both ways.
TEST(ReplaceElements, TwoThreeFlipAndBack) {
    Mesh mesh(3, 3);
    mesh.add_vertex({0, 0, 1});    // 0 apex above
    mesh.add_vertex({1, 0, 0});    // 1
    mesh.add_vertex({0, 1, 0});    // 2
    mesh.add_vertex({-1, -1, 0});  // 3
    mesh.add_vertex({0, 0, -1});   // 4 apex below
    // 1,2,3 turn counter-clockwise seen from above, so <1,2,3,0> is positive and <1,2,3,4> not
    const std::array<Simplex, 2> two{Simplex(+1, {1, 2, 3, 0}), Simplex(-1, {1, 2, 3, 4})};
    ASSERT_TRUE(mesh.assign_elements(two).ok());
    ASSERT_TRUE(mesh.validate().ok());
    const Mesh before = mesh;
    std::vector<FaceId> hull = mesh.boundary_faces();

    const std::array<ElementId, 2> old{0, 1};
    const std::array<Simplex, 3> three{two[0].substituted(3, 4), two[0].substituted(1, 4),
                                       two[0].substituted(2, 4)};
    const auto created = mesh.replace_elements(old, three);
    ASSERT_TRUE(created.ok()) << created.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.boundary_faces(), hull);  // same six Face objects on the hull

    const std::vector<ElementId> three_ids = *created;
    const auto back = mesh.replace_elements(three_ids, two);
    ASSERT_TRUE(back.ok()) << back.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.boundary_faces(), hull);
    for (ElementId t = 0; t < 2; ++t) EXPECT_EQ(mesh.simplex((*back)[t]), before.simplex(t));
}

TEST(ReplaceElements, RefusesAnExistingFaceAndLeavesTheMeshAlone) {
    // In a grid, re-adding a triangle that overlaps a neighbour's face must be refused.
    Mesh mesh = test::planar_grid(3);
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const Mesh before = mesh;
    // replacing element 0 by a copy of its neighbour 1 would represent that triangle twice
    const std::array<ElementId, 1> old{0};
    const std::array<Simplex, 1> clash{mesh.simplex(1)};
    const auto result = mesh.replace_elements(old, clash);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "element " + [&] {
        std::ostringstream out;
        out << mesh.simplex(1);
        return out.str();
    }() + " already exists as an element that stays (invariant 7.4)");
    EXPECT_EQ(result.code(), RefusalCode::not_manifold);
    expect_same_state(mesh, before);
    EXPECT_EQ(watcher.removed + watcher.added, 0);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(ReplaceElements, RefusesTopologicallyImpossibleFlip) {
    // Thesis Fig. 5.9: vertex 0 has degree 3. Flipping edge 0-1 would create edge 2-3, which
    // exists already, and the new <3,2,0> would be the mirror image of the element <0,2,3>.
    //
    //            2
    //          / | `
    //         /  0  \          triangles <0,1,2>, <0,2,3>, <0,3,1>
    //        / /   ` `
    //       3 ------- 1
    Mesh mesh(2, 2);
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({2, -1, 0});
    mesh.add_vertex({0, 2, 0});
    mesh.add_vertex({-2, -1, 0});
    const std::array<Simplex, 3> tris{Simplex(+1, {0, 1, 2}), Simplex(+1, {0, 2, 3}),
                                      Simplex(+1, {0, 3, 1})};
    ASSERT_TRUE(mesh.assign_elements(tris).ok());
    ASSERT_TRUE(mesh.validate().ok());
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const Mesh before = mesh;
    const std::array<ElementId, 2> old{0, 2};
    const std::array<Simplex, 2> flipped{Simplex(+1, {2, 3, 1}), Simplex(+1, {3, 2, 0})};
    const auto result = mesh.replace_elements(old, flipped);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "face +<2,3> already exists in an element that stays (invariant 7.4)");
    EXPECT_EQ(result.code(), RefusalCode::not_manifold);
    EXPECT_EQ(result.refusal().item, 0u);
    expect_same_state(mesh, before);
    EXPECT_EQ(watcher.removed + watcher.added + watcher.boundary_added_count, 0);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(ReplaceElements, RefusesBadArguments) {
    Mesh mesh = unit_square();
    const Mesh before = mesh;
    {
        const std::array<ElementId, 1> old{7};
        EXPECT_EQ(mesh.replace_elements(old, {}).reason(), "element 7 does not exist");
        EXPECT_EQ(mesh.replace_elements(old, {}).code(), RefusalCode::not_found);
    }
    {
        const std::array<ElementId, 2> old{1, 1};
        EXPECT_EQ(mesh.replace_elements(old, {}).reason(), "element 1 is listed twice");
        EXPECT_EQ(mesh.replace_elements(old, {}).code(), RefusalCode::bad_argument);
    }
    {
        const std::array<ElementId, 2> old{0, 1};
        const std::array<Simplex, 2> same{Simplex(+1, {0, 1, 3}), Simplex(+1, {1, 3, 0})};
        EXPECT_EQ(mesh.replace_elements(old, same).reason(),
                  "new elements 0 and 1 have the same vertices");
        EXPECT_EQ(mesh.replace_elements(old, same).code(), RefusalCode::not_manifold);
    }
    {
        const std::array<ElementId, 2> old{0, 1};
        const std::array<Simplex, 2> overlap{Simplex(+1, {0, 1, 2}), Simplex(+1, {0, 1, 3})};
        EXPECT_EQ(mesh.replace_elements(old, overlap).reason(),
                  "face +<0,1> would belong to two new elements (invariant 7.4)");
        EXPECT_EQ(mesh.replace_elements(old, overlap).code(), RefusalCode::not_manifold);
    }
    {
        const std::array<Simplex, 1> unknown{Simplex(+1, {0, 1, 4})};
        EXPECT_EQ(mesh.replace_elements({}, unknown).reason(),
                  "vertex 4 does not exist (the mesh has 4 vertices)");
        EXPECT_EQ(mesh.replace_elements({}, unknown).code(), RefusalCode::bad_argument);
    }
    expect_same_state(mesh, before);
    EXPECT_TRUE(mesh.validate().ok());
}

// The element with exactly these vertices (either orientation), or invalid_id.
ElementId element_with(const Mesh& mesh, std::initializer_list<VertexId> vertices) {
    const Simplex wanted(+1, vertices);
    for (ElementId t : elements(mesh))
        if (mesh.simplex(t).same_vertices(wanted)) return t;
    return invalid_id;
}

// planar_grid(2): the six triangles around the centre 4, in ring order 014 154 458 487 347 043.
// Removing 014 and 458 leaves 154 on its own: star(4) would fall into two pieces.
//
//   6 --- 7 --- 8
//   |   / |   / |
//   | /   | /   |
//   3 --- 4 --- 5
//   |   / |   / |
//   | /   | /   |
//   0 --- 1 --- 2
TEST(ReplaceElements, RefusesToPinchAVertexStarInTheGrid) {
    Mesh mesh = test::planar_grid(2);
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const Mesh before = mesh;
    const std::array<ElementId, 2> old{element_with(mesh, {0, 1, 4}), element_with(mesh, {4, 5, 8})};
    ASSERT_NE(old[0], invalid_id);
    ASSERT_NE(old[1], invalid_id);
    const auto refused = mesh.replace_elements(old, std::span<const Simplex>{});
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "star connectivity: vertex 4 would be pinched (its star would fall into 2 pieces)");
    EXPECT_EQ(refused.code(), RefusalCode::pinched_star);
    expect_same_state(mesh, before);
    EXPECT_EQ(watcher.removed + watcher.added, 0);
    EXPECT_TRUE(mesh.validate().ok());

    // Replacing 014 and 154 by 015 and 054 (the other diagonal of 0-1-5-4) keeps every star in
    // one piece through the new triangles: 4 keeps 054 (mates 4-5 of 458 and 0-4 of 043), 5 gets
    // 015 (mate 1-5 of 125) and 054.
    const std::array<ElementId, 2> pair{element_with(mesh, {0, 1, 4}), element_with(mesh, {1, 5, 4})};
    const std::array<Simplex, 2> flipped{Simplex(+1, {0, 1, 5}), Simplex(+1, {0, 5, 4})};
    const auto replaced = mesh.replace_elements(pair, flipped);
    ASSERT_TRUE(replaced.ok()) << replaced.reason();
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.element_count(), 8u);

    // without 015 the triangle 125 would hang at 5 by a vertex only: refused
    const Mesh flipped_state = mesh;
    const std::array<ElementId, 1> lone{element_with(mesh, {0, 1, 5})};
    const auto pinched = mesh.replace_elements(lone, std::span<const Simplex>{});
    ASSERT_FALSE(pinched.ok());
    EXPECT_EQ(pinched.reason(), "star connectivity: vertex 5 would be pinched (its star would fall into 2 pieces)");
    EXPECT_EQ(pinched.code(), RefusalCode::pinched_star);
    expect_same_state(mesh, flipped_state);
    EXPECT_TRUE(mesh.validate().ok());
}

// kuhn_cube(1): six tetrahedra in a ring around the diagonal 0-7. Taking out two that are not
// neighbours, {0,1,3,7} and {0,2,6,7}, splits the ring: the stars of 0 (and 7) fall into two
// pieces (the 3D case: faces keyed by two vertices besides the centre).
TEST(ReplaceElements, RefusesToPinchAVertexStarInTheKuhnCube) {
    Mesh mesh = kuhn_cube(1);
    const Mesh before = mesh;
    const std::array<ElementId, 2> old{element_with(mesh, {0, 1, 3, 7}), element_with(mesh, {0, 2, 6, 7})};
    ASSERT_NE(old[0], invalid_id);
    ASSERT_NE(old[1], invalid_id);
    const auto refused = mesh.replace_elements(old, std::span<const Simplex>{});
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "star connectivity: vertex 0 would be pinched (its star would fall into 2 pieces)");
    EXPECT_EQ(refused.code(), RefusalCode::pinched_star);
    expect_same_state(mesh, before);
    EXPECT_TRUE(mesh.validate().ok());

    // two neighbours in the ring ({0,1,3,7} and {0,2,3,7} share the face 0-3-7): no pinch
    const std::array<ElementId, 2> neighbours{element_with(mesh, {0, 1, 3, 7}), element_with(mesh, {0, 2, 3, 7})};
    const auto removed = mesh.replace_elements(neighbours, std::span<const Simplex>{});
    ASSERT_TRUE(removed.ok()) << removed.reason();
    EXPECT_EQ(mesh.element_count(), 4u);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

}  // namespace
}  // namespace sxk
