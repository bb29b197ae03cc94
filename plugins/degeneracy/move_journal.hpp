// Undo for one removal move (a split and a collapse, or a collapse): what the move removed is
// remembered before, and put back if the move made new flat elements. The kernel's edits are
// transactions one by one; a move of two or three edits needs this to be one.
//
//   begin(vertices of t)          the elements of their stars (every element a move on t can
//                                 remove: split_edge removes star(ab), split_face the two
//                                 elements of abc, collapse_edge star(from), all inside them)
//   ... the move's edits ...      the watcher log records what they created
//   created()                     the move's new elements still in the mesh
//   undo()                        ONE replace_elements: created() -> the remembered elements
//                                 that are gone, with their labels; face labels restored; the
//                                 move's new vertices (in no element now) removed
#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "sxk/mesh.hpp"

namespace sxk::degeneracy::detail {

class MoveJournal {
public:
    // `created_log`: the ids the mesh's watcher reports as added or changed, appended in order.
    MoveJournal(Mesh& mesh, const std::vector<ElementId>& created_log) : m_mesh(mesh), m_log(created_log) {}

    void begin(std::span<const VertexId> vertices);
    std::vector<ElementId> created() const;
    // The remembered elements the move removed (by their vertices).
    std::vector<Simplex> removed() const;
    // True when the mesh changed since begin().
    bool changed() const { return m_log.size() != m_log_start || m_mesh.vertex_count() != m_vertex_count; }
    // False when the mesh could not be put back exactly (the move removed an element outside
    // the remembered stars, or replace_elements refused): the move then stays.
    bool undo();

private:
    Mesh& m_mesh;
    const std::vector<ElementId>& m_log;
    std::size_t m_log_start = 0;
    std::size_t m_vertex_count = 0;
    std::size_t m_element_count = 0;
    std::vector<std::pair<ElementId, Simplex>> m_elements;
    std::vector<int> m_labels;
    std::vector<std::pair<Simplex, int>> m_face_labels;  // labels of the remembered elements' faces
};

}  // namespace sxk::degeneracy::detail
