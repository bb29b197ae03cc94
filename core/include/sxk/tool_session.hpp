// Tool sessions: a cutter, a needle or a brush driven once per frame by an application, each
// frame one transaction that can be undone.
//
//     auto session = factory->begin("snapcut", mesh, options);   // a plug-in's ToolFactory
//     for each frame:
//         auto report = (*session)->step(pose);   // completes, or the mesh is as before
//         if (report) solver.update(report->elements, report->vertices);
//     (*session)->undo_step();                    // the last frame back
//     (*session)->end();                          // or cancel(): every frame of the session back
//
// A tool derives from ToolSession and implements apply(): whatever Mesh calls and operations
// the pose asks for. step() makes them one EditJournal step (sxk/edit_journal.hpp): if apply()
// refuses, everything it did is rolled back exactly and the refusal is returned. The session
// uses the mesh's journal when the application attached one (its steps then are entries of the
// application's undo history, or parts of the application's open step) and one of its own
// otherwise. Watchers hear each step's changes as they happen, and the net change back on a
// rollback or undo.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

// Where a tool is for one step, in the positions the tool works in (a cutter acts on the
// deformed positions, thesis §3.2.2): its reference point (a scalpel's tip, a needle's tip) and
// its axes (unit vectors in mesh coordinates: the tool's x, y and z; a needle points along z).
// A tool with extent (a scalpel's blade, a needle's shaft) reaches back from `position` along
// -axes[2] by `length`: the blade runs from its handle end position - length * axes[2] to its tip.
struct ToolPose {
    Point position{0, 0, 0};
    std::array<Point, 3> axes{Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1}};
    double length = 0;
};

// What one step did, for the application (solver, renderer) and for logs.
struct StepReport {
    std::vector<ElementId> elements;   // created or changed by the step and still there, sorted
    std::size_t elements_removed = 0;  // elements of before the step that it removed
    std::vector<VertexId> vertices;    // moved or added by the step, sorted
    std::vector<std::string> actions;  // what the tool did, in order, in words ("snapped 3 vertices")
};

class SXK_API ToolSession {
public:
    explicit ToolSession(Mesh& mesh);
    virtual ~ToolSession();
    ToolSession(const ToolSession&) = delete;
    ToolSession& operator=(const ToolSession&) = delete;

    Mesh& mesh() { return m_mesh; }
    const Mesh& mesh() const { return m_mesh; }

    // One transaction: apply(pose) as one step. Refuses (the mesh as before, watchers told the
    // net change back) when apply refuses, and after end().
    Outcome<StepReport> step(const ToolPose& pose);
    // Takes back the newest step of this session still kept. Refuses when there is none, when
    // that step was part of an application's open step (the application undoes it), or when
    // the mesh changed since (another tool or the application edited it).
    Outcome<Done> undo_step();
    // Takes again the newest step undo_step took back, as it was: the mesh and the tool's side
    // logs (the journal's redo). Refuses when there is none, when a step was taken since, or when
    // the mesh changed since.
    Outcome<Done> redo_step();
    // Takes back every kept step of this session, newest first; stops at the first that cannot
    // be (the reason says how many were).
    Outcome<Done> cancel();
    // Ends the session: its steps stay; step() refuses from now on.
    void end() { m_ended = true; }
    bool ended() const { return m_ended; }
    // Steps kept (taken and not undone).
    std::size_t steps() const { return m_kept.size(); }

protected:
    // What the tool does at `pose`: any Mesh calls and operations, adding what it did to
    // `report.actions` (step() fills in elements and vertices). A refusal takes it all back.
    virtual Outcome<Done> apply(const ToolPose& pose, StepReport& report) = 0;
    // State the tool keeps between steps, attached to the session's journal (side_log.hpp): every
    // step marks it, a refused step takes it back, and undo_step and redo_step (or an
    // application's undo and redo) take it back and forth with the mesh, so the tool needs no
    // stack of its own. Call it from the tool's constructor; the log, a member of the tool,
    // detaches itself when destroyed. Refuses a log attached to another journal.
    Outcome<Done> keep_beside(SideLog& log);
    // Inside apply(): the elements the step's edits have changed or added so far, in the order of
    // their events (an id may repeat, and may have been removed since). It only grows during a
    // step, so a tool that follows what its own edits made (a cutter carrying its marks over to
    // new edges) keeps how far it has read. Empty outside apply().
    std::span<const ElementId> elements_edited_in_step() const;
    // Inside apply(): the vertices the step's edits have moved so far (Mesh::move_vertices, in
    // either position set), in the order of their events (a vertex may repeat). With
    // elements_edited_in_step(), where the step changed the body: a simulation relaxes around
    // them (Simulation::relax_near). Empty outside apply().
    std::span<const VertexId> vertices_moved_in_step() const;

private:
    Mesh& m_mesh;
    JournalScope m_journal;
    // per kept step: an entry of the journal's history (undo_step takes it back), part of an
    // application's open step (the application undoes it), or a step that changed nothing, in
    // the mesh or a side log (the journal keeps no entry for it; undoing it is taking back nothing)
    enum class Kept : std::uint8_t { history_entry, application_step, nothing };
    std::vector<Kept> m_kept;
    std::vector<Kept> m_undone;  // taken back by undo_step, newest last: what redo_step takes again
    std::uint64_t m_revision = 0;  // the mesh's revision after this session's last change
    const std::vector<ElementId>* m_step_elements = nullptr;  // the step watcher's, during apply()
    const std::vector<VertexId>* m_step_vertices = nullptr;   // the same
    bool m_ended = false;
};

// The service a plug-in offers for its tools (PluginHost::service<ToolFactory>(), plugin.hpp).
struct ToolFactory {
    static constexpr std::string_view service_id = "sxk.tools";
    static constexpr std::uint32_t service_version = 1;

    // The tools offered, e.g. {"snapcut"}.
    std::span<const std::string_view> (*tools)();
    // A session of `tool` on `mesh`, with the tool's options as on its command line
    // ("--depth", "0.01"); refuses an unknown tool or bad options, with the reason.
    Outcome<std::unique_ptr<ToolSession>> (*begin)(std::string_view tool, Mesh& mesh,
                                                   std::span<const std::string> options);
};

}  // namespace sxk
