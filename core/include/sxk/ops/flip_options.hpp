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
};

}  // namespace sxk
