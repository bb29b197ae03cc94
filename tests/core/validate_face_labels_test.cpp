// validate() checks that every face label names a face of the mesh: a label keyed by a vertex
// set that no element has would be written into files that readers refuse ("triangle 1 is not a
// face of any tetrahedron"), so an operation that forgets to move labels is caught here.
#include <gtest/gtest.h>

#include "fixtures.hpp"
#include "sxk/mesh.hpp"

namespace sxk {
namespace {

//   3 ------- 2       unit_square: <0,1,2>, <0,2,3>; the edges 0-1 (boundary) and 0-2 (the
//   |       / |       interior diagonal) are faces, 1-3 is not
//   |     /   |
//   |   /     |
//   | /       |
//   0 ------- 1
TEST(ValidateFaceLabels, LabelsOfBoundaryAndInteriorFacesAreFine) {
    Mesh mesh = test::unit_square();
    mesh.face_labels()[Simplex(+1, {0, 1})] = 3;
    mesh.face_labels()[Simplex(+1, {0, 2})] = 4;
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(ValidateFaceLabels, NamesALabelOfAMissingFace) {
    Mesh mesh = test::unit_square();
    mesh.face_labels()[Simplex(+1, {1, 3})] = 7;
    const auto checked = mesh.validate();
    ASSERT_FALSE(checked.ok());
    EXPECT_EQ(checked.reason(), "face label: label 7 names +<1,3>, which is not a face of the mesh");
    EXPECT_EQ(checked.code(), RefusalCode::invalid_mesh);
}

TEST(ValidateFaceLabels, TetrahedralFaces) {
    Mesh mesh = test::kuhn_cube(1);
    const Simplex face = mesh.face_simplex(mesh.face(0, 0));
    mesh.face_labels()[Simplex(+1, face.vertices())] = 2;
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    // (0,0,0), (1,0,0), (0,1,1): not on one monotone path from corner 0 to corner 7, so no
    // Kuhn tetrahedron has this triangle
    mesh.face_labels()[Simplex(+1, {0, 1, 6})] = 5;
    const auto checked = mesh.validate();
    ASSERT_FALSE(checked.ok());
    EXPECT_EQ(checked.reason().rfind("face label: label 5 names +<0,1,6>", 0), 0u) << checked.reason();
    EXPECT_EQ(checked.code(), RefusalCode::invalid_mesh);
}

}  // namespace
}  // namespace sxk
