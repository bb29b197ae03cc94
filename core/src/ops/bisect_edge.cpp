// bisect(e) of thesis §6.5 (Fig. 6.7), planned on an overlay, then replayed with split_edge.
#include "sxk/ops/bisect_edge.hpp"

#include <string>

#include "ops/bisect_2d_helpers.hpp"

namespace sxk {

Outcome<BisectEdgeResult> bisect_edge(Mesh& mesh, VertexId p, VertexId q) {
    if (mesh.topological_dimension() != 2)
        return Refusal{RefusalCode::wrong_dimension,
                       "bisect_edge: needs a triangle mesh (topological dimension 2)"};
    if (p >= mesh.vertex_count() || q >= mesh.vertex_count())
        return Refusal{RefusalCode::not_found,
                       "bisect_edge: " + std::to_string(p >= mesh.vertex_count() ? p : q) +
                       " is not a vertex"};
    if (p == q)
        return Refusal{RefusalCode::bad_argument, "bisect_edge: the two ends are the same vertex"};
    const detail::Edge edge = detail::make_edge(p, q);
    if (detail::elements_with_edge(mesh, p, q).empty())
        return Refusal{RefusalCode::not_found,
                       "bisect_edge: " + detail::edge_text(edge) + " is not an edge"};

    detail::BisectionPlan plan(mesh);
    if (auto refused = plan.bisect(edge, "bisect_edge"))
        return *refused;
    auto applied = plan.apply(mesh, "bisect_edge");
    if (!applied)
        return applied.refusal();
    BisectEdgeResult result;
    for (const SplitResult& split : *applied)
        result.vertices.push_back(split.vertex);
    result.midpoint = result.vertices.back();
    return result;
}

}  // namespace sxk
