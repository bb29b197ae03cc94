// Pieces a cut separated from the rest of the mesh, found at the cost of the pieces, not of the
// mesh (a whole-mesh component count, sxk/components.hpp, is O(n) per step).
//
// The seeds (the elements on both sides of the new cut) are first put in groups known connected
// by their own neighbourhood: face neighbours, and the fans around the edges of their boundary
// faces; at the rim of a cut both sides lie in one fan. With one group nothing came loose and no
// search runs. Otherwise one breadth-first search per group runs through face neighbours, the
// searches taking one element each in turn. Two searches that meet are one; a search that runs
// out of elements before meeting the others has found a whole component: a loose piece. When a
// single search is left it is the body the pieces came off, and it stops. The searches race per
// body as it was before the step (the two sides of a cut node and its copy were one body): on a
// mesh of several bodies each body keeps its last search. So the work is about
// the seeds' number when nothing comes loose, and the loose pieces' size times the number of
// searches when something may have.
//
//        body (search left running: stops)      ======  the new cut faces
//      ---------------------------------
//        ======================                 seeds on both sides; the piece below the cut
//        piece (search ran out: loose)          runs out first
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "face_selection.hpp"
#include "sxk/mesh.hpp"

namespace sxk::snapcut {

struct LoosePieces {
    std::vector<std::vector<ElementId>> pieces;  // each sorted; in the order they were found
};

// The components of the seeds' elements that are not the last one standing on their body (dead
// ids skipped). `cut_pairs` are the step's dissections' (original, copy) nodes: the seeds around
// the two ends of a pair were one body before the step, so each body keeps its largest part (the
// last search left on it) and only the others are loose; two bodies cut in one step each keep
// one part. With the seeds all in one component there is no loose piece.
LoosePieces find_loose_pieces(const Mesh& mesh, std::span<const ElementId> seeds,
                              std::span<const std::pair<VertexId, VertexId>> cut_pairs);

// Crumbs (keep_crumbs_attached.cpp). Where the incision's surface folds around a tetrahedron or
// two at its rim (tetrahedra whose faces were selected from different sides, or that a later
// sweep completes around a corner), opening every selected face would cut that crumb loose: a
// piece of a few elements that then floats in the simulation (the thesis' "cut free" elements,
// §3.3). Returns `faces` (interior faces, sorted as Simplex(+1, vertices)) less one face per
// crumb of at most `crumb` elements that opening them would make, the crumb being closed off by
// the boundary and the faces to open: the crumb stays on the side across that face (the lowest
// such face by vertices, so the choice is deterministic). A face left out keeps its cut label.
//
// Layers. Where a tetrahedron lies flat along the cut (all four corners on it), its neighbours on
// both sides select the faces they share with it (face_selection.hpp, "Corners snapped
// elsewhere"), and the flat tetrahedra next to it with it make a layer the faces close off. With
// `marks`, a piece made only of elements whose corners are all snapped (CutMarks::snapped) is a
// crumb up to `largest_layer` elements: its corners all lie within the snap's reach of the sweeps,
// so it is a film along the incision however many elements it has. A random through cut of the
// 213k femur cut such a film of 11 elements (5.7 mean volumes) loose, its corners within 0.12 h of
// the sweeps: too much material for a crumb by volume, and it floated as a third piece.
inline constexpr std::size_t largest_layer = 64;
std::vector<Simplex> keep_crumbs_attached(const Mesh& mesh, std::vector<Simplex> faces, std::size_t crumb,
                                          const CutMarks* marks = nullptr);

}  // namespace sxk::snapcut
