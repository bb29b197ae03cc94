#include <gtest/gtest.h>

#include "ops/split_collapse_fixtures.hpp"
#include "sxk/ops/collapse_edge.hpp"
#include "sxk/ops/split_edge.hpp"

namespace sxk {
namespace {

using test::expect_same_state;

//   3 ------- 2            3 ------- 2
//   |  B    / |            | \     / |     the diagonal 0-2 gets m = 4 at t = 1/4;
//   |     /   |    --->    |  B1  /  |     A = <0,1,2> -> <4,1,2>, <0,4,2>
//   |   /   A |            | B0 4  A1|     B = <0,2,3> -> <4,2,3>, <0,4,3>
//   | /       |            | /  A0 \ |
//   0 ------- 1            0 ------- 1
TEST(SplitEdge, InteriorEdgeOfTheUnitSquareAndBack) {
    Mesh mesh = test::unit_square();
    mesh.set_label(0, 7);
    mesh.set_label(1, 9);
    mesh.set_deformed(2, {2, 2, 0});  // the deformed square is bigger: m interpolates both sets
    const auto before = test::sorted_simplexes(mesh);

    const auto split = split_edge(mesh, 0, 2, 0.25);
    ASSERT_TRUE(split.ok()) << split.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(split->vertex, 4u);
    EXPECT_EQ(mesh.reference(4), (Point{0.25, 0.25, 0}));
    EXPECT_EQ(mesh.deformed(4), (Point{0.5, 0.5, 0}));
    ASSERT_EQ(split->elements.size(), 4u);
    EXPECT_EQ(mesh.element_count(), 4u);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    for (ElementId t : split->elements) {
        EXPECT_TRUE(mesh.simplex(t).contains(4));
        // children inherit the label of their parent: the one with vertex 1 came from A
        EXPECT_EQ(mesh.label(t), mesh.simplex(t).contains(1) ? 7 : 9);
    }
    EXPECT_EQ(mesh.boundary_face_count(), 4u);

    // inverse identity: collapse the new vertex back onto an end
    const auto back = collapse_edge(mesh, 4, 0);
    ASSERT_TRUE(back.ok()) << back.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(*back, 0u);
    EXPECT_EQ(test::sorted_simplexes(mesh), before);
    EXPECT_EQ(mesh.vertex_element(4), invalid_id);
}

//   3 ------- 2
//   |       / |      the boundary edge 0-1 gets m = 4 at its midpoint: only A is split,
//   |     /   |      and the boundary gains one edge
//   |   /  A  |
//   | /       |
//   0 -- 4 -- 1
TEST(SplitEdge, BoundaryEdgeSplitsOneTriangle) {
    Mesh mesh = test::unit_square();
    const auto before = test::sorted_simplexes(mesh);
    const auto split = split_edge(mesh, 0, 1);
    ASSERT_TRUE(split.ok()) << split.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.reference(split->vertex), (Point{0.5, 0, 0}));
    EXPECT_EQ(mesh.element_count(), 3u);
    EXPECT_EQ(mesh.boundary_face_count(), 5u);
    EXPECT_TRUE(test::all_strictly_positive(mesh));

    const auto back = collapse_edge(mesh, split->vertex, 1);
    ASSERT_TRUE(back.ok()) << back.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(test::sorted_simplexes(mesh), before);
}

// The Kuhn cube's main diagonal 0-7 is in all six tetrahedra: twelve halves around m = 8 at
// the cube's centre, and back.
TEST(SplitEdge, MainDiagonalOfTheKuhnCubeAndBack) {
    Mesh mesh = test::kuhn_cube(1);
    const auto before = test::sorted_simplexes(mesh);
    const auto split = split_edge(mesh, 0, 7);
    ASSERT_TRUE(split.ok()) << split.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.reference(split->vertex), (Point{0.5, 0.5, 0.5}));
    EXPECT_EQ(mesh.element_count(), 12u);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    for (ElementId t : split->elements) {
        // each half keeps the label (the path order) of its parent; parents had labels 0..5
        EXPECT_GE(mesh.label(t), 0);
        EXPECT_LE(mesh.label(t), 5);
    }

    const auto back = collapse_edge(mesh, split->vertex, 7);
    ASSERT_TRUE(back.ok()) << back.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(test::sorted_simplexes(mesh), before);
}

TEST(SplitEdge, RefusesWhatIsNotAnEdgeOrAPointOnIt) {
    Mesh mesh = test::unit_square();
    const Mesh before = mesh;
    auto result = split_edge(mesh, 1, 3);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_edge: " + test::text(Simplex(+1, {1, 3})) + " is not an edge");
    expect_same_state(mesh, before);

    result = split_edge(mesh, 0, 2, 0.0);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_edge: t = 0.000000 is not in (0,1)");
    result = split_edge(mesh, 0, 2, 1.0);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_edge: t = 1.000000 is not in (0,1)");
    result = split_edge(mesh, 2, 2);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_edge: the two ends are the same vertex");
    result = split_edge(mesh, 0, 17);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_edge: 17 is not a vertex");
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

}  // namespace
}  // namespace sxk
