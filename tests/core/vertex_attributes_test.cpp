// Vertex attributes of the kernel: registration by name, defaults for add_vertex, interpolation
// by add_interpolated_vertex, removal of the last vertex (the roll-back of a refused split),
// copies and memory accounting. How the operations carry attributes is tested with each one
// (tests/ops/*_test.cpp).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "fixtures.hpp"
#include "sxk/mesh.hpp"

namespace sxk {
namespace {

using test::expect_same_state;

std::vector<double> values(const Mesh& mesh, AttributeId a, VertexId v) {
    const auto span = mesh.vertex_attribute(a, v);
    return {span.begin(), span.end()};
}

TEST(VertexAttributes, RegisterFindAndDefaults) {
    Mesh mesh = test::unit_square();
    const std::array<double, 3> still{0, 0, 0};
    const std::array<double, 1> room{20.5};
    const auto temperature = mesh.add_vertex_attribute("temperature", 1, room);
    ASSERT_TRUE(temperature.ok()) << temperature.reason();
    const auto velocity = mesh.add_vertex_attribute("velocity", 3, still);
    ASSERT_TRUE(velocity.ok()) << velocity.reason();
    EXPECT_NE(*temperature, *velocity);
    EXPECT_EQ(mesh.find_vertex_attribute("temperature"), *temperature);
    EXPECT_EQ(mesh.find_vertex_attribute("velocity"), *velocity);
    EXPECT_EQ(mesh.find_vertex_attribute("pressure"), invalid_id);
    EXPECT_EQ(mesh.vertex_attributes(), (std::vector<AttributeId>{*temperature, *velocity}));
    EXPECT_EQ(mesh.vertex_attribute_name(*velocity), "velocity");
    EXPECT_EQ(mesh.vertex_attribute_components(*velocity), 3);
    ASSERT_EQ(mesh.vertex_attribute_default(*temperature).size(), 1u);
    EXPECT_EQ(mesh.vertex_attribute_default(*temperature)[0], 20.5);
    // existing vertices get the default, and so do new ones
    for (VertexId v = 0; v < 4; ++v) {
        EXPECT_EQ(values(mesh, *temperature, v), std::vector<double>{20.5});
        EXPECT_EQ(values(mesh, *velocity, v), (std::vector<double>{0, 0, 0}));
    }
    mesh.vertex_attribute(*temperature, 2)[0] = 100;
    const VertexId fresh = mesh.add_vertex({2, 2, 0});
    EXPECT_EQ(values(mesh, *temperature, fresh), std::vector<double>{20.5});
    EXPECT_EQ(values(mesh, *temperature, 2), std::vector<double>{100});
    // an empty default means zeros
    const auto flags = mesh.add_vertex_attribute("flags", 2);
    ASSERT_TRUE(flags.ok());
    EXPECT_EQ(values(mesh, *flags, fresh), (std::vector<double>{0, 0}));
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(VertexAttributes, RefusesBadRegistrationsAndUnknownRemovals) {
    Mesh mesh = test::unit_square();
    ASSERT_TRUE(mesh.add_vertex_attribute("temperature", 1).ok());
    const std::array<double, 2> two{1, 2};
    const auto duplicate = mesh.add_vertex_attribute("temperature", 1);
    ASSERT_FALSE(duplicate.ok());
    EXPECT_EQ(duplicate.reason(), "add_vertex_attribute: an attribute called \"temperature\" exists");
    EXPECT_EQ(duplicate.code(), RefusalCode::not_applicable);
    const auto unnamed = mesh.add_vertex_attribute("", 1);
    ASSERT_FALSE(unnamed.ok());
    EXPECT_EQ(unnamed.reason(), "add_vertex_attribute: the name is empty");
    EXPECT_EQ(unnamed.code(), RefusalCode::bad_argument);
    const auto empty = mesh.add_vertex_attribute("nothing", 0);
    ASSERT_FALSE(empty.ok());
    EXPECT_EQ(empty.reason(), "add_vertex_attribute: \"nothing\" needs at least one component, not 0");
    EXPECT_EQ(empty.code(), RefusalCode::bad_argument);
    const auto mismatch = mesh.add_vertex_attribute("velocity", 3, two);
    ASSERT_FALSE(mismatch.ok());
    EXPECT_EQ(mismatch.reason(),
              "add_vertex_attribute: \"velocity\" has 3 components but a default value of 2");
    EXPECT_EQ(mismatch.code(), RefusalCode::bad_argument);
    EXPECT_EQ(mesh.vertex_attributes().size(), 1u);
    const auto unknown = mesh.remove_vertex_attribute(7);
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.reason(), "remove_vertex_attribute: 7 is not a vertex attribute");
    EXPECT_EQ(unknown.code(), RefusalCode::not_found);
}

TEST(VertexAttributes, RemovalKeepsOtherIdsAndFreesTheName) {
    Mesh mesh = test::unit_square();
    const AttributeId a = *mesh.add_vertex_attribute("a", 1);
    const AttributeId b = *mesh.add_vertex_attribute("b", 2);
    mesh.vertex_attribute(b, 3)[1] = 5;
    ASSERT_TRUE(mesh.remove_vertex_attribute(a).ok());
    EXPECT_FALSE(mesh.is_vertex_attribute(a));
    EXPECT_EQ(mesh.find_vertex_attribute("a"), invalid_id);
    EXPECT_EQ(mesh.vertex_attributes(), std::vector<AttributeId>{b});
    EXPECT_EQ(values(mesh, b, 3), (std::vector<double>{0, 5}));
    const AttributeId again = *mesh.add_vertex_attribute("a", 1);
    EXPECT_NE(again, a);  // ids are not reused
    ASSERT_FALSE(mesh.remove_vertex_attribute(a).ok());
    mesh.add_vertex({3, 3, 0});
    EXPECT_EQ(values(mesh, b, 4), (std::vector<double>{0, 0}));
    EXPECT_EQ(values(mesh, again, 4), std::vector<double>{0});
}

//   3 ------- 2      m = 0.25 * 0 + 0.75 * 2 in both positions and every attribute
//   |       / |
//   |     m   |
//   |   /     |
//   0 ------- 1
TEST(VertexAttributes, InterpolatedVertexInterpolatesEverything) {
    Mesh mesh = test::unit_square();
    mesh.set_deformed(2, {3, 5, 0});
    const AttributeId temperature = *mesh.add_vertex_attribute("temperature", 1);
    const AttributeId velocity = *mesh.add_vertex_attribute("velocity", 3);
    mesh.vertex_attribute(temperature, 0)[0] = 10;
    mesh.vertex_attribute(temperature, 2)[0] = 50;
    const std::array<double, 3> v2{4, -8, 12};
    std::copy(v2.begin(), v2.end(), mesh.vertex_attribute(velocity, 2).begin());
    const std::array<VertexId, 2> parents{0, 2};
    const std::array<double, 2> weights{0.25, 0.75};
    const auto m = mesh.add_interpolated_vertex(parents, weights);
    ASSERT_TRUE(m.ok()) << m.reason();
    EXPECT_EQ(*m, 4u);
    EXPECT_EQ(mesh.reference(4), (Point{0.75, 0.75, 0}));
    EXPECT_EQ(mesh.deformed(4), (Point{2.25, 3.75, 0}));
    EXPECT_EQ(values(mesh, temperature, 4), std::vector<double>{40});
    EXPECT_EQ(values(mesh, velocity, 4), (std::vector<double>{3, -6, 9}));
    EXPECT_EQ(mesh.vertex_element(4), invalid_id);
    EXPECT_TRUE(mesh.validate().ok());

    // one parent with weight 1 copies bit for bit, -0.0 included
    mesh.set_reference(1, {-0.0, 0.1, 0});
    mesh.vertex_attribute(temperature, 1)[0] = -0.0;
    const std::array<VertexId, 1> one{1};
    const std::array<double, 1> whole{1.0};
    const auto copy = mesh.add_interpolated_vertex(one, whole);
    ASSERT_TRUE(copy.ok());
    EXPECT_TRUE(std::signbit(mesh.reference(*copy)[0]));
    EXPECT_TRUE(std::signbit(mesh.vertex_attribute(temperature, *copy)[0]));
    EXPECT_EQ(mesh.reference(*copy), mesh.reference(1));
}

TEST(VertexAttributes, InterpolatedVertexRefusesBadParents) {
    Mesh mesh = test::unit_square();
    ASSERT_TRUE(mesh.add_vertex_attribute("temperature", 1).ok());
    const Mesh before = mesh;
    const std::array<VertexId, 2> parents{0, 9};
    const std::array<double, 2> weights{0.5, 0.5};
    const std::array<double, 1> one_weight{1};
    const auto unknown = mesh.add_interpolated_vertex(parents, weights);
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.reason(), "add_interpolated_vertex: parent 9 is not a vertex");
    EXPECT_EQ(unknown.code(), RefusalCode::not_found);
    EXPECT_EQ(unknown.refusal().item, 1u);
    const auto sizes = mesh.add_interpolated_vertex(parents, one_weight);
    ASSERT_FALSE(sizes.ok());
    EXPECT_EQ(sizes.reason(), "add_interpolated_vertex: 2 parents but 1 weights");
    EXPECT_EQ(sizes.code(), RefusalCode::bad_argument);
    const auto none = mesh.add_interpolated_vertex({}, {});
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.reason(), "add_interpolated_vertex: 0 parents but 0 weights");
    EXPECT_EQ(none.code(), RefusalCode::bad_argument);
    expect_same_state(mesh, before);
    EXPECT_EQ(mesh.vertex_attribute(0, 3).size(), 1u);
}

TEST(VertexAttributes, RemoveLastVertexUndoesAddVertexOnly) {
    Mesh mesh = test::unit_square();
    const AttributeId temperature = *mesh.add_vertex_attribute("temperature", 1);
    const Mesh before = mesh;
    mesh.add_vertex({5, 5, 0});
    mesh.vertex_attribute(temperature, 4)[0] = 3;
    ASSERT_TRUE(mesh.remove_last_vertex().ok());
    expect_same_state(mesh, before);
    // the attribute shrank with the vertices: a new vertex gets the default again
    mesh.add_vertex({5, 5, 0});
    EXPECT_EQ(values(mesh, temperature, 4), std::vector<double>{0});
    ASSERT_TRUE(mesh.remove_last_vertex().ok());
    // vertex 3 is in an element
    const auto refused = mesh.remove_last_vertex();
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "remove_last_vertex: vertex 3 is in element 1");
    EXPECT_EQ(refused.code(), RefusalCode::not_applicable);
    expect_same_state(mesh, before);
    Mesh empty(2, 2);
    const auto nothing = empty.remove_last_vertex();
    ASSERT_FALSE(nothing.ok());
    EXPECT_EQ(nothing.reason(), "remove_last_vertex: the mesh has no vertex");
    EXPECT_EQ(nothing.code(), RefusalCode::not_found);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(VertexAttributes, CopiesMovesAndMemory) {
    Mesh mesh = test::planar_grid(3);
    const std::size_t bare = mesh.memory_bytes();
    const AttributeId velocity = *mesh.add_vertex_attribute("velocity", 3);
    EXPECT_GE(mesh.memory_bytes(), bare + mesh.vertex_count() * 3 * sizeof(double));
    mesh.vertex_attribute(velocity, 5)[2] = 7;
    Mesh copy = mesh;
    EXPECT_EQ(copy.find_vertex_attribute("velocity"), velocity);
    EXPECT_EQ(values(copy, velocity, 5), (std::vector<double>{0, 0, 7}));
    copy.vertex_attribute(velocity, 5)[2] = 8;  // copies are independent
    EXPECT_EQ(mesh.vertex_attribute(velocity, 5)[2], 7);
    Mesh assigned(2, 2);
    assigned = copy;
    EXPECT_EQ(assigned.vertex_attribute(velocity, 5)[2], 8);
    Mesh moved = std::move(assigned);
    EXPECT_EQ(moved.vertex_attribute(velocity, 5)[2], 8);
    EXPECT_EQ(moved.vertex_attributes(), std::vector<AttributeId>{velocity});
    EXPECT_TRUE(moved.validate().ok());
}

}  // namespace
}  // namespace sxk
