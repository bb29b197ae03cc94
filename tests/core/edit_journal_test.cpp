// EditJournal (steps, rollback, undo/redo) and Mesh::move_vertices on hand-made meshes: each
// kind of recorded store, nesting, the refusals with their exact reasons, the id invariant and
// what watchers hear. The random edit sequences are in tests/ops/edit_journal_random_test.cpp.
#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <stdexcept>
#include <vector>

#include "../../fuzz/ops_driver.hpp"
#include "fixtures.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/mesh.hpp"
#include "sxk/generators.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

using ops_driver::snapshot;
using test::MirrorWatcher;

// A flip of the diagonal of the unit square: <0,1,2>,<0,2,3> -> <0,1,3>,<1,2,3>.
Outcome<std::vector<ElementId>> flip_diagonal(Mesh& mesh) {
    const std::array<ElementId, 2> old{0, 1};
    const std::array<Simplex, 2> made{Simplex(+1, {0, 1, 3}), Simplex(+1, {1, 2, 3})};
    return mesh.replace_elements(old, made);
}

TEST(EditJournal, RollbackPutsBackEveryKindOfStore) {
    Mesh mesh = test::unit_square();
    const AttributeId heat = *mesh.add_vertex_attribute("heat", 1);
    mesh.set_face_label(Simplex(+1, {0, 1}), 7);
    const auto before = snapshot(mesh);
    MirrorWatcher mirror;
    mesh.add_watcher(mirror);
    EditJournal journal(mesh);

    journal.checkpoint();
    ASSERT_TRUE(flip_diagonal(mesh).ok());
    const VertexId extra = mesh.add_vertex({2, 2, 0});
    const std::array<VertexId, 1> moved{2};
    const std::array<Point, 1> to{Point{1.5, 1.5, 0}};
    ASSERT_TRUE(mesh.move_vertices(moved, to, PositionSet::both).ok());
    mesh.set_label(0, 4);
    mesh.set_face_label(Simplex(+1, {1, 2}), 9);
    ASSERT_TRUE(mesh.erase_face_label(Simplex(-1, {0, 1})));
    const std::array<double, 1> hot{30.0};
    ASSERT_TRUE(mesh.set_vertex_attribute(heat, 1, hot).ok());
    ASSERT_TRUE(mesh.remove_last_vertex().ok());  // `extra` again
    EXPECT_EQ(mesh.vertex_count(), extra);
    EXPECT_GT(journal.recorded(), 0u);
    ASSERT_TRUE(journal.rollback().ok());

    EXPECT_EQ(journal.depth(), 0u);
    EXPECT_TRUE(snapshot(mesh) == before);
    EXPECT_EQ(mesh.vertex_attribute(heat, 1)[0], 0.0);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    mirror.expect_mirrors(mesh);
    mesh.remove_watcher(mirror);
}

TEST(EditJournal, TheNextEditAfterARollbackHandsOutTheSameIds) {
    Mesh mesh = test::unit_square();
    Mesh twin = mesh;
    EditJournal journal(mesh);
    journal.checkpoint();
    ASSERT_TRUE(flip_diagonal(mesh).ok());
    const std::array<ElementId, 1> gone{0};
    ASSERT_TRUE(mesh.replace_elements(gone, {}).ok());
    ASSERT_TRUE(journal.rollback().ok());
    // free lists and pool sizes are as at the checkpoint: the same edit makes the same ids
    const auto here = flip_diagonal(mesh);
    const auto there = flip_diagonal(twin);
    ASSERT_TRUE(here.ok() && there.ok());
    EXPECT_EQ(*here, *there);
    EXPECT_TRUE(snapshot(mesh) == snapshot(twin));
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(EditJournal, NestedStepsRollBackToTheirOwnCheckpoint) {
    Mesh mesh = test::unit_square();
    EditJournal journal(mesh);
    const auto start = snapshot(mesh);
    journal.checkpoint();
    ASSERT_TRUE(flip_diagonal(mesh).ok());
    const auto flipped = snapshot(mesh);
    journal.checkpoint();
    EXPECT_EQ(journal.depth(), 2u);
    mesh.set_label(0, 5);
    const std::array<VertexId, 1> v{0};
    const std::array<Point, 1> p{Point{-0.5, 0, 0}};
    ASSERT_TRUE(mesh.move_vertices(v, p, PositionSet::deformed).ok());
    ASSERT_TRUE(journal.rollback().ok());  // the inner step only
    EXPECT_TRUE(snapshot(mesh) == flipped);
    journal.checkpoint();
    mesh.set_label(1, 6);
    ASSERT_TRUE(journal.commit().ok());  // the inner step joins the outer one
    ASSERT_TRUE(journal.rollback().ok());
    EXPECT_TRUE(snapshot(mesh) == start);
    EXPECT_TRUE(mesh.validate().ok());
}

// An element or face is recorded once per stretch between checkpoints and rollbacks. What an inner
// step recorded goes with its rollback: the outer step's next store into the same element is
// recorded anew, and the outer rollback takes it back.
TEST(EditJournal, AStoreAfterAnInnerRollbackIsRecordedAgain) {
    Mesh mesh = test::unit_square();
    const int label = mesh.label(0);
    EditJournal journal(mesh);
    const auto start = snapshot(mesh);
    journal.checkpoint();
    journal.checkpoint();
    mesh.set_label(0, 5);
    mesh.set_label(0, 6);  // the same stretch: kept once
    ASSERT_TRUE(journal.rollback().ok());
    EXPECT_EQ(mesh.label(0), label);
    mesh.set_label(0, 7);
    ASSERT_TRUE(journal.rollback().ok());
    EXPECT_EQ(mesh.label(0), label);
    EXPECT_TRUE(snapshot(mesh) == start);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(EditJournal, UndoAndRedoWalkTheCommittedSteps) {
    Mesh mesh = test::unit_square();
    MirrorWatcher mirror;
    mesh.add_watcher(mirror);
    EditJournal journal(mesh);
    const auto s0 = snapshot(mesh);
    journal.checkpoint();
    ASSERT_TRUE(flip_diagonal(mesh).ok());
    ASSERT_TRUE(journal.commit().ok());
    const auto s1 = snapshot(mesh);
    journal.checkpoint();
    const std::array<VertexId, 1> v{2};
    const std::array<Point, 1> p{Point{1.25, 1.5, 0}};
    ASSERT_TRUE(mesh.move_vertices(v, p, PositionSet::reference).ok());
    mesh.set_label(1, 3);
    ASSERT_TRUE(journal.commit().ok());
    const auto s2 = snapshot(mesh);
    EXPECT_EQ(journal.undo_count(), 2u);

    ASSERT_TRUE(journal.undo().ok());
    EXPECT_TRUE(snapshot(mesh) == s1);
    mirror.expect_mirrors(mesh);
    ASSERT_TRUE(journal.undo().ok());
    EXPECT_TRUE(snapshot(mesh) == s0);
    mirror.expect_mirrors(mesh);
    EXPECT_EQ(journal.undo().reason(), "undo: nothing to undo");
    EXPECT_EQ(journal.undo().code(), RefusalCode::not_applicable);
    ASSERT_TRUE(journal.redo().ok());
    EXPECT_TRUE(snapshot(mesh) == s1);
    ASSERT_TRUE(journal.redo().ok());
    EXPECT_TRUE(snapshot(mesh) == s2);
    mirror.expect_mirrors(mesh);
    EXPECT_EQ(journal.redo().reason(), "redo: nothing to redo");
    EXPECT_EQ(journal.redo().code(), RefusalCode::not_applicable);
    // a new step forgets what could be redone
    ASSERT_TRUE(journal.undo().ok());
    journal.checkpoint();
    mesh.set_label(0, 8);
    ASSERT_TRUE(journal.commit().ok());
    EXPECT_EQ(journal.redo_count(), 0u);
    EXPECT_TRUE(mesh.validate().ok());
    mesh.remove_watcher(mirror);
}

// A step whose edits were all rolled back by an inner step records nothing, and the history before
// it still holds (the rollback moved the mesh's revision on, but not the mesh): the next step is
// undone, then the one before it.
TEST(EditJournal, AStepWhoseInnerStepRolledBackKeepsTheHistory) {
    Mesh mesh = test::unit_square();
    EditJournal journal(mesh);
    const auto s0 = snapshot(mesh);
    journal.checkpoint();
    ASSERT_TRUE(flip_diagonal(mesh).ok());
    ASSERT_TRUE(journal.commit().ok());
    const auto s1 = snapshot(mesh);
    journal.checkpoint();
    journal.checkpoint();
    mesh.set_label(1, 5);
    ASSERT_TRUE(journal.rollback().ok());
    ASSERT_TRUE(journal.commit().ok());
    EXPECT_EQ(journal.undo_count(), 1u);
    journal.checkpoint();
    mesh.set_label(0, 7);
    ASSERT_TRUE(journal.commit().ok());
    EXPECT_EQ(journal.undo_count(), 2u);
    ASSERT_TRUE(journal.undo().ok());
    EXPECT_TRUE(snapshot(mesh) == s1);
    ASSERT_TRUE(journal.undo().ok());
    EXPECT_TRUE(snapshot(mesh) == s0);
}

TEST(EditJournal, RefusesWhatItCannotDo) {
    Mesh mesh = test::unit_square();
    EditJournal journal(mesh);
    EXPECT_THROW(EditJournal second(mesh), std::logic_error);
    EXPECT_EQ(journal.commit().reason(), "commit: no step is open");
    EXPECT_EQ(journal.commit().code(), RefusalCode::not_applicable);
    EXPECT_EQ(journal.rollback().reason(), "rollback: no step is open");
    EXPECT_EQ(journal.rollback().code(), RefusalCode::not_applicable);
    journal.checkpoint();
    mesh.set_label(0, 1);
    EXPECT_EQ(journal.undo().reason(), "undo: a step is open");
    EXPECT_EQ(journal.undo().code(), RefusalCode::not_applicable);
    EXPECT_EQ(mesh.add_vertex_attribute("heat", 1).reason(),
              "add_vertex_attribute: not inside an EditJournal step");
    EXPECT_EQ(mesh.add_vertex_attribute("heat", 1).code(), RefusalCode::not_applicable);
    ASSERT_TRUE(journal.commit().ok());
    // a change the journal did not see makes the history unusable, not wrong
    mesh.set_label(0, 2);
    EXPECT_EQ(journal.undo().reason(), "undo: the mesh changed outside the journal since its last step");
    EXPECT_EQ(journal.undo().code(), RefusalCode::stale);
    EXPECT_EQ(mesh.label(0), 2);
}

TEST(EditJournal, AStepThatWasNotCommittedDoesNotHappen) {
    Mesh mesh = test::unit_square();
    const auto before = snapshot(mesh);
    {
        EditJournal journal(mesh);
        journal.checkpoint();
        ASSERT_TRUE(flip_diagonal(mesh).ok());
    }
    EXPECT_TRUE(snapshot(mesh) == before);
    EditJournal again(mesh);  // the first one let go of the mesh
    EXPECT_EQ(again.depth(), 0u);
}

TEST(EditJournal, HistoryLimitDropsTheOldestSteps) {
    Mesh mesh = test::unit_square();
    EditJournal journal(mesh);
    journal.set_history_limit(2);
    for (int label = 1; label <= 3; ++label) {
        journal.checkpoint();
        mesh.set_label(0, label);
        ASSERT_TRUE(journal.commit().ok());
    }
    EXPECT_EQ(journal.undo_count(), 2u);
    ASSERT_TRUE(journal.undo().ok());
    ASSERT_TRUE(journal.undo().ok());
    EXPECT_EQ(mesh.label(0), 1);
    EXPECT_FALSE(journal.undo().ok());
}

TEST(EditJournal, RollbackOfAnOperationInATetrahedralMesh) {
    Mesh mesh = std::move(*make_kuhn_cube(2));
    MirrorWatcher mirror;
    mesh.add_watcher(mirror);
    const auto before = snapshot(mesh);
    EditJournal journal(mesh);
    journal.checkpoint();
    const Simplex& t = mesh.simplex(0);
    ASSERT_TRUE(split_edge(mesh, t.vertex(0), t.vertex(1), 0.5).ok());
    mirror.expect_mirrors(mesh);
    ASSERT_TRUE(journal.rollback().ok());
    EXPECT_TRUE(snapshot(mesh) == before);
    mirror.expect_mirrors(mesh);
    EXPECT_TRUE(mesh.validate().ok());
    mesh.remove_watcher(mirror);
}

// ---- move_vertices ------------------------------------------------------------------------------

TEST(MoveVertices, TellsWatchersOncePerCall) {
    Mesh mesh = test::unit_square();
    MirrorWatcher mirror;
    mesh.add_watcher(mirror);
    const std::array<VertexId, 2> v{1, 3};
    const std::array<Point, 2> p{Point{1.1, 0, 0}, Point{0, 1.1, 0}};
    ASSERT_TRUE(mesh.move_vertices(v, p, PositionSet::deformed).ok());
    EXPECT_EQ(mirror.moves, 1);
    EXPECT_EQ(mesh.deformed(1), (Point{1.1, 0, 0}));
    EXPECT_EQ(mesh.reference(1), (Point{1, 0, 0}));
    mesh.set_reference(0, {0.1, 0.1, 0});  // observed: a watcher is attached
    EXPECT_EQ(mirror.moves, 2);
    ASSERT_TRUE(mesh.move_vertices({}, {}, PositionSet::both).ok());
    EXPECT_EQ(mirror.moves, 2);  // nothing moved, nobody told
    mirror.expect_mirrors(mesh);
    mesh.remove_watcher(mirror);
}

TEST(MoveVertices, RefusesBadArgumentsWithTheReason) {
    Mesh mesh = test::unit_square();
    const auto before = snapshot(mesh);
    const std::array<VertexId, 2> two{0, 0};
    const std::array<Point, 1> one{Point{0, 0, 0}};
    EXPECT_EQ(mesh.move_vertices(two, one, PositionSet::both).reason(), "move_vertices: 2 vertices but 1 points");
    EXPECT_EQ(mesh.move_vertices(two, one, PositionSet::both).code(), RefusalCode::bad_argument);
    const std::array<Point, 2> points{Point{0, 0, 0}, Point{0, 0, 0}};
    EXPECT_EQ(mesh.move_vertices(two, points, PositionSet::both).reason(), "move_vertices: vertex 0 is listed twice");
    EXPECT_EQ(mesh.move_vertices(two, points, PositionSet::both).code(), RefusalCode::bad_argument);
    const std::array<VertexId, 1> unknown{9};
    EXPECT_EQ(mesh.move_vertices(unknown, one, PositionSet::both).reason(), "move_vertices: vertex 9 does not exist");
    EXPECT_EQ(mesh.move_vertices(unknown, one, PositionSet::both).code(), RefusalCode::not_found);
    const std::array<VertexId, 1> v{2};
    const std::array<Point, 1> nan{Point{std::numeric_limits<double>::quiet_NaN(), 0, 0}};
    EXPECT_EQ(mesh.move_vertices(v, nan, PositionSet::both).reason(),
              "move_vertices: the point of vertex 2 is not finite");
    EXPECT_EQ(mesh.move_vertices(v, nan, PositionSet::both).code(), RefusalCode::bad_argument);
    const std::array<Point, 1> lifted{Point{1, 1, 0.5}};
    EXPECT_EQ(mesh.move_vertices(v, lifted, PositionSet::both).reason(),
              "move_vertices: the point of vertex 2 has z != 0 in a planar mesh");
    EXPECT_EQ(mesh.move_vertices(v, lifted, PositionSet::both).code(), RefusalCode::bad_argument);
    EXPECT_TRUE(snapshot(mesh) == before);
}

TEST(MoveVertices, RefusesInversionAndFlatnessOnRequest) {
    Mesh mesh = test::unit_square();  // <0,1,2>, <0,2,3>
    const auto before = snapshot(mesh);
    const std::array<VertexId, 1> v{2};
    // vertex 2 past the line 0-1: <0,1,2> inverts
    const std::array<Point, 1> below{Point{1, -0.5, 0}};
    const MoveCheck check{true, true};
    const auto inverted = mesh.move_vertices(v, below, PositionSet::deformed, check);
    EXPECT_EQ(inverted.reason(), "element 0 would be inverted in the deformed positions");
    EXPECT_EQ(inverted.code(), RefusalCode::would_invert);
    EXPECT_EQ(inverted.refusal().item, 0u);
    // vertex 2 onto the line 0-1: flat
    const std::array<Point, 1> on_line{Point{2, 0, 0}};
    EXPECT_EQ(mesh.move_vertices(v, on_line, PositionSet::reference, check).reason(),
              "element 0 would be flat in the reference positions");
    EXPECT_EQ(mesh.move_vertices(v, on_line, PositionSet::reference, check).code(),
              RefusalCode::would_flatten);
    EXPECT_TRUE(snapshot(mesh) == before);
    // without the check the move is made, and validate names the inversion
    ASSERT_TRUE(mesh.move_vertices(v, below, PositionSet::deformed).ok());
    EXPECT_EQ(mesh.validate(ValidateOptions{true, false}).reason(), "element 0 is inverted in the deformed positions");
    EXPECT_EQ(mesh.validate(ValidateOptions{true, false}).code(), RefusalCode::invalid_mesh);
}

// A move takes the stars walked for it (Mesh::walk_star) only while they are the stars of exactly
// its vertices in the mesh as it is: the watcher compares every move's elements_around_moved with
// the stars walked afresh.
TEST(MoveVertices, TakesTheStarsWalkedForItOnlyWhileTheyAreItsVerticesStars) {
    Mesh mesh = test::kuhn_cube(3);
    MirrorWatcher mirror;
    mesh.add_watcher(mirror);
    const VertexId a = 21, b = 22, c = 25;  // (1,1,1), (2,1,1), (1,2,1): inside, a-b an edge
    auto nudge = [&](std::vector<VertexId> vertices, double by) {
        std::vector<Point> points;
        for (const VertexId v : vertices) {
            const Point& x = mesh.deformed(v);
            points.push_back({x[0] + by, x[1] + by / 2, x[2] - by / 3});
        }
        return mesh.move_vertices(vertices, points, PositionSet::deformed, {true, true});
    };
    auto walk = [&](std::vector<VertexId> vertices) {
        mesh.begin_star_walks();
        for (const VertexId v : vertices) EXPECT_EQ(mesh.walk_star(v).size(), star(mesh, v).size()) << v;
    };
    walk({a, b});  // exactly the vertices moved: taken
    ASSERT_TRUE(nudge({b, a}, 0.01).ok());
    walk({a, b, c});  // more than moved
    ASSERT_TRUE(nudge({a, b}, 0.01).ok());
    walk({a, b});  // then the mesh changed: a's and b's stars have new elements
    ASSERT_TRUE(split_edge(mesh, a, b, 0.5).ok());
    ASSERT_TRUE(nudge({a, b}, 0.01).ok());
    walk({a});  // a refused move changes nothing: the walks stand for the next move
    EXPECT_EQ(nudge({a}, 2.0).code(), RefusalCode::would_invert);
    ASSERT_TRUE(nudge({a}, -0.01).ok());
    ASSERT_TRUE(nudge({a}, 0.01).ok());  // nor does a move change a star: they stand for the next
    ASSERT_TRUE(split_edge(mesh, a, c, 0.5).ok());  // until an edit
    ASSERT_TRUE(nudge({a}, -0.01).ok());
    EXPECT_TRUE(mesh.walk_star(static_cast<VertexId>(mesh.vertex_count())).empty());
    EXPECT_EQ(mirror.moves, 6);
    mirror.expect_mirrors(mesh);
    EXPECT_TRUE(mesh.validate({true, true}).ok()) << mesh.validate({true, true}).reason();
    mesh.remove_watcher(mirror);
}

}  // namespace
}  // namespace sxk
