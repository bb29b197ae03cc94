// The surface cutter on the femur (issue 16, "Done when"): the boundary surface of CGAL's femur
// (tools/make-data's femur.off: 3,897 nodes, 7,798 triangles, closed) cut with a line scalpel held
// level across the shaft and swept through it. The blade touches the shaft's side (an exposed
// edge, Fig. 5.12), the cut branches into two incisions around the shaft (Fig. 5.14), and they meet
// behind it and annihilate (Fig. 5.13). Then: a valid mesh after every movement, no pair of
// neighbouring triangles facing against each other that did not before (no flipped triangle), the
// bone in two pieces, every node of the cut within eps_edge of the blade's sweep, and undoing every
// movement gives the surface back byte for byte (its OFF text).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/fixtures.hpp"
#include "real/femur_data.hpp"
#include "surface_cut.hpp"
#include "sxk/components.hpp"
#include "sxk/io.hpp"
#include "sxk/quality.hpp"

namespace sxk::test {
namespace {

using delaunaycut::Blade;
using delaunaycut::SurfaceCutSession;

std::string off_text(const Mesh& mesh, const std::string& name) {
    const std::string path = (std::filesystem::temp_directory_path() / name).string();
    write_mesh(mesh, path);
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    std::filesystem::remove(path);
    return text.str();
}

TEST(DelaunayCutFemur, ALevelBladeThroughTheShaftBranchesAnnihilatesAndSeparatesTheBone) {
    const std::string ele = make_femur();
    if (ele.empty()) GTEST_SKIP() << "tools/make-data femur did not run";
    const std::string off = (std::filesystem::path(ele).parent_path() / "femur.off").string();
    const Mesh surface = read_mesh(off);
    ASSERT_EQ(surface.topological_dimension(), 2);
    ASSERT_EQ(connected_components(surface).count, 1u);
    const std::size_t folds_before = folded_neighbours(surface);
    Mesh mesh = surface;
    auto session = SurfaceCutSession::make(mesh, {});
    ASSERT_TRUE(session.ok()) << session.reason();
    const double h = (*session)->mean_edge();
    // the shaft at z = 0.1 is a tube about 0.13 wide around (-0.07, 0.06); the blade, level at that
    // height and along y, sweeps across it in x in steps of a third of the mean edge
    constexpr double z = 0.1;
    const int steps = 120;
    std::size_t branches = 0, annihilations = 0, entries = 0;
    for (int i = 0; i <= steps; ++i) {
        const double x = -0.25 + 0.3 * i / steps;
        const auto stepped = (*session)->cut({x, -0.15, z}, {x, 0.3, z});
        ASSERT_TRUE(stepped.ok()) << "step " << i << ": " << stepped.reason();
        const auto valid = mesh.validate();
        ASSERT_TRUE(valid.ok()) << "step " << i << ": " << valid.reason();
        const auto& r = (*session)->last_step();
        branches += r.branches, annihilations += r.annihilations, entries += r.entries;
    }
    std::printf("entries %zu, branches %zu, annihilations %zu; %zu -> %zu triangles; h = %g\n", entries, branches,
                annihilations, surface.element_count(), mesh.element_count(), h);
    EXPECT_GE(branches, 1u);
    EXPECT_EQ(annihilations, 1u);
    EXPECT_LE(folded_neighbours(mesh), folds_before);
    EXPECT_EQ(connected_components(mesh).count, 2u);
    // the cut's nodes: the corners of the boundary edges it made, within eps_edge of the plane z
    double farthest = 0;
    std::size_t nodes = 0;
    mesh.for_each_boundary_face([&](FaceId f) {
        const Simplex s = mesh.face_simplex(f);
        if (mesh.face_label(s) != delaunaycut::Options{}.cut_label) return;
        for (const VertexId v : s.vertices()) farthest = std::max(farthest, std::abs(mesh.deformed(v)[2] - z)), ++nodes;
    });
    std::printf("cut nodes %zu, farthest from the sweep %.3f h\n", nodes, farthest / h);
    EXPECT_GT(nodes, 10u);
    EXPECT_LE(farthest, delaunaycut::Options{}.eps_edge * h);
    ASSERT_TRUE((*session)->cancel().ok());
    (*session)->end();
    expect_same_state(mesh, surface);
    EXPECT_EQ(off_text(mesh, "sxk-femur-undone.off"), off_text(surface, "sxk-femur.off"));
}

}  // namespace
}  // namespace sxk::test
