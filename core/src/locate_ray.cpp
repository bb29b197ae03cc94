// SpatialIndex::pick: the first boundary face (on a surface, the first triangle) a ray meets,
// candidates in the order of their boxes' distance from the origin (sxk/locate.hpp).
#include <cmath>

#include "locate_trees.hpp"
#include "sxk/locate.hpp"

namespace sxk {
namespace {

template <int D>
RayHit first_hit(const detail::BoxTree<D>& boxes, const Mesh& mesh, const Point& o, const Point& d, Positions positions,
                 bool surface) {
    using Boxes = detail::BoxTree<D>;
    RayHit best;
    const auto& tree = boxes.tree;
    if (boxes.live_count == 0) return best;
    // the ray as a segment long enough to leave the bounds of every box, for the tree's pruning
    const auto bounds = tree.bounds();
    const typename Boxes::QueryPoint origin = Boxes::query_point(o);
    double reach = 0;
    for (int corner = 0; corner < (1 << D); ++corner) {
        Point p{};
        p[0] = corner & 1 ? detail::bg::get<0>(bounds.max_corner()) : detail::bg::get<0>(bounds.min_corner());
        p[1] = corner & 2 ? detail::bg::get<1>(bounds.max_corner()) : detail::bg::get<1>(bounds.min_corner());
        if constexpr (D == 3)
            p[2] = corner & 4 ? detail::bg::get<2>(bounds.max_corner()) : detail::bg::get<2>(bounds.min_corner());
        reach = std::max(reach, std::sqrt(detail::distance_squared(p, o)));
    }
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double scale = 2 * reach / length + 1;
    const Point far{o[0] + scale * d[0], o[1] + scale * d[1], o[2] + scale * d[2]};
    const detail::bg::model::segment<typename Boxes::QueryPoint> ray(origin, Boxes::query_point(far));
    const auto everything = static_cast<unsigned>(tree.size());
    for (auto it = tree.qbegin(detail::bgi::intersects(ray) && detail::bgi::nearest(origin, everything));
         it != tree.qend(); ++it) {
        // a box's distance from the origin bounds the distance of every hit inside it
        const double box_distance = std::sqrt(static_cast<double>(detail::bg::comparable_distance(origin, it->first)));
        if (best.found() && box_distance > best.t * length * detail::float_box_slack) break;
        boxes.any_member(it->second, [&](std::uint32_t id) {
            const RayHit hit = surface ? ray_meets_triangle_element(mesh, id, o, d, positions)
                                       : ray_meets_face(mesh, id, o, d, positions);
            if (hit.found() && hit.t < best.t) best = hit;
            return false;
        });
    }
    return best;
}

}  // namespace

RayHit SpatialIndex::pick(const Point& origin, const Point& direction) const {
    const Mesh& mesh = *m_mesh;
    const int n = mesh.ambient_dimension();
    const Point o = n == 2 ? Point{origin[0], origin[1], 0} : origin;
    const Point d = n == 2 ? Point{direction[0], direction[1], 0} : direction;
    for (int k = 0; k < n; ++k)
        if (!std::isfinite(o[static_cast<std::size_t>(k)]) || !std::isfinite(d[static_cast<std::size_t>(k)])) return {};
    if (d[0] == 0 && d[1] == 0 && d[2] == 0) return {};
    if (mesh.topological_dimension() < n) return first_hit<3>(m_trees->elements3, mesh, o, d, m_options.positions, true);
    if (n == 2) return first_hit<2>(m_trees->faces2, mesh, o, d, m_options.positions, false);
    return first_hit<3>(m_trees->faces3, mesh, o, d, m_options.positions, false);
}

}  // namespace sxk
