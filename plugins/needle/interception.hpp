// Which nodes a movement of the needle's tip makes needle nodes (thesis §6.4): "when the needle
// tip enters an element through an edge, the closest node of the edge is marked as a needle
// node". In 3D the tip enters a tetrahedron through a face: the closest node of the face.
#pragma once

#include <vector>

#include "sxk/locate.hpp"

namespace sxk::needle {

// For every edge (triangle mesh) or face (tetrahedral mesh) the closed segment [from, to] meets,
// decided exactly in the deformed positions, the vertex of it nearest the crossing (ties: the
// smaller id); an edge the segment runs along gives its vertices on the segment. The candidates
// are the elements `deformed` (an index over the deformed positions) finds along the segment.
// Sorted, without repeats.
std::vector<VertexId> intercepted_nodes(const Mesh& mesh, const SpatialIndex& deformed, const Point& from,
                                        const Point& to);

}  // namespace sxk::needle
