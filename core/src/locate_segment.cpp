// SpatialIndex::elements_crossed: the rtree's boxes that meet the segment, then the exact test
// (sxk/locate.hpp).
#include "locate_trees.hpp"
#include "sxk/locate.hpp"

namespace sxk {
namespace {

template <int D>
std::vector<ElementId> crossed(const SpatialIndex::Trees& trees, const Mesh& mesh, const Point& a, const Point& b,
                               Positions positions) {
    using Tree = detail::BoxTree<D>;
    const auto& tree = detail::element_tree<D>(trees).tree;
    std::vector<typename Tree::Value> candidates;
    if (a == b) {
        tree.query(detail::bgi::intersects(Tree::point_box(a)), std::back_inserter(candidates));
    } else {
        // a double-precision segment against float boxes: Boost computes in the more precise
        // type, and the boxes' margin (locate_trees.hpp) covers its rounding
        const detail::bg::model::segment<typename Tree::QueryPoint> segment(Tree::query_point(a), Tree::query_point(b));
        tree.query(detail::bgi::intersects(segment), std::back_inserter(candidates));
    }
    std::vector<ElementId> hits;
    for (const auto& candidate : candidates)
        detail::element_tree<D>(trees).any_member(candidate.second, [&](ElementId t) {
            if (segment_meets_element(mesh, t, a, b, positions)) hits.push_back(t);
            return false;
        });
    detail::sort_unique(hits);
    return hits;
}

}  // namespace

std::vector<ElementId> SpatialIndex::elements_crossed(const Point& a, const Point& b) const {
    if (m_mesh->ambient_dimension() == 2) {
        // the third coordinate of a planar query is ignored, also when deciding a == b
        return crossed<2>(*m_trees, *m_mesh, {a[0], a[1], 0}, {b[0], b[1], 0}, m_options.positions);
    }
    return crossed<3>(*m_trees, *m_mesh, a, b, m_options.positions);
}

}  // namespace sxk
