// The conventions every sxk command keeps (docs/cli.md "Conventions"): `sxk help COMMAND`, "did
// you mean" for a mistyped command or option, `-` for standard input and output with --format,
// the known formats named on an unknown extension, --json on the commands that report, and what
// `convert` reports being what it wrote.
#include <gtest/gtest.h>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

const std::string known = ".mesh .msh .node .ele .off .obj .vtu .vtk .stl .ply";

// A Kuhn cube of 2 x 2 x 2 cells: 27 vertices, 48 tetrahedra, 48 boundary triangles on 26 vertices.
fs::path cube(const ScratchFolder& folder) {
    const fs::path mesh = folder / "cube.mesh";
    const ProcessResult made = sxk({"generate", mesh.string(), "--cells", "2"});
    EXPECT_EQ(made.exit_code, 0) << made.err;
    return mesh;
}

TEST(SxkConventions, HelpCommandPrintsTheCommandsHelp) {
    const ProcessResult help = sxk({"help", "info"}), flag = sxk({"info", "--help"});
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_EQ(help.out, flag.out);
    EXPECT_NE(help.out.find("Usage: sxk info [OPTIONS] MESH"), std::string::npos) << help.out;
    EXPECT_EQ(help.err, "");
    const ProcessResult all = sxk({"help"});
    EXPECT_EQ(all.exit_code, 0);
    EXPECT_EQ(all.out, sxk({"--help"}).out);
    EXPECT_NE(all.out.find("Run 'sxk help COMMAND' (or 'sxk COMMAND --help') for a command's options."),
              std::string::npos);
    if (SXK_HAVE_STATS) {
        EXPECT_EQ(sxk({"help", "stats"}).out, sxk({"stats", "--help"}).out);
    }
}

TEST(SxkConventions, AMistypedCommandGetsWhatWasMeant) {
    const std::string docs = std::string(SXK_SOURCE_DIR) + "/docs";
    const std::string build_folder = std::string(SXK_BINARY_DIR) + "/lib/simplexkit/plugins";
    const ProcessResult run = sxk({"infoo", "x.mesh"}, {{"SXK_PLUGIN_PATH", docs}});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: unknown command 'infoo' (did you mean info? see sxk --help and sxk plugins; plug-ins "
                       "searched in " + build_folder + ", " + docs + ")\n");
    // nothing near: no guess
    EXPECT_EQ(sxk({"xyzzy"}, {{"SXK_PLUGIN_PATH", docs}}).err.find("did you mean"), std::string::npos);
}

TEST(SxkConventions, AMistypedOptionGetsWhatWasMeant) {
    const ProcessResult run = sxk({"info", "x.mesh", "--jsn"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: The following argument was not expected: --jsn (did you mean --json?)\n"
                       "Run 'sxk info --help' for more information.\n");
    // a plug-in's command, through the command-line library
    const ProcessResult plugin = sxk({"degeneracies", "in.mesh", "out.mesh", "--aspct", "0.1"});
    EXPECT_EQ(plugin.exit_code, 2);
    EXPECT_EQ(plugin.err, "sxk: degeneracies: The following arguments were not expected: 0.1 --aspct (did you mean "
                          "--aspect?)\nRun 'sxk degeneracies --help' for more information.\n");
}

TEST(SxkConventions, AnUnknownExtensionNamesTheKnownFormats) {
    const ProcessResult in = sxk({"info", "mesh.xyz"});
    EXPECT_EQ(in.exit_code, 2);
    EXPECT_EQ(in.err, "sxk: mesh.xyz:0: unknown mesh file extension '.xyz' (known: " + known + ")\n");
    ScratchFolder folder;
    const ProcessResult out = sxk({"convert", cube(folder).string(), (folder / "out.xyz").string()});
    EXPECT_EQ(out.exit_code, 2);
    EXPECT_EQ(out.err, "sxk: " + (folder / "out.xyz").string() + ":0: unknown output format (known: " + known + ")\n");
}

TEST(SxkConventions, ConvertReportsWhatItWrote) {
    ScratchFolder folder;
    const fs::path mesh = cube(folder), off = folder / "cube.off", vtu = folder / "cube.vtu";
    const ProcessResult surface = sxk({"convert", mesh.string(), off.string()});
    EXPECT_EQ(surface.exit_code, 0) << surface.err;
    EXPECT_EQ(surface.out, mesh.string() + " -> " + off.string() +
                               ": 26 vertices, 48 triangles (the boundary of 48 tetrahedra)\n");
    const ProcessResult volume = sxk({"convert", mesh.string(), vtu.string()});
    EXPECT_EQ(volume.out, mesh.string() + " -> " + vtu.string() + ": 27 vertices, 48 tetrahedra\n");
    // generate too: a cube to STL on standard output is its boundary, said on standard error
    const ProcessResult stl = sxk({"generate", "-", "--format", "stl", "--cells", "1"});
    EXPECT_EQ(stl.exit_code, 0) << stl.err;
    EXPECT_EQ(stl.err, "-: 8 vertices, 12 triangles (the boundary of 6 tetrahedra)\n");
    EXPECT_EQ(stl.out.size(), 84u + 12u * 50u);  // binary STL: header, count, 50 bytes a triangle
    const ProcessResult json = sxk({"convert", mesh.string(), off.string(), "--json"});
    EXPECT_EQ(json.exit_code, 0) << json.err;
    EXPECT_EQ(json.out, "{\n  \"input\": \"" + mesh.string() + "\",\n  \"output\": \"" + off.string() +
                            "\",\n  \"format\": \"off\",\n  \"vertices\": 27,\n  \"elements\": 48,\n"
                            "  \"element_kind\": \"tetrahedron\",\n  \"written\": {\n    \"vertices\": 26,\n"
                            "    \"elements\": 48,\n    \"element_kind\": \"triangle\",\n"
                            "    \"boundary_surface\": true\n  }\n}\n");
}

TEST(SxkConventions, DissectReportsAsJson) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh", faces = folder / "faces.txt", out = folder / "cut.mesh";
    write_file(mesh, two_tetrahedra_mesh);  // <0,1,2,3> and <1,2,3,4>, glued along 1-2-3
    write_file(faces, "1 2 3\n");
    const ProcessResult run = sxk({"dissect", mesh.string(), out.string(), "--faces", faces.string(), "--json"});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, "{\n  \"input\": \"" + mesh.string() + "\",\n  \"output\": \"" + out.string() +
                           "\",\n  \"faces\": \"" + faces.string() +
                           "\",\n  \"cut_faces\": 1,\n  \"new_vertices\": 3,\n  \"boundary_faces_on_cut\": 2,\n"
                           "  \"components\": 2,\n  \"vertices\": 8,\n  \"elements\": 2\n}\n");
}

TEST(SxkConventions, StandardInputAndOutputWithFormat) {
    ScratchFolder folder;
    const fs::path mesh = cube(folder), medit = folder / "piped.mesh";
    // a mesh to standard output: the file's bytes exactly; the report on standard error
    const ProcessResult out = sxk({"convert", mesh.string(), "-", "--format", "medit"});
    EXPECT_EQ(out.exit_code, 0) << out.err;
    EXPECT_EQ(out.err, mesh.string() + " -> -: 27 vertices, 48 tetrahedra\n");
    ASSERT_EQ(sxk({"convert", mesh.string(), medit.string()}).exit_code, 0);
    EXPECT_EQ(out.out, slurp(medit));
    // and from standard input
    const ProcessResult in = sxk({"info", "-", "--format", "mesh"}, {}, medit);
    EXPECT_EQ(in.exit_code, 0) << in.err;
    EXPECT_EQ(in.out.rfind("file: -\nvertices: 27\nelements: 48 tetrahedra\n", 0), 0u) << in.out;
    // without --format, or a format no stream carries
    const ProcessResult bare = sxk({"info", "-"}, {}, medit);
    EXPECT_EQ(bare.exit_code, 2);
    EXPECT_EQ(bare.err, "sxk: -:0: standard input needs --format (medit, gmsh, off, obj, vtu, vtk, stl, ply)\n");
    const ProcessResult tetgen = sxk({"convert", mesh.string(), "-", "--format", "tetgen"});
    EXPECT_EQ(tetgen.exit_code, 2);
    EXPECT_EQ(tetgen.err, "sxk: -:0: --format tetgen: not a format standard output can carry (medit, gmsh, off, obj, "
                          "vtu, vtk, stl, ply)\n");
    EXPECT_EQ(tetgen.out, "");
}

}  // namespace
}  // namespace sxk::test
