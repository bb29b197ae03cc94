// What a stretch of edits did, as the mesh's watcher events tell it (watcher.hpp): the elements
// they made or changed, the vertices they moved, and every element event with its simplex. A
// tool's step reads it (ToolSession::elements_edited_in_step), and so does a removal move that
// must know what it made and what it removed before it decides to keep itself (the degeneracy
// plug-in). Events are only appended; a mark() is how far they went, and truncate(mark) forgets
// what came after, for a caller that rolled those edits back and wants no trace of them.
//
//   StepEvents events;
//   const ScopedWatcher watching(mesh, events);
//   const StepEvents::Mark before = events.mark();
//   ... edits ...
//   events.created_since(mesh, before);   // the elements made or changed, still there
//   events.removed_since(before);         // the simplexes of before that the edits removed
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/watcher.hpp"

namespace sxk {

class SXK_API StepEvents final : public Watcher {
public:
    struct Event {
        enum class Kind : std::uint8_t { removed, changed, added } kind;
        Simplex was;  // removed, changed: before the event
        Simplex now;  // changed, added: after
    };
    // How far the events went: the sizes of the lists.
    struct Mark {
        std::size_t touched = 0, added = 0, moved = 0, events = 0;
    };

    // The elements made or changed, in the order of their events (an id may repeat, and may have
    // been removed since).
    const std::vector<ElementId>& touched() const { return m_touched; }
    // The elements made, in order (the same caveats).
    const std::vector<ElementId>& added() const { return m_added; }
    // The vertices moved (in either position set), in order (a vertex may repeat).
    const std::vector<VertexId>& moved() const { return m_moved; }
    const std::vector<Event>& events() const { return m_events; }

    Mark mark() const { return {m_touched.size(), m_added.size(), m_moved.size(), m_events.size()}; }
    // Forgets the events after `mark` (edits rolled back: an edit tried and refused leaves no
    // trace, and a log that kept every tried edit grew to gigabytes on the femur).
    void truncate(const Mark& mark);
    void clear() { truncate(Mark{}); }

    // The elements the edits since `mark` made or changed that are still elements, sorted.
    std::vector<ElementId> created_since(const Mesh& mesh, const Mark& mark) const;
    // The simplexes of the elements there at `mark` that the edits since removed (an element the
    // edits made and removed again was not there: it is matched off).
    std::vector<Simplex> removed_since(const Mark& mark) const;
    // The vertices of every element the events since `mark` removed, changed or made (each once
    // per event): the vertices whose stars the edits changed.
    template <class Visit>
    void for_changed_stars(const Mark& mark, Visit visit) const {
        for (std::size_t i = mark.events; i < m_events.size(); ++i) {
            const Event& e = m_events[i];
            if (e.kind != Event::Kind::added)
                for (const VertexId v : e.was.vertices()) visit(v);
            if (e.kind != Event::Kind::removed)
                for (const VertexId v : e.now.vertices()) visit(v);
        }
    }

    void element_removed(const Mesh& mesh, ElementId element, const Simplex& was) override;
    void element_changed(const Mesh& mesh, ElementId element, const Simplex& was) override;
    void element_added(const Mesh& mesh, ElementId element) override;
    void vertices_moved(const Mesh& mesh, std::span<const VertexId> moved, PositionSet which) override;

private:
    std::vector<ElementId> m_touched;
    std::vector<ElementId> m_added;
    std::vector<VertexId> m_moved;
    std::vector<Event> m_events;
};

}  // namespace sxk
