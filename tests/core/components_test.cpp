// connected_components: face-adjacency components through Boost.Graph.
#include <gtest/gtest.h>

#include <array>

#include "sxk/components.hpp"
#include "sxk/mesh.hpp"

namespace sxk::test {
namespace {

//   3        7
//   |\       |\        two tetrahedra <0,1,2,3> and <4,5,6,7> far apart, and a third
//   0-2      4-6       <1,2,3,8> glued to the first along face 1-2-3
//    \|       \|
//     1        5
Mesh three_tetrahedra() {
    Mesh mesh(3, 3);
    for (const Point& p : std::array<Point, 9>{Point{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 0, 0},
                                               {6, 0, 0}, {5, 1, 0}, {5, 0, 1}, {1, 1, 1}})
        mesh.add_vertex(p);
    const std::array<Simplex, 3> tetrahedra{Simplex(+1, {0, 1, 2, 3}), Simplex(+1, {4, 5, 6, 7}),
                                            Simplex(+1, {1, 2, 3, 8})};
    EXPECT_TRUE(mesh.assign_elements(tetrahedra).ok());
    return mesh;
}

TEST(ConnectedComponents, EmptyMeshHasNone) {
    const Components components = connected_components(Mesh(3, 3));
    EXPECT_EQ(components.count, 0u);
    EXPECT_TRUE(components.element_component.empty());
}

TEST(ConnectedComponents, FaceNeighboursShareAComponent) {
    const Mesh mesh = three_tetrahedra();
    ASSERT_TRUE(mesh.validate().ok());
    const Components components = connected_components(mesh);
    EXPECT_EQ(components.count, 2u);
    EXPECT_EQ(components.element_component, (std::vector<std::uint32_t>{0, 1, 0}));
}

TEST(ConnectedComponents, DeadElementsHaveNoComponent) {
    Mesh mesh = three_tetrahedra();
    const std::array<ElementId, 1> removed{2};
    ASSERT_TRUE(mesh.replace_elements(removed, {}).ok());
    ASSERT_TRUE(mesh.validate().ok());
    const Components components = connected_components(mesh);
    EXPECT_EQ(components.count, 2u);
    ASSERT_EQ(components.element_component.size(), mesh.element_capacity());
    EXPECT_EQ(components.element_component[0], 0u);
    EXPECT_EQ(components.element_component[1], 1u);
    if (mesh.element_capacity() > 2) {
        EXPECT_EQ(components.element_component[2], invalid_id);
    }
}

TEST(ConnectedComponents, PlanarStrip) {
    // a strip of 2 n triangles is one component; cutting out the middle pair splits it
    const int n = 6;
    Mesh mesh(2, 2);
    for (int i = 0; i <= n; ++i) {
        mesh.add_vertex({double(i), 0, 0});
        mesh.add_vertex({double(i), 1, 0});
    }
    std::vector<Simplex> triangles;
    for (int i = 0; i < n; ++i) {
        const VertexId a = VertexId(2 * i), b = a + 2, c = a + 3, d = a + 1;
        triangles.push_back(Simplex(+1, {a, b, c}));
        triangles.push_back(Simplex(+1, {a, c, d}));
    }
    ASSERT_TRUE(mesh.assign_elements(triangles).ok());
    EXPECT_EQ(connected_components(mesh).count, 1u);
    const std::array<ElementId, 2> middle{6, 7};
    ASSERT_TRUE(mesh.replace_elements(middle, {}).ok());
    EXPECT_EQ(connected_components(mesh).count, 2u);
}

}  // namespace
}  // namespace sxk::test
