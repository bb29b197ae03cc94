// snap_to_plane (plugins/degeneracy/snap_to_plane.hpp): the snapped test meshes of degeneracy
// removal, and the thesis' snapped cube (§3.3, Figs. 3.14-3.16) through remove_degeneracies.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/fixtures.hpp"
#include "remove_degeneracies.hpp"
#include "snap_to_plane.hpp"
#include "snapped_cube.hpp"
#include "sxk/generators.hpp"
#include "sxk/predicates.hpp"
#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"

namespace sxk::degeneracy {
namespace {

using test::expect_same_state;

double dot(const Point& a, const Point& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Signed distance of p from the plane, computed here independently of snap_to_plane.
double distance_to(const Plane& plane, const Point& p) {
    const Point d{p[0] - plane.point[0], p[1] - plane.point[1], p[2] - plane.point[2]};
    return dot(d, plane.normal) / std::sqrt(dot(plane.normal, plane.normal));
}

bool all_strictly_positive(const Mesh& mesh) {
    for (const ElementId t : elements(mesh))
        if (element_orientation(mesh, t, Positions::reference) != Sign::positive ||
            element_orientation(mesh, t, Positions::deformed) != Sign::positive)
            return false;
    return true;
}

// Elements whose thesis aspect ratio (reference positions) is below `threshold`.
std::size_t count_below(const Mesh& mesh, double threshold) {
    std::size_t n = 0;
    for (const ElementId t : elements(mesh))
        n += aspect_ratio(element_points(mesh, t, Positions::reference)) < threshold;
    return n;
}

std::string throw_message(auto&& call) {
    try {
        call();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(no std::invalid_argument)";
}

// ---- which vertices move, and where --------------------------------------------------------

// A plane whose normal has no negative component: every Kuhn tetrahedron spans more than
// 2 x 0.4 along it (its path climbs all three axes), so none has all four vertices within reach
// and no move is refused; the moved set is exactly the vertices within 0.4.
TEST(SnapToPlane, MovesExactlyTheVerticesWithinReachOntoThePlane) {
    Mesh mesh = test::kuhn_cube(4);
    const Mesh before = mesh;
    const Plane plane{{2.1, 1.9, 2.05}, {1, 0.8, 0.6}};
    const double reach = 0.4;
    std::vector<VertexId> within;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        if (std::abs(distance_to(plane, mesh.reference(v))) <= reach)
            within.push_back(v);
    ASSERT_GT(within.size(), 10u);

    const SnapReport report = snap_to_plane(mesh, plane, reach);
    EXPECT_EQ(report.moved, within);
    EXPECT_EQ(report.refused, 0u);
    EXPECT_NEAR(report.mean_edge_length, mean_edge_length(before), 1e-15);
    const Point unit{1 / std::sqrt(2.0), 0.8 / std::sqrt(2.0), 0.6 / std::sqrt(2.0)};
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (!std::binary_search(within.begin(), within.end(), v)) {
            EXPECT_EQ(mesh.reference(v), before.reference(v)) << v;
            EXPECT_EQ(mesh.deformed(v), before.deformed(v)) << v;
            continue;
        }
        EXPECT_NEAR(distance_to(plane, mesh.reference(v)), 0, 1e-14) << v;
        // orthogonally: the move is the old distance along the unit normal
        const double d = distance_to(plane, before.reference(v));
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_NEAR(mesh.reference(v)[k], before.reference(v)[k] - d * unit[k], 1e-14) << v;
        EXPECT_EQ(mesh.deformed(v), mesh.reference(v)) << v;  // the same move in both sets
    }
    EXPECT_GT(count_below(mesh, 0.5), 0u);  // it did reshape elements
    EXPECT_TRUE(all_strictly_positive(mesh));
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

// Deformed positions differ from the reference ones (a translated body): the vertices are chosen
// by their reference distance and each set is projected onto the plane.
TEST(SnapToPlane, ProjectsBothPositionSets) {
    Mesh mesh = test::kuhn_cube(3);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Point& r = mesh.reference(v);
        mesh.set_deformed(v, {r[0] + 0.5, r[1] - 0.25, r[2] + 0.1});
    }
    const Mesh before = mesh;
    const Plane plane{{1.5, 1.5, 1.4}, {0.1, 0.2, 1}};
    const double reach = 0.3;
    std::vector<VertexId> within;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        if (std::abs(distance_to(plane, mesh.reference(v))) <= reach)
            within.push_back(v);
    ASSERT_GT(within.size(), 5u);

    const SnapReport report = snap_to_plane(mesh, plane, reach);
    EXPECT_EQ(report.moved, within);
    EXPECT_EQ(report.refused, 0u);
    for (const VertexId v : within) {
        EXPECT_NEAR(distance_to(plane, mesh.reference(v)), 0, 1e-14) << v;
        EXPECT_NEAR(distance_to(plane, mesh.deformed(v)), 0, 1e-14) << v;
        EXPECT_NE(mesh.deformed(v), mesh.reference(v)) << v;
        EXPECT_NE(mesh.deformed(v), before.deformed(v)) << v;
    }
    EXPECT_TRUE(all_strictly_positive(mesh));
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

// ---- refused moves ---------------------------------------------------------------------------

//        0 (0.5, 0.1)            line y = -0.05, reach 0.2: 0 (0.15 away) would land below the
//       / \                      edge 1-2, inverting the triangle: refused. 1 and 2 (0.05 away)
//      1---2   (0,0) (1,0)       move after it, onto the line; the triangle stays positive.
//  - - - - - - -  y = -0.05
TEST(SnapToPlane, RefusesAMoveThatWouldInvertAndCountsIt) {
    Mesh mesh(2, 2);
    mesh.add_vertex({0.5, 0.1, 0});
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({1, 0, 0});
    const std::array<Simplex, 1> triangle{Simplex(+1, {1, 2, 0})};
    ASSERT_TRUE(mesh.assign_elements(triangle).ok());
    ASSERT_TRUE(all_strictly_positive(mesh));

    const SnapReport report = snap_to_plane(mesh, {{0, -0.05, 0}, {0, 1, 0}}, 0.2);
    EXPECT_EQ(report.refused, 1u);
    EXPECT_EQ(report.moved, (std::vector<VertexId>{1, 2}));
    EXPECT_EQ(mesh.reference(0), (Point{0.5, 0.1, 0}));
    EXPECT_EQ(mesh.deformed(0), (Point{0.5, 0.1, 0}));
    EXPECT_EQ(mesh.reference(1), (Point{0, -0.05, 0}));
    EXPECT_EQ(mesh.reference(2), (Point{1, -0.05, 0}));
    EXPECT_TRUE(all_strictly_positive(mesh));
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

//          0 (0.2, 0.2, 0.1)     the plane z = 0 holds 1, 2, 3 exactly (nothing to move) and
//         /|\                    would take 0 onto the base: a flat tetrahedron, refused.
//        3-+-2                   Nothing changes.
//         \|/
//          1 (origin)
TEST(SnapToPlane, RefusesAMoveThatWouldFlattenAndChangesNothing) {
    Mesh mesh(3, 3);
    mesh.add_vertex({0.2, 0.2, 0.1});
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({1, 0, 0});
    mesh.add_vertex({0, 1, 0});
    const std::array<Simplex, 1> tetrahedron{Simplex(+1, {1, 2, 3, 0})};
    ASSERT_TRUE(mesh.assign_elements(tetrahedron).ok());
    ASSERT_TRUE(all_strictly_positive(mesh));
    const Mesh before = mesh;

    const SnapReport report = snap_to_plane(mesh, {{0, 0, 0}, {0, 0, 2}}, 0.5);
    EXPECT_EQ(report.refused, 1u);
    EXPECT_TRUE(report.moved.empty());
    expect_same_state(mesh, before);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

// The same tetrahedron with the plane z = 0.08 and reach 0.05: only 0 is within reach (0.02),
// and its reference move is fine; but its deformed position, 0.1 higher like the whole deformed
// body, would be projected onto z = 0.08, below the deformed base at z = 0.1: inverted in the
// deformed positions, so refused.
TEST(SnapToPlane, RefusesAMoveThatWouldInvertInTheDeformedPositionsOnly) {
    Mesh mesh(3, 3);
    const std::array<Point, 4> points{Point{0.2, 0.2, 0.1}, Point{0, 0, 0}, Point{1, 0, 0},
                                      Point{0, 1, 0}};
    for (const Point& p : points)
        mesh.add_vertex(p, {p[0], p[1], p[2] + 0.1});
    const std::array<Simplex, 1> tetrahedron{Simplex(+1, {1, 2, 3, 0})};
    ASSERT_TRUE(mesh.assign_elements(tetrahedron).ok());
    const Mesh before = mesh;

    const SnapReport refused = snap_to_plane(mesh, {{0, 0, 0.08}, {0, 0, 1}}, 0.05);
    EXPECT_EQ(refused.refused, 1u);
    EXPECT_TRUE(refused.moved.empty());
    expect_same_state(mesh, before);

    // the control: without the deformed offset the same move is made
    Mesh still(3, 3);
    for (const Point& p : points)
        still.add_vertex(p);
    ASSERT_TRUE(still.assign_elements(tetrahedron).ok());
    const SnapReport made = snap_to_plane(still, {{0, 0, 0.08}, {0, 0, 1}}, 0.05);
    EXPECT_EQ(made.refused, 0u);
    EXPECT_EQ(made.moved, (std::vector<VertexId>{0}));
    EXPECT_EQ(still.reference(0)[2], 0.08);
    EXPECT_TRUE(all_strictly_positive(still));
    EXPECT_TRUE(still.validate().ok()) << still.validate().reason();
}

TEST(SnapToPlane, ZeroNormalOrNegativeDistanceThrowsWithTheReasonAndChangesNothing) {
    Mesh mesh = test::kuhn_cube(2);
    const Mesh before = mesh;
    EXPECT_EQ(throw_message([&] {
                  (void)snap_to_plane(mesh, {{1, 1, 1}, {0, 0, 0}}, 0.3);
              }),
              "snap_to_plane: the plane's normal must be finite and not zero");
    EXPECT_EQ(throw_message([&] {
                  (void)snap_to_plane(
                      mesh, {{1, 1, 1}, {std::numeric_limits<double>::quiet_NaN(), 1, 0}}, 0.3);
              }),
              "snap_to_plane: the plane's normal must be finite and not zero");
    EXPECT_EQ(throw_message([&] {
                  (void)snap_to_plane(mesh, {{1, 1, 1}, {0, 0, 1}}, -1);
              }),
              "snap_to_plane: max_distance must be finite and >= 0, not -1");
    expect_same_state(mesh, before);
    // distance 0 is allowed and moves only what lies on the plane already: nothing
    const SnapReport nothing = snap_to_plane(mesh, {{1, 1, 1}, {0, 0, 1}}, 0);
    EXPECT_TRUE(nothing.moved.empty());
    EXPECT_EQ(nothing.refused, 0u);
    expect_same_state(mesh, before);
}

// ---- elements_around -------------------------------------------------------------------------

// kuhn_cube(2): vertex 13 = (1,1,1) is the far corner of cube 0 and the near corner of cube 7
// (6 tetrahedra each: all paths) and a middle corner of the 6 other cubes (2 paths each): 24.
// Vertex 2 = (2,0,0) is corner (1,0,0) of cube 1: the 2 paths that start along x, neither
// containing 13.
TEST(SnapToPlane, ElementsAroundIsTheUnionOfTheStarsSortedWithoutRepeats) {
    Mesh mesh = test::kuhn_cube(2);
    const VertexId lonely = mesh.add_vertex({9, 9, 9});  // in no element
    std::vector<ElementId> star13 = star(mesh, 13);
    std::sort(star13.begin(), star13.end());
    EXPECT_EQ(star13.size(), 24u);
    EXPECT_EQ(elements_around(mesh, {13}), star13);

    std::vector<ElementId> expected = star13;
    for (const ElementId t : star(mesh, 2))
        expected.push_back(t);
    std::sort(expected.begin(), expected.end());
    expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
    EXPECT_EQ(expected.size(), 26u);
    const std::vector<ElementId> around = elements_around(mesh, {13, 2, 13, lonely, 100000});
    EXPECT_EQ(around, expected);
    EXPECT_TRUE(elements_around(mesh, {}).empty());
    EXPECT_TRUE(elements_around(mesh, {lonely}).empty());
}

// ---- the thesis' snapped cube (§3.3, Fig. 3.14: 729 nodes, 3072 tetrahedra) -----------------

void print(const char* name, const Report& report) {
    std::printf(
        "[ figures  ] %s: found %zu, remaining %zu, cut free %zu, peeled %zu, collapses %zu, "
        "splits %zu, "
        "flips %zu, elements %zu -> %zu, vertices %zu -> %zu\n",
        name, report.found, report.remaining, report.cut_free, report.peeled, report.collapses,
        report.splits, report.flips, report.elements_before, report.elements_after,
        report.vertices_before, report.vertices_after);
    for (std::size_t i = 0; i < report.passes.size(); ++i) {
        const PassReport& p = report.passes[i];
        std::printf(
            "[ figures  ]   pass %zu %s: found needle %zu spindle %zu sliver %zu cap %zu "
            "(total %zu); collapses %zu splits %zu flips %zu peeled %zu cut free %zu; "
            "elements %zu -> %zu; min aspect %.3g\n",
            i, to_string(p.kind), p.found[1], p.found[2], p.found[3], p.found[4], p.found_total(),
            p.collapses, p.splits, p.flips, p.peeled, p.cut_free, p.elements_before,
            p.elements_after, p.min_aspect_ratio_after);
    }
    for (std::size_t i = 0; i < report.remaining_reasons.size() && i < 20; ++i)
        std::printf("[ figures  ]   remaining %u: %s\n", report.remaining_elements[i].value(),
                    report.remaining_reasons[i].c_str());
    std::fflush(stdout);
}

// The "done when" on one snapped mesh.
void expect_done(const Mesh& mesh, const Report& report, std::size_t elements_before) {
    EXPECT_GT(report.found, 0u);
    EXPECT_EQ(report.remaining, 0u);
    EXPECT_EQ(count_below(mesh, 0.01), 0u);
    EXPECT_LE(10 * report.cut_free, report.found) << "cut free more than 10% of the degenerates";
    const auto after = static_cast<double>(mesh.element_count());
    EXPECT_LE(std::abs(after - static_cast<double>(elements_before)),
              0.05 * static_cast<double>(elements_before))
        << elements_before << " -> " << mesh.element_count();
    EXPECT_EQ(report.elements_before, elements_before);
    EXPECT_EQ(report.elements_after, mesh.element_count());
    EXPECT_TRUE(all_strictly_positive(mesh));
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

// The snapped cube of snapped_cube.hpp, checked and described. One material, as the thesis'
// cube: the test fixture's kuhn_cube labels its elements by t % 6, six materials whose
// interfaces no flip may move.
Mesh snapped_thesis_cube(SnapReport& snap) {
    Mesh mesh = test::snapped_thesis_cube(snap);
    EXPECT_EQ(mesh.vertex_count(), 729u);
    EXPECT_EQ(mesh.element_count(), 3072u);
    std::printf(
        "[ figures  ] snapped cube: h = %.4f, %zu vertices moved, %zu refused, %zu elements "
        "below aspect ratio 0.01\n",
        snap.mean_edge_length, snap.moved.size(), snap.refused, count_below(mesh, 0.01));
    EXPECT_TRUE(all_strictly_positive(mesh));
    EXPECT_TRUE(mesh.validate().ok());
    return mesh;
}

TEST(DegeneracySnappedCube, RemovesEveryDegenerateOfTheThesisCube) {
    SnapReport snap;
    Mesh mesh = snapped_thesis_cube(snap);
    const std::size_t degenerates = count_below(mesh, 0.01);
    ASSERT_GT(degenerates, 0u);
    const auto removed = remove_degeneracies(mesh);
    ASSERT_TRUE(removed.ok()) << removed.reason();
    print("cube, whole mesh", *removed);
    EXPECT_EQ(removed->found, degenerates);
    expect_done(mesh, *removed, 3072);
}

TEST(DegeneracySnappedCube, CandidatesAroundTheMovedVerticesGiveTheSameFigures) {
    SnapReport snap;
    Mesh whole = snapped_thesis_cube(snap);
    Mesh local = whole;
    const auto by_whole = remove_degeneracies(whole);
    ASSERT_TRUE(by_whole.ok()) << by_whole.reason();
    const std::vector<ElementId> candidates = elements_around(local, snap.moved);
    const auto by_local = remove_degeneracies(local, candidates);
    ASSERT_TRUE(by_local.ok()) << by_local.reason();
    print("cube, candidates", *by_local);
    // the unsnapped cube has no degenerate, so every one lies in the star of a moved vertex
    EXPECT_EQ(by_local->found, by_whole->found);
    ASSERT_FALSE(by_local->passes.empty());
    ASSERT_FALSE(by_whole->passes.empty());
    EXPECT_EQ(by_local->passes[0].found, by_whole->passes[0].found);
    EXPECT_EQ(by_local->cut_free, by_whole->cut_free);
    EXPECT_EQ(by_local->collapses, by_whole->collapses);
    EXPECT_EQ(by_local->splits, by_whole->splits);
    EXPECT_EQ(by_local->flips, by_whole->flips);
    EXPECT_EQ(by_local->peeled, by_whole->peeled);
    EXPECT_EQ(by_local->elements_after, by_whole->elements_after);
    expect_done(local, *by_local, 3072);
}

// A local run stays local whatever the threshold: at aspect ratio 0.41 every element of the Kuhn
// cube counts as degenerate, and the elements the removal made went on its list one after
// another until one step of a snap cut had collapsed the cube's 3072 elements to 1 (issue 47).
// Its edits reach a ring beyond the candidates' corners (in_region in remove_degeneracies.cpp,
// and a move's follow-ups): here the candidates are the star of the cube's middle vertex, as a
// snap cut passes the stars of the nodes it moved, and every element with no corner within two
// rings of the candidates' corners is untouched, the same simplex.
TEST(DegeneracySnappedCube, ALocalRunEditsOnlyAroundItsCandidatesAtAnyThreshold) {
    Mesh mesh = make_kuhn_cube(8).value();
    const VertexId middle = 4 + 9 * 4 + 81 * 4;  // (4, 4, 4): make_kuhn_cube numbers x fastest
    ASSERT_EQ(mesh.reference(middle), (Point{4, 4, 4}));
    const std::vector<ElementId> candidates = elements_around(mesh, {middle});
    std::vector<VertexId> near;  // the candidates' corners, then one ring more, then another
    for (const ElementId t : candidates)
        for (const VertexId v : mesh.simplex(t).vertices()) near.push_back(v);
    for (int ring = 0; ring < 2; ++ring) {
        std::sort(near.begin(), near.end());
        near.erase(std::unique(near.begin(), near.end()), near.end());
        for (const ElementId t : elements_around(mesh, near))
            for (const VertexId v : mesh.simplex(t).vertices()) near.push_back(v);
    }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    std::vector<Simplex> far;
    for (const ElementId t : elements(mesh)) {
        const auto corners = mesh.simplex(t).vertices();
        if (std::none_of(corners.begin(), corners.end(),
                         [&](VertexId v) { return std::binary_search(near.begin(), near.end(), v); }))
            far.push_back(mesh.simplex(t));
    }
    ASSERT_GT(far.size(), 1500u);  // half the cube lies beyond the region
    Options options;
    options.aspect_ratio = 0.41;
    const auto removed = remove_degeneracies(mesh, candidates, options);
    ASSERT_TRUE(removed.ok()) << removed.reason();
    print("Kuhn cube, star of the middle vertex, aspect ratio 0.41", *removed);
    std::vector<Simplex> after;
    for (const ElementId t : elements(mesh)) after.push_back(mesh.simplex(t));
    std::sort(after.begin(), after.end());
    std::size_t kept = 0;
    for (const Simplex& s : far) kept += std::binary_search(after.begin(), after.end(), s);
    EXPECT_EQ(kept, far.size());
    EXPECT_GE(mesh.element_count(), far.size());
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

// The progress a run tells (Options::progress): for every pass but the cut free one, calls with
// done 0, 1, ... below the count of its list, as the pass report gives it. At aspect ratio 0.2
// a sixth of the cube is listed and the passes run on while moves make new degenerates.
TEST(DegeneracySnappedCube, TellsItsProgressPassByPass) {
    SnapReport snap;
    Mesh mesh = snapped_thesis_cube(snap);
    std::vector<Progress> told;
    Options options;
    options.aspect_ratio = 0.2;
    options.progress = [&](const Progress& p) { told.push_back(p); };
    const auto removed = remove_degeneracies(mesh, options);
    ASSERT_TRUE(removed.ok()) << removed.reason();
    print("cube at aspect ratio 0.2, whole mesh", *removed);
    ASSERT_FALSE(told.empty());
    std::size_t pass = 0, expected_done = 0;
    for (const Progress& p : told) {
        ASSERT_GE(p.pass, 1u);
        ASSERT_LE(p.pass, removed->passes.size());
        if (p.pass != pass) {
            EXPECT_GT(p.pass, pass);
            pass = p.pass;
            expected_done = 0;
        }
        const PassReport& report = removed->passes[p.pass - 1];
        EXPECT_EQ(std::string(p.stage), to_string(report.kind)) << "pass " << p.pass;
        EXPECT_EQ(p.listed, report.found_total()) << "pass " << p.pass;
        EXPECT_EQ(p.done, expected_done++) << "pass " << p.pass;
        EXPECT_LT(p.done, p.listed);
    }
    std::size_t passes_with_a_list = 0;
    for (const PassReport& report : removed->passes)
        passes_with_a_list += report.kind != PassReport::Kind::cut_free && report.found_total() > 0;
    std::set<std::size_t> passes_told;
    for (const Progress& p : told) passes_told.insert(p.pass);
    EXPECT_EQ(passes_told.size(), passes_with_a_list);
    expect_done(mesh, *removed, 3072);
}

}  // namespace
}  // namespace sxk::degeneracy
