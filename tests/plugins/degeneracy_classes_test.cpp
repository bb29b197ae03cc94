// Degeneracy removal on drawn fixtures: one flat element of each class (thesis Fig. 3.8) in a
// small valid mesh, removed by the move Fig. 3.9 prescribes; flips and cutting free; triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "core/fixtures.hpp"
#include "remove_degeneracies.hpp"
#include "sxk/predicates.hpp"
#include "sxk/quality.hpp"

namespace sxk::degeneracy {
namespace {

// A tetrahedral mesh of the given points and vertex quadruples, each oriented positive (two
// vertices swapped when orient3d says negative).
Mesh tetrahedra(const std::vector<Point>& points, const std::vector<std::array<VertexId, 4>>& tets) {
    Mesh mesh(3, 3);
    for (const Point& p : points) mesh.add_vertex(p);
    std::vector<Simplex> simplexes;
    for (auto tet : tets) {
        if (orient3d(points[tet[0]], points[tet[1]], points[tet[2]], points[tet[3]]) == Sign::negative)
            std::swap(tet[2], tet[3]);
        simplexes.push_back(Simplex(+1, tet));
    }
    EXPECT_TRUE(mesh.assign_elements(simplexes).ok());
    return mesh;
}

Mesh triangles(const std::vector<Point>& points, const std::vector<std::array<VertexId, 3>>& tris) {
    Mesh mesh(2, 2);
    for (const Point& p : points) mesh.add_vertex(p);
    std::vector<Simplex> simplexes;
    for (auto tri : tris) {
        if (orient2d(points[tri[0]], points[tri[1]], points[tri[2]]) == Sign::negative) std::swap(tri[1], tri[2]);
        simplexes.push_back(Simplex(+1, tri));
    }
    EXPECT_TRUE(mesh.assign_elements(simplexes).ok());
    return mesh;
}

// What every successful removal must leave: a valid mesh, every element strictly positive in
// both position sets, none degenerate.
void expect_clean(const Mesh& mesh, const Options& options = {}) {
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    for (const ElementId t : elements(mesh)) {
        EXPECT_EQ(element_orientation(mesh, t, Positions::reference), Sign::positive) << "element " << t;
        EXPECT_EQ(element_orientation(mesh, t, Positions::deformed), Sign::positive) << "element " << t;
        EXPECT_EQ(classify(mesh, t, options), DegenerateClass::none) << "element " << t;
    }
}

std::size_t degenerates(const Mesh& mesh, const Options& options = {}) {
    std::size_t n = 0;
    for (const ElementId t : elements(mesh)) n += classify(mesh, t, options) != DegenerateClass::none;
    return n;
}

std::size_t found(const Report& report, DegenerateClass c) {
    return report.passes.front().found[static_cast<std::size_t>(c)];
}

// Cap: d just above the middle of abc, under a roof of three tetrahedra to apex p; q below.
//            p
//          / | \          abcd: the cap (large angles at da, db, dc)
//        a - d - b        dabp, dbcp, dcap: the roof; abcq: the floor
//          \ | /
//            q
Mesh cap_fixture() {
    return tetrahedra({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 1e-3}, {0.3, 0.3, 1}, {0.3, 0.3, -1}},
                      {{0, 1, 2, 3}, {3, 0, 1, 4}, {3, 1, 2, 4}, {3, 2, 0, 4}, {0, 1, 2, 5}});
}

// Sliver: a, b at height +e, c, d at -e; ab and cd cross above (0.5, 0.5); p above, q below.
Mesh sliver_fixture() {
    const double e = 1e-3;
    return tetrahedra({{0, 0, e}, {1, 1, e}, {1, 0, -e}, {0, 1, -e}, {0.5, 0.5, 1}, {0.5, 0.5, -1}},
                      {{0, 1, 2, 3}, {0, 1, 2, 4}, {0, 1, 3, 4}, {2, 3, 0, 5}, {2, 3, 1, 5}});
}

// Spindle: c just off the middle of ab (height e over the plane abd); abc is on the boundary
// (any tetrahedron on the other side of the flat triangle abc would be flat too).
Mesh spindle_fixture() {
    return tetrahedra({{-1, 0, 0}, {1, 0, 0}, {0, 0, 4e-3}, {0, 1, 0}, {0, 0.4, -1}, {-0.8, 0.6, 0.8}, {0.8, 0.6, 0.8}},
                      {{0, 1, 2, 3}, {0, 1, 3, 4}, {0, 2, 3, 5}, {1, 2, 3, 6}});
}

// Needle: a and b 0.005 apart; the edge ab is in the needle only (on the boundary).
Mesh needle_fixture() {
    return tetrahedra({{0, 0, 0}, {5e-3, 0, 0}, {0.5, 1, 0}, {0.4, 0.3, 1}, {-0.8, 0.8, 0.6}, {1, 0.8, 0.6}},
                      {{0, 1, 2, 3}, {0, 2, 3, 4}, {1, 2, 3, 5}});
}

TEST(DegeneracyClasses, FixturesHaveOneDegenerateOfTheirClass) {
    EXPECT_EQ(degenerates(cap_fixture()), 1u);
    EXPECT_EQ(classify(cap_fixture(), 0), DegenerateClass::cap);
    EXPECT_EQ(degenerates(sliver_fixture()), 1u);
    EXPECT_EQ(classify(sliver_fixture(), 0), DegenerateClass::sliver);
    EXPECT_EQ(degenerates(spindle_fixture()), 1u);
    EXPECT_EQ(classify(spindle_fixture(), 0), DegenerateClass::spindle);
    EXPECT_EQ(degenerates(needle_fixture()), 1u);
    EXPECT_EQ(classify(needle_fixture(), 0), DegenerateClass::needle);
}

TEST(DegeneracyClasses, CapSplitsTheOppositeFaceAndCollapses) {
    Mesh mesh = cap_fixture();
    const auto report = remove_degeneracies(mesh);
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_EQ(report->found, 1u);
    EXPECT_EQ(found(*report, DegenerateClass::cap), 1u);
    EXPECT_EQ(report->splits, 1u);
    EXPECT_EQ(report->collapses, 1u);
    EXPECT_EQ(report->flips, 0u);
    EXPECT_EQ(report->cut_free, 0u);
    EXPECT_EQ(report->remaining, 0u);
    // the face split makes 3 + 3 of abcd and abcq; the collapse removes abcd's three
    EXPECT_EQ(report->elements_before, 5u);
    EXPECT_EQ(report->elements_after, 6u);
    EXPECT_EQ(mesh.element_count(), 6u);
    EXPECT_EQ(report->vertices_after, 6u);  // the new vertex merged into d
    expect_clean(mesh);
}

TEST(DegeneracyClasses, SliverSplitsBothEdgesAndCollapses) {
    Mesh mesh = sliver_fixture();
    Options options;
    options.flips = false;  // else the clean 2-3 flip goes first (next test)
    const auto report = remove_degeneracies(mesh, options);
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_EQ(found(*report, DegenerateClass::sliver), 1u);
    EXPECT_EQ(report->splits, 2u);
    EXPECT_EQ(report->collapses, 1u);
    EXPECT_EQ(report->cut_free, 0u);
    EXPECT_EQ(report->remaining, 0u);
    EXPECT_EQ(mesh.element_count(), 8u);  // the four around the new middle vertex, twice
    EXPECT_EQ(report->vertices_after, 7u);
    expect_clean(mesh);
}

TEST(DegeneracyClasses, SliverIsFlippedFirstWhenAFlipIsClean) {
    Mesh mesh = sliver_fixture();
    const auto report = remove_degeneracies(mesh);
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_EQ(found(*report, DegenerateClass::sliver), 1u);
    EXPECT_EQ(report->flips, 1u);
    EXPECT_EQ(report->splits, 0u);
    EXPECT_EQ(report->collapses, 0u);
    EXPECT_EQ(report->remaining, 0u);
    // a 2-3 flip (5 -> 6 elements) or a 3-2 / 4-4 flip (4 or 5): no vertex added
    EXPECT_LE(mesh.element_count(), 6u);
    EXPECT_EQ(mesh.vertex_count(), 6u);
    expect_clean(mesh);
}

TEST(DegeneracyClasses, SpindleSplitsTheOppositeEdgeAndCollapses) {
    Mesh mesh = spindle_fixture();
    const auto report = remove_degeneracies(mesh);
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_EQ(found(*report, DegenerateClass::spindle), 1u);
    EXPECT_EQ(report->splits, 1u);
    EXPECT_EQ(report->collapses, 1u);
    EXPECT_EQ(report->cut_free, 0u);
    EXPECT_EQ(report->remaining, 0u);
    EXPECT_EQ(mesh.element_count(), 4u);  // abcd gone, abdq in two halves
    expect_clean(mesh);
}

TEST(DegeneracyClasses, NeedleCollapsesItsShortestEdge) {
    Mesh mesh = needle_fixture();
    const auto report = remove_degeneracies(mesh);
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_EQ(found(*report, DegenerateClass::needle), 1u);
    EXPECT_EQ(report->splits, 0u);
    EXPECT_EQ(report->collapses, 1u);
    EXPECT_EQ(report->remaining, 0u);
    EXPECT_EQ(mesh.element_count(), 2u);
    EXPECT_EQ(report->vertices_after, 5u);
    expect_clean(mesh);
}

TEST(DegeneracyClasses, ExactBoundaryRefusesTheSpindleAndItIsCutFree) {
    Mesh mesh = spindle_fixture();
    Options options;
    options.boundary_tolerance = 0;  // c is off the plane of the boundary face abq
    options.flips = false;
    const auto report = remove_degeneracies(mesh, options);
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_EQ(report->found, 1u);
    EXPECT_EQ(report->collapses, 0u);
    EXPECT_EQ(report->splits, 0u);  // the split was undone
    EXPECT_EQ(report->cut_free, 1u);
    EXPECT_EQ(report->remaining, 0u);
    EXPECT_EQ(mesh.element_count(), 3u);
    EXPECT_EQ(report->passes.back().kind, PassReport::Kind::cut_free);
    expect_clean(mesh, options);
}

TEST(DegeneracyClasses, WithoutCuttingFreeTheRefusalIsReported) {
    Mesh mesh = spindle_fixture();
    const Mesh before = mesh;
    Options options;
    options.boundary_tolerance = 0;
    options.flips = false;
    options.cut_free = false;
    const auto report = remove_degeneracies(mesh, options);
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_EQ(report->remaining, 1u);
    ASSERT_EQ(report->remaining_reasons.size(), 1u);
    EXPECT_NE(report->remaining_reasons[0].find("would move the boundary"), std::string::npos)
        << report->remaining_reasons[0];
    ASSERT_EQ(report->remaining_codes.size(), 1u);
    EXPECT_EQ(report->remaining_codes[0], RefusalCode::moves_boundary);
    // every try was undone: the same elements, the same vertices in use
    EXPECT_EQ(mesh.element_count(), before.element_count());
    EXPECT_EQ(mesh.vertex_count(), before.vertex_count());
    EXPECT_TRUE(mesh.validate().ok());
    std::vector<Simplex> a, b;
    for (const ElementId t : elements(mesh)) a.push_back(mesh.simplex(t));
    for (const ElementId t : elements(before)) b.push_back(before.simplex(t));
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b);
}

TEST(DegeneracyClasses, BadOptionsAreRefusedWithTheMeshUntouched) {
    Mesh mesh = cap_fixture();
    const Mesh before = mesh;
    Options options;
    options.aspect_ratio = 0;
    auto report = remove_degeneracies(mesh, options);
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.reason(), "remove_degeneracies: aspect_ratio 0 is not in (0, 1)");
    EXPECT_EQ(report.code(), RefusalCode::bad_argument);
    options = {};
    options.large_angle = 1.0;
    report = remove_degeneracies(mesh, options);
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.reason(), "remove_degeneracies: large_angle 1 is not in (pi/2, pi)");
    EXPECT_EQ(report.code(), RefusalCode::bad_argument);
    test::expect_same_state(mesh, before);
}

TEST(DegeneracyClasses, CandidatesLimitTheSearch) {
    Mesh mesh = cap_fixture();
    const std::array<ElementId, 2> floor_and_roof{4, 1};  // not the cap (element 0)
    const auto none = remove_degeneracies(mesh, floor_and_roof);
    ASSERT_TRUE(none.ok());
    EXPECT_EQ(none->found, 0u);
    EXPECT_EQ(mesh.element_count(), 5u);
    const std::array<ElementId, 1> cap{0};
    const auto one = remove_degeneracies(mesh, cap);
    ASSERT_TRUE(one.ok());
    EXPECT_EQ(one->found, 1u);
    EXPECT_EQ(one->remaining, 0u);
    expect_clean(mesh);
}

// Triangles: a cap (v just above the middle of ab) with room to flip, and one on the boundary.
TEST(DegeneracyClasses, FlatTriangleIsFlippedWhenBothNewTrianglesAreFine) {
    Mesh mesh = triangles({{0, 0, 0}, {2, 0, 0}, {1, 1e-3, 0}, {1, -1, 0}, {1, 1, 0}},
                          {{0, 1, 2}, {0, 3, 1}, {0, 2, 4}, {2, 1, 4}});
    const auto report = remove_degeneracies(mesh);
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_EQ(found(*report, DegenerateClass::cap), 1u);
    EXPECT_EQ(report->flips, 1u);
    EXPECT_EQ(report->collapses, 0u);
    EXPECT_EQ(mesh.element_count(), 4u);
    expect_clean(mesh);
}

TEST(DegeneracyClasses, FlatTriangleOnTheBoundaryIsSplitAndCollapsed) {
    Mesh mesh = triangles({{0, 0, 0}, {2, 0, 0}, {1, 1e-3, 0}, {1, 1, 0}}, {{0, 1, 2}, {0, 2, 3}, {2, 1, 3}});
    const auto report = remove_degeneracies(mesh);
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_EQ(report->splits, 1u);
    EXPECT_EQ(report->collapses, 1u);
    EXPECT_EQ(mesh.element_count(), 2u);
    expect_clean(mesh);
}

TEST(DegeneracyClasses, ShortEdgeTriangleCollapses) {
    // abc has the short boundary edge ab; ace and bfc are fine
    Mesh mesh = triangles({{0, 0, 0}, {1e-3, 0, 0}, {0.5, 1, 0}, {-1, 0.5, 0}, {1, 0.5, 0}},
                          {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}});
    const auto report = remove_degeneracies(mesh);
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_EQ(found(*report, DegenerateClass::needle), 1u);
    EXPECT_EQ(report->collapses, 1u);
    EXPECT_EQ(report->cut_free, 0u);
    EXPECT_EQ(mesh.element_count(), 2u);
    expect_clean(mesh);
}

}  // namespace
}  // namespace sxk::degeneracy
