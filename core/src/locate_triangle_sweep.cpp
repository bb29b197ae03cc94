// SpatialIndex::elements_hit_by_triangle: a scalpel's sweep, the elements and boundary faces a
// triangle meets (sxk/locate.hpp).
#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "locate_trees.hpp"
#include "sxk/locate.hpp"

namespace sxk {
namespace {

// A query box holding more than this many tree entries may be split (below).
constexpr std::size_t entries_per_box = 48;
// and a triangle is halved this many times at most along one branch (every edge is then under
// 1/256 of what it was); with corners so far apart that their distance overflows, not at all
// (fuzz/corpus/snapcut/huge: the halving never ended).
constexpr int max_halvings = 24;

// The tree entries whose boxes meet triangle (a, b, c), gathered from the boxes of pieces of the
// triangle: one box around a long triangle that lies oblique to the axes (a scalpel's sweep:
// a blade of 0.4 tilted by 0.02 over its length, moved 1e-3) holds a slab of the mesh, five times
// the elements the triangle meets on the 1.2M femur and growing with the resolution
// (docs/performance.md "snapcut"). A box that holds more than entries_per_box entries is dropped
// and the triangle is halved across its longest edge, so the boxes hug the triangle where the
// mesh is fine and stay whole where it is coarse or empty; but not once the piece is shorter
// than twice the entries' mean box size, where halving cannot shed entries (the star of a vertex
// with more than entries_per_box elements meets every piece around the vertex). The pieces'
// union is the triangle up to the rounding of the midpoints, far below the boxes' padding
// (box_of); the exact tests that follow are against the whole triangle, once per entry.
template <int D>
void gather(const detail::BoxTree<D>& boxes, const Point& a, const Point& b, const Point& c, int halvings,
            std::vector<std::uint32_t>& out) {
    using Tree = detail::BoxTree<D>;
    auto length2 = [](const Point& p, const Point& q) {
        return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
    };
    // rotate so that (p, q) is the longest edge and r the opposite corner
    const Point* p = &a;
    const Point* q = &b;
    const Point* r = &c;
    if (length2(b, c) > length2(*p, *q)) std::tie(p, q, r) = std::tuple{&b, &c, &a};
    if (length2(c, a) > length2(*p, *q)) std::tie(p, q, r) = std::tuple{&c, &a, &b};
    const double longest = std::sqrt(length2(*p, *q));

    const std::array<const Point*, 3> corners{&a, &b, &c};
    const std::size_t before = out.size();
    double entry_sizes = 0;  // the sum of the gathered entries' largest box sides
    bool split = false;
    for (auto it = boxes.tree.qbegin(detail::bgi::intersects(Tree::box_of(corners))); it != boxes.tree.qend(); ++it) {
        if (out.size() - before == entries_per_box) {
            split = halvings < max_halvings && std::isfinite(longest) && longest > 2 * entry_sizes / entries_per_box;
            if (split) break;
        }
        if (out.size() - before < entries_per_box) {
            double side = 0;
            for (int k = 0; k < D; ++k)
                side = std::max(side, double(Tree::corner(it->first.max_corner(), k) - Tree::corner(it->first.min_corner(), k)));
            entry_sizes += side;
        }
        out.push_back(it->second);
    }
    if (!split) return;
    out.resize(before);
    const Point m{((*p)[0] + (*q)[0]) / 2, ((*p)[1] + (*q)[1]) / 2, ((*p)[2] + (*q)[2]) / 2};
    gather<D>(boxes, *p, m, *r, halvings + 1, out);
    gather<D>(boxes, m, *q, *r, halvings + 1, out);
}

template <int D>
TriangleHits hit_by(const SpatialIndex::Trees& trees, const Mesh& mesh, const Point& a, const Point& b,
                    const Point& c, Positions positions) {
    std::vector<std::uint32_t> candidates;  // entry keys
    TriangleHits hits;
    const auto& element_boxes = detail::element_tree<D>(trees);
    gather<D>(element_boxes, a, b, c, 0, candidates);
    detail::sort_unique(candidates);
    for (const std::uint32_t candidate : candidates)
        element_boxes.any_member(candidate, [&](ElementId t) {
            if (triangle_meets_element(mesh, t, a, b, c, positions)) hits.elements.push_back(t);
            return false;
        });
    candidates.clear();
    const auto& face_boxes = detail::face_tree<D>(trees);
    gather<D>(face_boxes, a, b, c, 0, candidates);
    detail::sort_unique(candidates);
    for (const std::uint32_t candidate : candidates)
        face_boxes.any_member(candidate, [&](FaceId f) {
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
