// Cutting surfaces in space with a line scalpel (plugins/delaunaycut, thesis §5.3): the Gaussian
// bell of Fig. 5.19 cut through its boundary and across its top (a branch and an annihilation),
// undo, refusals, and seeded random blade paths on random bells.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/fixtures.hpp"
#include "surface_cut.hpp"
#include "sxk/components.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/generators.hpp"
#include "sxk/plugin_host.hpp"
#include "sxk/quality.hpp"

extern "C" const sxk_plugin_info* sxk_plugin_entry_delaunaycut();

namespace sxk::delaunaycut {
namespace {

Mesh bell(int cells = 14) {
    auto made = make_gaussian_bell({cells, cells}, {1.0, 1.0}, cells / 3.0, cells / 6.0);
    EXPECT_TRUE(made.ok()) << made.reason();
    return std::move(made).value();
}

// The blade's poses of a path, each one movement.
using BladePath = std::vector<Blade>;

// A straight sweep from `from` to `to` in `steps` movements.
BladePath sweep(const Blade& from, const Blade& to, int steps) {
    BladePath path;
    for (int i = 0; i <= steps; ++i) {
        const double s = static_cast<double>(i) / steps;
        path.push_back({{from.handle[0] + s * (to.handle[0] - from.handle[0]),
                         from.handle[1] + s * (to.handle[1] - from.handle[1]),
                         from.handle[2] + s * (to.handle[2] - from.handle[2])},
                        {from.tip[0] + s * (to.tip[0] - from.tip[0]), from.tip[1] + s * (to.tip[1] - from.tip[1]),
                         from.tip[2] + s * (to.tip[2] - from.tip[2])}});
    }
    return path;
}

struct SurfaceCut {
    std::unique_ptr<Mesh> mesh;
    CutStepReport total;
    std::size_t most_incisions = 0;
    bool valid = true;
};

SurfaceCut cut_along(const Mesh& input, const BladePath& path, const Options& options = {}) {
    SurfaceCut cut;
    cut.mesh = std::make_unique<Mesh>(input);
    auto session = SurfaceCutSession::make(*cut.mesh, options);
    EXPECT_TRUE(session.ok()) << session.reason();
    if (!session) return cut;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const auto stepped = (*session)->cut(path[i].handle, path[i].tip);
        EXPECT_TRUE(stepped.ok()) << "sample " << i << ": " << stepped.reason();
        const auto valid = cut.mesh->validate();
        EXPECT_TRUE(valid.ok()) << "sample " << i << ": " << valid.reason();
        EXPECT_EQ(folded_neighbours(*cut.mesh), 0u) << "sample " << i;  // no triangle flipped
        if (!valid) {
            cut.valid = false;
            break;
        }
        const CutStepReport& r = (*session)->last_step();
        cut.total.entries += r.entries, cut.total.fix_ups += r.fix_ups, cut.total.exits += r.exits;
        cut.total.branches += r.branches, cut.total.annihilations += r.annihilations;
        cut.total.retractions += r.retractions, cut.total.flips += r.flips;
        cut.total.nodes_removed += r.nodes_removed, cut.total.incision_splits += r.incision_splits;
        cut.total.faces_dissected += r.faces_dissected, cut.total.moves += r.moves;
        cut.most_incisions = std::max(cut.most_incisions, r.incisions);
    }
    (*session)->end();
    return cut;
}

void print(const SurfaceCut& cut, const Mesh& before) {
    const CutStepReport& t = cut.total;
    std::printf("entries %zu begun %zu exits %zu branches %zu annihilations %zu retractions %zu flips %zu removed %zu "
                "splits %zu dissected %zu moves %zu; triangles %zu -> %zu, components %zu, most incisions %zu\n",
                t.entries, t.fix_ups, t.exits, t.branches, t.annihilations, t.retractions, t.flips, t.nodes_removed,
                t.incision_splits, t.faces_dissected, t.moves, before.element_count(), cut.mesh->element_count(),
                connected_components(*cut.mesh).count, cut.most_incisions);
}

// An upright blade through the bell from one side of its boundary to the other: one entry, one
// exit, the bell in two pieces.
TEST(DelaunayCutSurface, AnUprightBladeCutsTheBellFromBoundaryToBoundary) {
    const Mesh surface = bell();
    const BladePath path = sweep({{-1, 7.3, 10}, {-1, 7.3, -1}}, {{15, 7.6, 10}, {15, 7.6, -1}}, 80);
    const SurfaceCut cut = cut_along(surface, path);
    print(cut, surface);
    EXPECT_EQ(cut.total.entries, 1u);
    EXPECT_EQ(cut.total.exits, 1u);
    EXPECT_EQ(connected_components(*cut.mesh).count, 2u);
}

// A level blade below the bell's top, swept across it: it touches the bell's front (an exposed
// edge), branches into two incisions around the top, which meet again behind it and annihilate:
// the top comes off.
TEST(DelaunayCutSurface, ALevelBladeBranchesAroundTheTopAndTheIncisionsMeetBehindIt) {
    const Mesh surface = bell();
    const BladePath path = sweep({{-1, -2, 2.5}, {-1, 16, 2.6}}, {{15, -2, 2.5}, {15, 16, 2.6}}, 80);
    const SurfaceCut cut = cut_along(surface, path);
    print(cut, surface);
    EXPECT_EQ(cut.total.branches, 1u);
    EXPECT_EQ(cut.total.annihilations, 1u);
    EXPECT_EQ(connected_components(*cut.mesh).count, 2u);
}

// The tip goes into the bell's flank from above and the blade moves on with its tip under the
// surface: one pierce point, a constrained edge from the entry node, opened by the incision split;
// then the blade is pulled out. A slit in the middle of the surface, the bell still in one piece.
TEST(DelaunayCutSurface, ATipEntryCutsASlitInTheMiddleOfTheSurface) {
    const Mesh surface = bell();
    BladePath path = sweep({{4.3, 6.1, 8}, {4.3, 6.1, 3}}, {{4.3, 6.1, 6}, {4.3, 6.1, 1}}, 10);  // down through
    const BladePath along = sweep({{4.3, 6.1, 6}, {4.3, 6.1, 1}}, {{4.3, 10.2, 6}, {4.3, 10.2, 1}}, 40);
    path.insert(path.end(), along.begin() + 1, along.end());
    const BladePath out = sweep({{4.3, 10.2, 6}, {4.3, 10.2, 1}}, {{4.3, 10.2, 12}, {4.3, 10.2, 7}}, 10);
    path.insert(path.end(), out.begin() + 1, out.end());
    const SurfaceCut cut = cut_along(surface, path);
    print(cut, surface);
    EXPECT_EQ(cut.total.entries, 1u);
    EXPECT_EQ(cut.total.fix_ups, 1u);       // the constrained edge
    EXPECT_GE(cut.total.incision_splits, 1u);  // which opened
    EXPECT_EQ(cut.total.retractions, 1u);   // the blade pulled out
    EXPECT_EQ(connected_components(*cut.mesh).count, 1u);
    std::size_t cut_edges = 0;
    cut.mesh->for_each_boundary_face([&](FaceId f) {
        if (cut.mesh->face_label(cut.mesh->face_simplex(f)) == Options{}.cut_label) ++cut_edges;
    });
    EXPECT_GE(cut_edges, 6u);  // both sides of a slit about four cells long
}

// The plug-in's tool is the surface session for a surface in space; a ToolPose is the blade: its
// tip at the position, the handle `length` back along axes[2].
TEST(DelaunayCutSurface, TheHostOffersTheSurfaceCutterForASurface) {
    PluginHost host;
    ASSERT_TRUE(host.add_static(sxk_plugin_entry_delaunaycut(), "linked-in delaunaycut"));
    Mesh mesh = bell();
    Options options;
    options.eps_edge = 0.25;
    auto session = host.begin_tool(mesh, options);
    ASSERT_TRUE(session) << session.reason();
    auto* cutter = dynamic_cast<SurfaceCutSession*>(session->get());
    ASSERT_NE(cutter, nullptr);
    EXPECT_EQ(cutter->options().eps_edge, 0.25);
    ToolPose pose;
    pose.axes[2] = {0, 0, -1};  // the blade points down, its handle 11 above the tip
    pose.length = 11;
    for (const Blade& blade : sweep({{-1, 7.3, 10}, {-1, 7.3, -1}}, {{15, 7.6, 10}, {15, 7.6, -1}}, 80)) {
        pose.position = blade.tip;
        ASSERT_TRUE((*session)->step(pose));
    }
    EXPECT_EQ(cutter->last_step().incisions, 0u);
    EXPECT_EQ(connected_components(mesh).count, 2u);
    EXPECT_TRUE(mesh.validate().ok());
    Options planar_only;
    planar_only.method = Method::subdivision;
    auto subdivision = host.begin_tool(mesh, planar_only);
    ASSERT_FALSE(subdivision);
    EXPECT_EQ(subdivision.code(), RefusalCode::bad_argument);
}

// Undoing every movement gives the input back, bit for bit (positions, connectivity, labels).
TEST(DelaunayCutSurface, UndoingEveryMovementRestoresTheBellBitForBit) {
    const Mesh surface = bell();
    Mesh mesh = surface;
    auto session = SurfaceCutSession::make(mesh, {});
    ASSERT_TRUE(session.ok()) << session.reason();
    const BladePath path = sweep({{-1, -2, 2.5}, {-1, 16, 2.6}}, {{15, -2, 2.5}, {15, 16, 2.6}}, 80);
    for (const Blade& blade : path) ASSERT_TRUE((*session)->cut(blade.handle, blade.tip).ok());
    EXPECT_GT(mesh.element_count(), surface.element_count());
    ASSERT_TRUE((*session)->cancel().ok());
    (*session)->end();
    ASSERT_TRUE(mesh.validate().ok());
    test::expect_same_state(mesh, surface);
}

// The blade and the incisions are a side log of the journal (ToolSession::keep_beside): the
// application's own undo and redo of a movement take them back and forth with the bell.
TEST(DelaunayCutSurface, TheApplicationsUndoAndRedoTakeTheBladeWithTheMesh) {
    const Mesh surface = bell();
    Mesh mesh = surface;
    EditJournal journal(mesh);
    journal.set_history_limit(1000);
    auto session = SurfaceCutSession::make(mesh, {});
    ASSERT_TRUE(session.ok()) << session.reason();
    SurfaceCutSession& cutter = **session;
    const BladePath path = sweep({{-1, -2, 2.5}, {-1, 16, 2.6}}, {{15, -2, 2.5}, {15, 16, 2.6}}, 80);
    std::size_t i = 0;
    for (; i < path.size() && cutter.active_nodes().empty(); ++i)
        ASSERT_TRUE(cutter.cut(path[i].handle, path[i].tip).ok());
    ASSERT_FALSE(cutter.active_nodes().empty()) << "the sweep never entered the bell";
    ASSERT_TRUE(cutter.cut(path[i].handle, path[i].tip).ok());  // one movement with incisions under way
    const Mesh before = mesh;
    const std::vector<VertexId> nodes_before = cutter.active_nodes();
    ASSERT_TRUE(cutter.cut(path[i + 1].handle, path[i + 1].tip).ok());
    const Mesh after = mesh;
    const std::vector<VertexId> nodes_after = cutter.active_nodes();

    ASSERT_TRUE(journal.undo().ok());
    test::expect_same_state(mesh, before);
    EXPECT_EQ(*cutter.blade(), path[i]);
    EXPECT_EQ(cutter.active_nodes(), nodes_before);
    ASSERT_TRUE(journal.redo().ok());
    test::expect_same_state(mesh, after);
    EXPECT_EQ(*cutter.blade(), path[i + 1]);
    EXPECT_EQ(cutter.active_nodes(), nodes_after);

    while (journal.undo_count() > 0) ASSERT_TRUE(journal.undo().ok());
    test::expect_same_state(mesh, surface);
    EXPECT_FALSE(cutter.blade().has_value());
    EXPECT_TRUE(cutter.active_nodes().empty());
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(DelaunayCutSurface, RefusesPlanarMeshesTheSubdivisionMethodAndFlatTriangles) {
    auto square = make_triangle_grid({3, 3});
    ASSERT_TRUE(square.ok());
    auto planar = SurfaceCutSession::make(*square, {});
    ASSERT_FALSE(planar.ok());
    EXPECT_EQ(planar.refusal().code, RefusalCode::wrong_dimension);
    EXPECT_EQ(planar.reason(),
              "delaunaycut: the surface cutter needs a triangle surface in space (triangles, Dimension 3)");
    Mesh surface = bell(4);
    Options subdivision;
    subdivision.method = Method::subdivision;
    auto refused = SurfaceCutSession::make(surface, subdivision);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "delaunaycut: the subdivision method cuts planar meshes only; surfaces are cut by "
                                "the delaunay method");
    Options bad;
    bad.eps_exit = 0;
    EXPECT_EQ(SurfaceCutSession::make(surface, bad).reason(), "delaunaycut: eps_exit 0 is not in (0, 10]");
    Mesh flat(2, 3);
    for (const Point& p : {Point{0, 0, 0}, Point{1, 0, 0}, Point{2, 0, 0}}) flat.add_vertex(p);
    const std::array<Simplex, 1> triangle{Simplex(+1, {0, 1, 2})};
    ASSERT_TRUE(flat.assign_elements(triangle).ok());
    EXPECT_EQ(SurfaceCutSession::make(flat, {}).reason(),
              "delaunaycut: triangle 0 is flat (collinear corners) in the deformed positions");
    // a blade that is not finite: refused, nothing changes
    auto session = SurfaceCutSession::make(surface, {});
    ASSERT_TRUE(session.ok());
    ASSERT_TRUE((*session)->cut({0, 0, 1}, {0, 0, -1}).ok());
    const auto nan = (*session)->cut({0, 0, std::nan("")}, {0, 0, -1});
    ASSERT_FALSE(nan.ok());
    EXPECT_EQ(nan.reason(), "delaunaycut: the blade's position is not finite");
}

// Seeded random blade paths on random bells: every movement leaves a valid mesh with no triangle
// flipped against a neighbour, and undoing them all gives the bell back. 60 paths of 200 movements: 12,000 movements.
TEST(DelaunayCutSurface, RandomBladePathsOnRandomBellsNeverBreakTheMesh) {
    // SXK_SEED=N replays another seed
    const char* replay = std::getenv("SXK_SEED");
    const unsigned seed = replay ? static_cast<unsigned>(std::atol(replay)) : 20261205u;
    std::printf("seed %u\n", seed);
    std::mt19937 random(seed);
    std::size_t movements = 0, entries = 0, branches = 0, annihilations = 0, exits = 0;
    for (int run = 0; run < 60; ++run) {
        SCOPED_TRACE("run " + std::to_string(run) + " of seed " + std::to_string(seed));
        std::uniform_int_distribution<int> cells(4, 16);
        const int n = cells(random);
        std::uniform_real_distribution<double> unit(0, 1);
        const double height = n * (0.1 + 0.5 * unit(random)), width = n * (0.1 + 0.2 * unit(random));
        auto made = make_gaussian_bell({n, n}, {1.0, 1.0}, height, width);
        ASSERT_TRUE(made.ok());
        const Mesh surface = *made;
        Mesh mesh = surface;
        auto session = SurfaceCutSession::make(mesh, {});
        ASSERT_TRUE(session.ok());
        // the blade's centre wanders over the bell, its direction turns slowly
        std::normal_distribution<double> wobble(0, 1);
        Point centre{n * unit(random), n * unit(random), n * 0.3 * unit(random)};
        Point direction{0.3 * wobble(random), 0.3 * wobble(random), 1};
        const double half = n * (0.2 + 0.6 * unit(random));
        const double stride = 0.05 + 0.5 * unit(random);
        for (int step = 0; step < 200; ++step) {
            for (std::size_t k = 0; k < 3; ++k) {
                centre[k] += stride * wobble(random);
                direction[k] += 0.1 * wobble(random);
            }
            const double length = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] +
                                             direction[2] * direction[2]);
            if (!(length > 0)) continue;
            Blade blade;
            for (std::size_t k = 0; k < 3; ++k) {
                blade.handle[k] = centre[k] + half * direction[k] / length;
                blade.tip[k] = centre[k] - half * direction[k] / length;
            }
            const auto stepped = (*session)->cut(blade.handle, blade.tip);
            ASSERT_TRUE(stepped.ok()) << "step " << step << ": " << stepped.reason();
            const auto valid = mesh.validate();
            ASSERT_TRUE(valid.ok()) << "step " << step << ": " << valid.reason();
            ASSERT_EQ(folded_neighbours(mesh), 0u) << "step " << step;
            const CutStepReport& r = (*session)->last_step();
            entries += r.entries, branches += r.branches, annihilations += r.annihilations, exits += r.exits;
            ++movements;
        }
        const auto cancelled = (*session)->cancel();
        ASSERT_TRUE(cancelled.ok()) << cancelled.reason();
        (*session)->end();
        test::expect_same_state(mesh, surface);
        if (HasFailure()) return;
    }
    std::printf("%zu movements: %zu entries, %zu branches, %zu annihilations, %zu exits\n", movements, entries,
                branches, annihilations, exits);
    EXPECT_GE(movements, 10000u);
    EXPECT_GT(entries, 100u);
    EXPECT_GT(branches, 0u);
    EXPECT_GT(exits, 0u);
}

}  // namespace
}  // namespace sxk::delaunaycut
