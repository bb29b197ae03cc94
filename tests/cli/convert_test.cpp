// sxk convert: formats by extension, --gmsh-version, --reorient, refusals.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

// <1,3,2,4>: the positive tetrahedron with two vertices swapped, i.e. inverted.
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

nlohmann::json info(const fs::path& mesh) {
    const ProcessResult run = sxk({"info", mesh.string(), "--json"});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return nlohmann::json::parse(run.out);
}

TEST(SxkConvert, RoundTripsThroughEveryReadableFormat) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const nlohmann::json before = info(mesh);
    for (const char* name : {"two.msh", "two.1.ele", "copy.mesh"}) {
        const fs::path out = folder / name;
        const ProcessResult run = sxk({"convert", mesh.string(), out.string()});
        ASSERT_EQ(run.exit_code, 0) << name << ": " << run.err;
        EXPECT_EQ(run.out, mesh.string() + " -> " + out.string() + ": 5 vertices, 2 tetrahedra\n");
        const nlohmann::json after = info(out);
        for (const char* key : {"vertices", "elements", "boundary_faces", "components"})
            EXPECT_EQ(after[key], before[key]) << name << ' ' << key;
    }
}

TEST(SxkConvert, GmshVersion22) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh", out = folder / "two.msh";
    write_file(mesh, two_tetrahedra_mesh);
    ASSERT_EQ(sxk({"convert", mesh.string(), out.string(), "--gmsh-version", "22"}).exit_code, 0);
    EXPECT_NE(slurp(out).find("2.2"), std::string::npos);
    EXPECT_EQ(info(out)["elements"], 2);
}

TEST(SxkConvert, RefusesOtherGmshVersions) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"convert", mesh.string(), (folder / "x.msh").string(), "--gmsh-version", "30"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err.rfind("sxk: --gmsh-version: ", 0), 0u) << run.err;
    EXPECT_FALSE(fs::exists(folder / "x.msh"));
}

TEST(SxkConvert, UnknownOutputExtensionIsAUsageError) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh", out = folder / "two.xyz";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"convert", mesh.string(), out.string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: " + out.string() +
                           ":0: unknown output format (known: .mesh .msh .node .ele .off .obj .vtu .vtk .stl .ply)\n");
    EXPECT_FALSE(fs::exists(out));
}

TEST(SxkConvert, EncodingChoosesBinaryGmshAndIsRefusedForTextFormats) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh", out = folder / "two.msh";
    write_file(mesh, two_tetrahedra_mesh);
    ASSERT_EQ(sxk({"convert", mesh.string(), out.string(), "--encoding", "binary"}).exit_code, 0);
    EXPECT_EQ(slurp(out).rfind("$MeshFormat\n4.1 1 8\n", 0), 0u);
    EXPECT_EQ(info(out)["elements"], 2);
    const ProcessResult text = sxk({"convert", mesh.string(), (folder / "b.mesh").string(), "--encoding", "binary"});
    EXPECT_EQ(text.exit_code, 2);
    EXPECT_EQ(text.err, "sxk: convert: --encoding binary: medit files are text only (binary: .msh .vtu .vtk .stl .ply)\n");
    EXPECT_FALSE(fs::exists(folder / "b.mesh"));
    const ProcessResult unknown = sxk({"convert", mesh.string(), out.string(), "--encoding", "zip"});
    EXPECT_EQ(unknown.exit_code, 2);
    EXPECT_EQ(unknown.err.rfind("sxk: --encoding: ", 0), 0u) << unknown.err;
}

TEST(SxkConvert, WritesVtuAndSurfaces) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    ASSERT_EQ(sxk({"convert", mesh.string(), (folder / "two.vtu").string()}).exit_code, 0);
    EXPECT_NE(slurp(folder / "two.vtu").find("VTKFile"), std::string::npos);
    // OFF holds triangles: the boundary surface of the tetrahedra
    ASSERT_EQ(sxk({"convert", mesh.string(), (folder / "two.off").string()}).exit_code, 0);
    const nlohmann::json surface = info(folder / "two.off");
    EXPECT_EQ(surface["element_kind"], "triangle");
    EXPECT_EQ(surface["elements"], 6);
    EXPECT_EQ(surface["ambient_dimension"], 3);
}

TEST(SxkConvert, InvertedInputNeedsReorient) {
    ScratchFolder folder;
    const fs::path mesh = folder / "inverted.mesh", out = folder / "fixed.mesh";
    write_file(mesh, inverted_tetrahedron_mesh);
    const ProcessResult refused = sxk({"convert", mesh.string(), out.string()});
    EXPECT_EQ(refused.exit_code, 2);
    EXPECT_EQ(refused.err.rfind("sxk: " + mesh.string() + ":", 0), 0u) << refused.err;

    const ProcessResult reoriented = sxk({"convert", mesh.string(), out.string(), "--reorient"});
    EXPECT_EQ(reoriented.exit_code, 0) << reoriented.err;
    EXPECT_EQ(reoriented.out, mesh.string() + " -> " + out.string() + ": 4 vertices, 1 tetrahedron, 1 reoriented\n");
    EXPECT_EQ(sxk({"validate", out.string()}).exit_code, 0);
}

TEST(SxkConvert, UnwritableOutputIsRefused) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh", out = folder / "no-such-folder" / "two.msh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"convert", mesh.string(), out.string()});
    EXPECT_EQ(run.exit_code, 1);
    // the file is named once, in front
    EXPECT_EQ(run.err, "sxk: " + out.string() + ":0: cannot write: No such file or directory\n");
}

}  // namespace
}  // namespace sxk::test
