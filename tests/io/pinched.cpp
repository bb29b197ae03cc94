// Pinched vertices (a vertex whose star is several fans touching only at it) are split on
// reading into one vertex per face-connected piece of the star (thesis §7.3, the
// (v,{})-components of dissection); ReadOptions::split_pinched = false refuses them as before,
// and a lenient read keeps them for validate() to name. Medit faces listed twice (CGAL writes
// every boundary triangle once per orientation) are one labelled face.
#include <gtest/gtest.h>

#include <sstream>

#include "io_fixtures.hpp"
#include "sxk/io.hpp"

namespace sxk {
namespace {

using test::data_file;
using test::element_list;
using test::expect_same_mesh;
using test::face_label_list;
using test::scratch_dir;

using List = std::vector<std::pair<Simplex, int>>;
using Copies = std::vector<std::pair<VertexId, VertexId>>;

// Elements in the mesh's own order (ids are file order), as (simplex, label).
List elements_in_order(const Mesh& mesh) {
    List list;
    for (ElementId t : elements(mesh))
        list.emplace_back(mesh.simplex(t), mesh.label(t));
    return list;
}

// tests/data/io/pinched.mesh: vertex 1 (id 0) joins the fan {element 1, element 3} and element 2.
TEST(PinchedVertices, MeditTetrahedraSplitIntoOneVertexPerPiece) {
    ReadReport report;
    const Mesh mesh = read_mesh(data_file("io/pinched.mesh"), {}, &report);
    EXPECT_EQ(report.pinched_vertices, 1u);
    EXPECT_EQ(report.vertex_copies, (Copies{{0, 8}}));
    ASSERT_EQ(mesh.vertex_count(), 9u);
    EXPECT_EQ(mesh.reference(8), (Point{0, 0, 0}));
    EXPECT_EQ(mesh.deformed(8), (Point{0, 0, 0}));
    // element order and labels kept; element 2 (the later piece) has the copy
    EXPECT_EQ(elements_in_order(mesh), (List{{Simplex(+1, {0, 4, 6, 5}), 2},
                                             {Simplex(+1, {8, 1, 2, 3}), 1},
                                             {Simplex(+1, {0, 4, 5, 7}), 3}}));
    // triangle 1-2-3 (listed twice, same reference) follows element 2 to the copy; 1-5-6 stays
    EXPECT_EQ(face_label_list(mesh), (List{{Simplex(+1, {0, 4, 5}), 12},
                                           {Simplex(+1, {1, 2, 3}), 13},
                                           {Simplex(+1, {1, 2, 8}), 11}}));
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(PinchedVertices, PlanarTrianglesAndTheirEdgeLabels) {
    ReadReport report;
    const Mesh mesh = read_mesh(data_file("io/pinched_planar.mesh"), {}, &report);
    EXPECT_EQ(report.pinched_vertices, 1u);
    EXPECT_EQ(report.vertex_copies, (Copies{{0, 5}}));
    EXPECT_EQ(mesh.ambient_dimension(), 2);
    ASSERT_EQ(mesh.vertex_count(), 6u);
    EXPECT_EQ(mesh.reference(5), (Point{0, 0, 0}));
    EXPECT_EQ(elements_in_order(mesh),
              (List{{Simplex(+1, {0, 1, 2}), 1}, {Simplex(+1, {5, 3, 4}), 2}}));
    EXPECT_EQ(face_label_list(mesh), (List{{Simplex(+1, {0, 1}), 7}, {Simplex(+1, {3, 5}), 8}}));
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(PinchedVertices, OffSurfaceWithTwoPinchedVertices) {
    // the split is in the common build step: OFF (numbered from 0) splits the same way
    ReadReport report;
    const Mesh mesh = read_mesh(data_file("io/pinched_surface.off"), {}, &report);
    EXPECT_EQ(report.pinched_vertices, 2u);
    // vertex 0: the first surface keeps it, the second gets 10; vertex 6: the second surface
    // (triangle 5 comes first) keeps it, the third gets 11
    EXPECT_EQ(report.vertex_copies, (Copies{{0, 10}, {6, 11}}));
    ASSERT_EQ(mesh.vertex_count(), 12u);
    EXPECT_EQ(mesh.reference(10), mesh.reference(0));
    EXPECT_EQ(mesh.reference(11), mesh.reference(6));
    const List elements = elements_in_order(mesh);
    ASSERT_EQ(elements.size(), 12u);
    EXPECT_EQ(elements[1].first, Simplex(+1, {0, 3, 2}));
    EXPECT_EQ(elements[5].first, Simplex(+1, {10, 6, 5}));
    EXPECT_EQ(elements[9].first, Simplex(+1, {11, 9, 8}));
    EXPECT_EQ(mesh.boundary_face_count(), 0u);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(PinchedVertices, StrictRefusesWithTheVertexOnItsLine) {
    ReadOptions strict;
    strict.split_pinched = false;
    const std::string file = data_file("io/pinched.mesh").string();
    try {
        read_mesh(file, strict);
        FAIL() << "a pinched vertex was read with split_pinched = false";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  file +
                      ":11: vertex 1 is non-manifold: the elements around it are not connected "
                      "through faces");
    }
}

TEST(PinchedVertices, LenientReadKeepsThemForValidate) {
    ReadOptions lenient;
    lenient.lenient = true;
    ReadReport report;
    const Mesh mesh = read_mesh(data_file("io/pinched.mesh"), lenient, &report);
    EXPECT_EQ(report.pinched_vertices, 0u);
    EXPECT_EQ(mesh.vertex_count(), 8u);
    EXPECT_EQ(mesh.validate().reason(),
              "star connectivity: the star of vertex 0 is not face-connected (2 of its 3 elements "
              "are reachable from element 0; the mesh is pinched at this vertex)");
    EXPECT_EQ(mesh.validate().code(), RefusalCode::invalid_mesh);
}

TEST(PinchedVertices, NoReportNoSplitWithoutPinchedVertices) {
    ReadReport report;
    const Mesh mesh = read_mesh(data_file("io/two_tets.mesh"), {}, &report);
    EXPECT_EQ(mesh.vertex_count(), 5u);
    EXPECT_EQ(report.pinched_vertices, 0u);
    EXPECT_TRUE(report.vertex_copies.empty());
}

// After the split the copies are vertices of their own: every writer writes them, and reading
// the file back gives the same mesh with nothing left to split.
TEST(PinchedVertices, SplitMeshRoundTripsThroughEveryWriter) {
    const Mesh tetrahedra = read_mesh(data_file("io/pinched.mesh"));
    const Mesh planar = read_mesh(data_file("io/pinched_planar.mesh"));
    const Mesh surface = read_mesh(data_file("io/pinched_surface.off"));
    struct Case {
        const Mesh& mesh;
        const char* file;
        int gmsh_version;
        bool labels;  // OFF and OBJ have none
    };
    const Case cases[] = {
        {tetrahedra, "t.mesh", 41, true}, {tetrahedra, "t.msh", 41, true},
        {tetrahedra, "t.msh", 22, true},  {tetrahedra, "t.node", 41, true},
        {planar, "p.mesh", 41, true},     {planar, "p.msh", 41, true},
        {planar, "p.msh", 22, true},      {planar, "p.node", 41, true},
        {planar, "p.off", 41, false},     {planar, "p.obj", 41, false},
        {surface, "s.mesh", 41, true},    {surface, "s.msh", 41, true},
        {surface, "s.off", 41, false},    {surface, "s.obj", 41, false},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::string(c.file) + " " + std::to_string(c.gmsh_version));
        WriteOptions options;
        options.gmsh_version = c.gmsh_version;
        const auto path = scratch_dir() / c.file;
        write_mesh(c.mesh, path, options);
        ReadReport report;
        const Mesh back = read_mesh(path, {}, &report);
        EXPECT_EQ(report.pinched_vertices, 0u);
        expect_same_mesh(c.mesh, back, c.labels);
        EXPECT_TRUE(back.validate().ok()) << back.validate().reason();
    }
}

// A CGAL Mesh_3 output with pinched vertices and every boundary triangle listed twice
// (tests/data/io/README.md says how it was made).
TEST(PinchedVertices, CgalMesh3OutputLoadsAndValidatesAfterTheSplit) {
    ReadReport report;
    const Mesh mesh = read_mesh(data_file("io/cgal_anchor_pinched.mesh"), {}, &report);
    EXPECT_EQ(report.pinched_vertices, 2u);
    EXPECT_EQ(report.vertex_copies, (Copies{{29, 256}, {100, 257}}));
    EXPECT_EQ(report.label_conflicts, 0u);
    EXPECT_EQ(mesh.vertex_count(), 258u);
    EXPECT_EQ(mesh.element_count(), 684u);
    EXPECT_EQ(mesh.boundary_face_count(), 524u);
    EXPECT_EQ(mesh.face_labels().size(), 524u);
    for (const auto& [original, copy] : report.vertex_copies)
        EXPECT_EQ(mesh.reference(copy), mesh.reference(original));
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    for (const char* name : {"cgal.mesh", "cgal.msh", "cgal.node"}) {
        const auto path = scratch_dir() / name;
        write_mesh(mesh, path);
        expect_same_mesh(mesh, read_mesh(path));
    }
}

// ---- Medit faces listed more than once -------------------------------------------------------

const char* repeated_triangles = R"(MeshVersionFormatted 2
Dimension 3
Vertices
5
0 0 0 0
1 0 0 0
0 1 0 0
0 0 1 0
0 0 -1 0
Triangles
5
1 2 3 %A
3 2 1 %B
1 2 4 6
1 2 4 6
1 4 2 6
Tetrahedra
2
1 2 3 4 1
1 3 2 5 2
End
)";

std::string with_references(const std::string& a, const std::string& b) {
    std::string text = repeated_triangles;
    text.replace(text.find("%A"), 2, a);
    text.replace(text.find("%B"), 2, b);
    return text;
}

TEST(MeditRepeatedFaces, SameReferenceIsOneLabelledFace) {
    std::istringstream in(with_references("5", "5"));
    ReadReport report;
    const Mesh mesh = read_mesh(in, Format::medit, "repeat.mesh", {}, &report);
    EXPECT_EQ(face_label_list(mesh),
              (List{{Simplex(+1, {0, 1, 2}), 5}, {Simplex(+1, {0, 1, 3}), 6}}));
    EXPECT_EQ(report.label_conflicts, 0u);
    EXPECT_EQ(report.first_label_conflict, "");
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(MeditRepeatedFaces, DifferentReferenceKeepsTheFirstAndSaysSo) {
    // CGAL gives an interface triangle the subdomain of either side: 2 then 1 here
    std::istringstream in(with_references("2", "1"));
    ReadReport report;
    const Mesh mesh = read_mesh(in, Format::medit, "repeat.mesh", {}, &report);
    EXPECT_EQ(face_label_list(mesh),
              (List{{Simplex(+1, {0, 1, 2}), 2}, {Simplex(+1, {0, 1, 3}), 6}}));
    EXPECT_EQ(report.label_conflicts, 1u);
    EXPECT_EQ(report.first_label_conflict,
              "repeat.mesh:13: triangle 2 repeats triangle 1 with reference 1, not 2");
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}
// (other formats still refuse a repeated face: tests/data/malformed/gmsh_face_repeat.msh)

}  // namespace
}  // namespace sxk
