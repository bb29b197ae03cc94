// sxk components: count and sizes, text and --json; unreadable input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

TEST(SxkComponents, OneComponentAsText) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"components", mesh.string()});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, "components: 1\n  0: 2 tetrahedra\n");
    EXPECT_EQ(run.err, "");
}

TEST(SxkComponents, TwoComponentsAsJson) {
    ScratchFolder folder;
    const fs::path mesh = folder / "apart.mesh";
    write_file(mesh, separate_tetrahedra_mesh);
    const ProcessResult run = sxk({"components", mesh.string(), "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["file"], mesh.string());
    EXPECT_EQ(json["components"], 2);
    EXPECT_EQ(json["sizes"], nlohmann::json::array({1, 1}));
}

TEST(SxkComponents, MissingFileExits2) {
    ScratchFolder folder;
    const fs::path mesh = folder / "none.mesh";
    const ProcessResult run = sxk({"components", mesh.string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(run.err.rfind("sxk: " + mesh.string() + ":0: ", 0), 0u) << run.err;
}

}  // namespace
}  // namespace sxk::test
