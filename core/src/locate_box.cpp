// SpatialIndex::elements_with_vertex_in_box: the elements a brush touches (sxk/locate.hpp).
#include <array>

#include "locate_trees.hpp"
#include "sxk/locate.hpp"

namespace sxk {
namespace {

template <int D>
std::vector<ElementId> with_vertex_in(const SpatialIndex::Trees& trees, const Mesh& mesh, const Point& low,
                                      const Point& high, Positions positions) {
    using Tree = detail::BoxTree<D>;
    for (std::size_t k = 0; k < static_cast<std::size_t>(D); ++k)
        if (!(low[k] <= high[k])) return {};
    const std::array<const Point*, 2> corners{&low, &high};
    std::vector<typename Tree::Value> candidates;
    detail::element_tree<D>(trees).tree.query(detail::bgi::intersects(Tree::box_of(corners)),
                                              std::back_inserter(candidates));
    auto inside = [&](VertexId v) {
        const Point& p = position(mesh, v, positions);
        for (std::size_t k = 0; k < static_cast<std::size_t>(D); ++k)
            if (p[k] < low[k] || p[k] > high[k]) return false;
        return true;
    };
    std::vector<ElementId> hits;
    for (const auto& candidate : candidates)
        detail::element_tree<D>(trees).any_member(candidate.second, [&](ElementId t) {
            for (const VertexId v : mesh.simplex(t).vertices())
                if (inside(v)) {
                    hits.push_back(t);
                    break;
                }
            return false;
        });
    detail::sort_unique(hits);
    return hits;
}

}  // namespace

std::vector<ElementId> SpatialIndex::elements_with_vertex_in_box(const Point& low, const Point& high) const {
    if (m_mesh->ambient_dimension() == 2)
        return with_vertex_in<2>(*m_trees, *m_mesh, low, high, m_options.positions);
    return with_vertex_in<3>(*m_trees, *m_mesh, low, high, m_options.positions);
}

}  // namespace sxk
