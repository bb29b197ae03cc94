// Crossings far from the mesh's nodes: where snapping alone cannot bring the incision close to the
// scalpel.
//
// The selection marks the end of each crossed edge nearer the crossing, and snapping moves it onto
// the sweep. A node is at most half its edge from the crossing, but a real mesh's interior edges
// are long (the femur's up to 7 times its mean edge h): a node 1.5 h from the sweep, whose star
// would invert before it gets there, stays off the cut or goes part of the way
// (node_snapping.hpp); and a node ahead of the blade goes onto the sweep's plane, beyond where the
// blade was, which is off the cut when the blade turns. So before the selection, an edge the sweep
// crosses whose nearer end is farther than `beyond` from everywhere the blade has swept (the
// sweeps so far, this one, and the rest of this movement) is split where the sweep crosses it
// (split_edge, both position sets at the same fraction of the edge, which is where the element
// maps the crossing): the new node lies on the sweep, every edge at it is marked with it (an exact
// touch would mark them so; rounding puts the node on either side of the plane), and the faces
// selected through it lie on the sweep where the edge was long.
//
//        a (far from the sweep)            a
//        |                                 |
//   =====x===== sweep        --->     =====m===== m: the new node, the mark of every edge at m
//        |                                 |
//        b                                 b
//
// The distance is to the swept surface, not to this sweep's triangle alone: a node just beyond
// one sweep triangle is often on the next (the movement's other half), and measured against the
// one triangle its edge was split at the first sweep's crossing while the next sweep marked the
// node itself, the incision ran through both and the femur cut stayed in one piece. The crossing
// is on the sweep and the nearer end farther than `beyond` from it, so both ends are farther
// than `beyond` from the crossing and no child is a sliver along the edge. Edges with a snapped
// end are left alone: the selection sees a snapped node where it was before the cut moved it, and
// the crossing of the edge it sees is not a point of the edge as it lies (select_faces marks the
// snapped end of such an edge when the other is far). Only unmarked edges
// count (the first crossing of an edge is its mark), and an edge split_edge refuses (a pinched
// star, a child flat by rounding) stays and is marked by the selection as before.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "face_selection.hpp"
#include "sxk/mesh.hpp"

namespace sxk::snapcut {

struct FarCrossings {
    std::size_t split = 0;    // edges split where the sweep crosses them
    std::size_t refused = 0;  // edges split_edge refused (left to the selection as they are)
};

// Splits the far crossings of sweep `sweep_index` among the edges of `candidates` (dead ids are
// skipped), far meaning beyond `swept.beyond` (> 0) of `swept`, and adds the children to
// `candidates` (sorted again, each once).
FarCrossings split_far_crossings(Mesh& mesh, CutMarks& marks, std::uint32_t sweep_index, const SweptSurface& swept,
                                 std::vector<ElementId>& candidates);

}  // namespace sxk::snapcut
