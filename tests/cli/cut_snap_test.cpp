// sxk cut snap IN PATH OUT (the snapcut plug-in, thesis chapter 3) through the binary: the
// thesis' cube cut along a recorded path, the JSON report, --undo, and the exact errors for bad
// paths (exit 2) and for a scalpel that never meets the mesh.
#include <algorithm>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_sxk.hpp"
#include "two_bodies.hpp"
#include "sxk/io.hpp"

namespace sxk::test {
namespace {

struct SnapCutFixture {
    ScratchFolder folder;
    fs::path cube = folder / "cube.mesh";
    fs::path out = folder / "out.mesh";
    SnapCutFixture() { EXPECT_EQ(sxk({"generate", cube.string(), "--cells", "8"}).exit_code, 0); }
    fs::path path(const char* name, const std::string& text) {
        const fs::path file = folder / name;
        write_file(file, text);
        return file;
    }
    ProcessResult cut(const fs::path& path, std::vector<std::string> options = {}) {
        std::vector<std::string> args{"cut", "snap", cube.string(), path.string(), out.string()};
        args.insert(args.end(), options.begin(), options.end());
        return sxk(args);
    }
};

// The blade stands in x = 3.3 from z = 4 up and crosses the cube along y in 5 steps.
const char* grid_plane_path = R"(# time hx hy hz tx ty tz
0.0  3.3 -1 10  3.3 -1 4
0.1  3.3  1 10  3.3  1 4
0.2  3.3  3 10  3.3  3 4
0.3  3.3  5 10  3.3  5 4
0.4  3.3  7 10  3.3  7 4
0.5  3.3  9 10  3.3  9 4
)";

TEST(SxkCutSnap, CutsTheCubeAlongThePathAndReportsEachStep) {
    SnapCutFixture f;
    const ProcessResult run = f.cut(f.path("plane.path", grid_plane_path), {"--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["options"]["degeneracy_removal"], true);
    ASSERT_EQ(json["steps"].size(), 6u);
    for (const char* key : {"faces_dissected", "nodes_snapped", "degenerates_found", "cut_free", "elements",
                            "vertices", "seconds", "edges_hit", "loose_pieces", "phase_seconds"})
        EXPECT_TRUE(json["steps"][1].contains(key)) << key;
    EXPECT_EQ(json["steps"][0]["sweeps"], 0);
    EXPECT_EQ(json["steps"][1]["line"], 3);
    EXPECT_EQ(json["summary"]["faces_dissected"], 64);
    EXPECT_EQ(json["summary"]["vertices"]["after"], 729 + 36);
    EXPECT_EQ(json["summary"]["elements"]["after"], 3072);
    EXPECT_EQ(sxk({"validate", f.out.string()}).exit_code, 0);
}

// tools/incision-distance (docs/snapcut.md "The femur") on the same cut: the 9 x 5 grid nodes at
// x = 3 and the 36 copies the dissection made, snapped onto the blade's plane x = 3.3, lie on the
// swept surface; without snapping they stay 0.3 from it, every one.
TEST(SxkCutSnap, TheIncisionDistanceToolMeasuresHowFarTheCutIsFromTheSweep) {
    SnapCutFixture f;
    const fs::path path = f.path("plane.path", grid_plane_path);
    const std::string tool = SXK_SOURCE_DIR "/tools/incision-distance";
    ASSERT_EQ(f.cut(path).exit_code, 0);
    const ProcessResult snapped = run_program(tool, {f.out.string(), path.string(), "--h", "1"});
    ASSERT_EQ(snapped.exit_code, 0) << snapped.err;
    EXPECT_EQ(snapped.out.substr(0, snapped.out.find('\n')),
              "81 corners, in h: mean 0.000, median 0.000, p95 0.000, max 0.000, above 0.5: 0");
    ASSERT_EQ(f.cut(path, {"--no-snap"}).exit_code, 0);
    const ProcessResult unsnapped = run_program(tool, {f.out.string(), path.string(), "--h", "1"});
    ASSERT_EQ(unsnapped.exit_code, 0) << unsnapped.err;
    EXPECT_EQ(unsnapped.out.substr(0, unsnapped.out.find('\n')),
              "81 corners, in h: mean 0.300, median 0.300, p95 0.300, max 0.300, above 0.5: 0");
    const ProcessResult bad = run_program(tool, {f.cube.string(), path.string()});
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_EQ(bad.err, "incision-distance: no face with the cut label, or a path of fewer than 2 samples\n");
}

TEST(SxkCutSnap, UndoingEveryStepWritesTheInputAsTheWriterWritesIt) {
    SnapCutFixture f;
    const ProcessResult run = f.cut(f.path("plane.path", grid_plane_path), {"--undo", "all"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("6 steps undone"), std::string::npos) << run.out;
    const fs::path rewritten = f.folder / "rewritten.mesh";
    ASSERT_EQ(sxk({"convert", f.cube.string(), rewritten.string()}).exit_code, 0);
    EXPECT_EQ(slurp(f.out), slurp(rewritten));
    // and two steps undone leave the first four
    const ProcessResult partly = f.cut(f.path("plane.path", grid_plane_path), {"--undo", "2", "--json"});
    ASSERT_EQ(partly.exit_code, 0) << partly.err;
    EXPECT_EQ(nlohmann::json::parse(partly.out)["summary"]["undone"], 2);
    EXPECT_EQ(sxk({"validate", f.out.string()}).exit_code, 0);
}

TEST(SxkCutSnap, BadPathsAreRefusedWithTheirLine) {
    SnapCutFixture f;
    struct Case {
        const char* text;
        std::string message;
    };
    const std::vector<Case> cases{
        {"0 3.3 -1 10 3.3 -1 4\n0.1 3.3 x 10 3.3 1 4\n", ":2: expected a coordinate, found 'x'"},
        {"0 3.3 -1 10 3.3 -1 4\n0.1 3.3 nan 10 3.3 1 4\n", ":2: coordinate is not finite"},
        {"# one sample\n0 3.3 -1 10 3.3 -1 4\n", ":0: 1 sample; a path needs at least 2 (a tool moves from one to the next)"},
        {"0 3.3 -1 10 3.3 -1\n0.1 3.3 1 10 3.3 1\n", ":1: 5 values after the time; expected 6"},
        {"0 3.3 -1 10 3.3 -1 4\n0.1 3.3 1 10 3.3 1 4 5\n", ":2: more than 6 values after the time"},
    };
    for (const Case& c : cases) {
        const fs::path path = f.path("bad.path", c.text);
        const ProcessResult run = f.cut(path);
        EXPECT_EQ(run.exit_code, 2) << c.text;
        EXPECT_EQ(run.err, "sxk: " + path.string() + c.message + "\n") << c.text;
        EXPECT_FALSE(fs::exists(f.out));
    }
}

// The same cut given as the triangles the blade sweeps (an .obj, one step each): the movement
// from (h, t) to (h', t') sweeps (h, t, t') and (h, t', h'), so the mesh written is the same.
TEST(SxkCutSnap, APathOfSweptTrianglesCutsAsTheScalpelPath) {
    SnapCutFixture f;
    ASSERT_EQ(f.cut(f.path("plane.path", grid_plane_path)).exit_code, 0);
    const std::string by_samples = slurp(f.out);
    std::string obj = "# the blade of grid_plane_path: handles 1-6, tips 7-12\n";
    for (int end = 0; end < 2; ++end)
        for (int i = 0; i < 6; ++i) obj += "v 3.3 " + std::to_string(2 * i - 1) + (end == 0 ? " 10\n" : " 4\n");
    for (int i = 1; i < 6; ++i) {
        const std::string h = std::to_string(i), t = std::to_string(i + 6), t1 = std::to_string(i + 7),
                          h1 = std::to_string(i + 1);
        obj += "f " + h + " " + t + " " + t1 + "\nf " + h + " " + t1 + " " + h1 + "\n";
    }
    const ProcessResult run = f.cut(f.path("plane.obj", obj), {"--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    ASSERT_EQ(json["steps"].size(), 10u);
    EXPECT_EQ(json["steps"][0]["line"], 14);  // the first "f"
    EXPECT_EQ(json["summary"]["faces_dissected"], 64);
    EXPECT_EQ(slurp(f.out), by_samples);
    // bad triangle files: the OBJ reader's messages, and a file without faces
    const std::vector<std::pair<std::string, std::string>> cases{
        {"v 0 0 0\nv 1 0 0\nf 1 2\n", ":3: face has 2 vertices: a face needs 3"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", ":4: vertex index 4 out of range (1..3)"},
        {"v 0 0 0\n", ":0: no face: a swept path is a list of triangles ('f a b c')"},
    };
    for (const auto& [text, message] : cases) {
        fs::remove(f.out);
        const fs::path path = f.path("bad.obj", text);
        const ProcessResult bad = f.cut(path);
        EXPECT_EQ(bad.exit_code, 2) << text;
        EXPECT_EQ(bad.err, "sxk: " + path.string() + message + "\n") << text;
        EXPECT_FALSE(fs::exists(f.out));
    }
}

// --frames: a picture before the cut and one per step, through the bezier plug-in's renderer.
TEST(SxkCutSnap, FramesArePicturesOfEachStep) {
    SnapCutFixture f;
    const fs::path frames = f.folder / "frames" / "cube";  // made, parents too
    const ProcessResult run = f.cut(f.path("plane.path", grid_plane_path), {"--frames", frames.string(), "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(nlohmann::json::parse(run.out)["frames"], frames.string());
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(frames)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"step-0000.png", "step-0001.png", "step-0002.png", "step-0003.png",
                                               "step-0004.png", "step-0005.png", "step-0006.png"}));
    for (const std::string& name : names)
        EXPECT_EQ(slurp(frames / name).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << name;
    // (without a load the cut stays closed and the pictures alike: the deforming cut below differs)
    // a folder that cannot be made
    write_file(f.folder / "file", "x");
    const ProcessResult bad = f.cut(f.path("plane.path", grid_plane_path), {"--frames", (f.folder / "file").string()});
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_EQ(bad.err.rfind("sxk: cut snap: --frames: cannot make folder " + (f.folder / "file").string(), 0), 0u)
        << bad.err;
}

TEST(SxkCutSnap, AScalpelThatNeverMeetsTheMeshIsAnInputError) {
    SnapCutFixture f;
    const fs::path path = f.path("away.path", "# far away\n0 20 0 5 20 0 1\n1 20 5 5 20 5 1\n");
    const ProcessResult run = f.cut(path);
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: " + path.string() + ":2: the scalpel never meets the mesh (no sweep crosses an edge)\n");
    EXPECT_FALSE(fs::exists(f.out));
}

TEST(SxkCutSnap, UsageErrors) {
    SnapCutFixture f;
    const fs::path path = f.path("plane.path", grid_plane_path);
    EXPECT_EQ(f.cut(path, {"--undo", "7"}).err, "sxk: cut snap: --undo 7: only 6 steps were taken\n");
    const ProcessResult bad_undo = f.cut(path, {"--undo", "some"});
    EXPECT_EQ(bad_undo.exit_code, 2);
    EXPECT_NE(bad_undo.err.find("'some' is neither a whole number >= 0 nor 'all'"), std::string::npos) << bad_undo.err;
    const ProcessResult bad_aspect = f.cut(path, {"--aspect", "2"});
    EXPECT_EQ(bad_aspect.exit_code, 2);
    EXPECT_NE(bad_aspect.err.find("--aspect: '2' is not in (0, 1)"), std::string::npos) << bad_aspect.err;
    const ProcessResult bad_split = f.cut(path, {"--split-beyond", "-0.5"});
    EXPECT_EQ(bad_split.exit_code, 2);
    EXPECT_NE(bad_split.err.find("--split-beyond: '-0.5' is not in [0, 1000]"), std::string::npos) << bad_split.err;
    const fs::path square = f.folder / "square.mesh";
    ASSERT_EQ(sxk({"convert", SXK_TEST_DATA_DIR "/io/square.mesh", square.string()}).exit_code, 0);
    const ProcessResult planar = sxk({"cut", "snap", square.string(), path.string(), f.out.string()});
    EXPECT_EQ(planar.exit_code, 2);
    EXPECT_EQ(planar.err, "sxk: " + square.string() + ":0: the snap cutter cuts tetrahedral meshes in space\n");
    const ProcessResult help = sxk({"cut", "snap", "--help"});
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.out.find("--no-degeneracy-removal"), std::string::npos);
    EXPECT_NE(help.out.find("--split-beyond"), std::string::npos);
}

TEST(SxkCutSnap, ListedAsAPluginCommandAndCutsADeformingBody) {
    const ProcessResult plugins = sxk({"plugins"});
    EXPECT_NE(plugins.out.find("snapcut 0.1.0  snap cutting: a scalpel cuts tetrahedral meshes along faces, snapped "
                               "and cleaned (thesis 3.2)\n"),
              std::string::npos)
        << plugins.out;
    SnapCutFixture f;
    const fs::path path = f.path("plane.path", grid_plane_path);
    const ProcessResult run =
        f.cut(path, {"--json", "--deform", "--fix y<0.001 --force y>7.99:0,20000,0 --E 1e5", "--relax-iterations", "30",
                     "--frames", (f.folder / "frames").string()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(slurp(f.folder / "frames" / "step-0000.png"), slurp(f.folder / "frames" / "step-0006.png"));
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["initial_relax"]["converged"], true);
    EXPECT_EQ(json["steps"][3]["relax"]["shown"], true);
    EXPECT_LE(json["steps"][3]["relax"]["iterations"].get<int>(), 30);
    EXPECT_EQ(sxk({"validate", f.out.string()}).exit_code, 0);
    const ProcessResult bad = f.cut(path, {"--deform", "--fix x<-5"});
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_EQ(bad.err, "sxk: cut snap: --deform: deform: --fix 'x<-5' selects no vertex of the mesh\n");
}

// --local N: each step relaxes a region around what it changed; the JSON says how large, and the
// options carry it.
TEST(SxkCutSnap, ADeformingBodyRelaxedOnlyAroundEachStep) {
    SnapCutFixture f;
    const fs::path path = f.path("plane.path", grid_plane_path);
    const ProcessResult run = f.cut(path, {"--json", "--deform", "--fix y<0.001 --force y>7.99:0,20000,0 --E 1e5",
                                           "--relax-iterations", "200", "--local", "100", "--far", "50"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["options"]["local_vertices"], 100);
    EXPECT_EQ(json["options"]["far_vertices"], 50);
    std::size_t cutting = 0;
    for (const auto& step : json["steps"]) {
        if (step["faces_dissected"].get<int>() == 0) continue;
        ++cutting;
        EXPECT_GT(step["relax"]["region_vertices"].get<int>(), 0) << step.dump();
        EXPECT_LT(step["relax"]["region_vertices"].get<int>(), 729) << step.dump();
    }
    EXPECT_GT(cutting, 0u);
    EXPECT_EQ(sxk({"validate", f.out.string()}).exit_code, 0);
    const ProcessResult bad = f.cut(path, {"--deform", "--fix y<0.001", "--local", "-3"});
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_EQ(bad.err, "sxk: cut snap: --local: '-3' is not a whole number in 0..100000000\n"
                       "Run 'sxk cut snap --help' for more information.\n");
}

// --undo takes decimal digits or 'all', read once: "20e-1" passed the check as a whole-valued
// number and std::stoull then undid 20 steps; "1e3" undid 1 (issue 47).
TEST(SxkCutSnap, UndoTakesDecimalDigitsOnly) {
    SnapCutFixture f;
    const fs::path path = f.path("plane.path", grid_plane_path);
    for (const std::string undo : {"20e-1", "1e3", "2.0", "+2", "0x2", "-0", "18446744073709551616"}) {
        const ProcessResult run = f.cut(path, {"--undo", undo});
        EXPECT_EQ(run.exit_code, 2) << undo;
        EXPECT_EQ(run.err, "sxk: cut snap: --undo: '" + undo +
                               "' is neither a whole number >= 0 nor 'all'\nRun 'sxk cut snap --help' for more "
                               "information.\n")
            << undo;
        EXPECT_FALSE(fs::exists(f.out)) << undo;
    }
    const ProcessResult two = f.cut(path, {"--undo", "02", "--json"});
    ASSERT_EQ(two.exit_code, 0) << two.err;
    EXPECT_EQ(nlohmann::json::parse(two.out)["summary"]["undone"], 2);
    EXPECT_EQ(sxk({"validate", f.out.string()}).exit_code, 0);
}

// Two cubes side by side, both cut through in one step along x = 3.3 (snapped to x = 3): each
// loses its smaller part, 3/8 of it, and keeps the larger. The race between the searches once
// ran over both bodies at once and removed three of the four halves (issue 47).
TEST(SxkCutSnap, RemoveLooseKeepsTheLargerPartOfEachBody) {
    ScratchFolder folder;
    const fs::path two = folder / "two.mesh", out = folder / "out.mesh", path = folder / "through.path";
    write_two_cubes(two, {0, 10, 0});
    write_file(path, "# time hx hy hz tx ty tz: one movement through both cubes\n"
                     "0 3.3 -1 10 3.3 -1 -1\n"
                     "1 3.3 19 10 3.3 19 -1\n");
    const ProcessResult run = sxk({"cut", "snap", two.string(), path.string(), out.string(), "--remove-loose", "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["steps"][1]["loose_pieces"], nlohmann::json::parse("[1152, 1152]"));
    EXPECT_EQ(json["summary"]["elements"]["after"], 2 * 1920);
    const ProcessResult components = sxk({"components", out.string()});
    ASSERT_EQ(components.exit_code, 0) << components.err;
    EXPECT_EQ(components.out.substr(0, components.out.find('\n')), "components: 2");
    EXPECT_EQ(sxk({"validate", out.string()}).exit_code, 0);
}

// Loads whose norm overflows a double: the solve before the cut is refused (it once "converged"
// with |r| inf <= inf and the cut went on), exit 1, nothing written; the JSON says why.
TEST(SxkCutSnap, ADeformingBodyWithLoadsTooLargeIsRefused) {
    SnapCutFixture f;
    const fs::path path = f.path("plane.path", grid_plane_path);
    const std::string too_large =
        "relax: elasticity: the loads are too large: their norm overflows a double, so no residual can be "
        "measured against them; scale the loads, or the units, down";
    const ProcessResult run = f.cut(path, {"--deform", "--fix z<0.001 --force z>7.99:0,0,1e200"});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err, "sxk: cut snap: --deform: " + too_large + "; nothing cut or written\n");
    EXPECT_EQ(run.out, "");
    EXPECT_FALSE(fs::exists(f.out));
    const ProcessResult json_run = f.cut(path, {"--deform", "--fix z<0.001 --force z>7.99:0,0,1e200", "--json"});
    EXPECT_EQ(json_run.exit_code, 1);
    const auto json = nlohmann::json::parse(json_run.out);
    EXPECT_EQ(json["initial_relax"]["converged"], false);
    EXPECT_EQ(json["initial_relax"]["refusal"]["code"], "bad_argument");
    EXPECT_EQ(json["initial_relax"]["refusal"]["reason"], too_large);
    EXPECT_EQ(json["steps"].size(), 0u);
    EXPECT_FALSE(fs::exists(f.out));
}

// A load whose linear answer inverts elements cannot be shown: the undeformed body was cut and
// text mode said nothing (issue 47). Refused as `sxk deform` refuses it: exit 1, nothing written,
// the JSON's initial_relax not shown, with the reason.
TEST(SxkCutSnap, ALoadedShapeThatCannotBeShownIsRefused) {
    SnapCutFixture f;
    const fs::path path = f.path("plane.path", grid_plane_path);
    const std::string load = "--fix y<0.001 --force y>7.99:0,1e9,0 --E 1e5";
    const ProcessResult run = f.cut(path, {"--deform", load});
    EXPECT_EQ(run.exit_code, 1);
    const std::string start = "sxk: cut snap: --deform: elasticity: the solution cannot be shown: element ";
    EXPECT_EQ(run.err.substr(0, start.size()), start) << run.err;
    const std::string end = " would be inverted in the deformed positions; nothing cut or written\n";
    ASSERT_GT(run.err.size(), end.size());
    EXPECT_EQ(run.err.substr(run.err.size() - end.size()), end) << run.err;
    EXPECT_FALSE(fs::exists(f.out));
    const ProcessResult json_run = f.cut(path, {"--deform", load, "--json"});
    EXPECT_EQ(json_run.exit_code, 1);
    const auto json = nlohmann::json::parse(json_run.out);
    EXPECT_EQ(json["initial_relax"]["shown"], false);
    EXPECT_EQ(json["initial_relax"]["refusal"]["code"], "would_invert");
    EXPECT_EQ("sxk: cut snap: --deform: " + json["initial_relax"]["refusal"]["reason"].get<std::string>() +
                  "; nothing cut or written\n",
              run.err);
}

// The relaxation's options without --deform (or --far without --local) were ignored in silence.
TEST(SxkCutSnap, RelaxationOptionsNeedADeformingBody) {
    SnapCutFixture f;
    const fs::path path = f.path("plane.path", grid_plane_path);
    const std::string hint = "Run 'sxk cut snap --help' for more information.\n";
    const std::string why = ": only with --deform (it says how the deforming body relaxes after each step)\n";
    for (const auto& [option, value] : std::vector<std::pair<std::string, std::string>>{
             {"--relax-iterations", "5"}, {"--local", "100"}, {"--far", "50"}}) {
        const ProcessResult run = f.cut(path, {option, value});
        EXPECT_EQ(run.exit_code, 2) << option;
        EXPECT_EQ(run.err, "sxk: cut snap: " + option + why + hint);
        EXPECT_FALSE(fs::exists(f.out));
    }
    const ProcessResult far = f.cut(path, {"--deform", "--fix y<0.001", "--far", "50"});
    EXPECT_EQ(far.exit_code, 2);
    EXPECT_EQ(far.err, "sxk: cut snap: --far: only with --local N > 0 (it relaxes the far field that a local "
                       "relaxation leaves)\n" + hint);
    EXPECT_FALSE(fs::exists(f.out));
}

// With --deform the solve before the first step writes the loaded shape outside any step:
// `--undo all` left it in OUT, which was then not IN (issue 47). Undoing every step takes it back.
TEST(SxkCutSnap, UndoingEveryStepOfADeformingCutWritesTheInput) {
    SnapCutFixture f;
    const fs::path path = f.path("plane.path", grid_plane_path);
    const ProcessResult run =
        f.cut(path, {"--deform", "--fix y<0.001 --force y>7.99:0,20000,0 --E 1e5", "--undo", "all"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("6 steps undone"), std::string::npos) << run.out;
    const fs::path rewritten = f.folder / "rewritten.mesh";
    ASSERT_EQ(sxk({"convert", f.cube.string(), rewritten.string()}).exit_code, 0);
    EXPECT_EQ(slurp(f.out), slurp(rewritten));
    // some steps undone: the body stays loaded
    ASSERT_EQ(f.cut(path, {"--deform", "--fix y<0.001 --force y>7.99:0,20000,0 --E 1e5", "--undo", "5"}).exit_code,
              0);
    EXPECT_NE(slurp(f.out), slurp(rewritten));
    EXPECT_EQ(sxk({"validate", f.out.string()}).exit_code, 0);
}

// The degeneracy removal of a step stays around the nodes the step snapped and split: at
// --aspect 0.41, where every element of the Kuhn cube is below the threshold, one step's removal
// once collapsed the cube's 3072 elements to 1, and at 0.5 failed after seconds (issue 47). Each
// step's removal reaches a ring beyond the stars of the nodes it snapped and split
// (tests/plugins/degeneracy_snap_test.cpp checks that bound), so the cut keeps most of the cube.
TEST(SxkCutSnap, TheDegeneracyRemovalStaysLocalAtAnyThreshold) {
    SnapCutFixture f;
    const fs::path path = f.path("plane.path", grid_plane_path);
    for (const std::string aspect : {"0.41", "0.5"}) {
        const ProcessResult run = f.cut(path, {"--aspect", aspect, "--json"});
        ASSERT_EQ(run.exit_code, 0) << aspect << run.err;
        const auto json = nlohmann::json::parse(run.out);
        EXPECT_GT(json["summary"]["elements"]["after"].get<int>(), 2000) << aspect;
        EXPECT_EQ(sxk({"validate", f.out.string()}).exit_code, 0) << aspect;
    }
    // at 0.41 the cube's far side, three cells and more from the blade at x = 3.3, is untouched:
    // its 2 x 8 x 8 cells of 6 tetrahedra each
    ASSERT_EQ(f.cut(path, {"--aspect", "0.41"}).exit_code, 0);
    const Mesh cut = read_mesh(f.out);
    std::size_t far = 0;
    for (const ElementId t : elements(cut)) {
        const auto corners = cut.simplex(t).vertices();
        far += std::all_of(corners.begin(), corners.end(), [&](VertexId v) { return cut.reference(v)[0] >= 6; });
    }
    EXPECT_EQ(far, 768u);
}

// --cut-label 0 labels the cut faces 0: the kernel's face labels are optional (no label is the
// absence of one, docs/kernel.md "Cut marks"), so 0 is a label like any other, and every writer
// with face labels keeps it (issue 47 found the cut faces unlabelled in a Gmsh file, whose
// writer then gave label 0 no physical group).
TEST(SxkCutSnap, CutLabelZeroIsALabelLikeAnyOther) {
    SnapCutFixture f;
    const fs::path path = f.path("plane.path", grid_plane_path);
    for (const std::string name : {"zero.mesh", "zero.msh"}) {
        const fs::path out = f.folder / name;
        const ProcessResult run = sxk({"cut", "snap", f.cube.string(), path.string(), out.string(), "--cut-label", "0"});
        ASSERT_EQ(run.exit_code, 0) << run.err;
        const Mesh cut = read_mesh(out);
        std::size_t zero = 0;
        for (const auto& [face, label] : cut.face_labels()) zero += label == 0;
        EXPECT_EQ(zero, 128u) << name;  // 64 faces dissected, two boundary faces each
        EXPECT_EQ(cut.face_labels().size(), 128u) << name;
        EXPECT_TRUE(cut.validate().ok()) << name;
    }
}

TEST(SxkGenerate, TheThesisCubeAndTheDelaunayCylinder) {
    ScratchFolder folder;
    const ProcessResult cube = sxk({"generate", (folder / "cube.mesh").string(), "--cells", "8"});
    ASSERT_EQ(cube.exit_code, 0) << cube.err;
    EXPECT_EQ(cube.out, (folder / "cube.mesh").string() + ": 729 vertices, 3072 tetrahedra\n");
    const ProcessResult beam = sxk({"generate", (folder / "beam.mesh").string(), "--cells", "16,4,4", "--spacing",
                                    "0.075,0.05,0.075"});
    ASSERT_EQ(beam.exit_code, 0) << beam.err;
    EXPECT_EQ(beam.out, (folder / "beam.mesh").string() + ": 425 vertices, 1536 tetrahedra\n");
    const ProcessResult cylinder = sxk({"generate", (folder / "cyl.mesh").string(), "--shape", "cylinder"});
    ASSERT_EQ(cylinder.exit_code, 0) << cylinder.err;
    EXPECT_EQ(cylinder.out.rfind((folder / "cyl.mesh").string() + ": 896 vertices, ", 0), 0u) << cylinder.out;
    EXPECT_EQ(sxk({"validate", (folder / "cyl.mesh").string()}).exit_code, 0);
    const ProcessResult bad = sxk({"generate", (folder / "x.mesh").string(), "--cells", "8,8"});
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_EQ(bad.err, "sxk: generate: --cells: expected one number or three (X,Y,Z), found 2 in '8,8'\n");
    const ProcessResult zero = sxk({"generate", (folder / "x.mesh").string(), "--cells", "0"});
    EXPECT_EQ(zero.err, "sxk: generate: --cells: '0' is not a whole number in 1..1000 per axis\n");
}

}  // namespace
}  // namespace sxk::test
