// Mesh::compact_vertices: vertices in no element go, the rest are renamed in order.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "fixtures.hpp"
#include "sxk/mesh.hpp"

namespace sxk {
namespace {

TEST(CompactVertices, DropsTheVerticesInNoElementAndRenamesTheRest) {
    Mesh mesh = test::unit_square();  // <0,1,2>, <0,2,3>
    const AttributeId heat = *mesh.add_vertex_attribute("heat", 1);
    mesh.add_vertex({5, 5, 0});  // 4: in no element
    // and 3 in no element once <0,2,3> is gone
    const std::array<ElementId, 1> gone{1};
    ASSERT_TRUE(mesh.replace_elements(gone, {}).ok());
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const std::array<double, 1> value{double(v)};
        ASSERT_TRUE(mesh.set_vertex_attribute(heat, v, value).ok());
    }
    mesh.set_face_label(Simplex(+1, {1, 2}), 7);
    const auto renamed = mesh.compact_vertices();
    ASSERT_TRUE(renamed.ok()) << renamed.reason();
    EXPECT_EQ(*renamed, (std::vector<VertexId>{0, 1, 2, invalid_id, invalid_id}));
    EXPECT_EQ(mesh.vertex_count(), 3u);
    EXPECT_EQ(mesh.simplex(0), Simplex(+1, {0, 1, 2}));
    EXPECT_EQ(mesh.vertex_attribute(heat, 2)[0], 2.0);
    EXPECT_EQ(mesh.face_label(Simplex(+1, {1, 2})), 7);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(CompactVertices, RenamesVerticesAfterAGap) {
    Mesh mesh(2, 2);
    mesh.add_vertex({9, 9, 0});  // 0: in no element
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({1, 0, 0});
    mesh.add_vertex({0, 1, 0});
    const std::array<Simplex, 1> triangle{Simplex(+1, {1, 2, 3})};
    ASSERT_TRUE(mesh.assign_elements(triangle).ok());
    mesh.set_face_label(Simplex(+1, {2, 3}), 4);
    const auto renamed = mesh.compact_vertices();
    ASSERT_TRUE(renamed.ok());
    EXPECT_EQ(*renamed, (std::vector<VertexId>{invalid_id, 0, 1, 2}));
    EXPECT_EQ(mesh.simplex(0), Simplex(+1, {0, 1, 2}));
    EXPECT_EQ(mesh.reference(0), (Point{0, 0, 0}));
    EXPECT_EQ(mesh.face_label(Simplex(+1, {1, 2})), 4);
    EXPECT_EQ(mesh.find_boundary_face(Simplex(+1, {0, 1})), mesh.face(0, 2));
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

}  // namespace
}  // namespace sxk
