// The snap cutter on the femur (issue 15, "Done when"): the femur of CGAL's data set
// tetrahedralised by TetGen -pq1.4 (tools/make-data: 47,733 nodes, 212,936 tetrahedra), deformed
// by a load (the elasticity plug-in's simulation: the lower end held, the upper end pushed
// sideways by 4 N, E = 1e6), cut through the shaft by the 20-sample curved path of
// tests/data/paths/femur-shaft.path with the simulation relaxed after every step (the whole body,
// and again only around what each step changed: Options::local_vertices). Then: a valid
// mesh with no element inverted or flat in either configuration; no degenerate element on the cut
// (TetGen's own boundary needles, about 30, are not the cut's); the bone in two pieces; the
// corners of the cut's faces within half a mean edge length h of the scalpel's sweep
// (CutStepReport::placement_error, incision_error); and undoing every step gives the deformed
// femur of before the cut back exactly. The same cut on the static femur separates it too, within
// half an edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "body_words.hpp"
#include "core/fixtures.hpp"
#include "degeneracy_plugin.hpp"
#include "plugins/snapcut_fixture.hpp"
#include "real/femur_data.hpp"
#include "simulation.hpp"
#include "snap_cut.hpp"
#include "snap_to_plane.hpp"
#include "sxk/components.hpp"
#include "sxk/io.hpp"
#include "sxk/locate.hpp"
#include "sxk/plugin_host.hpp"
#include "sxk/quality.hpp"
#include "sxk/tool_path.hpp"
#include "sxk/traversal.hpp"

namespace sxk::test {
namespace {

using snapcut::Scalpel;

constexpr int cut_label = snapcut::Options{}.cut_label;

double distance(const Point& a, const Point& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

std::set<Simplex> cut_faces(const Mesh& mesh) {
    std::set<Simplex> faces;
    mesh.for_each_boundary_face([&](FaceId f) {
        const Simplex s = mesh.face_simplex(f);
        if (mesh.face_label(s) == cut_label) faces.insert(s);
    });
    return faces;
}

// Faces a sweep selected that are still interior: holes in the incision (a selected face opens
// once the faces around its corners close up; at the incision's rim some never do).
std::size_t selected_faces_left_closed(const Mesh& mesh) {
    std::size_t closed = 0;
    for (const auto& [face, label] : mesh.face_labels()) {
        if (label != cut_label || mesh.find_boundary_face_unoriented(face) != invalid_id) continue;
        const VertexId v = face.vertex(0);
        if (v >= mesh.vertex_count() || mesh.vertex_element(v) == invalid_id) continue;
        for (const ElementId t : star(mesh, v))
            if (mesh.simplex(t).contains(face.vertex(1)) && mesh.simplex(t).contains(face.vertex(2))) {
                ++closed;
                break;
            }
    }
    return closed;
}

bool degenerate(const Mesh& mesh, ElementId t) {
    return aspect_ratio(element_points(mesh, t, Positions::reference)) < 0.01;
}

// The cut with the simulation relaxed after each step: the whole body `relax_iterations` CG
// iterations (local_vertices 0), or only around what the step changed (Options::local_vertices).
void cut_the_deformed_femur(std::size_t relax_iterations, std::size_t local_vertices) {
    const std::string femur = make_femur();
    ASSERT_FALSE(femur.empty()) << "tools/make-data femur failed";
    Mesh mesh = read_mesh(femur);
    const double h = sxk::mean_edge_length(mesh);
    std::size_t degenerate_before = 0;
    for (const ElementId t : elements(mesh)) degenerate_before += degenerate(mesh, t);

    PluginHost host;
    ASSERT_TRUE(host.add_static(sxk_plugin_entry_degeneracy(), "linked-in degeneracy"));
    const std::vector<std::string> loads{"--fix", "z<-0.45", "--force", "z>0.45:4,0,0", "--E", "1e6", "--nu", "0.3",
                                         "--tol", "1e-3"};
    auto simulation = elasticity::simulate(mesh, sxk::cli::body_options(loads).value());
    ASSERT_TRUE(simulation) << simulation.reason();
    const auto settled = (*simulation)->relax(500);  // deformed by the load (not necessarily at rest)
    ASSERT_TRUE(settled) << settled.reason();
    ASSERT_TRUE(settled->shown);
    double moved = 0;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) moved = std::max(moved, distance(mesh.deformed(v), mesh.reference(v)));
    std::printf("[ femur    ] deformed: the largest displacement %.3g h after %zu CG iterations\n", moved / h,
                settled->iterations);
    EXPECT_GT(moved, h);
    const Mesh loaded = mesh;

    snapcut::Options options;
    options.relax_iterations = relax_iterations;
    options.local_vertices = local_vertices;
    auto session = snapcut::SnapCutSession::make(
                       mesh, options, {host.service<degeneracy::DegeneracyService>().value(), simulation->get()})
                       .value();
    const std::array<int, 1> columns{6};
    const ToolPath path = read_tool_path(SXK_TEST_DATA_DIR "/paths/femur-shaft.path", columns);
    ASSERT_EQ(path.samples.size(), 20u);
    double placed = 0, placed_local = 0, farthest = 0, farthest_local = 0, cutting = 0, relaxing = 0;
    std::size_t loose = 0;
    for (std::size_t i = 0; i < path.samples.size(); ++i) {
        const auto& v = path.samples[i].values;
        const Scalpel scalpel{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
        const auto stepped = session->cut(scalpel);
        ASSERT_TRUE(stepped) << "step " << i << ": " << stepped.reason();
        EXPECT_EQ(session->last_step().relax_refusal, "") << "step " << i;
        if (local_vertices > 0) {
            EXPECT_LE(session->last_step().relax_region_vertices, local_vertices) << "step " << i;
        }
        loose += session->last_step().loose_pieces.size();
        // the corners of the faces this step selected, right after the snapping, and of those it
        // opened, right after the dissection (before the relaxation moves them)
        placed = std::max(placed, session->last_step().placement_error);
        placed_local = std::max(placed_local, session->last_step().placement_error_local);
        farthest = std::max(farthest, session->last_step().incision_error);
        farthest_local = std::max(farthest_local, session->last_step().incision_error_local);
        cutting += session->last_step().seconds - session->last_step().seconds_relax;
        relaxing += session->last_step().seconds_relax;
    }
    const std::set<Simplex> cut = cut_faces(mesh);
    std::printf("[ femur    ] %zu cut faces, %zu selected faces left closed; farthest corner from the sweep as placed "
                "%.3g h (%.3g of its own mean edge), as opened %.3g h (%.3g); %zu loose pieces; %.2f s cutting, %.2f s "
                "relaxing\n",
                cut.size(), selected_faces_left_closed(mesh), placed / h, placed_local, farthest / h, farthest_local,
                loose, cutting, relaxing);
    const auto valid = mesh.validate({.orientation = true, .flat_is_invalid = true});
    ASSERT_TRUE(valid) << valid.reason();
    EXPECT_GT(cut.size(), 300u);
    // The issue asks for half an edge length h: 0.425 h as placed and as opened (docs/snapcut.md
    // "The femur"; 1.44 h before the crossed edges were split by their distance from the swept
    // surface rather than from the sweep's plane).
    EXPECT_LE(placed, 0.5 * h);
    EXPECT_LE(farthest, 0.5 * h);
    // the bone in two: one piece came loose, and the simulation held it
    EXPECT_EQ(connected_components(mesh).count, 2u);
    EXPECT_EQ(loose, 1u);
    // no degenerate element touches the cut; the femur's own are left alone
    std::set<VertexId> on_cut;
    for (const Simplex& face : cut) on_cut.insert(face.vertices().begin(), face.vertices().end());
    std::size_t degenerate_after = 0;
    for (const ElementId t : elements(mesh)) {
        if (!degenerate(mesh, t)) continue;
        ++degenerate_after;
        for (const VertexId c : mesh.simplex(t).vertices())
            EXPECT_FALSE(on_cut.contains(c)) << "degenerate element " << t << " on the cut";
    }
    EXPECT_LE(degenerate_after, degenerate_before);

    ASSERT_TRUE(session->cancel());
    expect_same_state(mesh, loaded);
}

TEST(SnapCutFemur, ACurvedCutThroughTheShaftOfADeformedFemur) { cut_the_deformed_femur(20, 0); }

// The same with each step's relaxation around what it changed, 300 vertices (a step's region is
// the seeds, a few hundred corners at most here, then rings up to 300): the same invariants.
TEST(SnapCutFemur, TheSameCutRelaxedOnlyAroundEachStep) { cut_the_deformed_femur(200, 300); }

// The recorded femur path with each sample moved by `moved`, each movement in `steps` steps (the
// handle and the tip interpolated linearly; the samples themselves kept exactly).
template <class Move>
std::vector<Scalpel> femur_path(int steps, Move moved) {
    const std::array<int, 1> columns{6};
    const ToolPath recorded = read_tool_path(SXK_TEST_DATA_DIR "/paths/femur-shaft.path", columns);
    std::vector<Scalpel> path;
    for (std::size_t i = 0; i < recorded.samples.size(); ++i) {
        const auto& v = recorded.samples[i].values;
        const Scalpel sample{moved(v[0], v[1], v[2]), moved(v[3], v[4], v[5])};
        if (i > 0) {
            const Scalpel previous = path.back();
            for (int j = 1; j < steps; ++j) path.push_back(snapcut::between(previous, sample, double(j) / steps));
        }
        path.push_back(sample);
    }
    return path;
}

// The distance from p to the nearest of `sweeps`, every one measured (not the session's tree: the
// tests check what the session reports against it).
double distance_to_sweeps(const Point& p, std::span<const snapcut::Sweep> sweeps) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const snapcut::Sweep& sweep : sweeps) nearest = std::min(nearest, snapcut::distance_to_sweep(sweep, p));
    return nearest;
}

// The farthest corner of the cut faces of `mesh` from the nearest of `sweeps`: a corner the steps
// did not measure where it ended up (moved by a later step's collapse) shows here, beyond what
// the steps reported (CutStepReport::incision_error).
double farthest_cut_corner(const Mesh& mesh, std::span<const snapcut::Sweep> sweeps) {
    std::set<VertexId> corners;
    for (const Simplex& face : cut_faces(mesh)) corners.insert(face.vertices().begin(), face.vertices().end());
    double farthest = 0;
    for (const VertexId v : corners) farthest = std::max(farthest, distance_to_sweeps(mesh.deformed(v), sweeps));
    return farthest;
}

// Where a cut left the bone joined: a breadth-first search through the faces from the element
// lowest along the bone (z) to the highest, and of the faces on its way the one nearest the
// sweeps (its farthest corner), with each corner's distance, whether it was snapped and which of
// the face's edges carry a mark. Empty when the search does not get through. What a failing
// through cut prints: each kind of hole the cuts at 1 kHz left was found from this.
std::string where_the_bridge_is(const Mesh& mesh, const snapcut::CutMarks& marks) {
    const auto height = [&](ElementId t) {
        double z = 0;
        for (const VertexId v : mesh.simplex(t).vertices()) z += mesh.deformed(v)[2];
        return z;
    };
    ElementId low = invalid_id, high = invalid_id;
    for (const ElementId t : elements(mesh)) {
        if (low == invalid_id || height(t) < height(low)) low = t;
        if (high == invalid_id || height(t) > height(high)) high = t;
    }
    std::map<ElementId, ElementId> came_from{{low, low}};
    std::vector<ElementId> queue{low};
    for (std::size_t next = 0; next < queue.size() && !came_from.contains(high); ++next)
        for (int i = 0; i < 4; ++i) {
            const FaceId mate = mesh.mate(mesh.face(queue[next], i));
            if (mate == invalid_id) continue;
            const ElementId across = mesh.face_element(mate);
            if (came_from.emplace(across, queue[next]).second) queue.push_back(across);
        }
    if (!came_from.contains(high)) return "";
    const std::span<const snapcut::Sweep> sweeps = marks.sweeps();
    std::optional<Simplex> nearest;
    double nearest_distance = std::numeric_limits<double>::infinity();
    for (ElementId t = high; t != low; t = came_from.at(t)) {
        std::vector<VertexId> shared;
        const Simplex a = mesh.simplex(t), b = mesh.simplex(came_from.at(t));
        for (const VertexId v : a.vertices())
            if (b.contains(v)) shared.push_back(v);
        double farthest = 0;
        for (const VertexId v : shared) farthest = std::max(farthest, distance_to_sweeps(mesh.deformed(v), sweeps));
        if (farthest < nearest_distance) nearest_distance = farthest, nearest = Simplex(+1, shared);
    }
    if (!nearest) return "";
    std::string report = "the bone is joined across face";
    for (const VertexId v : nearest->vertices()) {
        report += " " + std::to_string(v) + " (" + std::to_string(distance_to_sweeps(mesh.deformed(v), sweeps));
        report += marks.snapped(v) ? ", snapped)" : ")";
    }
    report += "; marked edges:";
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (const auto mark = marks.mark(nearest->vertex(i), nearest->vertex(j)))
                report += " " + std::to_string(nearest->vertex(i)) + "-" + std::to_string(nearest->vertex(j)) +
                          " (at " + std::to_string(mark->node) + ", sweep " + std::to_string(mark->sweep) + ")";
    return report;
}

// The recorded path through the static femur, each movement in `steps` steps: what the cut did.
struct StaticCut {
    double h = 0, farthest = 0;  // the mean edge length; the farthest corner of the cut's faces
    double incision = 0;         // the farthest the steps reported (CutStepReport::incision_error)
    double left = 0;             // the farthest corner of the cut faces of the result
    std::size_t steps = 0, split = 0, dissected = 0, loose = 0, pieces = 0;
    std::string bridge;          // where_the_bridge_is, when the bone stayed in one piece
};

// The recorded path with each sample moved by `moved`.
template <class Move>
StaticCut cut_the_static_femur(int steps, Move moved) {
    const std::string femur = make_femur();
    EXPECT_FALSE(femur.empty()) << "tools/make-data femur failed";
    StaticCut cut;
    if (femur.empty()) return cut;
    Mesh mesh = read_mesh(femur);
    cut.h = sxk::mean_edge_length(mesh);
    PluginHost host;
    EXPECT_TRUE(host.add_static(sxk_plugin_entry_degeneracy(), "linked-in degeneracy"));
    auto session =
        snapcut::SnapCutSession::make(mesh, {}, {host.service<degeneracy::DegeneracyService>().value()}).value();
    const std::vector<Scalpel> path = femur_path(steps, moved);
    cut.steps = path.size();
    for (std::size_t i = 0; i < path.size(); ++i) {
        EXPECT_TRUE(session->cut(path[i])) << "step " << i;
        const auto& r = session->last_step();
        cut.farthest = std::max({cut.farthest, r.placement_error, r.incision_error});
        cut.incision = std::max(cut.incision, r.incision_error);
        cut.loose += r.loose_pieces.size();
        cut.split += r.edges_split;
        cut.dissected += r.faces_dissected;
    }
    expect_valid(mesh);
    cut.pieces = connected_components(mesh).count;
    cut.left = farthest_cut_corner(mesh, session->marks().sweeps());
    if (cut.pieces == 1) cut.bridge = where_the_bridge_is(mesh, session->marks());
    return cut;
}

StaticCut cut_the_static_femur(int steps) {
    return cut_the_static_femur(steps, [](double x, double y, double z) { return Point{x, y, z}; });
}

// The recorded path turned by `turn` (radians) about the shaft's centre line (x, y) = (-0.066,
// 0.065) (tests/data/paths/femur-shaft.path), raised by `raise` and tilted by `tilt`, each
// movement in `steps` steps.
struct ShaftCut {
    double turn = 0, raise = 0, tilt = 0;
    int steps = 1;
};

StaticCut cut_the_static_femur(const ShaftCut& how) {
    return cut_the_static_femur(how.steps, [&how](double x, double y, double z) {
        const double dx = x + 0.066, dy = y - 0.065;
        return Point{-0.066 + dx * std::cos(how.turn) - dy * std::sin(how.turn),
                     0.065 + dx * std::sin(how.turn) + dy * std::cos(how.turn), z + how.raise + how.tilt * dx};
    });
}

// The same path through the static femur (what `sxk cut snap` does with it; docs/snapcut.md
// measures the written cut with tools/incision-distance): valid, in two pieces, every corner of
// the cut within half an edge of the sweeps. Splitting by the distance to the sweeps so far alone,
// without the rest of the movement, left the bone in one piece here.
TEST(SnapCutFemur, TheShaftCutThroughTheStaticFemurSeparatesItWithinHalfAnEdge) {
    const StaticCut cut = cut_the_static_femur(1);
    std::printf("[ femur    ] static: %zu edges split, farthest corner %.3g h (%.3g h in the result), %zu loose "
                "pieces\n",
                cut.split, cut.farthest / cut.h, cut.left / cut.h, cut.loose);
    EXPECT_GT(cut.split, 0u);
    EXPECT_LE(cut.farthest, 0.5 * cut.h);
    EXPECT_LE(cut.left, cut.incision * (1 + 1e-12)) << "a corner of the cut farther than any step reported";
    EXPECT_EQ(cut.loose, 1u);
    EXPECT_EQ(cut.pieces, 2u) << cut.bridge;
}

// The same path sampled as a haptic device samples it: each movement (0.05 s) in 50 steps of a
// millisecond, 951 steps of about 0.04 mean edge lengths. A step's sweeps are slivers, and the
// selection, the snapping and the degeneracy removal's edits of 50 steps meet where one step's
// would: the bone must come apart as it does at the recorded rate.
TEST(SnapCutFemur, TheShaftCutAtAHapticRateSeparatesTheStaticFemur) {
    const StaticCut cut = cut_the_static_femur(50);
    std::printf("[ femur    ] at 1 kHz: %zu steps, %zu faces dissected, farthest corner %.3g h (%.3g h in the "
                "result), %zu loose pieces\n",
                cut.steps, cut.dissected, cut.farthest / cut.h, cut.left / cut.h, cut.loose);
    EXPECT_LE(cut.farthest, 0.5 * cut.h);
    EXPECT_LE(cut.left, cut.incision * (1 + 1e-12)) << "a corner of the cut farther than any step reported";
    EXPECT_EQ(cut.loose, 1u);
    EXPECT_EQ(cut.pieces, 2u) << cut.bridge;
}

// A through cut of the shaft: two pieces, one of them loose, every corner of the cut within what
// the steps reported.
void expect_separated(const ShaftCut& how, const StaticCut& cut, const std::string& which) {
    std::printf("[ femur    ] %s: turned %.1f degrees, raised %.3f, tilted %.2f, %d steps a movement: %zu faces "
                "dissected, %zu pieces, farthest corner %.3g (reported %.3g)\n",
                which.c_str(), how.turn * 180 / std::numbers::pi, how.raise, how.tilt, how.steps, cut.dissected,
                cut.pieces, cut.left, cut.incision);
    EXPECT_EQ(cut.pieces, 2u) << which << ": " << cut.bridge;
    EXPECT_EQ(cut.loose, 1u) << which;
    EXPECT_LE(cut.left, cut.incision * (1 + 1e-12)) << which
                                                    << ": a corner of the cut farther than any step reported";
}

// Through cuts of the shaft at other heights, tilts and directions, each sampled at another rate:
// the recorded path turned about the bone's axis by up to 15 degrees, raised or lowered by up to
// 0.15 (a sixth of the bone) and tilted by up to 0.2, each movement in 1 to 50 steps. Every cut
// must leave the static femur in exactly two pieces (before the selection completed tetrahedra
// from the corners already on the cut, 9 of 20 such cuts left it in one).
TEST(SnapCutFemur, RandomThroughCutsOfTheShaftSeparateItAtAnyRate) {
    const std::uint64_t seed = seed_for("SnapCutFemur.RandomThroughCutsOfTheShaftSeparateItAtAnyRate");
    std::mt19937_64 random(seed);
    const std::array<int, 6> rates{1, 2, 5, 10, 25, 50};
    for (int cut = 0; cut < 8; ++cut) {
        ShaftCut how;
        how.turn = std::uniform_real_distribution<double>(-15, 15)(random) * std::numbers::pi / 180;
        how.raise = std::uniform_real_distribution<double>(-0.15, 0.15)(random);
        how.tilt = std::uniform_real_distribution<double>(-0.2, 0.2)(random);
        how.steps = rates[std::uniform_int_distribution<std::size_t>(0, rates.size() - 1)(random)];
        const std::string which = "seed " + std::to_string(seed) + ", cut " + std::to_string(cut);
        expect_separated(how, cut_the_static_femur(how), which);
    }
}

// Two of those cuts (seeds 3408219504 and 220917740, cut 4 of each) stayed joined across a face
// of three snapped corners when the selection looked only at the elements the sweep meets: the
// "corners snapped elsewhere" rule completes elements the sweep does not meet, once a corner of
// theirs is snapped or an edit made them (CutMarks::look_again; docs/performance.md "Looking
// again only where something changed").
TEST(SnapCutFemur, ThroughCutsCompletedByCornersSnappedElsewhereSeparate) {
    const std::array<ShaftCut, 2> cuts{ShaftCut{0.1559601626468741, -0.14927123946174875, 0.16911597213517127, 50},
                                       ShaftCut{0.11566460886220351, -0.084913258127500169, -0.054958468746057726, 5}};
    for (std::size_t i = 0; i < cuts.size(); ++i)
        expect_separated(cuts[i], cut_the_static_femur(cuts[i]), "cut " + std::to_string(i));
}

// CI's random seed 3289562137, cut 5: the degeneracy removal cut free 2 flat elements that held
// 5 others on, with no dissection's copy among them, so no cut pair reached their seeds; searched
// as a body of their own they raced nothing and stayed in the mesh as a third piece
// (loose_pieces.cpp, bodies_of). They are now found loose, and cut free as a crumb.
TEST(SnapCutFemur, APieceTheRemovalCutOffWithoutACopyIsFoundLoose) {
    const ShaftCut how{0.0041028186510345685, -0.14142549717622172, -0.088097554844496551, 50};
    expect_separated(how, cut_the_static_femur(how), "seed 3289562137, cut 5");
}

// The property test of tests/plugins/snapcut_random_test.cpp on the femur (issue 15: "the cube,
// the femur and a random Delaunay mesh"): seeded random curved paths, blades of 0.3 to 1.2 times
// the bone's length tilting as they go, every step validated (no element inverted or flat in
// either configuration), every path cancelled and compared with the femur. 6 paths of 30
// movements (186 steps, about 80 s: a whole-mesh validation after each costs more than the step).
TEST(SnapCutFemur, RandomPathsKeepTheFemurValid) {
    const std::string femur = make_femur();
    ASSERT_FALSE(femur.empty()) << "tools/make-data femur failed";
    std::size_t dissected = 0;
    check_random_cuts("SnapCutFemur.RandomPathsKeepTheFemurValid", read_mesh(femur), 6, 30, dissected);
    EXPECT_GT(dissected, 0u);
}

}  // namespace
}  // namespace sxk::test
