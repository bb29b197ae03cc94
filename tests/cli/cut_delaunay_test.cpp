// sxk cut delaunay IN PATH OUT (the delaunaycut plug-in, thesis chapter 5) through the binary: the
// thesis' square cut by both methods, the JSON report, the pictures, --undo, and the exact errors
// for bad paths, a scalpel that never enters and meshes it cannot cut.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

struct DelaunayCutFixture {
    ScratchFolder folder;
    fs::path square = folder / "square.mesh";
    fs::path out = folder / "out.mesh";
    const std::string curve = SXK_SOURCE_DIR "/tests/data/paths/square-curve.path";
    DelaunayCutFixture() { EXPECT_EQ(sxk({"generate", square.string(), "--shape", "square", "--cells", "5"}).exit_code, 0); }
    fs::path path(const char* name, const std::string& text) {
        const fs::path file = folder / name;
        write_file(file, text);
        return file;
    }
    ProcessResult cut(const std::string& path, std::vector<std::string> options = {}) {
        std::vector<std::string> args{"cut", "delaunay", square.string(), path, out.string()};
        args.insert(args.end(), options.begin(), options.end());
        return sxk(args);
    }
};

TEST(SxkCutDelaunay, CutsTheThesisSquareByBothMethodsAndReportsEachStep) {
    DelaunayCutFixture f;
    const ProcessResult delaunay = f.cut(f.curve, {"--json"});
    ASSERT_EQ(delaunay.exit_code, 0) << delaunay.err;
    EXPECT_EQ(delaunay.err, "");
    const auto json = nlohmann::json::parse(delaunay.out);
    EXPECT_EQ(json["method"], "delaunay");
    ASSERT_EQ(json["steps"].size(), 61u);
    for (const char* key : {"phase", "entries", "fix_ups", "exits", "flips", "nodes_removed", "incision_splits",
                            "edges_split", "faces_dissected", "collapses", "lag", "elements", "vertices", "seconds"})
        EXPECT_TRUE(json["steps"][1].contains(key)) << key;
    EXPECT_EQ(json["steps"][1]["line"], 5);
    EXPECT_EQ(json["steps"].back()["phase"], "outside");
    EXPECT_EQ(json["triangles_before"], 50);
    EXPECT_LE(json["growth"].get<int>(), 10);  // thesis Fig. 5.16: +10
    EXPECT_EQ(sxk({"validate", f.out.string()}).exit_code, 0);
    EXPECT_EQ(sxk({"components", f.out.string()}).out.substr(0, 14), "components: 2\n");

    const ProcessResult subdivision = f.cut(f.curve, {"--json", "--method", "subdivision"});
    ASSERT_EQ(subdivision.exit_code, 0) << subdivision.err;
    const auto sub = nlohmann::json::parse(subdivision.out);
    EXPECT_GT(sub["growth"].get<int>(), json["growth"].get<int>());
    EXPECT_GT(json["smallest_angle_after"].get<double>(), 2 * sub["smallest_angle_after"].get<double>());
}

TEST(SxkCutDelaunay, DrawsTheCutAndTheAngleHistograms) {
    DelaunayCutFixture f;
    const fs::path svg = f.folder / "cut.svg", histogram = f.folder / "angles.svg";
    const ProcessResult run = f.cut(f.curve, {"--svg", svg.string(), "--histogram", histogram.string()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const std::string picture = slurp(svg);
    EXPECT_EQ(picture.rfind("<svg", 0), 0u);
    EXPECT_NE(picture.find("stroke=\"#d01c1c\""), std::string::npos);  // the incision
    EXPECT_NE(picture.find("<polyline"), std::string::npos);           // the path
    EXPECT_NE(slurp(histogram).find("smallest angle, after"), std::string::npos);
    EXPECT_NE(run.out.find("triangles 50 -> "), std::string::npos) << run.out;
}

TEST(SxkCutDelaunay, UndoingEveryStepWritesTheInputAsTheWriterWritesIt) {
    DelaunayCutFixture f;
    for (const char* method : {"delaunay", "subdivision"}) {
        const ProcessResult run = f.cut(f.curve, {"--undo", "all", "--method", method});
        ASSERT_EQ(run.exit_code, 0) << run.err;
        EXPECT_NE(run.out.find("61 steps undone"), std::string::npos) << run.out;
        EXPECT_EQ(slurp(f.out), slurp(f.square)) << method;
    }
}

TEST(SxkCutDelaunay, BadPathsAndMeshesAreRefusedWithTheirLine) {
    DelaunayCutFixture f;
    struct Case {
        const char* text;
        std::string message;
    };
    const std::vector<Case> cases{
        {"0 -1 2\n0.1 x 2\n", ":2: expected a coordinate, found 'x'"},
        {"0 -1 2\n0.1 nan 2\n", ":2: coordinate is not finite"},
        {"0 -1 2\n", ":0: 1 sample; a path needs at least 2 (a tool moves from one to the next)"},
        {"0 -1 2\n0.1 1 2 3\n", ":2: 3 values after the time; the first sample has 2"},
        {"0 -1 -1 -1\n0.1 -1 -2 -1\n", ":1: 3 values after the time; expected 2 or 6"},
        {"# outside all along\n0 -1 2\n0.1 -1 4\n", ":2: the scalpel never enters the mesh (no movement crosses its "
                                                    "boundary inwards)"},
        {"0 0 0 1 0 0 0\n0.1 1 0 1 1 0 0\n", ":1: a line scalpel ('time hx hy hz tx ty tz') cuts triangle surfaces "
                                             "in space (thesis 5.3); " + f.square.string() +
                                             " is not one (planar cuts take 'time x y')"},
    };
    for (const Case& c : cases) {
        const fs::path path = f.path("bad.path", c.text);
        const ProcessResult run = f.cut(path.string());
        EXPECT_EQ(run.exit_code, 2) << c.text;
        EXPECT_EQ(run.err, "sxk: " + path.string() + c.message + "\n") << c.text;
        EXPECT_FALSE(fs::exists(f.out));
    }
    const fs::path cube = f.folder / "cube.mesh";
    ASSERT_EQ(sxk({"generate", cube.string(), "--cells", "1"}).exit_code, 0);
    const ProcessResult tetrahedra = sxk({"cut", "delaunay", cube.string(), f.curve, f.out.string()});
    EXPECT_EQ(tetrahedra.exit_code, 2);
    EXPECT_EQ(tetrahedra.err,
              "sxk: " + cube.string() +
                  ":0: delaunaycut: the planar cutter needs a triangle mesh in the plane (Dimension 2)\n");
    const ProcessResult option = f.cut(f.curve, {"--eps-edge", "0"});
    EXPECT_EQ(option.exit_code, 2);
    EXPECT_NE(option.err.find("--eps-edge: '0' is not in (0, 10]"), std::string::npos) << option.err;
}

// Thesis Fig. 5.19: the 392-triangle Gaussian bell cut twice by a line scalpel
// (tests/data/paths/bell-two-cuts.path): an upright blade from boundary to boundary, then a level one
// across the top, which branches around it and meets itself behind it, crossing the first cut twice.
TEST(SxkCutDelaunay, CutsTheThesisBellTwiceWithALineScalpel) {
    ScratchFolder folder;
    const fs::path bell = folder / "bell.off", out = folder / "cut.mesh";
    const std::string path = SXK_SOURCE_DIR "/tests/data/paths/bell-two-cuts.path";
    const ProcessResult made = sxk({"generate", bell.string(), "--shape", "bell", "--cells", "14"});
    ASSERT_EQ(made.exit_code, 0) << made.err;
    EXPECT_EQ(made.out, bell.string() + ": 225 vertices, 392 triangles\n");
    const ProcessResult run = sxk({"cut", "delaunay", bell.string(), path, out.string(), "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["triangles_before"], 392);
    EXPECT_EQ(json["branches"], 1);
    EXPECT_EQ(json["annihilations"], 1);
    EXPECT_EQ(json["folded_neighbours_after"], 0);
    EXPECT_LT(json["incision_farthest"].get<double>(), 1.0 / 3);  // within eps_edge of the sweep
    EXPECT_GT(json["smallest_angle_after"].get<double>(), 10.0);
    for (const char* key : {"branches", "annihilations", "incisions"})
        EXPECT_TRUE(json["steps"][1].contains(key)) << key;
    EXPECT_EQ(sxk({"validate", out.string()}).exit_code, 0);
    // two halves of the bell, each with a piece of its top
    EXPECT_EQ(sxk({"components", out.string()}).out.substr(0, 14), "components: 4\n");
    // every step undone: the bell as the writer writes it
    const fs::path undone = folder / "undone.off";
    const ProcessResult back = sxk({"cut", "delaunay", bell.string(), path, undone.string(), "--undo", "all"});
    ASSERT_EQ(back.exit_code, 0) << back.err;
    EXPECT_EQ(slurp(undone), slurp(bell));
    // the scalpel must fit the mesh
    const std::string square_path = SXK_SOURCE_DIR "/tests/data/paths/square-curve.path";
    const ProcessResult point = sxk({"cut", "delaunay", bell.string(), square_path, out.string()});
    EXPECT_EQ(point.exit_code, 2);
    EXPECT_NE(point.err.find(": a point scalpel ('time x y') cuts planar meshes; " + bell.string() +
                             " is a surface in space, cut by a line scalpel ('time hx hy hz tx ty tz')\n"),
              std::string::npos)
        << point.err;
    const ProcessResult svg = sxk({"cut", "delaunay", bell.string(), path, out.string(), "--svg", "x.svg"});
    EXPECT_EQ(svg.exit_code, 2);
    EXPECT_EQ(svg.err, "sxk: --svg draws planar cuts; draw a surface's cut with 'sxk render " + out.string() +
                           " PICTURE.png'\n");
}

// The hostile trial: samples at +-1e17 around the square made only a dent, while +-1e3 ... 1e12 cut
// through. Along such a movement the whole square lies within one rounding step of its parameter:
// the movement was one piece, entered ~16 units off. Samples that far (more than 1e12 mean edges
// from the mesh's box) are refused with their line; 1e11 still cuts the square in two.
TEST(SxkCutDelaunay, SamplesTooFarFromTheMeshAreRefusedWithTheirLine) {
    DelaunayCutFixture f;
    const fs::path far = f.path("far.path", "0 -1e17 2.5\n1 1e17 2.5\n");
    const ProcessResult run = f.cut(far.string());
    EXPECT_EQ(run.exit_code, 2);
    // the 5 x 5 square's mean edge: (60 + 25 sqrt 2) / 85 = 1.1218
    EXPECT_EQ(run.err, "sxk: " + far.string() +
                           ":1: delaunaycut: the scalpel at (-1e+17, 2.5) is 1e+17 from the mesh, more than 1e12 mean "
                           "edges (1.12e+12): so far away a movement cannot be placed on the mesh in doubles\n");
    EXPECT_FALSE(fs::exists(f.out));
    const fs::path near = f.path("near.path", "0 -1e11 2.5\n1 1e11 2.5\n");
    for (const char* method : {"delaunay", "subdivision"}) {
        const ProcessResult cut = f.cut(near.string(), {"--method", method});
        ASSERT_EQ(cut.exit_code, 0) << method << ": " << cut.err;
        EXPECT_EQ(sxk({"validate", f.out.string()}).exit_code, 0) << method;
        EXPECT_EQ(sxk({"components", f.out.string()}).out.substr(0, 14), "components: 2\n") << method;
    }
}

// The same for the line scalpel on a surface: a blade whose tip or handle is more than 1e12 mean
// edges from the surface's box is refused with its line, and the bell is not written; one
// 1e3 away on either side cuts it in two.
TEST(SxkCutDelaunay, BladesTooFarFromTheSurfaceAreRefusedWithTheirLine) {
    ScratchFolder folder;
    const fs::path bell = folder / "bell.off", out = folder / "cut.off";
    ASSERT_EQ(sxk({"generate", bell.string(), "--shape", "bell", "--cells", "14"}).exit_code, 0);
    const fs::path far = folder / "far.path", near = folder / "near.path";
    write_file(far, "0 -1 7 9 -1 7 -1\n1 1e17 7 9 1e17 7 -1\n");
    const ProcessResult run = sxk({"cut", "delaunay", bell.string(), far.string(), out.string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err.rfind("sxk: " + far.string() + ":2: delaunaycut: the blade's tip at (1e+17, 7, -1) is 1e+17 from "
                            "the mesh, more than 1e12 mean edges (",
                            0),
              0u)
        << run.err;
    EXPECT_NE(run.err.find("): so far away a movement cannot be placed on the mesh in doubles\n"), std::string::npos)
        << run.err;
    EXPECT_FALSE(fs::exists(out));
    write_file(near, "0 -1e3 7 9 -1e3 7 -1\n1 1e3 7 9 1e3 7 -1\n");
    const ProcessResult cut = sxk({"cut", "delaunay", bell.string(), near.string(), out.string()});
    ASSERT_EQ(cut.exit_code, 0) << cut.err;
    EXPECT_EQ(sxk({"validate", out.string()}).exit_code, 0);
    EXPECT_EQ(sxk({"components", out.string()}).out.substr(0, 14), "components: 2\n");
}

// The hostile trial: a picture that cannot be written made the command exit 1 after OUT was
// replaced, and the message lacked "FILE:0:". Every output is checked before the cut: nothing is
// written, OUT stays as it was.
TEST(SxkCutDelaunay, AnUnwritablePictureIsRefusedBeforeOutIsReplaced) {
    DelaunayCutFixture f;
    write_file(f.out, "the user's old result\n");
    for (const char* option : {"--svg", "--histogram"}) {
        const std::string picture = (f.folder / "nowhere" / "x.svg").string();
        const ProcessResult run = f.cut(f.curve, {option, picture});
        EXPECT_EQ(run.exit_code, 1) << option;
        EXPECT_EQ(run.err, "sxk: " + picture + ":0: cannot write: No such file or directory\n") << option;
        EXPECT_EQ(run.out, "") << option;
        EXPECT_EQ(slurp(f.out), "the user's old result\n") << option;
    }
    // a directory where the picture goes
    const fs::path folder_in_the_way = f.folder / "in-the-way.svg";
    fs::create_directory(folder_in_the_way);
    const ProcessResult directory = f.cut(f.curve, {"--svg", folder_in_the_way.string()});
    EXPECT_EQ(directory.exit_code, 1);
    EXPECT_EQ(directory.err, "sxk: " + folder_in_the_way.string() + ":0: cannot write: is a directory\n");
    EXPECT_EQ(slurp(f.out), "the user's old result\n");
    // OUT itself: refused before the cut, with the same message the write gives
    const std::string lost = (f.folder / "nowhere" / "out.mesh").string();
    const ProcessResult out = sxk({"cut", "delaunay", f.square.string(), f.curve, lost});
    EXPECT_EQ(out.exit_code, 1);
    EXPECT_EQ(out.err, "sxk: " + lost + ":0: cannot write: No such file or directory\n");
}

// The hostile trial: `--svg sq19.mesh` overwrote the input mesh with SVG (exit 0), and `--svg
// x.png` wrote SVG into a .png name. A picture may be neither the input, nor OUT, nor the other
// picture, and its name must say what it holds.
TEST(SxkCutDelaunay, APictureMayNotOverwriteTheMeshesOrCarryAnotherExtension) {
    DelaunayCutFixture f;
    const std::string input = slurp(f.square);
    const std::string square = f.square.string();
    struct Case {
        std::vector<std::string> options;
        std::string message;
    };
    const fs::path svg = f.folder / "cut.svg";
    const std::vector<Case> cases{
        {{"--svg", square}, "--svg " + square + ": the same file as the input mesh " + square + "; name another file"},
        // the same file under another name
        {{"--histogram", (f.folder / "." / "square.mesh").string()},
         "--histogram " + (f.folder / "." / "square.mesh").string() + ": the same file as the input mesh " + square +
             "; name another file"},
        {{"--svg", f.out.string()},
         "--svg " + f.out.string() + ": the same file as the output mesh " + f.out.string() + "; name another file"},
        {{"--svg", svg.string(), "--histogram", svg.string()},
         "--histogram " + svg.string() + ": the same file as the file of --svg; name another file"},
        {{"--svg", (f.folder / "x.png").string()},
         "--svg " + (f.folder / "x.png").string() + ": the picture is SVG; name it *.svg"},
        {{"--histogram", (f.folder / "h.png").string()},
         "--histogram " + (f.folder / "h.png").string() + ": the histogram is SVG; name it *.svg"},
    };
    for (const Case& c : cases) {
        const ProcessResult run = f.cut(f.curve, c.options);
        EXPECT_EQ(run.exit_code, 2) << c.message;
        EXPECT_EQ(run.err, "sxk: cut delaunay: " + c.message + "\n");
        EXPECT_EQ(slurp(f.square), input) << c.message;
        EXPECT_FALSE(fs::exists(f.out)) << c.message;
        EXPECT_FALSE(fs::exists(svg)) << c.message;
        EXPECT_FALSE(fs::exists(f.folder / "x.png")) << c.message;
    }
    EXPECT_EQ(sxk({"validate", square}).exit_code, 0);
}

TEST(SxkGenerate, ThePlanarGridsOfTheThesis2DCuts) {
    ScratchFolder folder;
    const fs::path square = folder / "square.mesh", strip = folder / "strip.mesh";
    const ProcessResult fig = sxk({"generate", square.string(), "--shape", "square", "--cells", "19"});
    ASSERT_EQ(fig.exit_code, 0) << fig.err;
    EXPECT_EQ(fig.out, square.string() + ": 400 vertices, 722 triangles\n");  // thesis Fig. 5.8
    const ProcessResult two =
        sxk({"generate", strip.string(), "--shape", "square", "--cells", "3,2", "--spacing", "0.5,2"});
    ASSERT_EQ(two.exit_code, 0) << two.err;
    EXPECT_EQ(two.out, strip.string() + ": 12 vertices, 12 triangles\n");
    EXPECT_NE(slurp(strip).find("Dimension 2"), std::string::npos);
    EXPECT_EQ(sxk({"validate", strip.string()}).exit_code, 0);
    const ProcessResult three = sxk({"generate", strip.string(), "--shape", "square", "--cells", "3,2,1"});
    EXPECT_EQ(three.exit_code, 2);
    EXPECT_EQ(three.err, "sxk: generate: --cells: a square takes one number or two (X,Y), found 3 in '3,2,1'\n");
    const ProcessResult zero = sxk({"generate", strip.string(), "--shape", "square", "--cells", "0"});
    EXPECT_EQ(zero.err, "sxk: generate: --cells: '0' is not a whole number in 1..5000 per axis\n");
}

}  // namespace
}  // namespace sxk::test
