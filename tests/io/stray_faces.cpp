// Labelled faces that are no face of any element (ReadOptions::drop_stray_faces): CGAL's Mesh_3
// writes surface facets whose cells lie outside the complex. They are dropped and reported by
// default, refused with the old message when the option is off, and kept by a lenient read so
// that validate() names them.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "sxk/io.hpp"

namespace sxk {
namespace {

// One tetrahedron 1 2 3 4 with two labelled triangles: 1 2 3 is its face, 1 2 5 and 2 3 5 are
// faces of nothing (vertex 5 is in no element).
const char* stray_mesh = R"(MeshVersionFormatted 2
Dimension 3
Vertices
5
0 0 0 0
1 0 0 0
0 1 0 0
0 0 1 0
5 5 5 0
Triangles
3
1 2 3 1
1 2 5 2
2 3 5 2
Tetrahedra
1
1 2 3 4 0
End
)";

TEST(StrayFaces, AreDroppedAndReported) {
    std::istringstream in(stray_mesh);
    ReadReport report;
    const Mesh mesh = read_mesh(in, Format::medit, "stray.mesh", {}, &report);
    EXPECT_EQ(report.stray_faces, 2u);
    EXPECT_EQ(report.first_stray_face, "stray.mesh:13: triangle 2 is not a face of any tetrahedron");
    ASSERT_EQ(mesh.face_labels().size(), 1u);
    EXPECT_EQ(mesh.face_labels().at(Simplex(+1, {0, 1, 2})), 1);
    EXPECT_EQ(mesh.vertex_count(), 5u);  // the vertex stays: ids are the file's
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(StrayFaces, AreRefusedWhenNotDropped) {
    std::istringstream in(stray_mesh);
    ReadOptions options;
    options.drop_stray_faces = false;
    try {
        (void)read_mesh(in, Format::medit, "stray.mesh", options);
        FAIL() << "read";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()), "stray.mesh:13: triangle 2 is not a face of any tetrahedron");
    }
}

TEST(StrayFaces, ALenientReadKeepsThemForValidate) {
    std::istringstream in(stray_mesh);
    ReadOptions options;
    options.lenient = true;
    const Mesh mesh = read_mesh(in, Format::medit, "stray.mesh", options);
    EXPECT_EQ(mesh.face_labels().size(), 3u);
    const Outcome<Done> valid = mesh.validate();
    ASSERT_FALSE(valid.ok());
    EXPECT_EQ(valid.reason().rfind("face label: label 2 names ", 0), 0u) << valid.reason();
    EXPECT_EQ(valid.code(), RefusalCode::invalid_mesh);
}

}  // namespace
}  // namespace sxk
