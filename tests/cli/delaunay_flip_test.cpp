// sxk delaunay-flip IN OUT [--json]: Lawson's flips on a planar triangle mesh.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

//          4 (2, 0.3)
//        /   \                 a flat rhombus cut along its long diagonal 1-3: vertex 4 is
//   1 ---------- 3             inside the circle through 1, 2, 3, so one flip makes 2-4 the
//        \   /                 diagonal
//          2 (2, -0.3)
const char* flat_rhombus_mesh = R"(MeshVersionFormatted 2
Dimension 2
Vertices
4
0 0 0
2 -0.3 0
4 0 0
2 0.3 0
Triangles
2
1 2 3 5
1 3 4 5
End
)";

struct FlipFixture {
    ScratchFolder folder;
    fs::path mesh = folder / "rhombus.mesh";
    fs::path out = folder / "delaunay.mesh";
    FlipFixture() { write_file(mesh, flat_rhombus_mesh); }
};

TEST(SxkDelaunayFlip, FlipsTheLongDiagonal) {
    FlipFixture f;
    const ProcessResult run = sxk({"delaunay-flip", f.mesh.string(), f.out.string()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, f.mesh.string() + " -> " + f.out.string() + ": 1 flip, 2 triangles\n");
    EXPECT_EQ(run.err, "");
    EXPECT_EQ(sxk({"validate", f.out.string()}).exit_code, 0);
    const std::string text = slurp(f.out);
    // the new diagonal 2-4, both triangles keeping their label 5
    EXPECT_NE(text.find("Triangles\n2\n1 2 4 5\n2 3 4 5\n"), std::string::npos) << text;
    // already Delaunay: a second run flips nothing
    const ProcessResult again =
        sxk({"delaunay-flip", f.out.string(), (f.folder / "again.mesh").string(), "--json"});
    ASSERT_EQ(again.exit_code, 0) << again.err;
    const nlohmann::json json = nlohmann::json::parse(again.out);
    EXPECT_EQ(json["input"], f.out.string());
    EXPECT_EQ(json["output"], (f.folder / "again.mesh").string());
    EXPECT_EQ(json["flips"], 0);
    EXPECT_EQ(json["elements"], 2);
}

TEST(SxkDelaunayFlip, Json) {
    FlipFixture f;
    const ProcessResult run = sxk({"delaunay-flip", f.mesh.string(), f.out.string(), "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["flips"], 1);
    EXPECT_EQ(json["elements"], 2);
}

TEST(SxkDelaunayFlip, RefusesTetrahedra) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh", out = folder / "out.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"delaunay-flip", mesh.string(), out.string()});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err, "sxk: delaunay-flip needs a planar triangle mesh; " + mesh.string() +
                           " is a tetrahedral mesh\n");
    EXPECT_EQ(run.out, "");
    EXPECT_FALSE(fs::exists(out));
}

TEST(SxkDelaunayFlip, RefusesSurfacesInSpace) {
    ScratchFolder folder;
    const fs::path mesh = folder / "tri.off", out = folder / "out.off";
    write_file(mesh, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 0 1\n3 0 1 2\n");
    const ProcessResult run = sxk({"delaunay-flip", mesh.string(), out.string()});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err, "sxk: delaunay-flip needs a planar triangle mesh; " + mesh.string() +
                           " is a triangle surface in 3D\n");
    EXPECT_FALSE(fs::exists(out));
}

TEST(SxkDelaunayFlip, MissingOutputAndUnknownFormat) {
    FlipFixture f;
    ProcessResult run = sxk({"delaunay-flip", f.mesh.string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err,
              "sxk: OUT is required\nRun 'sxk delaunay-flip --help' for more information.\n");
    run = sxk({"delaunay-flip", f.mesh.string(), (f.folder / "out.xyz").string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err,
              "sxk: " + (f.folder / "out.xyz").string() +
                  ":0: unknown output format (known: .mesh .msh .node .ele .off .obj .vtu .vtk .stl .ply)\n");
}

}  // namespace
}  // namespace sxk::test
