// Dissection of a mesh along a set C of (d-1)-faces (thesis §7.3, Figs. 7.5-7.7): the faces of C
// are opened, so that the elements on their two sides no longer share those faces.
//
// The thesis splits vertices, not faces: for a vertex v of a face in C, two elements of star(v)
// are (v,C)-connected when a chain of elements of star(v), each sharing with the next a face that
// contains v and is NOT in C, joins them. If star(v) falls into l > 1 such classes, v stays with
// one class and l-1 copies of v (same reference and deformed position) take the others. A single
// change-elements then substitutes the copies, keeping every element and face identity.
//
//   Fig. 7.6: C = {a-v, v-b} (the cut, ===)          after dissect: v' is a copy of v
//
//            c                                          c
//          /   \   t0 above the cut                   /   \   t0 keeps v
//        /  t0   \    (a, v, b on the cut line)     /  t0   \   (a, b: boundary vertices)
//      a ===== v ===== b                             a ---- v ---- b
//        \  t1   /                                    a' --- v' --- b'
//          \   /   t1 below: star(v) = {t0, t1}         \  t1   /   t1 gets the copies (a and b
//            d     falls into two (v,C)-classes            \   /    split too when their stars
//                                                           d      fall apart)
//
//   Fig. 7.7: a face of C whose vertices' stars do not fall apart (an interior edge cut on its
//   own in 2D: the ring around each end point stays joined through the other edges) gives
//   l = 1 everywhere, so nothing changes and the face stays joined: no special case is needed.
//
// Contract.
//   Before: `cut_faces` are (d-1)-simplexes, each (in either orientation: a face in C counts
//   with its mate) a face of the mesh. Repeats are allowed.
//   After (on success): for each split vertex, the class holding the smallest element id keeps
//   the original vertex; the other classes, in order of their smallest element id, get new
//   vertices appended to the mesh (ids vertex_count() before, +1, ...), each a copy of its
//   original's positions and of every vertex attribute, bit for bit. The result lists
//   (original, new) pairs in order of creation. Only elements of split classes are changed,
//   with ONE Mesh::change_elements call; every ElementId and FaceId survives (Fig. 7.5), faces of
//   C that separate become boundary faces (their mates too), others keep their mates. Face
//   labels (keyed by vertex set) follow faces whose vertices were replaced by copies; the
//   original key keeps its label while some element still has that face (a labelled cut face
//   labels both of the boundary faces it becomes).
//   Cut mark: both boundary faces of every face of C that opened (it had a mate and has none
//   now) get the face label options.cut_label (default_cut_label; none when it is empty) unless
//   they have one already, so the cut surface is in every file format that writes face labels
//   (Medit, Gmsh, VTU, TetGen .face) and follows later edits as face labels do (splits pass
//   them to the pieces, collapses to the moved faces, flips refuse to remove them). The
//   result lists those faces, both sides, in `opened`.
//   Inverse: none in the kernel (stitching is the merge of the copies back into v).
// Refusals (mesh untouched), reasons begin with "dissect: ":
//   "cut face I has K vertices, not D" (I: index in cut_faces, D = topological dimension);
//   "cut face I <...> has a repeated or unknown vertex"; "cut face I <...> is not a face of the
//   mesh". Refusal::item is I. The argument above (faces not in C keep all their vertices'
//   classes together) shows change_elements cannot refuse on a valid mesh; should it refuse
//   anyway, the copies (in no element yet) are removed again, so no refusal adds a vertex.
#pragma once

#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

// The face label of a cut surface (DissectOptions::cut_label): a number unlikely to be one of a
// generator's surface patch references; `sxk render` draws boundary faces with it as cut faces.
inline constexpr int default_cut_label = 9999;

struct DissectOptions {
    // The label of the opened faces that have none; empty: leave them unlabelled.
    std::optional<int> cut_label = default_cut_label;
};

struct DissectResult {
    // (original vertex, new copy), in order of creation.
    std::vector<std::pair<VertexId, VertexId>> new_vertices;
    // The boundary faces the cut made, both sides of every face of C that opened, by FaceId
    // (face ids survive change_elements), in increasing order.
    std::vector<FaceId> opened;
};

SXK_API Outcome<DissectResult> dissect(Mesh& mesh, std::span<const Simplex> cut_faces,
                                       const DissectOptions& options = {});

}  // namespace sxk
