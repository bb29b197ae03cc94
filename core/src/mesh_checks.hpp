// Argument checks shared by the edit primitives.
#pragma once

#include <string>

#include "sxk/simplex.hpp"

namespace sxk::detail {

// Why `s` cannot be an element of a mesh with `vertices` vertices and elements of
// `vertex_count_per_element` vertices; empty when it can.
inline std::string check_simplex(const Simplex& s, int vertex_count_per_element,
                                 std::size_t vertices) {
    if (s.count() != vertex_count_per_element)
        return "element has " + std::to_string(s.count()) + " vertices, expected " +
               std::to_string(vertex_count_per_element);
    for (int j = 0; j < s.count(); ++j)
        if (s.vertex(j) >= vertices)
            return "vertex " + std::to_string(s.vertex(j)) + " does not exist (the mesh has " +
                   std::to_string(vertices) + " vertices)";
    if (!s.has_distinct_vertices()) return "element " + to_text(s) + " repeats a vertex";
    return {};
}

}  // namespace sxk::detail
