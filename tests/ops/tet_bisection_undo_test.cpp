// TetBisection's marks beside the mesh (sxk/ops/tet_bisection.hpp, sxk/side_log.hpp): attached to
// the mesh's journal, a rollback, undo or redo of bisections takes the marks with the mesh and
// leaves the state able to bisect, with the same result as never having bisected (both rules a
// tool uses: Maubach on a Kuhn cube, AMP on a general mesh).
#include <gtest/gtest.h>

#include <vector>

#include "core/fixtures.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/generators.hpp"
#include "sxk/io.hpp"
#include "sxk/ops/refine_around_tetrahedra.hpp"
#include "sxk/ops/remove_elements.hpp"
#include "sxk/ops/tet_bisection.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

// Every live element's marking, by element id.
std::vector<TetMarking> markings(const TetBisection& state) {
    std::vector<TetMarking> result(state.mesh().element_capacity());
    for (const ElementId t : elements(state.mesh())) result[t] = state.marking(t);
    return result;
}

void expect_same_markings(const std::vector<TetMarking>& a, const std::vector<TetMarking>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t t = 0; t < a.size(); ++t) {
        EXPECT_EQ(a[t].vertices, b[t].vertices) << "element " << t;
        EXPECT_EQ(a[t].acd_unmarked, b[t].acd_unmarked) << "element " << t;
        EXPECT_EQ(a[t].bcd_unmarked, b[t].bcd_unmarked) << "element " << t;
        EXPECT_EQ(a[t].flagged, b[t].flagged) << "element " << t;
        EXPECT_EQ(a[t].generation, b[t].generation) << "element " << t;
    }
}

// Refines around `a` in one journal step, undoes it, redoes it and undoes it again, then rolls a
// second refinement around `a` back, and refines around `b`: the same as refining around `b`
// alone on a fresh copy. The journal takes the marks with the mesh every time.
void expect_take_back_is_never_having_bisected(const Mesh& start, bool kuhn, const Point& a, const Point& b,
                                               double h) {
    Mesh mesh = start, fresh = start;
    auto state = kuhn ? TetBisection::for_kuhn_mesh(mesh) : TetBisection::with_amp_marking(mesh);
    auto other = kuhn ? TetBisection::for_kuhn_mesh(fresh) : TetBisection::with_amp_marking(fresh);
    ASSERT_TRUE(state.ok() && other.ok());
    EditJournal journal(mesh);
    ASSERT_TRUE(journal.attach(*state).ok());
    const std::vector<TetMarking> before = markings(*state);
    journal.checkpoint();
    auto first = refine_around_tetrahedra(*state, a, h);
    ASSERT_TRUE(first.ok()) << first.reason();
    ASSERT_GT(*first, 0u);
    ASSERT_TRUE(journal.commit().ok());
    const std::vector<TetMarking> after = markings(*state);
    ASSERT_TRUE(journal.undo().ok());
    EXPECT_FALSE(state->is_stale()) << state->stale_reason();
    ASSERT_TRUE(state->check_marking().ok());
    expect_same_markings(markings(*state), before);
    ASSERT_TRUE(journal.redo().ok());
    EXPECT_FALSE(state->is_stale()) << state->stale_reason();
    ASSERT_TRUE(state->check_marking().ok());
    expect_same_markings(markings(*state), after);
    ASSERT_TRUE(journal.undo().ok());
    // a refused step's rollback takes the marks back the same way
    journal.checkpoint();
    ASSERT_TRUE(refine_around_tetrahedra(*state, a, h).ok());
    ASSERT_TRUE(journal.rollback().ok());
    EXPECT_FALSE(state->is_stale()) << state->stale_reason();
    test::expect_same_state(mesh, start);
    expect_same_markings(markings(*state), before);

    auto second = refine_around_tetrahedra(*state, b, h);
    auto reference = refine_around_tetrahedra(*other, b, h);
    ASSERT_TRUE(second.ok() && reference.ok());
    EXPECT_EQ(*second, *reference);
    ASSERT_TRUE(mesh.validate({.orientation = true}).ok());
    test::expect_same_state(mesh, fresh);
    ASSERT_TRUE(state->check_marking().ok());
}

// An edit outside the bisection inside the step makes the state stale; undoing the step takes the
// staleness back with it, and redoing it brings it again.
TEST(TetBisectionTakeBack, AStepThatMadeTheStateStaleIsUndoneToAFreshOne) {
    Mesh mesh = test::kuhn_cube(2);
    auto state = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_TRUE(state.ok());
    EditJournal journal(mesh);
    ASSERT_TRUE(journal.attach(*state).ok());
    journal.checkpoint();
    ASSERT_TRUE(refine_around_tetrahedra(*state, {0.4, 0.6, 1.1}, 0.5).ok());
    const ElementId removed = *elements(mesh).begin();
    ASSERT_TRUE(remove_elements(mesh, std::vector<ElementId>{removed}).ok());
    ASSERT_TRUE(state->is_stale());
    const std::string reason = state->stale_reason();
    ASSERT_TRUE(journal.commit().ok());
    ASSERT_TRUE(journal.undo().ok());
    EXPECT_FALSE(state->is_stale()) << state->stale_reason();
    ASSERT_TRUE(state->check_marking().ok());
    ASSERT_TRUE(journal.redo().ok());
    EXPECT_EQ(state->stale_reason(), reason);
}

TEST(TetBisectionTakeBack, AfterAnUndoOnAKuhnCube) {
    expect_take_back_is_never_having_bisected(test::kuhn_cube(4), true, {1.1, 1.3, 2.2}, {2.9, 1.2, 0.7}, 0.2);
}

TEST(TetBisectionTakeBack, AfterAnUndoWithAmpMarks) {
    const std::vector<Point> points{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {0, 0, 3}, {3, 3, 0}, {3, 0, 3}, {0, 3, 3},
                                    {3, 3, 3}, {1.4, 1.6, 1.3}, {0.7, 2.1, 1.9}, {2.2, 0.8, 2.4}};
    auto mesh = make_delaunay(points);
    ASSERT_TRUE(mesh.ok()) << mesh.reason();
    expect_take_back_is_never_having_bisected(*mesh, false, {1.1, 1.3, 2.2}, {2.5, 1.2, 0.7}, 0.3);
}

}  // namespace
}  // namespace sxk
