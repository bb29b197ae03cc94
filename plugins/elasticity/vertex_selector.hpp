// Vertex selections as `sxk deform` takes them (docs/cli.md "sxk deform"): terms joined by '&',
// a vertex is selected when every term holds for it.
//
//   x<0.001  y>=0.2  z=1    a coordinate of the reference position against a number
//                           (operators < <= > >= =; '=' is exact)
//   label=N                 the vertex is a corner of an element labelled N
//   boundary                the vertex is a corner of a boundary face
//
// Only vertices in elements are ever selected. Spaces around terms and operators are allowed.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk::elasticity {

struct SelectorTerm {
    enum class Kind { coordinate, label, boundary } kind = Kind::boundary;
    enum class Compare { less, less_equal, greater, greater_equal, equal } compare = Compare::equal;
    int axis = 0;      // coordinate: 0 x, 1 y, 2 z
    double value = 0;  // coordinate: the number
    int label = 0;     // label: N
};

struct VertexSelector {
    std::string text;  // as given, for messages
    std::vector<SelectorTerm> terms;
};

// Refuses (bad_argument) a selector that does not parse, saying where: "selector 'x<<1': term
// 'x<<1': expected a number after '<', found '<1'".
Outcome<VertexSelector> parse_vertex_selector(std::string_view text);

// The vertices of `mesh` (in elements) that the selector selects, in increasing id order.
std::vector<VertexId> select_vertices(const Mesh& mesh, const VertexSelector& selector);

}  // namespace sxk::elasticity
