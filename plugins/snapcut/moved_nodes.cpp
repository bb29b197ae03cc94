// Moved nodes (moved_nodes.hpp): the radii of snapped nodes follow the moves of their neighbours.
#include "moved_nodes.hpp"

#include "sxk/traversal.hpp"

namespace sxk::snapcut {
namespace {

// Beyond this many moved vertices every snapped node's star is walked instead: a simulation
// frame moves them all, and the snapped nodes (a few thousand on the 1.2M femur) are fewer.
constexpr std::size_t most_followed = 4096;

}  // namespace

MovedNodes::MovedNodes(Mesh& mesh) : m_mesh(mesh) { mesh.add_watcher(*this); }

MovedNodes::~MovedNodes() { m_mesh.remove_watcher(*this); }

void MovedNodes::cover(const Mesh& mesh, CutMarks& marks) {
    if (m_all) {
        marks.cover_all(mesh);
    } else {
        std::vector<ElementId> around;
        for (const VertexId v : m_moved)
            if (mesh.vertex_element(v) != invalid_id) collect_star(mesh, v, mesh.vertex_element(v), around);
        marks.cover_elements(mesh, around);
    }
    m_moved.clear();
    m_all = false;
}

void MovedNodes::vertices_moved(const Mesh& /*mesh*/, std::span<const VertexId> vertices, PositionSet which) {
    if (!writes_deformed(which) || m_all) return;
    if (m_moved.size() + vertices.size() > most_followed) {
        m_all = true;
        m_moved.clear();
        return;
    }
    m_moved.insert(m_moved.end(), vertices.begin(), vertices.end());
}

}  // namespace sxk::snapcut
