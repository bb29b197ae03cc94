// sxk degeneracies IN OUT (the degeneracy plug-in, thesis §3.2.3) through the binary: usage and
// input errors (exit 2), an unwritable output (exit 1), a cap removed by split + collapse, a
// flat triangle removed, a boundary spindle cut free or listed as remaining, the JSON report;
// and the plug-in's service "sxk.degeneracy" called in process through a PluginHost.
#include <gtest/gtest.h>

#include <sstream>

#include <nlohmann/json.hpp>

// the Service struct of the plug-in (test_cli does not link the plug-in: it loads degeneracy.so)
#include "../../plugins/degeneracy/degeneracy_plugin.hpp"
#include "core/fixtures.hpp"
#include "run_sxk.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/io.hpp"
#include "sxk/mesh.hpp"
#include "sxk/plugin_host.hpp"
#include "sxk/quality.hpp"
#include "sxk/tool_session.hpp"

namespace sxk::test {
namespace {

// A cap, seen from above (+z):
//
//                 c 3 (0.5,0.9,0)        d lies 0.001 above the centroid of abc; the apices
//                / \ .                   p (0.5,0.3,1) above and q (0.5,0.3,-1) below it make
//               /   \ .                  a bipyramid over abc. Upper half: the cap <a,b,c,d>
//              /  d  \ .                 (dihedral angles near pi at da, db, dc) plus
//             /  4    \ .                <a,b,d,p>, <b,c,d,p>, <c,a,d,p>; lower half <a,c,b,q>.
//   a 1 (0,0,0) ------ b 2 (1,0,0)      All five positive (det[b-a, c-a, d-a] > 0 for each
//                                       listed order). Removal: split abc at d's foot m and
// collapse m-d: the three flat pieces of abcd go, abcq's three stay: 6 tetrahedra.
const char* cap_mesh = R"(MeshVersionFormatted 2
Dimension 3
Vertices
6
0 0 0 0
1 0 0 0
0.5 0.9 0 0
0.5 0.3 0.001 0
0.5 0.3 1 0
0.5 0.3 -1 0
Tetrahedra
5
1 2 3 4 0
1 2 4 5 0
2 3 4 5 0
3 1 4 5 0
1 3 2 6 0
End
)";

//   4 ---------------- 3      4 (0,1)  3 (1,1)  1 (0,0)  2 (1,0)
//   | `.            .' |      5 (0.5, 0.501) just above the diagonal 1-3: <1,3,5> is flat
//   |    `.      .'    |      (its angle at 5 is near pi); <3,4,5>, <4,1,5> and the lower
//   |       `.5.'      |      half <1,2,3> are fine. Flipping 1-3 (<1,2,5>, <2,3,5>) or a
//   |      .'          |      split + collapse removes the flat one.
//   |   .'             |
//   1 ---------------- 2
const char* flat_triangle_mesh = R"(MeshVersionFormatted 2
Dimension 2
Vertices
5
0 0 0
1 0 0
1 1 0
0 1 0
0.5 0.501 0
Triangles
4
1 2 3 0
1 3 5 0
3 4 5 0
4 1 5 0
End
)";

//              d (0,1,0)        seen from above (+z). A spindle: c lies 0.004 above the
//             / \ .             midpoint of the boundary edge ab, so <b,a,c,d> has one
//            /   \ .            dihedral angle near pi (at cd, opposite ab). Removing it
//           /     \ .           (split ab at c's foot, collapse) would move c onto ab: c is on
//          /       \ .          the boundary face <a,b,c>, which would leave its plane by half
//         a----c----b           its longest edge. With --boundary-tolerance 0 the collapse is
//                               refused and the spindle is cut free (with --no-cut-free it is
//   a (-1,0,0)  b (1,0,0)       reported as remaining). e (0,0.4,-1) below, f (-0.8,0.6,0.8)
//   c (0,0,0.004)               and g (0.8,0.6,0.8) above: <b,a,d,e>, <a,c,d,f>, <c,b,d,g>.
const char* spindle_mesh = R"(MeshVersionFormatted 2
Dimension 3
Vertices
7
-1 0 0 0
1 0 0 0
0 0 0.004 0
0 1 0 0
0 0.4 -1 0
-0.8 0.6 0.8 0
0.8 0.6 0.8 0
Tetrahedra
4
2 1 3 4 0
2 1 4 5 0
1 3 4 6 0
3 2 4 7 0
End
)";

struct DegeneraciesFixture {
    ScratchFolder folder;
    fs::path out = folder / "out.mesh";
    fs::path input(const char* name, const char* text) {
        const fs::path path = folder / name;
        write_file(path, text);
        return path;
    }
    ProcessResult run(const fs::path& in, std::vector<std::string> options = {}) {
        std::vector<std::string> args{"degeneracies", in.string(), out.string()};
        args.insert(args.end(), options.begin(), options.end());
        return sxk(args);
    }
};

const std::string degeneracies_hint = "Run 'sxk degeneracies --help' for more information.\n";

TEST(SxkDegeneracies, HelpNamesEveryOption) {
    const ProcessResult run = sxk({"degeneracies", "--help"});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(run.err, "");
    for (const char* word : {"IN", "OUT", "--aspect", "--angle", "--no-cut-free", "--no-flips",
                             "--no-peel", "--boundary-tolerance", "--json", "sxk degeneracies"})
        EXPECT_NE(run.out.find(word), std::string::npos) << word << " missing from\n" << run.out;
}

TEST(SxkDegeneracies, ListedAsAPluginCommand) {
    const ProcessResult run = sxk({"plugins"});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_NE(
        run.out.find("degeneracy 0.1.0  removes flat elements: split, collapse, flip, cut free "
                     "(thesis 3.2.3)\n"),
        std::string::npos)
        << run.out;
    EXPECT_NE(run.out.find("  sxk degeneracies  "), std::string::npos) << run.out;
}

TEST(SxkDegeneracies, AspectOutOfRangeIsAUsageError) {
    DegeneraciesFixture f;
    const fs::path in = f.input("cap.mesh", cap_mesh);
    ProcessResult run = f.run(in, {"--aspect", "1.5"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: degeneracies: --aspect: '1.5' is not in (0, 1)\n" + degeneracies_hint);
    EXPECT_EQ(run.out, "");
    run = f.run(in, {"--aspect", "0"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: degeneracies: --aspect: '0' is not in (0, 1)\n" + degeneracies_hint);
    run = f.run(in, {"--aspect", "small"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: degeneracies: --aspect: expected a finite number, found 'small'\n" + degeneracies_hint);
    EXPECT_FALSE(fs::exists(f.out));
}

TEST(SxkDegeneracies, AngleAndToleranceOutOfRange) {
    DegeneraciesFixture f;
    const fs::path in = f.input("cap.mesh", cap_mesh);
    ProcessResult run = f.run(in, {"--angle", "1.5"});  // below pi/2
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: degeneracies: --angle: '1.5' is not in (pi/2, pi)\n" + degeneracies_hint);
    run = f.run(in, {"--angle", "3.15"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: degeneracies: --angle: '3.15' is not in (pi/2, pi)\n" + degeneracies_hint);
    run = f.run(in, {"--boundary-tolerance", "-0.1"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: degeneracies: --boundary-tolerance: '-0.1' is not in [0, 1)\n" + degeneracies_hint);
    EXPECT_FALSE(fs::exists(f.out));
}

TEST(SxkDegeneracies, NanAndInfiniteThresholdsAreRefused) {
    DegeneraciesFixture f;
    const fs::path in = f.input("cap.mesh", cap_mesh);
    for (const char* option : {"--aspect", "--angle", "--boundary-tolerance"})
        for (const char* value : {"nan", "inf", "-inf"}) {
            const ProcessResult run = f.run(in, {option, value});
            EXPECT_EQ(run.exit_code, 2) << option << ' ' << value;
            EXPECT_EQ(run.err, "sxk: degeneracies: " + std::string(option) + ": expected a finite number, found '" +
                                   value + "'\n" + degeneracies_hint);
        }
    EXPECT_FALSE(fs::exists(f.out));
}

TEST(SxkDegeneracies, OperandsAreRequired) {
    DegeneraciesFixture f;
    const fs::path in = f.input("cap.mesh", cap_mesh);
    const ProcessResult run = sxk({"degeneracies", in.string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: degeneracies: OUT is required\n" + degeneracies_hint);
}

TEST(SxkDegeneracies, MissingInputFile) {
    DegeneraciesFixture f;
    const fs::path missing = f.folder / "missing.mesh";
    const ProcessResult run = f.run(missing);
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: " + missing.string() + ":0: no such file\n");
    EXPECT_EQ(run.out, "");
    EXPECT_FALSE(fs::exists(f.out));
}

TEST(SxkDegeneracies, UnknownOutputFormat) {
    DegeneraciesFixture f;
    const fs::path in = f.input("cap.mesh", cap_mesh);
    const fs::path bad = f.folder / "out.xyz";
    const ProcessResult run = sxk({"degeneracies", in.string(), bad.string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err,
              "sxk: " + bad.string() +
                  ":0: unknown output format (known: .mesh .msh .node .ele .off .obj .vtu .vtk .stl .ply)\n");
    EXPECT_FALSE(fs::exists(bad));
}

TEST(SxkDegeneracies, UnwritableOutputIsARefusal) {
    DegeneraciesFixture f;
    const fs::path in = f.input("cap.mesh", cap_mesh);
    const fs::path out = f.folder / "missing-folder" / "out.mesh";
    const ProcessResult run = sxk({"degeneracies", in.string(), out.string()});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err.rfind("sxk: " + out.string() + ":0: cannot write: ", 0), 0u) << run.err;
    EXPECT_EQ(run.out, "");
}

// The fixture really has one cap and nothing else degenerate (else the tests below prove little).
TEST(SxkDegeneracies, CapFixtureHasOneCap) {
    DegeneraciesFixture f;
    const fs::path in = f.input("cap.mesh", cap_mesh);
    EXPECT_EQ(sxk({"validate", in.string()}).exit_code, 0);
    const nlohmann::json quality =
        nlohmann::json::parse(sxk({"quality", in.string(), "--json"}).out);
    EXPECT_EQ(quality["degenerate"], 1);
    EXPECT_EQ(quality["inverted"], 0);
    EXPECT_EQ(quality["flat"], 0);
    EXPECT_EQ(quality["degenerate_by_class"]["cap"], 1) << quality.dump(2);
}

TEST(SxkDegeneracies, RemovesTheCap) {
    DegeneraciesFixture f;
    const fs::path in = f.input("cap.mesh", cap_mesh);
    const ProcessResult run = f.run(in);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    EXPECT_EQ(run.out.rfind("pass  kind", 0), 0u) << run.out;
    EXPECT_NE(run.out.find("\nfound 1 degenerate: removed 1, cracks 0 (cut free), remaining 0\n"),
              std::string::npos)
        << run.out;
    EXPECT_NE(run.out.find(in.string() + " -> " + f.out.string() +
                           ": 6 tetrahedra, 6 vertices in elements\n"),
              std::string::npos)
        << run.out;

    ASSERT_TRUE(fs::exists(f.out));
    const Mesh result = read_mesh(f.out);
    EXPECT_TRUE(result.validate().ok());
    EXPECT_EQ(result.element_count(), 6u);
    const QualitySummary summary = summarize_quality(result);
    EXPECT_EQ(summary.degenerate, 0u);
    EXPECT_EQ(summary.inverted, 0u);
    EXPECT_EQ(summary.flat, 0u);
    const nlohmann::json quality =
        nlohmann::json::parse(sxk({"quality", f.out.string(), "--json"}).out);
    EXPECT_EQ(quality["degenerate"], 0);
    EXPECT_GE(quality["min_aspect_ratio"].get<double>(), 0.01);
}

TEST(SxkDegeneracies, JsonReport) {
    DegeneraciesFixture f;
    const fs::path in = f.input("cap.mesh", cap_mesh);
    const ProcessResult run = f.run(in, {"--json", "--aspect", "0.02"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["file"], in.string());
    EXPECT_EQ(json["output"], f.out.string());
    EXPECT_EQ(json["options"]["aspect_ratio"], 0.02);
    EXPECT_NEAR(json["options"]["large_angle"].get<double>(), 0.99 * pi, 1e-12);
    EXPECT_EQ(json["options"]["cut_free"], true);
    EXPECT_EQ(json["options"]["flips"], true);

    ASSERT_GE(json["passes"].size(), 1u);
    const nlohmann::json& first = json["passes"][0];
    EXPECT_EQ(first["pass"], 1);
    EXPECT_EQ(first["kind"], "collapse");
    EXPECT_EQ(first["found"]["cap"], 1);
    EXPECT_EQ(first["found"]["needle"], 0);
    EXPECT_EQ(first["found"]["spindle"], 0);
    EXPECT_EQ(first["found"]["sliver"], 0);
    EXPECT_EQ(first["found"]["total"], 1);
    // thesis Fig. 3.9: a cap is removed by one face split and one collapse
    EXPECT_EQ(first["splits"], 1);
    EXPECT_EQ(first["collapses"], 1);
    EXPECT_EQ(first["cut_free"], 0);
    EXPECT_EQ(first["elements"]["before"], 5);
    EXPECT_EQ(first["vertices"]["before"], 6);
    const nlohmann::json& last = json["passes"].back();
    EXPECT_GE(last["min_aspect_ratio_after"].get<double>(), 0.02);
    EXPECT_GT(last["min_angle_after"].get<double>(), 0);
    EXPECT_LT(last["max_angle_after"].get<double>(), 0.99 * pi);

    const nlohmann::json& summary = json["summary"];
    EXPECT_EQ(summary["found"], 1);
    EXPECT_EQ(summary["removed"], 1);
    EXPECT_EQ(summary["cracks"], 0);
    EXPECT_EQ(summary["remaining"], 0);
    EXPECT_EQ(summary["elements"]["before"], 5);
    EXPECT_EQ(summary["elements"]["after"], last["elements"]["after"]);
    EXPECT_EQ(json["remaining"], nlohmann::json::array());

    const Mesh result = read_mesh(f.out);
    EXPECT_TRUE(result.validate().ok());
    EXPECT_EQ(summary["elements"]["after"].get<std::size_t>(), result.element_count());
}

TEST(SxkDegeneracies, NoCutFreeAndNoFlipsAreAccepted) {
    DegeneraciesFixture f;
    const fs::path in = f.input("cap.mesh", cap_mesh);
    const ProcessResult run =
        f.run(in, {"--no-cut-free", "--no-flips", "--boundary-tolerance", "0", "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["options"]["cut_free"], false);
    EXPECT_EQ(json["options"]["flips"], false);
    EXPECT_EQ(json["options"]["boundary_tolerance"], 0.0);
    // the cap needs neither: split + collapse remove it, nothing is cut free
    EXPECT_EQ(json["summary"]["remaining"], 0);
    EXPECT_EQ(json["summary"]["cracks"], 0);
    for (const nlohmann::json& pass : json["passes"]) {
        EXPECT_EQ(pass["flips"], 0);
        EXPECT_EQ(pass["cut_free"], 0);
        EXPECT_EQ(pass["kind"], "collapse");
    }
    const Mesh result = read_mesh(f.out);
    EXPECT_TRUE(result.validate().ok());
    EXPECT_EQ(summarize_quality(result).degenerate, 0u);
}

TEST(SxkDegeneracies, RemovesAFlatTriangle) {
    DegeneraciesFixture f;
    const fs::path in = f.input("flat.mesh", flat_triangle_mesh);
    const Mesh before = read_mesh(in);
    ASSERT_TRUE(before.validate().ok());
    ASSERT_EQ(summarize_quality(before).degenerate, 1u);

    const ProcessResult run = f.run(in, {"--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["summary"]["found"], 1);
    EXPECT_EQ(json["summary"]["remaining"], 0);
    EXPECT_EQ(json["summary"]["cracks"], 0);
    const Mesh result = read_mesh(f.out);
    EXPECT_TRUE(result.validate().ok());
    EXPECT_EQ(result.topological_dimension(), 2);
    const QualitySummary summary = summarize_quality(result);
    EXPECT_EQ(summary.degenerate, 0u);
    EXPECT_EQ(summary.inverted, 0u);
    EXPECT_EQ(json["summary"]["elements"]["after"].get<std::size_t>(), result.element_count());
}

TEST(SxkDegeneracies, WhatCannotCollapseIsCutFree) {
    DegeneraciesFixture f;
    const fs::path in = f.input("spindle.mesh", spindle_mesh);
    const ProcessResult run =
        f.run(in, {"--boundary-tolerance", "0", "--no-flips", "--no-peel", "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["passes"][0]["found"]["spindle"], 1);
    EXPECT_EQ(json["summary"]["found"], 1);
    EXPECT_EQ(json["summary"]["cracks"], 1);
    EXPECT_EQ(json["summary"]["removed"], 1);
    EXPECT_EQ(json["summary"]["remaining"], 0);
    EXPECT_EQ(json["summary"]["collapses"], 0);
    EXPECT_EQ(json["summary"]["splits"], 0);  // the refused split + collapse left no trace
    const nlohmann::json& last = json["passes"].back();
    EXPECT_EQ(last["kind"], "cut free");
    EXPECT_EQ(last["cut_free"], 1);
    EXPECT_EQ(last["elements"]["before"], 4);
    EXPECT_EQ(last["elements"]["after"], 3);
    const Mesh result = read_mesh(f.out);
    EXPECT_TRUE(result.validate().ok());
    EXPECT_EQ(result.element_count(), 3u);
    EXPECT_EQ(summarize_quality(result).degenerate, 0u);
}

// The spindle of spindle_mesh alone: cutting it free leaves no element at all. A file of no
// elements is one no command reads, so the result is refused (exit 1) and the output that was
// there before stays as it was.
TEST(SxkDegeneracies, AnEmptyResultIsRefusedAndNothingWritten) {
    DegeneraciesFixture f;
    const fs::path in = f.input("lone_spindle.mesh", R"(MeshVersionFormatted 2
Dimension 3
Vertices
4
-1 0 0 0
1 0 0 0
0 0 0.004 0
0 1 0 0
Tetrahedra
1
2 1 3 4 0
End
)");
    write_file(f.out, "precious\n");
    const ProcessResult run = f.run(in, {"--boundary-tolerance", "0", "--no-flips", "--no-peel"});
    EXPECT_EQ(run.exit_code, 1) << run.out;
    EXPECT_EQ(run.err, "sxk: " + f.out.string() + ":0: cannot write: the mesh has no elements\n");
    EXPECT_EQ(slurp(f.out), "precious\n");
}

TEST(SxkDegeneracies, WithoutCuttingFreeTheRemainingAreListed) {
    DegeneraciesFixture f;
    const fs::path in = f.input("spindle.mesh", spindle_mesh);
    const std::vector<std::string> options{"--boundary-tolerance", "0", "--no-flips", "--no-peel",
                                           "--no-cut-free"};
    const ProcessResult text = f.run(in, options);
    ASSERT_EQ(text.exit_code, 0) << text.err;  // remaining degenerates are reported, not an error
    EXPECT_EQ(text.err, "");
    EXPECT_NE(text.out.find("\nfound 1 degenerate: removed 0, cracks 0 (cut free), remaining 1\n"
                            "  remaining: element "),
              std::string::npos)
        << text.out;
    EXPECT_NE(text.out.find("would move the boundary"), std::string::npos) << text.out;

    std::vector<std::string> with_json = options;
    with_json.push_back("--json");
    const ProcessResult run = f.run(in, with_json);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["options"]["cut_free"], false);
    EXPECT_EQ(json["options"]["peel"], false);
    EXPECT_EQ(json["summary"]["remaining"], 1);
    EXPECT_EQ(json["summary"]["cracks"], 0);
    ASSERT_EQ(json["remaining"].size(), 1u);
    EXPECT_TRUE(json["remaining"][0]["element"].is_number_unsigned());
    EXPECT_NE(json["remaining"][0]["reason"].get<std::string>().find("would move the boundary"),
              std::string::npos)
        << json["remaining"][0]["reason"];
    EXPECT_EQ(json["remaining"][0]["code"], "moves_boundary");
    // the output still holds the spindle, unchanged
    const Mesh result = read_mesh(f.out);
    EXPECT_TRUE(result.validate().ok());
    EXPECT_EQ(result.element_count(), 4u);
    EXPECT_EQ(
        summarize_quality(result).by_class[static_cast<std::size_t>(DegenerateClass::spindle)], 1u);
}

TEST(SxkDegeneracies, CleanMeshIsCopied) {
    DegeneraciesFixture f;
    const fs::path in = f.input("two.mesh", two_tetrahedra_mesh);
    const ProcessResult run = f.run(in);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("found 0 degenerates: removed 0, cracks 0 (cut free), remaining 0\n"),
              std::string::npos)
        << run.out;
    const Mesh result = read_mesh(f.out);
    EXPECT_TRUE(result.validate().ok());
    EXPECT_EQ(result.element_count(), 2u);
    EXPECT_EQ(result.vertex_count(), 5u);
}

// An interface of another version than the plug-in's, and one nobody offers, are refused.
struct OldDegeneracyService {
    static constexpr std::string_view service_id = "sxk.degeneracy";
    static constexpr std::uint32_t service_version = 1;
};
struct CutterService {
    static constexpr std::string_view service_id = "sxk.cutter";
    static constexpr std::uint32_t service_version = 1;
};

TEST(DegeneracyService, AServiceOfAnotherVersionIsRefused) {
    PluginHost host;
    host.load_folder(SXK_PLUGIN_BUILD_DIR);
    EXPECT_EQ(host.service<OldDegeneracyService>().reason(),
              "plug-in degeneracy offers sxk.degeneracy version 5, not version 1");
    EXPECT_EQ(host.service<CutterService>().reason(), "no plug-in offers sxk.cutter");
    EXPECT_EQ(host.service<degeneracy::DegeneracyService>("stats").reason(), "plug-in stats offers sxk.degeneracy");
    EXPECT_EQ(host.service<degeneracy::DegeneracyService>("nothing").reason(), "no plug-in called nothing");
    EXPECT_EQ(host.service<OldDegeneracyService>().code(), RefusalCode::not_found);
    EXPECT_EQ(host.service<CutterService>().code(), RefusalCode::not_found);
}

// A command that edits may edit the application's mesh in place, as one step of its journal.
TEST(DegeneracyService, TheCommandEditsAMeshInMemoryAsOneStep) {
    PluginHost host;
    host.load_folder(SXK_PLUGIN_BUILD_DIR);
    const FoundCommand found = host.find_command(std::vector<std::string>{"degeneracies"});
    ASSERT_NE(found.command, nullptr);
    ASSERT_TRUE(found.command->edits_mesh());
    std::istringstream text(cap_mesh);
    Mesh mesh = read_mesh(text, Format::medit, "cap.mesh");
    const Mesh before = mesh;
    EditJournal journal(mesh);
    std::ostringstream out, err;
    EXPECT_EQ(found.command->run_on_mutable_mesh(mesh, "cap", {}, out, err), 0) << err.str();
    EXPECT_NE(out.str().find("\ncap: 6 tetrahedra, 6 vertices in elements\n"), std::string::npos) << out.str();
    EXPECT_EQ(journal.undo_count(), 1u);
    ASSERT_TRUE(journal.undo().ok());
    EXPECT_EQ(mesh.element_count(), before.element_count());
    EXPECT_TRUE(mesh.validate().ok());
}

// The plug-in's tool: a brush session found through the host, each step one undoable transaction,
// refusals with their reasons.
TEST(DegeneracyService, TheBrushIsAToolOfTheHost) {
    PluginHost host;
    host.load_folder(SXK_PLUGIN_BUILD_DIR);
    const auto factory = host.tool("degeneracies");
    ASSERT_TRUE(factory.ok()) << factory.reason();
    const auto tools = (*factory)->tools();
    ASSERT_EQ(tools.size(), 1u);
    EXPECT_EQ(tools[0].name, "degeneracies");
    std::istringstream text(cap_mesh);
    Mesh mesh = read_mesh(text, Format::medit, "cap.mesh");
    const Mesh before = mesh;

    degeneracy::BrushOptions options;
    const auto missing = host.begin_tool(mesh, options);
    EXPECT_EQ(missing.code(), RefusalCode::bad_argument);
    EXPECT_EQ(missing.reason(), "degeneracies: radius 0 is not in (0, 1e+300]");
    options.radius = 0.2;
    options.removal.aspect_ratio = 1;
    EXPECT_EQ(host.begin_tool(mesh, options).reason(), "remove_degeneracies: aspect_ratio 1 is not in (0, 1)");

    options.removal = {};
    auto brush = host.begin_tool(mesh, options);
    ASSERT_TRUE(brush.ok()) << brush.reason();
    ToolPose far;
    far.position = {5, 5, 5};
    const auto nothing = (*brush)->step(far);
    ASSERT_TRUE(nothing.ok()) << nothing.reason();
    EXPECT_EQ(nothing->actions, std::vector<std::string>{"no element within the brush"});
    EXPECT_EQ(mesh.element_count(), 5u);
    ToolPose at_cap;
    at_cap.position = {0.5, 0.3, 0.001};  // vertex 4 of the file, the cap's apex
    const auto step = (*brush)->step(at_cap);
    ASSERT_TRUE(step.ok()) << step.reason();
    ASSERT_EQ(step->actions.size(), 1u);
    EXPECT_NE(step->actions[0].find("1 degenerate, 1 removed"), std::string::npos) << step->actions[0];
    EXPECT_EQ(mesh.element_count(), 6u);
    EXPECT_FALSE(step->elements.empty());
    ASSERT_TRUE(mesh.validate().ok());
    EXPECT_EQ((*brush)->steps(), 2u);
    ASSERT_TRUE((*brush)->undo_step().ok());
    test::expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

// An application loads degeneracy.so and calls remove_degeneracies through the service.
TEST(DegeneracyService, RemovesTheCapInProcess) {
    PluginHost host;
    host.load_folder(SXK_PLUGIN_BUILD_DIR);
    ASSERT_NE(host.find("degeneracy"), nullptr);
    const auto found = host.service<degeneracy::DegeneracyService>();
    ASSERT_TRUE(found.ok()) << found.reason();
    const degeneracy::DegeneracyService* service = *found;

    std::istringstream text(cap_mesh);
    Mesh mesh = read_mesh(text, Format::medit, "cap.mesh");
    EXPECT_EQ(service->classify(mesh, 0, {}), DegenerateClass::cap);
    EXPECT_EQ(service->classify(mesh, 1, {}), DegenerateClass::none);

    const Outcome<degeneracy::Report> report = service->remove(mesh, {});
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_EQ(report->found, 1u);
    EXPECT_EQ(report->remaining, 0u);
    EXPECT_EQ(report->cut_free, 0u);
    EXPECT_EQ(report->elements_after, mesh.element_count());
    EXPECT_TRUE(mesh.validate().ok());
    EXPECT_EQ(summarize_quality(mesh, {}, Positions::reference).degenerate, 0u);

    // out-of-range options are refused and leave the mesh alone
    const Mesh before = mesh;
    degeneracy::Options bad;
    bad.aspect_ratio = 2;
    const Outcome<degeneracy::Report> refused = service->remove(mesh, bad);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(),
              "remove_degeneracies: aspect_ratio 2 is not in (0, 1)");
    EXPECT_EQ(refused.code(), RefusalCode::bad_argument);
    expect_same_state(mesh, before);
    EXPECT_TRUE(mesh.validate().ok());
}

}  // namespace
}  // namespace sxk::test
