// SpatialIndex::elements_hit_by_triangle: a scalpel's sweep, the elements and boundary faces a
// triangle meets (sxk/locate.hpp).
#include "locate_trees.hpp"
#include "sxk/locate.hpp"

namespace sxk {
namespace {

template <int D>
TriangleHits hit_by(const SpatialIndex::Trees& trees, const Mesh& mesh, const Point& a, const Point& b,
                    const Point& c, Positions positions) {
    using Tree = detail::BoxTree<D>;
    const std::array<const Point*, 3> corners{&a, &b, &c};
    const typename Tree::Box query = Tree::box_of(corners);
    std::vector<typename Tree::Value> candidates;
    TriangleHits hits;
    detail::element_tree<D>(trees).tree.query(detail::bgi::intersects(query), std::back_inserter(candidates));
    for (const auto& candidate : candidates)
        detail::element_tree<D>(trees).any_member(candidate.second, [&](ElementId t) {
            if (triangle_meets_element(mesh, t, a, b, c, positions)) hits.elements.push_back(t);
            return false;
        });
    candidates.clear();
    detail::face_tree<D>(trees).tree.query(detail::bgi::intersects(query), std::back_inserter(candidates));
    for (const auto& candidate : candidates)
        detail::face_tree<D>(trees).any_member(candidate.second, [&](FaceId f) {
            if (triangle_meets_face(mesh, f, a, b, c, positions)) hits.boundary_faces.push_back(f);
            return false;
        });
    detail::sort_unique(hits.elements);
    detail::sort_unique(hits.boundary_faces);
    return hits;
}

}  // namespace

TriangleHits SpatialIndex::elements_hit_by_triangle(const Point& a, const Point& b, const Point& c) const {
    if (m_mesh->ambient_dimension() == 2)
        return hit_by<2>(*m_trees, *m_mesh, {a[0], a[1], 0}, {b[0], b[1], 0}, {c[0], c[1], 0}, m_options.positions);
    return hit_by<3>(*m_trees, *m_mesh, a, b, c, m_options.positions);
}

}  // namespace sxk
