// SpatialIndex::locate: a walk from the hint, then the rtree's candidates at the point
// (sxk/locate.hpp).
#include <cmath>

#include "locate_trees.hpp"
#include "sxk/locate.hpp"

namespace sxk {
namespace {

// The walk from a hint is worth its steps while it is shorter than a tree descent: 128 steps are
// ~2 us of exact tests, about what the rtree costs on a 1M-element mesh (docs/performance.md
// "locate").
constexpr std::size_t hint_walk_steps = 128;
// From the seed of x's grid cell (locate_trees.hpp), a cell or two away at most: a longer walk
// means a stale seed, and the tree is cheaper than walking on.
constexpr std::size_t seed_walk_steps = 16;

// The rtree's first candidate is next to x; when it does not contain x, a short walk from it
// usually reaches the element that does in a step or two through the mesh's neighbour cache,
// where each further candidate costs a descent through the tree's nodes, which miss the cache on
// a 1M-element mesh (docs/performance.md "locate").
constexpr std::size_t candidate_walk_steps = 8;

template <int D>
Location locate_in_tree(const SpatialIndex::Trees& trees, const Mesh& mesh, const Point& x, Positions positions) {
    const auto& boxes = detail::element_tree<D>(trees);
    const auto query = detail::BoxTree<D>::point_box(x);
    bool first = true;
    Location found;
    for (auto it = boxes.tree.qbegin(detail::bgi::intersects(query)); it != boxes.tree.qend(); ++it)
        if (boxes.any_member(it->second, [&](ElementId t) {
                if ((found = locate_in_element(mesh, t, x, positions)).found()) return true;
                if (!first) return false;
                first = false;
                const ElementId walked = walk_to_point(mesh, x, t, positions, candidate_walk_steps);
                return walked != invalid_id && (found = locate_in_element(mesh, walked, x, positions)).found();
            }))
            return found;
    return {};
}

// Surfaces: the nearest triangle among those whose boxes come within the tolerance.
Location locate_on_surface(const SpatialIndex::Trees& trees, const Mesh& mesh, const Point& x, Positions positions,
                           double tolerance) {
    const Point low{x[0] - tolerance, x[1] - tolerance, x[2] - tolerance};
    const Point high{x[0] + tolerance, x[1] + tolerance, x[2] + tolerance};
    const std::array<const Point*, 2> corners{&low, &high};
    const auto query = detail::BoxTree<3>::box_of(corners);
    Location best;
    double best_distance = std::numeric_limits<double>::infinity();
    const auto& tree = trees.elements3.tree;
    for (auto it = tree.qbegin(detail::bgi::intersects(query)); it != tree.qend(); ++it)
        trees.elements3.any_member(it->second, [&](ElementId t) {
            const Location found = locate_in_element(mesh, t, x, positions, tolerance);
            if (!found.found()) return false;
            const Point q = [&] {
                const Simplex& s = mesh.simplex(found.element);
                Point p{};
                for (int j = 0; j < 3; ++j)
                    for (std::size_t k = 0; k < 3; ++k)
                        p[k] += found.barycentric[static_cast<std::size_t>(j)] * position(mesh, s.vertex(j), positions)[k];
                return p;
            }();
            if (const double distance = detail::distance_squared(q, x); distance < best_distance) {
                best_distance = distance;
                best = found;
            }
            return false;
        });
    return best;
}

}  // namespace

Location SpatialIndex::locate(const Point& x, ElementId hint) const {
    const Mesh& mesh = *m_mesh;
    for (int k = 0; k < mesh.ambient_dimension(); ++k)
        if (!std::isfinite(x[static_cast<std::size_t>(k)])) return {};
    const bool surface = mesh.topological_dimension() < mesh.ambient_dimension();
    const double tolerance = surface ? surface_tolerance() : 0;
    if (mesh.is_element(hint)) {
        const ElementId walked = walk_to_point(mesh, x, hint, m_options.positions, hint_walk_steps);
        if (walked != invalid_id)
            if (const Location found = locate_in_element(mesh, walked, x, m_options.positions, tolerance); found.found())
                return found;
    }
    if (surface) return locate_on_surface(*m_trees, mesh, x, m_options.positions, tolerance);
    // the seed of x's grid cell, then the tree; the answer seeds the cell (locate_trees.hpp)
    detail::SeedGrid& grid = m_trees->seeds;
    const std::size_t cell = grid.empty() ? detail::SeedGrid::npos : grid.cell_of(x, mesh.ambient_dimension());
    if (cell != detail::SeedGrid::npos) {
        const ElementId seed = grid.seeds[cell].load(std::memory_order_relaxed);
        if (mesh.is_element(seed))
            if (const ElementId walked = walk_to_point(mesh, x, seed, m_options.positions, seed_walk_steps);
                walked != invalid_id)
                if (const Location found = locate_in_element(mesh, walked, x, m_options.positions); found.found())
                    return found;
    }
    const Location found = mesh.ambient_dimension() == 2 ? locate_in_tree<2>(*m_trees, mesh, x, m_options.positions)
                                                         : locate_in_tree<3>(*m_trees, mesh, x, m_options.positions);
    if (cell != detail::SeedGrid::npos && found.found()) grid.seeds[cell].store(found.element, std::memory_order_relaxed);
    return found;
}

}  // namespace sxk
