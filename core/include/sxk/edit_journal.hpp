// Steps of several edits that complete or leave the mesh as it was, and an undo/redo history of
// them.
//
// A tool's frame is several kernel edits (snap, dissect, collapse, flip, bisect) and vertex
// moves; each edit is a transaction on its own, but the frame must be one: thesis §3.3 ends with
// incisions that lose their connection once degeneracies are removed, which a cutter can only
// avoid by taking back the whole frame. The journal makes any sequence of Mesh calls one step:
//
//   EditJournal journal(mesh);
//   journal.checkpoint();                 // a step opens (steps nest)
//   ... replace_elements, change_elements, the operations of sxk/ops, move_vertices,
//       add_vertex, set_label, set_face_label, set_vertex_attribute ...
//   journal.commit();                     // or journal.rollback(): the mesh is as at checkpoint()
//   journal.undo();  journal.redo();      // committed outermost steps, newest first
//
// What a rollback restores: connectivity, both position sets, element and face labels, vertex
// attribute values set through the mesh, and the vertex count, exactly. The id invariant: every
// element, face and vertex id valid at the checkpoint names the same object afterwards, and the
// pools and free lists are as they were, so the next edit hands out the same ids and any file
// written afterwards is byte for byte the file written at the checkpoint. Watchers, who heard
// every edit of the step as it happened, hear the net change back as one edit (watcher.hpp);
// moved vertices as one vertices_moved with PositionSet::both.
//
// Cost: the mesh records what each store overwrites (core/src/undo_log.hpp), so a step and its
// rollback cost what the step touched, never the size of the mesh; outside a step nothing is
// recorded. Not recorded (documented as bulk paths in mesh.hpp): the mutable face_labels() map
// and writes through vertex_attribute spans; adding or removing vertex attributes and
// assign_elements are refused inside a step.
//
// State kept beside the mesh (a tool's) joins the steps through side logs (side_log.hpp):
// attach() one, and every step marks it, rolls it back, records it and undoes or redoes it with
// the mesh. A step that changed only a side log is a step of the history too.
//
// One journal per mesh; the mesh must not be moved, and must outlive the journal. Destroying the
// journal with steps open rolls them back (a step that was not committed did not happen).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/side_log.hpp"

namespace sxk {

class SXK_API EditJournal {
public:
    // Throws std::logic_error when `mesh` already has a journal (a programming error).
    explicit EditJournal(Mesh& mesh);
    ~EditJournal();
    EditJournal(const EditJournal&) = delete;
    EditJournal& operator=(const EditJournal&) = delete;

    Mesh& mesh() { return m_mesh; }
    const Mesh& mesh() const { return m_mesh; }

    // ---- steps ----------------------------------------------------------------------------------
    // Opens a step inside the open one, if any.
    void checkpoint();
    // Closes the innermost step keeping its edits (they belong to the enclosing step, if any; the
    // outermost goes to the history). Refuses when no step is open.
    Outcome<Done> commit();
    // Takes back every change since the innermost checkpoint and closes that step. Refuses when
    // no step is open.
    Outcome<Done> rollback();
    // Open steps (0: none).
    std::size_t depth() const { return m_marks.size(); }
    // Stores recorded since the outermost checkpoint (what a rollback would replay).
    std::size_t recorded() const;

    // ---- history --------------------------------------------------------------------------------
    // Committed outermost steps kept for undo (default 100; 0 keeps none). Older ones are dropped.
    void set_history_limit(std::size_t steps);
    std::size_t undo_count() const { return m_undo.size(); }
    // Outermost steps committed with something to undo (mesh edits or side log changes), since
    // the journal began: a step that grew it is an entry of the history (unless the history keeps
    // none), whatever the limit dropped.
    std::uint64_t steps_recorded() const { return m_steps_recorded; }
    std::size_t redo_count() const { return m_redo.size(); }
    // Takes back the newest committed step (redo puts it back; a new commit forgets what could
    // be redone). Refuses, changing nothing, when a step is open, when there is nothing to undo
    // (redo), or when the mesh changed outside the journal since the history's last step (the
    // record would no longer fit).
    Outcome<Done> undo();
    Outcome<Done> redo();
    void clear_history();

    // ---- side logs --------------------------------------------------------------------------------
    // Steps from now on mark, roll back, record and replay `log` with the mesh (side_log.hpp).
    // Attached while steps are open, it is marked for each of them as it is now. Refuses a log
    // attached to another journal; attaching it again here changes nothing.
    Outcome<Done> attach(SideLog& log);
    // Steps no longer concern `log`: its marks in open steps and its records in the history are
    // dropped (a history step left with nothing to replay is dropped with them). Nothing when it
    // is not attached here. A log's destructor detaches it.
    void detach(SideLog& log);
    std::size_t side_log_count() const { return m_sides.size(); }

    // The journal attached to `mesh`, or nullptr.
    static EditJournal* of(Mesh& mesh) { return mesh.m_journal; }

private:
    struct Log;
    struct Side {
        SideLog* log;
        std::vector<std::size_t> marks;  // one per open step, outermost first
    };
    Outcome<Done> replay_history(std::deque<std::unique_ptr<Log>>& from,
                                 std::deque<std::unique_ptr<Log>>& to, const char* what);

    Mesh& m_mesh;
    std::unique_ptr<Log> m_open;       // the record of the open steps
    std::vector<std::size_t> m_marks;  // where each open step starts in it
    std::deque<std::unique_ptr<Log>> m_undo;
    std::deque<std::unique_ptr<Log>> m_redo;
    std::vector<Side> m_sides;  // in the order of attachment
    std::size_t m_history_limit = 100;
    std::uint64_t m_revision_at_open = 0;  // the mesh's revision when the outermost step opened
    std::uint64_t m_history_revision = 0;  // the mesh's revision after the history's last change
    std::uint64_t m_steps_recorded = 0;
};

// A step for the length of a scope: opened at construction, committed by commit(), rolled back
// by the destructor otherwise (an early return or an exception undoes the step, and the steps
// still open inside it).
class SXK_API EditStep {
public:
    explicit EditStep(EditJournal& journal) : m_journal(journal), m_depth(journal.depth()) { journal.checkpoint(); }
    ~EditStep();
    EditStep(const EditStep&) = delete;
    EditStep& operator=(const EditStep&) = delete;
    // Closes inner steps left open (kept), then this one. Refuses when already closed.
    Outcome<Done> commit();

private:
    EditJournal& m_journal;
    std::size_t m_depth;  // the journal's depth outside this step
    bool m_closed = false;
};

// The journal of a mesh for the length of a scope: the one attached (an application's, whose
// open step then holds what the scope does), or one of its own, attached until the scope ends.
// What needs several edits to be one (a plug-in's multi-edit move, a tool step) uses it whether
// or not the application journals the mesh.
class SXK_API JournalScope {
public:
    explicit JournalScope(Mesh& mesh);
    JournalScope(const JournalScope&) = delete;
    JournalScope& operator=(const JournalScope&) = delete;
    EditJournal& journal() { return *m_journal; }
    EditJournal* operator->() { return m_journal; }
    // True when the scope attached the journal (the mesh had none).
    bool owned() const { return m_own != nullptr; }

private:
    std::unique_ptr<EditJournal> m_own;
    EditJournal* m_journal;
};

}  // namespace sxk
