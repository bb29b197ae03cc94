// Cut marks that follow the mesh's edits, and crumbs kept attached (plugins/snapcut: CutMarks::
// carry_to_copies, mark_from_earlier_sweeps, keep_crumbs_attached), on the 2 x 2 x 2 Kuhn cube
// (snapcut_fixture.hpp: kuhn2_vertex(i, j, k)).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "face_selection.hpp"
#include "loose_pieces.hpp"
#include "moved_nodes.hpp"
#include "snapcut_fixture.hpp"
#include "sxk/generators.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk::test {
namespace {

using snapcut::CutMarks;

// The interior faces of the plane x = 1.
std::vector<Simplex> faces_of_x_equals_1(const Mesh& mesh) {
    std::set<Simplex> faces;
    for (const ElementId t : elements(mesh))
        for (int i = 0; i < 4; ++i) {
            const FaceId f = mesh.face(t, i);
            if (mesh.mate(f) == invalid_id) continue;
            const Simplex face = mesh.face_simplex(f);
            if (std::all_of(face.vertices().begin(), face.vertices().end(),
                            [&](VertexId v) { return mesh.reference(v)[0] == 1.0; }))
                faces.insert(Simplex(+1, face.vertices()));
        }
    return {faces.begin(), faces.end()};
}

TEST(SnapCutMarks, ADissectionCopyTakesTheMarksOfItsOriginalsEdges) {
    Mesh mesh = make_kuhn_cube(2).value();
    CutMarks marks;
    const std::uint32_t sweep = marks.add_sweep(plane_x(1.3));
    (void)snapcut::select_faces(mesh, marks, sweep, all_elements(mesh));
    const std::size_t before = marks.mark_count();
    const auto dissected = dissect(mesh, faces_of_x_equals_1(mesh));
    ASSERT_TRUE(dissected) << dissected.reason();
    ASSERT_FALSE(dissected->new_vertices.empty());
    expect_valid(mesh);
    marks.carry_to_copies(mesh, dissected->new_vertices);
    // Every edge of the mesh from x = 1 to x = 2 crosses the sweep, copies' edges included, and
    // is marked at its x = 1 end by sweep 0: the copies took their originals' marks over.
    std::size_t crossing = 0;
    for (const ElementId t : elements(mesh)) {
        const Simplex s = mesh.simplex(t);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                const VertexId u = s.vertex(i), v = s.vertex(j);
                if (mesh.reference(u)[0] != 1.0 || mesh.reference(v)[0] != 2.0) continue;
                ++crossing;
                const auto mark = marks.mark(u, v);
                ASSERT_TRUE(mark) << "edge " << u << "-" << v;
                EXPECT_EQ(mark->node, u);
                EXPECT_EQ(mark->sweep, sweep);
            }
    }
    EXPECT_GT(crossing, 0u);
    EXPECT_GT(marks.mark_count(), before) << "no copy on the marked side: the test proves nothing";
    // the elements with carried marks wait for the next selection
    ASSERT_FALSE(marks.pending().empty());
    for (const ElementId t : marks.pending()) EXPECT_TRUE(mesh.is_element(t));
    EXPECT_TRUE(std::is_sorted(marks.pending().begin(), marks.pending().end()));
    // and a rollback to a mark from before takes them back
    CutMarks again;
    const std::size_t empty = again.mark();
    (void)again.add_sweep(plane_x(1.3));
    again.carry_to_copies(mesh, dissected->new_vertices);
    again.rollback_to(empty);
    EXPECT_TRUE(again.pending().empty());
    EXPECT_TRUE(again.sweeps().empty());
}

// A split of an edge from a node the cut snapped makes edges no sweep has seen: the one from the
// snapped node to the new vertex crosses the sweep at the snapped node, and takes the sweep's
// mark; an edge whose nearer end is the new vertex would pull it onto the cut, and stays unmarked.
TEST(SnapCutMarks, NewEdgesTakeTheMarkOfAnEarlierSweepWhenTheirNearerEndIsOnTheCut) {
    Mesh mesh = make_kuhn_cube(2).value();
    CutMarks marks;
    const std::uint32_t sweep = marks.add_sweep(plane_x(1.3));
    (void)marks.add_sweep(plane_x(0.2));  // a later sweep these edges do not cross
    const VertexId v = kuhn2_vertex(1, 1, 1);
    // v snapped onto the sweep's plane, as the cutter does
    const Point was = mesh.deformed(v);
    const Point on_plane{1.3, 1, 1};
    ASSERT_TRUE(mesh.move_vertices(std::span(&v, 1), std::span(&on_plane, 1), PositionSet::both));
    marks.add_snapped(mesh, v, was);
    const auto split = split_edge(mesh, v, kuhn2_vertex(2, 1, 1));  // m at x = 1.65
    ASSERT_TRUE(split) << split.reason();
    const VertexId m = split->vertex;
    marks.mark_from_earlier_sweeps(mesh, split->elements);
    const auto mark = marks.mark(v, m);
    ASSERT_TRUE(mark);
    EXPECT_EQ(mark->node, v);
    EXPECT_EQ(mark->sweep, sweep);
    EXPECT_FALSE(marks.mark(m, kuhn2_vertex(2, 1, 1)));  // 1.65 to 2: beside both sweeps
    // m's edges to the x = 1 nodes other than v cross x = 1.3 nearer m: not marked
    for (const VertexId w : {kuhn2_vertex(1, 0, 1), kuhn2_vertex(1, 1, 0), kuhn2_vertex(1, 0, 0)})
        if (marks.mark(m, w)) ADD_FAILURE() << "edge " << m << "-" << w << " marked";
    // every mark this made is at v (its edges touch the plane there), and the elements around
    // the marked edges, v-m's among them, wait for the next selection
    for (const ElementId t : marks.pending()) EXPECT_TRUE(mesh.simplex(t).contains(v)) << "element " << t;
    for (const ElementId t : star(mesh, v)) {
        if (!mesh.simplex(t).contains(m)) continue;
        EXPECT_TRUE(std::binary_search(marks.pending().begin(), marks.pending().end(), t)) << "element " << t;
    }
    expect_valid(mesh);
}

TEST(SnapCutCrumbs, ATetrahedronTheCutWouldCloseOffKeepsItsLowestFaceClosed) {
    const Mesh mesh = make_kuhn_cube(2).value();
    // an element at the cube's centre with all four faces interior
    const ElementId inner = interior_element(mesh);
    ASSERT_NE(inner, invalid_id);
    std::vector<Simplex> faces;
    for (int i = 0; i < 4; ++i) faces.push_back(Simplex(+1, mesh.face_simplex(mesh.face(inner, i)).vertices()));
    std::sort(faces.begin(), faces.end());
    const auto kept = snapcut::keep_crumbs_attached(mesh, faces, 4);
    EXPECT_EQ(kept, std::vector<Simplex>(faces.begin() + 1, faces.end()));
    // 0: any piece may come loose
    EXPECT_EQ(snapcut::keep_crumbs_attached(mesh, faces, 0), faces);
    // the faces of x = 1 halve the cube: two pieces of 24, no crumb
    const std::vector<Simplex> plane = faces_of_x_equals_1(mesh);
    EXPECT_EQ(snapcut::keep_crumbs_attached(mesh, plane, 4), plane);
    // and a half is a crumb when crumbs may be that large: one face of the plane stays closed
    EXPECT_EQ(snapcut::keep_crumbs_attached(mesh, plane, 24).size(), plane.size() - 1);
}

// A piece made only of elements whose corners are all snapped is a film along the incision: kept
// attached up to snapcut::largest_layer elements, whatever its count against the crumb's. The
// half x <= 1 of the 2 x 2 x 2 Kuhn cube (24 elements) with every corner snapped stands for one.
TEST(SnapCutCrumbs, APieceFlatAlongTheCutKeepsAFaceClosedAtAnySizeUpToTheLayerLimit) {
    const Mesh mesh = make_kuhn_cube(2).value();
    const std::vector<Simplex> plane = faces_of_x_equals_1(mesh);
    snapcut::CutMarks marks;
    VertexId last_inner = invalid_id;  // a node of the half off the plane
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.deformed(v)[0] > 1) continue;
        marks.add_snapped(mesh, v, mesh.deformed(v));
        if (mesh.deformed(v)[0] < 1) last_inner = v;
    }
    static_assert(snapcut::largest_layer >= 24);
    const auto kept = snapcut::keep_crumbs_attached(mesh, plane, 4, &marks);
    ASSERT_EQ(kept.size(), plane.size() - 1);
    EXPECT_EQ(kept, std::vector<Simplex>(plane.begin() + 1, plane.end()));  // the lowest face stays closed
    // the other half has corners off the cut: no layer, and with the marks alone nothing changes
    EXPECT_EQ(snapcut::keep_crumbs_attached(mesh, plane, 0, &marks), plane);
    // one corner of the half not on the cut: a piece of 24 like any other
    snapcut::CutMarks all_but_one;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        if (mesh.deformed(v)[0] <= 1 && v != last_inner) all_but_one.add_snapped(mesh, v, mesh.deformed(v));
    EXPECT_EQ(snapcut::keep_crumbs_attached(mesh, plane, 4, &all_but_one), plane);
}

// CutMarks::elements_near hands the selection every element with a snapped corner that meets the
// sweep as the selection sees it (where its snapped corners were), whatever else it leaves out:
// its planes in doubles part only elements that are apart from the sweep. Random sweeps through a
// 6 x 6 x 6 Kuhn cube whose nodes were snapped from random places up to a fifth of an edge away,
// slivers as thin as a haptic step's among them, checked against the exact test of every element
// around a snapped node.
TEST(SnapCutMarks, ElementsNearHoldEveryElementWithASnappedCornerThatMeetsTheSweep) {
    const std::uint64_t seed = seed_for("SnapCutMarks.ElementsNearHoldEveryElementWithASnappedCornerThatMeetsTheSweep");
    std::mt19937_64 random(seed);
    const Mesh mesh = make_kuhn_cube(6).value();
    CutMarks marks;
    std::uniform_real_distribution<double> inside(0, 6), nudge(-0.2, 0.2), unit(-1, 1);
    std::bernoulli_distribution snap(0.3);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (!snap(random)) continue;
        const Point& at = mesh.deformed(v);
        marks.add_snapped(mesh, v, Point{at[0] + nudge(random), at[1] + nudge(random), at[2] + nudge(random)});
    }
    // a node snapped after its neighbour moved the neighbour's star as the selection sees it (the
    // cutter snaps a node from where the selection sees it, so there it does not)
    marks.cover_all(mesh);
    std::size_t meeting = 0, handed = 0;
    for (int round = 0; round < 300; ++round) {
        const Point a{inside(random), inside(random), inside(random)};
        const Point b{inside(random), inside(random), inside(random)};
        const double width = std::pow(10.0, -3 * std::uniform_real_distribution<double>(0, 1)(random));
        const Point c{b[0] + width * unit(random), b[1] + width * unit(random), b[2] + width * unit(random)};
        const snapcut::Sweep sweep{a, b, c};
        const std::vector<ElementId> near = marks.elements_near(mesh, sweep);
        handed += near.size();
        // the elements the caller has (every other one here) are left out, and only those
        std::vector<ElementId> known, rest;
        for (std::size_t i = 0; i < near.size(); ++i) (i % 2 == 0 ? known : rest).push_back(near[i]);
        ASSERT_EQ(marks.elements_near(mesh, sweep, known), rest) << "sweep " << round << " (seed " << seed << ")";
        for (const ElementId t : elements(mesh)) {
            const auto corners = mesh.simplex(t).vertices();
            const bool snapped_corner =
                std::any_of(corners.begin(), corners.end(), [&](VertexId v) { return marks.snapped(v); });
            if (!snapped_corner || !snapcut::meets_as_selected(mesh, marks, t, a, b, c)) continue;
            ++meeting;
            ASSERT_TRUE(std::binary_search(near.begin(), near.end(), t))
                << "element " << t << " meets sweep " << round << " but is not near it (seed " << seed << ")";
        }
    }
    EXPECT_GT(meeting, 1000u);  // the sweeps do meet elements around snapped nodes
    EXPECT_LT(handed, 3 * meeting) << "the planes part most of those that do not";
}

// A dissection's copy of a snapped node is recorded with its original's place, so an element with
// both as corners is flat as the selection sees it, yet its edges are edges of the mesh that the
// selection marks when a sweep crosses them: the element meets such a sweep (meets_as_selected)
// and elements_near hands it over. (Asking the index along the blade missed such an edge that
// following the blade marked: tests/plugins/snapcut_track_test.cpp, found on random points.)
TEST(SnapCutMarks, AnElementFlatAsTheSelectionSeesItMeetsASweepThatCrossesOneOfItsEdges) {
    const Mesh mesh = make_kuhn_cube(2).value();
    const ElementId t = *elements(mesh).begin();
    const Simplex s = mesh.simplex(t);
    const VertexId original = s.vertex(0), copy = s.vertex(1), other = s.vertex(2);
    CutMarks marks;
    marks.add_snapped(mesh, original, mesh.deformed(original));
    marks.add_snapped(mesh, copy, marks.selection_position(mesh, original));
    const auto corners = marks.selection_corners(mesh, t);
    ASSERT_EQ(orient3d(corners[0], corners[1], corners[2], corners[3]), Sign::zero);
    // a small triangle square to the edge from `other` to the original's place, about its middle
    const Point& from = mesh.deformed(other);
    const Point& to = marks.selection_position(mesh, original);
    const Point middle{(from[0] + to[0]) / 2, (from[1] + to[1]) / 2, (from[2] + to[2]) / 2};
    const Point along{to[0] - from[0], to[1] - from[1], to[2] - from[2]};
    // two directions square to `along`: crossed with the axis it is least along, then with itself
    const std::size_t least = std::abs(along[0]) <= std::abs(along[1]) && std::abs(along[0]) <= std::abs(along[2])
                                  ? 0
                                  : (std::abs(along[1]) <= std::abs(along[2]) ? 1 : 2);
    Point axis{0, 0, 0};
    axis[least] = 1;
    auto cross = [](const Point& x, const Point& y) {
        return Point{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
    };
    const Point e1 = cross(along, axis), e2 = cross(along, e1);
    const double size = 0.01;
    const snapcut::Sweep sweep{{middle[0] + size * e1[0], middle[1] + size * e1[1], middle[2] + size * e1[2]},
                               {middle[0] + size * e2[0], middle[1] + size * e2[1], middle[2] + size * e2[2]},
                               {middle[0] - size * (e1[0] + e2[0]), middle[1] - size * (e1[1] + e2[1]),
                                middle[2] - size * (e1[2] + e2[2])}};
    ASSERT_TRUE(segment_meets_triangle(from, to, sweep.a, sweep.b, sweep.c));
    EXPECT_FALSE(triangle_meets_tetrahedron(sweep.a, sweep.b, sweep.c, corners[0], corners[1], corners[2], corners[3]))
        << "a flat tetrahedron meets nothing in the kernel's test";
    EXPECT_TRUE(snapcut::meets_as_selected(mesh, marks, t, sweep.a, sweep.b, sweep.c));
    const std::vector<ElementId> near = marks.elements_near(mesh, sweep);
    EXPECT_TRUE(std::binary_search(near.begin(), near.end(), t));
    // moved off the edge (beyond `other`, along it), the sweep crosses none of its edges
    const Point beyond{2 * from[0] - middle[0], 2 * from[1] - middle[1], 2 * from[2] - middle[2]};
    const Point shift{beyond[0] - middle[0], beyond[1] - middle[1], beyond[2] - middle[2]};
    const snapcut::Sweep off{{sweep.a[0] + shift[0], sweep.a[1] + shift[1], sweep.a[2] + shift[2]},
                             {sweep.b[0] + shift[0], sweep.b[1] + shift[1], sweep.b[2] + shift[2]},
                             {sweep.c[0] + shift[0], sweep.c[1] + shift[1], sweep.c[2] + shift[2]}};
    EXPECT_FALSE(snapcut::meets_as_selected(mesh, marks, t, off.a, off.b, off.c));
    expect_valid(mesh);
}

// A dissection's copy of a snapped node is recorded with its original's place, passed as the
// original's selection_position: a reference into the table the record may grow (a copy has the
// highest id). The sanitizer build's fuzz replay found it read after the table moved.
TEST(SnapCutMarks, ACopyTakesItsOriginalsPlaceWhenTheTableGrows) {
    const Mesh mesh = make_kuhn_cube(4).value();  // 125 vertices
    CutMarks marks;
    const Point was{0.25, -0.5, 0.125};
    marks.add_snapped(mesh, 0, was);
    marks.add_snapped(mesh, 124, marks.selection_position(mesh, 0));
    EXPECT_EQ(marks.selection_position(mesh, 124), was);
    EXPECT_EQ(marks.selection_position(mesh, 0), was);
}

// A snapped node's star reaches farther as the selection sees it when a neighbour moves away (a
// simulation frame, the caller's own move): elements_near then misses the elements of the star
// that meet a sweep beyond the node's radius, until the moves widen it (MovedNodes::cover).
TEST(SnapCutMarks, ElementsNearFollowTheNeighboursOfASnappedNodeWhenTheyMove) {
    Mesh mesh = make_kuhn_cube(4).value();  // vertex (i, j, k) is (5 k + j) 5 + i
    const VertexId v = (5 * 2 + 2) * 5 + 2, w = (5 * 3 + 3) * 5 + 3;  // (2, 2, 2) and (3, 3, 3): an edge
    CutMarks marks;
    snapcut::MovedNodes moves(mesh);
    marks.add_snapped(mesh, v, mesh.deformed(v));
    EXPECT_NEAR(marks.radius(v), std::sqrt(3.0), 1e-12);  // the longest edges of the Kuhn cube
    const Point moved{3.4, 3.4, 3.4};
    ASSERT_TRUE(mesh.move_vertices(std::span(&w, 1), std::span(&moved, 1), PositionSet::both));
    // a small triangle square to edge v-w, across it near w: 2.3 from v, beyond the radius
    const double at = 2 + 0.95 * 1.4, size = 0.05;
    const Point e1{size / std::sqrt(2.0), -size / std::sqrt(2.0), 0};
    const Point e2{size / std::sqrt(6.0), size / std::sqrt(6.0), -2 * size / std::sqrt(6.0)};
    const snapcut::Sweep sweep{{at + e1[0], at + e1[1], at + e1[2]},
                               {at + e2[0], at + e2[1], at + e2[2]},
                               {at - e1[0] - e2[0], at - e1[1] - e2[1], at - e1[2] - e2[2]}};
    std::vector<ElementId> meeting;  // the elements of v's star the sweep meets: those at edge v-w
    for (const ElementId t : star(mesh, v))
        if (snapcut::meets_as_selected(mesh, marks, t, sweep.a, sweep.b, sweep.c)) meeting.push_back(t);
    std::sort(meeting.begin(), meeting.end());
    ASSERT_FALSE(meeting.empty());
    EXPECT_TRUE(marks.elements_near(mesh, sweep).empty()) << "the radius before the move does not reach";
    moves.cover(mesh, marks);
    EXPECT_NEAR(marks.radius(v), 1.4 * std::sqrt(3.0), 1e-12);
    EXPECT_EQ(marks.elements_near(mesh, sweep), meeting);
    expect_valid(mesh);
}

}  // namespace
}  // namespace sxk::test
