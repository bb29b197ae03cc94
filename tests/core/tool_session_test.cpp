// ToolSession: each step one transaction (a refusal after several edits leaves the mesh as it
// was), the step report, undo_step and cancel, a session on an application's journal. The tool
// here is a test tool: it splits an edge at the dragged vertex (one to a vertex of the vertex's
// anchor element) and drags the vertex to the pose,
// refusing a pose whose z axis points down only after both edits, so that a refusal has to undo
// them.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "../../fuzz/ops_driver.hpp"
#include "fixtures.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/tool_session.hpp"

namespace sxk {
namespace {

using ops_driver::snapshot;

class DragTool final : public ToolSession {
public:
    DragTool(Mesh& mesh, VertexId dragged) : ToolSession(mesh), m_dragged(dragged) {}

protected:
    Outcome<Done> apply(const ToolPose& pose, StepReport& report) override {
        const Simplex& anchor = mesh().simplex(mesh().vertex_element(m_dragged));
        const VertexId other = anchor.vertex(0) == m_dragged ? anchor.vertex(1) : anchor.vertex(0);
        if (auto split = split_edge(mesh(), m_dragged, other, 0.5); !split) return split.refusal();
        report.actions.push_back("split an edge");
        const std::array<VertexId, 1> v{m_dragged};
        const std::array<Point, 1> p{pose.position};
        if (auto moved = mesh().move_vertices(v, p, PositionSet::deformed, MoveCheck{true, true}); !moved)
            return moved.refusal();
        report.actions.push_back("dragged a vertex");
        if (pose.axes[2][2] < 0)
            return Refusal{RefusalCode::not_applicable, "the tool points away from the mesh"};
        return Done{};
    }

private:
    VertexId m_dragged;
};

TEST(ToolSession, AStepIsOneTransaction) {
    Mesh mesh = test::planar_grid(4);
    test::MirrorWatcher mirror;
    mesh.add_watcher(mirror);
    DragTool tool(mesh, 6);
    const auto start = snapshot(mesh);

    ToolPose pose;
    pose.position = mesh.deformed(6);
    pose.position[0] += 0.01;
    const auto report = tool.step(pose);
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_EQ(report->actions, (std::vector<std::string>{"split an edge", "dragged a vertex"}));
    const VertexId made = static_cast<VertexId>(mesh.vertex_count() - 1);
    EXPECT_EQ(report->vertices, (std::vector<VertexId>{6, made}));
    EXPECT_EQ(report->elements_removed, 2u);  // the two triangles at an interior edge, split in four
    EXPECT_EQ(report->elements.size(), 4u);
    for (ElementId t : report->elements) EXPECT_TRUE(mesh.simplex(t).contains(made));
    EXPECT_EQ(tool.steps(), 1u);
    const auto after_one = snapshot(mesh);

    // split and drag are done, then refused: both go
    pose.axes[2] = {0, 0, -1};
    const auto refused = tool.step(pose);
    EXPECT_EQ(refused.reason(), "the tool points away from the mesh");
    EXPECT_EQ(refused.code(), RefusalCode::not_applicable);
    EXPECT_TRUE(snapshot(mesh) == after_one);
    EXPECT_EQ(tool.steps(), 1u);
    mirror.expect_mirrors(mesh);

    ASSERT_TRUE(tool.undo_step().ok());
    EXPECT_TRUE(snapshot(mesh) == start);
    EXPECT_EQ(tool.undo_step().reason(), "undo_step: the session has no step to undo");
    EXPECT_EQ(tool.undo_step().code(), RefusalCode::not_applicable);
    EXPECT_TRUE(mesh.validate(ValidateOptions{true}).ok());
    mirror.expect_mirrors(mesh);
    mesh.remove_watcher(mirror);
}

// Edits only when the pose is right of x = 0: a frame where the tool touches nothing.
class SometimesTool final : public ToolSession {
public:
    using ToolSession::ToolSession;

protected:
    Outcome<Done> apply(const ToolPose& pose, StepReport& report) override {
        if (pose.position[0] <= 0) return Done{};
        if (auto split = split_edge(mesh(), 0, 1, 0.5); !split) return split.refusal();
        report.actions.push_back("split edge 0-1");
        return Done{};
    }
};

// SometimesTool's poses: right of x = 0 it edits, left of it it does not.
ToolPose pose_at_x(double x) {
    ToolPose pose;
    pose.position = {x, 0, 0};
    return pose;
}

// A step that changed nothing leaves no entry in the journal's history: undoing it takes back
// nothing, and the step before it is undone next (it used to undo that one at once).
TEST(ToolSession, UndoingAStepThatChangedNothingTakesBackNothing) {
    Mesh mesh = test::planar_grid(2);
    const auto start = snapshot(mesh);
    SometimesTool tool(mesh);
    const ToolPose right = pose_at_x(1), left = pose_at_x(-1);
    ASSERT_TRUE(tool.step(right).ok());
    const auto after_split = snapshot(mesh);
    const auto idle = tool.step(left);
    ASSERT_TRUE(idle.ok()) << idle.reason();
    EXPECT_TRUE(idle->elements.empty());
    EXPECT_EQ(tool.steps(), 2u);
    ASSERT_TRUE(tool.undo_step().ok());
    EXPECT_TRUE(snapshot(mesh) == after_split);
    ASSERT_TRUE(tool.undo_step().ok());
    EXPECT_TRUE(snapshot(mesh) == start);
    EXPECT_EQ(tool.undo_step().reason(), "undo_step: the session has no step to undo");
    EXPECT_TRUE(mesh.validate().ok());
}

// redo_step takes again what undo_step took back, newest undone first, steps that changed nothing
// included; a new step leaves nothing to redo; and an edit by someone else refuses it.
TEST(ToolSession, RedoTakesAgainWhatUndoTookBack) {
    Mesh mesh = test::planar_grid(2);
    const auto start = snapshot(mesh);
    SometimesTool tool(mesh);
    const ToolPose right = pose_at_x(1), left = pose_at_x(-1);
    EXPECT_EQ(tool.redo_step().reason(), "redo_step: the session has no undone step to redo");
    EXPECT_EQ(tool.redo_step().code(), RefusalCode::not_applicable);
    ASSERT_TRUE(tool.step(right).ok());
    const auto after_split = snapshot(mesh);
    ASSERT_TRUE(tool.step(left).ok());  // changes nothing
    ASSERT_TRUE(tool.undo_step().ok());
    ASSERT_TRUE(tool.undo_step().ok());
    EXPECT_TRUE(snapshot(mesh) == start);
    ASSERT_TRUE(tool.redo_step().ok());
    EXPECT_TRUE(snapshot(mesh) == after_split);
    EXPECT_EQ(tool.steps(), 1u);
    ASSERT_TRUE(tool.redo_step().ok());  // the step that changed nothing
    EXPECT_EQ(tool.steps(), 2u);
    EXPECT_TRUE(snapshot(mesh) == after_split);
    EXPECT_EQ(tool.redo_step().reason(), "redo_step: the session has no undone step to redo");

    // a new step: nothing ahead to redo
    ASSERT_TRUE(tool.undo_step().ok());
    ASSERT_TRUE(tool.step(left).ok());
    EXPECT_EQ(tool.redo_step().reason(), "redo_step: the session has no undone step to redo");

    // an edit made by someone else since the undo
    ASSERT_TRUE(tool.undo_step().ok());
    ASSERT_TRUE(tool.undo_step().ok());
    const std::array<VertexId, 1> v{8};  // the corner (2, 2)
    const std::array<Point, 1> p{Point{2.01, 2, 0}};
    ASSERT_TRUE(mesh.move_vertices(v, p, PositionSet::deformed).ok());
    const auto redo = tool.redo_step();
    EXPECT_EQ(redo.reason(), "redo_step: the mesh changed since the session's last undo");
    EXPECT_EQ(redo.code(), RefusalCode::stale);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(ToolSession, CancelTakesBackEveryStep) {
    Mesh mesh = test::planar_grid(4);
    const auto start = snapshot(mesh);
    DragTool tool(mesh, 6);
    ToolPose pose;
    pose.position = mesh.deformed(6);
    for (int i = 0; i < 3; ++i) {
        pose.position[1] += 0.05;
        ASSERT_TRUE(tool.step(pose).ok());
    }
    EXPECT_EQ(tool.steps(), 3u);
    ASSERT_TRUE(tool.cancel().ok());
    EXPECT_TRUE(snapshot(mesh) == start);
    EXPECT_TRUE(tool.ended());
    EXPECT_EQ(tool.step(pose).reason(), "step: the session has ended");
    EXPECT_EQ(tool.step(pose).code(), RefusalCode::not_applicable);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(ToolSession, UndoRefusesAfterAnEditFromElsewhere) {
    Mesh mesh = test::planar_grid(4);
    DragTool tool(mesh, 6);
    ToolPose pose;
    pose.position = mesh.deformed(6);
    ASSERT_TRUE(tool.step(pose).ok());
    mesh.set_label(0, 3);
    EXPECT_EQ(tool.undo_step().reason(), "undo_step: the mesh changed since the session's last step");
    EXPECT_EQ(tool.undo_step().code(), RefusalCode::stale);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(ToolSession, StepsGoToTheApplicationsJournal) {
    Mesh mesh = test::planar_grid(4);
    EditJournal journal(mesh);
    const auto start = snapshot(mesh);
    DragTool tool(mesh, 6);
    ToolPose pose;
    pose.position = mesh.deformed(6);
    ASSERT_TRUE(tool.step(pose).ok());
    EXPECT_EQ(journal.undo_count(), 1u);  // the application can undo the tool's step itself
    // inside an application's open step the tool's step is part of it
    journal.checkpoint();
    pose.position[1] += 0.05;
    ASSERT_TRUE(tool.step(pose).ok());
    EXPECT_EQ(tool.undo_step().reason(), "undo_step: the step is part of the application's open step");
    EXPECT_EQ(tool.undo_step().code(), RefusalCode::not_applicable);
    ASSERT_TRUE(journal.rollback().ok());
    ASSERT_TRUE(journal.undo().ok());
    EXPECT_TRUE(snapshot(mesh) == start);
    EXPECT_TRUE(mesh.validate().ok());
}

// A tool that follows its own edits: elements_edited_in_step() grows with each edit of the step
// (the children of a split at vertex 0), starts empty in every step, and is empty outside apply().
class WatchfulTool final : public ToolSession {
public:
    using ToolSession::ToolSession;
    std::vector<std::size_t> sizes;           // before the split, after it, per step
    std::vector<ElementId> seen;              // what the last step's split made, as the tool saw it
    std::vector<ElementId> made;              // what split_edge said it made
    std::size_t outside() const { return elements_edited_in_step().size(); }

protected:
    Outcome<Done> apply(const ToolPose&, StepReport&) override {
        sizes.push_back(elements_edited_in_step().size());
        const Simplex& anchor = mesh().simplex(mesh().vertex_element(0));
        auto split = split_edge(mesh(), 0, anchor.vertex(0) == 0 ? anchor.vertex(1) : anchor.vertex(0), 0.5);
        if (!split) return split.refusal();
        const auto edited = elements_edited_in_step();
        sizes.push_back(edited.size());
        seen.assign(edited.begin(), edited.end());
        made = split->elements;
        return Done{};
    }
};

TEST(ToolSession, TheToolSeesTheElementsItsStepEditedSoFar) {
    Mesh mesh = test::planar_grid(2);
    WatchfulTool tool(mesh);
    EXPECT_EQ(tool.outside(), 0u);
    ASSERT_TRUE(tool.step(ToolPose{}).ok());
    ASSERT_EQ(tool.sizes.size(), 2u);
    EXPECT_EQ(tool.sizes[0], 0u);
    EXPECT_GT(tool.sizes[1], 0u);
    std::sort(tool.seen.begin(), tool.seen.end());
    tool.seen.erase(std::unique(tool.seen.begin(), tool.seen.end()), tool.seen.end());
    std::sort(tool.made.begin(), tool.made.end());
    EXPECT_EQ(tool.seen, tool.made);
    EXPECT_EQ(tool.outside(), 0u);
    ASSERT_TRUE(tool.step(ToolPose{}).ok());  // the next step starts from nothing again
    EXPECT_EQ(tool.sizes[2], 0u);
    EXPECT_TRUE(mesh.validate().ok());
}

// vertices_moved_in_step(): the vertices the step has moved so far, empty at the start of each
// step and outside apply().
class MovingTool final : public ToolSession {
public:
    using ToolSession::ToolSession;
    std::vector<std::vector<VertexId>> seen;  // before and after the move, per step
    std::size_t outside() const { return vertices_moved_in_step().size(); }

protected:
    Outcome<Done> apply(const ToolPose& pose, StepReport&) override {
        seen.emplace_back(vertices_moved_in_step().begin(), vertices_moved_in_step().end());
        const std::array<VertexId, 2> v{4, 1};
        const std::array<Point, 2> p{pose.position, mesh().reference(1)};
        if (auto moved = mesh().move_vertices(v, p, PositionSet::deformed, MoveCheck{true, true}); !moved)
            return moved.refusal();
        seen.emplace_back(vertices_moved_in_step().begin(), vertices_moved_in_step().end());
        return Done{};
    }
};

TEST(ToolSession, TheToolSeesTheVerticesItsStepMovedSoFar) {
    Mesh mesh = test::planar_grid(2);  // vertex 4: the middle of a 3 x 3 grid of vertices
    MovingTool tool(mesh);
    EXPECT_EQ(tool.outside(), 0u);
    ToolPose pose;
    pose.position = {0.9, 1.1, 0};
    ASSERT_TRUE(tool.step(pose).ok());
    ASSERT_EQ(tool.seen.size(), 2u);
    EXPECT_TRUE(tool.seen[0].empty());
    EXPECT_EQ(tool.seen[1], (std::vector<VertexId>{4, 1}));
    EXPECT_EQ(tool.outside(), 0u);
    pose.position = {1.1, 0.9, 0};
    ASSERT_TRUE(tool.step(pose).ok());  // the next step starts from nothing again
    EXPECT_TRUE(tool.seen[2].empty());
    EXPECT_TRUE(mesh.validate().ok());
}

}  // namespace
}  // namespace sxk
