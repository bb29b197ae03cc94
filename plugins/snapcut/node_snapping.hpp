// Node snapping of the snap cut (thesis §3.2.2, Fig. 3.6): the corners of the selected faces
// move onto the sweep, so that the incision follows the scalpel instead of the mesh's faces.
//
//   interior node v:  w = the orthogonal projection of v onto the sweep's plane
//   boundary node v:  for each boundary face f around v, w_f = the projection of v onto the line
//                     where the sweep's plane meets f's plane, kept when w_f lies in f; w is the
//                     w_f nearest v (a flat surface keeps its shape)
//
//          sweep plane                 f, g: boundary faces around v
//              |                        w_f lies in f: a candidate
//       f      |  w_f                   w_g does not lie in g: not
//      ------v-+------ g
//
// All this in the deformed positions (where the scalpel is). The reference position is the
// element of v's star that holds w (deformed) mapping w back: the same barycentric weights of its
// reference corners (its strain, as the thesis says). The move is refused when no element of the
// star holds w, when it would make an element of the star inverted or flat in either position set
// (the thesis' §3.4 remedy for the inverted elements snapping made), or when it would leave one
// below `min_aspect_ratio` (0: no such check). A node refused for its star's shapes goes 7/8, 3/4,
// 1/2 or 1/4 of the way when that is allowed ("partly" snapped: on the femur this halves the
// incision's distance from the sweep); otherwise it stays and the refusal is reported.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "face_selection.hpp"
#include "sxk/mesh.hpp"

namespace sxk::snapcut {

struct NodeToSnap {
    VertexId node = invalid_id;
    std::uint32_t sweep = 0;  // whose plane it goes to (index into CutMarks::sweeps())
};

struct SnapResult {
    std::vector<VertexId> snapped;                         // in the order tried
    std::vector<Point> snapped_from;                       // their deformed positions before
    std::size_t partly = 0;  // of the snapped, those moved only part of the way (see above)
    std::vector<std::pair<VertexId, std::string>> refused; // node, why
};

// Snaps `nodes` one after the other (each move checked against the positions of those before).
SnapResult snap_nodes(Mesh& mesh, std::span<const NodeToSnap> nodes, const std::vector<Sweep>& sweeps,
                      double min_aspect_ratio);

}  // namespace sxk::snapcut
