// sxk locate MESH --points FILE [--deformed] [--json]: the containing element and barycentric
// coordinates of each point, as text and JSON; malformed point files are input errors (exit 2).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

struct LocateFixture {
    ScratchFolder folder;
    fs::path mesh = folder / "square.mesh";
    fs::path points = folder / "points.txt";
    LocateFixture(const char* mesh_text = unit_square_mesh) { write_file(mesh, mesh_text); }
    ProcessResult run(const std::string& point_lines, std::vector<std::string> options = {}) {
        write_file(points, point_lines);
        std::vector<std::string> args{"locate", mesh.string(), "--points", points.string()};
        args.insert(args.end(), options.begin(), options.end());
        return sxk(args);
    }
};

//   3 ------- 2        the unit square, 0-based: triangle 0 = <0,1,2>, triangle 1 = <0,2,3>
//   |       / |
//   |     /   |
//   |   /     |
//   0 ------- 1
const char* square_points = "0.75 0.25\n# a comment, then a blank line\n\n0.5 0.5 0  # on the diagonal\n2 2\n0.25 0.75\n";

TEST(SxkLocate, PrintsEachPointsTriangleAndWeights) {
    LocateFixture f;
    const ProcessResult run = f.run(square_points);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out,
              "0.75 0.25: triangle 0, vertices 0 1 2, barycentric 0.25 0.5 0.25\n"
              "0.5 0.5 0: triangle 0, vertices 0 1 2, barycentric 0.5 0 0.5\n"
              "2 2: outside\n"
              "0.25 0.75: triangle 1, vertices 0 2 3, barycentric 0.25 0.25 0.5\n");
    EXPECT_EQ(run.err, "");
    // the deformed positions of a file are its positions
    EXPECT_EQ(f.run(square_points, {"--deformed"}).out, run.out);
}

TEST(SxkLocate, JsonHasOneEntryPerPointInOrder) {
    LocateFixture f;
    const ProcessResult run = f.run(square_points, {"--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json expected = nlohmann::json::parse(R"({"points": [
        {"element": 0, "vertices": [0, 1, 2], "barycentric": [0.25, 0.5, 0.25]},
        {"element": 0, "vertices": [0, 1, 2], "barycentric": [0.5, 0.0, 0.5]},
        {"element": null},
        {"element": 1, "vertices": [0, 2, 3], "barycentric": [0.25, 0.25, 0.5]}]})");
    EXPECT_EQ(nlohmann::json::parse(run.out), expected) << run.out;
    EXPECT_EQ(f.run("", {"--json"}).out, "{\n  \"points\": []\n}\n");
}

//   <0,1,2,3> and <1,2,3,4> (0-based), glued along 1-2-3
TEST(SxkLocate, Tetrahedra) {
    LocateFixture f(two_tetrahedra_mesh);
    const ProcessResult run = f.run("0.25 0.25 0.25\n0.5 0.5 0.5\n0.6 0.6 0.6\n-1 0 0\n");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out,
              "0.25 0.25 0.25: tetrahedron 0, vertices 0 1 2 3, barycentric 0.25 0.25 0.25 0.25\n"
              "0.5 0.5 0.5: tetrahedron 1, vertices 1 2 3 4, barycentric 0.25 0.25 0.25 0.25\n"
              "0.6 0.6 0.6: tetrahedron 1, vertices 1 2 3 4, barycentric 0.2 0.2 0.2 0.4\n"
              "-1 0 0: outside\n");
}

TEST(SxkLocate, MalformedLinesAreInputErrors) {
    LocateFixture f;
    const std::string file = f.points.string();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"0.5 0.5\n0.5 x\n", "sxk: " + file + ":2: expected a finite number, found 'x'\n"},
        {"nan 0.5\n", "sxk: " + file + ":1: expected a finite number, found 'nan'\n"},
        {"\n\n1 2 3 4\n", "sxk: " + file + ":3: expected 2 or 3 coordinates (x y [z]), found 4\n"},
        {"0.5\n", "sxk: " + file + ":1: expected 2 or 3 coordinates (x y [z]), found 1\n"},
    };
    for (const auto& [text, message] : cases) {
        const ProcessResult run = f.run(text);
        EXPECT_EQ(run.exit_code, 2) << text;
        EXPECT_EQ(run.err, message);
        EXPECT_EQ(run.out, "");
    }
    LocateFixture tetrahedra(two_tetrahedra_mesh);
    const ProcessResult run = tetrahedra.run("0.1 0.1 0.1\n0.1 0.1\n");
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: " + tetrahedra.points.string() + ":2: expected 3 coordinates (x y z), found 2\n");
}

TEST(SxkLocate, UnreadablePointsFileAndMissingOption) {
    LocateFixture f;
    const fs::path missing = f.folder / "none.txt";
    ProcessResult run = sxk({"locate", f.mesh.string(), "--points", missing.string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err.rfind("sxk: " + missing.string() + ":0: ", 0), 0u) << run.err;
    run = sxk({"locate", f.mesh.string(), "--points", f.folder.path().string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: " + f.folder.path().string() + ":0: is a directory\n");
    run = sxk({"locate", f.mesh.string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: --points is required\nRun 'sxk locate --help' for more information.\n");
    run = sxk({"locate", "--help"});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_NE(run.out.find("Usage: sxk locate [OPTIONS] MESH"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace sxk::test
