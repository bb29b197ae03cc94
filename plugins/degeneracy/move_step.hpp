// One removal move (a split and a collapse, or a collapse, or flips) as one EditJournal step:
// kept when it pays, rolled back exactly when it is refused part way or does not pay. The
// kernel's edits are transactions one by one; a move of two or three edits needs the journal to
// be one (edit_journal.hpp).
//
//   begin()      a step opens; the run's events (sxk/step_events.hpp) are marked
//   ... the move's edits ...
//   created()    the move's new or changed elements still in the mesh
//   removed()    the elements of before the move that it removed (their simplexes)
//   keep()       commit: the move stays (inside the run's step, or the application's)
//   undo()       rollback: the mesh is as before begin(), ids included, and the events
//                forget the move (its own and the rollback's)
//
// Follow-up moves (removals of what a move made) are steps nested inside the move's: undoing
// the move undoes them too.
#pragma once

#include <cstddef>
#include <vector>

#include "sxk/edit_journal.hpp"
#include "sxk/mesh.hpp"
#include "sxk/step_events.hpp"

namespace sxk::degeneracy::detail {

class MoveStep {
public:
    MoveStep(Mesh& mesh, EditJournal& journal, StepEvents& events) : m_mesh(mesh), m_journal(journal), m_events(events) {}

    void begin();
    std::vector<ElementId> created() const;
    std::vector<Simplex> removed() const;
    void keep();
    void undo();

private:
    Mesh& m_mesh;
    EditJournal& m_journal;
    StepEvents& m_events;
    StepEvents::Mark m_start;
};

}  // namespace sxk::degeneracy::detail
