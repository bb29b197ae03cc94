// The vertices that moved between two looks of the selection: a simulation frame, the caller's
// own moves, the cut's snaps and the degeneracy removal's edits. A snapped node's star, as the
// selection sees it, reaches farther when a corner of it moves away (CutMarks::radius), and
// CutMarks::elements_near would then miss elements that meet the sweep: `cover` widens the radii
// of the snapped nodes around the moves before the selection looks again.
#pragma once

#include <span>
#include <vector>

#include "face_selection.hpp"
#include "sxk/mesh.hpp"
#include "sxk/watcher.hpp"

namespace sxk::snapcut {

class MovedNodes final : public Watcher {
public:
    explicit MovedNodes(Mesh& mesh);
    ~MovedNodes() override;
    MovedNodes(const MovedNodes&) = delete;
    MovedNodes& operator=(const MovedNodes&) = delete;

    // Widens the radii of the snapped nodes around the vertices moved since the last call (every
    // snapped node's after a move of many, a simulation frame), then forgets the moves.
    void cover(const Mesh& mesh, CutMarks& marks);

    void vertices_moved(const Mesh& mesh, std::span<const VertexId> vertices, PositionSet which) override;

private:
    Mesh& m_mesh;
    std::vector<VertexId> m_moved;
    bool m_all = false;  // more moved than are worth a star each
};

}  // namespace sxk::snapcut
