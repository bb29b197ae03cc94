// split_edge (thesis §3.2 subdivision; connectivity edit by §7.3 replace-elements).
#include "sxk/ops/split_edge.hpp"

#include <array>

#include "ops/edge_star.hpp"
#include "ops/split_parents.hpp"

namespace sxk {

Outcome<SplitResult> split_edge(Mesh& mesh, VertexId a, VertexId b, double t, const SplitOptions& options) {
    if (a >= mesh.vertex_count() || b >= mesh.vertex_count())
        return Refusal{RefusalCode::not_found,
                       "split_edge: " + std::to_string(a >= mesh.vertex_count() ? a : b) +
                       " is not a vertex"};
    if (a == b)
        return Refusal{RefusalCode::bad_argument, "split_edge: the two ends are the same vertex"};
    // negated comparison so that NaN is refused too
    if (!(t > 0 && t < 1))
        return Refusal{RefusalCode::bad_argument,
                       "split_edge: t = " + std::to_string(t) + " is not in (0,1)"};
    // the edge's elements in star(a) order, found without allocating (a triangle mesh stops
    // the walk at the first one: its neighbour across ab is the only other)
    detail::SmallVector<ElementId, 64> parents;
    detail::edge_elements_into(mesh, a, b, parents);
    if (parents.empty())
        return Refusal{RefusalCode::not_found,
                       "split_edge: " + to_text(Simplex(+1, {a, b})) + " is not an edge"};
    if (const int fans = detail::edge_fans(mesh, parents, a, b); fans > 1)
        return Refusal{RefusalCode::pinched_star,
                       "split_edge: the " + std::string(mesh.topological_dimension() == 3 ? "tetrahedra" : "triangles") +
                           " around " + to_text(Simplex(+1, {a, b})) + " are " + std::to_string(fans) +
                           " fans joined only at the edge: the new vertex's star would be pinched"};

    const std::array<VertexId, 2> ends{a, b};
    const std::array<double, 2> weights{1 - t, t};
    return detail::split_parents(mesh, parents, ends, weights, "split_edge", options.vanishing_with);
}

}  // namespace sxk
