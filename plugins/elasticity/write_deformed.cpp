// ElasticBody::write_deformed: the solution as the mesh's deformed positions (elastic_body.hpp).
#include <vector>

#include "elastic_body.hpp"

namespace sxk::elasticity {

Outcome<Done> ElasticBody::write_deformed(Mesh& mesh) const {
    std::vector<VertexId> vertices;
    vertices.reserve(vertex_count());
    for (VertexId v = 0; v < vertex_count(); ++v) vertices.push_back(v);
    return write_deformed(mesh, vertices);
}

Outcome<Done> ElasticBody::write_deformed(Mesh& mesh, std::span<const VertexId> vertices) const {
    if (&mesh != m_mesh)
        return Refusal{RefusalCode::bad_argument, "elasticity: write_deformed: not the mesh of this body"};
    std::vector<VertexId> moved;
    std::vector<Point> points;
    moved.reserve(vertices.size());
    points.reserve(vertices.size());
    for (const VertexId v : vertices) {
        if (v >= vertex_count() || v >= mesh.vertex_count() || mesh.vertex_element(v) == invalid_id) continue;
        const Point& x = mesh.reference(v);
        moved.push_back(v);
        points.push_back({x[0] + m_u[3 * v], x[1] + m_u[3 * v + 1], x[2] + m_u[3 * v + 2]});
    }
    if (auto written = mesh.move_vertices(moved, points, PositionSet::deformed,
                                          {.refuse_inverted = true, .refuse_flat = true});
        !written)
        // the item is the element, which names the same thing to our caller
        return Refusal{written.code(), "elasticity: the solution cannot be shown: " + written.reason(),
                       written.refusal().item};
    return Done{};
}

}  // namespace sxk::elasticity
