// make_delaunay and cylinder_cloud (sxk/generators.hpp): CGAL's Delaunay tetrahedralisation.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cmath>
#include <numbers>
#include <string>

#include "cgal_kernel.hpp"
#include "sxk/generators.hpp"

namespace sxk {

Outcome<Mesh> make_delaunay(std::span<const Point> points) {
    using Kernel = detail::Kernel;
    using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<VertexId, Kernel>;
    using Tds = CGAL::Triangulation_data_structure_3<VertexBase>;
    using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
    if (points.size() < 4)
        return Refusal{RefusalCode::bad_argument,
                       "make_delaunay: " + std::to_string(points.size()) + " points; a tetrahedron needs 4"};
    Mesh mesh(3, 3);
    std::vector<std::pair<Kernel::Point_3, VertexId>> located;
    located.reserve(points.size());
    for (const Point& p : points) {
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            return Refusal{RefusalCode::bad_argument,
                           "make_delaunay: point " + std::to_string(located.size()) + " is not finite"};
        located.emplace_back(detail::to_cgal_3(p), mesh.add_vertex(p));
    }
    const Delaunay delaunay(located.begin(), located.end());
    if (delaunay.dimension() < 3)
        return Refusal{RefusalCode::not_applicable, "make_delaunay: the points are coplanar"};
    std::vector<Simplex> tets;
    tets.reserve(delaunay.number_of_finite_cells());
    for (auto cell = delaunay.finite_cells_begin(); cell != delaunay.finite_cells_end(); ++cell)
        // CGAL's cells are positively oriented: (v0, v1, v2, v3) has v3 on the positive side
        tets.emplace_back(+1, std::array<VertexId, 4>{cell->vertex(0)->info(), cell->vertex(1)->info(),
                                                      cell->vertex(2)->info(), cell->vertex(3)->info()});
    if (Outcome<Done> assigned = mesh.assign_elements(tets); !assigned)
        return assigned.refusal().prefixed("make_delaunay: ");
    return mesh;
}

std::vector<Point> cylinder_cloud(int rings, int layers, double spacing) {
    std::vector<Point> points;
    for (int layer = 0; layer <= layers; ++layer) {
        const double z = layer * spacing;
        points.push_back({0, 0, z});
        for (int k = 1; k <= rings; ++k) {
            const int count = static_cast<int>(std::lround(2 * std::numbers::pi * k));
            const double turn = (layer % 2 == 0 ? 0.0 : 0.5) * 2 * std::numbers::pi / count;
            for (int i = 0; i < count; ++i) {
                const double angle = turn + 2 * std::numbers::pi * i / count;
                points.push_back({k * spacing * std::cos(angle), k * spacing * std::sin(angle), z});
            }
        }
    }
    return points;
}

}  // namespace sxk
