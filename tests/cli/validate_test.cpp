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
