// SpatialIndex::nearest_boundary_point: boundary faces in the order of their boxes' distance,
// until a box is farther than the nearest point found (sxk/locate.hpp).
#include <cmath>

#include "locate_trees.hpp"
#include "sxk/locate.hpp"

namespace sxk {
namespace {

template <int D>
BoundaryPoint nearest(const SpatialIndex::Trees& trees, const Mesh& mesh, const Point& x, Positions positions) {
    using Tree = detail::BoxTree<D>;
    const auto& boxes = detail::face_tree<D>(trees);
    const auto& tree = boxes.tree;
    BoundaryPoint best;
    if (boxes.live_count == 0) return best;
    const typename Tree::QueryPoint q = Tree::query_point(x);
    // the box distance is a lower bound of the distance to its face: once a box is farther than
    // the best face, so is every face after it (the iterator yields boxes nearest first)
    const auto everything = static_cast<unsigned>(tree.size());
    for (auto it = tree.qbegin(detail::bgi::nearest(q, everything)); it != tree.qend(); ++it) {
        const double box_distance = std::sqrt(static_cast<double>(detail::bg::comparable_distance(q, it->first)));
        if (best.found() && box_distance > best.distance * detail::float_box_slack) break;
        boxes.any_member(it->second, [&](FaceId f) {
            const BoundaryPoint candidate = nearest_point_on_face(mesh, f, x, positions);
            if (candidate.distance < best.distance) best = candidate;
            return false;
        });
    }
    return best;
}

}  // namespace

BoundaryPoint SpatialIndex::nearest_boundary_point(const Point& x) const {
    for (int k = 0; k < m_mesh->ambient_dimension(); ++k)
        if (!std::isfinite(x[static_cast<std::size_t>(k)])) return {};
    if (m_mesh->ambient_dimension() == 2)
        return nearest<2>(*m_trees, *m_mesh, {x[0], x[1], 0}, m_options.positions);
    return nearest<3>(*m_trees, *m_mesh, x, m_options.positions);
}

}  // namespace sxk
