// Every file in tests/data/malformed is refused with exactly this message ("FILE:LINE: reason").
// The files carry a comment saying what is wrong with them where the format has comments.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <set>
#include <string>

#include "io_fixtures.hpp"
#include "sxk/io.hpp"

namespace sxk {
namespace {

struct Case {
    const char* read;      // the file handed to read_mesh
    const char* blamed;    // the file the message names (TetGen: .node, .ele); nullptr: `read`
    const char* expected;  // "LINE: reason"
    bool strict = false;   // read with split_pinched and drop_stray_faces false (sxk's --strict)
};

const Case cases[] = {
    // Medit
    {"medit_truncated.mesh", nullptr, "12: truncated file: expected vertex index"},
    {"medit_short_section.mesh", nullptr, "10: section Vertices declares 5 entries but has 4"},
    {"medit_long_section.mesh", nullptr,
     "13: section Tetrahedra has more than the 1 entries it declares"},
    {"medit_index_range.mesh", nullptr, "12: vertex index 9 out of range (1..4)"},
    {"medit_index_zero.mesh", nullptr, "12: vertex index 0: indices start at 1"},
    {"medit_nan.mesh", nullptr, "7: coordinate is not finite"},
    {"medit_overflow.mesh", nullptr, "8: coordinate is not finite"},
    {"medit_duplicate.mesh", nullptr, "13: element 2 repeats element 1"},
    {"medit_non_manifold.mesh", nullptr,
     "22: element 3 makes face (1 2 3) non-manifold: it is shared by 3 elements"},
    {"medit_inverted.mesh", nullptr, "14: element 2 is inverted"},
    {"medit_inconsistent.mesh", nullptr,
     "17: element 2 is oriented inconsistently with element 1 across face (1 2)"},
    // read by default since pinched vertices are split (tests/io/pinched.cpp); strict refuses
    {"medit_non_manifold_vertex.mesh", nullptr,
     "6: vertex 1 is non-manifold: the elements around it are not connected through faces", true},
    {"medit_unknown_keyword.mesh", nullptr, "10: unknown keyword 'Tetrahedrons'"},
    {"medit_hexahedra.mesh", nullptr, "14: Hexahedra are not supported: simplicial meshes only"},
    {"medit_after_end.mesh", nullptr, "14: unexpected data after End"},
    {"medit_dimension.mesh", nullptr, "3: Dimension must be 2 or 3, found '4'"},
    // read by default since labelled faces of no element are dropped (tests/io/stray_faces.cpp)
    {"medit_not_a_face.mesh", nullptr, "14: triangle 2 is not a face of any tetrahedron", true},
    {"medit_bad_number.mesh", nullptr, "7: expected y coordinate, found '0.5.5'"},
    {"medit_no_elements.mesh", nullptr, "0: no triangles or tetrahedra"},
    {"medit_repeated_vertex.mesh", nullptr, "12: element 1 has a repeated vertex"},
    {"medit_empty.mesh", nullptr, "0: empty file"},
    {"medit_binary.mesh", nullptr, "5: binary data (byte 0x00)"},
    {"medit_bad_utf8.mesh", nullptr, "2: binary data (byte 0xFF)"},
    // Gmsh
    // a binary header without the int 1 that gives the byte order
    {"gmsh_binary.msh", nullptr, "0: expected the int 1 after the header, found 1684948260, at byte 20"},
    {"gmsh_version.msh", nullptr, "2: unsupported Gmsh version '3.0' (2.2 and 4.1 are supported)"},
    {"gmsh_undefined_node.msh", nullptr, "13: undefined node 9"},
    {"gmsh_hexahedron.msh", nullptr,
     "13: element type 5 is not supported (simplexes only: 15 point, 1 line, 2 triangle, 4 "
     "tetrahedron)"},
    {"gmsh_short_elements.msh", nullptr, "15: section $Elements declares 3 elements but has 2"},
    {"gmsh_unknown_section.msh", nullptr, "7: unknown section '$Foo'"},
    {"gmsh_duplicate_node.msh", nullptr, "8: node 2 is defined twice"},
    {"gmsh_unknown_entity.msh", nullptr, "22: unknown entity (dimension 3, tag 7)"},
    {"gmsh_missing_elements.msh", nullptr, "10: missing $Elements section"},
    {"gmsh_face_repeat.msh", nullptr, "17: triangle 2 repeats triangle 1"},
    {"gmsh_extra_elements.msh", nullptr,
     "14: section $Elements has more than the 1 elements it declares"},
    {"gmsh_names_short.msh", nullptr, "8: section $PhysicalNames declares 3 names but has 2"},
    {"gmsh_names_long.msh", nullptr,
     "7: section $PhysicalNames has more than the 1 names it declares"},
    {"gmsh_names_count.msh", nullptr, "5: expected number of physical names, found 'two'"},
    {"gmsh_names_negative.msh", nullptr, "5: number of physical names out of range: '-1'"},
    {"gmsh_names_unquoted.msh", nullptr, "6: expected a quoted physical name, found 'outside'"},
    {"gmsh_names_unclosed.msh", nullptr, "6: physical name without its closing '\"'"},
    {"gmsh_names_dimension.msh", nullptr, "6: physical dimension out of range: '4'"},
    {"gmsh_names_after.msh", nullptr, "6: unexpected '8' after the physical name"},
    // TetGen: X.node and X.ele are read together
    {"tetgen_sequence.ele", "tetgen_sequence.node", "5: node 3 out of sequence: expected 2"},
    {"tetgen_index_range.ele", nullptr, "3: vertex index 4 out of range (0..3)"},
    {"tetgen_second_order.ele", nullptr, "1: second-order elements (10 nodes) are not supported"},
    {"tetgen_truncated.ele", nullptr, "3: truncated file: the header declares 2 elements, found 1"},
    {"tetgen_extra_value.ele", nullptr, "3: unexpected value '1' at the end of the line"},
    {"tetgen_missing_ele.node", "tetgen_missing_ele.ele", "0: no such file"},
    {"tetgen_first_number.ele", "tetgen_first_number.node",
     "3: the first node must be numbered 0 or 1, found '5'"},
    // OFF
    {"off_quad.off", nullptr, "8: face 1 has 4 vertices: only triangles are supported"},
    {"off_extra.off", nullptr, "9: more data than the header declares (4 vertices, 1 faces)"},
    {"off_variant.off", nullptr, "1: unsupported OFF variant '4OFF'"},
    {"off_truncated.off", nullptr, "5: truncated file: the header declares 3 vertices, found 2"},
    {"off_negative_vertices.off", nullptr, "3: number of vertices out of range: '-3'"},
    {"off_negative_faces.off", nullptr, "3: number of faces out of range: '-1'"},
    {"off_negative_edges.off", nullptr, "3: number of edges out of range: '-3'"},
    {"off_large_vertices.off", nullptr, "3: number of vertices out of range: '4294967295'"},
    {"off_huge_faces.off", nullptr, "3: number of faces is too large: '99999999999999999999'"},
    {"off_few_faces.off", nullptr, "7: truncated file: the header declares 2 faces, found 1"},
    {"off_short_face.off", nullptr, "7: face 1 declares 3 vertices but has 2"},
    {"off_long_face.off", nullptr,
     "8: face 1 has 2 values after its 3 vertices (a colour is 1, 3 or 4 values)"},
    // OBJ
    {"obj_polygon.obj", nullptr,
     "6: face has 4 vertices: only triangles are supported (triangulate the polygons first)"},
    {"obj_relative.obj", nullptr, "5: relative vertex index -5 out of range (3 vertices so far)"},
    {"obj_unknown.obj", nullptr, "3: unknown keyword 'vx'"},
    {"obj_forward.obj", nullptr, "3: vertex index 7 out of range (1..4)"},
    {"obj_infinite.obj", nullptr, "4: coordinate is not finite"},
    {"obj_zero.obj", nullptr, "5: vertex index 0: indices start at 1"},
    // no file at all
    {"nonexistent.mesh", nullptr, "0: no such file"},
    {"unknown_extension.step", nullptr, "0: unknown mesh file extension '.step' (known: .mesh .msh .node .ele .off .obj .vtu .vtk .stl .ply)"},
};

class Malformed : public ::testing::TestWithParam<Case> {};

TEST_P(Malformed, IsRefusedWithItsExactMessage) {
    const Case& c = GetParam();
    const std::string dir = std::string(SXK_TEST_DATA_DIR) + "/malformed/";
    const std::string expected = dir + (c.blamed ? c.blamed : c.read) + ":" + c.expected;
    try {
        ReadOptions options;
        options.split_pinched = options.drop_stray_faces = !c.strict;
        const Mesh mesh = read_mesh(dir + c.read, options);
        FAIL() << c.read << " was read: " << mesh.element_count() << " elements";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()), expected);
    }
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
    std::string name = info.param.read;
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch)))
            ch = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Files, Malformed, ::testing::ValuesIn(cases), case_name);

// Every fixture in the folder has a row above (a new file without an expectation would
// silently test nothing), and there are at least 20 distinct ones.
TEST(MalformedFolder, EveryFileHasAnExpectation) {
    std::set<std::string> listed;
    for (const Case& c : cases) {
        listed.insert(c.read);
        if (c.blamed)
            listed.insert(c.blamed);
    }
    std::size_t files = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(SXK_TEST_DATA_DIR) + "/malformed")) {
        ++files;
        const std::string name = entry.path().filename().string();
        // the partner of a TetGen pair is read together with the listed file
        const std::string stem = entry.path().stem().string();
        EXPECT_TRUE(listed.count(name) || listed.count(stem + ".ele") ||
                    listed.count(stem + ".node"))
            << name << " has no expected message";
    }
    EXPECT_GE(files, 20u);
}

}  // namespace
}  // namespace sxk
