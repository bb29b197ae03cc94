// Mesh basics: construction, pools, accessors, watchers. The edit primitives live in files of
// their own (assign_elements.cpp, replace_elements.cpp, change_elements.cpp, validate.cpp).
#include "sxk/mesh.hpp"

#include <algorithm>

#include "undo_log.hpp"
#include <stdexcept>
#include <string>

namespace sxk {

Mesh::Mesh(int topological_dimension, int ambient_dimension)
    : m_dimension(topological_dimension), m_ambient(ambient_dimension) {
    if (topological_dimension < 2 || topological_dimension > 3)
        throw std::invalid_argument("topological dimension must be 2 or 3, not " +
                                    std::to_string(topological_dimension));
    if (ambient_dimension < topological_dimension || ambient_dimension > 3)
        throw std::invalid_argument("ambient dimension must be " +
                                    std::string(topological_dimension == 2 ? "2 or 3" : "3") +
                                    ", not " + std::to_string(ambient_dimension));
}

Mesh::Mesh(const Mesh& other)
    : m_dimension(other.m_dimension),
      m_ambient(other.m_ambient),
      m_reference(other.m_reference),
      m_deformed(other.m_deformed),
      m_vertex_element(other.m_vertex_element),
      m_vertices_in_elements(other.m_vertices_in_elements),
      m_elements(other.m_elements),
      m_faces(other.m_faces),
      m_free_element(other.m_free_element),
      m_free_face(other.m_free_face),
      m_element_count(other.m_element_count),
      m_boundary(other.m_boundary),
      m_face_labels(other.m_face_labels),
      m_label_names(other.m_label_names),
      m_attributes(other.m_attributes),
      m_element_attributes(other.m_element_attributes) {}

Mesh& Mesh::operator=(const Mesh& other) {
    if (this != &other) {
        if (m_undo != nullptr) throw std::logic_error("Mesh: assigned to inside an open EditJournal step");
        Mesh copy(other);
        copy.m_watchers = std::move(m_watchers);
        copy.m_journal = m_journal;
        copy.m_revision = m_revision + 1;  // a history of the old content no longer fits
        *this = std::move(copy);
        // the watchers stay with this mesh, whose content is new to them
        for (Watcher* w : m_watchers) w->init(*this);
    }
    return *this;
}

void Mesh::recount_anchors() {
    m_vertices_in_elements = static_cast<std::size_t>(
        std::count_if(m_vertex_element.begin(), m_vertex_element.end(), [](ElementId a) { return a != invalid_id; }));
}

Mesh::Mesh(Mesh&& other) noexcept = default;
Mesh& Mesh::operator=(Mesh&& other) noexcept = default;
Mesh::~Mesh() = default;

VertexId Mesh::add_vertex(const Point& reference, const Point& deformed) {
    if (m_undo != nullptr) m_undo->vertex_added();
    ++m_revision;
    m_reference.push_back(reference);
    m_deformed.push_back(deformed);
    m_vertex_element.push_back(invalid_id);
    for (detail::AttributeColumn& a : m_attributes)
        a.values.insert(a.values.end(), a.default_value.begin(), a.default_value.end());
    return static_cast<VertexId>(m_reference.size() - 1);
}

void Mesh::reserve(std::size_t vertices, std::size_t elements) {
    m_reference.reserve(vertices);
    m_deformed.reserve(vertices);
    m_vertex_element.reserve(vertices);
    for (detail::AttributeColumn& a : m_attributes)
        a.values.reserve(vertices * static_cast<std::size_t>(a.components));
    m_elements.reserve(elements);
    m_faces.reserve(elements * static_cast<std::size_t>(m_dimension + 1));
    for (detail::AttributeColumn& a : m_element_attributes)
        a.values.reserve(elements * static_cast<std::size_t>(a.components));
    size_move_scratch();
}

VertexId Mesh::opposite_vertex(ElementId t, FaceId f) const {
    // faces[i] represents simplex.subn(i), the face without vertex i (invariant 7.1)
    const ElementRecord& e = m_elements[t];
    for (int i = 0; i <= m_dimension; ++i)
        if (e.faces[static_cast<std::size_t>(i)] == f) return e.simplex.vertex(i);
    return invalid_id;
}

FaceId Mesh::opposite_face(ElementId t, VertexId v) const {
    const int i = m_elements[t].simplex.index(v);
    return i < 0 ? FaceId{invalid_id} : m_elements[t].faces[static_cast<std::size_t>(i)];
}

int Mesh::face_slot(FaceId f) const {
    const ElementRecord& e = m_elements[m_faces[f].element];
    for (int i = 0; i <= m_dimension; ++i)
        if (e.faces[static_cast<std::size_t>(i)] == f) return i;
    return -1;
}

Simplex Mesh::face_simplex(FaceId f) const {
    return m_elements[m_faces[f].element].simplex.subn(face_slot(f));
}

FaceId Mesh::find_boundary_face(const Simplex& sigma) const {
    const FaceId f = m_boundary.find(sigma);
    if (f == invalid_id || !(face_simplex(f) == sigma)) return invalid_id;
    return f;
}

std::vector<FaceId> Mesh::boundary_faces() const {
    std::vector<FaceId> faces;
    faces.reserve(m_boundary.size());
    for_each_boundary_face([&](FaceId f) { faces.push_back(f); });
    std::sort(faces.begin(), faces.end());
    return faces;
}

ElementId Mesh::allocate_element() {
    if (m_free_element != invalid_id) {
        const ElementId t = m_free_element;
        m_free_element = ElementId{m_elements[t].faces[0]};  // a free element links the next in faces[0]
        element_for_write(t) = ElementRecord{};
        ++m_element_count;
        return t;
    }
    // a fresh id needs no record: a rollback cuts the pool back to its size (note_pools); the
    // element attributes keep their grown rows (they are at least the pool's size)
    m_elements.emplace_back();
    ++m_element_count;
    if (!m_element_attributes.empty()) grow_element_attributes();
    return static_cast<ElementId>(m_elements.size() - 1);
}

void Mesh::free_element(ElementId t) {
    ElementRecord& e = element_for_write(t);
    e = ElementRecord{};
    e.faces[0] = FaceId{m_free_element};  // the free list's link (allocate_element)
    m_free_element = t;
    --m_element_count;
}

FaceId Mesh::allocate_face() {
    if (m_free_face != invalid_id) {
        const FaceId f = m_free_face;
        m_free_face = m_faces[f].mate;
        face_for_write(f) = FaceRecord{};
        return f;
    }
    m_faces.emplace_back();
    return static_cast<FaceId>(m_faces.size() - 1);
}

void Mesh::free_face(FaceId f) {
    face_for_write(f) = FaceRecord{invalid_id, m_free_face};
    m_free_face = f;
}

void Mesh::add_watcher(Watcher& watcher) {
    if (std::find(m_watchers.begin(), m_watchers.end(), &watcher) == m_watchers.end())
        m_watchers.push_back(&watcher);
    watcher.init(*this);
}

void Mesh::remove_watcher(Watcher& watcher) {
    m_watchers.erase(std::remove(m_watchers.begin(), m_watchers.end(), &watcher), m_watchers.end());
}

std::size_t Mesh::memory_bytes() const {
    std::size_t attributes =
        (m_attributes.capacity() + m_element_attributes.capacity()) * sizeof(detail::AttributeColumn);
    for (const auto* table : {&m_attributes, &m_element_attributes})
        for (const detail::AttributeColumn& a : *table)
            attributes += a.name.capacity() + (a.default_value.capacity() + a.values.capacity()) * sizeof(double);
    return attributes + m_reference.capacity() * sizeof(Point) + m_deformed.capacity() * sizeof(Point) +
           m_vertex_element.capacity() * sizeof(ElementId) +
           m_elements.capacity() * sizeof(ElementRecord) + m_faces.capacity() * sizeof(FaceRecord) +
           m_boundary.memory_bytes();
}

void Mesh::link_neighbor(ElementId t, int i) {
    ElementRecord& e = element_for_write(t);
    const FaceId g = m_faces[e.faces[static_cast<std::size_t>(i)]].mate;
    if (g == invalid_id) {
        e.neighbors[static_cast<std::size_t>(i)] = invalid_id;
        return;
    }
    const ElementId n = m_faces[g].element;
    e.neighbors[static_cast<std::size_t>(i)] = n;
    const ElementRecord& other = m_elements[n];
    for (int j = 0; j <= m_dimension; ++j)
        if (other.faces[static_cast<std::size_t>(j)] == g) element_for_write(n).neighbors[static_cast<std::size_t>(j)] = t;
}

void Mesh::link_neighbors(ElementId t) {
    for (int i = 0; i <= m_dimension; ++i) link_neighbor(t, i);
}

void Mesh::unlink_neighbor(FaceId f) {
    const ElementId t = m_faces[f].element;
    for (int j = 0; j <= m_dimension; ++j)
        if (m_elements[t].faces[static_cast<std::size_t>(j)] == f)
            element_for_write(t).neighbors[static_cast<std::size_t>(j)] = invalid_id;
}

void Mesh::repair_anchors(std::span<const Simplex> added, std::span<const ElementId> added_ids,
                          std::span<const VertexId> old_vertices,
                          std::span<const ElementId> neighbours,
                          std::span<const ElementId> edited_sorted) {
    // An anchor outside the edited elements is an element the edit did not touch, which holds
    // its vertex as before (anchors were valid): only anchors into edited (freed, reused or
    // substituted) elements are looked at, so untouched elements are never loaded.
    auto holds = [&](ElementId a, VertexId v) {
        if (a == invalid_id) return false;
        if (!std::binary_search(edited_sorted.begin(), edited_sorted.end(), a)) return true;
        return is_element(a) && m_elements[a].simplex.contains(v);
    };
    for (std::size_t i = 0; i < added.size(); ++i)
        for (VertexId v : added[i].vertices())
            if (!holds(m_vertex_element[v], v)) set_anchor(v, added_ids[i]);
    for (VertexId v : old_vertices) {
        const ElementId a = m_vertex_element[v];
        if (holds(a, v)) continue;
        ElementId anchor = invalid_id;
        for (ElementId n : neighbours)
            if (m_elements[n].simplex.contains(v)) {
                anchor = n;
                break;
            }
        set_anchor(v, anchor);
    }
}

}  // namespace sxk
