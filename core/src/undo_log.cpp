// The EditJournal's record (undo_log.hpp): the mesh's recorded stores, and their replay.
#include "undo_log.hpp"

#include <algorithm>
#include <type_traits>

#include "moving_vertices.hpp"

namespace sxk {

// ---- what the mesh notes ------------------------------------------------------------------------

void Mesh::note_element(ElementId t) {
    m_noted.elements.grow(std::size_t{t} + 1);
    if (m_noted.elements.mark(t)) m_undo->element(*this, t);
}
void Mesh::note_face(FaceId f) {
    m_noted.faces.grow(std::size_t{f} + 1);
    if (m_noted.faces.mark(f)) m_undo->face(*this, f);
}
void Mesh::new_record_stretch() {
    m_noted.elements.new_round(m_elements.size());
    m_noted.faces.new_round(m_faces.size());
}
void Mesh::note_anchor(VertexId v) { m_undo->anchor(*this, v); }
void Mesh::note_pools() {
    if (m_undo != nullptr) m_undo->pools(*this);
}

void Mesh::boundary_insert(const Simplex& sigma, FaceId f) {
    if (m_undo != nullptr) m_undo->boundary_inserted(sigma);
    m_boundary.insert(sigma, f);
}

void Mesh::boundary_erase(const Simplex& sigma) {
    if (m_undo != nullptr) {
        const FaceId f = m_boundary.find(sigma);
        if (f == invalid_id) return;
        m_undo->boundary_erased(sigma, f);
    }
    m_boundary.erase(sigma);
}

namespace detail {

void UndoLog::face_label(const Mesh& mesh, const Simplex& key) {
    const auto it = mesh.m_face_labels.find(key);
    m_entries.emplace_back(FaceLabelWas{key, it == mesh.m_face_labels.end() ? std::nullopt
                                                                             : std::optional<int>(it->second)});
}

void UndoLog::attribute(const Mesh& mesh, AttributeId a, VertexId v) {
    const std::span<const double> value = mesh.vertex_attribute(a, v);
    m_entries.emplace_back(AttributeWas{a, v, m_values.size()});
    m_values.insert(m_values.end(), value.begin(), value.end());
}

void UndoLog::element_attribute(const Mesh& mesh, AttributeId a, ElementId t) {
    const std::span<const double> value = mesh.element_attribute(a, t);
    m_entries.emplace_back(ElementAttributeWas{a, t, m_values.size()});
    m_values.insert(m_values.end(), value.begin(), value.end());
}

void UndoLog::vertex_removed(const Mesh& mesh) {
    const auto v = static_cast<VertexId>(mesh.vertex_count() - 1);
    m_entries.emplace_back(VertexRemoved{mesh.m_reference[v], mesh.m_deformed[v], mesh.m_vertex_element[v],
                                         m_values.size()});
    for (const detail::AttributeColumn& a : mesh.m_attributes) {
        const auto n = static_cast<std::size_t>(a.components);
        m_values.insert(m_values.end(), a.values.begin() + static_cast<std::ptrdiff_t>(v * n),
                        a.values.begin() + static_cast<std::ptrdiff_t>((v + 1) * n));
    }
}

namespace {

// What watchers knew of a touched element or face before the replay, to report the difference
// once it is done (the same events, in the same order, as an edit: watcher.hpp).
struct ElementState {
    ElementId id;
    bool alive;
    Simplex simplex;
};
struct FaceState {
    FaceId id;
    bool boundary;  // alive and without a mate
    Simplex simplex;
};

template <class T>
void sort_unique(std::vector<T>& ids) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

}  // namespace

void UndoLog::undo(Mesh& mesh, std::size_t first, UndoLog* inverse) {
    // ---- what the watchers know: the touched ids, before -------------------------------------
    const bool tell = !mesh.m_watchers.empty();
    std::vector<ElementId> elements;
    std::vector<FaceId> faces;
    std::vector<VertexId> moved;
    if (tell) {
        for (std::size_t i = first; i < m_entries.size(); ++i) {
            if (const auto* e = std::get_if<ElementWas>(&m_entries[i])) elements.push_back(e->id);
            else if (const auto* f = std::get_if<FaceWas>(&m_entries[i])) faces.push_back(f->id);
            else if (const auto* p = std::get_if<PositionWas>(&m_entries[i])) moved.push_back(p->vertex);
        }
        sort_unique(elements);
        // a face whose element changes its simplex changes its own (invariant 7.1) without a
        // store into the face pool: the faces of touched elements count as touched
        const int k = mesh.element_vertex_count();
        for (ElementId t : elements)
            if (mesh.is_element(t))
                for (int j = 0; j < k; ++j) faces.push_back(mesh.face(t, j));
        sort_unique(faces);
        sort_unique(moved);
    }
    auto element_state = [&](ElementId t) {
        const bool alive = mesh.is_element(t);
        return ElementState{t, alive, alive ? mesh.simplex(t) : Simplex{}};
    };
    auto face_state = [&](FaceId f) {
        const bool boundary = mesh.is_face(f) && mesh.is_element(mesh.face_element(f)) && mesh.mate(f) == invalid_id;
        return FaceState{f, boundary, boundary ? mesh.face_simplex(f) : Simplex{}};
    };
    std::vector<ElementState> elements_before;
    std::vector<FaceState> faces_before;
    for (ElementId t : elements) elements_before.push_back(element_state(t));
    for (FaceId f : faces) faces_before.push_back(face_state(f));

    // ---- the replay -----------------------------------------------------------------------------
    for (std::size_t i = m_entries.size(); i-- > first;) {
        std::visit(
            [&](auto& entry) {
                using E = std::decay_t<decltype(entry)>;
                if constexpr (std::is_same_v<E, ElementWas>) {
                    if (inverse) inverse->element(mesh, entry.id);
                    mesh.m_elements[entry.id] = entry.record;
                } else if constexpr (std::is_same_v<E, FaceWas>) {
                    if (inverse) inverse->face(mesh, entry.id);
                    mesh.m_faces[entry.id] = entry.record;
                } else if constexpr (std::is_same_v<E, AnchorWas>) {
                    if (inverse) inverse->anchor(mesh, entry.vertex);
                    mesh.count_anchor(mesh.m_vertex_element[entry.vertex], entry.anchor);
                    mesh.m_vertex_element[entry.vertex] = entry.anchor;
                } else if constexpr (std::is_same_v<E, PoolsWere>) {
                    if (inverse) inverse->pools(mesh);
                    mesh.m_free_element = entry.free_element;
                    mesh.m_free_face = entry.free_face;
                    mesh.m_element_count = entry.element_count;
                    // ids past the old sizes were handed out by the step (their records were
                    // put back above, to the empty record they started as)
                    mesh.m_elements.resize(entry.elements);
                    mesh.m_faces.resize(entry.faces);
                } else if constexpr (std::is_same_v<E, BoundaryInserted>) {
                    if (inverse) inverse->boundary_erased(entry.key, mesh.m_boundary.find(entry.key));
                    mesh.m_boundary.erase(entry.key);
                } else if constexpr (std::is_same_v<E, BoundaryErased>) {
                    if (inverse) inverse->boundary_inserted(entry.key);
                    mesh.m_boundary.insert(entry.key, entry.face);
                } else if constexpr (std::is_same_v<E, PositionWas>) {
                    if (inverse) inverse->position(mesh, entry.vertex);
                    mesh.m_reference[entry.vertex] = entry.reference;
                    mesh.m_deformed[entry.vertex] = entry.deformed;
                } else if constexpr (std::is_same_v<E, FaceLabelWas>) {
                    if (inverse) inverse->face_label(mesh, entry.key);
                    if (entry.label)
                        mesh.m_face_labels[entry.key] = *entry.label;
                    else
                        mesh.m_face_labels.erase(entry.key);
                } else if constexpr (std::is_same_v<E, AttributeWas>) {
                    if (inverse) inverse->attribute(mesh, entry.attribute, entry.vertex);
                    const std::span<double> value = mesh.vertex_attribute(entry.attribute, entry.vertex);
                    std::copy_n(m_values.begin() + static_cast<std::ptrdiff_t>(entry.offset), value.size(),
                                value.begin());
                } else if constexpr (std::is_same_v<E, ElementAttributeWas>) {
                    if (inverse) inverse->element_attribute(mesh, entry.attribute, entry.element);
                    const std::span<double> value = mesh.element_attribute(entry.attribute, entry.element);
                    std::copy_n(m_values.begin() + static_cast<std::ptrdiff_t>(entry.offset), value.size(),
                                value.begin());
                } else if constexpr (std::is_same_v<E, VertexAdded>) {
                    if (inverse) inverse->vertex_removed(mesh);
                    mesh.m_reference.pop_back();
                    mesh.m_deformed.pop_back();
                    mesh.count_anchor(mesh.m_vertex_element.back(), invalid_id);
                    mesh.m_vertex_element.pop_back();
                    for (detail::AttributeColumn& a : mesh.m_attributes)
                        a.values.resize(a.values.size() - static_cast<std::size_t>(a.components));
                } else if constexpr (std::is_same_v<E, VertexRemoved>) {
                    if (inverse) inverse->vertex_added();
                    mesh.m_reference.push_back(entry.reference);
                    mesh.m_deformed.push_back(entry.deformed);
                    mesh.m_vertex_element.push_back(entry.anchor);
                    mesh.count_anchor(invalid_id, entry.anchor);
                    // a vertex back at an id a watcher may have seen another vertex at (one the
                    // step added and a rollback took away): its position is news, told as a move
                    if (tell) moved.push_back(static_cast<VertexId>(mesh.m_reference.size() - 1));
                    std::size_t at = entry.offset;
                    for (detail::AttributeColumn& a : mesh.m_attributes) {
                        const auto n = static_cast<std::size_t>(a.components);
                        a.values.insert(a.values.end(), m_values.begin() + static_cast<std::ptrdiff_t>(at),
                                        m_values.begin() + static_cast<std::ptrdiff_t>(at + n));
                        at += n;
                    }
                }
            },
            m_entries[i]);
    }
    m_entries.resize(first);
    ++mesh.m_revision;
    if (!tell) return;

    // ---- the net change, told once ------------------------------------------------------------
    std::vector<ElementState> elements_after;
    std::vector<FaceState> faces_after;
    for (ElementId t : elements) elements_after.push_back(element_state(t));
    for (FaceId f : faces) faces_after.push_back(face_state(f));
    sort_unique(moved);
    moved.erase(std::remove_if(moved.begin(), moved.end(), [&](VertexId v) { return v >= mesh.vertex_count(); }),
                moved.end());
    const MovingVertices moving(mesh, moved);
    for (Watcher* w : mesh.m_watchers) {
        for (std::size_t i = 0; i < elements.size(); ++i) {
            const ElementState &was = elements_before[i], &now = elements_after[i];
            if (was.alive && !now.alive) w->element_removed(mesh, was.id, was.simplex);
        }
        for (std::size_t i = 0; i < elements.size(); ++i) {
            const ElementState &was = elements_before[i], &now = elements_after[i];
            if (was.alive && now.alive && !(was.simplex == now.simplex))
                w->element_changed(mesh, was.id, was.simplex);
        }
        for (std::size_t i = 0; i < elements.size(); ++i)
            if (!elements_before[i].alive && elements_after[i].alive) w->element_added(mesh, elements[i]);
        for (std::size_t i = 0; i < faces.size(); ++i)
            if (faces_before[i].boundary && !faces_after[i].boundary)
                w->boundary_removed(mesh, faces[i], faces_before[i].simplex);
        for (std::size_t i = 0; i < faces.size(); ++i)
            if (faces_before[i].boundary && faces_after[i].boundary &&
                !(faces_before[i].simplex == faces_after[i].simplex))
                w->boundary_changed(mesh, faces[i], faces_before[i].simplex);
        for (std::size_t i = 0; i < faces.size(); ++i)
            if (!faces_before[i].boundary && faces_after[i].boundary) w->boundary_added(mesh, faces[i]);
        if (!moved.empty()) w->vertices_moved(mesh, moved, PositionSet::both);
    }
}

}  // namespace detail
}  // namespace sxk
