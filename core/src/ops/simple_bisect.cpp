// simple-bisect (thesis §6.5, Fig. 6.6), through split_edge.
#include "sxk/ops/simple_bisect.hpp"

#include <string>

#include "ops/bisect_2d_helpers.hpp"
#include "sxk/ops/split_edge.hpp"

namespace sxk {

Outcome<SplitResult> simple_bisect(Mesh& mesh, VertexId p, VertexId q) {
    if (mesh.topological_dimension() != 2)
        return Refusal{RefusalCode::wrong_dimension,
                       "simple_bisect: needs a triangle mesh (topological dimension 2)"};
    if (p >= mesh.vertex_count() || q >= mesh.vertex_count())
        return Refusal{RefusalCode::not_found,
                       "simple_bisect: " + std::to_string(p >= mesh.vertex_count() ? p : q) +
                       " is not a vertex"};
    if (p == q)
        return Refusal{RefusalCode::bad_argument,
                       "simple_bisect: the two ends are the same vertex"};
    const detail::Edge edge = detail::make_edge(p, q);
    const std::vector<ElementId> around = detail::elements_with_edge(mesh, p, q);
    if (around.empty())
        return Refusal{RefusalCode::not_found,
                       "simple_bisect: " + detail::edge_text(edge) + " is not an edge"};
    for (ElementId t : around)
        if (const detail::Edge h = detail::hypotenuse_in_mesh(mesh, t); !(h == edge))
            return Refusal{RefusalCode::not_applicable,
                           "simple_bisect: " + detail::edge_text(edge) +
                           " is not the hypotenuse of element " + std::to_string(t) +
                           " (its hypotenuse is " + detail::edge_text(h) + ")"};
    auto split = split_edge(mesh, p, q, 0.5);
    if (!split)
        return split.refusal().prefixed("simple_bisect: ");
    return split;
}

}  // namespace sxk
