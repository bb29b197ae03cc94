#include <gtest/gtest.h>

#include <array>
#include <map>
#include <utility>
#include <vector>

#include "ops/split_collapse_fixtures.hpp"
#include "core/fixtures.hpp"
#include "sxk/ops/collapse_edge.hpp"
#include "sxk/ops/remove_elements.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

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
    EXPECT_EQ(result.code(), RefusalCode::not_found);
    expect_same_state(mesh, before);

    result = split_edge(mesh, 0, 2, 0.0);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_edge: t = 0.000000 is not in (0,1)");
    EXPECT_EQ(result.code(), RefusalCode::bad_argument);
    result = split_edge(mesh, 0, 2, 1.0);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_edge: t = 1.000000 is not in (0,1)");
    EXPECT_EQ(result.code(), RefusalCode::bad_argument);
    result = split_edge(mesh, 2, 2);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_edge: the two ends are the same vertex");
    EXPECT_EQ(result.code(), RefusalCode::bad_argument);
    result = split_edge(mesh, 0, 17);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_edge: 17 is not a vertex");
    EXPECT_EQ(result.code(), RefusalCode::not_found);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}


// kuhn_cube(1) as two materials (label 1 for even element ids, 2 for odd) with a temperature
// that is linear in the position and a 3-component velocity: split the main diagonal 0-7 at
// t = 1/4. The new vertex gets 3/4 of vertex 0's values plus 1/4 of vertex 7's, with the same
// weights and summation order as its position; each child keeps the label of its parent.
TEST(SplitEdge, VertexAttributesAndLabelsFollowTheSplit) {
    Mesh mesh = test::kuhn_cube(1);
    for (ElementId t : elements(mesh)) mesh.set_label(t, t % 2 == 0 ? 1 : 2);
    const AttributeId temperature = *mesh.add_vertex_attribute("temperature", 1);
    const AttributeId velocity = *mesh.add_vertex_attribute("velocity", 3);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Point& p = mesh.reference(v);
        mesh.vertex_attribute(temperature, v)[0] = 10 + p[0] + 2 * p[1] + 4 * p[2];
        for (std::size_t k = 0; k < 3; ++k) mesh.vertex_attribute(velocity, v)[k] = -p[k];
    }
    // parent label by the two vertices of the parent other than the split edge's
    std::map<std::pair<VertexId, VertexId>, int> label_of_parent;
    for (ElementId t : elements(mesh)) {
        std::vector<VertexId> rest;
        for (VertexId v : mesh.simplex(t).vertices())
            if (v != 0 && v != 7) rest.push_back(v);
        label_of_parent[{rest[0], rest[1]}] = mesh.label(t);
    }
    const auto split = split_edge(mesh, 0, 7, 0.25);
    ASSERT_TRUE(split.ok()) << split.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    const VertexId m = split->vertex;
    EXPECT_EQ(mesh.vertex_attribute(temperature, m)[0], 0.75 * 10 + 0.25 * 17);
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(mesh.vertex_attribute(velocity, m)[k], -0.25);
        EXPECT_EQ(mesh.reference(m)[k], 0.25);
    }
    ASSERT_EQ(split->elements.size(), 12u);
    for (ElementId t : split->elements) {
        std::vector<VertexId> rest;
        for (VertexId v : mesh.simplex(t).vertices())
            if (v != 0 && v != 7 && v != m) rest.push_back(v);
        ASSERT_EQ(rest.size(), 2u);
        EXPECT_EQ(mesh.label(t), (label_of_parent[{rest[0], rest[1]}]));
    }
    EXPECT_TRUE(test::all_strictly_positive(mesh));
}

// A split that replace_elements refuses after the geometric pre-checks passed leaves no vertex
// behind. That cannot happen on a valid mesh, so the mesh is built unchecked: E = <0,1,3>,
// Q = <0,2,1> and P = <0,1,2> (in that order, so Q's face <1,0> mates with E's <0,1>, and P,
// the same triangle as Q turned over, keeps a second +<0,1>: invariant 7.4 is broken).
// Splitting 1-2 (an edge of P and Q) passes the orientation checks, since each child keeps its
// parent's sign; but the children of P and Q have the same vertex sets (and P's child <0,1,m>
// repeats E's face +<0,1>): replace_elements refuses after split_edge added m, and the split
// must take m away again.
//
//   2               P and Q: the same triangle 0-1-2, both orientations
//   | \             E: 0-1-3 below
//   0 - 1
//    \ /
//     3
TEST(SplitEdge, RefusalAfterAddingTheVertexRemovesItAgain) {
    Mesh mesh(2, 2);
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({1, 0, 0});
    mesh.add_vertex({0, 1, 0});
    mesh.add_vertex({0.5, -1, 0});
    const std::array<Simplex, 3> triangles{Simplex(+1, {0, 1, 3}), Simplex(+1, {0, 2, 1}),
                                           Simplex(+1, {0, 1, 2})};
    ASSERT_TRUE(mesh.assign_elements_unchecked(triangles).ok());
    ASSERT_FALSE(mesh.validate().ok());
    ASSERT_TRUE(mesh.add_vertex_attribute("temperature", 1).ok());
    const Mesh before = mesh;
    const auto split = split_edge(mesh, 1, 2);
    ASSERT_FALSE(split.ok());
    EXPECT_EQ(split.reason(), "split_edge: new elements 0 and 2 have the same vertices");
    EXPECT_EQ(split.code(), RefusalCode::not_manifold);
    EXPECT_EQ(mesh.vertex_count(), 4u);
    expect_same_state(mesh, before);
}


// A flat triangle <0,1,2> (vertex 2 on the edge 0-1) over <1,0,3>: its halves would be flat,
// so the split is refused, unless SplitOptions names vertex 2 as vanishing with them (the
// caller collapses the new vertex into 2 next, which removes them: degeneracy removal).
//
//   0 -- 2 -- 1        0 -- m=2 -- 1      then collapse m into 2:
//    \       /          \   |    /        <0,1,3> in two halves, the flat triangle gone
//     \     /            \  |   /
//        3                   3
TEST(SplitEdge, ParentsVanishingWithAVertexMayHaveFlatChildren) {
    Mesh mesh(2, 2);
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({2, 0, 0});
    mesh.add_vertex({1, 0, 0});
    mesh.add_vertex({1, -1, 0});
    const std::array<Simplex, 2> triangles{Simplex(+1, {0, 1, 2}), Simplex(+1, {1, 0, 3})};
    ASSERT_TRUE(mesh.assign_elements(triangles).ok());
    const Mesh before = mesh;
    const auto checked = split_edge(mesh, 0, 1);
    ASSERT_FALSE(checked.ok());
    EXPECT_EQ(checked.reason().rfind("split_edge: new element ", 0), 0u) << checked.reason();
    EXPECT_NE(checked.reason().find(" would be flat in the reference positions"), std::string::npos);
    EXPECT_EQ(checked.code(), RefusalCode::would_flatten);
    expect_same_state(mesh, before);
    const std::array<VertexId, 1> vanishing{2};
    const auto split = split_edge(mesh, 0, 1, 0.5, SplitOptions{vanishing});
    ASSERT_TRUE(split.ok()) << split.reason();
    EXPECT_EQ(mesh.element_count(), 4u);
    const auto collapsed = collapse_edge(mesh, split->vertex, 2);
    ASSERT_TRUE(collapsed.ok()) << collapsed.reason();
    EXPECT_EQ(mesh.element_count(), 2u);
    for (const ElementId t : elements(mesh))
        EXPECT_EQ(element_orientation(mesh, t, Positions::reference), Sign::positive);
    EXPECT_TRUE(mesh.validate().ok());
}

// Face labels (keyed by vertex set) follow the split: the labelled boundary edge 0-1 of the
// unit square becomes 0-4 and 4-1 with its label; the other labels stay.
TEST(SplitEdge, FaceLabelsPassToTheHalves) {
    Mesh mesh = test::unit_square();
    mesh.face_labels()[Simplex(+1, {0, 1})] = 5;
    mesh.face_labels()[Simplex(+1, {1, 2})] = 6;
    const auto split = split_edge(mesh, 0, 1);
    ASSERT_TRUE(split.ok()) << split.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.face_labels(), (FaceLabels{{Simplex(+1, {0, 4}), 5}, {Simplex(+1, {1, 4}), 5},
                                              {Simplex(+1, {1, 2}), 6}}));
}
}  // namespace
}  // namespace sxk

namespace sxk::test {
namespace {

// An edge whose tetrahedra are two fans joined only at the edge (two_fan_edge).
TEST(SplitEdge, RefusesAnEdgeWhoseTetrahedraAreTwoFans) {
    std::optional<TwoFanEdge> fans = two_fan_edge();
    ASSERT_TRUE(fans) << "no edge of the cube became two fans";
    Mesh& mesh = fans->mesh;
    const VertexId a = fans->a, b = fans->b;
    const Mesh before = mesh;
    const auto refused = split_edge(mesh, a, b);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.code(), RefusalCode::pinched_star);
    EXPECT_EQ(refused.reason(), "split_edge: the tetrahedra around " + to_text(Simplex(+1, {a, b})) +
                                    " are 2 fans joined only at the edge: the new vertex's star "
                                    "would be pinched");
    expect_same_state(mesh, before);
}

}  // namespace
}  // namespace sxk::test
