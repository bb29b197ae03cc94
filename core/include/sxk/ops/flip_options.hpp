// Options shared by the tetrahedral flips flip_23, flip_32 and flip_44 (thesis §5.2.2: flips
// are the local reconnection step; in 3D they "must be checked for failure cases").
#pragma once

namespace sxk {

struct TetFlipOptions {
    // false: every new tetrahedron must be strictly positive by exact orient3d in BOTH the
    // reference and the deformed positions (a simulation needs both shapes valid, thesis
    // §3.2.2). true: only the topological checks are made (for meshes without geometry or for
    // callers that check geometry themselves).
    bool topology_only = false;

    // true: the caller guarantees that the reference positions EMBED the mesh (elements meet
    // only in shared faces: a mesh from a mesher or a Delaunay triangulation, edited since only
    // by geometric flips, splits and bisections). Then "the new edge or triangle already
    // exists" (thesis Fig. 5.9) needs no search: the new elements are checked strictly positive
    // in the reference positions, so the new edge pq (2-3, 4-4) crosses the interior of a face
    // of the mesh that has no vertex in common with it, or the new triangle cde (3-2) is
    // crossed by the old edge ab; an existing pq or cde would meet that face or edge outside
    // their common faces, which an embedding excludes. The flips then skip the star walk that
    // looks for it (the most expensive part of a flip on a large mesh, docs/performance.md).
    // Ignored when topology_only is true (no geometry, no proof). The kernel cannot check the
    // guarantee cheaply: on a mesh that is not embedded (a folded deformed state copied into
    // the reference positions, overlapping input) a flip may then represent an edge twice,
    // which validate() reports as a broken invariant. Default false: every flip searches.
    bool reference_is_embedding = false;
};

namespace detail {
// True when the flips may skip their search for an existing new edge or triangle because the
// geometric test in the reference positions proves it absent (TetFlipOptions above).
inline bool embedding_proves_absence(const TetFlipOptions& options) {
    return options.reference_is_embedding && !options.topology_only;
}
}  // namespace detail

}  // namespace sxk
