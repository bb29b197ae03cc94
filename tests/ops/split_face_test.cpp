#include <gtest/gtest.h>

#include "ops/split_collapse_fixtures.hpp"
#include "ops/tet_flip_fixtures.hpp"
#include "sxk/ops/collapse_edge.hpp"
#include "sxk/ops/split_face.hpp"

namespace sxk {
namespace {

using test::expect_same_state;

//                 0                               0
//                /|\                             /|\       the shared triangle 1,2,3 gets
//     (0,1,0) 2 / | \ 1 (1,0,0)   --->        2 / | \ 1    m = 5 at its centroid: p = 0 and
//              \  |  /                         \ 5 /       q = 4 each join m with the three
//               3 (-1,-1,0)                     3|         edges of the triangle: 2 x 3 tets
//                 |                              |
//                 4                              4
TEST(SplitFace, SharedTriangleOfTwoTetsAndBack) {
    Mesh mesh = test::two_tets();
    mesh.set_label(0, 3);
    mesh.set_label(1, 5);
    const auto before = test::sorted_simplexes(mesh);
    const std::vector<FaceId> hull = mesh.boundary_faces();

    const auto split = split_face(mesh, test::shared_face(mesh));
    ASSERT_TRUE(split.ok()) << split.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(split->vertex, 5u);
    EXPECT_EQ(mesh.reference(5), (Point{0, 0, 0}));
    ASSERT_EQ(split->elements.size(), 6u);
    EXPECT_EQ(mesh.element_count(), 6u);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    EXPECT_EQ(mesh.boundary_faces(), hull);  // face reuse: the hull keeps its ids
    for (ElementId t : split->elements)
        EXPECT_EQ(mesh.label(t), mesh.simplex(t).contains(0) ? 3 : 5);

    const auto back = collapse_edge(mesh, 5, 1);
    ASSERT_TRUE(back.ok()) << back.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(test::sorted_simplexes(mesh), before);
}

TEST(SplitFace, BoundaryTriangleWithWeights) {
    Mesh mesh = test::two_tets();
    const FaceId f = mesh.boundary_faces().front();
    const Simplex sigma = mesh.face_simplex(f);
    const auto split = split_face(mesh, f, {2, 1, 1});
    ASSERT_TRUE(split.ok()) << split.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.element_count(), 4u);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    for (std::size_t k = 0; k < 3; ++k) {
        const double expected = 0.5 * mesh.reference(sigma.vertex(0))[k] +
                                0.25 * mesh.reference(sigma.vertex(1))[k] +
                                0.25 * mesh.reference(sigma.vertex(2))[k];
        EXPECT_DOUBLE_EQ(mesh.reference(split->vertex)[k], expected);
        EXPECT_DOUBLE_EQ(mesh.deformed(split->vertex)[k], expected);
    }
}

TEST(SplitFace, Refusals) {
    Mesh square = test::unit_square();
    const Mesh square_before = square;
    auto result = split_face(square, 0);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(),
              "split_face: needs a tetrahedral mesh (split a triangle mesh's edges with split_edge)");
    EXPECT_EQ(result.code(), RefusalCode::wrong_dimension);
    expect_same_state(square, square_before);

    Mesh mesh = test::two_tets();
    const Mesh before = mesh;
    result = split_face(mesh, 999);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_face: 999 is not a face");
    EXPECT_EQ(result.code(), RefusalCode::not_found);
    result = split_face(mesh, test::shared_face(mesh), {1, 0, 1});
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_face: the weights must all be > 0 (the new vertex inside the face)");
    EXPECT_EQ(result.code(), RefusalCode::bad_argument);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}


// The new vertex of a face split carries every vertex attribute interpolated with the
// normalised weights of its position (a, b, c: the canonical vertices of the face).
TEST(SplitFace, VertexAttributesAreInterpolatedWithTheWeights) {
    Mesh mesh = test::two_tets();
    const AttributeId heat = *mesh.add_vertex_attribute("heat", 2);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        mesh.vertex_attribute(heat, v)[0] = 8.0 * v;
        mesh.vertex_attribute(heat, v)[1] = 1;
    }
    const FaceId f = test::shared_face(mesh);
    const Simplex sigma = mesh.face_simplex(f);
    const auto split = split_face(mesh, f, {1, 1, 2});
    ASSERT_TRUE(split.ok()) << split.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    const double expected = 0.25 * 8 * sigma.vertex(0) + 0.25 * 8 * sigma.vertex(1) + 0.5 * 8 * sigma.vertex(2);
    EXPECT_DOUBLE_EQ(mesh.vertex_attribute(heat, split->vertex)[0], expected);
    EXPECT_DOUBLE_EQ(mesh.vertex_attribute(heat, split->vertex)[1], 1.0);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
}
}  // namespace
}  // namespace sxk
