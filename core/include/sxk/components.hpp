// Connected components of the element face-adjacency: two elements are in one component when a
// chain of elements, each sharing a (d-1)-face with the next (a face and its mate), joins them.
// Elements touching only at a vertex or an edge are in different components.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/ids.hpp"
#include "sxk/mesh.hpp"

namespace sxk {

struct Components {
    // Indexed by ElementId (size mesh.element_capacity()): the component of each live element,
    // 0..count-1, numbered in order of each component's smallest element id; invalid_id for
    // dead ids.
    std::vector<std::uint32_t> element_component;
    std::size_t count = 0;
};

// O(n) in the number of elements. An empty mesh has 0 components.
SXK_API Components connected_components(const Mesh& mesh);

}  // namespace sxk
