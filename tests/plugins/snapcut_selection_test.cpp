// Face selection of the snap cut (plugins/snapcut/face_selection.hpp, thesis §3.2.1), on the
// 2 x 2 x 2 Kuhn cube (snapcut_fixture.hpp: kuhn2_vertex(i, j, k)).
#include <gtest/gtest.h>

#include <algorithm>

#include "face_selection.hpp"
#include "snapcut_fixture.hpp"
#include "sxk/generators.hpp"
#include "sxk/traversal.hpp"

namespace sxk::test {
namespace {

using snapcut::CutMarks;
using snapcut::Selection;

Selection select_plane(const Mesh& mesh, CutMarks& marks, double c) {
    const std::uint32_t sweep = marks.add_sweep(plane_x(c));
    return select_faces(mesh, marks, sweep, all_elements(mesh));
}

// The faces of the plane x = 1 (all interior): 2 x 2 squares of 2 triangles.
void expect_the_faces_of_x_equals_1(const Mesh& mesh, const Selection& selection) {
    ASSERT_EQ(selection.faces.size(), 8u);
    for (const auto& face : selection.faces)
        for (int j = 0; j < 3; ++j) EXPECT_EQ(mesh.reference(face.face.vertex(j))[0], 1.0);
}

TEST(SnapCutSelection, EachCrossedEdgeMarksItsEndNearerTheCrossing) {
    const Mesh mesh = make_kuhn_cube(2).value();
    CutMarks marks;
    const Selection selection = select_plane(mesh, marks, 1.3);
    // the edges from x = 1 to x = 2: (1,j,k)-(2,j',k') with j' - j, k' - k in {0, 1}
    EXPECT_EQ(selection.edges_hit, marks.mark_count());
    EXPECT_GT(selection.edges_hit, 0u);
    const auto mark = marks.mark(kuhn2_vertex(1, 0, 0), kuhn2_vertex(2, 0, 0));
    ASSERT_TRUE(mark);
    EXPECT_EQ(mark->node, kuhn2_vertex(1, 0, 0));
    EXPECT_EQ(mark->sweep, 0u);
    EXPECT_FALSE(marks.mark(kuhn2_vertex(0, 0, 0), kuhn2_vertex(1, 0, 0)));  // x from 0 to 1 does not reach 1.3
    expect_the_faces_of_x_equals_1(mesh, selection);
}

TEST(SnapCutSelection, AnExactHalfMarksTheLowerVertexId) {
    // x = 1.5 halves every edge from x = 1 to x = 2 exactly; the lower id is the x = 1 end
    const Mesh mesh = make_kuhn_cube(2).value();
    CutMarks marks;
    const Selection selection = select_plane(mesh, marks, 1.5);
    EXPECT_EQ(marks.mark(kuhn2_vertex(1, 1, 1), kuhn2_vertex(2, 2, 2))->node, kuhn2_vertex(1, 1, 1));
    expect_the_faces_of_x_equals_1(mesh, selection);
}

TEST(SnapCutSelection, OnlyTheFirstCrossingOfAnEdgeCounts) {
    const Mesh mesh = make_kuhn_cube(2).value();
    CutMarks marks;
    (void)select_plane(mesh, marks, 1.7);  // marks the x = 2 ends
    const std::size_t marked = marks.mark_count();
    const Selection again = select_plane(mesh, marks, 1.3);  // would mark the x = 1 ends
    EXPECT_EQ(again.edges_hit, 0u);
    EXPECT_EQ(marks.mark_count(), marked);
    EXPECT_EQ(marks.mark(kuhn2_vertex(1, 0, 0), kuhn2_vertex(2, 0, 0))->node, kuhn2_vertex(2, 0, 0));
    EXPECT_EQ(marks.mark(kuhn2_vertex(1, 0, 0), kuhn2_vertex(2, 0, 0))->sweep, 0u);
    // the x = 2 faces are on the boundary: nothing to open, nothing selected
    EXPECT_TRUE(again.faces.empty());
}

TEST(SnapCutSelection, FourMarkedCornersSelectTheFaceWithoutTheHighestId) {
    const Mesh mesh = make_kuhn_cube(2).value();
    const ElementId inner = interior_element(mesh);  // a tetrahedron whose four faces are interior
    ASSERT_NE(inner, invalid_id);
    const Simplex s = mesh.simplex(inner);
    CutMarks marks;
    const std::uint32_t far = marks.add_sweep({{10, 10, 10}, {11, 10, 10}, {10, 11, 10}});
    // marks of earlier sweeps on the tetrahedron's edges: each corner marked by some edge
    marks.add_mark(s.vertex(0), s.vertex(1), {s.vertex(0), far});
    marks.add_mark(s.vertex(1), s.vertex(2), {s.vertex(1), far});
    marks.add_mark(s.vertex(2), s.vertex(3), {s.vertex(2), far});
    marks.add_mark(s.vertex(0), s.vertex(3), {s.vertex(3), far});
    const std::vector<ElementId> candidates{inner};
    const Selection selection = select_faces(mesh, marks, far, candidates);
    ASSERT_EQ(selection.faces.size(), 1u);
    EXPECT_EQ(selection.faces[0].face, Simplex(+1, {s.vertex(0), s.vertex(1), s.vertex(2)}));
    EXPECT_EQ(selection.edges_hit, 0u);
}

// A face whose three corners were snapped from other tetrahedra's edges, between two tetrahedra
// no sweep crosses, is selected from them (face_selection.hpp, "Corners snapped elsewhere"); with
// two snapped corners it is not, nor by a tetrahedron with all four snapped (which face would be
// the cut's?): the tetrahedron across then selects it.
TEST(SnapCutSelection, ThreeCornersSnappedElsewhereSelectTheirFaceWithoutAMark) {
    const Mesh mesh = make_kuhn_cube(2).value();
    const ElementId inner = interior_element(mesh);
    ASSERT_NE(inner, invalid_id);
    const Simplex s = mesh.simplex(inner);
    const ElementId across = mesh.neighbor(inner, 3);  // across the face without s.vertex(3)
    const std::vector<ElementId> both{std::min(inner, across), std::max(inner, across)};
    const auto select_with_snapped = [&](std::initializer_list<VertexId> snapped,
                                         const std::vector<ElementId>& candidates) {
        CutMarks marks;
        const std::uint32_t far = marks.add_sweep({{10, 10, 10}, {11, 10, 10}, {10, 11, 10}});
        for (const VertexId v : snapped) marks.add_snapped(mesh, v, mesh.deformed(v));
        const Selection selection = select_faces(mesh, marks, far, candidates);
        EXPECT_EQ(selection.edges_hit, 0u);
        EXPECT_EQ(marks.mark_count(), 0u);
        return selection;
    };
    const Simplex face(+1, {s.vertex(0), s.vertex(1), s.vertex(2)});
    for (const auto& candidates : {both, std::vector<ElementId>{inner}, std::vector<ElementId>{across}}) {
        const Selection three = select_with_snapped({s.vertex(0), s.vertex(1), s.vertex(2)}, candidates);
        ASSERT_EQ(three.faces.size(), 1u);
        EXPECT_EQ(three.faces[0].face, face);
    }
    EXPECT_TRUE(select_with_snapped({s.vertex(0), s.vertex(1)}, both).faces.empty());
    const std::initializer_list<VertexId> all_four{s.vertex(0), s.vertex(1), s.vertex(2), s.vertex(3)};
    EXPECT_TRUE(select_with_snapped(all_four, {inner}).faces.empty());
    const Selection from_across = select_with_snapped(all_four, {across});
    ASSERT_EQ(from_across.faces.size(), 1u);
    EXPECT_EQ(from_across.faces[0].face, face);
}

TEST(SnapCutSelection, TetrahedraWithOneOrTwoMarkedCornersAreIncomplete) {
    const Mesh mesh = make_kuhn_cube(2).value();
    CutMarks marks;
    // a sweep that stops halfway up: x = 1.3 for z below 1 only
    const std::uint32_t sweep = marks.add_sweep({{1.3, -1, -1}, {1.3, 5, -1}, {1.3, 2, 1}});
    const Selection selection = select_faces(mesh, marks, sweep, all_elements(mesh));
    EXPECT_FALSE(marks.incomplete().empty());
    for (const ElementId t : marks.incomplete()) {
        const Simplex s = mesh.simplex(t);
        int marked = 0;
        for (int i = 0; i < 4; ++i) {
            bool is_marked = false;
            for (int j = 0; j < 4; ++j)
                if (i != j) {
                    const auto mark = marks.mark(s.vertex(i), s.vertex(j));
                    is_marked = is_marked || (mark && mark->node == s.vertex(i));
                }
            marked += is_marked;
        }
        EXPECT_TRUE(marked == 1 || marked == 2) << "element " << t << ": " << marked;
    }
    EXPECT_LT(selection.faces.size(), 8u);
}

// CutMarks as a side log (sxk/side_log.hpp): a rollback to a mark takes back what came after it;
// a committed step's record undoes it and redoes it again.
TEST(SnapCutSelection, AMarkTakesBackWhatCameAfterItAndARecordRedoesIt) {
    const Mesh mesh = make_kuhn_cube(2).value();
    auto first_cut = [&](CutMarks& marks) {
        (void)select_plane(mesh, marks, 1.3);
        marks.add_snapped(mesh, kuhn2_vertex(1, 1, 1), mesh.deformed(kuhn2_vertex(1, 1, 1)));
    };
    auto second_cut = [&](CutMarks& marks) {
        (void)select_plane(mesh, marks, 0.4);
        marks.add_snapped(mesh, kuhn2_vertex(0, 1, 1), mesh.deformed(kuhn2_vertex(0, 1, 1)));
    };
    // the state after the first cut, and after both
    CutMarks both;
    first_cut(both);
    const std::size_t marked = both.mark_count();
    const std::vector<ElementId> incomplete = both.incomplete();
    second_cut(both);
    ASSERT_GT(both.mark_count(), marked);
    auto expect_first_cut_only = [&](const CutMarks& marks) {
        EXPECT_EQ(marks.mark_count(), marked);
        EXPECT_EQ(marks.sweeps().size(), 1u);
        EXPECT_EQ(marks.incomplete(), incomplete);
        EXPECT_TRUE(marks.snapped(kuhn2_vertex(1, 1, 1)));
        EXPECT_FALSE(marks.snapped(kuhn2_vertex(0, 1, 1)));
        EXPECT_FALSE(marks.mark(kuhn2_vertex(0, 0, 0), kuhn2_vertex(1, 0, 0)));
    };
    auto expect_both_cuts = [&](const CutMarks& marks) {
        EXPECT_EQ(marks.mark_count(), both.mark_count());
        EXPECT_EQ(marks.sweeps().size(), 2u);
        EXPECT_EQ(marks.incomplete(), both.incomplete());
        EXPECT_TRUE(marks.snapped(kuhn2_vertex(0, 1, 1)));
        for (const ElementId t : elements(mesh)) {
            const Simplex s = mesh.simplex(t);
            for (int i = 0; i < 4; ++i)
                for (int j = i + 1; j < 4; ++j) {
                    const auto a = both.mark(s.vertex(i), s.vertex(j)), b = marks.mark(s.vertex(i), s.vertex(j));
                    ASSERT_EQ(a.has_value(), b.has_value());
                    if (a) {
                        EXPECT_EQ(a->node, b->node);
                        EXPECT_EQ(a->sweep, b->sweep);
                    }
                }
        }
    };

    CutMarks marks;
    first_cut(marks);
    const std::size_t step = marks.mark();
    second_cut(marks);
    marks.rollback_to(step);
    expect_first_cut_only(marks);

    const std::size_t committed = marks.mark();
    second_cut(marks);
    std::unique_ptr<SideRecord> record = marks.commit(committed);
    ASSERT_NE(record, nullptr);
    record = marks.replay(std::move(record));  // undo
    expect_first_cut_only(marks);
    record = marks.replay(std::move(record));  // redo
    expect_both_cuts(marks);
}

}  // namespace
}  // namespace sxk::test
