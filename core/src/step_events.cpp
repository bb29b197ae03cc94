// StepEvents (step_events.hpp): what edits did, from their watcher events.
#include "sxk/step_events.hpp"

#include <algorithm>

namespace sxk {

void StepEvents::element_removed(const Mesh&, ElementId, const Simplex& was) {
    m_events.push_back({Event::Kind::removed, was, Simplex{}});
}

void StepEvents::element_changed(const Mesh& mesh, ElementId element, const Simplex& was) {
    m_touched.push_back(element);
    m_events.push_back({Event::Kind::changed, was, mesh.simplex(element)});
}

void StepEvents::element_added(const Mesh& mesh, ElementId element) {
    m_touched.push_back(element);
    m_added.push_back(element);
    m_events.push_back({Event::Kind::added, Simplex{}, mesh.simplex(element)});
}

void StepEvents::vertices_moved(const Mesh&, std::span<const VertexId> moved, PositionSet) {
    m_moved.insert(m_moved.end(), moved.begin(), moved.end());
}

void StepEvents::truncate(const Mark& mark) {
    m_touched.resize(std::min(mark.touched, m_touched.size()));
    m_added.resize(std::min(mark.added, m_added.size()));
    m_moved.resize(std::min(mark.moved, m_moved.size()));
    m_events.resize(std::min(mark.events, m_events.size()));
}

std::vector<ElementId> StepEvents::created_since(const Mesh& mesh, const Mark& mark) const {
    std::vector<ElementId> ids(m_touched.begin() + static_cast<std::ptrdiff_t>(mark.touched), m_touched.end());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::erase_if(ids, [&](ElementId t) { return !mesh.is_element(t); });
    return ids;
}

std::vector<Simplex> StepEvents::removed_since(const Mark& mark) const {
    // an element the edits made and then removed again was not there before: the simplexes made
    // so far are matched off first
    std::vector<Simplex> made, gone;
    auto made_before = [&](const Simplex& s) {
        const auto it = std::find(made.begin(), made.end(), s);
        if (it == made.end()) return false;
        made.erase(it);
        return true;
    };
    for (std::size_t i = mark.events; i < m_events.size(); ++i) {
        const Event& e = m_events[i];
        if (e.kind != Event::Kind::added && !made_before(e.was)) gone.push_back(e.was);
        if (e.kind != Event::Kind::removed) made.push_back(e.now);
    }
    return gone;
}

}  // namespace sxk
