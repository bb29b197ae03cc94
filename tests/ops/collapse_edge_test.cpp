#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <vector>
#include <cstdlib>
#include <iostream>
#include <random>

#include "ops/split_collapse_fixtures.hpp"
#include "sxk/ops/collapse_edge.hpp"
#include "sxk/ops/split_edge.hpp"

namespace sxk {
namespace {

using test::expect_same_state;

// planar_grid(2), vertex id = 3 j + i:
//
//   6 ---- 7 ---- 8          6 ---- 7 ---- 8
//   |    / |    / |          |    /    __/ |     the interior vertex 4 collapses onto the
//   |  /   |  /   |          |  /   __/    |     corner 0 along the diagonal 0-4: the two
//   3 ---- 4 ---- 5   --->   3   __/ ----- 5     triangles <0,1,4>, <0,4,3> vanish, the four
//   |    / |    / |          | _/      __/ |     others of star(4) get 0 for 4
//   |  /   |  /   |          |/     __/    |
//   0 ---- 1 ---- 2          0 ---- 1 ---- 2
TEST(CollapseEdge, InteriorVertexOntoACorner) {
    Mesh mesh = test::planar_grid(2);
    for (ElementId t : elements(mesh)) mesh.set_label(t, static_cast<int>(t) + 10);
    const auto star_labels = [&] {
        std::vector<std::pair<Simplex, int>> expected;
        for (ElementId t : elements(mesh)) {
            const Simplex& tau = mesh.simplex(t);
            if (tau.contains(4) && !tau.contains(0)) expected.emplace_back(tau.substituted(4, 0), mesh.label(t));
        }
        return expected;
    }();
    const auto result = collapse_edge(mesh, 4, 0);
    ASSERT_TRUE(result.ok()) << result.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(*result, 0u);
    EXPECT_EQ(mesh.element_count(), 6u);
    EXPECT_EQ(mesh.vertex_element(4), invalid_id);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    for (const auto& [sigma, label] : star_labels) {
        bool found = false;
        for (ElementId t : elements(mesh))
            if (mesh.simplex(t) == sigma) {
                found = true;
                EXPECT_EQ(mesh.label(t), label);  // survivors keep their label
            }
        EXPECT_TRUE(found) << sigma;
    }
}

// A boundary vertex may slide along the boundary: 1 onto 0 on the bottom edge.
TEST(CollapseEdge, BoundaryVertexAlongTheBoundary) {
    Mesh mesh = test::planar_grid(2);
    const auto result = collapse_edge(mesh, 1, 0);
    ASSERT_TRUE(result.ok()) << result.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.element_count(), 7u);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
}

// Collapse to a point in planar_grid(3) (vertex id = 4 j + i): the interior vertex 5 = (1,1)
// onto its interior neighbour 6 = (2,1), the survivor 6 moved to the midpoint (1.5, 1).
TEST(CollapseEdge, ToAPointMovesTheSurvivor) {
    Mesh mesh = test::planar_grid(3);
    const auto result = collapse_edge(mesh, 5, 6, {1.5, 1, 0}, {1.5, 1, 0});
    ASSERT_TRUE(result.ok()) << result.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(*result, 6u);
    EXPECT_EQ(mesh.reference(6), (Point{1.5, 1, 0}));
    EXPECT_EQ(mesh.deformed(6), (Point{1.5, 1, 0}));
    EXPECT_EQ(mesh.element_count(), 16u);
    EXPECT_TRUE(test::all_strictly_positive(mesh));

    // in planar_grid(2), 5 = (2,1) is on the right side: moving it to (1.5, 1) is refused
    Mesh grid = test::planar_grid(2);
    const Mesh before = grid;
    const auto moved = collapse_edge(grid, 4, 5, {1.5, 1, 0}, {1.5, 1, 0});
    ASSERT_FALSE(moved.ok());
    EXPECT_EQ(moved.reason(), "collapse_edge: boundary face " + test::text(Simplex(+1, {2, 5})) +
                                  " would leave its line in the reference positions: the"
                                  " collapse would move the boundary");
    EXPECT_EQ(moved.code(), RefusalCode::moves_boundary);
    expect_same_state(grid, before);
}

// Thesis Fig. 3.10 in 2D: an annulus around the triangular hole 0,1,2. The vertices 0 and 1
// both see 2 but no triangle holds 0, 1 and 2: collapsing 0-1 would make 0-2 and 1-2 one edge
// and pinch the hole shut (link(0) ∩ link(1) = {2, 3, ...} != link(0-1) = {3, outside}).
//
//                5
//               / \   .
//              / 2 \   .
//             / / \ \   .
//            / /hole\ \   .
//           / 0 ----- 1 \   .
//          3 ----------- 4
TEST(CollapseEdge, RefusesTheLinkConditionViolation) {
    Mesh mesh(2, 2);
    for (const Point& p : {Point{0, 0, 0}, Point{2, 0, 0}, Point{1, 2, 0}, Point{-2, -1, 0},
                           Point{4, -1, 0}, Point{1, 4, 0}})
        mesh.add_vertex(p);
    const std::array<Simplex, 6> annulus{Simplex(+1, {3, 4, 1}), Simplex(+1, {3, 1, 0}),
                                         Simplex(+1, {4, 5, 2}), Simplex(+1, {4, 2, 1}),
                                         Simplex(+1, {5, 3, 0}), Simplex(+1, {5, 0, 2})};
    ASSERT_TRUE(mesh.assign_elements(annulus).ok());
    ASSERT_TRUE(test::all_strictly_positive(mesh));
    const Mesh before = mesh;
    const auto result = collapse_edge(mesh, 0, 1);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "collapse_edge: " + test::text(Simplex(+1, {0, 1})) +
                                   " violates the link condition (the result would not be a manifold)");
    EXPECT_EQ(result.code(), RefusalCode::link_condition);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

// The star of 0 is not convex at 2 (a reflex ring vertex):
//
//       3 (-2,1)         1 (2,1)      collapsing 0 onto 3 turns <0,1,2> into <3,1,2>, which
//          \  ` .   . `  /            runs clockwise: refused, in the reference positions or
//           \    2(0,.2) /            (second case: reference convex, deformed reflex) in the
//            \    |     /             deformed ones
//             \   0    /
//              \  |   /
//                 4 (0,-1)
Mesh reflex_fan(Point reference_2, Point deformed_2) {
    Mesh mesh(2, 2);
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({2, 1, 0});
    mesh.add_vertex(reference_2, deformed_2);
    mesh.add_vertex({-2, 1, 0});
    mesh.add_vertex({0, -1, 0});
    const std::array<Simplex, 4> fan{Simplex(+1, {0, 1, 2}), Simplex(+1, {0, 2, 3}),
                                     Simplex(+1, {0, 3, 4}), Simplex(+1, {0, 4, 1})};
    EXPECT_TRUE(mesh.assign_elements(fan).ok());
    return mesh;
}

TEST(CollapseEdge, RefusesAnInvertingCollapseInEitherPositions) {
    Mesh mesh = reflex_fan({0, 0.2, 0}, {0, 0.2, 0});
    ASSERT_TRUE(test::all_strictly_positive(mesh));
    Mesh before = mesh;
    auto result = collapse_edge(mesh, 0, 3);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "collapse_edge: element " + test::text(Simplex(+1, {3, 1, 2})) +
                                   " would be inverted in the reference positions");
    EXPECT_EQ(result.code(), RefusalCode::would_invert);
    expect_same_state(mesh, before);

    mesh = reflex_fan({0, 2, 0}, {0, 0.2, 0});
    ASSERT_TRUE(test::all_strictly_positive(mesh));
    before = mesh;
    result = collapse_edge(mesh, 0, 3);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "collapse_edge: element " + test::text(Simplex(+1, {3, 1, 2})) +
                                   " would be inverted in the deformed positions");
    EXPECT_EQ(result.code(), RefusalCode::would_invert);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(CollapseEdge, RefusesToMoveTheBoundary) {
    Mesh mesh = test::planar_grid(2);
    const Mesh before = mesh;
    // boundary vertex 1 onto the interior vertex 4 across an interior edge
    auto result = collapse_edge(mesh, 1, 4);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "collapse_edge: " + test::text(Simplex(+1, {1, 4})) +
                                   " is interior but vertex 1 is on the boundary: the collapse"
                                   " would move the boundary");
    EXPECT_EQ(result.code(), RefusalCode::moves_boundary);
    expect_same_state(mesh, before);
    // the corner 0 along the bottom edge onto 1: the left side would tilt
    result = collapse_edge(mesh, 0, 1);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "collapse_edge: boundary face " + test::text(Simplex(+1, {3, 0})) +
                                   " would leave its line in the reference positions: the"
                                   " collapse would move the boundary");
    EXPECT_EQ(result.code(), RefusalCode::moves_boundary);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

// The bottom side 0-1-2 of planar_grid(2) bent by lifting vertex 1 a little: collapsing 1 into
// 2 along it moves the side. Exactly: refused; within a boundary tolerance: done.
TEST(CollapseEdge, BoundaryToleranceAllowsASmallMoveOfTheBoundary) {
    Mesh mesh = test::planar_grid(2);
    const Point p0 = mesh.reference(0), p2 = mesh.reference(2);
    const double lift = 1e-3 * (p2[0] - p0[0]);
    const Point bent{(p0[0] + p2[0]) / 2, p0[1] + lift, 0};
    mesh.set_reference(1, bent);
    mesh.set_deformed(1, bent);
    const Mesh before = mesh;
    auto exact = collapse_edge(mesh, 1, 2);
    ASSERT_FALSE(exact.ok());
    EXPECT_EQ(exact.reason(), "collapse_edge: boundary face " + test::text(Simplex(+1, {0, 1})) +
                                  " would leave its line in the reference positions: the"
                                  " collapse would move the boundary");
    EXPECT_EQ(exact.code(), RefusalCode::moves_boundary);
    expect_same_state(mesh, before);
    // 2 lies about 2 * lift from the line 0-1, whose length is half the side: relative 0.004
    auto too_tight = collapse_edge(mesh, 1, 2, CollapseOptions{0.001});
    ASSERT_FALSE(too_tight.ok());
    expect_same_state(mesh, before);
    auto bad = collapse_edge(mesh, 1, 2, CollapseOptions{-1});
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.reason(), "collapse_edge: boundary tolerance must be in [0, 1)");
    EXPECT_EQ(bad.code(), RefusalCode::bad_argument);
    expect_same_state(mesh, before);
    auto tolerant = collapse_edge(mesh, 1, 2, CollapseOptions{0.01});
    ASSERT_TRUE(tolerant.ok()) << tolerant.reason();
    EXPECT_EQ(mesh.element_count(), 7u);  // the one triangle on the edge 1-2 is gone
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(CollapseEdge, RefusesWhatIsNotAnEdge) {
    Mesh mesh = test::planar_grid(2);
    const Mesh before = mesh;
    auto result = collapse_edge(mesh, 0, 8);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "collapse_edge: " + test::text(Simplex(+1, {0, 8})) + " is not an edge");
    EXPECT_EQ(result.code(), RefusalCode::not_found);
    result = collapse_edge(mesh, 4, 4);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "collapse_edge: the two ends are the same vertex");
    EXPECT_EQ(result.code(), RefusalCode::bad_argument);
    result = collapse_edge(mesh, 4, 99);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "collapse_edge: 99 is not a vertex");
    EXPECT_EQ(result.code(), RefusalCode::not_found);
    expect_same_state(mesh, before);
}

// The centre 13 = (1,1,1) of kuhn_cube(2) onto 1 = (1,0,0): the tetrahedron <0,3,4,13> of
// star(13) keeps its face 0,3,4 in the plane z = 0 and 1 lies in that plane too.
TEST(CollapseEdge, RefusesFlatTetrahedra) {
    Mesh mesh = test::kuhn_cube(2);
    const Mesh before = mesh;
    const auto result = collapse_edge(mesh, 13, 1);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "collapse_edge: element " + test::text(Simplex(-1, {0, 1, 3, 4})) +
                                   " would be flat in the reference positions");
    EXPECT_EQ(result.code(), RefusalCode::would_flatten);
    expect_same_state(mesh, before);
    // while the corner 0 is fine: star(13) is star-shaped around it
    ASSERT_TRUE(collapse_edge(mesh, 13, 0).ok());
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_TRUE(test::all_strictly_positive(mesh));
}

// A boundary vertex of the cube sliding along a cube edge onto the corner.
TEST(CollapseEdge, TetrahedralBoundaryVertexAlongAnEdge) {
    Mesh mesh = test::kuhn_cube(2);
    const auto result = collapse_edge(mesh, 1, 0);
    ASSERT_TRUE(result.ok()) << result.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_TRUE(test::all_strictly_positive(mesh));
}

// Random split_edge / collapse_edge on a planar grid and a Kuhn cube. Oracles: validate() and
// exact positive orientation after every accepted operation, an untouched mesh after every
// refusal. SXK_SEED=<n> replays a run.
void random_splits_and_collapses(Mesh mesh, int operations) {
    std::uint32_t seed = std::random_device{}();
    if (const char* given = std::getenv("SXK_SEED")) seed = static_cast<std::uint32_t>(std::strtoul(given, nullptr, 10));
    std::cout << "random_splits_and_collapses seed " << seed << '\n';
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 random(seed);
    int splits = 0, collapses = 0, refusals = 0;
    for (int step = 0; step < operations; ++step) {
        std::uniform_int_distribution<std::size_t> pick_element(0, mesh.element_capacity() - 1);
        ElementId t = static_cast<ElementId>(pick_element(random));
        while (!mesh.is_element(t)) t = static_cast<ElementId>(pick_element(random));
        std::uniform_int_distribution<int> pick_vertex(0, mesh.element_vertex_count() - 1);
        const int i = pick_vertex(random);
        int j = pick_vertex(random);
        while (j == i) j = pick_vertex(random);
        const VertexId a = mesh.simplex(t).vertex(i), b = mesh.simplex(t).vertex(j);
        const Mesh before = mesh;
        if (random() % 2 == 0) {
            const double where = std::uniform_real_distribution<double>(0.1, 0.9)(random);
            const auto result = split_edge(mesh, a, b, where);
            if (!result.ok()) {
                // only the rounding of the new point can refuse a split of an edge (a child of
                // a nearly flat parent); the mesh must be untouched
                ++refusals;
                EXPECT_NE(result.reason().find(" would be "), std::string::npos) << result.reason();
                EXPECT_TRUE(result.code() == RefusalCode::would_flatten ||
                            result.code() == RefusalCode::would_invert)
                    << to_string(result.code());
                expect_same_state(mesh, before);
                if (::testing::Test::HasFailure()) FAIL() << "step " << step << ": " << result.reason();
                continue;
            }
            ++splits;
        } else {
            const auto result = collapse_edge(mesh, a, b);
            if (!result.ok()) {
                ++refusals;
                expect_same_state(mesh, before);
                if (::testing::Test::HasFailure()) FAIL() << "step " << step << ": " << result.reason();
                continue;
            }
            ++collapses;
        }
        ASSERT_TRUE(mesh.validate().ok()) << "step " << step << ": " << mesh.validate().reason();
        ASSERT_TRUE(test::all_strictly_positive(mesh)) << "step " << step;
    }
    std::cout << splits << " splits, " << collapses << " collapses, " << refusals << " refusals\n";
    EXPECT_GT(collapses, 0);
}

TEST(CollapseEdge, RandomSplitsAndCollapsesOnAPlanarGrid) {
    random_splits_and_collapses(test::planar_grid(6), 2000);
}

TEST(CollapseEdge, RandomSplitsAndCollapsesOnAKuhnCube) {
    random_splits_and_collapses(test::kuhn_cube(3), 2000);
}


// Attributes under collapse: the plain collapse leaves the survivor's values; the collapse to
// the midpoint of the edge averages them (s = 1/2 along the edge), and to a point a quarter
// of the way from `to` takes 3/4 of `to` and 1/4 of `from`. Labels of the re-attached
// triangles are their own (two materials: left column 1, the rest 2).
TEST(CollapseEdge, VertexAttributesFollowTheSurvivor) {
    Mesh mesh = test::planar_grid(3);  // vertex id = 4 j + i
    for (ElementId t : elements(mesh))
        mesh.set_label(t, mesh.simplex(t).contains(0) || mesh.simplex(t).contains(4) ? 1 : 2);
    const AttributeId temperature = *mesh.add_vertex_attribute("temperature", 1);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) mesh.vertex_attribute(temperature, v)[0] = 100.0 + v;
    std::map<std::vector<VertexId>, int> labels_after;  // star(5) without 6, with 5 -> 6
    for (ElementId t : elements(mesh))
        if (mesh.simplex(t).contains(5) && !mesh.simplex(t).contains(6)) {
            std::vector<VertexId> key;
            for (VertexId v : mesh.simplex(t).vertices()) key.push_back(v == 5 ? 6 : v);
            std::sort(key.begin(), key.end());
            labels_after[key] = mesh.label(t);
        }

    Mesh plain = mesh;
    ASSERT_TRUE(collapse_edge(plain, 5, 6).ok());
    ASSERT_TRUE(plain.validate().ok());
    EXPECT_EQ(plain.vertex_attribute(temperature, 6)[0], 106.0);
    EXPECT_EQ(plain.vertex_attribute(temperature, 5)[0], 105.0);

    Mesh midpoint = mesh;
    ASSERT_TRUE(collapse_edge(midpoint, 5, 6, {1.5, 1, 0}, {1.5, 1, 0}).ok());
    ASSERT_TRUE(midpoint.validate().ok()) << midpoint.validate().reason();
    EXPECT_EQ(midpoint.vertex_attribute(temperature, 6)[0], 105.5);
    for (ElementId t : elements(midpoint)) {
        std::vector<VertexId> key(midpoint.simplex(t).vertices().begin(), midpoint.simplex(t).vertices().end());
        std::sort(key.begin(), key.end());
        if (labels_after.count(key)) {
            EXPECT_EQ(midpoint.label(t), labels_after[key]);
        }
    }

    Mesh quarter = mesh;
    ASSERT_TRUE(collapse_edge(quarter, 5, 6, {1.75, 1, 0}, {1.75, 1, 0}).ok());
    EXPECT_EQ(quarter.vertex_attribute(temperature, 6)[0], 0.75 * 106 + 0.25 * 105);
    ASSERT_TRUE(quarter.validate().ok());

    // a refused collapse to a point changes no attribute either
    Mesh refused = mesh;
    ASSERT_FALSE(collapse_edge(refused, 5, 6, {5, 5, 0}, {5, 5, 0}).ok());
    EXPECT_EQ(refused.vertex_attribute(temperature, 6)[0], 106.0);
    expect_same_state(refused, mesh);
}

// Face labels under collapse, planar_grid(2) (vertex id = 3 j + i): 1 slides onto 0 along the
// bottom side. The labelled edge 0-1 vanishes with its label, the labelled 1-2 becomes 0-2.
TEST(CollapseEdge, FaceLabelsFollowTheSurvivor) {
    Mesh mesh = test::planar_grid(2);
    mesh.face_labels()[Simplex(+1, {0, 1})] = 3;
    mesh.face_labels()[Simplex(+1, {1, 2})] = 4;
    mesh.face_labels()[Simplex(+1, {0, 3})] = 5;
    const auto result = collapse_edge(mesh, 1, 0);
    ASSERT_TRUE(result.ok()) << result.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.face_labels(), (FaceLabels{{Simplex(+1, {0, 2}), 4}, {Simplex(+1, {0, 3}), 5}}));
}
}  // namespace
}  // namespace sxk
