// Planar cutting (plugins/delaunaycut, thesis chapter 5 §5.2 and §5.4): the thesis' Fig. 5.16 and
// Fig. 5.8 cuts with their bounds, undo, the entry and exit cases, refusals, and seeded random
// scalpel paths on random meshes with both methods.
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/fixtures.hpp"
#include "incision_distance.hpp"
#include "planar_cut.hpp"
#include "svg_picture.hpp"
#include "sxk/components.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/generators.hpp"
#include "sxk/plugin_host.hpp"
#include "sxk/ops/make_delaunay_by_flips.hpp"
#include "sxk/quality.hpp"
#include "sxk/tool_path.hpp"

extern "C" const sxk_plugin_info* sxk_plugin_entry_delaunaycut();

namespace sxk::delaunaycut {
namespace {

Mesh square_grid(int cells) {
    auto made = make_triangle_grid({cells, cells});
    EXPECT_TRUE(made.ok()) << made.reason();
    return std::move(made).value();
}

std::vector<Point> recorded_path(const std::string& name) {
    const std::array<int, 1> columns{2};
    std::vector<Point> path;
    for (const ToolSample& sample : read_tool_path(SXK_TEST_DATA_DIR "/paths/" + name, columns).samples)
        path.push_back({sample.values[0], sample.values[1], 0});
    return path;
}

double smallest_angle(const Mesh& mesh) {
    const AngleCounts angles = triangle_angle_degrees(mesh);
    return *std::min_element(angles.smallest.begin(), angles.smallest.end());
}

// A mesh cut along a path, every step checked: valid, no triangle inverted or flat.
struct Cut {
    std::unique_ptr<Mesh> mesh;
    std::size_t triangles_before = 0;
    long long growth = 0;
    double smallest_angle = 0;
    IncisionDistance incision;
    double mean_edge = 0;
};

Cut cut_along(const Mesh& input, const std::vector<Point>& path, const Options& options) {
    Cut cut;
    cut.mesh = std::make_unique<Mesh>(input);
    cut.triangles_before = input.element_count();
    auto session = PlanarCutSession::make(*cut.mesh, options);
    EXPECT_TRUE(session.ok()) << session.reason();
    if (!session) return cut;
    ValidateOptions geometry;
    geometry.orientation = true;
    geometry.flat_is_invalid = true;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const auto stepped = (*session)->cut(path[i]);
        EXPECT_TRUE(stepped.ok()) << "sample " << i << ": " << stepped.reason();
        const auto valid = cut.mesh->validate(geometry);
        EXPECT_TRUE(valid.ok()) << "sample " << i << ": " << valid.reason();
        if (!valid) break;
    }
    cut.mean_edge = (*session)->mean_edge();
    (*session)->end();
    cut.growth = static_cast<long long>(cut.mesh->element_count()) - static_cast<long long>(cut.triangles_before);
    cut.smallest_angle = smallest_angle(*cut.mesh);
    cut.incision = incision_distance(*cut.mesh, path, options.cut_label);
    return cut;
}

Options with_method(Method method, double eps_edge = 1.0 / 3) {
    Options options;
    options.method = method;
    options.eps_edge = eps_edge;
    return options;
}

// Thesis Fig. 5.16: the 50-triangle square and a curved path. The thesis' subdivision cut adds 62
// triangles, its Delaunay cut 10 (eps_edge = h/3) and 12 (h/8). Ours: no more than those, with a
// smallest angle at least twice the subdivision cut's, the square in two pieces, and the incision
// within a tenth of an edge of the path (the dilation of its nodes, 0.04 h measured).
TEST(DelaunayCut, TheThesisSquareCutGrowsLessThanItsAndKeepsTwiceTheSubdivisionsSmallestAngle) {
    const Mesh square = square_grid(5);
    const std::vector<Point> path = recorded_path("square-curve.path");
    const Cut subdivision = cut_along(square, path, with_method(Method::subdivision));
    EXPECT_EQ(connected_components(*subdivision.mesh).count, 2u);
    // the subdivision cut's nodes are where the chords from its last node to the scalpel cross edges
    EXPECT_LT(subdivision.incision.farthest, 0.05 * subdivision.mean_edge);
    for (const auto& [eps_edge, thesis_growth] : {std::pair{1.0 / 3, 10LL}, std::pair{1.0 / 8, 12LL}}) {
        SCOPED_TRACE("eps_edge " + std::to_string(eps_edge));
        const Cut delaunay = cut_along(square, path, with_method(Method::delaunay, eps_edge));
        EXPECT_GT(delaunay.growth, 0);
        EXPECT_LE(delaunay.growth, thesis_growth);
        EXPECT_LT(delaunay.growth, subdivision.growth);
        EXPECT_GE(delaunay.smallest_angle, 2 * subdivision.smallest_angle);
        EXPECT_EQ(connected_components(*delaunay.mesh).count, 2u);
        EXPECT_GT(delaunay.incision.nodes, 4u);
        EXPECT_LT(delaunay.incision.farthest, 0.1 * delaunay.mean_edge);
    }
}

// Thesis §5.5's scale-independent criterion: a node goes when the angles opposite its edge to the
// active node are small, whatever the mesh's scale. The same cut in the square at 1 and at 1000 times
// its size makes the same mesh, up to that scale.
TEST(DelaunayCut, TheShortAngleCriterionDoesNotDependOnTheMeshScale) {
    Options options = with_method(Method::delaunay);
    options.short_angle = 20;
    const std::vector<Point> path = recorded_path("square-curve.path");
    const Cut unit = cut_along(square_grid(5), path, options);
    auto big = make_triangle_grid({5, 5}, {1000, 1000});
    ASSERT_TRUE(big.ok());
    std::vector<Point> scaled;
    for (const Point& p : path) scaled.push_back({1000 * p[0], 1000 * p[1], 0});
    const Cut large = cut_along(*big, scaled, options);
    EXPECT_EQ(unit.growth, large.growth);
    EXPECT_LE(unit.growth, 10);
    EXPECT_NEAR(unit.smallest_angle, large.smallest_angle, 1e-6);
    EXPECT_EQ(connected_components(*unit.mesh).count, 2u);
}

// Thesis Fig. 5.8: a regular 722-triangle mesh and a long curved path, +57 triangles there.
TEST(DelaunayCut, TheThesisLongCurvedCutGrowsLessThanIts) {
    const Cut delaunay = cut_along(square_grid(19), recorded_path("long-curve.path"), with_method(Method::delaunay));
    EXPECT_GT(delaunay.growth, 0);
    EXPECT_LE(delaunay.growth, 57);
    EXPECT_EQ(connected_components(*delaunay.mesh).count, 2u);
    EXPECT_LT(delaunay.incision.farthest, 0.1 * delaunay.mean_edge);
    EXPECT_GT(delaunay.smallest_angle, 5.0);  // 6.7 degrees measured; subdivision: 0.0
}

TEST(PlanarCut, UndoingEveryStepRestoresTheMeshExactly) {
    const Mesh square = square_grid(5);
    const std::vector<Point> path = recorded_path("square-curve.path");
    for (const Method method : {Method::delaunay, Method::subdivision}) {
        SCOPED_TRACE(std::string(method_name(method)));
        Mesh mesh = square;
        auto session = PlanarCutSession::make(mesh, with_method(method));
        ASSERT_TRUE(session.ok()) << session.reason();
        for (const Point& p : path) ASSERT_TRUE((*session)->cut(p).ok());
        EXPECT_NE(mesh.element_count(), square.element_count());
        EXPECT_EQ((*session)->phase(), Phase::outside);
        ASSERT_TRUE((*session)->cancel().ok());
        test::expect_same_state(mesh, square);
        ASSERT_TRUE(mesh.validate().ok());
    }
}

// One undo takes back one movement and the session's state with it: the same movement again
// gives the same mesh.
TEST(PlanarCut, AStepUndoneAndTakenAgainGivesTheSameMesh) {
    Mesh mesh = square_grid(5);
    auto session = PlanarCutSession::make(mesh, with_method(Method::delaunay));
    ASSERT_TRUE(session.ok());
    const std::vector<Point> path = recorded_path("square-curve.path");
    for (std::size_t i = 0; i < 20; ++i) ASSERT_TRUE((*session)->cut(path[i]).ok());
    ASSERT_EQ((*session)->phase(), Phase::cutting);
    const Mesh before = mesh;
    ASSERT_TRUE((*session)->cut(path[20]).ok());
    const Mesh after = mesh;
    ASSERT_TRUE((*session)->undo_step().ok());
    test::expect_same_state(mesh, before);
    ASSERT_TRUE((*session)->cut(path[20]).ok());
    test::expect_same_state(mesh, after);
    ASSERT_TRUE(mesh.validate().ok());
}

// The scalpel and the cut's state are a side log of the journal (ToolSession::keep_beside): the
// application's own undo and redo of a movement take them back and forth with the mesh, and
// placing the scalpel, which edits nothing, is a step it can undo too.
TEST(PlanarCut, TheApplicationsUndoAndRedoTakeTheScalpelWithTheMesh) {
    Mesh mesh = square_grid(5);
    EditJournal journal(mesh);
    auto session = PlanarCutSession::make(mesh, with_method(Method::delaunay));
    ASSERT_TRUE(session.ok());
    PlanarCutSession& cutter = **session;
    const std::vector<Point> path = recorded_path("square-curve.path");
    ASSERT_TRUE(cutter.cut(path[0]).ok());  // placed: no edit
    EXPECT_EQ(journal.undo_count(), 1u);
    for (std::size_t i = 1; i < 20; ++i) ASSERT_TRUE(cutter.cut(path[i]).ok());
    ASSERT_EQ(cutter.phase(), Phase::cutting);
    const Mesh before = mesh;
    const Point scalpel_before = *cutter.scalpel();
    const VertexId active_before = cutter.active_node();
    ASSERT_TRUE(cutter.cut(path[20]).ok());
    const Mesh after = mesh;
    const VertexId active_after = cutter.active_node();

    ASSERT_TRUE(journal.undo().ok());
    test::expect_same_state(mesh, before);
    EXPECT_EQ(*cutter.scalpel(), scalpel_before);
    EXPECT_EQ(cutter.active_node(), active_before);
    EXPECT_EQ(cutter.phase(), Phase::cutting);
    ASSERT_TRUE(journal.redo().ok());
    test::expect_same_state(mesh, after);
    EXPECT_EQ(*cutter.scalpel(), path[20]);
    EXPECT_EQ(cutter.active_node(), active_after);

    // every step back: the square as it was and no scalpel
    while (journal.undo_count() > 0) ASSERT_TRUE(journal.undo().ok());
    test::expect_same_state(mesh, square_grid(5));
    EXPECT_FALSE(cutter.scalpel().has_value());
    EXPECT_EQ(cutter.phase(), Phase::outside);
    ASSERT_TRUE(mesh.validate().ok());
}

// An entry within eps_entry of a boundary node drags that node (no split); the scalpel going back
// out before the fix-up leaves the dent and nothing cut.
TEST(DelaunayCut, AnEntryNearANodeDragsItAndARetractionLeavesTheDent) {
    Mesh mesh = square_grid(5);
    const VertexId node = 2;  // (2, 0) on the bottom side
    auto session = PlanarCutSession::make(mesh, with_method(Method::delaunay));
    ASSERT_TRUE(session.ok());
    ASSERT_TRUE((*session)->cut({2.05, -0.5, 0}).ok());
    ASSERT_TRUE((*session)->cut({2.05, 0.1, 0}).ok());
    EXPECT_EQ((*session)->last_step().entries, 1u);
    EXPECT_EQ((*session)->last_step().edges_split, 0u);
    EXPECT_EQ((*session)->phase(), Phase::entering);
    EXPECT_EQ((*session)->active_node(), node);
    EXPECT_EQ(mesh.deformed(node), (Point{2.05, 0.1, 0}));
    ASSERT_TRUE((*session)->cut({2.05, -0.5, 0}).ok());
    EXPECT_EQ((*session)->last_step().retractions, 1u);
    EXPECT_EQ((*session)->phase(), Phase::outside);
    EXPECT_EQ(mesh.deformed(node), (Point{2.05, 0.1, 0}));  // the dent stays
    EXPECT_EQ(mesh.element_count(), 50u);
    ASSERT_TRUE(mesh.validate(ValidateOptions{true, true}).ok());
}

// Far from a node the entry splits the boundary edge; once the node is eps_entry in, the dent is
// filled and the incision begins, labelled as the cut.
TEST(DelaunayCut, AnEntryAwayFromNodesSplitsTheEdgeAndTheFixUpBeginsTheIncision) {
    Mesh mesh = square_grid(5);
    auto session = PlanarCutSession::make(mesh, with_method(Method::delaunay));
    ASSERT_TRUE(session.ok());
    ASSERT_TRUE((*session)->cut({2.5, -0.5, 0}).ok());
    ASSERT_TRUE((*session)->cut({2.5, 0.1, 0}).ok());
    EXPECT_EQ((*session)->last_step().edges_split, 1u);
    EXPECT_EQ((*session)->phase(), Phase::entering);
    ASSERT_TRUE((*session)->cut({2.5, 0.6, 0}).ok());
    EXPECT_EQ((*session)->last_step().fix_ups, 1u);
    EXPECT_EQ((*session)->phase(), Phase::cutting);
    const IncisionDistance incision = incision_distance(mesh, std::vector<Point>{{2.5, 0, 0}, {2.5, 0.6, 0}}, 9999);
    EXPECT_EQ(incision.nodes, 3u);  // the active node and the two at the entry
    EXPECT_LT(incision.farthest, 0.05 * (*session)->mean_edge() + 1e-12);
    ASSERT_TRUE(mesh.validate(ValidateOptions{true, true}).ok());
}

TEST(PlanarCut, RefusesMeshesItCannotCutAndPositionsThatAreNotFinite) {
    Mesh cube = test::kuhn_cube(1);
    auto tetrahedra = PlanarCutSession::make(cube, Options{});
    ASSERT_FALSE(tetrahedra.ok());
    EXPECT_EQ(tetrahedra.code(), RefusalCode::wrong_dimension);
    EXPECT_EQ(tetrahedra.reason(), "delaunaycut: the planar cutter needs a triangle mesh in the plane (Dimension 2)");
    Mesh square = square_grid(2);
    Options bad;
    bad.eps_exit = 0;
    auto refused = PlanarCutSession::make(square, bad);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "delaunaycut: eps_exit 0 is not in (0, 10]");
    auto session = PlanarCutSession::make(square, Options{});
    ASSERT_TRUE(session.ok());
    ASSERT_TRUE((*session)->cut({-1, 1, 0}).ok());
    const Mesh before = square;
    const auto nan = (*session)->cut({std::nan(""), 1, 0});
    ASSERT_FALSE(nan.ok());
    EXPECT_EQ(nan.code(), RefusalCode::bad_argument);
    EXPECT_EQ(nan.reason(), "delaunaycut: the scalpel's position is not finite");
    test::expect_same_state(square, before);
    EXPECT_EQ((*session)->steps(), 1u);
}

// A deformed body: the deformed positions an affine map of the reference ones (a shear and a
// stretch). The cut is made in the deformed positions; every node it moves or adds gets the reference
// position that the triangle holding it maps back to, so the map still holds at every vertex, and
// the mesh is valid in both position sets.
TEST(DelaunayCut, CutsTheDeformedShapeAndMapsNewNodesBackToTheReference) {
    Mesh mesh = square_grid(5);
    auto deform = [](const Point& p) { return Point{1.5 * p[0] + 0.3 * p[1], 0.8 * p[1] - 0.1 * p[0], 0}; };
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) mesh.set_deformed(v, deform(mesh.reference(v)));
    std::vector<Point> path;
    for (const Point& p : recorded_path("square-curve.path")) path.push_back(deform(p));
    for (const Method method : {Method::delaunay, Method::subdivision}) {
        SCOPED_TRACE(std::string(method_name(method)));
        const Cut cut = cut_along(mesh, path, with_method(method));
        EXPECT_GT(cut.growth, 0);
        EXPECT_EQ(connected_components(*cut.mesh).count, 2u);
        std::size_t moved = 0;
        for (VertexId v = 0; v < cut.mesh->vertex_count(); ++v) {
            if (cut.mesh->vertex_element(v) == invalid_id) continue;
            const Point expected = deform(cut.mesh->reference(v));
            for (std::size_t k = 0; k < 2; ++k) EXPECT_NEAR(cut.mesh->deformed(v)[k], expected[k], 1e-12) << v;
            moved += v >= mesh.vertex_count() || cut.mesh->reference(v) != mesh.reference(v);
        }
        EXPECT_GT(moved, 4u);
        EXPECT_TRUE(cut.mesh->validate(ValidateOptions{true, true}).ok());
    }
}

// The host begins the plug-in's tool from its typed options; a ToolPose's position is the scalpel.
TEST(PlanarCut, TheHostOffersTheToolWithItsOptions) {
    PluginHost host;
    ASSERT_TRUE(host.add_static(sxk_plugin_entry_delaunaycut(), "linked-in delaunaycut"));
    auto factory = host.tool("delaunaycut");
    ASSERT_TRUE(factory) << factory.reason();
    ASSERT_EQ((*factory)->tools().size(), 1u);
    EXPECT_EQ((*factory)->tools()[0].name, "delaunaycut");
    Mesh mesh = square_grid(5);
    Options options;
    options.method = Method::subdivision;
    options.eps_exit = 0.25;
    auto session = host.begin_tool(mesh, options);
    ASSERT_TRUE(session) << session.reason();
    auto* cutter = dynamic_cast<PlanarCutSession*>(session->get());
    ASSERT_NE(cutter, nullptr);
    EXPECT_EQ(cutter->options().method, Method::subdivision);
    EXPECT_EQ(cutter->options().eps_exit, 0.25);
    ToolPose pose;
    for (const Point& p : recorded_path("square-curve.path")) {
        pose.position = p;
        ASSERT_TRUE((*session)->step(pose));
    }
    EXPECT_EQ(connected_components(mesh).count, 2u);
    EXPECT_TRUE(mesh.validate(ValidateOptions{true, true}).ok());
    Options bad;
    bad.eps_edge = -1;
    const auto refused = host.begin_tool(mesh, bad);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.code(), RefusalCode::bad_argument);
    EXPECT_EQ(refused.reason(), "delaunaycut: eps_edge -1 is not in (0, 10]");
    EXPECT_EQ(host.tool("scalpel").reason(), "no tool called scalpel; the plug-ins offer: delaunaycut");
}

// A random mesh: a jittered grid made Delaunay by flips.
Mesh random_mesh(std::mt19937_64& random) {
    std::uniform_int_distribution<int> cells(3, 12);
    Mesh mesh = square_grid(cells(random));
    std::uniform_real_distribution<double> jitter(-0.15, 0.15);  // no triangle of the grid turns over
    const int n = static_cast<int>(std::lround(std::sqrt(static_cast<double>(mesh.vertex_count())))) - 1;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Point p = mesh.deformed(v);
        const bool side_x = p[0] == 0 || p[0] == n, side_y = p[1] == 0 || p[1] == n;
        const Point moved{side_x ? p[0] : p[0] + jitter(random), side_y ? p[1] : p[1] + jitter(random), 0};
        mesh.set_reference(v, moved);
        mesh.set_deformed(v, moved);
    }
    EXPECT_TRUE(make_delaunay_by_flips(mesh).ok());
    return mesh;
}

// A random scalpel path: from outside the mesh, heading roughly inwards, turning smoothly by
// random amounts, with random step lengths from a hundredth of an edge to two edges.
std::vector<Point> random_path(std::mt19937_64& random, double side, std::size_t samples) {
    std::uniform_real_distribution<double> unit(0, 1);
    const double angle = 2 * pi * unit(random);
    Point p{side / 2 - 0.7 * side * std::cos(angle), side / 2 - 0.7 * side * std::sin(angle), 0};
    double heading = angle + (unit(random) - 0.5);
    std::vector<Point> path{p};
    while (path.size() < samples) {
        heading += 0.6 * (unit(random) - 0.5);
        const double step = unit(random) < 0.2 ? 2 * unit(random) : 0.01 + 0.3 * unit(random);
        p = {p[0] + step * std::cos(heading), p[1] + step * std::sin(heading), 0};
        path.push_back(p);
    }
    return path;
}

// Seeded random paths on random meshes, both methods: never an invalid mesh, an inverted or flat
// triangle, or a refused step; undoing everything gives the mesh back. 60 meshes, 2 methods, 90
// movements: 10,800 movements.
TEST(PlanarCut, RandomPathsOnRandomMeshesNeverLeaveAnInvalidMesh) {
    std::mt19937_64 random(test::seed_for("PlanarCut.RandomPaths"));
    std::size_t movements = 0;
    double smallest_delaunay = 180, smallest_subdivision = 180;
    for (int trial = 0; trial < 60; ++trial) {
        const Mesh mesh = random_mesh(random);
        const double side = std::sqrt(static_cast<double>(mesh.vertex_count())) - 1;
        const std::vector<Point> path = random_path(random, side, 91);
        for (const Method method : {Method::delaunay, Method::subdivision}) {
            SCOPED_TRACE("trial " + std::to_string(trial) + ", " + std::string(method_name(method)));
            const Cut cut = cut_along(mesh, path, with_method(method));
            movements += path.size() - 1;
            (method == Method::delaunay ? smallest_delaunay : smallest_subdivision) =
                std::min(method == Method::delaunay ? smallest_delaunay : smallest_subdivision, cut.smallest_angle);
            if (trial % 10 == 0) {  // and back
                Mesh again = mesh;
                auto session = PlanarCutSession::make(again, with_method(method));
                ASSERT_TRUE(session.ok());
                for (const Point& p : path) ASSERT_TRUE((*session)->cut(p).ok());
                ASSERT_TRUE((*session)->cancel().ok());
                test::expect_same_state(again, mesh);
            }
            if (HasFailure()) return;
        }
    }
    EXPECT_GE(movements, 10000u);
    std::cout << "smallest angle over all cuts: Delaunay " << smallest_delaunay << ", subdivision "
              << smallest_subdivision << " degrees\n";
}

}  // namespace
}  // namespace sxk::delaunaycut
