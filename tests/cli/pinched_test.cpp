// Pinched vertices through the sxk commands: split by default with a warning on stderr,
// --strict refuses them (every command that reads a mesh, plug-in commands too), sxk validate
// judges the file as it is. Medit triangles listed twice with another reference are reported.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

const fs::path pinched = fs::path(SXK_TEST_DATA_DIR) / "io" / "pinched.mesh";
const fs::path pinched_surface = fs::path(SXK_TEST_DATA_DIR) / "io" / "pinched_surface.off";

std::string split_warning(const fs::path& file, const std::string& what) {
    return "sxk: warning: " + file.string() + ": split " + what + " (--strict refuses them)\n";
}

TEST(SxkPinched, InfoSplitsAndSaysSo) {
    const ProcessResult run = sxk({"info", pinched.string(), "--json"});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, split_warning(pinched, "1 pinched vertex into 2"));
    const nlohmann::json json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["vertices"], 9);
    EXPECT_EQ(json["components"], 2);
}

TEST(SxkPinched, TwoPinchedVerticesArePlural) {
    const ProcessResult run = sxk({"info", pinched_surface.string()});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, split_warning(pinched_surface, "2 pinched vertices into 4"));
}

TEST(SxkPinched, StrictRefusesOnEveryCommandThatReadsAMesh) {
    ScratchFolder folder;
    write_file(folder / "faces.txt", "# none\n");
    const std::string refusal = "sxk: " + pinched.string() +
                                ":11: vertex 1 is non-manifold: the elements around it are not "
                                "connected through faces\n";
    const std::vector<std::vector<std::string>> commands = {
        {"info", pinched.string(), "--strict"},
        {"convert", "--strict", pinched.string(), (folder / "out.msh").string()},
        {"quality", "--strict", pinched.string()},
        {"components", "--strict", pinched.string()},
        {"dissect", "--strict", pinched.string(), (folder / "out.mesh").string(), "--faces",
         (folder / "faces.txt").string()},
        {"delaunay-flip", "--strict", pinched.string(), (folder / "out.mesh").string()},
        {"refine", "--strict", pinched.string(), (folder / "out.mesh").string(), "--around",
         "0.2,0.2,0.2", "--size", "0.3"},
        {"locate", "--strict", pinched.string(), "--points", (folder / "faces.txt").string()},
    };
    for (const auto& args : commands) {
        const ProcessResult run = sxk(args);
        EXPECT_EQ(run.exit_code, 2) << args[0] << ": " << run.err;
        EXPECT_EQ(run.err, refusal) << args[0];
        EXPECT_EQ(run.out, "") << args[0];
    }
    EXPECT_FALSE(fs::exists(folder / "out.msh"));
}

TEST(SxkPinched, PluginsCommandHasNoStrict) {
    const ProcessResult run = sxk({"plugins", "--strict"});
    EXPECT_EQ(run.exit_code, 2);
}

TEST(SxkPinched, ValidateJudgesTheFileAsItIs) {
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"validate", pinched.string()},
          std::vector<std::string>{"validate", "--flat-invalid", pinched.string()}}) {
        const ProcessResult run = sxk(args);
        EXPECT_EQ(run.exit_code, 1) << run.err;
        EXPECT_EQ(run.out, pinched.string() +
                               ": invalid: star connectivity: the star of vertex 0 is not "
                               "face-connected (2 of its 3 elements are reachable from element 0; "
                               "the mesh is pinched at this vertex)\n");
        EXPECT_EQ(run.err, "");
    }
}

TEST(SxkPinched, ConvertWritesTheSplitMeshWhichValidates) {
    ScratchFolder folder;
    for (const char* name : {"split.mesh", "split.msh", "split.node", "split.vtu"}) {
        const fs::path out = folder / name;
        const ProcessResult run = sxk({"convert", pinched.string(), out.string()});
        EXPECT_EQ(run.exit_code, 0) << name << ": " << run.err;
        EXPECT_EQ(run.err, split_warning(pinched, "1 pinched vertex into 2")) << name;
        if (std::string(name) == "split.vtu")
            continue;  // write only
        const ProcessResult check = sxk({"validate", out.string()});
        EXPECT_EQ(check.exit_code, 0) << name << ": " << check.out;
        EXPECT_EQ(check.out, out.string() + ": valid (9 vertices, 3 tetrahedra)\n");
        EXPECT_EQ(check.err, "");
    }
}

TEST(SxkPinched, MeditTriangleRepeatedWithAnotherReference) {
    ScratchFolder folder;
    const fs::path mesh = folder / "interface.mesh";
    // the interface triangle 1-2-3 from either side, with the subdomain of that side (CGAL)
    write_file(mesh, R"(MeshVersionFormatted 1
Dimension 3
Vertices
5
0 0 0 0
1 0 0 0
0 1 0 0
0 0 1 0
0 0 -1 0
Triangles
2
1 2 3 1
3 2 1 2
Tetrahedra
2
1 2 3 4 1
1 3 2 5 2
End
)");
    const ProcessResult run = sxk({"info", mesh.string()});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "sxk: warning: " + mesh.string() +
                           ":13: triangle 2 repeats triangle 1 with reference 2, not 1; the first "
                           "reference is kept\n");
    EXPECT_NE(run.out.find("face labels: 1\n"), std::string::npos) << run.out;
}

// CGAL Mesh_3 output (tests/data/io/README.md): two pinched vertices, each boundary triangle
// listed twice with the same reference.
TEST(SxkPinched, CgalMeshThroughInfoConvertAndValidate) {
    const fs::path cgal = fs::path(SXK_TEST_DATA_DIR) / "io" / "cgal_anchor_pinched.mesh";
    const ProcessResult info = sxk({"info", cgal.string(), "--json"});
    EXPECT_EQ(info.exit_code, 0) << info.err;
    EXPECT_EQ(info.err, split_warning(cgal, "2 pinched vertices into 4"));
    const nlohmann::json json = nlohmann::json::parse(info.out);
    EXPECT_EQ(json["vertices"], 258);
    EXPECT_EQ(json["elements"], 684);
    EXPECT_EQ(json["boundary_faces"], 524);

    const ProcessResult raw = sxk({"validate", cgal.string()});
    EXPECT_EQ(raw.exit_code, 1);
    EXPECT_EQ(raw.out, cgal.string() +
                           ": invalid: star connectivity: the star of vertex 29 is not "
                           "face-connected (2 of its 8 elements are reachable from element 136; "
                           "the mesh is pinched at this vertex)\n");

    ScratchFolder folder;
    for (const char* name : {"anchor.msh", "anchor.mesh"}) {
        const fs::path out = folder / name;
        const ProcessResult convert = sxk({"convert", cgal.string(), out.string()});
        EXPECT_EQ(convert.exit_code, 0) << convert.err;
        EXPECT_EQ(convert.err, split_warning(cgal, "2 pinched vertices into 4"));
        const ProcessResult valid = sxk({"validate", out.string()});
        EXPECT_EQ(valid.exit_code, 0) << valid.out;
        EXPECT_EQ(valid.out, out.string() + ": valid (258 vertices, 684 tetrahedra)\n");
        EXPECT_EQ(valid.err, "");
    }
}

#if SXK_HAVE_STATS
TEST(SxkPinched, PluginCommandsSplitAndTakeStrict) {
    const ProcessResult split = sxk({"stats", pinched.string(), "--json"});
    EXPECT_EQ(split.exit_code, 0) << split.err;
    EXPECT_EQ(split.err, split_warning(pinched, "1 pinched vertex into 2"));
    EXPECT_EQ(nlohmann::json::parse(split.out)["elements"], 3);
    const ProcessResult strict = sxk({"stats", pinched.string(), "--strict"});
    EXPECT_EQ(strict.exit_code, 2);
    EXPECT_EQ(strict.err, "sxk: " + pinched.string() +
                              ":11: vertex 1 is non-manifold: the elements around it are not "
                              "connected through faces\n");
}
#endif

}  // namespace
}  // namespace sxk::test

namespace sxk::test {
namespace {

// A labelled triangle of no tetrahedron (tests/data/malformed/medit_not_a_face.mesh, as CGAL's
// Mesh_3 writes surface facets whose cells lie outside the complex): dropped with a warning,
// refused with --strict, judged as it is by validate.
TEST(SxkStrayFaces, InfoDropsThemAndSaysSo) {
    const fs::path file = fs::path(SXK_TEST_DATA_DIR) / "malformed" / "medit_not_a_face.mesh";
    const ProcessResult run = sxk({"info", file.string(), "--json"});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "sxk: warning: " + file.string() +
                           ":14: triangle 2 is not a face of any tetrahedron; dropped (--strict refuses it)\n");
    const ProcessResult strict = sxk({"info", "--strict", file.string()});
    EXPECT_EQ(strict.exit_code, 2);
    EXPECT_EQ(strict.err, "sxk: " + file.string() + ":14: triangle 2 is not a face of any tetrahedron\n");
    const ProcessResult validate = sxk({"validate", file.string()});
    EXPECT_EQ(validate.exit_code, 1) << validate.err;
    EXPECT_EQ(validate.out.rfind(file.string() + ": invalid: face label: label 1 names ", 0), 0u) << validate.out;
}

}  // namespace
}  // namespace sxk::test
