// Mesh::compact_vertices: drops the vertices that are in no element.
#include <array>

#include "sxk/mesh.hpp"

namespace sxk {

Outcome<std::vector<VertexId>> Mesh::compact_vertices() {
    if (m_undo != nullptr)
        return Refusal{RefusalCode::not_applicable,
                       "compact_vertices: not inside an EditJournal step"};
    const std::size_t n = vertex_count();
    std::vector<VertexId> renamed(n, invalid_id);
    VertexId kept = 0;
    for (std::size_t v = 0; v < n; ++v)
        if (m_vertex_element[v] != invalid_id) renamed[v] = kept++;
    if (kept == n) return renamed;

    // The renaming keeps the order of the ids, so every canonical simplex stays canonical with
    // its sign: elements and faces keep their ids and slots, only their vertex ids change.
    for (std::size_t v = 0; v < n; ++v) {
        const VertexId to = renamed[v];
        if (to == invalid_id || to == v) continue;
        m_reference[to] = m_reference[v];
        m_deformed[to] = m_deformed[v];
        m_vertex_element[to] = m_vertex_element[v];
        for (detail::AttributeColumn& a : m_attributes) {
            const auto c = static_cast<std::size_t>(a.components);
            for (std::size_t i = 0; i < c; ++i) a.values[to * c + i] = a.values[v * c + i];
        }
    }
    m_reference.resize(kept);
    m_deformed.resize(kept);
    m_vertex_element.resize(kept);
    for (detail::AttributeColumn& a : m_attributes) a.values.resize(kept * static_cast<std::size_t>(a.components));
    auto rename = [&](const Simplex& s) {
        std::array<VertexId, 4> vertices{};
        for (int j = 0; j < s.count(); ++j) vertices[static_cast<std::size_t>(j)] = renamed[s.vertex(j)];
        return Simplex(s.sign(), std::span<const VertexId>(vertices.data(), static_cast<std::size_t>(s.count())));
    };
    for (ElementRecord& e : m_elements)
        if (e.simplex.count() != 0) e.simplex = rename(e.simplex);
    // the boundary map is keyed by vertices: built again from the faces without a mate
    m_boundary.clear();
    for (FaceId f = 0; f < m_faces.size(); ++f)
        if (m_faces[f].element != invalid_id && m_faces[f].mate == invalid_id) m_boundary.insert(face_simplex(f), f);
    // a label of a face with a dropped vertex names no face of the mesh (a lenient read keeps
    // such labels): it goes with the vertex
    FaceLabels labels;
    for (const auto& [face, label] : m_face_labels) {
        bool named = true;
        for (const VertexId v : face.vertices()) named = named && renamed[v] != invalid_id;
        if (named) labels.emplace(rename(face), label);
    }
    m_face_labels = std::move(labels);
    ++m_revision;
    for (Watcher* w : m_watchers) w->init(*this);
    return renamed;
}

}  // namespace sxk
