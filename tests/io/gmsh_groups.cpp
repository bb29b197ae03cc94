// Gmsh files other tools read right: every element and labelled face in a physical group, label
// 0 and negative labels carried by a group named `label N`, $PhysicalNames read and written back,
// and binary files (2.2 and 4.1, both byte orders) read and written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io_fixtures.hpp"
#include "sxk/io.hpp"

namespace sxk {
namespace {

using test::data_file;
using test::file_bytes;
using test::expect_same_mesh;
using test::planar_triangles;
using test::scratch_dir;
using test::two_tetrahedra;

Mesh write_then_read(const Mesh& mesh, const std::string& name, int version, Encoding encoding) {
    WriteOptions options;
    options.gmsh_version = version;
    options.encoding = encoding;
    const auto path = scratch_dir() / name;
    write_mesh(mesh, path, options);
    return read_mesh(path);
}

// The two tetrahedra with label 0 on one element and a negative label on a face: labels Gmsh
// cannot hold as physical tags.
Mesh unlabelled_tetrahedra() {
    Mesh mesh = two_tetrahedra();
    mesh.set_label(ElementId{0}, 0);
    mesh.face_labels()[Simplex(+1, {0, 1, 3})] = -4;
    return mesh;
}

TEST(GmshGroups, Version41PutsEveryEntityInAPhysicalGroupAndNamesLabelZero) {
    const Mesh mesh = unlabelled_tetrahedra();
    const auto path = scratch_dir() / "zero.msh";
    write_mesh(mesh, path);
    const std::string text = file_bytes(path);
    // element labels {0, 2}: 0 takes tag 1; face labels {-4, 5}: -4 takes tag 1
    EXPECT_NE(text.find("$PhysicalNames\n2\n2 1 \"label -4\"\n3 1 \"label 0\"\n$EndPhysicalNames\n"),
              std::string::npos)
        << text;
    // no entity without a physical tag: each entity line has "1 TAG 0" after its box
    const std::size_t entities = text.find("$Entities\n0 0 2 2\n");
    ASSERT_NE(entities, std::string::npos) << text;
    EXPECT_EQ(text.find(" 0 0\n", entities), std::string::npos) << text;
    expect_same_mesh(mesh, read_mesh(path));
}

TEST(GmshGroups, Version22WritesAGroupAndAnEntityOfAtLeastOne) {
    const Mesh mesh = unlabelled_tetrahedra();
    WriteOptions options;
    options.gmsh_version = 22;
    const auto path = scratch_dir() / "zero22.msh";
    write_mesh(mesh, path, options);
    const std::string text = file_bytes(path);
    // faces by vertices: {0,1,2} labelled 5 is element 1, {0,1,3} labelled -4 (group 1) element
    // 2; the tetrahedron labelled 0 (group 1) is element 3
    const std::size_t elements = text.find("$Elements\n4\n");
    ASSERT_NE(elements, std::string::npos) << text;
    EXPECT_NE(text.find("\n1 2 2 5 5 ", elements), std::string::npos) << text;
    EXPECT_NE(text.find("\n2 2 2 1 1 ", elements), std::string::npos) << text;
    EXPECT_NE(text.find("\n3 4 2 1 1 ", elements), std::string::npos) << text;
    EXPECT_EQ(text.find(" 2 0 0 ", elements), std::string::npos) << text;
    expect_same_mesh(mesh, read_mesh(path));
}

TEST(GmshGroups, LabelNamesGoThroughEveryVersionAndEncoding) {
    Mesh mesh = two_tetrahedra();
    mesh.label_names().elements[1] = "upper bone";
    mesh.label_names().elements[2] = "lower";
    mesh.label_names().faces[7] = "skin \"outer\"";  // quotes cannot be written: left out
    for (const int version : {22, 41})
        for (const Encoding encoding : {Encoding::ascii, Encoding::binary}) {
            SCOPED_TRACE(std::to_string(version) + " " + std::string(to_string(encoding)));
            const Mesh again = write_then_read(mesh, "named.msh", version, encoding);
            expect_same_mesh(mesh, again);
            EXPECT_EQ(again.label_names().elements, (std::map<int, std::string>{{1, "upper bone"}, {2, "lower"}}));
            EXPECT_EQ(again.label_names().faces, (std::map<int, std::string>{{7, "skin outer"}}));
        }
}

TEST(GmshGroups, AUsersNameThatReadsAsAnotherLabelIsNotWritten) {
    Mesh mesh = two_tetrahedra();
    mesh.label_names().elements[1] = "label 2";  // would make the group of label 1 read as label 2
    mesh.label_names().elements[2] = "label 2";  // its own label: harmless, kept
    const Mesh again = read_mesh([&] {
        const auto path = scratch_dir() / "misleading.msh";
        write_mesh(mesh, path);
        return path;
    }());
    expect_same_mesh(mesh, again);
    // a group named `label N` is the label itself, not a name
    EXPECT_TRUE(again.label_names().elements.empty());
}

TEST(GmshGroups, BinaryRoundTripsAreExact) {
    for (const int version : {22, 41}) {
        SCOPED_TRACE(version);
        expect_same_mesh(two_tetrahedra(), write_then_read(two_tetrahedra(), "two.msh", version, Encoding::binary));
        expect_same_mesh(planar_triangles(),
                         write_then_read(planar_triangles(), "square.msh", version, Encoding::binary));
        expect_same_mesh(unlabelled_tetrahedra(),
                         write_then_read(unlabelled_tetrahedra(), "zero.msh", version, Encoding::binary));
    }
}

TEST(GmshGroups, BinaryFilesSayWhatTheyAre) {
    WriteOptions options;
    options.encoding = Encoding::binary;
    const auto path = scratch_dir() / "b.msh";
    write_mesh(two_tetrahedra(), path, options);
    const std::string text = file_bytes(path);
    EXPECT_EQ(text.substr(0, 32), std::string("$MeshFormat\n4.1 1 8\n\x01\0\0\0\n$EndMeshFormat\n", 32));
    options.gmsh_version = 22;
    write_mesh(two_tetrahedra(), path, options);
    EXPECT_EQ(file_bytes(path).substr(0, 32), std::string("$MeshFormat\n2.2 1 8\n\x01\0\0\0\n$EndMeshFormat\n", 32));
}

// Files Gmsh 4.8 wrote (tests/data/io/gmsh_made/make.py): a box, its volume in group 7 "bone",
// two sides in group 3 "sides"; Gmsh saves only what is in a physical group.
TEST(GmshGroups, ReadsWhatGmshWritesInEveryVersionAndEncoding) {
    const Mesh reference = read_mesh(data_file("io/gmsh_made/box41_ascii.msh"));
    EXPECT_EQ(reference.topological_dimension(), 3);
    EXPECT_GT(reference.element_count(), 0u);
    EXPECT_GT(reference.face_labels().size(), 0u);
    for (ElementId t : elements(reference))
        EXPECT_EQ(reference.label(t), 7);
    for (const auto& [face, label] : reference.face_labels())
        EXPECT_EQ(label, 3);
    EXPECT_EQ(reference.label_names().elements, (std::map<int, std::string>{{7, "bone"}}));
    EXPECT_EQ(reference.label_names().faces, (std::map<int, std::string>{{3, "sides"}}));
    for (const char* name : {"box41_binary.msh", "box22_ascii.msh", "box22_binary.msh"}) {
        SCOPED_TRACE(name);
        const Mesh mesh = read_mesh(data_file(std::string("io/gmsh_made/") + name));
        expect_same_mesh(reference, mesh);
        EXPECT_EQ(mesh.label_names().elements, reference.label_names().elements);
        EXPECT_EQ(mesh.label_names().faces, reference.label_names().faces);
    }
}

// A 2.2 binary file in big-endian byte order, made by hand: one triangle labelled 5.
std::string big_endian_triangle() {
    std::string bytes = "$MeshFormat\n2.2 1 8\n";
    auto int32 = [&](std::int32_t value) {
        for (int shift = 24; shift >= 0; shift -= 8)
            bytes += static_cast<char>((static_cast<std::uint32_t>(value) >> shift) & 0xFF);
    };
    auto real = [&](double value) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &value, 8);
        for (int shift = 56; shift >= 0; shift -= 8)
            bytes += static_cast<char>((bits >> shift) & 0xFF);
    };
    int32(1);
    bytes += "\n$EndMeshFormat\n$Nodes\n3\n";
    const double points[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int v = 0; v < 3; ++v) {
        int32(v + 1);
        for (double c : points[v])
            real(c);
    }
    bytes += "\n$EndNodes\n$Elements\n1\n";
    for (std::int32_t value : {2, 1, 2, 1, 5, 5, 1, 2, 3})
        int32(value);
    bytes += "\n$EndElements\n";
    return bytes;
}

TEST(GmshGroups, ReadsBigEndianBinaryFiles) {
    std::istringstream in(big_endian_triangle());
    const Mesh mesh = read_mesh(in, Format::gmsh, "big.msh");
    ASSERT_EQ(mesh.element_count(), 1u);
    EXPECT_EQ(mesh.ambient_dimension(), 2);
    EXPECT_EQ(mesh.label(ElementId{0}), 5);
    EXPECT_EQ(mesh.reference(VertexId{1}), (Point{1, 0, 0}));
    EXPECT_TRUE(mesh.validate().ok());
}

std::string read_error(const std::string& bytes) {
    std::istringstream in(bytes);
    try {
        (void)read_mesh(in, Format::gmsh, "bad.msh");
    } catch (const InputError& error) {
        return error.what();
    }
    return "read";
}

TEST(GmshGroups, BrokenBinaryFilesAreRefusedWithTheirByte) {
    const std::string good = big_endian_triangle();
    EXPECT_EQ(read_error(good.substr(0, 60)), "bad.msh:0: $Nodes: truncated file: 3 nodes declared, room for 0, at byte 49");
    std::string wrong_mark = good;
    wrong_mark[23] = 7;  // the int 1 after the header, big-endian: 00 00 00 07 is 7 either way round
    EXPECT_EQ(read_error(wrong_mark), "bad.msh:0: expected the int 1 after the header, found 117440512, at byte 20");
    EXPECT_EQ(read_error("$MeshFormat\n2.2 1 4\n"),
              "bad.msh:0: expected file type 1 and data size 8 after the version, found '1 4', at byte 20");
    std::string many_nodes = good;
    many_nodes.replace(many_nodes.find("$Nodes\n3\n") + 7, 1, "9");
    EXPECT_EQ(read_error(many_nodes), "bad.msh:0: $Nodes: truncated file: 9 nodes declared, room for 5, at byte 49");
    std::string undefined = good;
    undefined[undefined.size() - 15] = 9;  // the last node of the triangle: 3 -> 9 (big-endian low byte)
    EXPECT_EQ(read_error(undefined), "bad.msh:0: $Elements: undefined node 9, at byte 192");
    std::string type = good;
    type[type.find("$Elements\n1\n") + 15] = 3;  // element type 2 -> 3 (a quadrangle)
    EXPECT_EQ(read_error(type),
              "bad.msh:0: $Elements: element type 3 is not supported (simplexes only: 15 point, 1 line, 2 "
              "triangle, 4 tetrahedron), at byte 160");
    EXPECT_EQ(read_error(good.substr(0, good.size() - 14)),
              "bad.msh:0: $Elements: expected $EndElements after the section's data (the counts do not match the "
              "data), at byte 192");
}

TEST(GmshGroups, PhysicalNamesInABinaryFileAreCheckedOnTheirLine) {
    std::string bytes = big_endian_triangle();
    bytes.insert(bytes.find("$Nodes"), "$PhysicalNames\n1\n2 5 surface\n$EndPhysicalNames\n");
    EXPECT_EQ(read_error(bytes), "bad.msh:7: expected a quoted physical name, found 'surface'");
}

}  // namespace
}  // namespace sxk
