#include <gtest/gtest.h>

#include <array>

#include "ops/split_collapse_fixtures.hpp"
#include "sxk/ops/collapse_edge.hpp"
#include "sxk/ops/split_element.hpp"

namespace sxk {
namespace {

using test::expect_same_state;

//   3 ------- 2          3 ------- 2
//   |  B    / |          |  B    /|||     A = <0,1,2> becomes three triangles around
//   |     /   |   --->   |     / 4  |     its centroid m = 4; B is untouched
//   |   /  A  |          |   /  / \ |
//   | /       |          | / /     \|
//   0 ------- 1          0 ------- 1
TEST(SplitElement, TriangleAroundItsCentroidAndBack) {
    Mesh mesh = test::unit_square();
    mesh.set_label(0, 4);
    const auto before = test::sorted_simplexes(mesh);
    const auto split = split_element(mesh, 0);
    ASSERT_TRUE(split.ok()) << split.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    ASSERT_EQ(split->elements.size(), 3u);
    EXPECT_EQ(mesh.element_count(), 4u);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    for (ElementId t : split->elements) EXPECT_EQ(mesh.label(t), 4);
    EXPECT_DOUBLE_EQ(mesh.reference(split->vertex)[0], 2.0 / 3.0);
    EXPECT_DOUBLE_EQ(mesh.reference(split->vertex)[1], 1.0 / 3.0);

    const auto back = collapse_edge(mesh, split->vertex, 1);
    ASSERT_TRUE(back.ok()) << back.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(test::sorted_simplexes(mesh), before);
}

TEST(SplitElement, TetrahedronWithWeightsAndBack) {
    Mesh mesh = test::kuhn_cube(1);
    const auto before = test::sorted_simplexes(mesh);
    const std::array<double, 4> weights{1, 2, 3, 4};
    const Simplex tau = mesh.simplex(2);
    const auto split = split_element(mesh, 2, weights);
    ASSERT_TRUE(split.ok()) << split.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.element_count(), 9u);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    for (std::size_t k = 0; k < 3; ++k) {
        double expected = 0;
        for (int j = 0; j < 4; ++j) expected += weights[static_cast<std::size_t>(j)] / 10 * mesh.reference(tau.vertex(j))[k];
        EXPECT_NEAR(mesh.deformed(split->vertex)[k], expected, 1e-15);
    }
    const auto back = collapse_edge(mesh, split->vertex, tau.vertex(3));
    ASSERT_TRUE(back.ok()) << back.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(test::sorted_simplexes(mesh), before);
}

TEST(SplitElement, Refusals) {
    Mesh mesh = test::unit_square();
    const Mesh before = mesh;
    auto result = split_element(mesh, 7);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_element: 7 is not an element");
    EXPECT_EQ(result.code(), RefusalCode::not_found);
    const std::array<double, 2> two{1, 1};
    result = split_element(mesh, 0, two);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_element: needs 3 weights, got 2");
    EXPECT_EQ(result.code(), RefusalCode::bad_argument);
    const std::array<double, 3> negative{1, -1, 1};
    result = split_element(mesh, 0, negative);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "split_element: the weights must all be > 0 (the new vertex inside the element)");
    EXPECT_EQ(result.code(), RefusalCode::bad_argument);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}


// A two-material square: the children of the split triangle keep its label, the other
// triangle keeps its own, and the centroid gets the mean of the three corner temperatures.
TEST(SplitElement, VertexAttributesAndLabels) {
    Mesh mesh = test::unit_square();
    mesh.set_label(0, 4);
    mesh.set_label(1, 6);
    const AttributeId temperature = *mesh.add_vertex_attribute("temperature", 1);
    for (VertexId v = 0; v < 4; ++v) mesh.vertex_attribute(temperature, v)[0] = 3.0 * v;
    const auto split = split_element(mesh, 0);
    ASSERT_TRUE(split.ok()) << split.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_DOUBLE_EQ(mesh.vertex_attribute(temperature, split->vertex)[0], (0 + 3 + 6) / 3.0);
    for (ElementId t : split->elements) EXPECT_EQ(mesh.label(t), 4);
    EXPECT_EQ(mesh.label(1), 6);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
}
}  // namespace
}  // namespace sxk
