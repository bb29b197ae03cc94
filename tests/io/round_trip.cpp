// write -> read gives the same mesh: connectivity, labels, face labels, and positions bit for
// bit, in every format that can hold the mesh.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io_fixtures.hpp"
#include "sxk/io.hpp"

namespace sxk {
namespace {

using test::expect_same_mesh;
using test::planar_triangles;
using test::scratch_dir;
using test::tetrahedron_surface;
using test::two_tetrahedra;

Mesh write_then_read(const Mesh& mesh, const std::string& file_name,
                     const WriteOptions& options = {}) {
    const auto path = scratch_dir() / file_name;
    write_mesh(mesh, path, options);
    return read_mesh(path);
}

TEST(RoundTrip, MeditTetrahedra) {
    const Mesh mesh = two_tetrahedra();
    expect_same_mesh(mesh, write_then_read(mesh, "two.mesh"));
}

TEST(RoundTrip, MeditPlanarTriangles) {
    const Mesh mesh = planar_triangles();
    expect_same_mesh(mesh, write_then_read(mesh, "square.mesh"));
}

TEST(RoundTrip, MeditSurface) {
    const Mesh mesh = tetrahedron_surface();
    expect_same_mesh(mesh, write_then_read(mesh, "surface.mesh"));
}

TEST(RoundTrip, Gmsh41Tetrahedra) {
    const Mesh mesh = two_tetrahedra();
    expect_same_mesh(mesh, write_then_read(mesh, "two.msh"));
}

TEST(RoundTrip, Gmsh22Tetrahedra) {
    const Mesh mesh = two_tetrahedra();
    WriteOptions options;
    options.gmsh_version = 22;
    expect_same_mesh(mesh, write_then_read(mesh, "two.msh", options));
}

TEST(RoundTrip, GmshPlanarTrianglesBothVersions) {
    const Mesh mesh = planar_triangles();
    for (int version : {22, 41}) {
        WriteOptions options;
        options.gmsh_version = version;
        expect_same_mesh(mesh, write_then_read(mesh, "square.msh", options));
    }
}

TEST(RoundTrip, GmshSurface) {
    const Mesh mesh = tetrahedron_surface();
    expect_same_mesh(mesh, write_then_read(mesh, "surface.msh"));
}

TEST(RoundTrip, GmshLabelZeroAndUnlabelledEntities) {
    // label 0 means "no physical tag": an entity without one reads back as 0
    Mesh mesh = two_tetrahedra();
    mesh.set_label(0, 0);
    mesh.face_labels()[Simplex(+1, {0, 1, 3})] = 0;
    expect_same_mesh(mesh, write_then_read(mesh, "zero.msh"));
}

TEST(RoundTrip, TetgenTetrahedra) {
    const Mesh mesh = two_tetrahedra();
    const auto dir = scratch_dir();
    write_mesh(mesh, dir / "two.ele");
    EXPECT_TRUE(std::filesystem::exists(dir / "two.node"));
    EXPECT_TRUE(std::filesystem::exists(dir / "two.face"));
    expect_same_mesh(mesh, read_mesh(dir / "two.node"));
    expect_same_mesh(mesh, read_mesh(dir / "two.ele"));
}

TEST(RoundTrip, TetgenWithoutLabelsWritesThePlainBoundary) {
    Mesh mesh = two_tetrahedra();
    mesh.face_labels().clear();
    mesh.set_label(0, 0);
    mesh.set_label(1, 0);
    const auto dir = scratch_dir();
    write_mesh(mesh, dir / "plain.node");
    std::ifstream face(dir / "plain.face");
    std::size_t count = 0, markers = 9;
    face >> count >> markers;
    EXPECT_EQ(count, mesh.boundary_face_count());
    EXPECT_EQ(markers, 0u);
    expect_same_mesh(mesh, read_mesh(dir / "plain.ele"));
}

TEST(RoundTrip, TetgenPlanarTrianglesUseEdgeFile) {
    const Mesh mesh = planar_triangles();
    const auto dir = scratch_dir();
    write_mesh(mesh, dir / "square.node");
    EXPECT_TRUE(std::filesystem::exists(dir / "square.edge"));
    expect_same_mesh(mesh, read_mesh(dir / "square.ele"));
}

TEST(RoundTrip, OffAndObjTriangles) {
    for (const char* name : {"surface.off", "surface.obj"}) {
        const Mesh mesh = tetrahedron_surface();
        expect_same_mesh(mesh, write_then_read(mesh, name), false);
    }
    for (const char* name : {"square.off", "square.obj"}) {
        const Mesh mesh = planar_triangles();
        expect_same_mesh(mesh, write_then_read(mesh, name), false);
    }
}

TEST(RoundTrip, OffAndObjOfTetrahedraHoldTheBoundarySurface) {
    const Mesh mesh = two_tetrahedra();
    for (const char* name : {"boundary.off", "boundary.obj"}) {
        const Mesh surface = write_then_read(mesh, name);
        EXPECT_EQ(surface.topological_dimension(), 2);
        EXPECT_EQ(surface.ambient_dimension(), 3);
        EXPECT_EQ(surface.vertex_count(), 5u);  // all five vertices are on the boundary
        ASSERT_EQ(surface.element_count(), mesh.boundary_face_count());
        // vertices keep their order (compact renumbering of the used ones), so the triangles
        // are exactly the boundary faces, outward oriented
        std::vector<Simplex> expected, actual;
        for (FaceId f : mesh.boundary_faces())
            expected.push_back(mesh.face_simplex(f));
        for (ElementId t : elements(surface))
            actual.push_back(surface.simplex(t));
        std::sort(expected.begin(), expected.end());
        std::sort(actual.begin(), actual.end());
        EXPECT_EQ(expected, actual);
        EXPECT_EQ(surface.boundary_face_count(), 0u);  // closed
        EXPECT_TRUE(surface.validate().ok()) << surface.validate().reason();
    }
}

TEST(RoundTrip, BoundaryRenumbersCompactly) {
    // an interior vertex (5, inside the big tetrahedron) is not on the boundary surface
    Mesh mesh(3, 3);
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({4, 0, 0});
    mesh.add_vertex({0, 4, 0});
    mesh.add_vertex({0, 0, 4});
    mesh.add_vertex({1, 1, 1});
    // star of vertex 4: the four tetrahedra (face, 4), each face of <0,1,2,3> joined to 4
    const Simplex simplexes[] = {Simplex(+1, {4, 1, 2, 3}), Simplex(+1, {0, 4, 2, 3}),
                                 Simplex(+1, {0, 1, 4, 3}), Simplex(+1, {0, 1, 2, 4})};
    ASSERT_TRUE(mesh.assign_elements(simplexes).ok());
    ASSERT_TRUE(mesh.validate().ok());
    const Mesh surface = write_then_read(mesh, "star.obj");
    EXPECT_EQ(surface.vertex_count(), 4u);
    EXPECT_EQ(surface.element_count(), 4u);
    EXPECT_TRUE(surface.validate().ok()) << surface.validate().reason();
}

TEST(RoundTrip, ReferencePositionsOnRequest) {
    Mesh mesh = two_tetrahedra();
    Mesh expected = two_tetrahedra();
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        Point p = mesh.deformed(v);
        p[0] += 0.5;
        mesh.set_deformed(v, p);
    }
    WriteOptions options;
    options.positions = Positions::reference;
    expect_same_mesh(expected, write_then_read(mesh, "reference.mesh", options));
    // the default writes the deformed shape
    const Mesh deformed = write_then_read(mesh, "deformed.mesh");
    EXPECT_EQ(deformed.deformed(0)[0], mesh.deformed(0)[0]);
    EXPECT_EQ(deformed.reference(0)[0], mesh.deformed(0)[0]);
}

TEST(RoundTrip, ExtremeCoordinatesSurviveEveryFormat) {
    // large and tiny magnitudes, negative zero: shortest round-trip text must keep them all
    Mesh mesh(3, 3);
    mesh.add_vertex({-0.0, 1e-300, 2.2250738585072014e-308});
    mesh.add_vertex({1.7976931348623157e308, 1e-300, 0});
    mesh.add_vertex({0, 1e300, 0});
    mesh.add_vertex({0, 1e-300, 1e300});
    const Simplex simplexes[] = {Simplex(+1, {0, 1, 2, 3})};
    ASSERT_TRUE(mesh.assign_elements(simplexes).ok());
    for (const char* name : {"big.mesh", "big.msh", "big.node"}) {
        SCOPED_TRACE(name);
        expect_same_mesh(mesh, write_then_read(mesh, name));
    }
}

TEST(RoundTrip, StreamsReadWhatFilesHold) {
    const Mesh mesh = two_tetrahedra();
    const auto path = scratch_dir() / "stream.mesh";
    write_mesh(mesh, path);
    std::ifstream in(path);
    expect_same_mesh(mesh, read_mesh(in, Format::medit, "stream.mesh"));
    const auto dir = path.parent_path();
    write_mesh(mesh, dir / "stream.node");
    std::ifstream node(dir / "stream.node"), ele(dir / "stream.ele");
    // read_tetgen has no .face stream: the face labels are not read
    const Mesh read = read_tetgen(node, "stream.node", ele, "stream.ele");
    EXPECT_EQ(test::element_list(mesh), test::element_list(read));
    EXPECT_TRUE(read.face_labels().empty());
    EXPECT_TRUE(read.validate().ok());
}

// .vtu and .vtk: tests/io/vtk_formats.cpp

TEST(RoundTrip, WriterRefusals) {
    const Mesh mesh = two_tetrahedra();
    EXPECT_THROW(write_mesh(mesh, scratch_dir() / "x.unknown"), OutputError);
    EXPECT_THROW(write_mesh(mesh, "/nonexistent-folder/x.mesh"), OutputError);
    WriteOptions options;
    options.gmsh_version = 30;
    EXPECT_THROW(write_mesh(mesh, scratch_dir() / "x.msh", options), OutputError);
}

}  // namespace
}  // namespace sxk
