// SpatialIndex::elements_hit_by_triangle: a scalpel's sweep, the elements and boundary faces a
// triangle meets (sxk/locate.hpp).
#include <algorithm>
#include <cmath>
#include <iterator>
#include <tuple>
#include <utility>

#include "locate_trees.hpp"
#include "sxk/locate.hpp"

namespace sxk {
namespace {

// A piece of the triangle longer than this many mean entry sides (BoxTree::mean_side) is halved
// before it is looked up, at most max_blind_halvings deep (1024 pieces). A blade at a haptic
// rate sweeps a sliver as long as the blade: on the 1.2M femur, its pieces' lookups cost 0.20 ms
// a sweep with 16 sides, 0.26 with 32, 0.27 with 4, 0.40 with 2 (more lookups), 0.33 ms when
// each piece was looked up and halved only once its box held too many entries
// (tools/bench/snapcut_latency --substeps 50, docs/performance.md "snapcut").
constexpr double piece_sides = 16;
constexpr int max_blind_halvings = 10;
// A piece still longer (a triangle of more than 1024 pieces) whose box holds more than this many
// entries is halved further, at most max_halvings deep along one branch (every edge is then
// under 1/256 of what it was); with corners so far apart that their distance overflows, not at
// all (fuzz/corpus/snapcut/huge: the halving never ended).
constexpr std::size_t entries_per_box = 48;
constexpr int max_halvings = 24;

// The tree entries whose boxes meet triangle (a, b, c), gathered from the boxes of pieces of the
// triangle: one box around a long triangle that lies oblique to the axes (a scalpel's sweep:
// a blade of 0.4 tilted by 0.02 over its length, moved 1e-3) holds a slab of the mesh, five times
// the elements the triangle meets on the 1.2M femur and growing with the resolution
// (docs/performance.md "snapcut"). So the triangle is halved across its longest edge down to
// pieces of a few entry sizes, each looked up whole. A triangle too large for that many pieces
// is halved further where its boxes hold more than entries_per_box entries; but not once the
// piece is shorter than twice its entries' mean box size, where halving cannot shed entries (the
// star of a vertex with more than entries_per_box elements meets every piece around the vertex).
// The pieces' union is the triangle up to the rounding of the midpoints, far below the boxes'
// padding (box_of); the exact tests that follow are against the whole triangle, once per entry.
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
    const Point m{((*p)[0] + (*q)[0]) / 2, ((*p)[1] + (*q)[1]) / 2, ((*p)[2] + (*q)[2]) / 2};
    const auto halve = [&] {
        gather<D>(boxes, *p, m, *r, halvings + 1, out);
        gather<D>(boxes, m, *q, *r, halvings + 1, out);
    };
    const bool long_piece = std::isfinite(longest) && longest > piece_sides * boxes.mean_side;
    if (long_piece && halvings < max_blind_halvings) return halve();

    const std::array<const Point*, 3> corners{&a, &b, &c};
    // the callback form of the query: Boost's query iterators (qbegin) are type-erased, and
    // cost half as much again on the femur's sweeps
    thread_local std::vector<typename Tree::Value> found;
    found.clear();
    boxes.tree.query(detail::bgi::intersects(Tree::box_of(corners)), std::back_inserter(found));
    if (long_piece && found.size() > entries_per_box && halvings < max_halvings) {
        double sides = 0;  // the entries' largest box sides
        for (const auto& [box, key] : found) {
            double side = 0;
            for (int k = 0; k < D; ++k)
                side = std::max(side, double(Tree::corner(box.max_corner(), k) - Tree::corner(box.min_corner(), k)));
            sides += side;
        }
        if (longest > 2 * sides / double(found.size())) return halve();
    }
    for (const auto& value : found) out.push_back(value.second);
}

// The members of `boxes` that `meets` (the exact test against the triangle), sorted: the
// candidates are the members of the entries whose boxes meet pieces of the triangle.
template <int D, class Id, class Meets>
void members_meeting(const detail::BoxTree<D>& boxes, const Point& a, const Point& b, const Point& c, Meets meets,
                     std::vector<Id>& out) {
    std::vector<std::uint32_t> candidates;  // entry keys
    gather<D>(boxes, a, b, c, 0, candidates);
    detail::sort_unique(candidates);
    for (const std::uint32_t candidate : candidates)
        boxes.any_member(candidate, [&](Id id) {
            if (meets(id)) out.push_back(id);
            return false;
        });
    detail::sort_unique(out);
}

template <int D>
TriangleHits hit_by(const SpatialIndex::Trees& trees, const Mesh& mesh, const Point& a, const Point& b,
                    const Point& c, Positions positions, TriangleHitsOf what) {
    TriangleHits hits;
    if (what != TriangleHitsOf::boundary_faces)
        members_meeting<D, ElementId>(
            detail::element_tree<D>(trees), a, b, c,
            [&](ElementId t) { return triangle_meets_element(mesh, t, a, b, c, positions); }, hits.elements);
    if (what != TriangleHitsOf::elements)
        members_meeting<D, FaceId>(
            detail::face_tree<D>(trees), a, b, c,
            [&](FaceId f) { return triangle_meets_face(mesh, f, a, b, c, positions); }, hits.boundary_faces);
    return hits;
}

}  // namespace

TriangleHits SpatialIndex::elements_hit_by_triangle(const Point& a, const Point& b, const Point& c,
                                                   TriangleHitsOf what) const {
    if (m_mesh->ambient_dimension() == 2)
        return hit_by<2>(*m_trees, *m_mesh, {a[0], a[1], 0}, {b[0], b[1], 0}, {c[0], c[1], 0}, m_options.positions,
                         what);
    return hit_by<3>(*m_trees, *m_mesh, a, b, c, m_options.positions, what);
}

}  // namespace sxk
