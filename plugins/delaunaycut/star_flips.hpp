// Lawson's flips around one node (thesis §5.2.2: "after each movement, local remeshing is applied to
// the active triangles"; §5.3.1 on surfaces): the edges of the node's triangles that fail the
// empty-circle test (is_locally_delaunay: exact incircle in the plane, the unfolded criterion on a
// surface) are flipped one at a time, the star looked at again after each, until none fails or a
// flip limit is reached. flip_edge refuses what cannot be flipped (a reflex quadrilateral, Fig. 5.9's
// flips, a labelled constraint, a fold of the two new triangles); such edges are left as they are.
#pragma once

#include <cstddef>
#include <functional>

#include "sxk/mesh.hpp"

namespace sxk::delaunaycut {

struct StarFlipRules {
    // Whether a flip may join c and d, the vertices opposite the edge (the surface cutter: not two
    // incisions' nodes, §5.3.2); empty: any.
    std::function<bool(VertexId c, VertexId d)> may_join;
    // A surface: a flip whose two new triangles face against a triangle around them (folds_at) that
    // the old two did not is taken back.
    bool no_new_folds = false;
    std::size_t most = 64;
};

// The number of flips made.
std::size_t flip_star(Mesh& mesh, VertexId v, const StarFlipRules& rules = {});

}  // namespace sxk::delaunaycut
