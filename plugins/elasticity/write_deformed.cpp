// ElasticBody::write_deformed: the solution as the mesh's deformed positions (elastic_body.hpp).
#include <vector>

#include "elastic_body.hpp"

namespace sxk::elasticity {

Outcome<Done> ElasticBody::write_deformed(Mesh& mesh) const {
    if (&mesh != m_mesh)
        return Refusal{RefusalCode::bad_argument,
                       "elasticity: write_deformed: not the mesh of this body"};
    std::vector<VertexId> vertices;
    std::vector<Point> points;
    for (VertexId v = 0; v < vertex_count(); ++v) {
        if (v >= mesh.vertex_count() || mesh.vertex_element(v) == invalid_id)
            continue;
        const Point& x = mesh.reference(v);
        vertices.push_back(v);
        points.push_back({x[0] + m_u[3 * v], x[1] + m_u[3 * v + 1], x[2] + m_u[3 * v + 2]});
    }
    if (auto moved = mesh.move_vertices(vertices, points, PositionSet::deformed,
                                        {.refuse_inverted = true, .refuse_flat = true});
        !moved)
        // the item is the element, which names the same thing to our caller
        return Refusal{moved.code(), "elasticity: the solution cannot be shown: " + moved.reason(),
                       moved.refusal().item};
    return Done{};
}

}  // namespace sxk::elasticity
