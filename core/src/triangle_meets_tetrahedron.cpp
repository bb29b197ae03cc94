// triangle_meets_tetrahedron (sxk/predicates.hpp): a closed triangle against a closed
// tetrahedron, decided by orientation signs.
//
// Why not CGAL::do_intersect(Triangle_3, Tetrahedron_3), which it replaced: that test has no
// early exit for a tetrahedron on one side of the triangle's plane, and most elements the spatial
// index hands a scalpel's sweep are such (their boxes meet a piece of the sliver's box). On the
// 1.2M femur's blade slivers (tools/bench/sweep_tests, ns per test, ours / CGAL): 65 / 401 for
// elements with a corner in a sliver's box, 267 / 475 for the neighbours of those it meets, and
// 296 / 221 for those it meets; about 223 candidates of which 40 meet a sweep at the haptic rate
// (docs/performance.md "snapcut_latency"). Every decision is one orientation sign through the
// kernel's static filter; a collinear triangle goes to CGAL's segment test.
// tests/core/predicates_test.cpp holds the two against each other on configurations that are
// degenerate almost everywhere.
//
// Why these steps suffice. If T and K meet, their common part Q is convex. Either a vertex of
// the slice K ∩ plane(T) lies in T (that vertex is where an edge of K meets the plane), or Q
// reaches the boundary of T (Q holds a point of T, the slice a vertex outside T, and the segment
// between them lies in the slice and leaves T), so an edge of T meets K: either a corner of T is
// in K or the edge crosses a face of K. Conversely each of those is a common point.
#include <array>
#include <cmath>

#include "cgal_kernel.hpp"
#include "sxk/predicates.hpp"
#include "tetrahedron_signs.hpp"

namespace sxk {
namespace {

using detail::Kernel;
using detail::faces;
using detail::line_through_triangle;
using detail::orientation_sign;

constexpr std::array<std::array<std::size_t, 2>, 6> edges{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

// A collinear triangle is the segment between its two farthest corners (or a point), against a
// proper tetrahedron: CGAL's tests, which need a proper triangle no more.
bool collinear_meets(const std::array<Kernel::Point_3, 3>& t, const std::array<Kernel::Point_3, 4>& p) {
    const Kernel::Tetrahedron_3 k(p[0], p[1], p[2], p[3]);
    std::size_t from = 0, to = 1;
    for (const auto& [i, j] : std::array<std::array<std::size_t, 2>, 2>{{{0, 2}, {1, 2}}})
        if (CGAL::squared_distance(t[i], t[j]) > CGAL::squared_distance(t[from], t[to])) from = i, to = j;
    if (t[from] == t[to]) return !k.has_on_unbounded_side(t[from]);
    return CGAL::do_intersect(Kernel::Segment_3(t[from], t[to]), k);
}

// A plane through an edge of T with T's third corner on one side and every corner of K strictly
// on the other: T and K are apart. The plane passes through the edge and the edge's first end
// moved along T's normal (in doubles): any plane through the edge will do, so the rounded point
// takes nothing from the signs' exactness. The elements around the nodes a cut snapped lie along
// the blade's sliver, mostly behind it, straddling its plane: here they are told apart by 5 to 15
// signs instead of the 17 and more of the tests below (docs/performance.md "Following the
// blade").
bool beyond_an_edge(const std::array<Kernel::Point_3, 3>& t, const std::array<Kernel::Point_3, 4>& p) {
    const Kernel::Vector_3 normal = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
    for (std::size_t x = 0; x < 3; ++x) {
        const Kernel::Point_3& from = t[x];
        const Kernel::Point_3& to = t[(x + 1) % 3];
        const Kernel::Point_3 lifted = from + normal;
        // corners so far apart that the normal overflows (fuzz/corpus/snapcut): no plane from it,
        // and the exact signs must not see an infinite point
        if (!std::isfinite(lifted.x()) || !std::isfinite(lifted.y()) || !std::isfinite(lifted.z())) return false;
        const int third = orientation_sign(from, to, lifted, t[(x + 2) % 3]);
        if (third == 0) continue;  // the lifted point fell on the edge's line or T's plane: no plane
        bool apart = true;
        for (std::size_t i = 0; i < 4 && apart; ++i) apart = orientation_sign(from, to, lifted, p[i]) == -third;
        if (apart) return true;
    }
    return false;
}

}  // namespace

bool triangle_meets_tetrahedron(const Point& a, const Point& b, const Point& c, const Point& p0, const Point& p1,
                                const Point& p2, const Point& p3) {
    using P = Kernel::Point_3;
    const std::array<P, 3> t{detail::to_cgal_3(a), detail::to_cgal_3(b), detail::to_cgal_3(c)};
    const std::array<P, 4> p{detail::to_cgal_3(p0), detail::to_cgal_3(p1), detail::to_cgal_3(p2),
                             detail::to_cgal_3(p3)};
    // the plane of T: all corners of K strictly on one side separate them (a collinear T has no
    // plane: every sign is zero then, as it is for no proper T and K, and CGAL decides)
    std::array<int, 4> side{};
    int above = 0, below = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        side[i] = orientation_sign(t[0], t[1], t[2], p[i]);
        above += side[i] > 0;
        below += side[i] < 0;
    }
    if (above == 4 || below == 4) return false;
    if (above + below > 0 && beyond_an_edge(t, p)) return false;
    const int volume = orientation_sign(p[0], p[1], p[2], p[3]);
    if (volume == 0) return false;  // a flat tetrahedron: no element to meet (as the index has it)
    if (above + below == 0) return collinear_meets(t, p);

    // the planes of K's faces: inside[i][x] > 0 when corner x of T is on the inner side of face i
    std::array<std::array<int, 3>, 4> inside{};
    for (std::size_t i = 0; i < 4; ++i) {
        const auto& f = faces[i];
        for (std::size_t x = 0; x < 3; ++x) inside[i][x] = volume * orientation_sign(p[f[0]], p[f[1]], p[f[2]], t[x]);
        if (inside[i][0] < 0 && inside[i][1] < 0 && inside[i][2] < 0) return false;
    }
    for (std::size_t x = 0; x < 3; ++x)
        if (inside[0][x] >= 0 && inside[1][x] >= 0 && inside[2][x] >= 0 && inside[3][x] >= 0) return true;

    // an edge of K crossing T (an edge lying in T's plane is found through its ends, each on an
    // edge of K that crosses the plane, or through the edge of T that crosses it)
    for (const auto& [i, j] : edges) {
        if (side[i] * side[j] > 0 || (side[i] == 0 && side[j] == 0)) continue;
        if (line_through_triangle(p[i], p[j], t[0], t[1], t[2])) return true;
    }

    // an edge of T crossing a face of K. Its ends are outside K by now, so an edge of T lying in
    // the plane of a face that it meets leaves that face through an edge of K: there it crosses
    // the plane of the face on the other side of that edge (found here), or it passes through a
    // corner of K (found above: an edge of K from that corner crosses T's plane there).
    for (std::size_t x = 0; x < 3; ++x) {
        const std::size_t y = (x + 1) % 3;
        for (std::size_t i = 0; i < 4; ++i) {
            if (inside[i][x] * inside[i][y] > 0 || (inside[i][x] == 0 && inside[i][y] == 0)) continue;
            const auto& f = faces[i];
            if (line_through_triangle(t[x], t[y], p[f[0]], p[f[1]], p[f[2]])) return true;
        }
    }
    return false;
}

}  // namespace sxk
