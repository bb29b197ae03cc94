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

TEST(SxkValidate, FlatElementIsReportedAndInvalidWithStrict) {
    ScratchFolder folder;
    const fs::path mesh = folder / "flat.mesh";
    write_file(mesh, flat_tetrahedron_mesh);
    const ProcessResult run = sxk({"validate", mesh.string()});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, mesh.string() + ": valid (5 vertices, 2 tetrahedra); 1 flat element, first element 1 (--strict: invalid)\n");
    const ProcessResult strict = sxk({"validate", mesh.string(), "--strict"});
    EXPECT_EQ(strict.exit_code, 1) << strict.err;
    EXPECT_EQ(strict.out, mesh.string() + ": invalid: element 1 is flat in the reference positions\n");
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
