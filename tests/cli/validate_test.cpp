// sxk validate: 0 valid, 1 invalid naming the broken invariant, 2 unreadable.
#include <gtest/gtest.h>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

TEST(SxkValidate, ValidMeshExitsZero) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"validate", mesh.string()});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, mesh.string() + ": valid (5 vertices, 2 tetrahedra)\n");
    EXPECT_EQ(run.err, "");
}

TEST(SxkValidate, VertexStarNotFaceConnectedIsInvalid) {
    ScratchFolder folder;
    const fs::path mesh = folder / "star.mesh";
    write_file(mesh, vertex_star_mesh);
    const ProcessResult run = sxk({"validate", mesh.string()});
    EXPECT_EQ(run.exit_code, 1) << run.err;
    const std::string expected =
        mesh.string() + ": invalid: star connectivity: the star of vertex 0 is not face-connected";
    EXPECT_EQ(run.out.substr(0, expected.size()), expected) << run.out;
    EXPECT_EQ(run.err, "");
}

TEST(SxkValidate, DuplicatedTetrahedronIsInvalid) {
    ScratchFolder folder;
    const fs::path mesh = folder / "duplicate.mesh";
    write_file(mesh, duplicated_tetrahedron_mesh);
    const ProcessResult run = sxk({"validate", mesh.string()});
    EXPECT_EQ(run.exit_code, 1) << run.err;
    const std::string expected = mesh.string() + ": invalid: invariant 7.4 (uniqueness)";
    EXPECT_EQ(run.out.substr(0, expected.size()), expected) << run.out;
}

TEST(SxkValidate, DuplicatedTetrahedronIsRefusedByTheOtherCommands) {
    // only validate reads leniently; everywhere else a duplicate is an input error
    ScratchFolder folder;
    const fs::path mesh = folder / "duplicate.mesh";
    write_file(mesh, duplicated_tetrahedron_mesh);
    const ProcessResult run = sxk({"info", mesh.string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err.rfind("sxk: " + mesh.string() + ":", 0), 0u) << run.err;
}

// One tetrahedron listed in the order that gives it negative volume: the connectivity is fine,
// the geometry is not. The reader refuses it everywhere else ("element 1 is inverted").
const char* inverted_tetrahedron_mesh = R"(MeshVersionFormatted 2
Dimension 3
Vertices
4
0 0 0 0
1 0 0 0
0 1 0 0
0 0 1 0
Tetrahedra
1
1 3 2 4 0
End
)";

// A unit tetrahedron and a flat one (its four vertices in the plane z = 0) glued along 1-2-3.
const char* flat_tetrahedron_mesh = R"(MeshVersionFormatted 2
Dimension 3
Vertices
5
0 0 0 0
1 0 0 0
0 1 0 0
0 0 1 0
1 1 0 0
Tetrahedra
2
1 2 3 4 0
1 3 2 5 0
End
)";

TEST(SxkValidate, InvertedElementIsInvalid) {
    ScratchFolder folder;
    const fs::path mesh = folder / "inverted.mesh";
    write_file(mesh, inverted_tetrahedron_mesh);
    const ProcessResult run = sxk({"validate", mesh.string()});
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_EQ(run.out, mesh.string() + ": invalid: element 0 is inverted in the reference positions\n");
    EXPECT_EQ(run.err, "");
}

TEST(SxkValidate, FlatElementIsReportedAndInvalidWithFlatInvalid) {
    ScratchFolder folder;
    const fs::path mesh = folder / "flat.mesh";
    write_file(mesh, flat_tetrahedron_mesh);
    const ProcessResult run = sxk({"validate", mesh.string()});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, mesh.string() +
                           ": valid (5 vertices, 2 tetrahedra); 1 flat element, first element 1 (--flat-invalid: invalid)\n");
    const ProcessResult flat = sxk({"validate", mesh.string(), "--flat-invalid"});
    EXPECT_EQ(flat.exit_code, 1) << flat.err;
    EXPECT_EQ(flat.out, mesh.string() + ": invalid: element 1 is flat in the reference positions\n");
    const ProcessResult json = sxk({"validate", mesh.string(), "--flat-invalid", "--json"});
    EXPECT_EQ(json.exit_code, 1) << json.err;
    EXPECT_EQ(json.out, "{\n  \"file\": \"" + mesh.string() +
                            "\",\n  \"valid\": false,\n  \"vertices\": 5,\n  \"elements\": 2,\n  \"element_kind\": "
                            "\"tetrahedron\",\n  \"refusal\": {\n    \"code\": \"invalid_mesh\",\n    \"reason\": "
                            "\"element 1 is flat in the reference positions\"\n  }\n}\n");
    const ProcessResult valid = sxk({"validate", mesh.string(), "--json"});
    EXPECT_EQ(valid.exit_code, 0) << valid.err;
    EXPECT_EQ(valid.out, "{\n  \"file\": \"" + mesh.string() +
                             "\",\n  \"valid\": true,\n  \"vertices\": 5,\n  \"elements\": 2,\n  \"element_kind\": "
                             "\"tetrahedron\",\n  \"flat\": 1,\n  \"first_flat\": 1\n}\n");
}

// --strict means one thing everywhere (refuse what the readers repair); validate repairs nothing.
TEST(SxkValidate, StrictIsNotValidatesAndSaysWhatIs) {
    ScratchFolder folder;
    const fs::path mesh = folder / "flat.mesh";
    write_file(mesh, flat_tetrahedron_mesh);
    const ProcessResult run = sxk({"validate", mesh.string(), "--strict"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(run.err, "sxk: validate: --strict: validate repairs nothing (the file is judged as it is); flat "
                       "elements are made invalid by --flat-invalid\nRun 'sxk validate --help' for more "
                       "information.\n");
}

TEST(SxkValidate, UnreadableExitsTwo) {
    ScratchFolder folder;
    const fs::path mesh = folder / "garbage.mesh";
    write_file(mesh, "this is not a mesh\n");
    const ProcessResult run = sxk({"validate", mesh.string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(run.err.rfind("sxk: " + mesh.string() + ":", 0), 0u) << run.err;
}

}  // namespace
}  // namespace sxk::test
