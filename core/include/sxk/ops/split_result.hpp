// What a split creates: the new vertex and the new elements (shared by split_edge, split_face
// and split_element).
#pragma once

#include <vector>

#include "sxk/ids.hpp"

namespace sxk {

struct SplitResult {
    VertexId vertex = invalid_id;        // the new vertex (id vertex_count() - 1 after the split)
    std::vector<ElementId> elements;     // the children, in the order the header of the op names
};

}  // namespace sxk
