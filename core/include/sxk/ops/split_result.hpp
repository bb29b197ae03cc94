// What a split creates: the new vertex and the new elements (shared by split_edge, split_face
// and split_element).
#pragma once

#include <span>
#include <vector>

#include "sxk/ids.hpp"

namespace sxk {

struct SplitResult {
    VertexId vertex = invalid_id;        // the new vertex (id vertex_count() - 1 after the split)
    std::vector<ElementId> elements;     // the children, in the order the header of the op names
};

// Options of split_edge and split_face.
struct SplitOptions {
    // Parents that contain ALL of these vertices (none when empty, the default) are about to
    // vanish: the caller's next edit collapses the new vertex into one of them, which removes
    // every element containing both, or the caller undoes the split. Their children are not
    // checked for orientation, so a flat parent can be split (its children are flat too, and
    // rounding may give them either sign). Degeneracy removal splits flat elements this way
    // (thesis Fig. 3.9: split, then collapse the short edge); every other child is checked.
    std::span<const VertexId> vanishing_with;
};

}  // namespace sxk
