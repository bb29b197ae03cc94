// How a total force is shared among the vertices it acts on (`sxk deform --force ... --share`).
#pragma once

#include <span>
#include <vector>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/plugins/elasticity.hpp"  // Share

namespace sxk::elasticity {

// The parts (summing to 1) of `vertices` (sorted, in elements) in a total force. By area: each
// boundary face whose corners are all selected (a triangle of a tetrahedral mesh, an edge of a
// triangle mesh) gives each corner an equal part of its area (length), in reference positions:
// the consistent nodal loads of a uniform traction on linear elements. Refuses (not_found) by
// area when no boundary face has all its corners selected.
Outcome<std::vector<double>> load_shares(const Mesh& mesh, std::span<const VertexId> vertices,
                                         Share share);

}  // namespace sxk::elasticity
