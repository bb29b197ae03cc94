// sxk refine IN OUT --around X,Y[,Z] --size H: refine-around (thesis §6.5) from the command line;
// bad arguments are usage errors (exit 2), a point outside the mesh is a refusal (exit 1).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

struct RefineFixture {
    ScratchFolder folder;
    fs::path mesh = folder / "square.mesh";
    fs::path out = folder / "refined.mesh";
    RefineFixture() { write_file(mesh, unit_square_mesh); }
    ProcessResult run(std::vector<std::string> options) {
        std::vector<std::string> args{"refine", mesh.string(), out.string()};
        args.insert(args.end(), options.begin(), options.end());
        return sxk(args);
    }
};

//   4 ------- 3        the unit square (file numbering); x = (0.3, 0.2), H = 0.75: the
//   |       / |        diagonal 1-3 is bisected, then the bottom edge 1-2 of x's new
//   |     5   |        triangle: 2 bisections, 6 vertices, 5 triangles
//   |   /  \  |
//   | /  x   \|
//   1 -- 6 -- 2
TEST(SxkRefine, RefinesAroundAPoint) {
    RefineFixture f;
    const ProcessResult run = f.run({"--around", "0.3,0.2", "--size", "0.75"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, f.mesh.string() + " -> " + f.out.string() +
                           ": 2 bisections, 6 vertices, 5 triangles\n");
    EXPECT_EQ(run.err, "");
    EXPECT_EQ(sxk({"validate", f.out.string()}).exit_code, 0);
    const nlohmann::json info = nlohmann::json::parse(sxk({"info", f.out.string(), "--json"}).out);
    EXPECT_EQ(info["vertices"], 6);
    EXPECT_EQ(info["elements"], 5);
    EXPECT_EQ(info["boundary_faces"], 5);
}

TEST(SxkRefine, JsonAndAThirdCoordinate) {
    RefineFixture f;
    const ProcessResult run = f.run({"--around", "0.5,0.5,0", "--size", "0.1", "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["input"], f.mesh.string());
    EXPECT_EQ(json["output"], f.out.string());
    EXPECT_GT(json["bisections"].get<int>(), 4);
    EXPECT_EQ(json["vertices"].get<int>(), 4 + json["bisections"].get<int>());
    const nlohmann::json info = nlohmann::json::parse(sxk({"info", f.out.string(), "--json"}).out);
    EXPECT_EQ(info["elements"], json["elements"]);
    EXPECT_EQ(info["vertices"], json["vertices"]);
    EXPECT_EQ(sxk({"validate", f.out.string()}).exit_code, 0);
}

TEST(SxkRefine, SizeIsRequired) {
    RefineFixture f;
    const ProcessResult run = f.run({"--around", "0.5,0.5"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: --size is required\nRun 'sxk refine --help' for more information.\n");
    EXPECT_EQ(run.out, "");
    EXPECT_FALSE(fs::exists(f.out));
}

TEST(SxkRefine, MalformedPoint) {
    RefineFixture f;
    ProcessResult run = f.run({"--around", "1,x", "--size", "0.5"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err,
              "sxk: --around: expected a finite number, found 'x' in '1,x' (expected X,Y or X,Y,Z)\n"
              "Run 'sxk refine --help' for more information.\n");
    run = f.run({"--around", "1", "--size", "0.5"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err,
              "sxk: --around: '1' has one coordinate (expected X,Y or X,Y,Z)\n"
              "Run 'sxk refine --help' for more information.\n");
    run = f.run({"--around", "1,2,3,4", "--size", "0.5"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err,
              "sxk: --around: '1,2,3,4' has more than three coordinates (expected X,Y or X,Y,Z)\n"
              "Run 'sxk refine --help' for more information.\n");
    EXPECT_FALSE(fs::exists(f.out));
}

TEST(SxkRefine, SizeMustBeAPositiveNumber) {
    RefineFixture f;
    ProcessResult run = f.run({"--around", "0.5,0.5", "--size", "-1"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err,
              "sxk: --size: '-1' is not a positive number\nRun 'sxk refine --help' for more "
              "information.\n");
    run = f.run({"--around", "0.5,0.5", "--size", "0"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err,
              "sxk: --size: '0' is not a positive number\nRun 'sxk refine --help' for more "
              "information.\n");
    run = f.run({"--around", "0.5,0.5", "--size", "small"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(
        run.err,
        "sxk: --size: expected a finite number, found 'small'\nRun 'sxk refine --help' for more information.\n");
    EXPECT_FALSE(fs::exists(f.out));
}

TEST(SxkRefine, NanAndInfiniteNumbersAreRefused) {
    RefineFixture f;
    const std::string hint = "\nRun 'sxk refine --help' for more information.\n";
    ProcessResult run = f.run({"--around", "0.5,0.5", "--size", "inf"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: --size: expected a finite number, found 'inf'" + hint);
    run = f.run({"--around", "0.5,0.5", "--size", "nan"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: --size: expected a finite number, found 'nan'" + hint);
    run = f.run({"--around", "0.5,nan", "--size", "0.5"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err,
              "sxk: --around: expected a finite number, found 'nan' in '0.5,nan' (expected X,Y or X,Y,Z)" + hint);
    run = f.run({"--around", "0.5,0.5,-inf", "--size", "0.5"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err,
              "sxk: --around: expected a finite number, found '-inf' in '0.5,0.5,-inf' (expected X,Y or X,Y,Z)" +
                  hint);
    run = f.run({"--around", "0.5,,0.5", "--size", "0.5"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err,
              "sxk: --around: expected a finite number, found '' in '0.5,,0.5' (expected X,Y or X,Y,Z)" + hint);
    EXPECT_FALSE(fs::exists(f.out));
}

TEST(SxkRefine, PointOutsideTheMeshIsRefused) {
    RefineFixture f;
    const ProcessResult run = f.run({"--around", "5,0.5", "--size", "0.5"});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err, "sxk: refine_around: point (5, 0.5) is not in the mesh\n");
    EXPECT_EQ(run.out, "");
    EXPECT_FALSE(fs::exists(f.out));
    // just outside, the coordinates as given: six digits made it "(1, 0.5)", a point on the square
    const ProcessResult near = f.run({"--around", "1.0000001,0.5", "--size", "0.5"});
    EXPECT_EQ(near.exit_code, 1);
    EXPECT_EQ(near.err, "sxk: refine_around: point (1.0000001, 0.5) is not in the mesh\n");
}

// Two tetrahedra glued along <2,3,4> (file numbering), labels 1 and 2: longest-edge bisection
// around a point of the first one keeps the mesh valid, its labels and its boundary label.
TEST(SxkRefine, RefinesTetrahedraAroundAPoint) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh", out = folder / "out.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"refine", mesh.string(), out.string(), "--around",
                                   "0.2,0.2,0.2", "--size", "0.3", "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const nlohmann::json json = nlohmann::json::parse(run.out);
    const int bisections = json["bisections"].get<int>();
    EXPECT_GT(bisections, 3);
    // every bisection adds one vertex
    EXPECT_EQ(json["vertices"].get<int>(), 5 + bisections);
    EXPECT_EQ(sxk({"validate", out.string()}).exit_code, 0);
    const nlohmann::json info = nlohmann::json::parse(sxk({"info", out.string(), "--json"}).out);
    EXPECT_EQ(info["elements"], json["elements"]);
}

TEST(SxkRefine, AmpRuleRefinesTetrahedraAndUnknownRulesAreRefused) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh", out = folder / "out.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"refine", mesh.string(), out.string(), "--around",
                                   "0.2,0.2,0.2", "--size", "0.3", "--rule", "amp", "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json json = nlohmann::json::parse(run.out);
    EXPECT_GT(json["bisections"].get<int>(), 3);
    EXPECT_EQ(json["vertices"].get<int>(), 5 + json["bisections"].get<int>());
    EXPECT_EQ(sxk({"validate", out.string()}).exit_code, 0);

    const ProcessResult bad = sxk({"refine", mesh.string(), out.string(), "--around",
                                   "0.2,0.2,0.2", "--size", "0.3", "--rule", "newest"});
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("--rule: newest not in {longest-edge,amp}"), std::string::npos) << bad.err;
}

TEST(SxkRefine, PointOutsideTheTetrahedraIsRefused) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh", out = folder / "out.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run =
        sxk({"refine", mesh.string(), out.string(), "--around", "2,2,2", "--size", "0.1"});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err, "sxk: refine_around_tetrahedra: point (2, 2, 2) is not in the mesh\n");
    EXPECT_FALSE(fs::exists(out));
    // the hostile trial's "point (8, 4, 4)": rounded to six digits, a point outside read as one on the mesh
    const ProcessResult near =
        sxk({"refine", mesh.string(), out.string(), "--around", "2.0000001,2,2", "--size", "0.1"});
    EXPECT_EQ(near.exit_code, 1);
    EXPECT_EQ(near.err, "sxk: refine_around_tetrahedra: point (2.0000001, 2, 2) is not in the mesh\n");
}

TEST(SxkRefine, UnreadableInput) {
    ScratchFolder folder;
    const fs::path missing = folder / "none.mesh";
    const ProcessResult run = sxk({"refine", missing.string(), (folder / "out.mesh").string(),
                                   "--around", "0,0", "--size", "1"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err.rfind("sxk: " + missing.string() + ":0: ", 0), 0u) << run.err;
}

}  // namespace
}  // namespace sxk::test
