// Which nodes a movement of the needle's tip makes needle nodes (thesis §6.4): "when the needle
// tip enters an element through an edge, the closest node of the edge is marked as a needle
// node". In 3D the tip enters a tetrahedron through a face: the closest node of the face. A needle
// with a radius takes every node its cross-section sweeps over too.
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

// A needle of `radius` > 0: the vertices within `radius` of the tip's path [from, to] (deformed
// positions) that are not ahead of the tip (their offset from `to` along `axis`, the needle's unit
// direction from base to tip, is at most 0): the material the needle's cross-section enters. The
// thesis' 3D needle is "represented in the mesh by a jagged surface" (Fig. 6.14): these nodes,
// held to the needle, are that surface and what it encloses. Candidates: the elements with a
// vertex in the path's box widened by `radius` (the index's box query). Sorted, without repeats.
std::vector<VertexId> nodes_within_radius(const Mesh& mesh, const SpatialIndex& deformed, const Point& from,
                                          const Point& to, const Point& axis, double radius);

}  // namespace sxk::needle
