// The building blocks of the removal moves (thesis Fig. 3.9): collapse an edge whichever way
// the checks allow; the worst shape a move left.
#include <algorithm>

#include "removal_steps.hpp"
#include "sxk/ops/collapse_edge.hpp"
#include "sxk/traversal.hpp"

namespace sxk::degeneracy::detail {

Refused collapse_one_way(Mesh& mesh, VertexId a, VertexId b, bool reverse, const Options& options) {
    const auto collapsed = reverse ? collapse_edge(mesh, b, a, CollapseOptions{options.boundary_tolerance})
                                   : collapse_edge(mesh, a, b, CollapseOptions{options.boundary_tolerance});
    if (collapsed) return std::nullopt;
    return collapsed.refusal();
}

ElementId element_containing(const Mesh& mesh, std::span<const VertexId> vertices) {
    const VertexId first = vertices[0];
    if (first >= mesh.vertex_count() || mesh.vertex_element(first) == invalid_id) return invalid_id;
    for (const ElementId t : star(mesh, first))
        if (std::all_of(vertices.begin(), vertices.end(), [&](VertexId v) { return mesh.simplex(t).contains(v); }))
            return t;
    return invalid_id;
}

ElementId element_with(const Mesh& mesh, const Simplex& vertices) {
    // an element containing all d + 1 vertices of a d-simplex is that simplex
    return element_containing(mesh, vertices.vertices());
}

Shapes shapes_of(const Mesh& mesh, std::span<const ElementId> elements, const Options& options) {
    Shapes shapes;
    for (const ElementId t : elements) {
        const double aspect = element_aspect_ratio(mesh, t, options.positions);
        shapes.worst = std::min(shapes.worst, aspect);
        shapes.degenerate += aspect < options.aspect_ratio;
    }
    return shapes;
}

Shapes shapes_of(const Mesh& mesh, std::span<const Simplex> simplexes, const Options& options) {
    Shapes shapes;
    for (const Simplex& simplex : simplexes) {
        const double aspect = aspect_ratio_of(mesh, simplex.vertices(), options.positions);
        shapes.worst = std::min(shapes.worst, aspect);
        shapes.degenerate += aspect < options.aspect_ratio;
    }
    return shapes;
}

}  // namespace sxk::degeneracy::detail
