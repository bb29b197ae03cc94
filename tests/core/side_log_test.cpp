// Side logs (side_log.hpp) on the EditJournal: state kept beside the mesh is marked, rolled back,
// recorded, undone and redone with the mesh's edits, nested steps included, and a log that is
// detached or destroyed leaves the history consistent.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "../../fuzz/ops_driver.hpp"
#include "fixtures.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/remove_elements.hpp"
#include "sxk/side_log.hpp"

namespace sxk {
namespace {

using ops_driver::snapshot;

// A tool's state as a test sees it: where its scalpel is and how many faces it marked.
struct Scalpel {
    Point position{};
    int marked = 0;
    bool operator==(const Scalpel&) const = default;
};

// Moves vertex 2 of the unit square: an edit the journal records.
void move_vertex_2(Mesh& mesh, double x) {
    const std::array<VertexId, 1> moved{2};
    const std::array<Point, 1> to{Point{x, 1, 0}};
    ASSERT_TRUE(mesh.move_vertices(moved, to, PositionSet::both).ok());
}

// A log that says, when taken back, how many elements the mesh had then: the journal calls side
// logs after it has replayed the mesh.
class CountingLog final : public SideLog {
public:
    explicit CountingLog(const Mesh& mesh) : m_mesh(mesh) {}
    std::vector<std::string> heard;
    std::size_t mark() override {
        heard.push_back("mark");
        return m_marks++;
    }
    void rollback_to(std::size_t mark) override {
        heard.push_back("rollback_to " + std::to_string(mark) + " at " + std::to_string(m_mesh.element_count()));
        m_marks = mark;
    }
    void keep(std::size_t mark) override {
        heard.push_back("keep " + std::to_string(mark));
        m_marks = mark;
    }
    std::unique_ptr<SideRecord> commit(std::size_t mark) override {
        heard.push_back("commit " + std::to_string(mark));
        m_marks = mark;
        return std::make_unique<SideRecord>();
    }
    std::unique_ptr<SideRecord> replay(std::unique_ptr<SideRecord> record) override {
        heard.push_back("replay at " + std::to_string(m_mesh.element_count()));
        return record;
    }

private:
    const Mesh& m_mesh;
    std::size_t m_marks = 0;
};

TEST(SideLog, ARollbackTakesBackTheMeshAndTheStateTogether) {
    Mesh mesh = test::unit_square();
    const auto before = snapshot(mesh);
    EditJournal journal(mesh);
    SnapshotLog<Scalpel> scalpel(Scalpel{{0.5, 0.5, 0}, 0});
    ASSERT_TRUE(journal.attach(scalpel).ok());
    EXPECT_EQ(scalpel.journal(), &journal);
    EXPECT_EQ(journal.side_log_count(), 1u);

    journal.checkpoint();
    move_vertex_2(mesh, 1.25);
    scalpel.edit() = {{0.75, 0.5, 0}, 3};
    ASSERT_TRUE(journal.rollback().ok());
    EXPECT_TRUE(snapshot(mesh) == before);
    EXPECT_EQ(scalpel.get(), (Scalpel{{0.5, 0.5, 0}, 0}));
    EXPECT_EQ(journal.undo_count(), 0u);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(SideLog, NestedStepsKeepOrTakeBackTheirOwnChanges) {
    Mesh mesh = test::unit_square();
    EditJournal journal(mesh);
    SnapshotLog<Scalpel> scalpel;
    ASSERT_TRUE(journal.attach(scalpel).ok());

    journal.checkpoint();
    scalpel.edit().marked = 1;
    journal.checkpoint();  // inner, rolled back
    scalpel.edit().marked = 2;
    move_vertex_2(mesh, 1.5);
    ASSERT_TRUE(journal.rollback().ok());
    EXPECT_EQ(scalpel.get().marked, 1);
    journal.checkpoint();  // inner, kept
    scalpel.edit().marked = 5;
    ASSERT_TRUE(journal.commit().ok());
    EXPECT_EQ(scalpel.get().marked, 5);
    ASSERT_TRUE(journal.rollback().ok());  // the outer step, and the inner one it holds
    EXPECT_EQ(scalpel.get().marked, 0);
    EXPECT_EQ(mesh.deformed(2)[0], 1.0);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(SideLog, UndoAndRedoRestoreTheMeshAndTheStateTogether) {
    Mesh mesh = test::unit_square();
    const auto at_start = snapshot(mesh);
    EditJournal journal(mesh);
    SnapshotLog<Scalpel> scalpel;
    ASSERT_TRUE(journal.attach(scalpel).ok());

    journal.checkpoint();
    move_vertex_2(mesh, 1.25);
    scalpel.edit() = {{1, 2, 3}, 7};
    ASSERT_TRUE(journal.commit().ok());
    const auto after_step = snapshot(mesh);
    const Scalpel state_after = scalpel.get();
    ASSERT_EQ(journal.undo_count(), 1u);

    ASSERT_TRUE(journal.undo().ok());
    EXPECT_TRUE(snapshot(mesh) == at_start);
    EXPECT_EQ(scalpel.get(), Scalpel{});
    ASSERT_TRUE(journal.redo().ok());
    EXPECT_TRUE(snapshot(mesh) == after_step);
    EXPECT_EQ(scalpel.get(), state_after);
    ASSERT_TRUE(journal.undo().ok());
    EXPECT_EQ(scalpel.get(), Scalpel{});
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

// A step that moved only the tool (placing a scalpel) is a step of the history: the application's
// undo takes it back. A step that changed nothing is not.
TEST(SideLog, AStepThatChangedOnlyASideLogCanBeUndone) {
    Mesh mesh = test::unit_square();
    EditJournal journal(mesh);
    SnapshotLog<Scalpel> scalpel;
    ASSERT_TRUE(journal.attach(scalpel).ok());

    journal.checkpoint();
    ASSERT_TRUE(journal.commit().ok());
    EXPECT_EQ(journal.undo_count(), 0u);

    journal.checkpoint();
    scalpel.edit().position = {0.25, 0.25, 0};
    ASSERT_TRUE(journal.commit().ok());
    ASSERT_EQ(journal.undo_count(), 1u);
    ASSERT_TRUE(journal.undo().ok());
    EXPECT_EQ(scalpel.get(), Scalpel{});
    ASSERT_TRUE(journal.redo().ok());
    EXPECT_EQ(scalpel.get().position, (Point{0.25, 0.25, 0}));
}

TEST(SideLog, TheJournalCallsLogsAfterTheMeshInReverseOrderOfAttachment) {
    Mesh mesh = test::unit_square();
    EditJournal journal(mesh);
    CountingLog first(mesh), second(mesh);
    ASSERT_TRUE(journal.attach(first).ok());
    ASSERT_TRUE(journal.attach(second).ok());

    journal.checkpoint();
    const std::array<ElementId, 1> gone{0};
    ASSERT_TRUE(remove_elements(mesh, gone).ok());
    ASSERT_EQ(mesh.element_count(), 1u);
    ASSERT_TRUE(journal.rollback().ok());
    // the mesh has its two triangles again when the logs are taken back
    EXPECT_EQ(first.heard, (std::vector<std::string>{"mark", "rollback_to 0 at 2"}));
    EXPECT_EQ(second.heard, (std::vector<std::string>{"mark", "rollback_to 0 at 2"}));

    first.heard.clear();
    second.heard.clear();
    journal.checkpoint();
    journal.checkpoint();
    ASSERT_TRUE(remove_elements(mesh, gone).ok());
    ASSERT_TRUE(journal.commit().ok());
    ASSERT_TRUE(journal.commit().ok());
    EXPECT_EQ(first.heard, (std::vector<std::string>{"mark", "mark", "keep 1", "commit 0"}));
    ASSERT_TRUE(journal.undo().ok());
    EXPECT_EQ(first.heard.back(), "replay at 2");
    EXPECT_EQ(second.heard.back(), "replay at 2");
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(SideLog, AttachedWhileAStepIsOpenItIsMarkedForThatStep) {
    Mesh mesh = test::unit_square();
    EditJournal journal(mesh);
    SnapshotLog<Scalpel> scalpel(Scalpel{{}, 4});
    journal.checkpoint();
    ASSERT_TRUE(journal.attach(scalpel).ok());
    ASSERT_TRUE(journal.attach(scalpel).ok());  // again: nothing changes
    EXPECT_EQ(journal.side_log_count(), 1u);
    scalpel.edit().marked = 9;
    ASSERT_TRUE(journal.rollback().ok());
    EXPECT_EQ(scalpel.get().marked, 4);
}

TEST(SideLog, ALogBelongsToOneJournal) {
    Mesh one = test::unit_square(), other = test::unit_square();
    EditJournal first(one), second(other);
    SnapshotLog<int> log;
    ASSERT_TRUE(first.attach(log).ok());
    const auto refused = second.attach(log);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "attach: the side log is attached to another journal");
    EXPECT_EQ(refused.code(), RefusalCode::not_applicable);
    EXPECT_EQ(log.journal(), &first);
}

// Detached (or destroyed), a log's records leave the history; a step that held nothing else
// leaves with them, and the mesh's steps stay undoable.
TEST(SideLog, DetachingOrDestroyingALogDropsItsRecords) {
    Mesh mesh = test::unit_square();
    const auto at_start = snapshot(mesh);
    EditJournal journal(mesh);
    auto scalpel = std::make_unique<SnapshotLog<Scalpel>>();
    SnapshotLog<int> count;
    ASSERT_TRUE(journal.attach(*scalpel).ok());
    ASSERT_TRUE(journal.attach(count).ok());

    journal.checkpoint();  // the mesh and the scalpel
    move_vertex_2(mesh, 1.25);
    scalpel->edit().marked = 1;
    ASSERT_TRUE(journal.commit().ok());
    journal.checkpoint();  // the scalpel only
    scalpel->edit().marked = 2;
    ASSERT_TRUE(journal.commit().ok());
    journal.checkpoint();  // the count only
    count.edit() = 3;
    ASSERT_TRUE(journal.commit().ok());
    ASSERT_EQ(journal.undo_count(), 3u);

    scalpel.reset();  // detaches itself
    EXPECT_EQ(journal.side_log_count(), 1u);
    EXPECT_EQ(journal.undo_count(), 2u);
    journal.detach(count);
    EXPECT_EQ(count.journal(), nullptr);
    EXPECT_EQ(journal.undo_count(), 1u);
    ASSERT_TRUE(journal.undo().ok());
    EXPECT_TRUE(snapshot(mesh) == at_start);
    EXPECT_EQ(count.get(), 3);  // no longer the journal's
}

// A journal destroyed with a step open takes the step back, side logs included, and leaves the
// logs detached.
TEST(SideLog, AJournalDestroyedWithAStepOpenTakesBackTheLogs) {
    Mesh mesh = test::unit_square();
    SnapshotLog<Scalpel> scalpel;
    {
        EditJournal journal(mesh);
        ASSERT_TRUE(journal.attach(scalpel).ok());
        journal.checkpoint();
        scalpel.edit().marked = 6;
        move_vertex_2(mesh, 2);
    }
    EXPECT_EQ(scalpel.get().marked, 0);
    EXPECT_EQ(scalpel.journal(), nullptr);
    EXPECT_EQ(mesh.deformed(2)[0], 1.0);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

// on_restore: told, after every rollback, undo and redo that changed the value, the value it
// replaced, with the new value in place (the needle re-holds the body's nodes so).
TEST(SideLog, ASnapshotsFollowerHearsTheValueEachRestoreReplaced) {
    Mesh mesh = test::unit_square();
    EditJournal journal(mesh);
    SnapshotLog<int> count(1);
    std::vector<std::string> heard;
    count.on_restore([&](const int& replaced) {
        heard.push_back(std::to_string(replaced) + " -> " + std::to_string(count.get()));
    });
    ASSERT_TRUE(journal.attach(count).ok());
    journal.checkpoint();
    count.edit() = 5;
    journal.checkpoint();  // an inner step that leaves the value alone: nothing to follow
    move_vertex_2(mesh, 3);
    ASSERT_TRUE(journal.rollback().ok());
    ASSERT_TRUE(journal.rollback().ok());
    journal.checkpoint();
    count.edit() = 7;
    move_vertex_2(mesh, 2);
    ASSERT_TRUE(journal.commit().ok());
    ASSERT_TRUE(journal.undo().ok());
    ASSERT_TRUE(journal.redo().ok());
    EXPECT_EQ(heard, (std::vector<std::string>{"5 -> 1", "7 -> 1", "1 -> 7"}));
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

}  // namespace
}  // namespace sxk
