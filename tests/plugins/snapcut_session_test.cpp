// The snap cutter's session (plugins/snapcut/snap_cut.hpp): cuts on the thesis' cube, undo,
// refusals, the tool through the host. Every cut ends with validate().
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "body_words.hpp"
#include "core/fixtures.hpp"
#include "simulation.hpp"
#include "snapcut_fixture.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/components.hpp"
#include "sxk/plugin_host.hpp"
#include "sxk/plugins/elasticity.hpp"
#include "sxk/traversal.hpp"

extern "C" const sxk_plugin_info* sxk_plugin_entry_snapcut();
extern "C" const sxk_plugin_info* sxk_plugin_entry_elasticity();

namespace sxk::test {
namespace {

using snapcut::Scalpel;
using snapcut::SnapCutSession;

constexpr int cut_label = snapcut::Options{}.cut_label;

std::size_t boundary_faces_with_label(const Mesh& mesh, int label) {
    std::size_t count = 0;
    mesh.for_each_boundary_face([&](FaceId f) { count += mesh.face_label(mesh.face_simplex(f)) == label; });
    return count;
}

// The blade stands in the plane x = 3.3 from z = 4 to above the cube and crosses it along y in
// 10 steps: the cut should open the faces of the grid plane x = 3 above z = 4.
std::vector<Scalpel> grid_plane_path() { return straight_path({3.3, -1, 0}, {0, 1, 0}, 10, 4, 10, 10); }

TEST(SnapCut, APlaneAlongTheGridOpensTheGridFacesItCrosses) {
    Mesh mesh = make_kuhn_cube(8).value();
    auto session = SnapCutSession::make(mesh, {}, {degeneracy_service()}).value();
    std::size_t dissected = 0, snapped = 0;
    for (const Scalpel& scalpel : grid_plane_path()) {
        ASSERT_TRUE(session->cut(scalpel));
        dissected += session->last_step().faces_dissected;
        snapped += session->last_step().nodes_snapped;
        EXPECT_EQ(session->last_step().nodes_refused, 0u);
    }
    expect_valid(mesh);
    // the faces in x = 3 with z in [4, 8]: 8 x 4 squares of 2 triangles, both sides labelled
    EXPECT_EQ(dissected, 64u);
    EXPECT_EQ(boundary_faces_with_label(mesh, cut_label), 128u);
    // the 9 x 5 grid nodes of that plane from the tip line up snapped onto x = 3.3 ...
    EXPECT_EQ(snapped, 45u);
    // ... and those above the tip line split in two: 9 x 4 new vertices
    EXPECT_EQ(mesh.vertex_count(), 729u + 36u);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Point& p = mesh.reference(v);
        if (std::abs(p[0] - 3.3) < 0.5 && p[2] >= 4) {
            EXPECT_NEAR(p[0], 3.3, 1e-12) << "vertex " << v;
        }
    }
    // the two sides share no face: every face with its corners on the cut above the tip is open
    for (const ElementId t : elements(mesh))
        for (int i = 0; i < 4; ++i) {
            const Simplex face = mesh.face_simplex(mesh.face(t, i));
            bool on_cut = true;
            for (int j = 0; j < 3; ++j) {
                const Point& p = mesh.reference(face.vertex(j));
                on_cut = on_cut && std::abs(p[0] - 3.3) < 1e-9 && p[2] > 4.5;
            }
            if (on_cut) {
                EXPECT_EQ(mesh.mate(mesh.face(t, i)), invalid_id) << "element " << t;
            }
        }
}

// Fig. 3.17: in the thesis, an incision made in several steps could come apart (degeneracy
// removal collapsed the edges whose marks connected one sweep to the next). A cut through the
// whole cube along a tilted plane must separate it in two, however many steps it takes.
struct ThroughCut {
    std::size_t loose = 0, dissected = 0, split = 0;
};

ThroughCut cut_through_the_cube(Mesh& mesh, int steps, const snapcut::Options& options) {
    auto session = SnapCutSession::make(mesh, options, {degeneracy_service()}).value();
    ThroughCut cut;
    for (const Scalpel& scalpel : plane_path(diagonal_point, diagonal_normal, -8, 8, -12, 30, steps)) {
        EXPECT_TRUE(session->cut(scalpel));
        cut.loose += session->last_step().loose_pieces.size();
        cut.dissected += session->last_step().faces_dissected;
        cut.split += session->last_step().edges_split;
    }
    return cut;
}

class SnapCutThrough : public ::testing::TestWithParam<int> {};

TEST_P(SnapCutThrough, ACutThroughTheCubeSeparatesItInAnyNumberOfSteps) {
    Mesh mesh = make_kuhn_cube(8).value();
    const ThroughCut cut = cut_through_the_cube(mesh, GetParam(), {});
    expect_valid(mesh);
    EXPECT_EQ(connected_components(mesh).count, 2u);
    EXPECT_EQ(cut.loose, 1u);
    EXPECT_GE(cut.dissected, 180u);
}

INSTANTIATE_TEST_SUITE_P(Steps, SnapCutThrough, ::testing::Values(1, 4, 16, 64, 256));

// The same cut with every crossing more than 0.2 h from the plane split (Options::split_beyond,
// split_far_crossings.hpp): 114 to 186 edges split, and the cube still comes apart in two
// however many steps (with a split node's edges marked by the exact test alone, its rounding
// left holes from 16 steps on).
class SnapCutThroughSplitting : public ::testing::TestWithParam<int> {};

TEST_P(SnapCutThroughSplitting, ACutThroughTheCubeWithItsCrossingsSplitSeparatesIt) {
    Mesh mesh = make_kuhn_cube(8).value();
    const ThroughCut cut = cut_through_the_cube(mesh, GetParam(), {.split_beyond = 0.2});
    expect_valid(mesh);
    EXPECT_GE(cut.split, 100u);
    EXPECT_EQ(connected_components(mesh).count, 2u);
    EXPECT_EQ(cut.loose, 1u);
}

INSTANTIATE_TEST_SUITE_P(Steps, SnapCutThroughSplitting, ::testing::Values(1, 16, 256));

// One Kuhn cube cut through by the plane x = 1/2: every edge it crosses has both ends 1/2 from
// the plane (0.43 h), beyond split_beyond = 0.3 h. The nine such edges (four along x, four face
// diagonals, the main diagonal) are split at their midpoints, which lie on the plane exactly, and
// the cut runs through them alone: no node moves, and the cube comes apart on x = 1/2.
TEST(SnapCutSplitting, CrossingsFarFromBothEndsGetANodeOnTheSweep) {
    Mesh mesh = make_kuhn_cube(1).value();
    auto session = SnapCutSession::make(mesh, {.split_beyond = 0.3}, {degeneracy_service()}).value();
    std::size_t split = 0, dissected = 0, loose = 0;
    for (const Scalpel& scalpel : straight_path({0.5, -1, 0}, {0, 1, 0}, 3, -1, 2, 1)) {
        ASSERT_TRUE(session->cut(scalpel));
        split += session->last_step().edges_split;
        dissected += session->last_step().faces_dissected;
        loose += session->last_step().loose_pieces.size();
    }
    expect_valid(mesh);
    EXPECT_EQ(split, 9u);
    EXPECT_GT(dissected, 0u);
    EXPECT_EQ(loose, 1u);
    EXPECT_EQ(connected_components(mesh).count, 2u);
    mesh.for_each_boundary_face([&](FaceId f) {
        const Simplex face = mesh.face_simplex(f);
        if (mesh.face_label(face) != cut_label) return;
        for (const VertexId v : face.vertices()) {
            EXPECT_EQ(mesh.reference(v)[0], 0.5) << "vertex " << v;
            EXPECT_EQ(mesh.deformed(v)[0], 0.5) << "vertex " << v;
        }
    });
    // the default (half the mean edge) leaves these edges to the snapping
    Mesh whole = make_kuhn_cube(1).value();
    auto plain = SnapCutSession::make(whole, {}, {degeneracy_service()}).value();
    for (const Scalpel& scalpel : straight_path({0.5, -1, 0}, {0, 1, 0}, 3, -1, 2, 1)) {
        ASSERT_TRUE(plain->cut(scalpel));
        EXPECT_EQ(plain->last_step().edges_split, 0u);
    }
    expect_valid(whole);
}

// The unit cube (mean edge h = 1.17) cut by x = 0.55 with a blade that stops at y = 0.6. Three
// edges run from y = 0 to the corners (1, 1, z) and cross the sweep at y = 0.55, their nearer
// ends 0.45 from the sweep's plane but 0.6 from the swept surface (0.4 ahead of the blade).
// Snapped onto the plane, those corners would lie ahead of where the blade went; split_beyond
// 0.45 (0.53) splits the three edges where crossed instead, and nothing else: the other nearer
// ends are within 0.45 of the sweeps (the crossings over the movement's second sweep triangle
// included, whose nearer ends are farther than that from the first). Measured against the plane
// (the rule before), nothing would be split.
TEST(SnapCutSplitting, ANodeAheadOfTheBladeIsNotSnappedBeyondIt) {
    Mesh mesh = make_kuhn_cube(1).value();
    const double h = sxk::mean_edge_length(mesh);
    auto session = SnapCutSession::make(mesh, {.split_beyond = 0.45}, {degeneracy_service()}).value();
    ASSERT_TRUE(session->cut({{0.55, -1, 2}, {0.55, -1, -1}}));
    ASSERT_TRUE(session->cut({{0.55, 0.6, 2}, {0.55, 0.6, -1}}));
    expect_valid(mesh);
    EXPECT_EQ(session->last_step().edges_split, 3u);
    EXPECT_GT(session->last_step().faces_selected, 0u);
    EXPECT_LE(session->last_step().placement_error, 0.45 * h);
    std::size_t unmoved = 0;
    for (VertexId v = 0; v < 8; ++v) {
        const Point& p = mesh.reference(v);
        if (p[0] == 1 && p[1] == 1) {
            EXPECT_EQ(mesh.deformed(v), p) << "vertex " << v;
            ++unmoved;
        }
    }
    EXPECT_EQ(unmoved, 2u);
}

TEST(SnapCutSplitting, ADistanceOutOfRangeIsRefused) {
    Mesh mesh = make_kuhn_cube(1).value();
    for (const auto& [bad, text] : {std::pair{-1.0, "-1"}, std::pair{std::nan(""), "nan"},
                                    std::pair{static_cast<double>(INFINITY), "inf"}, std::pair{1001.0, "1001"}}) {
        const auto made = SnapCutSession::make(mesh, {.split_beyond = bad});
        ASSERT_FALSE(made.ok());
        EXPECT_EQ(made.code(), RefusalCode::bad_argument);
        EXPECT_EQ(made.reason(), "snapcut: split_beyond " + std::string(text) + " is not in [0, 1000]");
    }
}

TEST(SnapCut, WithoutSnappingTheGridFacesOpenWhereTheyAre) {
    Mesh mesh = make_kuhn_cube(8).value();
    snapcut::Options options;
    options.snap = false;
    auto session = SnapCutSession::make(mesh, options, {degeneracy_service()}).value();
    for (const Scalpel& scalpel : grid_plane_path()) ASSERT_TRUE(session->cut(scalpel));
    expect_valid(mesh);
    EXPECT_EQ(boundary_faces_with_label(mesh, cut_label), 128u);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) EXPECT_EQ(mesh.reference(v), mesh.deformed(v));
}

TEST(SnapCut, UndoingEveryStepRestoresTheMeshExactly) {
    const Mesh original = make_kuhn_cube(8).value();
    Mesh mesh = original;
    auto session = SnapCutSession::make(mesh, {}, {degeneracy_service()}).value();
    for (const Scalpel& scalpel : grid_plane_path()) ASSERT_TRUE(session->cut(scalpel));
    ASSERT_TRUE(session->cancel());
    expect_same_state(mesh, original);
    expect_valid(mesh);
}

TEST(SnapCut, AStepUndoneAndTakenAgainCutsAsBefore) {
    // the session's marks and scalpel go back with the mesh (side logs of its journal)
    Mesh straight = make_kuhn_cube(8).value();
    Mesh again = straight;
    auto one = SnapCutSession::make(straight, {}, {degeneracy_service()}).value();
    auto two = SnapCutSession::make(again, {}, {degeneracy_service()}).value();
    const std::vector<Scalpel> path = grid_plane_path();
    for (std::size_t i = 0; i < path.size(); ++i) {
        ASSERT_TRUE(one->cut(path[i]));
        ASSERT_TRUE(two->cut(path[i]));
        if (i == 4 || i == 5) {
            ASSERT_TRUE(two->undo_step());
            ASSERT_TRUE(two->cut(path[i]));
        }
    }
    expect_same_state(again, straight);
    expect_valid(again);
}

// The application's own journal (issue 48, "one undo"): undoing and redoing a step through it takes
// the marks, the snapped nodes, the sweeps and the scalpel with the mesh, and the cut then goes on
// as if nothing had been undone.
TEST(SnapCut, TheApplicationsUndoAndRedoTakeTheMarksAndTheScalpelWithTheMesh) {
    Mesh straight = make_kuhn_cube(8).value();
    Mesh mesh = straight;
    EditJournal journal(mesh);
    auto one = SnapCutSession::make(straight, {}, {degeneracy_service()}).value();
    auto two = SnapCutSession::make(mesh, {}, {degeneracy_service()}).value();
    const std::vector<Scalpel> path = grid_plane_path();
    ASSERT_GT(path.size(), 6u);
    for (std::size_t i = 0; i < 5; ++i) {
        ASSERT_TRUE(one->cut(path[i]));
        ASSERT_TRUE(two->cut(path[i]));
    }
    const Mesh before = mesh;
    const std::size_t marks_before = two->marks().mark_count(), sweeps_before = two->marks().sweeps().size();
    ASSERT_TRUE(two->cut(path[5]));
    ASSERT_GT(two->last_step().faces_dissected, 0u) << "the step cuts nothing: the test proves nothing";
    const Mesh after = mesh;
    const std::size_t marks_after = two->marks().mark_count(), sweeps_after = two->marks().sweeps().size();
    ASSERT_GT(marks_after, marks_before);

    ASSERT_TRUE(journal.undo().ok());
    expect_same_state(mesh, before);
    EXPECT_EQ(two->marks().mark_count(), marks_before);
    EXPECT_EQ(two->marks().sweeps().size(), sweeps_before);
    EXPECT_EQ(two->scalpel(), std::optional<Scalpel>(path[4]));
    ASSERT_TRUE(journal.redo().ok());
    expect_same_state(mesh, after);
    EXPECT_EQ(two->marks().mark_count(), marks_after);
    EXPECT_EQ(two->marks().sweeps().size(), sweeps_after);
    EXPECT_EQ(two->scalpel(), std::optional<Scalpel>(path[5]));
    ASSERT_TRUE(journal.undo().ok());

    for (std::size_t i = 5; i < path.size(); ++i) {
        ASSERT_TRUE(one->cut(path[i]));
        ASSERT_TRUE(two->cut(path[i]));
    }
    expect_same_state(mesh, straight);
    EXPECT_EQ(two->marks().mark_count(), one->marks().mark_count());
    expect_valid(mesh);
}

TEST(SnapCut, ARefusedStepLeavesTheMeshAndTheSessionAsTheyWere) {
    const Mesh original = make_kuhn_cube(4).value();
    Mesh mesh = original;
    auto session = SnapCutSession::make(mesh, {}, {degeneracy_service()}).value();
    ASSERT_TRUE(session->cut({{1.3, -1, 6}, {1.3, -1, 2}}));
    const auto refused = session->cut({{1.3, 2, 6}, {1.3, 2, std::nan("")}});
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.code(), RefusalCode::bad_argument);
    EXPECT_EQ(refused.reason(), "snapcut: the scalpel's coordinates must be finite");
    expect_same_state(mesh, original);
    EXPECT_EQ(session->steps(), 1u);
    ASSERT_TRUE(session->scalpel());
    EXPECT_EQ(session->scalpel()->tip, (Point{1.3, -1, 2}));
}

TEST(SnapCut, OnlyTetrahedralMeshesInSpaceAreCut) {
    Mesh planar = planar_grid(3);
    const auto refused = SnapCutSession::make(planar, {});
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.code(), RefusalCode::not_applicable);
    EXPECT_EQ(refused.reason(), "snapcut: the snap cutter cuts tetrahedral meshes in space");
    Mesh cube = make_kuhn_cube(2).value();
    snapcut::Options options;
    options.aspect_ratio = 1.5;
    EXPECT_EQ(SnapCutSession::make(cube, options).reason(), "snapcut: aspect_ratio 1.5 is not in (0, 1)");
}

TEST(SnapCut, WithoutTheDegeneracyServiceFlatElementsStayAndTheCutStillWorks) {
    Mesh mesh = make_kuhn_cube(8).value();
    auto session = SnapCutSession::make(mesh, {}).value();
    EXPECT_FALSE(session->has_degeneracy_service());
    for (const Scalpel& scalpel : grid_plane_path()) {
        ASSERT_TRUE(session->cut(scalpel));
        EXPECT_FALSE(session->last_step().degeneracy_removal_ran);
    }
    expect_valid(mesh);
    EXPECT_EQ(boundary_faces_with_label(mesh, cut_label), 128u);
}

TEST(SnapCut, AScalpelThatMissesTheMeshCutsNothing) {
    const Mesh original = make_kuhn_cube(4).value();
    Mesh mesh = original;
    auto session = SnapCutSession::make(mesh, {}, {degeneracy_service()}).value();
    for (const Scalpel& scalpel : straight_path({10, -1, 0}, {0, 1, 0}, 6, 1, 3, 3)) {
        ASSERT_TRUE(session->cut(scalpel));
        EXPECT_EQ(session->last_step().edges_hit, 0u);
    }
    expect_same_state(mesh, original);
}

// The thesis' cube held at y = 0 and pulled up at y = 8, settled, then cut along the diagonal
// plane in `steps` steps with `options`, every step relaxed (no refusal): the mesh stays valid,
// more than 50 faces open, the iterations the steps report are those the simulation ran, and
// undoing every step gives back the deformed mesh of before the cut. The steps' reports.
std::vector<snapcut::CutStepReport> cut_the_deforming_cube(const snapcut::Options& options, int steps) {
    Mesh mesh = make_kuhn_cube(8).value();
    const std::vector<std::string> words{"--fix", "y<0.001", "--force", "y>7.99:0,20000,0", "--E", "1e5"};
    auto simulation = elasticity::simulate(mesh, sxk::cli::body_options(words).value());
    if (!simulation) {
        ADD_FAILURE() << simulation.reason();
        return {};
    }
    const auto settled = (*simulation)->relax(100000);
    EXPECT_TRUE(settled && settled->converged && settled->shown);
    const Mesh loaded = mesh;
    EXPECT_NE(mesh.deformed(728), mesh.reference(728));  // the far corner moved
    auto session = SnapCutSession::make(mesh, options, {degeneracy_service(), simulation->get()}).value();
    std::vector<snapcut::CutStepReport> reports;
    std::size_t dissected = 0, relaxed = 0;
    for (const Scalpel& scalpel : plane_path(diagonal_point, diagonal_normal, -8, 8, -1, 10, steps)) {
        const auto stepped = session->cut(scalpel);
        EXPECT_TRUE(stepped) << stepped.reason();
        const auto& r = reports.emplace_back(session->last_step());
        EXPECT_TRUE(r.relaxed);
        EXPECT_EQ(r.relax_refusal, "");
        dissected += r.faces_dissected;
        relaxed += r.relax_iterations;
    }
    expect_valid(mesh);
    EXPECT_GT(dissected, 50u);
    EXPECT_EQ((*simulation)->total_iterations(), settled->iterations + relaxed);
    EXPECT_TRUE(session->cancel());
    expect_same_state(mesh, loaded);
    return reports;
}

// Issue item 6: with a simulation the session relaxes the whole body after each step, and the next
// sweep meets the new deformed shape.
TEST(SnapCut, ADeformingBodyIsRelaxedAfterEveryStepAndTheCutFollowsIt) {
    snapcut::Options options;
    options.relax_iterations = 50;
    for (const snapcut::CutStepReport& r : cut_the_deforming_cube(options, 12)) {
        if (r.faces_dissected > 0) {  // the cut changed the body
            EXPECT_GT(r.relax_iterations, 0u);
        }
        EXPECT_EQ(r.relax_region_vertices, 0u);  // the whole body
    }
}

// Options::local_vertices: each step relaxes only around what it changed (bounded regions), the
// far field by blocks with far_vertices.
TEST(SnapCut, ALocalRelaxationAfterEachStepStaysAroundWhatTheStepChanged) {
    snapcut::Options options;
    options.relax_iterations = 200;
    options.local_vertices = 120;
    options.far_vertices = 120;
    std::size_t largest_region = 0, far_blocks = 0;
    for (const snapcut::CutStepReport& r : cut_the_deforming_cube(options, 24)) {
        if (r.faces_dissected > 0) {
            EXPECT_GT(r.relax_region_vertices, 0u);  // a region, not the whole body (0)
            EXPECT_GT(r.relax_iterations, 0u);
        }
        largest_region = std::max(largest_region, r.relax_region_vertices);
        far_blocks += r.relax_far_vertices > 0;
    }
    // the region is the step's seeds and their rings up to 120 vertices: well short of the body
    EXPECT_GT(largest_region, 0u);
    EXPECT_LT(largest_region, 729u / 2);
    EXPECT_GT(far_blocks, 0u);
}

TEST(SnapCut, ThePoseOfAToolSessionIsTheScalpel) {
    const Scalpel scalpel{{1, 2, 9}, {1, 2, 3}};
    const ToolPose pose = snapcut::to_pose(scalpel);
    EXPECT_EQ(pose.position, scalpel.tip);
    EXPECT_EQ(pose.length, 6.0);
    EXPECT_EQ(pose.axes[2], (Point{0, 0, -1}));
    EXPECT_EQ(snapcut::scalpel_of(pose).handle, scalpel.handle);
}

TEST(SnapCut, TheHostOffersTheToolAndItFindsTheDegeneracyRemoval) {
    PluginHost host;
    ASSERT_TRUE(host.add_static(sxk_plugin_entry_snapcut(), "linked-in snapcut"));
    ASSERT_TRUE(host.add_static(sxk_plugin_entry_degeneracy(), "linked-in degeneracy"));  // after: looked up late
    // the tool by name, whichever plug-in offers it (the degeneracy plug-in offers a tool too)
    auto factory = host.tool("snapcut");
    ASSERT_TRUE(factory) << factory.reason();
    ASSERT_EQ((*factory)->tools().size(), 1u);
    EXPECT_EQ((*factory)->tools()[0].name, "snapcut");
    EXPECT_EQ((*factory)->tools()[0].options_version, snapcut::Options::options_version);
    Mesh mesh = make_kuhn_cube(8).value();
    snapcut::Options options;
    options.aspect_ratio = 0.02;
    auto session = host.begin_tool(mesh, options);
    ASSERT_TRUE(session) << session.reason();
    auto* cutter = dynamic_cast<SnapCutSession*>(session->get());
    ASSERT_NE(cutter, nullptr);
    EXPECT_TRUE(cutter->has_degeneracy_service());
    EXPECT_EQ(cutter->options().aspect_ratio, 0.02);
    for (const Scalpel& scalpel : grid_plane_path()) ASSERT_TRUE((*session)->step(snapcut::to_pose(scalpel)));
    expect_valid(mesh);
    EXPECT_EQ(boundary_faces_with_label(mesh, cut_label), 128u);

    snapcut::Options bad;
    bad.aspect_ratio = 2;
    const auto refused = host.begin_tool(mesh, bad);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.code(), RefusalCode::bad_argument);
    EXPECT_EQ(refused.reason(), "snapcut: aspect_ratio 2 is not in (0, 1)");
    bad = {};
    bad.far_vertices = 10;
    EXPECT_EQ(host.begin_tool(mesh, bad).reason(),
              "snapcut: far_vertices needs local_vertices > 0 (it relaxes the far field that a local relaxation "
              "leaves)");
    EXPECT_EQ(host.tool("scalpel").reason(), "no tool called scalpel; the plug-ins offer: degeneracies, snapcut");
    // options of another layout than the plug-in reads, and another tool's name
    EXPECT_EQ((*factory)->begin("snapcut", 99, &options, mesh, {}).reason(),
              "snapcut: options of version 99, the plug-in reads version 1 (rebuild against its installed header)");
    EXPECT_EQ((*factory)->begin("needle", 1, &options, mesh, {}).code(), RefusalCode::not_found);
    expect_valid(mesh);
}

// The application's simulation given to the tool (ToolContext): the session relaxes the body after
// every step, and undoing the steps takes the mesh and the session's state back together.
TEST(SnapCut, TheToolCutsTheApplicationsSimulationAndUndoesIt) {
    PluginHost host;
    ASSERT_TRUE(host.add_static(sxk_plugin_entry_elasticity(), "linked-in elasticity"));
    ASSERT_TRUE(host.add_static(sxk_plugin_entry_snapcut(), "linked-in snapcut"));
    ASSERT_TRUE(host.add_static(sxk_plugin_entry_degeneracy(), "linked-in degeneracy"));
    Mesh mesh = make_kuhn_cube(8).value();
    auto elasticity = host.service<elasticity::ElasticityService>();
    ASSERT_TRUE(elasticity) << elasticity.reason();
    elasticity::Options body;
    body.fix = {"y<0.001"};
    body.force = {{"y>7.99", {0, 20000, 0}}};
    body.young = 1e5;
    auto simulation = (*elasticity)->simulate(mesh, body);
    ASSERT_TRUE(simulation) << simulation.reason();
    ASSERT_TRUE((*simulation)->relax(100000));
    const Mesh loaded = mesh;
    snapcut::Options cut;
    cut.relax_iterations = 50;
    auto session = host.begin_tool(mesh, cut, {.simulation = simulation->get()});
    ASSERT_TRUE(session) << session.reason();
    auto* cutter = dynamic_cast<SnapCutSession*>(session->get());
    ASSERT_NE(cutter, nullptr);
    std::size_t relaxed = 0;
    for (const Scalpel& scalpel : grid_plane_path()) {
        ASSERT_TRUE((*session)->step(snapcut::to_pose(scalpel)));
        relaxed += cutter->last_step().relaxed;
    }
    EXPECT_EQ(relaxed, grid_plane_path().size());  // every step, the first pose's too
    expect_valid(mesh);
    EXPECT_GT(boundary_faces_with_label(mesh, cut_label), 0u);
    ASSERT_TRUE((*session)->cancel()) << (*session)->cancel().reason();
    expect_valid(mesh);
    test::expect_same_state(mesh, loaded);

    elasticity::Options unheld;
    unheld.force = {{"y>7.99", {0, 1, 0}}};
    EXPECT_EQ((*elasticity)->simulate(mesh, unheld).reason(),
              "deform: nothing holds the body (no --fix or --displace), so it can move freely and the problem is "
              "singular; fix at least three non-collinear vertices of every connected part");
    elasticity::Options soft = body;
    soft.poisson = 0.5;
    EXPECT_EQ((*elasticity)->simulate(mesh, soft).reason(), "elasticity: poisson 0.5 is not in (-1, 0.5)");
}

}  // namespace
}  // namespace sxk::test
