// Readers on hand-written files (tests/data/io): what other programs write, not what we write.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "io_fixtures.hpp"
#include "sxk/io.hpp"
#include "sxk/predicates.hpp"

namespace sxk {
namespace {

using test::data_file;
using test::element_list;
using test::face_label_list;

using List = std::vector<std::pair<Simplex, int>>;

// The mesh every two_tets.* fixture holds (see the picture in two_tets.mesh).
void expect_two_tets(const Mesh& mesh) {
    EXPECT_EQ(mesh.topological_dimension(), 3);
    EXPECT_EQ(mesh.ambient_dimension(), 3);
    ASSERT_EQ(mesh.vertex_count(), 5u);
    EXPECT_EQ(mesh.deformed(4), (Point{0, 0, -1}));
    EXPECT_EQ(mesh.reference(1), (Point{1, 0, 0}));
    EXPECT_EQ(element_list(mesh),
              (List{{Simplex(+1, {0, 1, 2, 3}), 1}, {Simplex(+1, {0, 2, 1, 4}), 2}}));
    EXPECT_EQ(face_label_list(mesh),
              (List{{Simplex(+1, {0, 1, 2}), 5}, {Simplex(+1, {0, 1, 3}), 7}}));
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(Readers, MeditKeepsElementAndFaceLabels) {
    expect_two_tets(read_mesh(data_file("io/two_tets.mesh")));
}

TEST(Readers, GmshVersion22WithSparseTagsAndPhysicalNames) {
    expect_two_tets(read_mesh(data_file("io/two_tets22.msh")));
}

TEST(Readers, GmshVersion41WithEntitiesAndParametricNodes) {
    expect_two_tets(read_mesh(data_file("io/two_tets41.msh")));
}

TEST(Readers, TetgenOneBasedWithAttributesMarkersAndAdjacency) {
    expect_two_tets(read_mesh(data_file("io/two_tets.ele")));
    expect_two_tets(read_mesh(data_file("io/two_tets.node")));
}

TEST(Readers, MeditPlanarSquare) {
    const Mesh mesh = read_mesh(data_file("io/square.mesh"));
    EXPECT_EQ(mesh.topological_dimension(), 2);
    EXPECT_EQ(mesh.ambient_dimension(), 2);
    EXPECT_EQ(element_list(mesh), (List{{Simplex(+1, {0, 1, 2}), 1}, {Simplex(+1, {0, 2, 3}), 2}}));
    EXPECT_EQ(face_label_list(mesh), (List{{Simplex(+1, {0, 1}), 10}, {Simplex(+1, {0, 2}), 11}}));
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(Readers, ObjCornerFormsAndNegativeIndices) {
    const Mesh mesh = read_mesh(data_file("io/square.obj"));
    EXPECT_EQ(mesh.topological_dimension(), 2);
    EXPECT_EQ(mesh.ambient_dimension(), 2);  // every z is 0
    EXPECT_EQ(element_list(mesh), (List{{Simplex(+1, {0, 1, 2}), 0}, {Simplex(+1, {0, 2, 3}), 0}}));
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(Readers, OffClosedSurfaceWithColours) {
    const Mesh mesh = read_mesh(data_file("io/tetra.off"));
    EXPECT_EQ(mesh.topological_dimension(), 2);
    EXPECT_EQ(mesh.ambient_dimension(), 3);
    EXPECT_EQ(mesh.element_count(), 4u);
    EXPECT_EQ(mesh.boundary_face_count(), 0u);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(Readers, ReorientFlipsAndCounts) {
    // tetrahedron 1 3 2 4 is negative; with reorient it becomes +<0,1,2,3>
    const std::string text =
        "MeshVersionFormatted 2\nDimension 3\nVertices 5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
        "0 0 -1 0\nTetrahedra 2\n1 3 2 4 0\n1 2 3 5 0\nEnd\n";
    std::istringstream refused(text);
    try {
        (void)read_mesh(refused, Format::medit, "flip.mesh");
        FAIL() << "read an inverted mesh";
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(), "flip.mesh:10: element 1 is inverted");
        EXPECT_EQ(error.file(), "flip.mesh");
        EXPECT_EQ(error.line(), 10u);
        EXPECT_EQ(error.reason(), "element 1 is inverted");
    }
    std::istringstream in(text);
    ReadOptions options;
    options.reorient = true;
    ReadReport report;
    const Mesh mesh = read_mesh(in, Format::medit, "flip.mesh", options, &report);
    EXPECT_EQ(report.reoriented, 2u);
    EXPECT_EQ(element_list(mesh),
              (List{{Simplex(+1, {0, 1, 2, 3}), 0}, {Simplex(+1, {0, 2, 1, 4}), 0}}));
    for (ElementId t : elements(mesh))
        EXPECT_EQ(element_orientation(mesh, t), Sign::positive);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(Readers, ReorientPlanarTriangles) {
    // clockwise square from OFF, z = 0: planar, so orientation is checked and can be repaired
    const std::string text = "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 2 1\n3 0 3 2\n";
    std::istringstream refused(text);
    EXPECT_THROW((void)read_mesh(refused, Format::off, "cw.off"), InputError);
    std::istringstream in(text);
    ReadOptions options;
    options.reorient = true;
    ReadReport report;
    const Mesh mesh = read_mesh(in, Format::off, "cw.off", options, &report);
    EXPECT_EQ(report.reoriented, 2u);
    EXPECT_EQ(mesh.ambient_dimension(), 2);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(Readers, FlatElementsAreAccepted) {
    // four coplanar points: orientation zero is not "inverted" (degeneracy is a plug-in's job)
    std::istringstream in(
        "MeshVersionFormatted 2\nDimension 3\nVertices 4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n1 1 0 0\n"
        "Tetrahedra 1\n1 2 3 4 0\nEnd\n");
    const Mesh mesh = read_mesh(in, Format::medit, "flat.mesh");
    EXPECT_EQ(mesh.element_count(), 1u);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(Readers, SurfaceTrianglesAreNotOrientationChecked) {
    // a triangle surface in 3D has no inside: either orientation reads
    std::istringstream in("v 0 0 1\nv 0 1 0\nv 1 0 0\nf 1 2 3\n");
    const Mesh mesh = read_mesh(in, Format::obj, "s.obj");
    EXPECT_EQ(mesh.ambient_dimension(), 3);
    EXPECT_EQ(mesh.element_count(), 1u);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(Readers, AmbientDimensionRule) {
    // x y z formats: planar when triangles and every z is exactly 0 (-0.0 counts, and is
    // stored as +0); Medit says its dimension, so Dimension 3 with z = 0 stays 3D
    std::istringstream planar("v 0 0 -0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const Mesh a = read_mesh(planar, Format::obj, "a.obj");
    EXPECT_EQ(a.ambient_dimension(), 2);
    EXPECT_FALSE(std::signbit(a.deformed(0)[2]));
    std::istringstream lifted("v 0 0 0\nv 1 0 0\nv 0 1 1e-300\nf 1 2 3\n");
    EXPECT_EQ(read_mesh(lifted, Format::obj, "b.obj").ambient_dimension(), 3);
    std::istringstream medit(
        "MeshVersionFormatted 2\nDimension 3\nVertices 3\n0 0 0 0\n1 0 0 0\n0 1 0 0\nTriangles 1\n"
        "1 2 3 0\nEnd\n");
    EXPECT_EQ(read_mesh(medit, Format::medit, "c.mesh").ambient_dimension(), 3);
}

TEST(Readers, NumbersInEveryNotation) {
    // leading '+', exponents, no leading digit, underflow to zero; CRLF line ends; UTF-8 comment
    std::istringstream in(
        "\xEF\xBB\xBFMeshVersionFormatted 2\r\nDimension 3 # d\xC3\xA9j\xC3\xA0 vu\r\nVertices "
        "4\r\n"
        "+0 .0 0. 0\r\n1E0 0 1e-400 0\r\n0 +1.0e+0 0 0\r\n0 0 10e-1 0\r\nTetrahedra 1\r\n"
        "1 2 3 4 +3\r\nEnd\r\n");
    const Mesh mesh = read_mesh(in, Format::medit, "n.mesh");
    EXPECT_EQ(mesh.deformed(1), (Point{1, 0, 0}));
    EXPECT_EQ(mesh.deformed(2), (Point{0, 1, 0}));
    EXPECT_EQ(mesh.deformed(3), (Point{0, 0, 1}));
    EXPECT_EQ(mesh.label(0), 3);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(Readers, UnusedVerticesAreKept) {
    std::istringstream in("OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n5 5 5\n3 0 1 2\n");
    const Mesh mesh = read_mesh(in, Format::off, "u.off");
    EXPECT_EQ(mesh.vertex_count(), 4u);
    EXPECT_EQ(mesh.vertex_element(3), invalid_id);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(Readers, TetgenZeroBasedFromStreams) {
    std::istringstream node("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
    std::istringstream ele("1 4 0\n0 0 1 2 3\n");
    const Mesh mesh = read_tetgen(node, "t.node", ele, "t.ele");
    EXPECT_EQ(element_list(mesh), (List{{Simplex(+1, {0, 1, 2, 3}), 0}}));
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(Readers, TetgenTwoDimensionalNodesMakeAPlanarMesh) {
    std::istringstream node("3 2\n1 0 0\n2 1 0\n3 0 1\n");
    std::istringstream ele("1 3 0\n1 1 2 3\n");
    const Mesh mesh = read_tetgen(node, "t.node", ele, "t.ele");
    EXPECT_EQ(mesh.topological_dimension(), 2);
    EXPECT_EQ(mesh.ambient_dimension(), 2);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(Readers, FormatFromExtension) {
    EXPECT_EQ(format_from_extension("a/b.mesh"), Format::medit);
    EXPECT_EQ(format_from_extension("b.MSH"), Format::gmsh);
    EXPECT_EQ(format_from_extension("b.1.node"), Format::tetgen);
    EXPECT_EQ(format_from_extension("b.ele"), Format::tetgen);
    EXPECT_EQ(format_from_extension("b.off"), Format::off);
    EXPECT_EQ(format_from_extension("b.obj"), Format::obj);
    EXPECT_EQ(format_from_extension("b.vtu"), Format::vtu);
    EXPECT_EQ(format_from_extension("b.vtk"), Format::vtk);
    EXPECT_EQ(format_from_extension("b.STL"), Format::stl);
    EXPECT_EQ(format_from_extension("b.ply"), Format::ply);
    EXPECT_EQ(format_from_extension("b.vtm"), std::nullopt);
    EXPECT_EQ(format_from_extension("mesh"), std::nullopt);
    EXPECT_EQ(to_string(Format::gmsh), "gmsh");
    EXPECT_EQ(to_string(Format::tetgen), "tetgen");
}

TEST(Readers, StreamErrorsNameTheStream) {
    std::istringstream empty("  \n\t\n");
    try {
        (void)read_mesh(empty, Format::gmsh, "<stdin>");
        FAIL();
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(), "<stdin>:0: empty file");
    }
    std::istringstream tetgen("1 3 0 0\n");
    try {
        (void)read_mesh(tetgen, Format::tetgen, "x.node");
        FAIL();
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(),
                     "x.node:0: TetGen meshes need a .node and an .ele stream (read_tetgen)");
    }
}

TEST(Readers, TetgenHeaderDefaultsAndFaceFileBesideIt) {
    // ".ele" header with the count only: 4 nodes per element, no attributes (TetGen's
    // defaults), so the labelled faces come from X.face
    const auto dir = test::scratch_dir();
    std::ofstream(dir / "d.node") << "4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
    std::ofstream(dir / "d.ele") << "1\n1 1 2 3 4\n";
    std::ofstream(dir / "d.face") << "1 1\n1 3 2 1 -4\n";
    std::ofstream(dir / "d.edge") << "this file belongs to triangle meshes and is not read\n";
    const Mesh mesh = read_mesh(dir / "d.ele");
    EXPECT_EQ(element_list(mesh), (List{{Simplex(+1, {0, 1, 2, 3}), 0}}));
    EXPECT_EQ(face_label_list(mesh), (List{{Simplex(+1, {0, 1, 2}), -4}}));
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(Readers, Gmsh41WithoutEntitiesHasNoLabels) {
    std::istringstream in(
        "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n"
        "1 0 0\n0 1 0\n$EndNodes\n$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n");
    const Mesh mesh = read_mesh(in, Format::gmsh, "e.msh");
    EXPECT_EQ(mesh.ambient_dimension(), 2);
    EXPECT_EQ(element_list(mesh), (List{{Simplex(+1, {0, 1, 2}), 0}}));
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(Readers, MissingFileAndFolder) {
    try {
        (void)read_mesh(data_file("io"));  // a folder, and no extension
        FAIL();
    } catch (const InputError& error) {
        EXPECT_EQ(error.line(), 0u);
        EXPECT_EQ(error.reason(),
                  "unknown mesh file extension '' (known: .mesh .msh .node .ele .off .obj .vtu .vtk .stl .ply)");
    }
    const auto dir = test::scratch_dir();
    std::filesystem::create_directories(dir / "folder.mesh");
    try {
        (void)read_mesh(dir / "folder.mesh");
        FAIL();
    } catch (const InputError& error) {
        EXPECT_EQ(error.reason(), "is a directory");
    }
}

}  // namespace
}  // namespace sxk
