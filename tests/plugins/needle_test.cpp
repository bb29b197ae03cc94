// The needle plug-in (thesis chapter 6): insertion into the thesis' slab (2D, right triangles) and
// a Kuhn cube (3D), with the elasticity plug-in's simulation; the shapes bisection keeps, needle
// nodes on the needle, stick-slip friction, undo, geometry only, refusals, the ToolFactory tool,
// and seeded random needle paths.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "body_words.hpp"
#include "core/fixtures.hpp"
#include "needle.hpp"
#include "simulation.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/generators.hpp"
#include "sxk/plugin_host.hpp"

extern "C" const sxk_plugin_info* sxk_plugin_entry_needle();
extern "C" const sxk_plugin_info* sxk_plugin_entry_elasticity();

namespace sxk::needle {
namespace {

// The thesis' slab (§6.8.1): 0.1 x 0.1 m in right triangles of size h3 = 12.5 mm, fixed at x = 0.1,
// E = 34 kPa, nu = 0.34, 1 cm thick; eq. 6.9 with tol 0.01 and eps_round 1e-8.
const std::vector<std::string> slab_body{"--fix", "x>0.0999", "--E", "34e3", "--nu", "0.34", "--thickness", "0.01",
                                         "--tol", "0.01", "--rounding", "1e-8"};
const std::vector<std::string> cube_body{"--fix", "x>0.0999", "--E", "34e3", "--nu", "0.34", "--tol", "0.01",
                                         "--rounding", "1e-8"};

struct Insertion {
    Mesh mesh;
    Mesh before{mesh};
    std::unique_ptr<Simulation> simulation;
    std::unique_ptr<NeedleSession> session;

    Insertion(Mesh start, const std::vector<std::string>& body, Options options = {})
        : mesh(std::move(start)), before(mesh) {
        if (!body.empty()) {
            auto made = elasticity::simulate(mesh, sxk::cli::body_options(body).value());
            EXPECT_TRUE(made.ok()) << made.reason();
            simulation = std::move(*made);
        }
        auto made = NeedleSession::make(mesh, options, simulation.get());
        EXPECT_TRUE(made.ok()) << made.reason();
        session = std::move(*made);
    }
};

Mesh slab() { return *make_triangle_grid({8, 8}, {0.0125, 0.0125}); }
Mesh cube() { return *make_kuhn_cube(8, 0.0125); }

// Needle of length 0.1 along +x at height y (2D) / y, z (3D), tip at x.
Needle along_x(double x, double y, double z = 0) { return {{x - 0.1, y, z}, {x, y, z}}; }

// Where a needle node is: the body's solution.
Point position_of(const Insertion& run, VertexId v) {
    const auto u = run.simulation->displacement(v);
    const Point& x = run.mesh.reference(v);
    return {x[0] + u[0], x[1] + u[1], x[2] + u[2]};
}

// Every needle node where its needle coordinates put it: on the line at d_perp from the axis (a
// relocated node: d_perp = 0, on the needle), and a sticking one at its d_needle; within 1e-12 of the
// needle's length.
void expect_nodes_on_needle(const Insertion& run) {
    const Needle needle = *run.session->needle();
    const Eigen::Vector3d tip(needle.tip[0], needle.tip[1], needle.tip[2]);
    const Eigen::Vector3d base(needle.base[0], needle.base[1], needle.base[2]);
    const double length = (tip - base).norm();
    const Eigen::Vector3d axis = (tip - base) / length;
    for (const NeedleNode& node : run.session->nodes()) {
        const Point x = position_of(run, node.vertex);
        const Eigen::Vector3d d = Eigen::Vector3d(x[0], x[1], x[2]) - tip;
        const Eigen::Vector3d across = d - d.dot(axis) * axis;
        const Eigen::Vector3d perp(node.perp[0], node.perp[1], node.perp[2]);
        EXPECT_LE((across - perp).norm(), 1e-12 * length) << "node " << node.vertex;
        if (node.grip == Grip::stick) {
            EXPECT_NEAR(d.dot(axis), node.along, 1e-12 * length) << "node " << node.vertex;
        }
    }
}

// Every triangle right-angled and isosceles (congruent, up to scale, to the starting ones).
void expect_right_isosceles(const Mesh& mesh) {
    for (const ElementId t : elements(mesh)) {
        const auto v = mesh.simplex(t).vertices();
        std::array<double, 3> squared{};
        for (int k = 0; k < 3; ++k) {
            const Point& a = mesh.reference(v[k]);
            const Point& b = mesh.reference(v[(k + 1) % 3]);
            squared[k] = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
        }
        std::sort(squared.begin(), squared.end());
        EXPECT_NEAR(squared[0], squared[1], 1e-9 * squared[2]) << "triangle " << t;
        EXPECT_NEAR(squared[0] + squared[1], squared[2], 1e-9 * squared[2]) << "triangle " << t;
    }
}

TEST(Needle, InsertsIntoTheThesisSlabKeepingEveryTriangleCongruentAndTheNodesOnTheNeedle) {
    Insertion run(slab(), slab_body);
    const double h6 = 0.1 / 64, speed = 0.3 * h6;
    std::size_t intercepted = 0, slipping_steps = 0;
    for (double x = -0.01; x <= 0.07 + 1e-12; x += speed) {
        auto step = run.session->move(along_x(x, 0.05));
        ASSERT_TRUE(step.ok()) << step.reason();
        ASSERT_TRUE(run.mesh.validate({.orientation = true, .flat_is_invalid = true}).ok()) << "x = " << x;
        expect_nodes_on_needle(run);
        intercepted += step->intercepted;
        slipping_steps += step->slip > 0;
        EXPECT_TRUE(step->converged);
    }
    expect_right_isosceles(run.mesh);
    // nodes on y = 0.05 every h6 or so over the 70 mm inserted
    EXPECT_GE(run.session->nodes().size(), 20u);
    EXPECT_EQ(intercepted, run.session->nodes().size());
    EXPECT_GT(slipping_steps, 100u);
    // refined around the shaft: triangles of size h6 (hypotenuse sqrt 2 h6) all along it
    std::size_t fine = 0;
    for (const ElementId t : elements(run.mesh)) {
        const auto v = run.mesh.simplex(t).vertices();
        const Point& a = run.mesh.reference(v[0]);
        if (std::abs(a[1] - 0.05) < 0.002 && a[0] < 0.07) {
            double longest = 0;
            for (int k = 0; k < 3; ++k) {
                const Point& p = run.mesh.reference(v[k]);
                const Point& q = run.mesh.reference(v[(k + 1) % 3]);
                longest = std::max(longest, std::hypot(p[0] - q[0], p[1] - q[1]));
            }
            EXPECT_LE(longest, std::sqrt(2.0) * 0.1 / 32 + 1e-12) << "triangle " << t;
            ++fine;
        }
    }
    EXPECT_GT(fine, 40u);
    // sliding through the whole shaft, the needle drags with the dynamic friction of the inserted
    // length: 20 N/m over 70 mm and the bulge at the tip (1.4 N + 0.1 N)
    const double inserted = 0.07;
    const Friction f;
    const double friction = f.force(0, inserted);
    EXPECT_NEAR(run.session->last_step().axial_force, friction, 0.1 * friction);
    EXPECT_LT(run.session->last_step().lateral_force, 0.01 * friction);
}

TEST(Needle, NodesStickWhenTheNeedleStopsAndSlipWhenItIsPulledBack) {
    Insertion run(slab(), slab_body);
    const double speed = 0.3 * 0.1 / 64;
    double x = -0.01;
    for (; x <= 0.04; x += speed) ASSERT_TRUE(run.session->move(along_x(x, 0.05)).ok());
    ASSERT_GT(run.session->last_step().slip, 0u);
    // the needle stops: the loop runs on until no grip changes (thesis §6.8.4): the tissue slides
    // back along the needle for a few steps, then every node sticks
    int still_steps = 0;
    for (;; ++still_steps) {
        auto still = run.session->move(along_x(x - speed, 0.05));
        ASSERT_TRUE(still.ok());
        if ((still->loosened + still->gripped == 0 && still->slip == 0) || still_steps == 100) break;
    }
    EXPECT_LT(still_steps, 100);
    EXPECT_EQ(run.session->last_step().slip, 0u);
    EXPECT_GT(run.session->last_step().stick, 10u);
    // pulled back: the tissue is dragged back until the nodes slip the other way, and the
    // needle's force turns round
    for (int k = 0; k < 60; ++k) ASSERT_TRUE(run.session->move(along_x(x - speed * (2 + k), 0.05)).ok());
    EXPECT_GT(run.session->last_step().slip, 0u);
    EXPECT_LT(run.session->last_step().axial_force, 0);
    for (const NeedleNode& node : run.session->nodes())
        if (node.grip == Grip::slip) {
            EXPECT_EQ(node.sense, -1);
        }
    // pulled out: every node released, the tip outside
    for (double back = x; back > -0.02; back -= 10 * speed) ASSERT_TRUE(run.session->move(along_x(back, 0.05)).ok());
    EXPECT_TRUE(run.session->nodes().empty());
    EXPECT_FALSE(run.session->last_step().tip_inside);
    EXPECT_TRUE(run.mesh.validate({.orientation = true}).ok());
}

TEST(Needle, UndoingEveryStepGivesTheSlabBackBitForBit) {
    Insertion run(slab(), slab_body);
    double last = 0;
    for (double x = -0.01; x <= 0.03; x += 0.002) {
        ASSERT_TRUE(run.session->move(along_x(x, 0.047)).ok());
        last = x;
    }
    ASSERT_GT(run.mesh.element_count(), run.before.element_count());
    // one step back, then forward again: the same as never having undone it
    const std::size_t nodes = run.session->nodes().size();
    ASSERT_TRUE(run.session->undo_step().ok());
    auto again = run.session->move(along_x(last, 0.047));
    ASSERT_TRUE(again.ok()) << again.reason();
    EXPECT_EQ(run.session->nodes().size(), nodes);
    expect_nodes_on_needle(run);
    ASSERT_TRUE(run.session->cancel().ok());
    ASSERT_TRUE(run.mesh.validate().ok());
    test::expect_same_state(run.mesh, run.before);
    EXPECT_TRUE(run.session->nodes().empty());
}

// Options::local_vertices: every step solves at most so many vertices around the needle, the far
// field held; the needle's force stays near the whole body's, and settle() lets the far field catch
// up (docs/needle.md "Local solve").
TEST(Needle, LocalSolveBoundsTheRegionAndSettleCatchesTheFarFieldUp) {
    Options local_options;
    local_options.local_vertices = 200;
    Options far_options = local_options;
    far_options.far_vertices = 200;
    const Mesh fine = *make_triangle_grid({32, 32}, {0.1 / 32, 0.1 / 32});
    Insertion whole(fine, slab_body), local(fine, slab_body, local_options), far(fine, slab_body, far_options);
    auto early = local.session->settle(100);
    ASSERT_FALSE(early.ok());
    EXPECT_EQ(early.refusal().code, RefusalCode::not_applicable);
    EXPECT_EQ(early.reason(), "needle: settle: the needle has not been placed");
    const double speed = 0.3 * 0.1 / 64;
    for (double x = -0.01; x <= 0.05; x += speed) {
        ASSERT_TRUE(whole.session->move(along_x(x, 0.05)).ok());
        auto far_step = far.session->move(along_x(x, 0.05));
        ASSERT_TRUE(far_step.ok()) << far_step.reason();
        EXPECT_LE(far_step->far_vertices, 200u);
        auto step = local.session->move(along_x(x, 0.05));
        ASSERT_TRUE(step.ok()) << step.reason();
        ASSERT_TRUE(local.mesh.validate({.orientation = true, .flat_is_invalid = true}).ok()) << "x = " << x;
        EXPECT_LE(step->solved_vertices, std::max<std::size_t>(200, local.session->nodes().size())) << "x = " << x;
        expect_nodes_on_needle(local);
    }
    EXPECT_EQ(whole.session->last_step().solved_vertices, whole.mesh.vertices_in_elements());
    const double force = whole.session->last_step().axial_force;
    EXPECT_GT(force, 0.5);
    EXPECT_NEAR(local.session->last_step().axial_force, force, 0.15 * force);
    // the far field lags: settling moves vertices the local steps held, less when far-field blocks
    // followed every step
    auto settling_moves = [](Insertion& run) {
        const std::vector<Point> was(run.mesh.deformed_positions().begin(), run.mesh.deformed_positions().end());
        EXPECT_TRUE(run.session->settle(100000).ok());
        double most = 0;
        for (VertexId v = 0; v < run.mesh.vertex_count(); ++v)
            most = std::max(most, std::hypot(run.mesh.deformed(v)[0] - was[v][0], run.mesh.deformed(v)[1] - was[v][1]));
        EXPECT_TRUE(run.session->undo_step().ok());
        return most;
    };
    const double lag = settling_moves(local), far_lag = settling_moves(far);
    std::printf("settling moves a vertex by %.3g mm after local steps, %.3g mm with far-field blocks\n", 1e3 * lag,
                1e3 * far_lag);
    EXPECT_GT(lag, 1e-4);
    EXPECT_LT(far_lag, 0.6 * lag);
    ASSERT_TRUE(far.mesh.validate({.orientation = true, .flat_is_invalid = true}).ok());
    const std::vector<Point> before(local.mesh.deformed_positions().begin(), local.mesh.deformed_positions().end());
    auto settled = local.session->settle(100000);
    ASSERT_TRUE(settled.ok()) << settled.reason();
    EXPECT_TRUE(settled->converged);
    EXPECT_EQ(settled->solved_vertices, local.mesh.vertices_in_elements());
    std::size_t moved = 0;
    for (VertexId v = 0; v < local.mesh.vertex_count(); ++v) moved += local.mesh.deformed(v) != before[v] ? 1 : 0;
    EXPECT_GT(moved, 400u);
    EXPECT_GT(settled->iterations, 0u);
    expect_nodes_on_needle(local);
    // the settling step is undone as any other
    ASSERT_TRUE(local.session->undo_step().ok());
    for (VertexId v = 0; v < local.mesh.vertex_count(); ++v) ASSERT_EQ(local.mesh.deformed(v), before[v]);
    ASSERT_TRUE(local.session->cancel().ok());
    ASSERT_TRUE(local.mesh.validate().ok());
    test::expect_same_state(local.mesh, local.before);
}

// §6.8.6: along a tilted line the intercepted nodes are off the needle; relocation moves them onto
// it (both positions), unless that would invert an element.
TEST(Needle, RelocationMovesInterceptedNodesOntoTheNeedle) {
    Options options;
    options.relocate = true;
    Insertion run(slab(), slab_body, options);
    const double angle = 0.3;
    const Eigen::Vector2d axis(std::cos(angle), std::sin(angle));
    std::size_t relocated = 0, kept = 0;
    for (double s = -0.01; s <= 0.07; s += 0.0005) {
        const Eigen::Vector2d tip = Eigen::Vector2d(0, 0.03) + s * axis, base = tip - 0.1 * axis;
        auto step = run.session->move({{base.x(), base.y(), 0}, {tip.x(), tip.y(), 0}});
        ASSERT_TRUE(step.ok()) << step.reason();
        ASSERT_TRUE(run.mesh.validate({.orientation = true, .flat_is_invalid = true}).ok()) << "s = " << s;
        expect_nodes_on_needle(run);
        relocated += step->relocated;
        kept += step->not_relocated;
    }
    EXPECT_GT(relocated, 20u);
    EXPECT_EQ(relocated + kept, run.session->nodes().size());
    std::size_t on_needle = 0;
    for (const NeedleNode& node : run.session->nodes()) on_needle += node.perp == Point{0, 0, 0};
    EXPECT_EQ(on_needle, relocated);
    ASSERT_TRUE(run.session->cancel().ok());
    test::expect_same_state(run.mesh, run.before);
}

TEST(Needle, InsertsIntoAKuhnCubeKeepingThreeShapesOfTetrahedra) {
    Options options;
    options.h_ref = 0.1 / 32;
    Insertion run(cube(), cube_body, options);
    std::set<test::ShapeSignature> start_shapes;
    for (const ElementId t : elements(run.mesh)) start_shapes.insert(test::shape_signature(run.mesh, t));
    EXPECT_EQ(start_shapes.size(), 1u);
    for (double x = -0.01; x <= 0.07 + 1e-12; x += 0.001) {
        auto step = run.session->move(along_x(x, 0.051, 0.049));
        ASSERT_TRUE(step.ok()) << step.reason();
        ASSERT_TRUE(run.mesh.validate({.orientation = true, .flat_is_invalid = true}).ok()) << "x = " << x;
        expect_nodes_on_needle(run);
    }
    std::set<test::ShapeSignature> shapes;
    for (const ElementId t : elements(run.mesh)) shapes.insert(test::shape_signature(run.mesh, t));
    EXPECT_LE(shapes.size(), 3u);  // Maubach's three classes (sxk/ops/tet_bisection.hpp)
    EXPECT_GE(run.session->nodes().size(), 15u);
    EXPECT_GT(run.session->last_step().axial_force, 0);
    ASSERT_TRUE(run.session->cancel().ok());
    test::expect_same_state(run.mesh, run.before);
}

// Thesis Fig. 6.14's needle of 1 mm radius, here 2 mm in a Kuhn cube refined to h6: every node
// within the radius of the inserted shaft is a needle node, and only those and the nodes of the
// faces the tip entered; the refinement reaches across the radius; the body follows, the mesh
// stays valid and in Maubach's classes, and undoing gives the cube back.
TEST(Needle, ANeedleWithARadiusHoldsEveryNodeItsCrossSectionPassedOver) {
    const double radius = 0.002, y = 0.051, z = 0.049, end = 0.05;
    Options line;
    line.h_ref = 0.1 / 64;
    Options thick = line;
    thick.radius = radius;
    Insertion thin_run(cube(), {}, line), geometry(cube(), {}, thick), body(cube(), cube_body, thick);
    std::size_t thin_bisections = 0, thick_bisections = 0;
    for (double x = -0.01; x <= end + 1e-12; x += 0.001) {
        auto thin = thin_run.session->move(along_x(x, y, z));
        ASSERT_TRUE(thin.ok()) << thin.reason();
        thin_bisections += thin->bisections;
        auto step = geometry.session->move(along_x(x, y, z));
        ASSERT_TRUE(step.ok()) << step.reason();
        thick_bisections += step->bisections;
        auto solved = body.session->move(along_x(x, y, z));
        ASSERT_TRUE(solved.ok()) << solved.reason();
        ASSERT_TRUE(body.mesh.validate({.orientation = true, .flat_is_invalid = true}).ok()) << "x = " << x;
        expect_nodes_on_needle(body);
    }
    ASSERT_TRUE(geometry.mesh.validate({.orientation = true, .flat_is_invalid = true}).ok());
    // geometry only, nothing moves: the vertices within the radius of the shaft, up to the tip
    std::set<VertexId> within, held;
    for (const ElementId t : elements(geometry.mesh))
        for (const VertexId v : geometry.mesh.simplex(t).vertices()) {
            const Point& p = geometry.mesh.deformed(v);
            if (p[0] <= end && std::hypot(p[1] - y, p[2] - z) <= radius) within.insert(v);
        }
    for (const NeedleNode& node : geometry.session->nodes()) {
        held.insert(node.vertex);
        const double off = std::hypot(node.perp[1], node.perp[2]);
        // beyond the radius only the nearest node of a face the tip entered: within an edge of h6
        EXPECT_LE(off, std::max(radius, std::sqrt(3.0) * line.h_ref)) << "node " << node.vertex;
    }
    for (const VertexId v : within) EXPECT_TRUE(held.count(v)) << "vertex " << v << " is within the radius";
    EXPECT_GT(within.size(), 3 * thin_run.session->nodes().size());
    EXPECT_GT(thick_bisections, 2 * thin_bisections);
    std::set<test::ShapeSignature> shapes;
    for (const ElementId t : elements(body.mesh)) shapes.insert(test::shape_signature(body.mesh, t));
    EXPECT_LE(shapes.size(), 3u);
    EXPECT_GT(body.session->last_step().axial_force, 0);
    std::printf("radius %.3f: %zu needle nodes (%zu within it), %zu bisections; a line: %zu nodes, %zu bisections\n",
                radius, held.size(), within.size(), thick_bisections, thin_run.session->nodes().size(),
                thin_bisections);
    ASSERT_TRUE(body.session->cancel().ok());
    test::expect_same_state(body.mesh, body.before);
    // relocating with a radius moves the nodes outside it onto its surface, and only those (a
    // radius of a third of h6: the nodes of the faces the tip enters are mostly outside it)
    Options onto = thick;
    onto.radius = line.h_ref / 3;
    onto.relocate = true;
    Insertion moved(cube(), {}, onto);
    std::size_t relocated = 0, refused = 0;
    for (double x = -0.01; x <= end + 1e-12; x += 0.001) {
        auto step = moved.session->move(along_x(x, y, z));
        ASSERT_TRUE(step.ok()) << step.reason();
        relocated += step->relocated;
        refused += step->not_relocated;
    }
    ASSERT_TRUE(moved.mesh.validate({.orientation = true, .flat_is_invalid = true}).ok());
    std::size_t outside = 0, on_surface = 0;
    for (const NeedleNode& node : moved.session->nodes()) {
        const Point& p = moved.mesh.deformed(node.vertex);
        const double off = std::hypot(p[1] - y, p[2] - z);
        EXPECT_NEAR(off, std::hypot(node.perp[1], node.perp[2]), 1e-15) << "node " << node.vertex;
        outside += off > onto.radius * (1 + 1e-12);
        on_surface += std::abs(off - onto.radius) <= 1e-12 * onto.radius;
    }
    EXPECT_GT(relocated, 0u);
    EXPECT_EQ(outside, refused);
    EXPECT_GE(on_surface, relocated - refused);
    Options bad = thick;
    bad.radius = -1;
    Mesh square = slab();
    EXPECT_EQ(NeedleSession::make(square, bad).reason(), "needle: radius -1 is not in [0, 1e+300]");
}

TEST(Needle, WithoutABodyRefinesAndTracksNodesButMovesNothing) {
    Insertion run(slab(), {});
    EXPECT_TRUE(run.session->geometry_only());
    for (double x = -0.01; x <= 0.05; x += 0.001) ASSERT_TRUE(run.session->move(along_x(x, 0.0437)).ok());
    EXPECT_GT(run.session->nodes().size(), 10u);
    for (VertexId v = 0; v < run.mesh.vertex_count(); ++v)
        EXPECT_EQ(run.mesh.deformed(v), run.mesh.reference(v)) << "vertex " << v;
    // the nodes keep their offsets (no relocation), which the tracking reports
    for (const NeedleNode& node : run.session->nodes()) {
        const Point& x = run.mesh.deformed(node.vertex);
        EXPECT_NEAR(node.perp[1], x[1] - 0.0437, 1e-15);
        EXPECT_LE(std::abs(node.perp[1]), 0.1 / 64);
    }
    EXPECT_EQ(run.session->last_step().iterations, 0u);
    expect_right_isosceles(run.mesh);
}

// The application's own journal (issue 48, "one undo"): undoing and redoing a step through it takes
// the needle, its nodes and the bisection's marks with the mesh, and the insertion then goes on as
// if nothing had been undone (a Kuhn cube, geometry only, so that both runs are exact).
TEST(Needle, TheApplicationsUndoAndRedoTakeTheNodesAndTheMarksWithTheMesh) {
    Options options;
    options.h_ref = 0.1 / 32;
    Mesh mesh = cube(), straight = cube();
    EditJournal journal(mesh);
    auto made = NeedleSession::make(mesh, options, nullptr);
    auto reference = NeedleSession::make(straight, options, nullptr);
    ASSERT_TRUE(made.ok() && reference.ok());
    NeedleSession& needle = **made;
    for (double x = -0.01; x <= 0.02 + 1e-12; x += 0.002) {
        ASSERT_TRUE(needle.move(along_x(x, 0.051, 0.049)).ok());
        ASSERT_TRUE((*reference)->move(along_x(x, 0.051, 0.049)).ok());
    }
    const Mesh before = mesh;
    const std::vector<NeedleNode> nodes_before(needle.nodes().begin(), needle.nodes().end());
    const Needle needle_before = *needle.needle();
    ASSERT_TRUE(needle.move(along_x(0.024, 0.051, 0.049)).ok());
    ASSERT_GT(needle.last_step().bisections, 0u) << "the step refines nothing: the test proves nothing";
    const Mesh after = mesh;
    const std::vector<NeedleNode> nodes_after(needle.nodes().begin(), needle.nodes().end());

    ASSERT_TRUE(journal.undo().ok());
    test::expect_same_state(mesh, before);
    EXPECT_EQ(std::vector<NeedleNode>(needle.nodes().begin(), needle.nodes().end()), nodes_before);
    EXPECT_EQ(*needle.needle(), needle_before);
    ASSERT_TRUE(journal.redo().ok());
    test::expect_same_state(mesh, after);
    EXPECT_EQ(std::vector<NeedleNode>(needle.nodes().begin(), needle.nodes().end()), nodes_after);
    ASSERT_TRUE(journal.undo().ok());

    // on from the undone step: the marks are as they were, so the refinement is the same
    for (double x = 0.024; x <= 0.05 + 1e-12; x += 0.002) {
        ASSERT_TRUE(needle.move(along_x(x, 0.051, 0.049)).ok()) << "x = " << x;
        ASSERT_TRUE((*reference)->move(along_x(x, 0.051, 0.049)).ok());
    }
    ASSERT_TRUE(mesh.validate({.orientation = true, .flat_is_invalid = true}).ok());
    test::expect_same_state(mesh, straight);
    EXPECT_EQ(std::vector<NeedleNode>(needle.nodes().begin(), needle.nodes().end()),
              std::vector<NeedleNode>((*reference)->nodes().begin(), (*reference)->nodes().end()));
}

TEST(Needle, RefusesWhatItCannotDoWithTheReason) {
    Mesh surface = *make_gaussian_bell({4, 4}, {1, 1}, 1, 1);
    auto on_surface = NeedleSession::make(surface, {});
    ASSERT_FALSE(on_surface.ok());
    EXPECT_EQ(on_surface.refusal().code, RefusalCode::wrong_dimension);
    EXPECT_EQ(on_surface.reason(),
              "needle: needs a triangle mesh in the plane or a tetrahedral mesh (this one has 2-simplices in 3D)");
    Mesh square = slab();
    Options bad;
    bad.h_ref = 0;
    EXPECT_EQ(NeedleSession::make(square, bad).reason(), "needle: h_ref 0 is not in (0, 1e+300]");
    bad = {};
    bad.friction.static_ratio = 0.5;
    EXPECT_EQ(NeedleSession::make(square, bad).reason(), "needle: friction.static_ratio 0.5 is not in [1, 1e+300]");
    auto session = NeedleSession::make(square, {});
    ASSERT_TRUE(session.ok());
    const Mesh before = square;
    EXPECT_EQ((*session)->move({{0, 0, 0}, {0, 0, 0}}).reason(), "needle: the needle has zero length (base = tip)");
    EXPECT_EQ((*session)->move({{0, 0, 0}, {NAN, 0, 0}}).reason(),
              "needle: a coordinate of the needle is not a finite number");
    EXPECT_EQ((*session)->steps(), 0u);
    test::expect_same_state(square, before);
}

TEST(Needle, TheHostOffersTheNeedle) {
    PluginHost host;
    ASSERT_TRUE(host.add_static(sxk_plugin_entry_needle(), "linked-in needle"));
    Mesh square = slab();
    Options options;
    options.h_ref = 0.003;
    options.relocate = true;
    auto session = host.begin_tool(square, options);
    ASSERT_TRUE(session.ok()) << session.reason();
    // geometry only (no simulation given), and the first step says so
    auto first = (*session)->step(NeedleSession::pose_of(along_x(-0.01, 0.05)));
    ASSERT_TRUE(first.ok()) << first.reason();
    ASSERT_FALSE(first->actions.empty());
    EXPECT_NE(first->actions.front().find("geometry only"), std::string::npos) << first->actions.front();
    ASSERT_TRUE((*session)->step(NeedleSession::pose_of(along_x(0.02, 0.05))).ok());
    EXPECT_GT(square.element_count(), 128u);
    EXPECT_TRUE(square.validate().ok());
    Options wrong;
    wrong.h_ref = -1;
    auto refused = host.begin_tool(square, wrong);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.refusal().code, RefusalCode::bad_argument);
    EXPECT_EQ(refused.reason(), "needle: h_ref -1 is not in (0, 1e+300]");
    wrong = {};
    wrong.friction.static_ratio = 0.5;
    EXPECT_EQ(host.begin_tool(square, wrong).reason(), "needle: friction.static_ratio 0.5 is not in [1, 1e+300]");
}

// With the application's simulation (the elasticity plug-in's) given to the tool, the session solves.
TEST(Needle, TheHostsNeedleSolvesTheApplicationsSimulation) {
    PluginHost host;
    ASSERT_TRUE(host.add_static(sxk_plugin_entry_elasticity(), "linked-in elasticity"));
    ASSERT_TRUE(host.add_static(sxk_plugin_entry_needle(), "linked-in needle"));
    Mesh square = slab();
    const Mesh before = square;
    auto elasticity = host.service<elasticity::ElasticityService>();
    ASSERT_TRUE(elasticity.ok()) << elasticity.reason();
    elasticity::Options slab_body;
    slab_body.fix = {"x>0.0999"};
    slab_body.young = 34e3;
    slab_body.poisson = 0.34;
    slab_body.thickness = 0.01;
    slab_body.tolerance = 0.01;
    auto body = (*elasticity)->simulate(square, slab_body);
    ASSERT_TRUE(body.ok()) << body.reason();
    auto session = host.begin_tool(square, Options{}, {.simulation = body->get()});
    ASSERT_TRUE(session.ok()) << session.reason();
    auto* needle = dynamic_cast<NeedleSession*>(session->get());
    ASSERT_NE(needle, nullptr);
    EXPECT_FALSE(needle->geometry_only());
    std::size_t iterations = 0;
    for (double x = -0.01; x <= 0.03; x += 0.001) {
        ASSERT_TRUE((*session)->step(NeedleSession::pose_of(along_x(x, 0.05))).ok());
        iterations += needle->last_step().iterations;
    }
    EXPECT_GT(iterations, 0u);
    EXPECT_GT(needle->last_step().axial_force, 0);
    ASSERT_TRUE((*session)->cancel().ok());
    test::expect_same_state(square, before);
    slab_body.fix = {"x>7"};
    auto refused = (*elasticity)->simulate(square, slab_body);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "deform: --fix 'x>7' selects no vertex of the mesh");
}

// Seeded random needle paths into slabs and cubes, lines and needles with a radius: every step
// valid (no inverted or flat element in either position set), nodes on the needle, and undoing
// everything gives the start back.
TEST(Needle, RandomNeedlePathsNeverBreakTheMesh) {
    const char* replay = std::getenv("SXK_SEED");
    const unsigned seed = replay ? static_cast<unsigned>(std::atol(replay)) : 20261205u;
    std::printf("seed %u\n", seed);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    std::size_t steps = 0;
    for (int run_index = 0; steps < 10000; ++run_index) {
        const bool solid = run_index % 5 == 4;
        SCOPED_TRACE("run " + std::to_string(run_index) + " of seed " + std::to_string(seed));
        Options options;
        options.h_ref = (solid ? 0.1 / 16 : 0.1 / 64) * (0.5 + unit(random));
        options.relocate = unit(random) < 0.3;
        options.friction.shaft = 5 + 40 * unit(random);
        if (unit(random) < 0.3) {
            options.local_vertices = 20 + static_cast<std::size_t>(300 * unit(random));
            if (unit(random) < 0.5) options.far_vertices = 20 + static_cast<std::size_t>(300 * unit(random));
        }
        if (unit(random) < 0.3) options.radius = options.h_ref * 2 * unit(random);
        Insertion run(solid ? cube() : slab(), solid ? cube_body : slab_body, options);
        // a wandering needle: enters from the left, turns, advances and withdraws at random
        Eigen::Vector3d tip(-0.01, 0.02 + 0.06 * unit(random), solid ? 0.02 + 0.06 * unit(random) : 0.0);
        double angle = 0.4 * (unit(random) - 0.5), lift = solid ? 0.4 * (unit(random) - 0.5) : 0.0;
        const int moves = solid ? 60 : 400;
        for (int k = 0; k < moves; ++k, ++steps) {
            angle += 0.03 * (unit(random) - 0.5);
            lift += solid ? 0.03 * (unit(random) - 0.5) : 0.0;
            const Eigen::Vector3d axis =
                Eigen::Vector3d(std::cos(angle) * std::cos(lift), std::sin(angle) * std::cos(lift), std::sin(lift));
            const double advance = (unit(random) < 0.8 ? 1 : -1.5) * 0.002 * unit(random);
            tip += advance * axis;
            const Eigen::Vector3d base = tip - 0.1 * axis;
            // now and then the needle rests and the body settles
            auto step = k > 0 && unit(random) < 0.02
                            ? run.session->settle(1000)
                            : run.session->move({{base[0], base[1], base[2]}, {tip[0], tip[1], tip[2]}});
            ASSERT_TRUE(step.ok()) << "move " << k << ": " << step.reason();
            const auto valid = run.mesh.validate({.orientation = true, .flat_is_invalid = true});
            ASSERT_TRUE(valid.ok()) << "move " << k << ": " << valid.reason();
            if (step->shown) expect_nodes_on_needle(run);
        }
        ASSERT_TRUE(run.session->cancel().ok());
        test::expect_same_state(run.mesh, run.before);
    }
    std::printf("%zu needle movements\n", steps);
}

}  // namespace
}  // namespace sxk::needle
