// MovingVertices: the vertices of the move being told to watchers, for
// Mesh::elements_around_moved (sxk/mesh.hpp). Mesh::move_vertices and set_position hold one
// while they check and tell, the EditJournal's undo and redo (undo_log.cpp) while they tell
// the positions they put back.
#pragma once

#include <span>

#include "sxk/mesh.hpp"

namespace sxk {

// While a move is checked and told: the vertices whose stars elements_around_moved() gives. A
// watcher that moves vertices in turn gets its own, and the outer move's are found again after.
class MovingVertices {
public:
    MovingVertices(Mesh& mesh, std::span<const VertexId> vertices) : m_mesh(mesh), m_outer(mesh.m_moving) {
        m_mesh.m_moving = vertices;
        m_mesh.m_around_moved_found = false;
    }
    ~MovingVertices() {
        m_mesh.m_moving = m_outer;
        m_mesh.m_around_moved_found = false;
    }
    MovingVertices(const MovingVertices&) = delete;
    MovingVertices& operator=(const MovingVertices&) = delete;

private:
    Mesh& m_mesh;
    std::span<const VertexId> m_outer;
};

}  // namespace sxk
