// MoveJournal (move_journal.hpp): undo of a multi-edit removal move.
#include "move_journal.hpp"

#include <algorithm>

#include "sxk/traversal.hpp"

namespace sxk::degeneracy::detail {

void MoveJournal::begin(std::span<const VertexId> vertices) {
    m_log_start = m_log.size();
    m_vertex_count = m_mesh.vertex_count();
    m_element_count = m_mesh.element_count();
    std::vector<ElementId> around;
    for (const VertexId v : vertices)
        if (m_mesh.vertex_element(v) != invalid_id) collect_star(m_mesh, v, m_mesh.vertex_element(v), around);
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    m_elements.clear();
    m_labels.clear();
    m_face_labels.clear();
    for (const ElementId t : around) {
        m_elements.emplace_back(t, m_mesh.simplex(t));
        m_labels.push_back(m_mesh.label(t));
        if (m_mesh.face_labels().empty()) continue;
        for (int i = 0; i < m_mesh.simplex(t).count(); ++i) {
            const Simplex key(+1, m_mesh.simplex(t).subn(i).vertices());
            const auto label = m_mesh.face_labels().find(key);
            if (label != m_mesh.face_labels().end()) m_face_labels.emplace_back(key, label->second);
        }
    }
}

std::vector<ElementId> MoveJournal::created() const {
    std::vector<ElementId> ids(m_log.begin() + static_cast<std::ptrdiff_t>(m_log_start), m_log.end());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::erase_if(ids, [&](ElementId t) { return !m_mesh.is_element(t); });
    return ids;
}

std::vector<Simplex> MoveJournal::removed() const {
    std::vector<Simplex> gone;
    for (const auto& [t, simplex] : m_elements)
        if (!m_mesh.is_element(t) || m_mesh.simplex(t) != simplex) gone.push_back(simplex);
    return gone;
}

bool MoveJournal::undo() {
    const std::vector<ElementId> now = created();
    std::vector<Simplex> gone;
    std::vector<int> labels;
    for (std::size_t i = 0; i < m_elements.size(); ++i) {
        const auto& [t, simplex] = m_elements[i];
        if (m_mesh.is_element(t) && m_mesh.simplex(t) == simplex) continue;
        gone.push_back(simplex);
        labels.push_back(m_labels[i]);
    }
    // An element the move made that is one of the remembered ones (same vertices) is replaced
    // by itself: harmless. The counts must come back to where they were.
    if (m_mesh.element_count() - now.size() + gone.size() != m_element_count) return false;
    std::vector<Simplex> new_faces;
    if (!m_mesh.face_labels().empty())
        for (const ElementId t : now)
            for (int i = 0; i < m_mesh.simplex(t).count(); ++i)
                new_faces.emplace_back(+1, m_mesh.simplex(t).subn(i).vertices());
    if (!m_mesh.replace_elements(now, gone, labels)) return false;
    for (const Simplex& face : new_faces) m_mesh.face_labels().erase(face);
    for (const auto& [face, label] : m_face_labels) m_mesh.face_labels()[face] = label;
    while (m_mesh.vertex_count() > m_vertex_count)
        if (!m_mesh.remove_last_vertex()) return false;
    return true;
}

}  // namespace sxk::degeneracy::detail
