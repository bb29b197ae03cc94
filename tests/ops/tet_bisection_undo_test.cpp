// TetBisection's take-back (sxk/ops/tet_bisection.hpp): a journal undo or rollback of bisections
// makes the state stale; take_back restores the marks written since and lets it bisect again, with
// the same result as never having bisected (both rules a tool uses: Maubach on a Kuhn cube, AMP on
// a general mesh).
#include <gtest/gtest.h>

#include <vector>

#include "core/fixtures.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/generators.hpp"
#include "sxk/io.hpp"
#include "sxk/ops/refine_around_tetrahedra.hpp"
#include "sxk/ops/tet_bisection.hpp"

namespace sxk {
namespace {

// Refines around `a` in one journal step, undoes it, takes the marks back, then refines around
// `b`; the same as refining around `b` alone on a fresh copy.
void expect_take_back_is_never_having_bisected(const Mesh& start, bool kuhn, const Point& a, const Point& b,
                                               double h) {
    Mesh mesh = start, fresh = start;
    auto state = kuhn ? TetBisection::for_kuhn_mesh(mesh) : TetBisection::with_amp_marking(mesh);
    auto other = kuhn ? TetBisection::for_kuhn_mesh(fresh) : TetBisection::with_amp_marking(fresh);
    ASSERT_TRUE(state.ok() && other.ok());
    EditJournal journal(mesh);
    const std::size_t mark = state->undo_mark();
    journal.checkpoint();
    auto first = refine_around_tetrahedra(*state, a, h);
    ASSERT_TRUE(first.ok()) << first.reason();
    ASSERT_GT(*first, 0u);
    ASSERT_TRUE(journal.commit().ok());
    ASSERT_TRUE(journal.undo().ok());
    EXPECT_TRUE(state->is_stale());
    state->take_back(mark);
    EXPECT_FALSE(state->is_stale());
    ASSERT_TRUE(state->check_marking().ok());
    // a refused step's rollback is taken back the same way
    const std::size_t again = state->undo_mark();
    journal.checkpoint();
    ASSERT_TRUE(refine_around_tetrahedra(*state, a, h).ok());
    ASSERT_TRUE(journal.rollback().ok());
    state->take_back(again);
    test::expect_same_state(mesh, start);

    auto second = refine_around_tetrahedra(*state, b, h);
    auto reference = refine_around_tetrahedra(*other, b, h);
    ASSERT_TRUE(second.ok() && reference.ok());
    EXPECT_EQ(*second, *reference);
    ASSERT_TRUE(mesh.validate({.orientation = true}).ok());
    test::expect_same_state(mesh, fresh);
    ASSERT_TRUE(state->check_marking().ok());
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
