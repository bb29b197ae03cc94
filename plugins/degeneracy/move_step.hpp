// One removal move (a split and a collapse, or a collapse, or flips) as one EditJournal step:
// kept when it pays, rolled back exactly when it is refused part way or does not pay. The
// kernel's edits are transactions one by one; a move of two or three edits needs the journal to
// be one (edit_journal.hpp).
//
//   begin()      a step opens; the move log marks where the move's events start
//   ... the move's edits ...
//   created()    the move's new or changed elements still in the mesh
//   removed()    the elements of before the move that it removed (their simplexes)
//   keep()       commit: the move stays (inside the run's step, or the application's)
//   undo()       rollback: the mesh is as before begin(), ids included, and the move log
//                forgets the move (its events and the rollback's own)
//
// Follow-up moves (removals of what a move made) are steps nested inside the move's: undoing
// the move undoes them too.
#pragma once

#include <cstddef>
#include <vector>

#include "sxk/edit_journal.hpp"
#include "sxk/mesh.hpp"

namespace sxk::degeneracy::detail {

// What the edits of a removal run did, as their watcher events tell it: `touched` the elements
// created or changed (where new degenerates can appear: an element no edit touches keeps its
// shape, so the thesis' "new list" needs to look only there), `events` every element event in
// order with the simplex concerned (removed/changed: the one before; added: the new one).
class MoveLog final : public Watcher {
public:
    struct Event {
        enum class Kind { removed, changed, added } kind;
        Simplex was;  // removed, changed: before the event
        Simplex now;  // changed, added: after
    };
    void element_removed(const Mesh&, ElementId, const Simplex& was) override {
        events.push_back({Event::Kind::removed, was, Simplex{}});
    }
    void element_changed(const Mesh& mesh, ElementId element, const Simplex& was) override {
        touched.push_back(element);
        events.push_back({Event::Kind::changed, was, mesh.simplex(element)});
    }
    void element_added(const Mesh& mesh, ElementId element) override {
        touched.push_back(element);
        events.push_back({Event::Kind::added, Simplex{}, mesh.simplex(element)});
    }
    // Forgets what came after these sizes: a rolled-back move left no shape behind, and a log
    // that kept every tried move grew to gigabytes on the femur (issue 47, defect 10).
    void truncate(std::size_t touched_size, std::size_t events_size) {
        touched.resize(touched_size);
        events.resize(events_size);
    }
    std::vector<ElementId> touched;
    std::vector<Event> events;
};

class MoveStep {
public:
    MoveStep(Mesh& mesh, EditJournal& journal, MoveLog& log) : m_mesh(mesh), m_journal(journal), m_log(log) {}

    void begin();
    std::vector<ElementId> created() const;
    std::vector<Simplex> removed() const;
    void keep();
    void undo();

private:
    Mesh& m_mesh;
    EditJournal& m_journal;
    MoveLog& m_log;
    std::size_t m_touched_start = 0;
    std::size_t m_events_start = 0;
};

}  // namespace sxk::degeneracy::detail
